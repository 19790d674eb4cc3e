"""LAMMPS timing of fix wall/tabor against LAMMPS's own fix wall/gran (issue 31,
item 6), on the deposition run of examples/lammps/deposition.py.

The same aerosol (TIMING_GRAINS grains, default 10^4; pair_style tabor between the
grains in every run), the same time step and steps, on 1 rank, alternately
TIMING_REPEATS times (the machine may be shared), with the plate as
  tabor-jkr: fix wall/tabor jkr/load-controlled + mindlin NULL + sds + marshall,
  granular:  fix wall/gran granular jkr + the same sub-models (the same law),
  tabor:     fix wall/tabor maugis range h (each contact's Lambda, 1 at the median
             radius; deposition.py's own wall) + the same sub-models (reference),
  none:      no wall (the baseline: fix nve/sphere is in the Modify time too).
The wall's cost is the fastest Modify time (LAMMPS's own timer breakdown) minus the
fastest of `none`; printed, and the ratio tabor-jkr/granular (target: at most
1.0). No assertion: wall-clock times depend on the machine.

Environment: as deposition.py (TABOR, TABOR_PLUGIN, TABOR_FFI_LIB, LAMMPS_VENV);
TIMING_GRAINS, TIMING_REPEATS (3); TIMING_BEFORE_PLUGIN: another build of the
plugin (e.g. before a change), run as a fifth variant `before-jkr` (tabor-jkr with
that plugin) in the same alternation, its ratio printed beside.
"""

import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
GRAINS = os.environ.get("TIMING_GRAINS", "10000")
REPEATS = int(os.environ.get("TIMING_REPEATS", "3"))
BEFORE = os.environ.get("TIMING_BEFORE_PLUGIN")
VARIANTS = ("none", "tabor-jkr", "granular", "tabor") + (("before-jkr",) if BEFORE else ())


def main():
    best = {}
    for _ in range(REPEATS):
        for wall in VARIANTS:
            env = dict(os.environ, DEP_WALL=wall, DEP_RANKS="1", DEP_GRAINS=GRAINS,
                       DEP_OUT=os.path.join(ROOT, "target", "lammps-deposition-timing"))
            if wall == "before-jkr":
                env.update(DEP_WALL="tabor-jkr", TABOR_PLUGIN=BEFORE)
            out = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "lammps", "deposition.py")],
                                 env=env, check=True, capture_output=True, text=True).stdout
            t = {k: float(v) for k, v in re.findall(r"(\w+) ([0-9.]+)", out.split("timing (s): ")[1].splitlines()[0])}
            steps = int(re.search(r"(\d+) steps of", out).group(1))
            for k in ("Modify", "Pair", "Loop"):
                best[(wall, k)] = min(best.get((wall, k), float("inf")), t[k])
    print(f"deposition, {GRAINS} grains, {steps} steps, 1 rank; fastest of {REPEATS} (s):")
    print(f"{'wall':>10} {'Loop':>8} {'Pair':>8} {'Modify':>8} {'wall cost':>10} {'us/step':>8}")
    for wall in VARIANTS:
        cost = best[(wall, "Modify")] - best[("none", "Modify")]
        print(f"{wall:>10} {best[(wall, 'Loop')]:8.3f} {best[(wall, 'Pair')]:8.3f} {best[(wall, 'Modify')]:8.3f} "
              f"{cost:10.3f} {1e6 * cost / steps:8.2f}")
    base = best[("none", "Modify")]
    ratio = (best[("tabor-jkr", "Modify")] - base) / (best[("granular", "Modify")] - base)
    print(f"fix wall/tabor (jkr) / fix wall/gran granular jkr, same sub-models: {ratio:.2f}x (target <= 1.0)")
    ratio_md = (best[("tabor", "Modify")] - base) / (best[("granular", "Modify")] - base)
    print(f"fix wall/tabor (maugis) / fix wall/gran granular jkr: {ratio_md:.2f}x")
    if BEFORE:
        ratio_b = (best[("before-jkr", "Modify")] - base) / (best[("granular", "Modify")] - base)
        print(f"fix wall/tabor (jkr) of TIMING_BEFORE_PLUGIN / fix wall/gran granular jkr: {ratio_b:.2f}x")


if __name__ == "__main__":
    main()

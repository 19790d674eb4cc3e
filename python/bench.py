"""Benchmarks of the Python package: time and memory per element, as ratios against
numpy in the same run.

    python bench.py [--points N] [--sweep-points M]   (tabor, numpy, scipy installed)

Each case runs in its own subprocess, so that its peak resident memory is its own:
"memory" is (peak RSS − RSS before the call − the bytes of the returned arrays) per
element, i.e. what a call costs beyond its outputs (after one small call, so that
the thread pool and other once-per-process set-up are not counted per element).
Times are the best of a few repeats: wall clock (all cores; "ratio") and CPU time
of the process summed over its threads ("cpu ratio", which a machine shared with
other work disturbs less than the wall clock).

1. ``tabor.jkr`` over N speeds (every column: loss, sticking velocity, contact
   radii, restitution, ...) against numpy's closed form ε = √(1 − v_c²/v²)
   (5.37)/(5.38) on the same array.
2. ``tabor.effective`` over N radii against numpy's three closed forms.
3. ``Scene.restitution`` (silica.toml, JKR) over N speeds against the same numpy
   closed form.
4. ``Scene.sweep("speed")`` (silica.toml) over M speeds (every outcome column).
5. N fast-tier and 10³ direct Maugis-Dugdale losses; the direct ones against
   SciPy's brentq + quad (tests/md_scipy.py).
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import time
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
# the installed package, not the source folder python/tabor next to this script
sys.path = [p for p in sys.path if Path(p or ".").resolve() != HERE]
sys.path.insert(0, str(HERE / "tests"))
SCENE = HERE.parent / "examples" / "scenes" / "silica.toml"
JKR = dict(modulus=27.8e9, radius=5e-7, work_of_adhesion=0.05, mass=5.55e-15)


def best(f, repeats=3, clock=time.perf_counter):
    times = []
    out = None
    for _ in range(repeats):
        out = None  # the previous result is freed before the clock starts
        t = clock()
        out = f()
        times.append(clock() - t)
    return min(times), out


def rss():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def reset_peak():
    """Resets the process's peak resident memory (Linux >= 4.0: /proc/self/clear_refs)."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
    except OSError:
        pass


def peak_rss():
    """The peak resident memory of this process's own address space (VmHWM).
    Not ``getrusage``'s ``ru_maxrss``: on Linux that starts at the parent's
    resident size at the fork (the address space before exec), so a child of a
    parent that imported SciPy reported the parent's 78 MB as its peak."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) * 1024
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def nbytes(result):
    if isinstance(result, dict):
        return sum(v.nbytes for v in result.values() if isinstance(v, np.ndarray))
    return result.nbytes


def child(case, n):
    import tabor

    warnings.simplefilter("ignore")
    scene = tabor.Scene.from_path(SCENE)
    v_c = scene.sticking_velocity()
    if case == "jkr":
        v = np.geomspace(0.05, 5, n)
        ref = lambda: tabor.jkr(**JKR, speed=v)  # noqa: E731
        e0 = tabor.jkr(**JKR)
        base = lambda: np.sqrt(np.clip(1.0 - (e0["sticking_velocity"] / v) ** 2, 0.0, None))  # noqa: E731
        check = lambda out, b: np.max(np.abs(out["restitution"] - b))  # noqa: E731
    elif case == "effective":
        r = np.geomspace(1e-7, 1e-4, n)
        ref = lambda: tabor.effective(youngs_modulus=54e9, poisson_ratio=0.17, radius=r, density=2650.0,  # noqa: E731
                                      target_radius=r)

        def base():
            e = 1 / (2 * (1 - 0.17**2) / 54e9)
            m = 4 / 3 * np.pi * r**3 * 2650.0
            return (np.full_like(r, e), r * r / (r + r), m * m / (m + m))

        check = lambda out, b: np.max(np.abs(out["effective_mass"] / b[2] - 1))  # noqa: E731
    elif case == "restitution":
        v = np.geomspace(0.5 * v_c, 100 * v_c, n)
        ref = lambda: scene.restitution(v)  # noqa: E731
        base = lambda: np.sqrt(np.clip(1.0 - (v_c / v) ** 2, 0.0, None))  # noqa: E731
        check = lambda out, b: np.max(np.abs(out - b))  # noqa: E731
    elif case == "sweep":
        v = np.geomspace(0.5 * v_c, 100 * v_c, n)
        ref = lambda: scene.sweep("speed", v)  # noqa: E731
        base = lambda: np.sqrt(np.clip(1.0 - (v_c / v) ** 2, 0.0, None))  # noqa: E731
        check = lambda out, b: np.max(np.abs(out["restitution"] - b))  # noqa: E731
    else:
        raise SystemExit(f"unknown case {case}")
    t_np, b = best(base, 5)
    c_np, _ = best(base, 5, clock=time.process_time)
    warm_up(case, scene)
    reset_peak()
    before = rss()
    t0, c0 = time.perf_counter(), time.process_time()
    out = ref()
    t_first, c_first = time.perf_counter() - t0, time.process_time() - c0
    peak = peak_rss()
    extra = (peak - before - nbytes(out)) / n
    t_tabor = min(t_first, best(ref, 2)[0]) if n <= 10**6 else t_first
    c_tabor = min(c_first, best(ref, 2, clock=time.process_time)[0]) if n <= 10**6 else c_first
    print(json.dumps(dict(case=case, n=n, tabor=t_tabor, numpy=t_np, cpu_tabor=c_tabor, cpu_numpy=c_np,
                          bytes_per_element=extra, output_bytes_per_element=nbytes(out) / n,
                          diff=float(check(out, b)))))


def warm_up(case, scene):
    """One small call first, so that what is set up once per process (the thread
    pool, lazily built tables) is not counted per element."""
    import tabor

    v = np.geomspace(0.1, 1.0, 64)
    if case == "jkr":
        tabor.jkr(**JKR, speed=v)
    elif case == "effective":
        tabor.effective(youngs_modulus=54e9, poisson_ratio=0.17, radius=v * 1e-6, density=2650.0)
    elif case == "restitution":
        scene.restitution(v)
    elif case == "sweep":
        scene.sweep("speed", v)


def run_child(case, n):
    done = subprocess.run([sys.executable, __file__, "--child", case, str(n)], capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{case}: {done.stderr}")
    return json.loads(done.stdout)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--points", type=int, default=10**6, help="points of benchmarks 1-3 and 5 (default 1e6)")
    p.add_argument("--sweep-points", type=int, default=10**5, help="points of the sweep (default 1e5)")
    p.add_argument("--direct", type=int, default=10**3, help="direct Maugis-Dugdale losses (default 1e3)")
    p.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    args = p.parse_args()
    if args.child:
        child(args.child[0], int(args.child[1]))
        return
    import tabor
    from md_scipy import loss as scipy_loss

    warnings.simplefilter("ignore")  # quad's roundoff notes in the SciPy baseline
    n = args.points
    print(f"tabor {tabor.__version__}, numpy {np.__version__}, {os.cpu_count()} cores, "
          f"{tabor.get_num_threads()} threads")
    print(f"{'case':<34}{'tabor':>11}{'numpy':>11}{'ratio':>8}{'cpu ratio':>10}{'B/elem':>9}{'out B/elem':>11}"
          f"{'max diff':>10}")
    for case, count, label in (("jkr", n, "tabor.jkr(speed=...)"), ("effective", n, "tabor.effective(radius=...)"),
                               ("restitution", n, "Scene.restitution (silica, JKR)"),
                               ("sweep", args.sweep_points, "Scene.sweep('speed') (silica)")):
        r = run_child(case, count)
        print(f"{label + f' {count:.0e}':<34}{r['tabor'] * 1e3:>9.1f}ms{r['numpy'] * 1e3:>9.2f}ms"
              f"{r['tabor'] / r['numpy']:>8.1f}{r['cpu_tabor'] / r['cpu_numpy']:>10.1f}"
              f"{r['bytes_per_element']:>9.1f}{r['output_bytes_per_element']:>11.1f}"
              f"{r['diff']:>10.1e}")
    lam = np.geomspace(0.01, 100.0, n)
    tabor.maugis_dugdale_loss(1.0, fast=True)  # builds the table once
    t_fast, _ = best(lambda: tabor.maugis_dugdale_loss(lam, fast=True), 5)
    print(f"{n:.0e} fast-tier MD losses: {t_fast * 1e3:.1f} ms ({t_fast / n * 1e9:.0f} ns/point)")
    m = args.direct
    lam3 = np.geomspace(0.7, 10.0, m)
    t_dir, w_dir = best(lambda: tabor.maugis_dugdale_loss(lam3, tolerance=1e-12), 3)
    t_sp, w_sp = best(lambda: np.array([scipy_loss(x) for x in lam3]), 1)
    rel = np.max(np.abs(w_dir / w_sp - 1))
    print(f"{m:.0e} direct MD losses: tabor {t_dir * 1e3:.1f} ms, SciPy brentq+quad {t_sp * 1e3:.0f} ms, "
          f"SciPy/tabor = {t_sp / t_dir:.0f} (max rel diff {rel:.1e})")


if __name__ == "__main__":
    main()

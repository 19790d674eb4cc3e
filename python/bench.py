"""Benchmarks of the Python package, printed as ratios (issue 15, "Speed").

    python bench.py [--points N]     (from python/, with tabor, numpy, scipy installed)

1. 10⁶ scene restitutions (``Scene.restitution``, the JKR scene silica.toml) against
   numpy's closed form on the same array, ε = √(1 − v_c²/v²) (5.37)/(5.38).
2. 10⁶ Maugis-Dugdale losses from the fast tier (``fast=True``).
3. 10³ direct Maugis-Dugdale losses (tolerance 1e-12) against the same 10³ through
   SciPy (brentq + quad, tests/md_scipy.py, written from seed 000 §5.3.2).

Each timing is the best of a few repeats (wall clock, all cores).
"""

import argparse
import os
import sys
import time
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
# the installed package, not the source folder python/tabor next to this script
sys.path = [p for p in sys.path if Path(p or ".").resolve() != HERE]
sys.path.insert(0, str(HERE / "tests"))
import tabor  # noqa: E402
from md_scipy import loss as scipy_loss  # noqa: E402

SCENE = HERE.parent / "examples" / "scenes" / "silica.toml"


def best(f, repeats=3):
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return min(times), out


def main():
    warnings.simplefilter("ignore")  # quad's roundoff notes in the SciPy baseline
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--points", type=int, default=10**6, help="points of benchmarks 1 and 2 (default 1e6)")
    p.add_argument("--direct", type=int, default=10**3, help="points of benchmark 3 (default 1e3)")
    args = p.parse_args()
    n, m = args.points, args.direct
    print(f"tabor {tabor.__version__}, numpy {np.__version__}, {os.cpu_count()} cores")

    # 1. scene restitution against numpy's closed form
    scene = tabor.Scene.from_path(SCENE)
    v_c = scene.sticking_velocity()
    v = np.geomspace(0.5 * v_c, 100 * v_c, n)
    t_np, e_np = best(lambda: np.sqrt(np.clip(1.0 - (v_c / v) ** 2, 0.0, None)), 5)
    t_sc, e_sc = best(lambda: scene.restitution(v), 1 if n > 10**5 else 3)
    err = np.max(np.abs(e_sc - e_np))
    print(f"1. {n:.0e} scene restitutions: tabor {t_sc * 1e3:9.1f} ms, numpy closed form "
          f"{t_np * 1e3:7.1f} ms, ratio tabor/numpy = {t_sc / t_np:.1f}  (max |diff| {err:.1e})")

    # 2. fast-tier Maugis-Dugdale losses
    lam = np.geomspace(0.01, 100.0, n)
    tabor.maugis_dugdale_loss(1.0, fast=True)  # builds the table once
    t_fast, _ = best(lambda: tabor.maugis_dugdale_loss(lam, fast=True), 5)
    print(f"2. {n:.0e} fast-tier MD losses: {t_fast * 1e3:9.1f} ms  ({t_fast / n * 1e9:.0f} ns/point; "
          f"target < 100 ms for 1e6 on two cores)")

    # 3. direct losses against SciPy (case 3, where the SciPy reference applies)
    lam3 = np.geomspace(0.7, 10.0, m)
    t_dir, w_dir = best(lambda: tabor.maugis_dugdale_loss(lam3, tolerance=1e-12), 3)
    t_sp, w_sp = best(lambda: np.array([scipy_loss(x) for x in lam3]), 1)
    rel = np.max(np.abs(w_dir / w_sp - 1))
    print(f"3. {m:.0e} direct MD losses: tabor {t_dir * 1e3:9.1f} ms, SciPy brentq+quad "
          f"{t_sp * 1e3:9.1f} ms, ratio SciPy/tabor = {t_sp / t_dir:.0f}  (max rel diff {rel:.1e})")
    print(f"   fast tier against SciPy on the same {m:.0e}: ratio SciPy/tabor-fast = "
          f"{t_sp / best(lambda: tabor.maugis_dugdale_loss(lam3, fast=True), 5)[0]:.0f}")


if __name__ == "__main__":
    main()

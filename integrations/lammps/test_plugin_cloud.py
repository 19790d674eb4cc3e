"""Proof by LAMMPS of pair_style tabor in a polydisperse cloud (issue 21, items 4-5).

A cloud of CLOUD_GRAINS (default 10^4) silica grains, log-normal radii (median
1 um, sigma = 0.3, cut at 3 sigma, every radius distinct: no two equal effective
radii, one law per type pair serves them all), JKR adhesion (load-controlled, as
LAMMPS's jkr) with friction, rolling and twisting (mindlin NULL + sds + marshall),
in a periodic box with LAMMPS's defaults (newton on). The grains sit in rows
along x, 5 nm apart, with random velocities, so thousands of contacts form, stick,
slide and roll within a few hundred steps.

1. MPI: the same run on 1 and on 2 ranks ends with the same set of contacts
   (pairs in contact) and the same positions to round-off (printed); also with
   `tangential mindlin_deresiewicz` (its spring bed in every contact's history).
2. Restart: run STEPS/2, write_restart, read_restart in a new LAMMPS process,
   include the same pair lines again, run STEPS/2; against one straight run of
   STEPS (the plugin without and with micro-slip). (a) Every contact keeps its state across the restart: the contact list
   with each contact's normal and tangential force (compute pair/local, the
   plugin's single() reading the stored history) is the same just before
   write_restart and just after read_restart. (b) The continued run's deviation
   from the straight run is compared with LAMMPS's own pair granular (the same
   models) restarted the same way, which LAMMPS documents as not bit-exact (the
   deviation is round-off amplified by the many-body dynamics, so only its order
   of magnitude is meaningful): the plugin's must stay within 10 times pair
   granular's.
3. History width: switching the pair coefficients from `mindlin` (10 doubles a
   contact) to `mindlin_deresiewicz` (79) between runs, and reading a restart file
   of the narrower layout with the wider, keeps every contact and its normal
   force.

Environment: TABOR_PLUGIN, LAMMPS_VENV; CLOUD_GRAINS, CLOUD_STEPS (default 600).
"""

import math
import os
import random
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from lammps_case import (E, E_STAR, FRICTION, NU, RHO, W, hertz_contact_time, pair_tabor, read_dump,  # noqa: E402
                         report, run_lmp)

GRAINS = int(os.environ.get("CLOUD_GRAINS", "10000"))
STEPS = int(os.environ.get("CLOUD_STEPS", "600"))

# silica grains (lammps_case's RHO, E, NU, W, FRICTION), log-normal radii: median R0, spread SIGMA
R0, SIGMA = 1e-6, 0.3
GAP = 5e-9
SPEED = 0.2            # velocity components uniform in (-SPEED, SPEED) m/s
STEPS_PER_CONTACT = 50  # a DEM time step: the Hertz contact time of two median grains at SPEED / 50

PAIRS = {
    "tabor": pair_tabor(f"pair_coeff * * jkr/load-controlled {E_STAR!r} {W} poisson {NU} {FRICTION}"),
    "granular": ["pair_style granular",
                 f"pair_coeff * * jkr {E} 0 {NU} {W / 2} damping viscoelastic {FRICTION}"],
}
# the plugin with micro-slip: the spring bed of every contact (79 doubles of history)
# must move between ranks and through restart files as the shorter history does
PAIRS["tabor_md"] = [l.replace("tangential mindlin ", "tangential mindlin_deresiewicz ") for l in PAIRS["tabor"]]


def time_step():
    m_star = RHO * 4 / 3 * math.pi * R0 ** 3 / 2
    tc = hertz_contact_time(m_star, R0 / 2, E_STAR, SPEED)
    return tc / STEPS_PER_CONTACT


def make_cloud(path, grains=GRAINS, seed=21):
    """Writes the cloud as a LAMMPS data file (atom_style sphere); returns the radii."""
    rng = random.Random(seed)
    radii = []
    while len(radii) < grains:
        z = rng.gauss(0.0, 1.0)
        if abs(z) <= 3.0:
            radii.append(R0 * math.exp(SIGMA * z))
    assert len(set(radii)) == grains, "radii must all be distinct"
    r_max = max(radii)
    rows = math.ceil(math.sqrt(grains / 100))
    per_row = math.ceil(grains / (rows * rows))
    pitch = 2 * r_max + 4 * GAP
    atoms, lengths, k = [], [], 0
    for a in range(rows):
        for b in range(rows):
            x = 0.0
            for n in range(per_row):
                if k == grains:
                    break
                r = radii[k]
                if n > 0:
                    x += r + GAP
                atoms.append((k + 1, r, x, (a + 0.5) * pitch, (b + 0.5) * pitch))
                x += r
                k += 1
            lengths.append(x)
    lx = max(lengths) + radii[0] + GAP + r_max
    with open(path, "w") as f:
        f.write(f"polydisperse cloud\n\n{grains} atoms\n1 atom types\n\n")
        f.write(f"{-r_max} {lx - r_max} xlo xhi\n0 {rows * pitch} ylo yhi\n0 {rows * pitch} zlo zhi\n")
        f.write("\nAtoms # sphere\n\n")
        for i, r, x, y, z in atoms:
            f.write(f"{i} 1 {2 * r!r} {RHO} {x!r} {y!r} {z!r}\n")
        f.write("\nVelocities\n\n")
        for i, *_ in atoms:
            v = [rng.uniform(-SPEED, SPEED) for _ in range(3)]
            f.write(f"{i} {v[0]!r} {v[1]!r} {v[2]!r} 0 0 0\n")
    return radii


def setup_lines(pair):
    return ["comm_modify vel yes", *PAIRS[pair], f"neighbor {0.3 * R0} bin",
            "neigh_modify every 1 delay 0 check yes", "fix integrate all nve/sphere",
            f"timestep {time_step()!r}"]


CONTACTS = ["compute pl all pair/local force", "compute pp all property/local patom1 patom2",
            "compute pf all pair/local p2"]


def dump_contacts(name):
    # tabor's p2 is the tangential force; granular's p2 is a component of it: both
    # are functions of the stored history
    return [f"dump dc all local 1 {name} c_pp[1] c_pp[2] c_pl c_pf",
            "dump_modify dc format float %.17g", "run 0 post no", "undump dc"]


def lammps(lines, tmp, ranks=1, tag="run"):
    """lammps_case.run_lmp in the argument order of this script and time_*.py."""
    return run_lmp(lines, tmp, tag, ranks)


def read_contacts(path):
    """{(id1, id2): (force, p2)} for pairs with a nonzero force (in contact)."""
    out = {}
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(n for n, l in enumerate(lines) if l.startswith("ITEM: ENTRIES")) + 1
    for l in lines[start:]:
        a, b, force, p2 = l.split()
        if float(force) != 0.0:
            key = (min(int(a), int(b)), max(int(a), int(b)))
            out[key] = (float(force), abs(float(p2)))
    return out


HEAD = ["units si", "atom_style sphere", "atom_modify map array", "boundary p p p"]
FINAL = "write_dump all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g"


def deviation(a, b):
    return max(math.dist(a[i][:3], b[i][:3]) for i in a) / R0


def main():
    failures = []
    with tempfile.TemporaryDirectory(prefix="tabor-cloud-") as tmp:
        data = os.path.join(tmp, "cloud.data")
        radii = make_cloud(data)
        half = STEPS // 2
        print(f"{GRAINS} grains, radii {min(radii):.3e}..{max(radii):.3e} m (all distinct), "
              f"time step {time_step():.3e} s, {STEPS} steps")
        states, contacts = {}, {}
        # 1. the plugin on 1 and 2 ranks (without and with micro-slip)
        for pair in ("tabor", "tabor_md"):
            for ranks in (1, 2):
                dump = os.path.join(tmp, f"{pair}.{ranks}.dump")
                cdump = os.path.join(tmp, f"{pair}.{ranks}.contacts")
                log = lammps([*HEAD, f"read_data {data}", *setup_lines(pair), *CONTACTS,
                              f"run {STEPS}", FINAL.format(dump=dump), *dump_contacts(cdump)],
                             tmp, ranks, f"{pair}{ranks}")
                states[ranks] = read_dump(dump)
                contacts[ranks] = read_contacts(cdump)
                pair_time = next(float(s.split("|")[2]) for s in log.splitlines() if s.startswith("Pair "))
                print(f"  {pair}, {ranks} rank(s): {len(contacts[ranks])} contacts at the end, "
                      f"Pair time {pair_time:.2f} s")
            same = set(contacts[1]) == set(contacts[2])
            dev = deviation(states[1], states[2])
            print(f"  {pair} 1 vs 2 ranks: same contacts {same}, largest position difference {dev:.1e} R0")
            if not same:
                diff = set(contacts[1]) ^ set(contacts[2])
                failures.append(f"{pair} 1 vs 2 ranks: {len(diff)} contacts differ")
            if len(contacts[1]) < GRAINS // 10:
                failures.append(f"{pair}: only {len(contacts[1])} contacts formed: the cloud does not test contacts")
        # 2. restart, plugin and pair granular the same way
        devs = {}
        for pair in ("tabor", "tabor_md", "granular"):
            straight = os.path.join(tmp, f"{pair}.straight.dump")
            lammps([*HEAD, f"read_data {data}", *setup_lines(pair), f"run {STEPS}",
                    FINAL.format(dump=straight)], tmp, 1, f"{pair}.straight")
            restart = os.path.join(tmp, f"{pair}.restart")
            before = os.path.join(tmp, f"{pair}.before")
            after = os.path.join(tmp, f"{pair}.after")
            cont = os.path.join(tmp, f"{pair}.continued.dump")
            lammps([*HEAD, f"read_data {data}", *setup_lines(pair), *CONTACTS, f"run {half}",
                    *dump_contacts(before), f"write_restart {restart}"], tmp, 1, f"{pair}.first")
            lammps([f"read_restart {restart}", *setup_lines(pair), *CONTACTS, *dump_contacts(after),
                    f"run {STEPS - half}", FINAL.format(dump=cont)], tmp, 1, f"{pair}.second")
            cb, ca = read_contacts(before), read_contacts(after)
            kept = set(cb) == set(ca)
            worst = max((abs(ca[k][1] - cb[k][1]) / max(cb[k][1], 1e-300) for k in cb if k in ca and cb[k][1] > 0),
                        default=0.0)
            devs[pair] = deviation(read_dump(straight), read_dump(cont))
            print(f"  {pair:8} restart at step {half}: {len(cb)} contacts before, {len(ca)} after "
                  f"(same set: {kept}; largest relative change of a tangential force {worst:.1e}); "
                  f"continued vs straight run: largest position difference {devs[pair]:.1e} R0")
            if pair != "granular":
                if not kept:
                    failures.append(f"restart: contacts lost or gained ({len(set(cb) ^ set(ca))})")
                if worst > 1e-12:
                    failures.append(f"restart: a tangential force changed by {worst:.1e} (springs must keep their stretch)")
        # 3. the history width changes with the pair coefficients (10 doubles a
        # contact, 79 with mindlin_deresiewicz): in one process (fix tabor/history
        # widened in place) and through a restart file of the narrower layout
        # (read with the bed zero); every contact is kept, with its normal force
        md_coeff = next(l for l in PAIRS["tabor_md"] if l.startswith("pair_coeff"))
        before = os.path.join(tmp, "width.before")
        after = os.path.join(tmp, "width.after")
        restart = os.path.join(tmp, "width.restart")
        lammps([*HEAD, f"read_data {data}", *setup_lines("tabor"), *CONTACTS, f"run {half}",
                *dump_contacts(before), f"write_restart {restart}", md_coeff, *dump_contacts(after)],
               tmp, 1, "width.inplace")
        cb, ca = read_contacts(before), read_contacts(after)
        same_normal = all(ca[k][0] == cb[k][0] for k in cb if k in ca)
        print(f"  width 10 -> 79 in place: {len(cb)} contacts before, {len(ca)} after "
              f"(same set: {set(cb) == set(ca)}, same normal forces: {same_normal})")
        if set(cb) != set(ca) or not same_normal:
            failures.append("width change in place: contacts or normal forces lost")
        reread = os.path.join(tmp, "width.reread")
        lammps([f"read_restart {restart}", *setup_lines("tabor_md"), *CONTACTS, *dump_contacts(reread)],
               tmp, 1, "width.restart")
        cr = read_contacts(reread)
        same_normal = all(cr[k][0] == cb[k][0] for k in cb if k in cr)
        print(f"  restart of width 10 read with width 79: {len(cr)} contacts "
              f"(same set: {set(cb) == set(cr)}, same normal forces: {same_normal})")
        if set(cb) != set(cr) or not same_normal:
            failures.append("restart of the narrower layout: contacts or normal forces lost")
        for pair in ("tabor", "tabor_md"):
            if devs[pair] > 10 * devs["granular"] + 1e-12:
                failures.append(f"restart: the plugin's ({pair}) continued run deviates by {devs[pair]:.1e} R0, "
                                f"over 10 times pair granular's {devs['granular']:.1e} R0")
    return report(failures, "plugin cloud tests passed")


if __name__ == "__main__":
    sys.exit(main())

"""Proof by LAMMPS of pair_style tabor (the plugin of issue 17).

1. Two-sphere collisions with the plugin reproduce tabor's quasi-static
   restitution (`tabor impact`) within 1e-3, for JKR with both separation rules and
   Maugis-Dugdale across Lambda in each of its three cases, at two speeds each.
2. The most tensile force during each collision (LAMMPS's force on atom 2, min
   over all steps) equals the model's pull-off force (tabor_law_info) within 1 %.
   The same with the fragment that `tabor export lammps SCENE --plugin PATH`
   writes (`exported()`): Maugis-Dugdale case 2 and the adhesive Kelvin-Voigt
   polymer grains (JKR + Kuwabara-Kono damping A = eta_c/E*, tabor's coupled
   viscous-adhesive model).
3. A few hundred particles (isolated pairs colliding across the boundary between
   two MPI sub-domains and drifting through it while in contact) give the same
   outcomes, stuck or separated, on 1 and 2 MPI ranks.

Needs TABOR (tabor binary), TABOR_PLUGIN (taborplugin.so), TABOR_FFI_LIB
(libtabor_ffi.so), LAMMPS_VENV, LD_LIBRARY_PATH=<venv>/lib. Time steps are fixed
fractions of the Hertz contact time; nothing depends on wall-clock time.
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from collide import rebound  # noqa: E402
from lammps_case import (FFI, PLUGIN, ROOT, VENV, commands, export_plugin, load_scene, lmp_exe, lmp_new,  # noqa: E402
                         report, tabor_restitution, write_toml)
from tabor_ffi import law_info  # noqa: E402

STEPS_PER_CONTACT = 20000
RESTITUTION_TOL = 1e-3
PULLOFF_TOL = 0.01


def tabor_impact(scene, speed):
    path = write_toml(scene, ("sphere", "target", "adhesion", "impact"))
    try:
        return tabor_restitution(path, speed)
    finally:
        os.unlink(path)


def exported(path):
    """The fragment `tabor export lammps PATH --plugin PLUGIN` writes (its commands,
    comments dropped) and the same export as JSON."""
    return commands(export_plugin(path)), json.loads(export_plugin(path, "--json"))


def pair_coeff(scene):
    sp, ad = scene["sphere"], scene["adhesion"]
    e_star = sp["youngs_modulus"] / (2.0 * (1.0 - sp["poisson_ratio"] ** 2))
    w = ad["work_of_adhesion"]
    if "tabor_parameter" in ad:
        return "maugis", e_star, f"pair_coeff * * maugis {e_star!r} {w!r} {ad['tabor_parameter']!r}", ad["tabor_parameter"]
    model = "jkr/" + ad.get("separation", "fixed-grip")
    return model, e_star, f"pair_coeff * * {model} {e_star!r} {w!r}", 0.0


def setup(lmp, cmds):
    for c in cmds:
        lmp.command(c)


def collide(scene, speed, fragment=None):
    """Two equal spheres in their centre-of-mass frame; returns (e, min force, info).
    `fragment`: the commands of an exported fragment instead of the hand-written
    plugin load / pair_style / pair_coeff / neighbor lines."""
    r, rho = scene["sphere"]["radius"], scene["sphere"]["density"]
    model, e_star, coeff, lam = pair_coeff(scene)
    r_star = r / 2.0
    info = law_info(FFI, model, e_star, r_star, scene["adhesion"]["work_of_adhesion"], lam)
    plugin_cmds = fragment or [f"plugin load {PLUGIN}", "pair_style tabor", coeff,
                               f"neighbor {0.2 * r} bin", "neigh_modify every 1 delay 0 check yes"]
    m_star = rho * 4.0 / 3.0 * math.pi * r ** 3 / 2.0
    tc = 2.87 * (m_star ** 2 / (r_star * e_star ** 2 * speed)) ** 0.2
    dt = tc / STEPS_PER_CONTACT
    rng = info.interaction_range
    gap0 = rng + 20 * speed * dt
    lmp = lmp_new()
    try:
        setup(lmp, [
            "units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            "newton off", "comm_modify vel yes",
            f"region box block {-40 * r} {40 * r} {-40 * r} {40 * r} {-40 * r} {40 * r}",
            "create_box 1 box",
            f"create_atoms 1 single {-(r + gap0 / 2)} 0 0",
            f"create_atoms 1 single {r + gap0 / 2} 0 0",
            f"set atom * diameter {2 * r} density {rho}",
            f"set atom 1 vx {speed / 2}", f"set atom 2 vx {-speed / 2}",
            *plugin_cmds,
            "fix integrate all nve/sphere", f"timestep {dt}",
            "variable vrel equal vx[2]-vx[1]", f"variable gap equal x[2]-x[1]-{2 * r}",
            "variable fx2 equal fx[2]", "fix fv all vector 1 v_fx2",
            "variable fmin equal min(f_fv)",
        ])
        e, _ = rebound(lmp, gap0, speed, tc, STEPS_PER_CONTACT, rng, 200)
        # fmin: the tensile force on atom 2 (pulled towards -x) is negative
        return e, lmp.extract_variable("fmin"), info
    finally:
        lmp.close()


CASES = [  # (scene, adhesion overrides, label)
    ("jkr_fixed_grip", {}, "JKR fixed grip"),
    ("jkr_load_controlled", {}, "JKR load controlled"),
    ("maugis_case1", {"tabor_parameter": 0.1}, "MD case 1, Lambda 0.1"),
    ("maugis_case1", {}, "MD case 1, Lambda 0.3"),
    ("maugis_case2", {"tabor_parameter": 0.5}, "MD case 2, Lambda 0.5"),
    ("maugis_case2", {}, "MD case 2, Lambda 0.55"),
    ("maugis_case3", {"tabor_parameter": 1.0}, "MD case 3, Lambda 1.0"),
    ("maugis_case3", {}, "MD case 3, Lambda 1.5"),
    ("maugis_case3", {"tabor_parameter": 5.0}, "MD case 3, Lambda 5"),
]


def two_body():
    failures = []
    print(f"{'case':26} {'v (m/s)':>9} {'e LAMMPS':>9} {'e tabor':>9} {'diff':>9} {'Fmin/Fpo-1':>11}")
    for name, over, label in CASES:
        scene = load_scene(name, **over)
        v0 = scene["impact"]["speed"]
        for v in (v0, 2.5 * v0):
            e_t = tabor_impact(scene, v)
            e_l, fmin, info = collide(scene, v)
            diff = e_l - e_t
            ratio = fmin / info.pull_off_force - 1.0
            print(f"{label:26} {v:9.4f} {e_l:9.6f} {e_t:9.6f} {diff:+9.2e} {ratio:+11.2e}")
            if abs(diff) > RESTITUTION_TOL:
                failures.append(f"{label} at {v}: e LAMMPS {e_l:.6f} vs tabor {e_t:.6f}")
            if e_t > 0 and abs(ratio) > PULLOFF_TOL:
                failures.append(f"{label} at {v}: most tensile force {fmin:.4e} vs pull-off {info.pull_off_force:.4e}")
    return failures


EXPORTED = [  # (scene path, speeds, label); the fragment of `tabor export lammps --plugin`
    ("integrations/lammps/scenes/maugis_case2.toml", (0.08, 0.20), "exported: MD case 2, Lambda 0.55"),
    ("examples/scenes/polymer_grains_viscoadhesive.toml", (1.0, 2.0), "exported: JKR + Kelvin-Voigt"),
]


def exported_cases():
    """Two-body collisions run with the exported fragment, against `tabor impact`."""
    failures = []
    for rel, speeds, label in EXPORTED:
        path = os.path.join(ROOT, rel)
        cmds, data = exported(path)
        with open(path, "rb") as f:
            scene = tomllib.load(f)
        scene.setdefault("adhesion", {"work_of_adhesion": 0.0})
        for v in speeds:
            e_t = tabor_restitution(path, v)
            e_l, fmin, _ = collide(scene, v, fragment=cmds)
            diff = e_l - e_t
            # without damping the most tensile force is the law's pull-off force
            ratio = fmin / data["pull_off_force"] - 1.0 if data["pull_off_force"] < 0 else 0.0
            print(f"{label:26} {v:9.4f} {e_l:9.6f} {e_t:9.6f} {diff:+9.2e} {ratio:+11.2e}")
            if abs(diff) > RESTITUTION_TOL:
                failures.append(f"{label} at {v}: e LAMMPS {e_l:.6f} vs tabor {e_t:.6f}")
            if data["damping_time"] is None and e_t > 0 and abs(ratio) > PULLOFF_TOL:
                failures.append(f"{label} at {v}: most tensile force {fmin:.4e} vs pull-off {data['pull_off_force']:.4e}")
    return failures


MPI_INPUT = """units si
atom_style sphere
atom_modify map array
boundary p p p
newton off
comm_modify vel yes
processors * 1 1
region box block {lo} {hi} {lo} {hi} {zlo} {zhi}
create_box 1 box
{atoms}
set atom * diameter {d} density {rho}
{velocities}
plugin load {plugin}
pair_style tabor
{coeff}
neighbor {skin} bin
neigh_modify every 1 delay 0 check yes
fix integrate all nve/sphere
timestep {dt}
run {steps}
write_dump all custom {dump} id x y z vx vy vz modify sort id
"""


def many_particles(npairs=120):
    """npairs pairs on a line along y, each colliding along y at x just left of the
    sub-domain boundary x = 0 of 2 ranks and drifting along +x, so every pair
    crosses to the other rank while in contact (or after rebounding)."""
    scene = load_scene("maugis_case2")
    r, rho = scene["sphere"]["radius"], scene["sphere"]["density"]
    model, e_star, coeff, lam = pair_coeff(scene)
    info = law_info(FFI, model, e_star, r / 2, scene["adhesion"]["work_of_adhesion"], lam)
    # the sticking speed from tabor: bisection on `tabor impact`
    lo, hi = 0.001, 1.0
    for _ in range(30):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if tabor_impact(scene, mid) == 0.0 else (lo, mid)
    v_c = hi
    m_star = rho * 4.0 / 3.0 * math.pi * r ** 3 / 2.0
    vmax = 2.0 * v_c
    tc = 2.87 * (m_star ** 2 / (r / 2 * e_star ** 2 * vmax)) ** 0.2
    dt = tc / 2000
    drift = 20.0 * v_c
    gap0 = info.interaction_range + 2e-3 * r
    # speeds 0.5 v_c .. 2 v_c, skipping +-5 % around v_c (where rounding decides)
    speeds = []
    k = 0
    while len(speeds) < npairs:
        v = v_c * 0.5 * 4.0 ** (((k * 0.618034) % 1.0))
        k += 1
        if abs(v / v_c - 1.0) > 0.05:
            speeds.append(v)
    spacing = 6 * r
    ylen = npairs * spacing
    atoms, vels = [], []
    t_hit = gap0 / min(speeds)
    x0 = -0.3 * r
    for n, v in enumerate(speeds):
        yc = -ylen / 2 + (n + 0.5) * spacing
        x = x0 - drift * gap0 / v  # at contact the centre is at x0
        atoms.append(f"create_atoms 1 single {x!r} {yc - r - gap0 / 2!r} 0")
        atoms.append(f"create_atoms 1 single {x!r} {yc + r + gap0 / 2!r} 0")
        vels.append(f"set atom {2 * n + 1} vx {drift!r} vy {v / 2!r}")
        vels.append(f"set atom {2 * n + 2} vx {drift!r} vy {-v / 2!r}")
    # run until contact + the drift of 0.4 radii (both atoms past the boundary)
    steps = int((t_hit + 0.4 * r / drift) / dt) + 1
    results = {}
    for ranks in (1, 2):
        with tempfile.TemporaryDirectory() as tmp:
            dump = os.path.join(tmp, "final.dump")
            inp = os.path.join(tmp, "in.pairs")
            with open(inp, "w") as f:
                f.write(MPI_INPUT.format(
                    lo=-ylen / 2 - 10 * r, hi=ylen / 2 + 10 * r, zlo=-4 * r, zhi=4 * r,
                    atoms="\n".join(atoms), d=2 * r, rho=rho, velocities="\n".join(vels),
                    plugin=PLUGIN, coeff=coeff, skin=0.2 * r, dt=dt, steps=steps, dump=dump))
            cmd = [os.path.join(VENV, "bin", "mpirun"), "-np", str(ranks), lmp_exe(),
                   "-in", inp, "-log", "none", "-nocite", "-screen", "none"]
            subprocess.run(cmd, check=True, cwd=tmp)
            with open(dump) as f:
                rows = [l.split() for l in f.read().splitlines()[9:]]
            pos = {int(r_[0]): (float(r_[1]), float(r_[2])) for r_ in rows}
        outcome = []
        crossed = 0
        for n in range(npairs):
            a, b = pos[2 * n + 1], pos[2 * n + 2]
            gap = abs(b[1] - a[1]) - 2 * r
            outcome.append("stuck" if gap < info.interaction_range else "separated")
            crossed += a[0] > 0 and b[0] > 0
        results[ranks] = (outcome, crossed)
    o1, c1 = results[1]
    o2, c2 = results[2]
    expected = ["stuck" if v < v_c else "separated" for v in speeds]
    same = sum(a == b for a, b in zip(o1, o2))
    agree_tabor = sum(a == b for a, b in zip(o2, expected))
    print(f"{2 * npairs} particles: v_c (tabor) = {v_c:.5f} m/s; stuck on 1 rank {o1.count('stuck')}, "
          f"on 2 ranks {o2.count('stuck')}; identical outcomes {same}/{npairs}; "
          f"as tabor's v_c predicts {agree_tabor}/{npairs}; pairs that crossed the rank boundary {c2}/{npairs}")
    failures = []
    if same != npairs:
        failures.append(f"1 vs 2 ranks: {npairs - same} pairs differ")
    if agree_tabor != npairs:
        failures.append(f"{npairs - agree_tabor} outcomes differ from tabor's sticking velocity")
    if c2 < npairs:
        failures.append(f"only {c2}/{npairs} pairs crossed the rank boundary")
    return failures


def main():
    failures = two_body()
    failures += exported_cases()
    sys.stdout.flush()
    failures += many_particles()
    return report(failures, "plugin tests passed")


if __name__ == "__main__":
    sys.exit(main())

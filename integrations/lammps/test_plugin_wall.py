"""Proof by LAMMPS of fix wall/tabor (issue 31): a sphere on a flat wall.

1. Normal impacts against `tabor impact` on a flat target (R* = R, E* of sphere and
   wall, m* = m): JKR with both separation rules and Maugis-Dugdale at Lambda =
   0.3, 0.55, 2, at 0.5, 1.5 and 4 times the sticking velocity of `tabor sticking`
   (stuck below it: e = 0 in both). Also the wall fix as the fragment of
   `tabor export lammps SCENE --plugin PATH` writes it, included exactly as its
   header says.
2. Oblique impacts with friction, rolling and twisting (initial spins about the
   wall's normal and in its plane): `jkr/load-controlled` + `tangential mindlin NULL`
   + `rolling sds` + `twisting marshall` against LAMMPS's own `fix wall/gran
   granular jkr ... tangential mindlin NULL ... rolling sds ... twisting marshall`
   (the JKR limit: the same discrete scheme), and against `tabor impact --angle` on
   a flat (continuous time).
3. Restart: particles stuck to the wall and sliding on it; write_restart in the
   middle, read_restart in a new process, the same fix again: (a) the wall forces
   and torques of a `run 0` just before write_restart and just after read_restart
   are identical (the histories came back); (b) the continued run against the
   straight run, measured the same way for fix wall/gran granular (LAMMPS's own).
5. Wall motion (wiggle, shear) against fix wall/gran in the JKR limit;
   wall/tabor/region on a face of a block against the plane, and in its corner
   (two contacts at once, each with its history: a symmetric rebound); the
   zcylinder against a plane (a flat for the law).
4. MPI: particles sliding and stuck on the wall, drifting across the boundary of
   two sub-domains while in contact, on 1 and 2 ranks: the same final state (the
   wall force is per atom, so the same to the last bit when the histories travel
   with the atoms); also with `tangential mindlin_deresiewicz` (79 doubles a contact).
7. `tangential mindlin_deresiewicz` (the 32-spring bed of the plugin) against
   `tabor impact --angle` on a flat whose [friction] has tangential =
   "mindlin_deresiewicz" (the library's 1024-node bed), JKR, 0.3 and 1 m/s, angles
   spanning MBF's Psi = kappa tan(a)/mu = 0.3 to 8, within the time-step tolerance
   alone (the beds differ by at most 4e-4 in beta over Psi 0.1-10,
   crates/tabor-tangential/tests/micro_slip_step.rs: 4e-4 v_t0, below a tenth of
   tol_v here). The restart of 3 runs with it too (the bed written and read back in
   the middle of partial slip: 0 < |F_t| < mu F_n0), and a restart record of the
   other width: the 10 doubles of a mindlin contact read by a mindlin_deresiewicz
   wall keep every contact and its normal force; a 79-double record with a
   stretched bed read by a mindlin wall is refused with a clear error.

Tolerances, from the time step dt = t_c/STEPS (t_c the Hertz contact time, seed 000
(5.12)), as test_plugin_friction.py derives them: velocity Verlet is exact to
O(dt^2) between the events of a contact (jump-in, snap-off, stick/slip), and an
event can fall one step apart in two schemes, which changes the rebound velocity by
at most one step's impulse dt F/m and a spin by dt T/I; with F bounded by F_scale =
F_Hertz,max(v) + 2 |F_pulloff| and T by (mu R + mu_roll R + (2/3) mu a_max) F_scale,
tol_v = EVENTS dt F_scale/m, tol_w = EVENTS dt T_scale/I, EVENTS = 2 (restitution:
tol_v / v), against tabor's library and against fix wall/gran alike (which, in the
JKR limit, runs the same discrete scheme: the differences printed are round-off).

Needs TABOR, TABOR_PLUGIN, TABOR_FFI_LIB, LAMMPS_VENV, LD_LIBRARY_PATH=<venv>/lib.
"""

import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from lammps_case import (E, E_STAR, FFI, FRICTION, K_ROLL, MASS, MU, MU_ROLL, NU, R, RHO, SCENES, VENV, W,  # noqa: E402
                         export_plugin, force_scale, hertz_contact_time, hertz_overlap, lmp_exe, lmp_new, load_scene,
                         plugin_load, read_dump, report, run_lmp, tabor_json, write_temp, write_toml)
from tabor_ffi import law_info  # noqa: E402

STEPS = 5000            # steps per Hertz contact time
EVENTS = 2
# a silica sphere on a silica wall (lammps_case's R, RHO, E, NU, W); m* = m, R* = R
INERTIA = 0.4 * MASS * R ** 2
TABOR_JKR = f"jkr/load-controlled {E_STAR!r} {W} poisson {NU} {FRICTION}"
# LAMMPS's own: jkr E eta_n0 nu gamma (gamma = w/2), wall of the particle's material
GRANULAR_JKR = f"granular jkr {E} 0 {NU} {W / 2} damping viscoelastic {FRICTION}"
TABOR_MD = f"jkr/load-controlled {E_STAR!r} {W} poisson {NU} tangential mindlin_deresiewicz NULL 0 {MU}"


def plugin_wall(coeffs, extra=""):
    return [plugin_load(), f"fix wall all wall/tabor {coeffs} zplane 0.0 NULL {extra}".rstrip()]


def granular_wall(extra=""):
    return [f"fix wall all wall/gran {GRANULAR_JKR} zplane 0.0 NULL {extra}".rstrip()]


def contact_time(v):
    return hertz_contact_time(MASS, R, E_STAR, v)


def f_scale(v, pull_off):
    return force_scale(MASS, R, E_STAR, v, pull_off)


def wall_collide(wall_cmds, v, dt, reach, angle=0.0, spin=(0.0, 0.0, 0.0), max_steps=None):
    """One sphere onto the wall z = 0 at speed v, `angle` degrees from the normal
    (velocity (v sin a, 0, -v cos a)); the undisturbed path touches the wall after
    exactly `approach` steps, 20 more than it takes to cross `reach`. Runs until
    the sphere has left the reach receding (or `max_steps`: stuck). Returns
    (velocity, angular velocity, separated)."""
    a = math.radians(angle)
    vn, vt = v * math.cos(a), v * math.sin(a)
    approach = 20 + math.ceil(reach / (vn * dt))
    s = approach * dt
    tc = contact_time(v)
    chunk = int(math.ceil(tc / dt))
    max_steps = max_steps or 40 * chunk
    span = 40 * R + 2 * s * v
    lmp = lmp_new()
    try:
        for c in ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
                  f"region box block {-span} {span} {-span} {span} {-span} {span}", "create_box 1 box",
                  f"create_atoms 1 single {-s * vt!r} 0 {R + s * vn!r}",
                  f"set atom 1 diameter {2 * R!r} density {RHO!r}",
                  f"set atom 1 vx {vt!r} vy 0 vz {-vn!r}",
                  f"set atom 1 omega {spin[0]!r} {spin[1]!r} {spin[2]!r}",
                  *wall_cmds, "fix integrate all nve/sphere", f"timestep {dt!r}",
                  f"run {approach}"]:
            lmp.command(c)
        done = 0
        while done < max_steps:
            lmp.command(f"run {chunk}")
            done += chunk
            x, vv = lmp.extract_atom("x"), lmp.extract_atom("v")
            if x[0][2] - R > reach and vv[0][2] > 0:
                break
        x, vv, w = (lmp.extract_atom(n) for n in ("x", "v", "omega"))
        separated = x[0][2] - R > reach and vv[0][2] > 0
        return [vv[0][k] for k in range(3)], [w[0][k] for k in range(3)], separated
    finally:
        lmp.close()


NORMAL = [  # (scene, adhesion overrides, wall coefficients, label)
    ("jkr_wall", {}, f"jkr/fixed-grip {E_STAR!r} {W}", "JKR fixed grip"),
    ("jkr_wall", {"separation": "load-controlled"}, f"jkr/load-controlled {E_STAR!r} {W}", "JKR load controlled"),
    ("maugis_wall", {"tabor_parameter": 0.3}, f"maugis {E_STAR!r} {W} 0.3", "MD Lambda 0.3"),
    ("maugis_wall", {}, f"maugis {E_STAR!r} {W} 0.55", "MD Lambda 0.55"),
    ("maugis_wall", {"tabor_parameter": 2.0}, f"maugis {E_STAR!r} {W} 2.0", "MD Lambda 2"),
]


def normal_impacts():
    failures = []
    print(f"{'case':22} {'v/v_s':>5} {'v (m/s)':>9} {'e LAMMPS':>9} {'e tabor':>9} {'|diff|':>9} {'tol':>8}")
    for name, over, coeffs, label in NORMAL:
        s = load_scene(name, **over)
        path = write_toml(s)
        try:
            v_s = tabor_json(["sticking", path])["sticking_velocity"]
            model = coeffs.split()[0]
            info = law_info(FFI, model, E_STAR, R, W, s["adhesion"].get("tabor_parameter", 0.0))
            for ratio in (0.5, 1.5, 4.0):
                v = ratio * v_s
                o = tabor_json(["impact", path, "--speed", repr(v)])
                e_t = 0.0 if o["sticks"] else o["restitution"]
                dt = contact_time(v) / STEPS
                vel, _, sep = wall_collide(plugin_wall(coeffs), v, dt, info.interaction_range)
                e_l = vel[2] / v if sep else 0.0
                tol = EVENTS * dt * f_scale(v, info.pull_off_force) / MASS / v
                diff = abs(e_l - e_t)
                print(f"{label:22} {ratio:5.1f} {v:9.5f} {e_l:9.6f} {e_t:9.6f} {diff:9.2e} {tol:8.1e}")
                if diff > tol or (ratio < 1.0) != (e_t == 0.0) or (e_l == 0.0) != (e_t == 0.0):
                    failures.append(f"{label} at {ratio} v_s: e LAMMPS {e_l:.6f} vs tabor {e_t:.6f} (tol {tol:.1e})")
        finally:
            os.unlink(path)
    return failures


def exported_fragment():
    """The fragment of `tabor export lammps SCENE --plugin PATH` for a flat target,
    included as its header says (after create_box, before the run), against
    `tabor impact` at the scene's speed."""
    failures = []
    path = os.path.join(SCENES, "maugis_wall.toml")
    frag = export_plugin(path)
    v = 2.0 * tabor_json(["sticking", path])["sticking_velocity"]
    o = tabor_json(["impact", path, "--speed", repr(v)])
    info = law_info(FFI, "maugis", E_STAR, R, W, 0.55)
    dt = contact_time(v) / STEPS
    inc = write_temp(frag, ".lmp")
    try:
        vel, _, sep = wall_collide([f"include {inc}"], v, dt, info.interaction_range)
    finally:
        os.unlink(inc)
    e_l = vel[2] / v if sep else 0.0
    tol = EVENTS * dt * f_scale(v, info.pull_off_force) / MASS / v
    print(f"exported fragment (maugis_wall.toml) at {v:.5f} m/s: e LAMMPS {e_l:.6f}, tabor "
          f"{o['restitution']:.6f}, |diff| {abs(e_l - o['restitution']):.2e} (tol {tol:.1e})")
    if abs(e_l - o["restitution"]) > tol:
        failures.append(f"exported fragment: e {e_l:.6f} vs tabor {o['restitution']:.6f}")
    return failures


OBLIQUE = [  # (speed, angle, spin): spins about the normal (twisting) and in-plane (rolling)
    (0.3, 10.0, (0.0, 0.0, 0.0)), (0.3, 45.0, (0.0, 0.0, 0.0)), (0.3, 80.0, (0.0, 0.0, 0.0)),
    (1.0, 30.0, (0.0, 0.0, 3e4)), (1.0, 60.0, (2e4, -1e5, 5e4)), (0.05, 20.0, (0.0, 2e4, 1e4)),
]


def tolerances(v, pull_off):
    dt = contact_time(v) / STEPS
    fs = f_scale(v, pull_off)
    d_max = hertz_overlap(MASS, R, E_STAR, v)
    a_max = math.sqrt(R * d_max) * 1.5   # JKR's contact radius exceeds Hertz's: margin 1.5
    ts = (MU * R + MU_ROLL * R + 2 / 3 * MU * a_max) * fs
    return EVENTS * dt * fs / MASS, EVENTS * dt * ts / INERTIA


def oblique():
    failures = []
    pull = law_info(FFI, "jkr/load-controlled", E_STAR, R, W).pull_off_force
    reach = law_info(FFI, "jkr/load-controlled", E_STAR, R, W).interaction_range
    print(f"{'v':>5} {'angle':>5} {'spin':>18} {'|du| tabor-gran':>15} {'|dw| tabor-gran':>15} {'tol v':>8} {'tol w':>8}")
    for v, a, spin in OBLIQUE:
        dt = contact_time(v) / STEPS
        ut, wt, st = wall_collide(plugin_wall(TABOR_JKR), v, dt, reach, a, spin)
        ug, wg, sg = wall_collide(granular_wall(), v, dt, reach, a, spin)
        du = math.dist(ut, ug)
        dw = math.dist(wt, wg)
        tol_v, tol_w = tolerances(v, pull)
        print(f"{v:5.2f} {a:5.0f} {str(spin):>18} {du:15.2e} {dw:15.2e} {tol_v:8.1e} {tol_w:8.1e}"
              f"{'' if st == sg else '  separation differs'}")
        if du > tol_v or dw > tol_w or st != sg:
            failures.append(f"oblique v {v} angle {a} spin {spin}: tabor vs wall/gran du {du:.2e} "
                            f"(tol {tol_v:.1e}), dw {dw:.2e} (tol {tol_w:.1e})")
    # against the library on a flat (tabor impact --angle), no initial spin
    s = load_scene("jkr_wall", separation="load-controlled")
    s["friction"] = {"coefficient": MU, "tangential": "mindlin", "tangential_damping": 0.0,
                     "rolling": {"stiffness": K_ROLL, "damping": 0.0, "coefficient": MU_ROLL},
                     "twisting": "marshall"}
    path = write_toml(s)
    try:
        print(f"{'library':>7} {'v':>5} {'angle':>5} {'|du| tabor-lib':>14} {'tol v':>8} {'|dw| tabor-lib':>14} {'tol w':>8}")
        # angles at which the sphere rebounds (at 0.3 m/s and 80 degrees it sticks and rolls on)
        for v, a in ((0.3, 10.0), (0.3, 45.0), (0.3, 70.0), (1.0, 30.0), (1.0, 80.0)):
            o = tabor_json(["impact", path, "--speed", repr(v), "--angle", repr(a)])
            after = o["after"]["sphere"]
            u, w, sep = wall_collide(plugin_wall(TABOR_JKR), v, contact_time(v) / STEPS, reach, a)
            # LAMMPS -> tabor's frame: x_t = -z, y_t = x, z_t = -y
            du = math.dist([-u[2], u[0], -u[1]], after["velocity"])
            dw = math.dist([-w[2], w[0], -w[1]], after["angular_velocity"])
            tol_v, tol_w = tolerances(v, pull)
            print(f"{'':7} {v:5.2f} {a:5.0f} {du:14.2e} {tol_v:8.1e} {dw:14.2e} {tol_w:8.1e}")
            if o["sticks"] or not sep:
                failures.append(f"library v {v} angle {a}: sticks (tabor {o['sticks']}, LAMMPS {not sep}): "
                                "choose a case that rebounds")
            elif du > tol_v or dw > tol_w:
                failures.append(f"library v {v} angle {a}: du {du:.2e} (tol {tol_v:.1e}), dw {dw:.2e} (tol {tol_w:.1e})")
    finally:
        os.unlink(path)
    return failures


def micro_slip_wall():
    """`tangential mindlin_deresiewicz` on the wall against `tabor impact --angle` on
    a flat with the library's micro-slip bed (docstring, item 7). Tolerances: the
    time-step ones, EVENTS dt F_scale/m and EVENTS dt mu R F_scale/I (no rolling or
    twisting here)."""
    failures = []
    law = law_info(FFI, "jkr/load-controlled", E_STAR, R, W)
    s = load_scene("jkr_wall", separation="load-controlled")
    s["friction"] = {"coefficient": MU, "tangential": "mindlin_deresiewicz"}
    path = write_toml(s)
    kappa = 2 * (1 - NU) / (2 - NU)
    print(f"{'v':>5} {'Psi':>4} {'angle':>6} {'beta wall':>9} {'beta lib':>9} {'|du|':>8} {'tol v':>8} {'|dw|':>8} {'tol w':>8}")
    worst = 0.0
    try:
        for v in (0.3, 1.0):
            dt = contact_time(v) / STEPS
            fs = f_scale(v, law.pull_off_force)
            tol_v, tol_w = EVENTS * dt * fs / MASS, EVENTS * dt * MU * R * fs / INERTIA
            for psi in (0.3, 1.0, 2.5, 8.0):
                a = math.degrees(math.atan(psi * MU / kappa))
                o = tabor_json(["impact", path, "--speed", repr(v), "--angle", repr(a)])
                after = o["after"]["sphere"]
                u, w, sep = wall_collide(plugin_wall(TABOR_MD), v, dt, law.interaction_range, a)
                ut, wt = [-u[2], u[0], -u[1]], [-w[2], w[0], -w[1]]   # LAMMPS -> tabor's frame
                du, dw = math.dist(ut, after["velocity"]), math.dist(wt, after["angular_velocity"])
                vt0 = v * math.sin(math.radians(a))
                # tangential restitution of the contact point (tabor's frame: tangent y, normal x)
                beta = [-(x[1] + R * y[2]) / vt0 for x, y in ((ut, wt), (after["velocity"], after["angular_velocity"]))]
                print(f"{v:5.2f} {psi:4.1f} {a:6.2f} {beta[0]:+9.5f} {beta[1]:+9.5f} {du:8.1e} {tol_v:8.1e} {dw:8.1e} {tol_w:8.1e}")
                worst = max(worst, du / tol_v, dw / tol_w)
                if o["sticks"] or not sep:
                    failures.append(f"micro-slip wall v {v} Psi {psi}: sticks (tabor {o['sticks']}, LAMMPS {not sep})")
                elif du > tol_v or dw > tol_w:
                    failures.append(f"micro-slip wall v {v} Psi {psi}: du {du:.2e} (tol {tol_v:.1e}), "
                                    f"dw {dw:.2e} (tol {tol_w:.1e})")
    finally:
        os.unlink(path)
    print(f"  largest difference {worst:.2f} of the time-step tolerance")
    return failures


DUMP = "write_dump all custom {p} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g"


def bed(n_stuck, n_sliding, span):
    """Atoms of a bed on the wall z = 0: n_stuck dropped at 0.3 of the JKR sticking
    velocity, n_sliding dropped as slowly with a tangential speed and spins, all
    within 1/4 of a radius of touching, spread along x over [-span, span]."""
    lines, k = [], 0
    n = n_stuck + n_sliding
    for i in range(n):
        k += 1
        x = -span + 2 * span * (i + 0.5) / n
        y = 3 * R * (i % 3 - 1)
        lines += [f"create_atoms 1 single {x!r} {y!r} {R * 1.002!r}"]
        # sliding atoms move towards x = 0 (the boundary of two sub-domains)
        vt = (0.0, 0.0) if i < n_stuck else (-math.copysign(0.5 + 0.1 * i, x), 0.2 * (i % 2))
        spin = (0.0, 0.0, 0.0) if i < n_stuck else (1e4, -2e4, 3e4 * (1 + i % 2))
        lines += [f"set atom {k} vx {vt[0]!r} vy {vt[1]!r} vz -0.03",
                  f"set atom {k} omega {spin[0]!r} {spin[1]!r} {spin[2]!r}"]
    return lines


def setup_lines(wall, n_stuck, n_sliding, span, processors=None, skin=0.2 * R):
    return ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            *([f"processors {processors}"] if processors else []),
            f"region box block {-span - 10 * R} {span + 10 * R} {-10 * R} {10 * R} {-2 * R} {20 * R}",
            "create_box 1 box", *bed(n_stuck, n_sliding, span),
            f"set group all diameter {2 * R!r} density {RHO!r}",
            "comm_modify vel yes", f"neighbor {skin!r} bin", "neigh_modify every 1 delay 0 check yes",
            *wall, "fix integrate all nve/sphere",
            f"timestep {contact_time(0.03) / 200!r}"]


def restart():
    """Stuck and sliding particles on the wall, restarted in the middle."""
    failures = []
    steps, half = 4000, 2000
    span = 20 * R
    devs = {}
    with tempfile.TemporaryDirectory(prefix="tabor-wall-restart-") as tmp:
        # the region variant too (its wall contacts carry the surface they touch;
        # read_restart does not restore regions: defined again, as the fix)
        region_box = f"region plate block {-span - 10 * R!r} {span + 10 * R!r} {-10 * R!r} {10 * R!r} 0 {20 * R!r}"
        region_fix = f"fix wall all wall/tabor/region {TABOR_JKR} plate contacts"
        load = plugin_load()
        md = plugin_wall(TABOR_MD, "contacts")
        for kind, wall, reread in (("tabor", plugin_wall(TABOR_JKR, "contacts"), plugin_wall(TABOR_JKR, "contacts")),
                                   ("granular", granular_wall("contacts"), granular_wall("contacts")),
                                   ("region", [region_box, load, region_fix], [region_box, load, region_fix]),
                                   ("slip", md, md), ("widened", plugin_wall(TABOR_JKR, "contacts"), md)):
            straight = os.path.join(tmp, f"{kind}.straight")
            run_lmp([*setup_lines(wall, 3, 5, span), f"run {steps}", DUMP.format(p=straight)], tmp, f"{kind}.s")
            rst = os.path.join(tmp, f"{kind}.restart")
            snap = "write_dump all custom {p} id f_wall[1] f_wall[2] f_wall[3] f_wall[4] f_wall[5] f_wall[6] f_wall[7] " \
                   "modify sort id format float %.17g"
            before, after = os.path.join(tmp, f"{kind}.before"), os.path.join(tmp, f"{kind}.after")
            cont = os.path.join(tmp, f"{kind}.cont")
            run_lmp([*setup_lines(wall, 3, 5, span), f"run {half}", "run 0 post no", snap.format(p=before),
                     f"write_restart {rst}"], tmp, f"{kind}.a")
            run_lmp([f"read_restart {rst}", "comm_modify vel yes", f"neighbor {0.2 * R!r} bin",
                     "neigh_modify every 1 delay 0 check yes", *reread, "fix integrate all nve/sphere",
                     f"timestep {contact_time(0.03) / 200!r}", "run 0 post no", snap.format(p=after),
                     f"run {steps - half}", DUMP.format(p=cont)], tmp, f"{kind}.b")
            b, a = read_dump(before), read_dump(after)
            same = b == a
            # the test needs springs stretched: sliding atoms with a tangential force
            sheared = sum(1 for row in b.values() if abs(row[1]) + abs(row[2]) > 0.0)
            touching = sum(1 for row in a.values() if row[0] == 1.0)
            if kind == "widened":
                # mindlin's 10 doubles read by the 79-double wall: the contacts and normal forces stay
                kept = touching == len(a) and all(a[i][3] == b[i][3] for i in a)
                print(f"  widened : 10-double records read by a mindlin_deresiewicz wall: {touching} of {len(a)} "
                      f"contacts kept, normal forces identical: {kept}")
                failures += [] if kept else ["restart widened: contacts or normal forces lost"]
                continue
            if kind == "slip":
                f_po = abs(law_info(FFI, "jkr/load-controlled", E_STAR, R, W).pull_off_force)
                ratios = [math.hypot(r[1], r[2]) / (MU * (r[3] + 2 * f_po)) for r in b.values()]
                partial = sum(1 for x in ratios if 0.0 < x < 0.99)
                print(f"  slip    : |F_t|/(mu F_n0) at write_restart {' '.join(f'{x:.2f}' for x in ratios)}")
                if partial < 5:
                    failures.append(f"restart slip: only {partial} contacts in partial slip at write_restart")
            s, c = read_dump(straight), read_dump(cont)
            devs[kind] = max(max(abs(s[i][k] - c[i][k]) / R for k in range(3)) for i in s)
            stuck_after = sum(1 for i in c if c[i][2] - R < 0.01 * R)
            print(f"  {kind:8}: wall outputs of run 0 before write_restart and after read_restart identical: {same} "
                  f"({touching} of {len(a)} touching, {sheared} sheared); continued vs straight run: largest position difference "
                  f"{devs[kind]:.2e} R; {stuck_after} of {len(c)} on the wall at the end")
            if kind != "granular":
                if not same:
                    failures.append("restart: the wall forces/torques changed across write_restart/read_restart")
                if sheared < 5:
                    failures.append(f"restart: only {sheared} atoms with a tangential wall force: the test tests little")
                if touching != len(a) or stuck_after != len(c):
                    failures.append(f"restart: {touching} touching after read_restart, {stuck_after} on the wall at "
                                    f"the end, of {len(a)}")
        print(f"  restart deviation: fix wall/tabor {devs['tabor']:.2e} R, wall/tabor/region {devs['region']:.2e} R, "
              f"mindlin_deresiewicz {devs['slip']:.2e} R, fix wall/gran {devs['granular']:.2e} R")
        if max(devs["tabor"], devs["region"], devs["slip"]) > max(devs["granular"], 1e-15):
            failures.append(f"restart: fix wall/tabor's continued run deviates by {devs['tabor']:.2e} R "
                            f"(region {devs['region']:.2e} R, mindlin_deresiewicz {devs['slip']:.2e} R), "
                            f"more than fix wall/gran's {devs['granular']:.2e} R")
        # the stretched beds of the slip run read by a wall without micro-slip: refused
        inp = os.path.join(tmp, "in.narrowed")
        with open(inp, "w") as f:
            f.write("\n".join([f"read_restart {os.path.join(tmp, 'slip.restart')}", *plugin_wall(TABOR_JKR), "run 0"]))
        p = subprocess.run([os.path.join(VENV, "bin", "mpirun"), "-np", "1", lmp_exe(), "-in", inp, "-log", "none",
                            "-nocite"], cwd=tmp, capture_output=True, text=True)
        err = [line for line in (p.stdout + p.stderr).splitlines() if "ERROR" in line]
        print(f"  narrowed: 79-double records read by a mindlin wall: exit {p.returncode}, {err[0] if err else 'no error'}")
        if p.returncode == 0 or not err or "79 doubles per wall contact" not in err[0]:
            failures.append(f"restart narrowed: not refused with a clear error ({err})")
    return failures


def mpi():
    """Sliding and stuck particles crossing x = 0 (the boundary of 2 sub-domains);
    no pair style: every atom meets only the wall, so the answer cannot depend on
    the decomposition but through the wall histories that travel with the atoms.
    Sliding on an adhesive wall stops within ~0.1 R, so the atoms start within
    0.05 R of the boundary, and the skin is 0.002 R: the atoms are exchanged
    between the ranks (at reneighboring) many times while in contact."""
    failures = []
    span = 0.05 * R
    n_stuck, n_sliding = 4, 12
    n = n_stuck + n_sliding
    with tempfile.TemporaryDirectory(prefix="tabor-wall-mpi-") as tmp:
        out, builds = {}, 0
        for ranks, coeffs in ((1, TABOR_JKR), (2, TABOR_JKR), ("1md", TABOR_MD), ("2md", TABOR_MD)):
            p = os.path.join(tmp, f"mpi.{ranks}")
            np_ = int(str(ranks)[0])
            log = run_lmp([*setup_lines(plugin_wall(coeffs), n_stuck, n_sliding, span, "2 1 1" if np_ == 2 else None,
                                 0.002 * R),
                     "run 10000", DUMP.format(p=p)], tmp, f"mpi{ranks}", np_)
            out[ranks] = read_dump(p)
            builds = int(re.search(r"Neighbor list builds = (\d+)", log).group(1))
        dev_md = max(max(abs(out["1md"][i][k] - out["2md"][i][k]) for k in range(9)) for i in out[1])
        print(f"  mindlin_deresiewicz: 1 vs 2 ranks largest difference {dev_md:.1e}")
        failures += [f"MPI mindlin_deresiewicz: 1 and 2 ranks differ by {dev_md:.1e}"] if dev_md != 0.0 else []
        dev = max(max(abs(out[1][i][k] - out[2][i][k]) for k in range(9)) for i in out[1])
        x0 = {i + 1: -span + 2 * span * (i + 0.5) / n for i in range(n)}
        crossed = sum(1 for i in out[1] if (out[1][i][0] > 0) != (x0[i] > 0))
        on_wall = sum(1 for i in out[1] if out[1][i][2] - R < 0.01 * R)
        print(f"  1 vs 2 ranks: largest difference of any position/velocity/spin component {dev:.1e}; "
              f"{crossed} atoms crossed the sub-domain boundary x = 0 ({builds} reneighborings, each an exchange), {on_wall} of {n} on the wall at the end")
        if dev != 0.0:
            failures.append(f"MPI: 1 and 2 ranks differ by {dev:.1e}")
        if crossed < 3 or on_wall != n or builds < 10:
            failures.append(f"MPI: {crossed} atoms crossed x = 0, {on_wall} of {n} on the wall: the test tests little")
    return failures


STYLES = [  # (label, wall/tabor tail, wall/gran tail, angle)
    ("zplane, wiggle z", "zplane 0.0 NULL wiggle z 2e-9 3e-8", "zplane 0.0 NULL wiggle z 2e-9 3e-8", 30.0),
    ("zplane, shear x", "zplane 0.0 NULL shear x 0.2", "zplane 0.0 NULL shear x 0.2", 30.0),
    ("zplane, shear y", "zplane 0.0 NULL shear y -0.1", "zplane 0.0 NULL shear y -0.1", 60.0),
]
FACE = "region plate block -1e-4 1e-4 -1e-4 1e-4 0 1e-4"
CORNER = f"region plate block -1e-4 {R!r} -1e-4 1e-4 0 1e-4"


def styles():
    """Wall motions against LAMMPS's own fix wall/gran in the JKR limit (the same
    discrete scheme: round-off); wall/tabor/region on a face of a block against the
    plane (the same contact: round-off) and in its corner (two contacts at once,
    symmetric about the diagonal: the rebound must be too, within the time-step
    tolerance, as the two contacts may start one step apart); the zcylinder against
    a plane (a flat for the law: the same rebound). LAMMPS's own wall/gran/region
    is printed beside its wall/gran plane, for information."""
    failures = []
    law = law_info(FFI, "jkr/load-controlled", E_STAR, R, W)
    v = 0.3
    dt = contact_time(v) / STEPS
    reach = law.interaction_range
    tol_v, tol_w = tolerances(v, law.pull_off_force)
    load = plugin_load()
    print(f"{'case':32} {'|du| tabor-gran':>15} {'|dw| tabor-gran':>15} {'|v| after':>10}")
    for label, ours, theirs, angle in STYLES:
        ut, wt, st = wall_collide([load, f"fix wall all wall/tabor {TABOR_JKR} {ours}"], v, dt, reach, angle)
        ug, wg, sg = wall_collide([f"fix wall all wall/gran {GRANULAR_JKR} {theirs}"], v, dt, reach, angle)
        du, dw = math.dist(ut, ug), math.dist(wt, wg)
        print(f"{label:32} {du:15.2e} {dw:15.2e} {math.hypot(*ut):10.4f}")
        if du > tol_v or dw > tol_w or st != sg:
            failures.append(f"{label}: tabor vs wall/gran du {du:.2e} (tol {tol_v:.1e}), dw {dw:.2e} (tol {tol_w:.1e})")
    plane = wall_collide([load, f"fix wall all wall/tabor {TABOR_JKR} zplane 0.0 NULL"], v, dt, reach, 30.0)
    face = wall_collide([FACE, load, f"fix wall all wall/tabor/region {TABOR_JKR} plate"], v, dt, reach, 30.0)
    du, dw = math.dist(plane[0], face[0]), math.dist(plane[1], face[1])
    print(f"{'region, one face vs zplane':32} {du:15.2e} {dw:15.2e} {math.hypot(*face[0]):10.4f}")
    if du > 1e-12 * v or dw > 1e-12 * v / R:
        failures.append(f"region face vs plane: du {du:.2e}, dw {dw:.2e} (round-off expected)")
    gp = wall_collide([f"fix wall all wall/gran {GRANULAR_JKR} zplane 0.0 NULL"], v, dt, reach, 30.0)
    gr = wall_collide([FACE, f"fix wall all wall/gran/region {GRANULAR_JKR} region plate"], v, dt, reach, 30.0)
    print(f"  (LAMMPS's own, same case: wall/gran/region vs its wall/gran plane: |du| {math.dist(gp[0], gr[0]):.2e} "
          f"m/s, |dw| {math.dist(gp[1], gr[1]):.2e} rad/s; rebound normal speed {gr[0][2]:.6f} vs {gp[0][2]:.6f})")
    u, w, sep = wall_collide([CORNER, load, f"fix wall all wall/tabor/region {TABOR_JKR} plate"], v, dt, reach, 45.0)
    asym = abs(u[0] + u[2])
    print(f"{'region corner: u_x + u_z, |w|':32} {asym:15.2e} {math.hypot(*w):15.2e} {math.hypot(*u):10.4f}")
    # the two contacts may start one step apart (the start positions differ by
    # rounding): the time-step tolerance
    if asym > tol_v or math.hypot(*w) > tol_w or not (u[0] < 0 < u[2]) or not sep:
        failures.append(f"region corner: u {u}, w {w}: not the symmetric rebound off both faces")
    # zcylinder of radius 50 R about z through (0, 0): the sphere starts inside at
    # (-(50 R - R - gap), 0, 0) moving in -x onto the wall: the same law as the plane
    approach = 20 + math.ceil(reach / (v * dt))
    s = approach * dt * v
    rc = 50 * R
    outs = []
    for wall in (f"zcylinder {rc!r}", f"xplane {-rc!r} NULL"):
        lmp = lmp_new()
        try:
            for c in ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
                      f"region box block {-2 * rc} {2 * rc} {-2 * rc} {2 * rc} {-2 * rc} {2 * rc}", "create_box 1 box",
                      f"create_atoms 1 single {-(rc - R - s)!r} 0 0", f"set atom 1 diameter {2 * R!r} density {RHO!r}",
                      f"set atom 1 vx {-v!r} vy 0 vz 0", load,
                      f"fix wall all wall/tabor {TABOR_JKR} {wall}", "fix integrate all nve/sphere", f"timestep {dt!r}",
                      f"run {approach + 4 * int(contact_time(v) / dt)}"]:
                lmp.command(c)
            outs.append(lmp.extract_atom("v")[0][0] / v)
        finally:
            lmp.close()
    print(f"zcylinder (radius 50 R) vs plane: e {outs[0]:.12f} vs {outs[1]:.12f}, |diff| {abs(outs[0] - outs[1]):.1e}")
    if abs(outs[0] - outs[1]) > 1e-9 or not outs[0] > 0:
        failures.append(f"zcylinder: e {outs[0]} vs plane {outs[1]}")
    return failures


BAD = [  # (fix arguments after wall/tabor, a phrase the error must hold)
    ("maugis 2.78e10 0.05 0.5", "missing the wallstyle"),
    ("maugis 2.78e10 0.05 0.5 zplane 0", "missing hi"),
    ("maugis 2.78e10 0.05 0.5 zplane 1 0", "lo 1 must be below hi 0"),
    ("maugis 2.78e10 0.05 -1 zplane 0 NULL", "tabor_parameter"),
    ("maugis 2.78e10 0.05 0.5 frob 1 zplane 0 NULL", "unknown keyword frob"),
    ("maugis 2.78e10 0.05 0.5 zplane 0 NULL wiggle z 1 0", "period 0 must be > 0"),
    ("maugis 2.78e10 0.05 0.5 zplane 0 NULL shear z 1", "shear along the wall's normal"),
    ("hertz 2.78e10 zcylinder -1", "zcylinder radius -1"),
    ("jkr/fixed-grip 2.78e10 0.05 tangential mindlin NULL 0 0.3 zplane 0 NULL", "needs `poisson nu`"),
]


def bad_input():
    """Bad input stops LAMMPS with an error naming the parameter and value."""
    failures = []
    for args, phrase in BAD:
        lmp = lmp_new()
        try:
            for c in ["units si", "atom_style sphere", "boundary f f f", "region box block -1 1 -1 1 -1 1",
                      "create_box 1 box", plugin_load()]:
                lmp.command(c)
            try:
                lmp.command(f"fix w all wall/tabor {args}")
                failures.append(f"accepted: fix w all wall/tabor {args}")
            except Exception as e:  # noqa: BLE001 (LAMMPS raises its own exception types)
                if phrase not in str(e):
                    failures.append(f"fix wall/tabor {args}: error {e!s} lacks {phrase!r}")
        finally:
            lmp.close()
    print(f"  {len(BAD)} bad inputs refused with the parameter named" if not failures else "  bad inputs: FAILED")
    return failures


def main():
    failures = []
    print("1. normal impacts on the wall against tabor impact (flat target)")
    failures += normal_impacts()
    failures += exported_fragment()
    print("2. oblique impacts: fix wall/tabor against fix wall/gran granular jkr, and against tabor impact --angle")
    failures += oblique()
    print("3. restart with stuck and sliding particles")
    failures += restart()
    print("4. 1 and 2 MPI ranks")
    failures += mpi()
    print("5. wiggle, shear against fix wall/gran; region (one face, a corner); zcylinder")
    failures += styles()
    print("6. bad input")
    failures += bad_input()
    print("7. tangential mindlin_deresiewicz on the wall against tabor impact --angle (the library's bed)")
    failures += micro_slip_wall()
    return report(failures, "fix wall/tabor tests passed")


if __name__ == "__main__":
    sys.exit(main())

"""Proof by LAMMPS of the per-contact Tabor parameter of pair_style tabor (issue 31,
item 3): `pair_coeff * * maugis E* w range h` holds the Dugdale range h fixed and
gives each contact the Tabor parameter of its own effective radius,
Lambda = d_n(R*)/h, d_n = (9 pi w R*^2 / (8 E*))^(2/3) / (3 R*) (seed 000 section
5.3.2, spec maugis-dugdale.md).

1. Pairs of silica spheres of three sizes spanning a factor 10 in R*, at one range
   h, collide in LAMMPS as `tabor impact --json` says for a scene with that range
   (the library converts h into each pair's own Lambda): the three Lambda lie in
   the three Maugis-Dugdale cases (0.38 < Lambda1, Lambda1 < 0.56 < Lambda2,
   0.82 > Lambda2), plus a pair of unequal spheres; at two speeds above the
   sticking velocity and one below it (stuck). Tolerance from the time step: runs
   at dt = t_c/5000 and dt/2; |e_tabor - e(dt/2)| <= 2 |e(dt) - e(dt/2)| + FLOOR,
   FLOOR = 2e-4 for tabor's own integration (its quasi-static restitution, to
   ~1e-5) and the table over Lambda (|dF| <= 3e-5 F_n, tests/lambda.rs of tabor-ffi).
2. The fixed-Lambda form at each pair's own Lambda gives the same restitution as
   the range form within 1e-5 (the table's error; the fixed form itself is
   test_plugin.py's, unchanged).
3. `stress s0` is `range w/s0`; bad input is refused at pair_coeff with an error
   naming the keyword: h or s0 negative, zero, non-finite; both given; Lambda given
   too.

Needs TABOR, TABOR_PLUGIN, TABOR_FFI_LIB, LAMMPS_VENV (test_plugin.sh sets them).
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collide import rebound  # noqa: E402
from lammps_case import (E, E_STAR, FFI, NU, PLUGIN, RHO, ROOT, W, export_plugin, hertz_contact_time,  # noqa: E402
                         lmp_new, report, tabor_impact, tabor_json, write_temp)
from tabor_ffi import law_info  # noqa: E402

# silica (lammps_case's E, NU, RHO, W); the radii are this test's own
FLOOR = 2e-4
SAME_FORM_TOL = 1e-5


def depth_scale(r_star):
    """d_n = a_c^2/(3 R*), a_c = (9 pi w R*^2/(8 E*))^(1/3) (spec maugis-dugdale.md)."""
    a_c = (9.0 * math.pi * W * r_star ** 2 / (8.0 * E_STAR)) ** (1.0 / 3.0)
    return a_c * a_c / (3.0 * r_star)


R_SMALL = 0.5e-6  # sphere radius of the smallest pair: R* = 0.25 um
H = depth_scale(R_SMALL / 2.0) / 0.38  # the range that puts that pair at Lambda = 0.38
PAIRS = [  # (sphere radius, target radius)
    (R_SMALL, R_SMALL),
    (R_SMALL * math.sqrt(10.0), R_SMALL * math.sqrt(10.0)),
    (10.0 * R_SMALL, 10.0 * R_SMALL),
    (R_SMALL, 10.0 * R_SMALL),
]


def scene(r1, r2, extra):
    lines = ['name = "lambda"', "[sphere]", f"radius = {r1!r}", f"density = {RHO!r}",
             f"youngs_modulus = {E!r}", f"poisson_ratio = {NU!r}", "[target]",
             f"radius = {r2!r}", f"density = {RHO!r}", f"youngs_modulus = {E!r}",
             f"poisson_ratio = {NU!r}", "[adhesion]", f"work_of_adhesion = {W!r}", extra,
             "[impact]", "speed = 1.0"]
    return write_temp("\n".join(lines) + "\n", ".toml")


def sticking_speed(path):
    return tabor_json(["impact", path])["sticking_velocity"]


def contact_time(r1, r2, speed):
    """Hertz's contact time 2.87 (m*^2/(R* E*^2 v))^(1/5)."""
    r_star = r1 * r2 / (r1 + r2)
    m1, m2 = RHO * 4.0 / 3.0 * math.pi * r1 ** 3, RHO * 4.0 / 3.0 * math.pi * r2 ** 3
    m_star = m1 * m2 / (m1 + m2)
    return hertz_contact_time(m_star, r_star, E_STAR, speed)


def run(coeff, r1, r2, speed, steps, max_contact_times=20, h=H):
    """One central collision of spheres r1, r2 (centre-of-mass frame) under
    `coeff`, at dt = t_c/steps; the spheres start a whole number of steps outside
    the interaction range (the larger of h and the snap-off gap, tabor_ffi), so the
    contact forms at the jump-in as from afar. Returns the restitution (0: stuck
    after max_contact_times contact times)."""
    r_star = r1 * r2 / (r1 + r2)
    reach = law_info(FFI, "maugis", E_STAR, r_star, W, depth_scale(r_star) / h).interaction_range
    tc = contact_time(r1, r2, speed)
    dt = tc / steps
    gap0 = reach + 20 * speed * dt
    m1, m2 = r1 ** 3, r2 ** 3
    lmp = lmp_new()
    try:
        span = 40.0 * (r1 + r2)
        for c in ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
                  "comm_modify vel yes",
                  f"region box block {-span} {span} {-span} {span} {-span} {span}",
                  "create_box 1 box", f"create_atoms 1 single {-(r1 + gap0 / 2)} 0 0",
                  f"create_atoms 1 single {r2 + gap0 / 2} 0 0",
                  f"set atom 1 diameter {2 * r1} density {RHO}",
                  f"set atom 2 diameter {2 * r2} density {RHO}",
                  f"set atom 1 vx {speed * m2 / (m1 + m2)}", f"set atom 2 vx {-speed * m1 / (m1 + m2)}",
                  f"plugin load {PLUGIN}", "pair_style tabor", coeff,
                  f"neighbor {0.2 * min(r1, r2)} bin", "neigh_modify every 1 delay 0 check yes",
                  "fix integrate all nve/sphere", f"timestep {dt}",
                  "variable vrel equal vx[2]-vx[1]", f"variable gap equal x[2]-x[1]-{r1 + r2}"]:
            lmp.command(c)
        return rebound(lmp, gap0, speed, tc, steps, reach, max_contact_times)[0]
    finally:
        lmp.close()


def collisions():
    failures = []
    coeff = f"pair_coeff * * maugis {E_STAR!r} {W!r} range {H!r}"
    print(f"range h = {H:.4e} m")
    print(f"{'R* (m)':>10} {'Lambda':>7} {'v (m/s)':>9} {'e tabor':>9} {'e(dt/2)':>9} "
          f"{'e(dt)':>9} {'|diff|':>9} {'tol':>9} {'fixed-L':>9}")
    lambdas = []
    for r1, r2 in PAIRS:
        r_star = r1 * r2 / (r1 + r2)
        lam = depth_scale(r_star) / H
        lambdas.append(lam)
        path = scene(r1, r2, f"range = {H!r}")
        try:
            v_stick = sticking_speed(path)
            for v in (0.5 * v_stick, 2.0 * v_stick, 6.0 * v_stick):
                o = tabor_impact(path, v)
                e_t = 0.0 if o["sticks"] else o["restitution"]
                lam_t = o.get("tabor_parameter")
                fine = run(coeff, r1, r2, v, 10000)
                coarse = run(coeff, r1, r2, v, 5000)
                tol = 2.0 * abs(coarse - fine) + FLOOR
                fixed = run(f"pair_coeff * * maugis {E_STAR!r} {W!r} {lam!r}", r1, r2, v, 10000)
                diff = abs(e_t - fine)
                print(f"{r_star:10.3e} {lam:7.4f} {v:9.4f} {e_t:9.6f} {fine:9.6f} {coarse:9.6f} "
                      f"{diff:9.2e} {tol:9.2e} {fixed - fine:+9.1e}")
                if lam_t is not None and abs(lam_t / lam - 1.0) > 1e-9:
                    failures.append(f"R* {r_star}: tabor's Lambda {lam_t} vs d_n/h {lam}")
                if diff > tol:
                    failures.append(f"R* {r_star:.3e} (Lambda {lam:.4f}) at {v}: e LAMMPS {fine:.6f} "
                                    f"vs tabor {e_t:.6f} (tolerance {tol:.2e})")
                if abs(fixed - fine) > SAME_FORM_TOL:
                    failures.append(f"R* {r_star:.3e} at {v}: fixed Lambda {fixed:.8f} vs range {fine:.8f}")
                if v < v_stick and (fine != 0.0 or e_t != 0.0):
                    failures.append(f"R* {r_star:.3e} at {v} below sticking: e {fine} / {e_t}, not stuck")
        finally:
            os.unlink(path)
    # the control: the smallest pair at the middle pair's Lambda held fixed (today's
    # form with one Lambda for the type pair) must miss tabor by more than the
    # tolerance, or the comparison above could not tell the forms apart
    r1, r2 = PAIRS[0]
    path = scene(r1, r2, f"range = {H!r}")
    try:
        v = 2.0 * sticking_speed(path)
        o = tabor_impact(path, v)
    finally:
        os.unlink(path)
    wrong = run(f"pair_coeff * * maugis {E_STAR!r} {W!r} {lambdas[1]!r}", r1, r2, v, 10000)
    print(f"control: R* {r1 / 2:.3e} at the fixed Lambda {lambdas[1]:.4f}: e {wrong:.6f} vs tabor "
          f"{o['restitution']:.6f}")
    if abs(wrong - o["restitution"]) < 10 * FLOOR:
        failures.append("the control (a wrong fixed Lambda) is not told apart from the per-contact form")
    # the sizes must span the three cases, across Lambda1 and Lambda2
    lam1, lam2 = 0.449528231858144, 0.6435337159896298
    if not (lambdas[0] < lam1 < lambdas[1] < lam2 < lambdas[2]):
        failures.append(f"the sizes' Lambda {lambdas} do not straddle Lambda1 and Lambda2")
    return failures


def pair_coeff_error(coeff):
    """The error LAMMPS raises for `coeff`, or None when it is accepted."""
    lmp = lmp_new()
    try:
        for c in ["units si", "atom_style sphere", "region box block -1 1 -1 1 -1 1",
                  "create_box 1 box", f"plugin load {PLUGIN}", "pair_style tabor"]:
            lmp.command(c)
        try:
            lmp.command(coeff)
        except Exception as e:  # noqa: BLE001 (LAMMPS raises its own exception types)
            return str(e)
        return None
    finally:
        lmp.close()


def bad_input():
    failures = []
    base = f"pair_coeff * * maugis {E_STAR!r} {W!r}"
    cases = [
        (f"{base} range -1e-10", "range"),
        (f"{base} range 0", "range"),
        (f"{base} range inf", "range"),
        (f"{base} range nan", "range"),
        (f"{base} stress 0", "stress"),
        (f"{base} stress -3e8", "stress"),
        (f"{base} stress inf", "stress"),
        (f"{base} range 2e-10 stress 2.5e8", "not both"),
        (f"{base} 0.5 range 2e-10", "Lambda"),
        (f"{base} range", "range"),
        (f"pair_coeff * * jkr/fixed-grip {E_STAR!r} {W!r} range 2e-10", "maugis"),
    ]
    for coeff, word in cases:
        msg = pair_coeff_error(coeff)
        print(f"  {coeff.split(' ', 3)[-1]}: {(msg or 'accepted').splitlines()[0]}")
        if msg is None or word not in msg:
            failures.append(f"{coeff!r} not refused naming {word!r}: {msg}")
    for ok in (f"{base} range 2e-10", f"{base} stress 2.5e8", f"{base} range 2e-10 damping 1e-9"):
        msg = pair_coeff_error(ok)
        if msg is not None:
            failures.append(f"{ok!r} refused: {msg}")
    return failures


def stress_is_range():
    """`stress s0` is `range w/s0`: the same restitution to the last digit."""
    r = R_SMALL * math.sqrt(10.0)
    path = scene(r, r, f"range = {H!r}")
    try:
        v = 2.0 * sticking_speed(path)
    finally:
        os.unlink(path)
    a = run(f"pair_coeff * * maugis {E_STAR!r} {W!r} range {H!r}", r, r, v, 5000)
    b = run(f"pair_coeff * * maugis {E_STAR!r} {W!r} stress {W / H!r}", r, r, v, 5000)
    print(f"range form e = {a:.12f}, stress form e = {b:.12f}")
    return [] if abs(a - b) <= 1e-12 else [f"stress form {b} vs range form {a}"]


def exported():
    """The pair_coeff line of `tabor export lammps examples/scenes/silica_maugis.toml
    --plugin PATH --per-contact-lambda` (range 0.3 nm) run in LAMMPS for the scene's
    1 um spheres and for spheres 10x larger (Lambda 0.30 and 0.65), against
    `tabor impact` of the scene with those radii, same tolerance as above."""
    failures = []
    path = os.path.join(ROOT, "examples/scenes/silica_maugis.toml")
    frag = export_plugin(path, "--per-contact-lambda")
    coeff = next(line for line in frag.splitlines() if line.startswith("pair_coeff"))
    h = float(coeff.split()[-1])
    print(f"exported: {coeff}")
    for r in (1e-6, 1e-5):
        spath = scene(r, r, f"range = {h!r}")
        try:
            v = 3.0 * sticking_speed(spath)
            o = tabor_impact(spath, v)
        finally:
            os.unlink(spath)
        fine = run(coeff, r, r, v, 10000, h=h)
        coarse = run(coeff, r, r, v, 5000, h=h)
        tol = 2.0 * abs(coarse - fine) + FLOOR
        print(f"  R {r:.1e} Lambda {o['tabor_parameter']:.4f} v {v:.4f}: e tabor {o['restitution']:.6f} "
              f"LAMMPS {fine:.6f} |diff| {abs(fine - o['restitution']):.2e} tol {tol:.2e}")
        if abs(fine - o["restitution"]) > tol:
            failures.append(f"exported fragment at R {r}: e {fine} vs tabor {o['restitution']}")
    return failures


def run_wall(model, r, speed, steps, max_contact_times=20):
    """A sphere of radius r falling on the wall z = 0 of `fix wall/tabor MODEL`
    (R* = r), at dt = t_c/steps, starting a whole number of steps beyond the
    reach of the law at its own Lambda; the restitution (0: stuck)."""
    reach = law_info(FFI, "maugis", E_STAR, r, W, depth_scale(r) / H).interaction_range
    m_flat = RHO * 4.0 / 3.0 * math.pi * r ** 3
    tc = hertz_contact_time(m_flat, r, E_STAR, speed)
    dt = tc / steps
    gap0 = reach + 20 * speed * dt
    lmp = lmp_new()
    try:
        span = 40.0 * r
        for c in ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
                  f"region box block {-span} {span} {-span} {span} {-span} {span}", "create_box 1 box",
                  f"create_atoms 1 single 0 0 {r + gap0}", f"set atom 1 diameter {2 * r} density {RHO}",
                  f"set atom 1 vz {-speed}", f"plugin load {PLUGIN}",
                  f"fix wall all wall/tabor {model} zplane 0.0 NULL", "fix integrate all nve/sphere",
                  f"timestep {dt}", f"variable gap equal z[1]-{r}", "variable vz equal vz[1]"]:
            lmp.command(c)
        return rebound(lmp, gap0, speed, tc, steps, reach, max_contact_times, velocity="vz")[0]
    finally:
        lmp.close()


def wall():
    """fix wall/tabor with `maugis E* w range h`: each sphere at its own Lambda =
    d_n(R)/h on the wall (R* = R), against `tabor impact` of the sphere on a flat
    at the same range; two sizes a factor 10 apart, below and above sticking."""
    failures = []
    model = f"maugis {E_STAR!r} {W!r} range {H!r}"
    print("fix wall/tabor, range h:")
    for r in (R_SMALL / 2.0, 5.0 * R_SMALL):
        path = scene(r, r, f"range = {H!r}")
        with open(path) as f:
            text = f.read().replace(f"[target]\nradius = {r!r}\n", "[target]\n")
        with open(path, "w") as f:
            f.write(text)
        try:
            v_stick = sticking_speed(path)
            for v in (0.5 * v_stick, 2.0 * v_stick):
                o = tabor_impact(path, v)
                e_t = 0.0 if o["sticks"] else o["restitution"]
                fine = run_wall(model, r, v, 10000)
                coarse = run_wall(model, r, v, 5000)
                tol = 2.0 * abs(coarse - fine) + FLOOR
                lam = depth_scale(r) / H
                print(f"  R {r:.2e} Lambda {lam:.4f} (tabor {o.get('tabor_parameter')}) v {v:.4f}: e tabor "
                      f"{e_t:.6f} LAMMPS {fine:.6f} |diff| {abs(fine - e_t):.2e} tol {tol:.2e}")
                if abs(fine - e_t) > tol:
                    failures.append(f"wall, R {r:.2e} at {v}: e {fine:.6f} vs tabor {e_t:.6f} (tol {tol:.2e})")
                if v < v_stick and fine != 0.0:
                    failures.append(f"wall, R {r:.2e} at {v} below sticking: e {fine}, not stuck")
        finally:
            os.unlink(path)
    return failures


def main():
    failures = collisions()
    failures += wall()
    failures += exported()
    print("bad input:")
    failures += bad_input()
    failures += stress_is_range()
    return report(failures, "per-contact Lambda: all passed")


if __name__ == "__main__":
    sys.exit(main())

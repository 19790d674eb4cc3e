"""Proof by LAMMPS for the oblique impact: tabor's library (`tabor impact --angle
--json`) against LAMMPS's own `pair_style granular` with `jkr` + `tangential
mindlin NULL` + `rolling sds` + `twisting marshall`, collision by collision
(oblique, with and without spin, several angles and speeds): the final velocities
and spins of both spheres in the centre-of-mass frame.

The tolerance comes from the time step, not from a fit: every collision runs in
LAMMPS at dt = t_c/8000 and at dt/2 (t_c the contact time tabor reports).
LAMMPS's velocity-Verlet with its explicit history update converges to the
continuous model tabor integrates, at first order once dt is below ~t_c/8000
(measured at 0.3 m/s, 10 deg: sphere v_y = 0.0174905, 0.0174914, 0.0174919 and
w_z = -21457.7, -21455.5, -21454.3 rad/s at t_c/8000, /16000, /32000, the
differences halving; tabor 0.0174923 and -21453.2). Coarser steps are not yet
in that regime: the contact forms and snaps off at a step boundary, and the
errors scatter (at t_c/1000 ... t_c/4000 v_x goes -0.144639, -0.144507,
-0.144573). So the difference of the two runs estimates the error of the finer
one (|X(dt) - X(dt/2)|), and tabor must lie within twice that difference of the
dt/2 run, plus a floor of 1e-6 of the scale (speed v, spin v/R) for tabor's own
integration tolerance and LAMMPS's rounding. The collision is `collide.py`'s
`collide_oblique` and the comparison its `time_step_errors`, which the oblique
tests of test_lammps.py use too.

Runs under pytest or as a plain script (`python test_oblique.py`, what test.sh
does); needs TABOR (the tabor binary) and LD_LIBRARY_PATH=<venv>/lib.
`python test_oblique.py --figure-points docs/figures/oblique_impact_lammps.csv`
writes the LAMMPS points of the example `oblique_impact`.
"""

import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from collide import collide_oblique, time_step_errors  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(HERE))
TABOR = os.environ.get("TABOR", os.path.join(ROOT, "target", "release", "tabor"))

# the verified reference case of the LAMMPS notes: two silica microspheres
R, RHO, E, NU, W = 1e-6, 2650.0, 54e9, 0.17, 0.05
MU, K_ROLL, MU_ROLL = 0.3, 50.0, 0.1
STEPS_PER_CONTACT = 8000

SCENE = f"""
name = "oblique"
[sphere]
radius = {R}
density = {RHO}
youngs_modulus = {E}
poisson_ratio = {NU}
[target]
radius = {R}
density = {RHO}
youngs_modulus = {E}
poisson_ratio = {NU}
[adhesion]
work_of_adhesion = {W}
separation = "load-controlled"
[friction]
coefficient = {MU}
rolling = {{ stiffness = {K_ROLL}, damping = 0.0, coefficient = {MU_ROLL} }}
twisting = "marshall"
[impact]
speed = 1.0
sphere_spin = [0.0, 0.0, SPIN]
"""

CASES = [  # (speed m/s, angle degrees, sphere spin about z rad/s)
    (0.3, 10.0, 0.0),
    (0.3, 30.0, 0.0),
    (1.0, 45.0, 0.0),
    (0.3, 10.0, 2e5),
    (1.0, 30.0, -3e5),
]


def tabor_oblique(speed, angle, spin, adhesive=True):
    scene = SCENE.replace("SPIN", repr(spin))
    if not adhesive:
        scene = scene.replace(f"[adhesion]\nwork_of_adhesion = {W}\nseparation = \"load-controlled\"\n", "")
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write(scene)
        path = f.name
    try:
        out = subprocess.run(
            [TABOR, "impact", path, "--speed", repr(speed), "--angle", repr(angle), "--json"],
            check=True, capture_output=True, text=True).stdout
    finally:
        os.unlink(path)
    return json.loads(out)


def lammps_oblique(speed, angle, spin, dt, contact_time, normal=None):
    """One collision in LAMMPS (`collide.collide_oblique`); returns the CoM-frame
    velocity and spin of both spheres after they have parted."""
    gamma = W / 2.0  # LAMMPS's jkr takes the surface energy per surface
    fragment = [
        "pair_style granular",
        f"pair_coeff * * {normal or f'jkr {E} 0.0 {NU} {gamma}'} damping viscoelastic "
        f"tangential mindlin NULL 0.0 {MU} rolling sds {K_ROLL} 0.0 {MU_ROLL} twisting marshall",
    ]
    # beyond the load-controlled pull-off separation of LAMMPS's jkr
    e_star = E / (2.0 * (1.0 - NU * NU))
    pulloff = (3.0 * math.pi ** 2 * W ** 2 * (R / 2.0) / (64.0 * e_star ** 2)) ** (1.0 / 3.0)
    bodies = {"sphere_radius": R, "sphere_density": RHO, "target_radius": R, "target_density": RHO}
    out = collide_oblique(fragment, bodies, speed, angle, dt, 2.0 * pulloff,
                          int(3 * contact_time / dt), spin=(0.0, 0.0, spin))
    assert out["separated"], f"LAMMPS: no separation at {speed} m/s, {angle} deg"
    return out


RESULTS = []


def check(speed, angle, spin):
    t = tabor_oblique(speed, angle, spin)
    assert not t["oblique"]["sticks"], t
    tc = t["oblique"]["contact_time"]
    dt = tc / STEPS_PER_CONTACT
    coarse = lammps_oblique(speed, angle, spin, dt, tc)
    fine = lammps_oblique(speed, angle, spin, dt / 2.0, tc)
    rows = time_step_errors(t["after"], coarse, fine, speed, R)
    RESULTS.append((speed, angle, spin, t["after"]["sphere"]["velocity"][:2],
                    t["after"]["sphere"]["angular_velocity"][2],
                    fine["sphere"]["velocity"][:2], fine["sphere"]["angular_velocity"][2],
                    max(diff / tol for *_, diff, tol in rows)))
    for name, ours, lf, lc, diff, tol in rows:
        assert diff <= tol, (
            f"{speed} m/s, {angle} deg, spin {spin}: {name} tabor {ours:.9e}"
            f" LAMMPS {lf:.9e} (dt/2) {lc:.9e} (dt): |diff| {diff:.2e} > {tol:.2e}")


def test_reference_case():
    check(*CASES[0])


def test_angles_and_speeds():
    for case in CASES[1:3]:
        check(*case)


def test_with_spin():
    for case in CASES[3:]:
        check(*case)


def main():
    failed = 0
    for case in CASES:
        try:
            check(*case)
        except AssertionError as e:
            failed += 1
            print(f"FAIL {e}")
    print("speed  angle  spin      tabor v_sphere (m/s), w_z (rad/s)        "
          "LAMMPS dt/2                          |diff|/tol")
    for s, a, w, tv, tw, lv, lw, worst in RESULTS:
        print(f"{s:<6} {a:<6} {w:<9.3g} ({tv[0]:+.6f}, {tv[1]:+.6f}) {tw:+.5e}  "
              f"({lv[0]:+.6f}, {lv[1]:+.6f}) {lw:+.5e}  {worst:.2f}")
    print(f"oblique: {len(CASES) - failed}/{len(CASES)} collisions within the time-step error")
    return 1 if failed else 0


def figure_points(path):
    """LAMMPS's tangential restitution beta against Psi for the example
    `oblique_impact` (Hertz and JKR, 1 m/s, dt = t_c/8000): model,psi,beta."""
    e_star = E / (2.0 * (1.0 - NU * NU))
    g_star = 1.0 / (2.0 * 2.0 * (2.0 - NU) * (1.0 + NU) / E)
    kappa = 4.0 * g_star / e_star
    rows = ["model,psi,tangential_restitution"]
    for model, adhesive, normal in [("Hertz", False, f"hertz/material {E} 0.0 {NU}"),
                                    ("JKR", True, None)]:
        for psi in [0.1, 0.3, 1.0, 2.0, 3.0, 5.0, 8.0]:
            angle = math.degrees(math.atan(psi * MU / kappa))
            t = tabor_oblique(1.0, angle, 0.0, adhesive)
            tc = t["oblique"]["contact_time"]
            out = lammps_oblique(1.0, angle, 0.0, tc / STEPS_PER_CONTACT, tc, normal)
            u_y = out["sphere"]["velocity"][1] - out["target"]["velocity"][1]
            w = out["sphere"]["angular_velocity"][2] + out["target"]["angular_velocity"][2]
            beta = -(u_y + R * w) / (1.0 * math.sin(math.radians(angle)))
            rows.append(f"{model},{psi},{beta!r}")
            print(rows[-1], "tabor", t["tangential_restitution"])
    with open(path, "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--figure-points":
        figure_points(sys.argv[2])
        sys.exit(0)
    sys.exit(main())

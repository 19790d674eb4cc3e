"""Proof by LAMMPS for the oblique impact: tabor's library (`tabor impact --angle
--json`) against LAMMPS's own `pair_style granular` with `jkr` + `tangential
mindlin NULL` + `rolling sds` + `twisting marshall`, collision by collision
(oblique, with and without spin, several angles and speeds): the final velocities
and spins of both spheres in the centre-of-mass frame.

The tolerance is fixed in advance, not taken from the runs: every collision runs
in LAMMPS at dt = t_c/32000, t_c/64000 and t_c/128000 (t_c the contact time
tabor reports; the damped one at a stick/slip switch, SWITCH_CASE, at
t_c/1024000 ... /4096000, compared directly). LAMMPS's velocity-Verlet with its explicit history update
converges to the continuous model tabor integrates at first order once dt is
below ~t_c/8000 without spin and ~t_c/32000 with it (0.5 m/s, 40 deg, spin
(1e5, -2e5, 3e4): v_x = -0.1889323, -0.1889271, -0.1889191, -0.1889231,
-0.1889211, -0.1889221 at t_c/8000 ... /256000), the errors halving with dt: of one sign (0.3 m/s, 10 deg: sphere v_y =
0.0174905, 0.0174914, 0.0174919, 0.0174921 and w_z = -21457.67, -21455.45,
-21454.34, -21453.79 rad/s at t_c/8000 ... /64000) or alternating where the
contact forms at a step boundary (0.3 m/s, 30 deg: v_x = -0.1262688,
-0.1262519, -0.1262604, -0.1262562, -0.1262583 at t_c/8000 ... /128000). Both
are geometric, and Aitken's extrapolation of three runs (`collide.aitken_limit`)
gives the limit: -0.12625756 from the first three and from the three after
them, where tabor gives -0.12625756 (a two-run Richardson extrapolation would
double an alternating error). With spin the sequence is not yet cleanly
geometric at t_c/128000: the extrapolations scatter by up to 5e-6 of the scale
(1 m/s, 30 deg, spin -3e5: 4.5e-6 on v_x). So tabor must lie within TOLERANCE =
1e-5 of the scale (speed v, spin v/R) of the limit (`collide.extrapolated_errors`),
fixed here, not taken from the runs; a 0.5 % error in the torque arm or the G*
mixing moves the spins by ~1e-3 of the scale, 100 times that.

The cases cover spins about z, spins in any direction and about the line of
centres (twisting), at several angles and speeds. A flat target needs a LAMMPS
wall (`fix wall/gran`, not in `collide.py` yet) and fixed grip is not a LAMMPS
`pair granular` model: the plugin's `jkr/fixed-grip` is checked against the
library in test_plugin_friction.py.

Runs under pytest or as a plain script (`python test_oblique.py`, what test.sh
does); needs TABOR (the tabor binary) and LD_LIBRARY_PATH=<venv>/lib.
`python test_oblique.py --figure-points docs/figures/oblique_impact_lammps.csv`
writes the LAMMPS points of the example `oblique_impact`.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collide import collide_oblique, components, extrapolated_errors  # noqa: E402
from lammps_case import (E, E_STAR, K_ROLL, MU, MU_ROLL, NU, R, SILICA_BODIES, SILICA_TOML, W,  # noqa: E402
                         tabor_json, write_temp)

# the verified reference case of the LAMMPS notes: two silica microspheres
# (lammps_case's R, RHO, E, NU, W, MU, K_ROLL, MU_ROLL)
STEPS_PER_CONTACT = 32000
TOLERANCE = 1e-5

SCENE = f"""
name = "oblique"
{SILICA_TOML}[adhesion]
work_of_adhesion = {W}
separation = "load-controlled"
[friction]
coefficient = {MU}
rolling = {{ stiffness = {K_ROLL}, damping = 0.0, coefficient = {MU_ROLL} }}
twisting = "marshall"
[impact]
speed = 1.0
sphere_spin = SPIN
"""

CASES = [  # (speed m/s, angle degrees, sphere spin (rad/s))
    (0.3, 10.0, (0.0, 0.0, 0.0)),
    (0.3, 30.0, (0.0, 0.0, 0.0)),
    (1.0, 45.0, (0.0, 0.0, 0.0)),
    (0.3, 10.0, (0.0, 0.0, 2e5)),
    (1.0, 30.0, (0.0, 0.0, -3e5)),
    (0.3, 20.0, (3e5, 0.0, 0.0)),       # about the line of centres: twisting
    (0.5, 40.0, (1e5, -2e5, 3e4)),      # any direction: out-of-plane slip
]


# A damped Hertz contact (`damping tsuji`, tangential damping x_gamma,t): its
# total normal force falls below 0 (the dashpot pulls) before the overlap
# vanishes, and every Coulomb limit mu |F_n| touches 0 there. Before stop 37
# the library mistook that point for the separation at small angles (e_t
# -0.4329 at 0.5, 1 and 3 degrees alike, the elastic energy left in the
# contact booked as a loss) when a twisting element was present.
# At 40 degrees a stick/slip switch near that point makes LAMMPS's sequence
# erratic (sphere v_y = 0.06413700, 0.06390096, 0.06235419, 0.06305169,
# 0.06244193, 0.06235405, 0.06235404, 0.06235485, 0.06235437, 0.06235417 m/s at
# t_c/8000 ... /4096000; tabor 0.06235423): it scatters about tabor's value
# without converging geometrically, so Aitken's extrapolation does not apply.
# That case (SWITCH_CASE) is compared directly with the three finest runs
# (t_c/1024000 ... /4096000, whose scatter is 6.8e-7 m/s, 2.3e-6 of the scale):
# each within TOLERANCE of the scale of tabor.
DAMPED_CASES = [(0.3, 1.0, (0.0, 0.0, 0.0)), (0.3, 3.0, (0.0, 0.0, 0.0)),
                (0.3, 10.0, (0.0, 0.0, 0.0))]
SWITCH_CASE = (0.3, 40.0, (0.0, 0.0, 0.0))
SWITCH_STEPS = (1024000, 2048000, 4096000)
TSUJI = 0.5           # LAMMPS's damping tsuji value (a restitution)
X_GAMMA_T = 0.5       # tangential damping, in units of the normal damping

# A soft constant tangential spring (`linear_history`, 100 N/m, mu 0.6) on Hertz
# with `damping coeff_restitution` (e = 0.5): the element slides through the
# tensile end, where F_n < 0 falls to 0 as delta^(1/4) and the sliding power
# grows as (t_e - t)^(-1/2). Before stop 37 the library stopped there ("step
# size underflow") at 30 and 50 degrees.
SOFT_CASES = [(0.15, 30.0, (0.0, 0.0, 0.0)), (0.15, 50.0, (0.0, 0.0, 0.0))]
SOFT_E, SOFT_K, SOFT_MU = 0.5, 100.0, 0.6

# (tabor scene keys, LAMMPS pair_coeff) of each damped contact
DAMPED = {
    "tsuji": (f"tangential_damping = {X_GAMMA_T}\n",
              f"[damping]\nmodel = \"tsuji\"\ncoefficient = {TSUJI}\n",
              f"hertz/material {E} {TSUJI} {NU} damping tsuji "
              f"tangential mindlin NULL {X_GAMMA_T} {MU}"),
    "soft": (f"tangential = \"linear_history\"\ntangential_stiffness = {SOFT_K}\n",
             f"[damping]\nmodel = \"coeff_restitution\"\nrestitution = {SOFT_E}\n",
             f"hertz/material {E} {SOFT_E} {NU} damping coeff_restitution "
             f"tangential linear_history {SOFT_K} 0.0 {SOFT_MU}"),
}


def tabor_oblique(speed, angle, spin, adhesive=True, damped=None):
    scene = SCENE.replace("SPIN", repr(list(spin)))
    if not adhesive or damped:
        scene = scene.replace(f"[adhesion]\nwork_of_adhesion = {W}\nseparation = \"load-controlled\"\n", "")
    if damped:
        friction, damping, _ = DAMPED[damped]
        scene = scene.replace("[friction]\n", f"[friction]\n{friction}")
        if damped == "soft":
            scene = scene.replace(f"coefficient = {MU}\n", f"coefficient = {SOFT_MU}\n", 1)
        scene += damping
    path = write_temp(scene, ".toml")
    try:
        return tabor_json(["impact", path, "--speed", repr(speed), "--angle", repr(angle)])
    finally:
        os.unlink(path)


def lammps_oblique(speed, angle, spin, dt, contact_time, normal=None, damped=None):
    """One collision in LAMMPS (`collide.collide_oblique`); returns the CoM-frame
    velocity and spin of both spheres after they have parted. `damped`: a key of
    `DAMPED`, Hertz with its damping and tangential model."""
    gamma = W / 2.0  # LAMMPS's jkr takes the surface energy per surface
    coeff = (f"{normal or f'jkr {E} 0.0 {NU} {gamma}'} damping viscoelastic "
             f"tangential mindlin NULL 0.0 {MU}")
    if damped:
        coeff = DAMPED[damped][2]
    fragment = [
        "pair_style granular",
        f"pair_coeff * * {coeff} rolling sds {K_ROLL} 0.0 {MU_ROLL} twisting marshall",
    ]
    # beyond the load-controlled pull-off separation of LAMMPS's jkr
    pulloff = (3.0 * math.pi ** 2 * W ** 2 * (R / 2.0) / (64.0 * E_STAR ** 2)) ** (1.0 / 3.0)
    out = collide_oblique(fragment, SILICA_BODIES, speed, angle, dt, 2.0 * pulloff,
                          int(3 * contact_time / dt), spin=tuple(spin))
    assert out["separated"], f"LAMMPS: no separation at {speed} m/s, {angle} deg"
    return out


RESULTS = []


def check(speed, angle, spin, damped=None):
    t = tabor_oblique(speed, angle, spin, damped=damped)
    assert not t["oblique"]["sticks"], t
    tc = t["oblique"]["contact_time"]
    dt = tc / STEPS_PER_CONTACT
    runs = [lammps_oblique(speed, angle, spin, dt / h, tc, damped=damped) for h in (1.0, 2.0, 4.0)]
    rows = extrapolated_errors(t["after"], runs, speed, R, TOLERANCE)
    limit = {name: lim for name, _, lim, *_ in rows}
    RESULTS.append((speed, angle, damped or spin, t["after"]["sphere"]["velocity"][:2],
                    t["after"]["sphere"]["angular_velocity"],
                    [limit["sphere.velocity[0]"], limit["sphere.velocity[1]"]],
                    max(diff / tol for *_, diff, tol in rows)))
    for name, ours, limit, lf, diff, tol in rows:
        assert diff <= tol, (
            f"{speed} m/s, {angle} deg, spin {spin}: {name} tabor {ours:.9e}"
            f" LAMMPS limit {limit:.9e} (dt/2: {lf:.9e}): |diff| {diff:.2e} > {tol:.2e}")


def check_direct(speed, angle, spin, damped):
    """tabor against LAMMPS's runs at the time steps SWITCH_STEPS (per contact
    time) directly, each within TOLERANCE of the scale (speed for velocities,
    speed/radius for spins): for a sequence that scatters instead of converging
    geometrically."""
    t = tabor_oblique(speed, angle, spin, damped=damped)
    assert not t["oblique"]["sticks"], t
    tc = t["oblique"]["contact_time"]
    worst = 0.0
    for steps in SWITCH_STEPS:
        run = lammps_oblique(speed, angle, spin, tc / steps, tc, damped=damped)
        for name, body, field, k, scale in components(speed, R):
            ours, theirs = t["after"][body][field][k], run[body][field][k]
            diff, tol = abs(ours - theirs), TOLERANCE * scale
            worst = max(worst, diff / tol)
            assert diff <= tol, (
                f"{speed} m/s, {angle} deg, {damped}: {name} tabor {ours:.9e} LAMMPS"
                f" (t_c/{steps}) {theirs:.9e}: |diff| {diff:.2e} > {tol:.2e}")
    v, w = t["after"]["sphere"]["velocity"], t["after"]["sphere"]["angular_velocity"]
    RESULTS.append((speed, angle, damped, v[:2], w, [run["sphere"]["velocity"][0],
                    run["sphere"]["velocity"][1]], worst))


def test_reference_case():
    check(*CASES[0])


def test_angles_and_speeds():
    for case in CASES[1:3]:
        check(*case)


def test_with_spin():
    for case in CASES[3:5]:
        check(*case)


def test_twisting_and_spin_in_any_direction():
    for case in CASES[5:]:
        check(*case)


def test_damped_hertz():
    for case in DAMPED_CASES:
        check(*case, damped="tsuji")


def test_damped_hertz_at_a_stick_slip_switch():
    check_direct(*SWITCH_CASE, damped="tsuji")


def test_soft_spring_through_the_tensile_end():
    for case in SOFT_CASES:
        check(*case, damped="soft")


def main():
    failed = 0
    for case in ([(c, None) for c in CASES] + [(c, "tsuji") for c in DAMPED_CASES]
                 + [(c, "soft") for c in SOFT_CASES]):
        try:
            check(*case[0], damped=case[1])
        except AssertionError as e:
            failed += 1
            print(f"FAIL {e}")
    try:
        check_direct(*SWITCH_CASE, damped="tsuji")
    except AssertionError as e:
        failed += 1
        print(f"FAIL {e}")
    print("speed  angle  spin (rad/s)               tabor v_sphere (m/s)     "
          "LAMMPS limit v_sphere     max |diff|/tol")
    for s, a, w, tv, tw, lv, worst in RESULTS:
        print(f"{s:<6} {a:<6} {str(w):<26} ({tv[0]:+.8f}, {tv[1]:+.8f})  "
              f"({lv[0]:+.8f}, {lv[1]:+.8f})  {worst:.3f}")
    total = len(CASES) + len(DAMPED_CASES) + len(SOFT_CASES) + 1
    print(f"oblique: {total - failed}/{total} collisions within {TOLERANCE:g} of LAMMPS's limit"
          " (the stick/slip switch case of its finest runs)")
    return 1 if failed else 0


def figure_points(path):
    """LAMMPS's tangential restitution beta against Psi for the example
    `oblique_impact` (Hertz and JKR, 1 m/s, dt = t_c/8000): model,psi,beta."""
    e_star = E_STAR
    g_star = 1.0 / (2.0 * 2.0 * (2.0 - NU) * (1.0 + NU) / E)
    kappa = 4.0 * g_star / e_star
    rows = ["model,psi,tangential_restitution"]
    for model, adhesive, normal in [("Hertz", False, f"hertz/material {E} 0.0 {NU}"),
                                    ("JKR", True, None)]:
        for psi in [0.1, 0.3, 1.0, 2.0, 3.0, 5.0, 8.0]:
            angle = math.degrees(math.atan(psi * MU / kappa))
            t = tabor_oblique(1.0, angle, (0.0, 0.0, 0.0), adhesive)
            tc = t["oblique"]["contact_time"]
            out = lammps_oblique(1.0, angle, (0.0, 0.0, 0.0), tc / 8000, tc, normal)
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

"""Proof by LAMMPS of pair_style tabor's DEM damping keywords (issue 30, item 4):
`damping viscoelastic eta_n0 | tsuji e | coeff_restitution e` (pair granular's model
names, the value after the name), exactly tabor_viscoadhesive::NormalDamping.

1. Without adhesion: the plugin's `hertz E* damping <model> <value>` against LAMMPS's
   own `pair granular hertz/material E <value> nu ... damping <model>`, two silica
   spheres, central collisions at 0.03, 0.3 and 3 m/s: the same discrete scheme and
   the same formulas, so the rebound velocities agree to round-off (SAME_SCHEME);
   and `coeff_restitution` rebounds with the nominal e.
2. With adhesion (JKR, load-controlled; where pair granular refuses tsuji and
   coeff_restitution): the plugin's `jkr/load-controlled E* w damping
   coeff_restitution 0.5` against the library (`tabor impact` of the same scene with
   [damping]) from 1e-3 to 100 times the library's sticking velocity v_c: it sticks
   below v_c and rebounds above with the library's restitution, never NaN.
3. Maugis-Dugdale (Lambda = 0.55) + `damping tsuji 0.7` through the fragment of
   `tabor export lammps --plugin`, against `tabor impact`, the same way.

Tolerance from the time step dt = t_c/STEPS_PER_CONTACT, as in
test_plugin_friction.py: the contact's end can fall one step apart in two schemes,
an impulse of at most dt F_scale, F_scale = F_Hertz,max(v) + 2 |F_pull-off|, so the
restitution may differ by EVENTS dt F_scale/(m* v), EVENTS = 2. Nothing is fitted.

Needs TABOR, TABOR_PLUGIN, TABOR_FFI_LIB, LAMMPS_VENV, LD_LIBRARY_PATH=<venv>/lib.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collide import collide_oblique  # noqa: E402
from lammps_case import (E, E_STAR, FFI, M_STAR, NU, R, R_STAR, SILICA_BODIES, SILICA_TOML, W,  # noqa: E402
                         commands, export_plugin, force_scale, hertz_contact_time, pair_tabor, report, tabor_impact,
                         write_temp)
from tabor_ffi import law_info  # noqa: E402

STEPS_PER_CONTACT = 5000
EVENTS = 2
SAME_SCHEME = 1e-9

# two silica spheres (lammps_case's R, RHO, E, NU, W, R_STAR, M_STAR)
BODIES = SILICA_BODIES


def contact_time(v):
    return hertz_contact_time(M_STAR, R_STAR, E_STAR, v)


def restitution_tolerance(v, pull_off=0.0):
    dt = contact_time(v) / STEPS_PER_CONTACT
    return EVENTS * dt * force_scale(M_STAR, R_STAR, E_STAR, v, pull_off) / (M_STAR * v)


def central(lines, v, reach, contact_times=12):
    """(restitution, separated) of a central collision at speed v (0 when stuck)."""
    dt = contact_time(v) / STEPS_PER_CONTACT
    o = collide_oblique(lines, BODIES, v, 0.0, dt, reach, contact_times * STEPS_PER_CONTACT)
    u = o["sphere"]["velocity"][0] - o["target"]["velocity"][0]
    if not math.isfinite(u):
        return float("nan"), o["separated"]
    return (-u / v if o["separated"] else 0.0), o["separated"]


def plugin(coeff):
    return pair_tabor(f"pair_coeff * * {coeff}")


def without_adhesion():
    failures = []
    cases = [("coeff_restitution", 0.5), ("tsuji", 0.7), ("viscoelastic", 2e15)]
    reach = 1e-3 * R
    print("damping without adhesion: plugin hertz vs pair granular hertz/material")
    print(f"{'model':18} {'value':>8} {'v':>5} {'e plugin':>10} {'e granular':>10} {'|diff|':>9} {'tol':>8}")
    for model, value in cases:
        for v in (0.03, 0.3, 3.0):
            p, ps = central(plugin(f"hertz {E_STAR!r} damping {model} {value!r}"), v, reach)
            g, gs = central(["pair_style granular",
                             f"pair_coeff * * hertz/material {E!r} {value!r} {NU} "
                             f"tangential linear_nohistory 0 0 damping {model}"], v, reach)
            tol = restitution_tolerance(v)
            print(f"{model:18} {value:8.3g} {v:5.2f} {p:10.6f} {g:10.6f} {abs(p - g):9.1e} {tol:8.1e}")
            if not (ps and gs) or not math.isfinite(p):
                failures.append(f"{model} v {v}: separated plugin {ps} granular {gs}, e {p}")
            elif abs(p - g) > SAME_SCHEME:
                failures.append(f"{model} {value} v {v}: plugin {p} vs granular {g}: beyond round-off "
                                f"of the same scheme ({SAME_SCHEME:.0e})")
            if model == "coeff_restitution" and abs(p - value) > tol:
                failures.append(f"coeff_restitution {value} v {v}: e = {p} (tol {tol:.1e})")
    return failures


SCENE = f"""name = "jkr-coeff-restitution"
{SILICA_TOML}[adhesion]
work_of_adhesion = {W}
separation = "load-controlled"
[damping]
model = "coeff_restitution"
restitution = 0.5
[impact]
speed = 0.3
"""


def with_adhesion():
    failures = []
    path = write_temp(SCENE, ".toml")
    try:
        v_c = tabor_impact(path, 0.3)["sticking_velocity"]
        info = law_info(FFI, "jkr/load-controlled", E_STAR, R_STAR, W)
        reach = 2 * info.interaction_range
        coeff = f"jkr/load-controlled {E_STAR!r} {W} damping coeff_restitution 0.5"
        print(f"JKR (load-controlled) + coeff_restitution 0.5: plugin vs tabor impact, v_c = {v_c:.6f} m/s")
        print(f"{'v/v_c':>7} {'v':>10} {'e plugin':>10} {'e tabor':>10} {'|diff|':>9} {'tol':>8}")
        for ratio in (1e-3, 0.3, 0.9, 1.1, 3.0, 30.0, 100.0):
            v = ratio * v_c
            lib = tabor_impact(path, v)
            e_lib = 0.0 if lib["sticks"] else lib["restitution"]
            # a stuck pair is followed for 40 contact times (it never parts)
            e_p, sep = central(plugin(coeff), v, reach, contact_times=40 if lib["sticks"] else 12)
            tol = restitution_tolerance(v, info.pull_off_force)
            print(f"{ratio:7.3g} {v:10.4e} {e_p:10.6f} {e_lib:10.6f} {abs(e_p - e_lib):9.1e} {tol:8.1e}")
            if not math.isfinite(e_p):
                failures.append(f"JKR coeff_restitution v {v}: NaN")
            elif sep == lib["sticks"]:
                failures.append(f"JKR coeff_restitution v {v} = {ratio} v_c: library sticks={lib['sticks']}, "
                                f"plugin separated={sep}")
            elif abs(e_p - e_lib) > tol:
                failures.append(f"JKR coeff_restitution v {v}: e plugin {e_p} vs tabor {e_lib} (tol {tol:.1e})")
    finally:
        os.unlink(path)
    return failures


def exported_maugis_tsuji():
    """Maugis-Dugdale (Lambda = 0.55, case 2) + `damping tsuji 0.7` through the
    fragment `tabor export lammps --plugin` writes, against `tabor impact`."""
    failures = []
    scene = SCENE.replace('separation = "load-controlled"', "tabor_parameter = 0.55").replace(
        'model = "coeff_restitution"\nrestitution = 0.5', 'model = "tsuji"\ncoefficient = 0.7')
    path = write_temp(scene, ".toml")
    try:
        cmds = commands(export_plugin(path))
        coeff = next(c for c in cmds if c.startswith("pair_coeff"))
        if " damping tsuji " not in coeff:
            failures.append(f"the exported line has no damping tsuji: {coeff}")
        v_c = tabor_impact(path, 0.3)["sticking_velocity"]
        info = law_info(FFI, "maugis", E_STAR, R_STAR, W, 0.55)
        reach = 2 * info.interaction_range
        print(f"Maugis-Dugdale 0.55 + tsuji 0.7 (exported fragment): plugin vs tabor impact, v_c = {v_c:.6f} m/s")
        for ratio in (0.3, 1.1, 3.0, 30.0):
            v = ratio * v_c
            lib = tabor_impact(path, v)
            e_lib = 0.0 if lib["sticks"] else lib["restitution"]
            e_p, sep = central(cmds, v, reach, contact_times=40 if lib["sticks"] else 12)
            tol = restitution_tolerance(v, info.pull_off_force)
            print(f"{ratio:7.3g} {v:10.4e} {e_p:10.6f} {e_lib:10.6f} {abs(e_p - e_lib):9.1e} {tol:8.1e}")
            if not math.isfinite(e_p):
                failures.append(f"MD tsuji v {v}: NaN")
            elif sep == lib["sticks"]:
                failures.append(f"MD tsuji v {v}: library sticks={lib['sticks']}, plugin separated={sep}")
            elif abs(e_p - e_lib) > tol:
                failures.append(f"MD tsuji v {v}: e plugin {e_p} vs tabor {e_lib} (tol {tol:.1e})")
    finally:
        os.unlink(path)
    return failures


def main():
    failures = without_adhesion() + with_adhesion() + exported_maugis_tsuji()
    return report(failures, "plugin damping tests passed")


if __name__ == "__main__":
    sys.exit(main())

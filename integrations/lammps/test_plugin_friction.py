"""Proof by LAMMPS of pair_style tabor with friction (issue 21, item 5).

1. JKR limit: `pair_style tabor` with `jkr/load-controlled` (LAMMPS's rule) and
   `tangential mindlin NULL 0 mu rolling sds k 0 mu_r twisting marshall` against
   LAMMPS's own `pair_style granular jkr ... tangential mindlin NULL ... rolling sds
   ... twisting marshall`, collision by collision: two silica spheres, oblique
   (10 to 80 degrees), three speeds, with and without an initial spin, and one case
   each of normal + tangential damping, `mindlin_rescale`, `linear_history` and
   `twisting sds`; newton on and off. Final relative velocity and both spins.
2. The same collisions (JKR) and Maugis-Dugdale at Lambda = 0.5 with friction, and
   at Lambda = 0.1 a twist through its no-contact part, against tabor's library
   (`tabor_tangential::oblique`, continuous time with the stick/slip switches
   located as events; example `oblique_library` of tabor-ffi).

Tolerance, derived from the time step dt = t_c/STEPS_PER_CONTACT (t_c the Hertz
contact time, seed 000 (5.12)): velocity Verlet with forces that switch at contact
events (jump-in, snap-off, stick/slip) is exact to O(dt^2) between events; an event
can fall one step apart in two schemes, which changes the relative velocity by at
most one step's impulse dt F/m* and a spin by dt T/I. With F bounded by
F_scale = F_Hertz,max(v) + 2 |F_pulloff| and the torque by
(mu R + mu_roll R* + (2/3) mu a_max) F_scale, the tolerances are
EVENTS * dt * F_scale / m* and EVENTS * dt * T_scale / I with EVENTS = 2.
Nothing is fitted to the measured differences (printed: plugin vs granular agree
to ~1e-13 relative; plugin vs the continuous-time library to ~1e-5).

The plugin and pair granular also run the same discrete scheme (velocity Verlet,
LAMMPS's sub-model updates step by step), so beyond the time-step bound they must
agree to round-off: ~1e-16 per step over the ~6e4 steps of a run (at most ~1e-11
of the scale v, v/R if it adds up linearly), with a factor 100 for its
amplification where a stick/slip or snap-off decision changes by one step:
SAME_SCHEME = 1e-9 of the scale.

3. `tangential mindlin_deresiewicz` (the per-contact spring bed of 32 springs):
   against the library's 1024-node spring bed over Maw, Barber & Fawcett's
   Psi = 0.1 to 10, Hertz (steel) and JKR (silica), within the time-step tolerance
   alone (the bed's own error, at most 4e-4 in beta, is measured in
   crates/tabor-tangential/tests/micro_slip_step.rs to lie below a tenth of it),
   and against the same form run outside LAMMPS (example `oblique_dem`, round-off).

Needs TABOR_PLUGIN, TABOR_FFI_LIB, OBLIQUE_LIBRARY, OBLIQUE_DEM (the example binaries), LAMMPS_VENV,
LD_LIBRARY_PATH=<venv>/lib.
"""

import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collide import collide_oblique  # noqa: E402
from lammps_case import (E, E_STAR, FFI, K_ROLL, M_STAR, MASS, MU, MU_ROLL, NU, R, R_STAR, RHO,  # noqa: E402
                         SILICA_BODIES, W, equal_spheres, force_scale, hertz_contact_time, hertz_overlap, pair_tabor,
                         report)
from tabor_ffi import law_info  # noqa: E402

LIBRARY = os.environ["OBLIQUE_LIBRARY"]
STEPS_PER_CONTACT = 5000
EVENTS = 2
SAME_SCHEME = 1e-9

# two silica spheres (lammps_case's R, RHO, E, NU, W, MU, K_ROLL, MU_ROLL, R_STAR, M_STAR)
INERTIA = 0.4 * MASS * R * R


def contact_time(v):
    return hertz_contact_time(M_STAR, R_STAR, E_STAR, v)


def tolerances(v, pull_off):
    """(velocity tolerance m/s, spin tolerance rad/s) at speed v, from dt."""
    dt = contact_time(v) / STEPS_PER_CONTACT
    dmax = hertz_overlap(M_STAR, R_STAR, E_STAR, v)
    f_scale = force_scale(M_STAR, R_STAR, E_STAR, v, pull_off)
    a_max = math.sqrt(R_STAR * dmax) * 2
    t_scale = (MU * R + MU_ROLL * R_STAR + 2 / 3 * MU * a_max) * f_scale
    return EVENTS * dt * f_scale / M_STAR, EVENTS * dt * t_scale / INERTIA


def granular_coeff(friction):
    t, roll, tw, damp = friction
    eta = 0.0 if damp is None else 2 * E_STAR * damp / M_STAR   # eta_n0 m_eff a = 2 E* A a
    return (f"pair_coeff * * jkr {E} {eta!r} {NU} {W / 2} damping viscoelastic tangential {t} "
            f"rolling {roll} twisting {tw}")


def tabor_coeff(friction, normal=f"jkr/load-controlled {E_STAR!r} {W}"):
    t, roll, tw, damp = friction
    normal = f"{normal} poisson {NU}"
    return (f"pair_coeff * * {normal}{'' if damp is None else f' damping {damp!r}'} tangential {t} "
            f"rolling {roll} twisting {tw}")


def collide(coeff_cmds, v, angle, spin=0.0, newton="on", reach=None, contact_times=12):
    """Two equal spheres whose undisturbed paths touch with the line of centres
    along x, relative velocity v (cos a, sin a, 0), in one `run` of the approach
    plus `contact_times` Hertz contact times (`collide.collide_oblique`). Returns
    (u_x, u_y, omega_z of 1, omega_z of 2, separated), with `separated` true when
    the spheres are beyond `reach` and receding."""
    reach = REACH if reach is None else reach
    dt = contact_time(v) / STEPS_PER_CONTACT
    out = collide_oblique(coeff_cmds, SILICA_BODIES, v, angle, dt, reach, contact_times * STEPS_PER_CONTACT,
                          spin=(0.0, 0.0, spin), newton=newton)
    s, t = out["sphere"], out["target"]
    return (s["velocity"][0] - t["velocity"][0], s["velocity"][1] - t["velocity"][1],
            s["angular_velocity"][2], t["angular_velocity"][2], out["separated"])


def plugin(friction, model=f"jkr/load-controlled {E_STAR!r} {W}"):
    return pair_tabor(tabor_coeff(friction, model))


def granular(friction):
    return ["pair_style granular", granular_coeff(friction)]


def library(cases):
    """tabor's library answers, one per (model, lambda, v, angle, spin)."""
    text = "".join(f"{R} {RHO} {E} {NU} {W} {m} {lam} {v} {a} {s} {MU} {K_ROLL} {MU_ROLL}\n"
                   for m, lam, v, a, s in cases)
    out = subprocess.run([LIBRARY], input=text, check=True, capture_output=True, text=True).stdout
    return [tuple(float(x) for x in line.split()) for line in out.splitlines()]


BASE = (f"mindlin NULL 0 {MU}", f"sds {K_ROLL} 0 {MU_ROLL}", "marshall", None)
VARIANTS = [  # (label, friction, speed, angle, spin)
    ("damped, x_gamma 0.5", (f"mindlin NULL 0.5 {MU}", f"sds {K_ROLL} 1e-7 {MU_ROLL}", "marshall", 2e-10), 0.3, 30, 0.0),
    ("mindlin_rescale", (f"mindlin_rescale NULL 0 {MU}", f"sds {K_ROLL} 0 {MU_ROLL}", "marshall", None), 0.3, 30, 0.0),
    ("linear_history", (f"linear_history 2000 0 {MU}", f"sds {K_ROLL} 0 {MU_ROLL}", "marshall", None), 0.3, 30, 0.0),
    ("twisting sds", (f"mindlin NULL 0 {MU}", f"sds {K_ROLL} 0 {MU_ROLL}", "sds 1e-12 0 0.05", None), 0.3, 30, 0.0),
]
JKR_PULL_OFF = 1.5 * math.pi * W * R_STAR
# beyond every interaction range used here (JKR load-controlled, MD Lambda 0.5)
REACH = 2 * max(law_info(FFI, "jkr/load-controlled", E_STAR, R_STAR, W).interaction_range,
                law_info(FFI, "maugis", E_STAR, R_STAR, W, 0.5).interaction_range)


def jkr_against_granular():
    failures = []
    cases = [(lab, BASE, v, a, s) for v in (0.15, 0.3, 0.6) for a in (10, 30, 60, 80)
             for s, lab in ((0.0, "no spin"), (3e4 * v / 0.3, "spin"))] + VARIANTS
    print(f"{'case':22} {'v':>5} {'angle':>5} {'|du| plugin-gran':>17} {'tol':>8} "
          f"{'|dw| plugin-gran':>17} {'tol':>8} {'newton off':>10} {'|du| lib':>9} {'|dw| lib':>9}")
    lib_cases = [("jkr", 0.0, v, a, s) for (_, _, v, a, s) in cases[:-len(VARIANTS)]]
    lib = library(lib_cases)
    for n, (label, fr, v, a, s) in enumerate(cases):
        p = collide(plugin(fr), v, a, s)
        g = collide(granular(fr), v, a, s)
        off = collide(plugin(fr), v, a, s, newton="off")
        tol_v, tol_w = tolerances(v, JKR_PULL_OFF)
        du = math.hypot(p[0] - g[0], p[1] - g[1])
        dw = max(abs(p[2] - g[2]), abs(p[3] - g[3]))
        same = "identical" if off == p else f"{max(abs(x - y) for x, y in zip(off[:4], p[:4])):.1e}"
        lib_txt = ""
        if n < len(lib_cases) and not p[4] and not lib[n][4]:
            failures.append(f"JKR {label} v {v} angle {a}: the library rebounds, the plugin did not separate")
        if n < len(lib_cases) and p[4]:
            ref = lib[n]
            du_l = math.hypot(p[0] - ref[0], p[1] - ref[1])
            dw_l = max(abs(p[2] - ref[2]), abs(p[3] - ref[3]))
            lib_txt = f"{du_l:9.1e} {dw_l:9.1e}"
            if ref[4] == 0 and (du_l > tol_v or dw_l > tol_w):
                failures.append(f"JKR {label} v {v} angle {a}: plugin vs library du {du_l:.2e} (tol {tol_v:.2e}), dw {dw_l:.2e} (tol {tol_w:.2e})")
        print(f"{label:22} {v:5.2f} {a:5.0f} {du:17.2e} {tol_v:8.1e} {dw:17.2e} {tol_w:8.1e} {same:>10} {lib_txt}")
        if du > tol_v or dw > tol_w:
            failures.append(f"{label} v {v} angle {a}: plugin vs granular du {du:.2e} (tol {tol_v:.2e}), dw {dw:.2e} (tol {tol_w:.2e})")
        elif du > SAME_SCHEME * v or dw > SAME_SCHEME * v / R:
            failures.append(f"{label} v {v} angle {a}: plugin vs granular du {du:.2e}, dw {dw:.2e}: "
                            f"beyond round-off of the same scheme ({SAME_SCHEME:.0e} of v, v/R)")
        if p[4] != g[4]:
            failures.append(f"{label} v {v} angle {a}: separated {p[4]} (plugin) vs {g[4]} (granular)")
        if off != p:
            failures.append(f"{label} v {v} angle {a}: newton off differs from newton on")
    return failures


def maugis_against_library(lam=0.5):
    failures = []
    pull = law_info(FFI, "maugis", E_STAR, R_STAR, W, lam).pull_off_force
    cases = [(v, a, s) for v in (0.2, 0.5) for a in (10, 30, 60) for s in (0.0, 2e4)]
    lib = library([("maugis", lam, v, a, s) for v, a, s in cases])
    print(f"Maugis-Dugdale Lambda = {lam} with friction, plugin vs tabor's library")
    for (v, a, s), ref in zip(cases, lib):
        p = collide(plugin(BASE, model=f"maugis {E_STAR!r} {W} {lam}"), v, a, s)
        tol_v, tol_w = tolerances(v, pull)
        du = math.hypot(p[0] - ref[0], p[1] - ref[1])
        dw = max(abs(p[2] - ref[2]), abs(p[3] - ref[3]))
        print(f"  v {v:4.2f} angle {a:3.0f} spin {s:7.0f}: u plugin ({p[0]:+.6f}, {p[1]:+.6f}) library "
              f"({ref[0]:+.6f}, {ref[1]:+.6f}); |du| {du:.1e} (tol {tol_v:.1e}), |dw| {dw:.1e} (tol {tol_w:.1e})")
        if bool(ref[4]) == p[4]:
            failures.append(f"MD v {v} angle {a}: library sticks={bool(ref[4])}, plugin separated={p[4]}")
        elif du > tol_v or dw > tol_w:
            failures.append(f"MD v {v} angle {a} spin {s}: du {du:.2e} (tol {tol_v:.2e}), dw {dw:.2e} (tol {tol_w:.2e})")
    return failures


def maugis_twist_against_library(lam=0.1):
    """A sphere spinning about the line of centres (a twist, 2e5 rad/s) through the
    no-contact part of Maugis-Dugdale at Lambda = 0.1 (the bodies attract at contact
    radius 0): the plugin and the library both keep the `mindlin` and `marshall`
    springs at zero displacement there, so the contact area starts unstrained.
    Plugin vs library: the relative velocity and both spins about x and z, within
    the time-step tolerances of the module docstring."""
    failures = []
    info = law_info(FFI, "maugis", E_STAR, R_STAR, W, lam)
    reach = 2 * info.interaction_range
    cases = [(v, a, 2e5) for v in (0.2, 0.5) for a in (10, 60)]
    text = "".join(f"{R} {RHO} {E} {NU} {W} maugis {lam} {v} {a} 0 {MU} {K_ROLL} {MU_ROLL} mindlin {sx}\n"
                   for v, a, sx in cases)
    out = subprocess.run([LIBRARY], input=text, check=True, capture_output=True, text=True).stdout
    lib = [tuple(float(x) for x in line.split()) for line in out.splitlines()]
    print(f"Maugis-Dugdale Lambda = {lam}, a twist through the no-contact part, plugin vs tabor's library")
    for (v, a, sx), ref in zip(cases, lib):
        dt = contact_time(v) / STEPS_PER_CONTACT
        o = collide_oblique(plugin(BASE, model=f"maugis {E_STAR!r} {W} {lam}"), SILICA_BODIES, v, a, dt, reach,
                            12 * STEPS_PER_CONTACT, spin=(sx, 0.0, 0.0))
        s_, t_ = o["sphere"], o["target"]
        p = (s_["velocity"][0] - t_["velocity"][0], s_["velocity"][1] - t_["velocity"][1],
             s_["angular_velocity"][2], t_["angular_velocity"][2],
             s_["angular_velocity"][0], t_["angular_velocity"][0])
        tol_v, tol_w = tolerances(v, info.pull_off_force)
        du = math.hypot(p[0] - ref[0], p[1] - ref[1])
        dw = max(abs(p[k] - ref[k]) for k in (2, 3))
        dtw = max(abs(p[4] - ref[6]), abs(p[5] - ref[7]))
        print(f"  v {v:4.2f} angle {a:3.0f}: twist after plugin ({p[4]:+.1f}, {p[5]:+.1f}) library "
              f"({ref[6]:+.1f}, {ref[7]:+.1f}) rad/s; |du| {du:.1e} (tol {tol_v:.1e}), |dw_z| {dw:.1e}, "
              f"|dw_x| {dtw:.1e} (tol {tol_w:.1e})")
        if bool(ref[4]) == o["separated"]:
            failures.append(f"MD twist v {v} angle {a}: library sticks={bool(ref[4])}, plugin separated={o['separated']}")
        elif du > tol_v or dw > tol_w or dtw > tol_w:
            failures.append(f"MD twist v {v} angle {a}: du {du:.2e} (tol {tol_v:.2e}), dw_z {dw:.2e}, "
                            f"dw_x {dtw:.2e} (tol {tol_w:.2e})")
    return failures


# Maw, Barber & Fawcett's steel (nu = 0.3), two equal spheres: the same chi = 3.5 as
# MBF's sphere on a flat, hence the same tangential restitution beta(Psi)
ST_R, ST_RHO, ST_E, ST_NU, ST_MU = 1e-3, 7800.0, 200e9, 0.3, 0.3
MBF_PSI = [0.1, 0.3, 0.6, 1.0, 1.5, 2.5, 3.5, 5.0, 8.0, 10.0]


def kappa(nu):
    """k_t/k_n = 4 G*/E* = 2 (1 - nu)/(2 - nu), one material."""
    return 2 * (1 - nu) / (2 - nu)


def micro_slip_against_library():
    """`tangential mindlin_deresiewicz` in the plugin (the per-contact spring bed,
    32 springs) against the library's 1024-node bed (oblique_library ...
    mindlin_deresiewicz), collision by collision over MBF's Psi = kappa tan(a)/mu
    from 0.1 to 10: Hertz (two steel spheres, 1 m/s) and JKR (two silica spheres,
    `jkr/load-controlled`, 0.3 and 1 m/s; Thornton & Yin's limit mu F_n0 over the
    JKR contact radius in both).

    Tolerance: the time-step one only (EVENTS impulses dt F_scale/m*, F_scale the
    largest Hertz force plus twice the pull-off force; spins dt mu R F_scale/I),
    no model gap: the two beds differ by at most 4e-4 in beta over this range
    (micro_slip_step.rs, where that is asserted below a tenth of the time-step
    tolerance), which moves u_y by 4e-4 v_t0/chi, well inside it."""
    failures = []
    cases = [("hertz", ST_R, ST_RHO, ST_E, ST_NU, 0.0, ST_MU, 1.0, psi) for psi in MBF_PSI]
    cases += [("jkr", R, RHO, E, NU, W, MU, v, psi) for v in (0.3, 1.0) for psi in MBF_PSI]
    print("mindlin_deresiewicz: plugin (32-spring bed) vs library (1024-node bed); "
          "beta = -(u_y + R (w1 + w2))/v_t0")
    print(f"{'law':5} {'v':>4} {'Psi':>5} {'angle':>6} {'beta plugin':>11} {'beta lib':>9} {'|du_x|':>8} "
          f"{'|du_y|':>8} {'tol':>8} {'|dw|':>8} {'tol':>8}")
    text = "".join(f"{r} {rho} {e} {nu} {w} {model} 0 {v} {math.degrees(math.atan(psi * mu / kappa(nu)))!r} "
                   f"0 {mu} 0 0 mindlin_deresiewicz\n" for model, r, rho, e, nu, w, mu, v, psi in cases)
    out = subprocess.run([LIBRARY], input=text, check=True, capture_output=True, text=True).stdout
    lib = [tuple(float(x) for x in line.split()) for line in out.splitlines()]
    worst = {}
    for (model, r, rho, e, nu, w, mu, v, psi), ref in zip(cases, lib):
        e_star, r_star = e / (2 * (1 - nu * nu)), r / 2
        m = rho * 4 / 3 * math.pi * r ** 3
        m_star, inertia = m / 2, 0.4 * m * r * r
        dt = hertz_contact_time(m_star, r_star, e_star, v) / STEPS_PER_CONTACT
        f_scale = force_scale(m_star, r_star, e_star, v, 1.5 * math.pi * w * r_star)
        tol_v = EVENTS * dt * f_scale / m_star
        tol_w = EVENTS * dt * mu * r * f_scale / inertia
        a = math.degrees(math.atan(psi * mu / kappa(nu)))
        normal = f"jkr/load-controlled {e_star!r} {w}" if model == "jkr" else f"hertz {e_star!r}"
        coeff = pair_tabor(f"pair_coeff * * {normal} poisson {nu} tangential mindlin_deresiewicz NULL 0 {mu}")
        bodies = equal_spheres(r, rho)
        reach = REACH if model == "jkr" else 1e-3 * r
        o = collide_oblique(coeff, bodies, v, a, dt, reach, 12 * STEPS_PER_CONTACT)
        s_, t_ = o["sphere"], o["target"]
        p = (s_["velocity"][0] - t_["velocity"][0], s_["velocity"][1] - t_["velocity"][1],
             s_["angular_velocity"][2], t_["angular_velocity"][2])
        vt0 = v * math.sin(math.radians(a))
        beta = [-(x[1] + r * (x[2] + x[3])) / vt0 for x in (p, ref)]
        dux, duy = abs(p[0] - ref[0]), abs(p[1] - ref[1])
        dw = max(abs(p[2] - ref[2]), abs(p[3] - ref[3]))
        print(f"{model:5} {v:4.2f} {psi:5.2f} {a:6.2f} {beta[0]:+11.5f} {beta[1]:+9.5f} {dux:8.1e} "
              f"{duy:8.1e} {tol_v:8.1e} {dw:8.1e} {tol_w:8.1e}")
        key = model
        worst[key] = max(worst.get(key, 0.0), dux / tol_v, duy / tol_v, dw / tol_w)
        if bool(ref[4]) == o["separated"]:
            failures.append(f"mindlin_deresiewicz {model} v {v} Psi {psi}: library sticks={bool(ref[4])}, "
                            f"plugin separated={o['separated']}")
        elif not all(math.isfinite(x) for x in p):
            failures.append(f"mindlin_deresiewicz {model} v {v} Psi {psi}: not finite {p}")
        elif dux > tol_v or duy > tol_v or dw > tol_w:
            failures.append(f"mindlin_deresiewicz {model} v {v} Psi {psi}: du_x {dux:.2e}, du_y {duy:.2e} "
                            f"(tol {tol_v:.2e}), dw {dw:.2e} (tol {tol_w:.2e})")
    for key, x in worst.items():
        print(f"  {key}: largest difference {x:.2f} of the time-step tolerance")
    return failures


DEM = os.environ.get("OBLIQUE_DEM", os.path.join(os.path.dirname(LIBRARY), "oblique_dem"))


def micro_slip_same_form():
    """The plugin's `mindlin_deresiewicz` against the same spring bed run
    outside LAMMPS (example `oblique_dem`: ContactModel::step, the code the plugin
    calls, in LAMMPS's nve/sphere scheme from collide_oblique's start): Hertz
    (steel, MBF's Psi) and JKR (silica, 5 to 80 degrees, 0.3 and 1 m/s). The same
    scheme and the same force code: the time-step tolerance (EVENTS dt F/m*) bounds
    them, and beyond it round-off of the same scheme, SAME_SCHEME (measured: 1e-16
    in velocity, 1e-10 rad/s of spins ~1e4 rad/s)."""
    failures = []
    steel = [("hertz", ST_R, ST_RHO, ST_E, ST_NU, 0.0, 1.0, math.degrees(math.atan(p * ST_MU / kappa(ST_NU))), ST_MU)
             for p in (0.1, 0.6, 1.5, 3.5, 8.0)]
    silica = [("jkr", R, RHO, E, NU, W, v, a, MU) for v in (0.3, 1.0) for a in (5, 20, 45, 80)]
    print("mindlin_deresiewicz: plugin vs the same form outside LAMMPS (oblique_dem)")
    rows = []
    for model, r, rho, e, nu, w, v, a, mu in steel + silica:
        e_star, r_star = e / (2 * (1 - nu * nu)), r / 2
        m_star = rho * 4 / 3 * math.pi * r ** 3 / 2
        dt = hertz_contact_time(m_star, r_star, e_star, v) / STEPS_PER_CONTACT
        reach = REACH if model == "jkr" else 1e-3 * r
        approach = 20 + math.ceil(reach / max(math.cos(math.radians(a)), 0.05) / (v * dt))
        steps = approach + 12 * STEPS_PER_CONTACT
        normal = f"jkr/load-controlled {e_star!r} {w}" if model == "jkr" else f"hertz {e_star!r}"
        lines = pair_tabor(f"pair_coeff * * {normal} poisson {nu} tangential mindlin_deresiewicz NULL 0 {mu}")
        bodies = equal_spheres(r, rho)
        o = collide_oblique(lines, bodies, v, a, dt, reach, 12 * STEPS_PER_CONTACT)
        p = (o["sphere"]["velocity"][0] - o["target"]["velocity"][0],
             o["sphere"]["velocity"][1] - o["target"]["velocity"][1],
             o["sphere"]["angular_velocity"][2], o["target"]["angular_velocity"][2], o["separated"])
        ref_in = f"{r} {rho} {e} {nu} {w} {model} 0 {v} {a!r} {mu} {dt!r} {steps} {reach!r}\n"
        ref = [float(x) for x in subprocess.run([DEM], input=ref_in, check=True, capture_output=True,
                                                 text=True).stdout.split()]
        f_scale = force_scale(m_star, r_star, e_star, v, 1.5 * math.pi * w * r_star)
        inertia = 0.4 * 2 * m_star * r * r
        tol_v = EVENTS * dt * f_scale / m_star
        tol_w = EVENTS * dt * mu * r * f_scale / inertia
        du = math.hypot(p[0] - ref[0], p[1] - ref[1])
        dw = max(abs(p[2] - ref[2]), abs(p[3] - ref[3]))
        vt0 = v * math.sin(math.radians(a))
        beta = -(p[1] + r * (p[2] + p[3])) / vt0
        print(f"  {model:5} v {v:4.2f} angle {a:6.2f}: beta {beta:+.4f} separated {p[4]}; |du| {du:.1e} "
              f"(tol {tol_v:.1e}), |dw| {dw:.1e} (tol {tol_w:.1e})")
        if not all(math.isfinite(x) for x in p[:4]):
            failures.append(f"same form {model} v {v} angle {a}: not finite")
        elif du > tol_v or dw > tol_w or bool(ref[4]) != p[4]:
            failures.append(f"same form {model} v {v} angle {a}: du {du:.2e} (tol {tol_v:.2e}), dw {dw:.2e} "
                            f"(tol {tol_w:.2e}), separated {p[4]} vs {bool(ref[4])}")
        elif du > SAME_SCHEME * v or dw > SAME_SCHEME * v / r:
            failures.append(f"same form {model} v {v} angle {a}: du {du:.2e}, dw {dw:.2e}: beyond round-off "
                            f"of the same scheme ({SAME_SCHEME:.0e} of v, v/R)")
    return failures


def micro_slip_newton():
    """`mindlin_deresiewicz` with `damping coeff_restitution` (its coefficient the
    one x_gamma multiplies) and an initial spin: newton on and off give identical
    collisions (the plugin keeps each history on both atoms)."""
    failures = []
    lines = pair_tabor(f"pair_coeff * * jkr/load-controlled {E_STAR!r} {W} poisson {NU} damping coeff_restitution 0.7 "
                       f"tangential mindlin_deresiewicz NULL 0.5 {MU}")
    for a in (10, 40):
        on = collide(lines, 0.5, a, 2e4)
        off = collide(lines, 0.5, a, 2e4, newton="off")
        print(f"mindlin_deresiewicz + coeff_restitution, {a} degrees: newton on {on[:4]}, off identical: {off == on}")
        if off != on or not all(math.isfinite(x) for x in on[:4]):
            failures.append(f"mindlin_deresiewicz newton off differs or not finite at {a} degrees: {on} vs {off}")
    return failures


def main():
    failures = micro_slip_against_library()
    failures += micro_slip_same_form()
    failures += micro_slip_newton()
    failures += jkr_against_granular()
    failures += maugis_against_library()
    failures += maugis_twist_against_library()
    return report(failures, "plugin friction tests passed")


if __name__ == "__main__":
    sys.exit(main())

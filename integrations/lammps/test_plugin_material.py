"""pair_style tabor's material form (issue 33, "LAMMPS users give E and nu per type and
gamma per surface"): `pair_coeff I I material E nu gamma MODEL ...`, types mixed as
pair granular mixes them.

1. The material form against today's E*/w form with the mixed values computed here
   from the formulas (not by the plugin): E* = 1/((1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j),
   w = 2 sqrt(gamma_i gamma_j), k_t NULL = 8 G* with
   1/G* = 2 (2 - nu_i)(1 + nu_i)/E_i + 2 (2 - nu_j)(1 + nu_j)/E_j, every other
   coefficient sqrt(c_i c_j): oblique collisions 1-1, 2-2 and 1-2 of a two-type
   system (different E, nu, gamma, radius, density, damping, friction, rolling).
2. Against LAMMPS's own pair granular (jkr E eta nu gamma damping viscoelastic,
   tangential mindlin, rolling sds, twisting marshall) with the same per-type
   values, the cross pair mixed by both (k_t given per type); and with k_t NULL,
   the cross pair given to pair granular explicitly with the G* above.
3. pair granular (22 Jul 2025) does not mix k_t NULL as its documentation says: it
   evaluates 8 G with its *mixed* E* in place of a Young's modulus and nu =
   sqrt(nu_i nu_j), 8 E*/(4 (2 - nu)(1 + nu)). Measured here on one step of a
   sliding contact (the tangential force is k_t a v dt): pair granular's mixed NULL
   equals that value, tabor's mixed NULL the documented one.
4. fix wall/tabor material E nu gamma against fix wall/gran granular jkr E 0 nu
   gamma (a wall of the particles' material), and wall_material E_w nu_w gamma_w
   against the E*/w wall with the values mixed here.
5. Bad input: one `ERROR:` line naming the parameter, at pair_coeff or at init.

Tolerance: the same scheme run by two codes (or one code with equal coefficients
computed in a different order) agrees to round-off, SAME_SCHEME = 1e-9 of the scale
(v for velocities, v/R for spins), as in test_plugin_friction.py's docstring.

Needs TABOR_PLUGIN, TABOR_FFI_LIB, TABOR, LAMMPS_VENV, LD_LIBRARY_PATH=<venv>/lib.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collide import collide_oblique  # noqa: E402
from lammps_case import FFI, PLUGIN, error_line, hertz_contact_time, lmp_new, lmp_output, pair_tabor, report  # noqa: E402
from tabor_ffi import law_info  # noqa: E402
import test_plugin_wall as wall  # noqa: E402

SAME_SCHEME = 1e-9
STEPS_PER_CONTACT = 4000

# two materials: silica-like grains (type 1) and a stiffer, stickier type 2
MAT = {1: dict(E=54e9, nu=0.17, gamma=0.025, R=1.0e-6, rho=2650.0, eta=1e15, kt=2e4, x=0.5, mu=0.3,
               kr=50.0, mur=0.1),
       2: dict(E=120e9, nu=0.3, gamma=0.04, R=1.5e-6, rho=4000.0, eta=3e15, kt=5e4, x=0.3, mu=0.45,
               kr=80.0, mur=0.2)}


def geom(a, b):
    return math.sqrt(a * b)


def e_star(a, b):
    return 1.0 / ((1.0 - a["nu"] * a["nu"]) / a["E"] + (1.0 - b["nu"] * b["nu"]) / b["E"])


def g_star(a, b):
    return 1.0 / (2.0 * (2.0 - a["nu"]) * (1.0 + a["nu"]) / a["E"] + 2.0 * (2.0 - b["nu"]) * (1.0 + b["nu"]) / b["E"])


def mixed(i, j):
    """The coefficients of types i j from the formulas of the docstring."""
    a, b = MAT[i], MAT[j]
    return dict(Es=e_star(a, b), w=2.0 * geom(a["gamma"], b["gamma"]), kt_null=8.0 * g_star(a, b),
                **{k: geom(a[k], b[k]) for k in ("eta", "kt", "x", "mu", "kr", "mur", "gamma", "nu")})


def friction(c, kt):
    return (f"tangential mindlin {kt} {c['x']!r} {c['mu']!r} rolling sds {c['kr']!r} 0 {c['mur']!r} "
            "twisting marshall")


def material_line(t, null=True):
    m = MAT[t]
    return (f"pair_coeff {t} {t} material {m['E']!r} {m['nu']!r} {m['gamma']!r} jkr/load-controlled "
            f"damping viscoelastic {m['eta']!r} " + friction(m, "NULL" if null else repr(m["kt"])))


def estar_line(i, j):
    c = mixed(i, j)
    return (f"pair_coeff {i} {j} jkr/load-controlled {c['Es']!r} {c['w']!r} damping viscoelastic {c['eta']!r} "
            + friction(c, repr(c["kt_null"])))


def granular_line(t, null=True):
    m = MAT[t]
    return (f"pair_coeff {t} {t} jkr {m['E']!r} {m['eta']!r} {m['nu']!r} {m['gamma']!r} damping viscoelastic "
            + friction(m, "NULL" if null else repr(m["kt"])))


def granular_cross_doc():
    """pair granular's explicit 1 2 line with the documented mixing: E_12 and nu_12
    such that its one-material E* is the mixed E*, k_t = 8 G* (documented)."""
    c = mixed(1, 2)
    nu = c["nu"]
    e12 = 2.0 * (1.0 - nu * nu) * c["Es"]
    return (f"pair_coeff 1 2 jkr {e12!r} {c['eta']!r} {nu!r} {c['gamma']!r} damping viscoelastic "
            + friction(c, repr(c["kt_null"])))


def bodies(i, j):
    return {"sphere_radius": MAT[i]["R"], "sphere_density": MAT[i]["rho"],
            "target_radius": MAT[j]["R"], "target_density": MAT[j]["rho"]}


def masses(i, j):
    m = [MAT[t]["rho"] * 4 / 3 * math.pi * MAT[t]["R"] ** 3 for t in (i, j)]
    return m[0] * m[1] / (m[0] + m[1])


def collide(cmds, i, j, v, angle, spin=0.0):
    c = mixed(i, j)
    r_star = MAT[i]["R"] * MAT[j]["R"] / (MAT[i]["R"] + MAT[j]["R"])
    tc = hertz_contact_time(masses(i, j), r_star, c["Es"], v)
    reach = 2 * law_info(FFI, "jkr/load-controlled", c["Es"], r_star, c["w"]).interaction_range
    out = collide_oblique(cmds, bodies(i, j), v, angle, tc / STEPS_PER_CONTACT, reach, 12 * STEPS_PER_CONTACT,
                          spin=(0.0, 0.0, spin), types=(i, j), ntypes=2)
    s, t = out["sphere"], out["target"]
    return (s["velocity"][0] - t["velocity"][0], s["velocity"][1] - t["velocity"][1],
            s["angular_velocity"][2], t["angular_velocity"][2], out["separated"])


def compare(label, a, b, v, radius, failures):
    du = math.hypot(a[0] - b[0], a[1] - b[1])
    dw = max(abs(a[2] - b[2]), abs(a[3] - b[3]))
    print(f"  {label:46} u ({a[0]:+.6f}, {a[1]:+.6f}) |du| {du:.1e} |dw| {dw:.1e} (tol {SAME_SCHEME * v:.0e}, "
          f"{SAME_SCHEME * v / radius:.0e}) separated {a[4]}")
    if du > SAME_SCHEME * v or dw > SAME_SCHEME * v / radius or a[4] != b[4]:
        failures.append(f"{label}: |du| {du:.2e}, |dw| {dw:.2e}, separated {a[4]} vs {b[4]}")


PAIRS = [(1, 1), (2, 2), (1, 2)]
CASES = [(0.3, 30, 0.0), (0.6, 60, 2e4)]   # (speed m/s, angle deg, spin rad/s)


def tabor(lines):
    return pair_tabor(*lines)


def granular(lines):
    return ["pair_style granular", *lines]


def against_formulas():
    """1. material form (the plugin mixes 1 2) vs the E*/w form with the values mixed here."""
    failures = []
    ours = tabor([material_line(1), material_line(2)])
    hand = tabor([estar_line(1, 1), estar_line(2, 2), estar_line(1, 2)])
    for i, j in PAIRS:
        for v, a, s in CASES:
            compare(f"{i}-{j} v {v} angle {a} spin {s:g}: material vs E*/w", collide(ours, i, j, v, a, s),
                    collide(hand, i, j, v, a, s), v, MAT[i]["R"], failures)
    return failures


def against_granular():
    """2. material form vs pair granular, the same per-type values."""
    failures = []
    # k_t per type: both codes mix it (geometric mean), with everything else
    ours = tabor([material_line(1, null=False), material_line(2, null=False)])
    theirs = granular([granular_line(1, null=False), granular_line(2, null=False)])
    for i, j in PAIRS:
        v, a, s = CASES[0]
        compare(f"{i}-{j} v {v} angle {a}: k_t given, both mix", collide(ours, i, j, v, a, s),
                collide(theirs, i, j, v, a, s), v, MAT[i]["R"], failures)
    # k_t NULL: the cross pair given to pair granular with the documented G*
    ours = tabor([material_line(1), material_line(2)])
    theirs = granular([granular_line(1), granular_line(2), granular_cross_doc()])
    for i, j in PAIRS:
        for v, a, s in CASES:
            compare(f"{i}-{j} v {v} angle {a} spin {s:g}: k_t NULL", collide(ours, i, j, v, a, s),
                    collide(theirs, i, j, v, a, s), v, MAT[i]["R"], failures)
    return failures


def sliding_force(lines):
    """The tangential force on atom 1 (type 1) after one step of a contact of types
    1 and 2 at a fixed overlap of 2 nm sliding at 1 mm/s: k_t a v dt (no damping)."""
    lmp = lmp_new()
    try:
        d = MAT[1]["R"] + MAT[2]["R"] - 2e-9
        for c in ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
                  "region box block -1e-5 1e-5 -1e-5 1e-5 -1e-5 1e-5", "create_box 2 box",
                  "create_atoms 1 single 0 0 0", f"create_atoms 2 single {d!r} 0 0",
                  f"set atom 1 diameter {2 * MAT[1]['R']!r} density 2650",
                  f"set atom 2 diameter {2 * MAT[2]['R']!r} density 2650",
                  "set atom 1 vy 1e-3", "neighbor 2e-7 bin", *lines, "fix 1 all nve/sphere",
                  "timestep 1e-13", "run 1"]:
            lmp.command(c)
        tag, f = lmp.extract_atom("id"), lmp.extract_atom("f")
        k = 0 if tag[0] == 1 else 1
        return f[k][1]
    finally:
        lmp.close()


def null_mixing():
    """3. k_t NULL of the cross pair: pair granular's code against its documentation."""
    failures = []
    c = mixed(1, 2)
    nu = c["nu"]
    code_kt = 8.0 * c["Es"] / (4.0 * (2.0 - nu) * (1.0 + nu))

    def line(t, kt, form):
        m = MAT[t] if t else c
        if form == "granular":
            e = m["E"] if t else 2.0 * (1.0 - nu * nu) * c["Es"]
            return (f"pair_coeff {t or 1} {t or 2} jkr {e!r} 0 {m['nu']!r} {m['gamma']!r} damping viscoelastic "
                    f"tangential mindlin {kt} 0 10")
        if t:
            return (f"pair_coeff {t} {t} material {m['E']!r} {m['nu']!r} {m['gamma']!r} jkr/load-controlled "
                    f"tangential mindlin {kt} 0 10")
        return f"pair_coeff 1 2 jkr/load-controlled {c['Es']!r} {c['w']!r} tangential mindlin {kt} 0 10"

    g_mixed = sliding_force(granular([line(1, "NULL", "granular"), line(2, "NULL", "granular")]))
    g_code = sliding_force(granular([line(1, "NULL", "granular"), line(2, "NULL", "granular"),
                                     line(0, repr(code_kt), "granular")]))
    g_doc = sliding_force(granular([line(1, "NULL", "granular"), line(2, "NULL", "granular"),
                                    line(0, repr(c["kt_null"]), "granular")]))
    t_mixed = sliding_force(tabor([line(1, "NULL", "tabor"), line(2, "NULL", "tabor")]))
    t_doc = sliding_force(tabor([line(1, "NULL", "tabor"), line(2, "NULL", "tabor"),
                                 line(0, repr(c["kt_null"]), "tabor")]))
    print(f"  pair granular mixed NULL: F_t {g_mixed:.6e}; with k_t 8 E*/(4(2-nu)(1+nu)) {g_code:.6e}; "
          f"with the documented 8 G* {g_doc:.6e} (ratio {g_mixed / g_doc:.4f})")
    print(f"  pair tabor mixed NULL:    F_t {t_mixed:.6e}; with the documented 8 G* {t_doc:.6e}")
    if abs(g_mixed - g_code) > 1e-12 * abs(g_code):
        failures.append(f"pair granular's mixed k_t NULL is no longer 8 E*/(4(2-nu)(1+nu)) ({g_mixed} vs {g_code}): "
                        "update doc/pair_tabor.rst's Mixing section")
    if abs(t_mixed - t_doc) > 1e-12 * abs(t_doc):
        failures.append(f"pair tabor's mixed k_t NULL is not the documented 8 G* ({t_mixed} vs {t_doc})")
    if abs(t_mixed - g_doc) > 1e-9 * abs(g_doc):
        failures.append(f"pair tabor's mixed k_t NULL differs from pair granular given the same k_t ({t_mixed} vs {g_doc})")
    return failures


STEEL = dict(E=200e9, nu=0.3, gamma=0.0125)


def walls():
    """4. fix wall/tabor material ... against fix wall/gran granular jkr (the wall of
    the particles' material), and wall_material against the E*/w wall mixed here."""
    failures = []
    silica = dict(E=wall.E, nu=wall.NU, gamma=wall.W / 2)
    reach = law_info(FFI, "jkr/load-controlled", wall.E_STAR, wall.R, wall.W).interaction_range
    ours = f"material {wall.E!r} {wall.NU!r} {wall.W / 2!r} jkr/load-controlled {wall.FRICTION}"
    es, w, kt = e_star(silica, STEEL), 2.0 * geom(silica["gamma"], STEEL["gamma"]), 8.0 * g_star(silica, STEEL)
    own = f"material {wall.E!r} {wall.NU!r} {wall.W / 2!r} jkr/load-controlled {wall.FRICTION} " \
          f"wall_material {STEEL['E']!r} {STEEL['nu']!r} {STEEL['gamma']!r}"
    hand = (f"jkr/load-controlled {es!r} {w!r} tangential mindlin {kt!r} 0 {wall.MU} "
            f"rolling sds {wall.K_ROLL} 0 {wall.MU_ROLL} twisting marshall")
    for v, a in ((0.3, 30.0), (1.0, 60.0)):
        dt = wall.contact_time(v) / wall.STEPS
        for label, x, y in (("material vs fix wall/gran", wall.plugin_wall(ours), wall.granular_wall()),
                            ("wall_material vs E*/w", wall.plugin_wall(own), wall.plugin_wall(hand))):
            ua, wa, sa = wall.wall_collide(x, v, dt, reach, a)
            ub, wb, sb = wall.wall_collide(y, v, dt, reach, a)
            du, dw = math.dist(ua, ub), math.dist(wa, wb)
            print(f"  wall {label:26} v {v} angle {a:4.0f}: |du| {du:.1e} |dw| {dw:.1e} "
                  f"(tol {SAME_SCHEME * v:.0e}, {SAME_SCHEME * v / wall.R:.0e}) separated {sa}")
            if du > SAME_SCHEME * v or dw > SAME_SCHEME * v / wall.R or sa != sb:
                failures.append(f"wall {label} v {v} angle {a}: |du| {du:.2e}, |dw| {dw:.2e}, separated {sa} vs {sb}")
    return failures


HEAD = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
        "region box block -1e-4 1e-4 -1e-4 1e-4 -1e-4 1e-4", "create_box 3 box",
        "create_atoms 1 single 0 0 0", "create_atoms 2 single 1e-5 0 0", "create_atoms 3 single 2e-5 0 0",
        "set atom * diameter 2e-6 density 2650", f"plugin load {PLUGIN}", "pair_style tabor"]
OK = "material 54e9 0.17 0.025 jkr/load-controlled"
RUN = ["neighbor 2e-7 bin", "fix integrate all nve/sphere", "timestep 1e-10", "run 0"]
BAD = [  # (lines after HEAD, words of the error)
    ([f"pair_coeff * * material 0 0.17 0.025 jkr/load-controlled"], ["material", "Young's modulus E 0"]),
    ([f"pair_coeff * * material -5e9 0.17 0.025 jkr/load-controlled"], ["Young's modulus E -5000000000"]),
    ([f"pair_coeff * * material 1e999 0.17 0.025 jkr/load-controlled"], ["1e999", "out of range"]),
    ([f"pair_coeff * * material 54e9 0.5 0.025 jkr/load-controlled"], ["Poisson's ratio nu 0.5", "(-1, 0.5)"]),
    ([f"pair_coeff * * material 54e9 -1 0.025 jkr/load-controlled"], ["Poisson's ratio nu -1"]),
    ([f"pair_coeff * * material 54e9 0.17 -0.01 jkr/load-controlled"], ["surface energy gamma -0.01"]),
    ([f"pair_coeff * * material 54e9 0.17 jkr/load-controlled"],
     ["material: surface energy gamma must be a number, not jkr/load-controlled"]),
    ([f"pair_coeff * * material 54e9 0.17 0.025"], ["missing the model"]),
    ([f"pair_coeff * * material 54e9 0.17 0.025 hertz"], ["hertz has no adhesion", "gamma 0.025"]),
    ([f"pair_coeff * * {OK} poisson 0.2"], ["poisson belongs to the E* form"]),
    ([f"pair_coeff * * {OK} wall_material 200e9 0.3 0"], ["wall_material belongs to a wall fix"]),
    ([f"pair_coeff 1 1 {OK}", "pair_coeff 2 2 jkr/load-controlled 2.78e10 0.05", "pair_coeff 3 3 " + OK,
      "pair_coeff 2 3 " + OK] + RUN,
     ["types 1 2", "pair_coeff 1 1 and 2 2 cannot be mixed", "only the material form"]),
    ([f"pair_coeff 1 1 {OK}", "pair_coeff 2 2 material 54e9 0.17 0.025 jkr/fixed-grip", "pair_coeff 3 3 " + OK,
      "pair_coeff 2 3 " + OK] + RUN,
     ["types 1 2", "the models differ (jkr/load-controlled, jkr/fixed-grip)"]),
    ([f"pair_coeff 1 1 {OK} damping viscoelastic 1e15", f"pair_coeff 2 2 {OK}", "pair_coeff 3 3 " + OK,
      "pair_coeff 2 3 " + OK] + RUN, ["types 1 2", "the damping models differ"]),
    ([f"pair_coeff 1 1 {OK} tangential mindlin NULL 0 0.3", f"pair_coeff 2 2 {OK}", "pair_coeff 3 3 " + OK,
      "pair_coeff 2 3 " + OK] + RUN, ["types 1 2", "the tangential models differ"]),
    ([f"pair_coeff 1 1 material 54e9 0.17 0.025 maugis range 3e-10",
      "pair_coeff 2 2 material 54e9 0.17 0.025 maugis 0.5", "pair_coeff 3 3 material 54e9 0.17 0.025 maugis 0.5",
      "pair_coeff 1 3 material 54e9 0.17 0.025 maugis 0.5"] + RUN,
     ["types 1 2", "maugis is given with range h and with a fixed Lambda"]),
    ([f"pair_coeff 1 1 {OK}", f"pair_coeff 3 3 {OK}", f"pair_coeff 1 3 {OK}"] + RUN, ["All pair coeffs are not set"]),
]


def lmp_run(lines):
    return lmp_output(lines, timeout=60)


def bad_input():
    """5. each bad input: one `ERROR:` line of error->all naming the parameter."""
    failures = []
    for lines, words in BAD:
        status, out = lmp_run(HEAD + lines)
        line = error_line(out)
        print(f"  {lines[-1 if lines[-1] != 'run 0' else 0][:60]:60} -> {line}")
        if status == 0 or line is None:
            failures.append(f"{lines}: not refused")
        elif not line.startswith("ERROR: ") or "on proc" in out:
            failures.append(f"{lines}: not a clean error->all: {line}")
        elif not all(w in line for w in words):
            failures.append(f"{lines}: the error does not say {words}: {line}")
    # the mixed pair runs where it can be mixed, and an explicit 1 2 line overrides
    good = HEAD + [f"pair_coeff 1 1 {OK}", "pair_coeff 2 2 material 70e9 0.2 0.03 jkr/load-controlled",
                   f"pair_coeff 3 3 {OK}", "pair_coeff 1 3 jkr/fixed-grip 2e10 0.05"] + RUN
    maugis = HEAD + ["pair_coeff 1 1 material 54e9 0.17 0.025 maugis range 3e-10 damping 1e-10",
                     "pair_coeff 2 2 material 70e9 0.2 0.03 maugis range 5e-10 damping 2e-10",
                     "pair_coeff 3 3 material 200e9 0.3 0 hertz", "pair_coeff 1 3 hertz 2e10",
                     "pair_coeff 2 3 hertz 2e10"] + RUN
    for lines in (good, maugis):
        status, out = lmp_run(lines)
        if status != 0:
            failures.append(f"a mixable system was refused: {out[-300:]}")
    return failures


def remix():
    """A mixed pair follows a later pair_coeff J J (mixed again at the next run):
    the force on atom 1 (type 1, overlapping atom 2 of type 2) after changing type
    2's material equals that of a fresh setup with the new material."""
    failures = []
    head = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
            "region box block -1e-5 1e-5 -1e-5 1e-5 -1e-5 1e-5", "create_box 2 box", "create_atoms 1 single 0 0 0",
            "create_atoms 2 single 1.99e-6 0 0", "set atom * diameter 2e-6 density 2650", "neighbor 2e-7 bin",
            f"plugin load {PLUGIN}", "pair_style tabor", "pair_coeff 1 1 " + OK]
    soft, stiff = "pair_coeff 2 2 material 20e9 0.3 0.01 jkr/load-controlled", \
        "pair_coeff 2 2 material 150e9 0.25 0.05 jkr/load-controlled"
    show = ["variable fx equal fx[1]", 'print "FX ${fx}"']
    _, changed = lmp_run(head + [soft, "run 0", stiff, "run 0"] + show)
    _, fresh = lmp_run(head + [stiff, "run 0"] + show)
    _, before = lmp_run(head + [soft, "run 0"] + show)
    values = [[x.split()[1] for x in out.splitlines() if x.startswith("FX ")] for out in (changed, fresh, before)]
    print(f"  type 2 changed after a run: fx[1] {values[0]}, fresh {values[1]}, before the change {values[2]}")
    if not all(values) or values[0][-1] != values[1][-1] or values[0][-1] == values[2][-1]:
        failures.append(f"the mixed pair 1 2 did not follow pair_coeff 2 2: {values}")
    return failures


def main():
    failures = []
    print("1. material form against the E*/w form with the values mixed from the formulas")
    failures += against_formulas()
    print("2. material form against pair granular jkr with the same E, nu, gamma per type")
    failures += against_granular()
    print("3. k_t NULL of a cross pair: pair granular's code, its documentation, tabor")
    failures += null_mixing()
    print("4. fix wall/tabor material (and wall_material)")
    failures += walls()
    print("5. bad input")
    failures += bad_input()
    failures += remix()
    return report(failures, "material form tests passed")


if __name__ == "__main__":
    sys.exit(main())

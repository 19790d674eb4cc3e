"""Scenes: the round trip against `tabor impact --json` of the same tree, the
restitution batch against outcome() and the JKR closed form (5.37)/(5.38), sweeps
and trajectories."""

import math
import re
import warnings

import numpy as np
import pytest

import tabor
from conftest import SCENES

SCENE_FILES = sorted(SCENES.glob("*.toml"))

# the keys the package documents and these tests rely on; the library may add more
KEYS = {
    "scene",
    "impact_speed",
    "restitution",
    "sticks",
    "sticking_velocity",
    "energy_loss",
    "kinetic_energy",
    "model",
    "branch",
    "tabor_parameter",
    "effects",
    "accuracy",
    "energy_loss_error",
    "cost",
    "warnings",
}


def without_version(ref):
    """The CLI's JSON without `tabor_version` (Python has `tabor.__version__`)."""
    assert ref.pop("tabor_version") == tabor.__version__
    return ref


def assert_same(py, cli, path="outcome"):
    """Equal as JSON values; floats to 1e-12 relative (the CLI is a debug build)."""
    if isinstance(cli, dict):
        assert isinstance(py, dict), path
        assert set(py) == set(cli), f"{path}: keys {sorted(set(py) ^ set(cli))} differ"
        for k in cli:
            assert_same(py[k], cli[k], f"{path}.{k}")
    elif isinstance(cli, list):
        assert isinstance(py, list) and len(py) == len(cli), path
        for i, (a, b) in enumerate(zip(py, cli)):
            assert_same(a, b, f"{path}[{i}]")
    elif isinstance(cli, float) and not isinstance(cli, bool):
        assert py == pytest.approx(cli, rel=1e-12, abs=0), path
    else:
        assert py == cli and type(py) is type(cli), f"{path}: {py!r} != {cli!r}"


def test_example_scenes_exist():
    assert len(SCENE_FILES) >= 5


@pytest.mark.parametrize("path", SCENE_FILES, ids=lambda p: p.stem)
def test_round_trip_against_cli_impact_json(path, cli):
    scene = tabor.Scene.from_path(path)
    if scene.speed is None:
        pytest.skip("no [impact] speed")
    py = scene.outcome()
    assert KEYS <= set(py), f"missing {KEYS - set(py)}"
    assert_same(py, without_version(cli("impact", str(path), "--json")))


def test_round_trip_at_another_speed(cli):
    path = SCENES / "silica_maugis.toml"
    py = tabor.Scene.from_path(path).outcome(speed=0.37)
    assert_same(py, without_version(cli("impact", str(path), "--speed", "0.37", "--json")))


def test_from_toml_equals_from_path():
    path = SCENES / "silica.toml"
    a = tabor.Scene.from_path(path).outcome()
    b = tabor.Scene.from_toml(path.read_text()).outcome()
    assert a == b


def test_from_json():
    text = """{"sphere": {"radius": 1e-6, "density": 2650, "youngs_modulus": 54e9,
               "poisson_ratio": 0.17},
               "target": {"youngs_modulus": 54e9, "poisson_ratio": 0.17},
               "adhesion": {"work_of_adhesion": 0.05}, "impact": {"speed": 0.2}}"""
    o = tabor.Scene.from_json(text).outcome()
    assert 0 < o["restitution"] < 1


def test_jkr_scene_restitution_is_the_closed_form():
    # silica.toml is JKR (no range): ε = √(1 − v_c²/v²) (5.37), (5.38), 0 below v_c
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    v_c = scene.sticking_velocity()
    assert v_c == pytest.approx(0.08659806, rel=1e-6)
    v = np.geomspace(0.5 * v_c, 100 * v_c, 500)
    e = scene.restitution(v)
    ref = np.sqrt(np.clip(1 - (v_c / v) ** 2, 0, None))
    np.testing.assert_allclose(e, ref, rtol=1e-12, atol=1e-12)
    assert np.all(e[v < v_c] == 0)


def test_restitution_batch_equals_outcome():
    scene = tabor.Scene.from_path(SCENES / "silica_maugis.toml")
    v = np.array([[0.05, 0.1], [0.3, 2.0]])
    e = scene.restitution(v)
    assert e.shape == (2, 2) and e.dtype == np.float64
    for idx in np.ndindex(v.shape):
        assert e[idx] == scene.outcome(speed=v[idx])["restitution"]
    assert isinstance(scene.restitution(0.3), float)


def test_sweep_columns():
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    v = np.geomspace(0.01, 1, 7)
    s = scene.sweep("speed", v)
    assert s["restitution"].shape == (7,) and s["restitution"].dtype == np.float64
    assert s["sticks"].dtype == np.bool_
    np.testing.assert_array_equal(s["restitution"], scene.restitution(v))
    np.testing.assert_array_equal(s["values"], v)
    assert all(isinstance(m, str) for m in s["model"])
    # another parameter: the work of adhesion (the loss grows like Δγ^(5/3))
    w = scene.sweep("work_of_adhesion", [0.025, 0.05])
    assert w["energy_loss"][1] / w["energy_loss"][0] == pytest.approx(2 ** (5 / 3), rel=1e-10)


def test_long_coupled_arrays_answer_like_single_outcomes():
    # 600 speeds of the coupled viscous-adhesive scene: prepared once for the
    # whole array (Scene::speed_batch_over), so the model answers from its speed
    # table certified against its simulation (tolerance 1e-10 of the scene);
    # every 50th point against an outcome of its own (simulated)
    scene = tabor.Scene.from_path(SCENES / "polymer_grains_viscoadhesive.toml")
    v = np.geomspace(0.9, 5.0, 600)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        e = scene.restitution(v)
        s = scene.sweep("speed", v)
        for i in range(0, 600, 50):
            one = scene.outcome(speed=v[i])["restitution"]
            assert e[i] == pytest.approx(one, rel=0, abs=1e-9), i
            assert s["restitution"][i] == pytest.approx(one, rel=0, abs=1e-9), i
    np.testing.assert_array_equal(s["sticks"], e == 0.0)


def test_sweep_with_more_distinct_strings_than_one_byte_codes_hold():
    # every Tabor parameter names its model: 300 distinct strings in one column,
    # merged from chunks with two-byte codes; each point against a sweep of its
    # own value (one-byte codes)
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    lam = np.geomspace(0.1, 10.0, 300)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = scene.sweep("tabor_parameter", lam)
        assert len(set(s["model"])) == 300
        for i in (0, 1, 254, 255, 256, 299):
            one = scene.sweep("tabor_parameter", [lam[i]])
            assert s["model"][i] == one["model"][0] and s["branch"][i] == one["branch"][0]
            assert s["restitution"][i] == one["restitution"][0]


def test_sweep_reasons_are_templates_with_their_numbers():
    # the plastic reason quotes the speed and the yield onset: one template for
    # every point below the onset, its numbers in reason_values
    scene = tabor.Scene.from_path(SCENES / "silica_maugis_plastic.toml")
    v = np.geomspace(0.05, 5, 8).reshape(2, 4)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = scene.sweep("speed", v)
        outcomes = {idx: scene.outcome(speed=v[idx]) for idx in np.ndindex(v.shape)}
    assert s["effects.plasticity.reason_values"].shape == (2, 4, 2)
    assert len(set(s["effects.plasticity.reason"][v < 1.9])) == 1
    number = re.compile(r"-?\d+(\.\d+)?e-?\d+")
    for idx, o in outcomes.items():
        for e in o["effects"]:
            text = s[f"effects.{e['name']}.reason"][idx].format(*s[f"effects.{e['name']}.reason_values"][idx])
            assert text == number.sub(lambda m: repr(float(m.group())), e["reason"]), (idx, e["name"])
    assert s["effects.elasticity.reason_values"].shape == (2, 4, 0)


def _silica_pair():
    eff = tabor.effective(youngs_modulus=54e9, poisson_ratio=0.17, radius=1e-6, density=2650.0, target_radius=1e-6)
    return eff["effective_modulus"], eff["effective_radius"], 0.05


def test_force_law_jkr_is_the_closed_form():
    # (5.33)/(5.34) parametrized by the contact radius, from first touch up
    e, r, w = _silica_pair()
    a0 = (9 * math.pi * w * r**2 / (8 * e)) ** (1 / 3) * (4 / 3) ** (2 / 3)  # d = 0
    a = a0 * np.linspace(1.0, 6.0, 40)
    d = a**2 / r - np.sqrt(2 * math.pi * w * a / e)
    f = 4 * e * a**3 / (3 * r) - np.sqrt(8 * math.pi * w * e * a**3)
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    np.testing.assert_allclose(scene.force(d), f, rtol=1e-9, atol=1e-12 * abs(f[0]))
    assert isinstance(scene.force(float(d[3])), float)
    assert scene.force(d.reshape(4, 10), overlap_rate=0.1).shape == (4, 10)


def test_force_law_maugis_dugdale_loading_path():
    # zero while the spheres approach, then the Maugis-Dugdale curve (in SI units,
    # force_displacement) beyond the jump into contact
    e, r, w = _silica_pair()
    sigma0 = w / 0.3e-9
    a = np.geomspace(2e-8, 1e-7, 30)
    f, d = tabor.force_displacement("maugis-dugdale", a, radius=r, contact_modulus=e, work_of_adhesion=w,
                                    cohesive_stress=sigma0)
    scene = tabor.Scene.from_path(SCENES / "silica_maugis.toml")
    on_curve = d > 0
    assert on_curve.sum() > 10
    np.testing.assert_allclose(scene.force(d[on_curve]), f[on_curve], rtol=1e-8, atol=1e-10 * abs(f).max())
    assert scene.force(-2e-9) == 0.0


def test_force_law_errors():
    with pytest.raises(tabor.ModelValidityError, match="no time-domain force law"):
        tabor.Scene.from_path(SCENES / "rubber_balls.toml").force(1e-6)
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    with pytest.raises(tabor.InputError, match="speed"):
        scene.force(1e-9, speed=-1.0)
    with pytest.raises(TypeError):
        scene.force("1e-9")
    with pytest.warns(tabor.InvalidPointsWarning, match="1 of 2"):
        out = scene.force([1e-9, -1e-6], errors="nan")
    assert np.isfinite(out[0]) and np.isnan(out[1])


def test_trajectory():
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    tr = scene.trajectory(tolerance=1e-9)
    for k in ("t", "d", "d_dot", "F", "a"):
        assert tr[k].shape == (tr["points"],)
    assert np.all(np.diff(tr["t"]) > 0)
    assert tr["restitution"] == pytest.approx(tr["restitution_analytic"], rel=1e-6)
    assert tr["max_overlap"] == pytest.approx(tr["d"].max(), rel=1e-6)


def test_scene_properties():
    scene = tabor.Scene.from_path(SCENES / "silica_maugis.toml")
    assert scene.name == "silica-maugis"
    assert scene.speed is not None
    assert scene.tabor_parameter is not None and scene.tabor_parameter > 0
    assert "Scene" in repr(scene)
    assert math.isfinite(scene.sticking_velocity())


def _with_accuracy(name, accuracy):
    """The bundled scene `name` with the top-level `accuracy` set."""
    lines = [l for l in (SCENES / name).read_text().splitlines() if not l.startswith("accuracy")]
    out = []
    for l in lines:
        out.append(l)
        if l.startswith("name ="):
            out.append(f"accuracy = {accuracy}")
    return tabor.Scene.from_toml("\n".join(out) + "\n")


def test_accuracy_floors_are_warned():
    """A path that computes at a floor of `tabor_numerics::tolerance` coarser than
    the scene's accuracy says so (code `accuracy-floor`); at the floor, silence."""

    def floors(run):
        with warnings.catch_warnings(record=True) as seen:
            warnings.simplefilter("always")
            out = run()
        return out, [str(w.message) for w in seen if "FLOOR" in str(w.message)]

    assert floors(lambda: _with_accuracy("rubber_viscoelastic.toml", "1e-12").outcome())[1] == []
    o, named = floors(lambda: _with_accuracy("rubber_viscoelastic.toml", "1e-13").outcome())
    assert len(named) == 1 and "MODEL_ACCURACY_FLOOR" in named[0]
    assert any(w["code"] == "accuracy-floor" for w in o["warnings"])
    oblique = lambda a: _with_accuracy("silica_oblique.toml", a).outcome(0.3, angle=40.0)
    assert floors(lambda: oblique("1e-13"))[1] == []
    o, named = floors(lambda: oblique("1e-14"))
    assert len(named) == 1 and "SIMULATION_ACCURACY_FLOOR" in named[0]
    assert any(w["code"] == "accuracy-floor" for w in o["warnings"])


def test_damped_scene_through_the_scene_api():
    """A scene with [damping] (silica_damped.toml: JKR + coeff_restitution e = 0.9)
    through the same Scene API: the dem-damping rule names the damping loss, sticks
    below the sticking velocity, tends to e far above it; without adhesion
    coeff_restitution gives e exactly (Hertz); sweeps and trajectories work."""
    s = tabor.Scene.from_path(SCENES / "silica_damped.toml")
    vc = s.sticking_velocity()
    assert math.isfinite(vc) and vc > 0
    below, above = s.outcome(0.5 * vc), s.outcome(100 * vc)
    assert below["sticks"] and below["restitution"] == 0.0
    assert not above["sticks"] and abs(above["restitution"] - 0.9) < 0.02
    assert above["combination"]["rule"] == "dem-damping"
    damping = next(e for e in above["effects"] if e["name"] == "damping")
    assert damping["used"] and damping["energy_loss"] > 0
    sw = s.sweep("speed", np.geomspace(0.1 * vc, 10 * vc, 5))
    assert np.all(np.isfinite(sw["restitution"]))
    assert sw["effects.damping.used"].all()
    tr = s.trajectory(10 * vc, tolerance=1e-9)
    assert tr["restitution"] == pytest.approx(s.outcome(10 * vc)["restitution"], rel=1e-6)
    hertz = tabor.Scene.from_toml(
        (SCENES / "silica_damped.toml").read_text().replace("work_of_adhesion = 0.05", "work_of_adhesion = 0.0"))
    assert hertz.outcome(0.3)["restitution"] == pytest.approx(0.9, abs=1e-9)

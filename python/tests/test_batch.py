"""Batch semantics and Python conventions: exception classes, TypeError, strict
booleans and strings, validity warnings through `warnings`, errors="nan",
threads=, Ctrl-C, empty inputs, result types."""

import os
import signal
import subprocess
import sys
import textwrap
import time
import warnings

import numpy as np
import pytest

import tabor
from conftest import SCENES

JKR = dict(contact_modulus=1e9, radius=1e-6, work_of_adhesion=0.05, mass=1e-14)


def test_exception_classes():
    assert issubclass(tabor.InputError, ValueError) and issubclass(tabor.InputError, tabor.TaborError)
    assert issubclass(tabor.ModelValidityError, ValueError)
    assert issubclass(tabor.ConvergenceError, RuntimeError)
    with pytest.raises(tabor.InputError, match=r"invalid tabor_parameter = -1"):
        tabor.maugis_dugdale_loss(-1.0)
    with pytest.raises(tabor.InputError, match=r"invalid contact_modulus = -1e9"):
        tabor.jkr(**{**JKR, "contact_modulus": -1e9})
    # valid numbers outside the model: the Maugis-Dugdale branch at a tiny lambda
    with pytest.raises(tabor.ModelValidityError, match=r"maugis_parameter = 1e-30.*DMT"):
        tabor.maugis_dugdale_curve(contact_radius=1.0, maugis_parameter=1e-30)


@pytest.mark.parametrize("bad", [None, "abc", "1.5", 1 + 2j, [1.0, None], True])
def test_type_errors_for_numbers(bad):
    with pytest.raises(TypeError):
        tabor.maugis_dugdale_loss(bad)
    with pytest.raises(TypeError):
        tabor.jkr(**{**JKR, "mass": bad})


def test_strict_booleans_and_strings():
    with pytest.raises(TypeError, match="fast must be True or False"):
        tabor.maugis_dugdale_loss(1.0, fast="no")
    with pytest.raises(TypeError, match="fast must be True or False"):
        tabor.maugis_dugdale_loss(1.0, fast=1)
    assert tabor.maugis_dugdale_loss(1.0, fast=np.bool_(True)) > 0
    with pytest.raises(TypeError, match="rigid_target must be True or False"):
        tabor.effective(youngs_modulus=1e9, poisson_ratio=0.3, radius=1e-6, mass=1.0, rigid_target="yes")
    with pytest.raises(TypeError, match="separation must be a str"):
        tabor.jkr(**JKR, separation=1)
    with pytest.raises(TypeError, match="model must be a str"):
        tabor.plastic(model=None, contact_modulus=1e11, radius=1e-4, mass=1e-8, yield_stress=1e9, speed=1.0)
    with pytest.raises(TypeError):
        tabor.jkr(**JKR, colour="red")  # an unknown keyword
    with pytest.raises(TypeError):
        tabor.jkr(radius=1e-6)  # a missing keyword
    with pytest.raises(TypeError):
        tabor.maugis_dugdale_loss(1.0, threads=1.5)
    with pytest.raises(tabor.InputError, match='errors = "ignore"'):
        tabor.maugis_dugdale_loss(1.0, errors="ignore")


def test_errors_nan_counts_and_marks_the_invalid_points():
    lam = np.array([1.0, -1.0, 2.0, np.nan])
    with pytest.warns(tabor.InvalidPointsWarning, match=r"2 of 4 points invalid.*tabor_parameter = -1.*\(at index 1\)"):
        w = tabor.maugis_dugdale_loss(lam, errors="nan")
    assert np.isnan(w[[1, 3]]).all() and np.isfinite(w[[0, 2]]).all()
    assert w[0] == tabor.maugis_dugdale_loss(1.0)
    with pytest.warns(tabor.InvalidPointsWarning, match="1 of 3"):
        out = tabor.jkr(**{**JKR, "mass": [1e-14, -1.0, 2e-14]}, speed=1.0, errors="nan")
    np.testing.assert_array_equal(out["valid"], [True, False, True])
    assert np.isnan(out["restitution"][1]) and out["model"][1] is None and out["evaluations"][1] == -1
    assert out["restitution"][0] == tabor.jkr(**JKR, speed=1.0)["restitution"]
    # raise mode (the default) names the first bad point
    with pytest.raises(tabor.InputError, match=r"\(at index 1\)"):
        tabor.jkr(**{**JKR, "mass": [1e-14, -1.0, -2.0]})
    # no warning when every point is valid
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        tabor.maugis_dugdale_loss([1.0, 2.0], errors="nan")


def test_validity_warnings_reach_the_warnings_module():
    scene = tabor.Scene.from_path(SCENES / "rubber_balls.toml")
    with pytest.warns(tabor.QuasiStaticWarning, match=r"elastic wave speed"):
        o = scene.outcome()
    assert any(w["code"] == "quasi-static" for w in o["warnings"])
    with warnings.catch_warnings():
        warnings.simplefilter("error", tabor.QuasiStaticWarning)  # as python -W error
        with pytest.raises(tabor.QuasiStaticWarning):
            scene.outcome()
    # restitution() reports the warnings of its fastest point
    with pytest.warns(tabor.QuasiStaticWarning, match="fastest"):
        scene.restitution([0.1, scene.speed])
    # a sweep counts them
    with pytest.warns(tabor.QuasiStaticWarning, match=r"\[\d+ of 3 points"):
        s = scene.sweep("speed", [scene.speed, 2 * scene.speed, 3 * scene.speed])
    assert all("quasi-static" in w for w in s["warnings"])
    coupled = tabor.Scene.from_path(SCENES / "polymer_grains_viscoadhesive.toml")
    with pytest.warns(tabor.CoupledModelWarning):
        coupled.outcome()
    assert issubclass(tabor.CoupledModelWarning, tabor.TaborWarning)


def test_warning_points_at_the_callers_line():
    scene = tabor.Scene.from_path(SCENES / "rubber_balls.toml")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scene.outcome()
    assert caught and all(w.filename == __file__ for w in caught)


def test_threads():
    lam = np.geomspace(0.01, 100, 20000)
    a = tabor.maugis_dugdale_loss(lam, fast=True, threads=1)
    b = tabor.maugis_dugdale_loss(lam, fast=True, threads=2)
    np.testing.assert_array_equal(a, b)
    default = tabor.get_num_threads()
    try:
        tabor.set_num_threads(1)
        assert tabor.get_num_threads() == 1
        np.testing.assert_array_equal(tabor.maugis_dugdale_loss(lam, fast=True), a)
    finally:
        tabor.set_num_threads(None)
    assert tabor.get_num_threads() == default
    with pytest.raises(tabor.InputError):
        tabor.set_num_threads(0)


def test_empty_inputs_give_empty_columns_with_every_key():
    full = tabor.jkr(**JKR, speed=[1.0])
    empty = tabor.jkr(**JKR, speed=np.empty(0))
    assert set(empty) == set(full)
    for k, v in empty.items():
        assert v.shape == (0,) and v.dtype == full[k].dtype, k
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    s0 = scene.sweep("speed", [])
    s1 = scene.sweep("speed", [0.1])
    assert set(s0) == set(s1)
    assert tabor.maugis_dugdale_loss(np.empty((0, 2))).shape == (0, 2)
    assert scene.restitution(np.empty(0)).shape == (0,)


def test_result_types():
    out = tabor.jkr(**JKR, speed=[0.5, 1.0])
    assert out["evaluations"].dtype == np.int64
    assert type(tabor.jkr(**JKR)["evaluations"]) is int
    assert "tabor_version" not in out and "restitution" not in tabor.jkr(**JKR)
    assert isinstance(tabor.__version__, str) and tabor.__version__.count(".") >= 2
    s = tabor.Scene.from_path(SCENES / "silica.toml").sweep("speed", [0.1, 0.2])
    assert "tabor_version" not in s and s["cost.evaluations"].dtype == np.int64
    assert s["effects.adhesion.used"].dtype == np.bool_
    public = {n for n in dir(tabor) if not n.startswith("_")}
    assert public <= set(tabor.__all__) | {"jkr"}, public - set(tabor.__all__)


def test_result_tables_match_the_library():
    # the documented keys (tabor/_results.py, the TypedDicts of the stub) are the
    # keys the library returns
    from tabor import _results

    assert set(tabor.effective(youngs_modulus=1e9, poisson_ratio=0.3, radius=1e-6, density=1e3)) == set(_results.EFFECTIVE)
    assert set(tabor.jkr(**JKR, speed=1.0)) == set(_results.JKR)
    base = dict(contact_modulus=1e11, radius=1e-4, mass=1e-8, yield_stress=1e9, speed=1.0)
    assert set(tabor.plastic(model="dimensionless-fit", density=7800.0, **base)) == set(_results.PLASTIC)
    assert set(tabor.visco(model="standard-flat", modulus_ratio=2.0, viscous_parameter=0.5)) == set(_results.VISCO)
    assert set(tabor.penalty(law="flores", restitution=0.8)) == set(_results.PENALTY)
    for path in sorted(SCENES.glob("*.toml")):
        scene = tabor.Scene.from_path(path)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            s = scene.sweep("speed", [scene.speed or 0.1])
        assert set(s) == set(_results.SWEEP) | {"parameter", "values"}, (path.stem, set(s) ^ set(_results.SWEEP))


def test_sweep_rejects_a_parameter_the_scene_lacks():
    scene = tabor.Scene.from_path(SCENES / "alumina_on_steel.toml")
    with pytest.raises(tabor.InputError, match=r"tabor_parameter.*\[adhesion\]"):
        scene.sweep("tabor_parameter", [np.nan, -1.0, 0.0])
    with pytest.raises(tabor.InputError, match=r"yield_stress"):
        tabor.Scene.from_path(SCENES / "silica.toml").sweep("yield_stress", [1e9])


def test_ctrl_c_interrupts_a_batch():
    # a batch of ~30 s; SIGINT after 1 s must end it within a fraction of a second
    code = textwrap.dedent("""
        import sys, time, numpy as np, tabor
        lam = np.geomspace(0.7, 50, 3_000_000)
        print("start", flush=True)
        t = time.perf_counter()
        try:
            tabor.maugis_dugdale_loss(lam, tolerance=1e-13)
        except KeyboardInterrupt:
            print(f"interrupted {time.perf_counter() - t:.3f}", flush=True)
            sys.exit(0)
        print("finished", flush=True)
        sys.exit(1)
    """)
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True, cwd="/")
    assert p.stdout.readline().strip() == "start"
    time.sleep(1.0)
    sent = time.perf_counter()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    latency = time.perf_counter() - sent
    assert p.returncode == 0 and out.startswith("interrupted"), out
    assert latency < 1.0, f"the batch stopped {latency:.2f} s after SIGINT"


@pytest.mark.skipif(os.environ.get("TABOR_BIG") != "1", reason="opt-in (TABOR_BIG=1): 10^7 elements, ~2 GB")
def test_ten_million_elements():
    v = np.geomspace(0.05, 5, 10**7)
    out = tabor.jkr(**JKR, speed=v)
    assert out["restitution"].shape == (10**7,)
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    assert scene.restitution(v).shape == (10**7,)

"""Broadcasting, shapes, scalar in → float out, every error path, the GIL, and the
type stubs."""

import ast
import threading
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

import tabor
from conftest import SCENES


# --- scalars and shapes -------------------------------------------------------


def test_scalar_in_float_out():
    assert type(tabor.maugis_dugdale_loss(1.0)) is float
    assert type(tabor.maugis_dugdale_loss(np.float64(1.0))) is float
    assert type(tabor.maugis_dugdale_loss(np.array(1.0))) is float
    assert type(tabor.maugis_dugdale_loss(2, fast=True)) is float
    p, d = tabor.maugis_dugdale_curve(contact_radius=1.0, maugis_parameter=1.0)
    assert type(p) is float and type(d) is float
    assert type(tabor.tabor_parameter_from_maugis(1.0)) is float
    out = tabor.jkr(contact_modulus=1e9, radius=1e-6, work_of_adhesion=0.05, mass=1e-14, speed=1.0)
    assert type(out["restitution"]) is float and type(out["sticks"]) is bool and type(out["model"]) is str
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    assert type(scene.restitution(0.2)) is float


def test_array_in_array_out_with_shape():
    lam = np.array([[0.5, 1.0, 2.0], [3.0, 4.0, 5.0]])
    w = tabor.maugis_dugdale_loss(lam)
    assert isinstance(w, np.ndarray) and w.dtype == np.float64 and w.shape == (2, 3)
    np.testing.assert_array_equal(w.ravel(), tabor.maugis_dugdale_loss(lam.ravel()))
    # a list, a 1-element array, an empty array
    assert tabor.maugis_dugdale_loss([1.0, 2.0]).shape == (2,)
    assert tabor.maugis_dugdale_loss([1.0]).shape == (1,)
    assert tabor.maugis_dugdale_loss(np.empty((0, 3))).shape == (0, 3)


def test_broadcasting_over_every_argument():
    lam = np.array([[0.3], [1.0], [3.0]])  # (3, 1)
    a = np.linspace(0.2, 2.0, 4)  # (4,)
    p, d = tabor.maugis_dugdale_curve(contact_radius=a, maugis_parameter=lam)
    assert p.shape == d.shape == (3, 4)
    for i in range(3):
        pi, di = tabor.maugis_dugdale_curve(contact_radius=a, maugis_parameter=lam[i, 0])
        np.testing.assert_array_equal(p[i], pi)
        np.testing.assert_array_equal(d[i], di)
    tol = np.array([1e-6, 1e-12])
    assert tabor.maugis_dugdale_loss(lam, tolerance=tol).shape == (3, 2)
    out = tabor.jkr(contact_modulus=[[1e9], [2e9]], radius=1e-6, work_of_adhesion=[0.01, 0.02, 0.05],
                    mass=1e-14, speed=1.0)
    assert out["restitution"].shape == (2, 3) and out["sticks"].dtype == np.bool_
    assert out["energy_loss"][1, 2] == tabor.jkr(contact_modulus=2e9, radius=1e-6, work_of_adhesion=0.05,
                                                 mass=1e-14)["energy_loss"]
    e = tabor.effective(youngs_modulus=[1e9, 2e9], poisson_ratio=[[0.1], [0.2], [0.3]],
                        radius=1e-6, density=1000)
    assert e["effective_modulus"].shape == (3, 2)


def test_non_contiguous_and_integer_input():
    lam = np.linspace(0.5, 5, 20)[::3]
    np.testing.assert_array_equal(tabor.maugis_dugdale_loss(lam), tabor.maugis_dugdale_loss(lam.copy()))
    assert tabor.maugis_dugdale_loss(np.array([1, 2])).dtype == np.float64
    big = np.linspace(0.5, 5, 12).reshape(3, 4).T  # Fortran order
    np.testing.assert_array_equal(tabor.maugis_dugdale_loss(big), tabor.maugis_dugdale_loss(big.copy()))


def test_parallel_result_is_deterministic():
    lam = np.geomspace(0.1, 100, 5000)
    a = tabor.maugis_dugdale_loss(lam, fast=True)
    b = np.array([tabor.maugis_dugdale_loss(x, fast=True) for x in lam[:200]])
    np.testing.assert_array_equal(a[:200], b)


# --- errors: ValueError naming the parameter, its value and the index -----------


def raises(match, f, *args, **kwargs):
    with pytest.raises(ValueError, match=match) as info:
        f(*args, **kwargs)
    return str(info.value)


def test_loss_errors():
    raises(r"invalid tabor_parameter = -1", tabor.maugis_dugdale_loss, -1.0)
    raises(r"invalid tabor_parameter = NaN", tabor.maugis_dugdale_loss, float("nan"))
    raises(r"tabor_parameter = inf", tabor.maugis_dugdale_loss, float("inf"), fast=True)
    m = raises(r"invalid tabor_parameter = 0.*\(at index 2\)", tabor.maugis_dugdale_loss, [1, 2, 0, -1])
    assert "index 3" not in m  # the first bad element
    raises(r"\(at index \(1, 0\)\)", tabor.maugis_dugdale_loss, [[1, 2], [-3, 4]])
    raises(r"invalid tolerance = 1\b", tabor.maugis_dugdale_loss, 1.0, tolerance=1.0)
    raises(r"tolerance = 0.*\(at index 1\)", tabor.maugis_dugdale_loss, 1.0, tolerance=[1e-8, 0.0])
    raises(r"do not broadcast", tabor.maugis_dugdale_loss, [1, 2], tolerance=[1e-8, 1e-9, 1e-10])


def test_curve_and_conversion_errors():
    curve = tabor.maugis_dugdale_curve
    raises(r"invalid maugis_parameter = -1", curve, maugis_parameter=-1.0, contact_radius=1.0)
    raises(r"invalid contact_radius = -0.5", curve, maugis_parameter=1.0, contact_radius=-0.5)
    raises(r"contact_radius = NaN.*\(at index 1\)", curve, maugis_parameter=1.0, contact_radius=[1.0, np.nan])
    raises(r"invalid maugis_parameter = 0", tabor.tabor_parameter_from_maugis, 0.0)
    raises(r"invalid tabor_mu = -2", tabor.tabor_parameter_from_tabor_mu, -2.0)
    raises(r"invalid tabor_parameter = -1", tabor.maugis_parameter_from_tabor, -1.0)


def test_scene_errors(tmp_path):
    raises(r"sphere", tabor.Scene.from_toml, "[sphere]\nradius = -1\n")
    raises(r"line 1", tabor.Scene.from_toml, "this is not toml")
    with pytest.raises(FileNotFoundError, match=r"nope\.toml"):
        tabor.Scene.from_path(tmp_path / "nope.toml")
    raises(r"line 1|EOF", tabor.Scene.from_json, "{")
    text = (SCENES / "silica.toml").read_text().replace("speed = 0.1", "")
    no_speed = tabor.Scene.from_toml(text)
    raises(r"impact\.speed", no_speed.outcome)
    raises(r"speed", no_speed.trajectory)
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    raises(r"speed = -1", scene.outcome, -1.0)
    raises(r"speed = -1.*\(at index 2\)", scene.restitution, [0.1, 0.2, -1.0, -2.0])
    raises(r"speed = NaN.*\(at index \(0, 1\)\)", scene.restitution, [[0.1, np.nan]])
    raises(r"invalid parameter = \"color\"", scene.sweep, "color", [1.0])
    raises(r"\(at index 1\)", scene.sweep, "sphere_radius", [1e-6, -1.0])
    raises(r"tolerance", scene.trajectory, 0.1, tolerance=2.0)
    with pytest.raises(TypeError):
        tabor.Scene(None)


def test_model_errors():
    base = dict(contact_modulus=1e9, radius=1e-6, work_of_adhesion=0.05, mass=1e-14)
    raises(r"invalid contact_modulus = -1e9", tabor.jkr, **{**base, "contact_modulus": -1e9})
    raises(r"invalid speed = -1", tabor.jkr, **base, speed=-1.0)
    raises(r"invalid mass = 0.*\(at index 1\)", tabor.jkr, **{**base, "mass": [1e-14, 0.0]})
    raises(r"invalid separation = \"sideways\"", tabor.jkr, **base, separation="sideways")
    raises(r"invalid tolerance", tabor.jkr, **base, tolerance=0.9)
    pbase = dict(contact_modulus=1e11, radius=1e-4, mass=1e-8, yield_stress=1e9, speed=1.0)
    raises(r"missing poisson_ratio", tabor.plastic, model="jackson-green", **pbase)
    raises(r"missing density", tabor.plastic, model="dimensionless-fit", **pbase)
    raises(r"missing work_of_adhesion", tabor.plastic, model="superposition", **pbase)
    raises(r"invalid model = \"plasticine\"", tabor.plastic, model="plasticine", **pbase)
    raises(r"invalid plastic_model", tabor.plastic, model="superposition", work_of_adhesion=0.1,
           plastic_model="superposition", **pbase)
    raises(r"invalid yield_stress = -1", tabor.plastic, model="thornton", **{**pbase, "yield_stress": -1.0})
    raises(r"invalid model = \"jelly\"", tabor.visco, model="jelly")
    raises(r"missing damping_ratio", tabor.visco, model="kelvin-voigt-flat")
    raises(r"damping_ratio = -1", tabor.visco, model="kelvin-voigt-flat", damping_ratio=-1.0)
    raises(r"invalid restitution = 1.5", tabor.penalty, law="flores", restitution=1.5)
    raises(r"invalid law", tabor.penalty, law="springy", restitution=0.5)
    raises(r"invalid exponent", tabor.penalty, law="characteristic", restitution=0.5, exponent=2.0)
    raises(r"density or mass", tabor.effective, youngs_modulus=1e9, poisson_ratio=0.3, radius=1e-6,
           density=1000, mass=1.0)
    raises(r"give the sphere's density or mass", tabor.effective, youngs_modulus=1e9,
           poisson_ratio=0.3, radius=1e-6)
    raises(r"invalid poisson_ratio = 0.6", tabor.effective, youngs_modulus=1e9, poisson_ratio=0.6,
           radius=1e-6, mass=1.0)
    raises(r"rigid_target", tabor.effective, youngs_modulus=1e9, poisson_ratio=0.3, radius=1e-6,
           mass=1.0, rigid_target=True, target_youngs_modulus=1e9)


# --- the GIL is released during a batch --------------------------------------


def test_batch_releases_the_gil():
    # 0.1-0.4 s of work (40 000 points took 0.038 s on a quiet machine: too quick
    # to tell)
    lam = np.geomspace(0.7, 50, 200_000)
    done = threading.Event()

    def work():
        tabor.maugis_dugdale_loss(lam, tolerance=1e-13)
        done.set()

    t = threading.Thread(target=work)
    ticks = 0
    start = time.perf_counter()
    t.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0)
    t.join()
    elapsed = time.perf_counter() - start
    # with the GIL held by the batch this thread could not run at all while it works
    assert elapsed > 0.05, "the batch was too quick to tell"
    assert ticks > 100


# --- documentation -------------------------------------------------------------


def test_stubs_cover_the_public_api():
    stub = Path(tabor.__file__).with_name("__init__.pyi")
    assert stub.exists()
    assert (Path(tabor.__file__).with_name("py.typed")).exists()
    tree = ast.parse(stub.read_text())
    names = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    names |= {t.target.id for t in tree.body if isinstance(t, ast.AnnAssign)}
    names |= {a.asname or a.name for t in tree.body if isinstance(t, ast.ImportFrom) for a in t.names}
    assert set(tabor.__all__) <= names


def test_stub_is_generated_from_the_tables():
    from tabor import _stubgen

    stub = Path(tabor.__file__).with_name("__init__.pyi").read_text()
    assert stub == _stubgen.stub(), "regenerate: python -m tabor._stubgen > python/tabor/__init__.pyi"


def test_help_shows_flags_and_units():
    doc = tabor.jkr.__doc__
    for flag in ("--modulus", "--radius", "--work-of-adhesion", "--mass", "--speed", "--separation",
                 "--tolerance", "(Pa)", "(5.36)"):
        assert flag in doc
    assert "(5.43)" in tabor.maugis_dugdale_loss.__doc__
    for f in (tabor.effective, tabor.plastic, tabor.visco, tabor.penalty):
        assert "--" in f.__doc__


def test_version_is_single_sourced():
    from importlib.metadata import version

    from tabor import _tabor

    # the wheel's version (maturin, dynamic = ["version"] from python/Cargo.toml),
    # the module's and the Rust workspace's are one
    assert tabor.__version__ == version("tabor") == _tabor.LIBRARY_VERSION


def test_menus_and_defaults_come_from_the_library():
    # every choice keyword offers its Rust menu (ALL/as_str) and its default is the
    # library's; the tolerance defaults are tabor_numerics::tolerance's constants
    import inspect

    sig = inspect.signature(tabor.jkr).parameters
    assert sig["tolerance"].default == tabor.DEFAULT_TOLERANCE == 1e-12
    assert inspect.signature(tabor.visco).parameters["tolerance"].default == tabor.ACCURACY == 1e-10
    assert inspect.signature(tabor.Scene.trajectory).parameters["tolerance"].default == tabor.COSTLY_TOLERANCE
    assert inspect.signature(tabor.maugis_dugdale_loss).parameters["tolerance"].default == tabor.DEFAULT_TOLERANCE
    assert sig["separation"].default == "fixed-grip"
    specs = tabor._tabor.SPECS
    for function, spec in specs.items():
        for name, kind, default, choices, _help in spec:
            if kind != "choice":
                continue
            names = [c for c, _about in choices]
            assert default is None or default in names
            numbers = {n: 1.0 for n, k, d, *_ in spec if k == "number" and d is None}
            others = {n: ch[0][0] for n, k, d, ch, _ in spec if k == "choice" and n != name and d is None}
            # each name is accepted (the call may then fail on the other inputs, never
            # on the name)
            for c in names:
                try:
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        getattr(tabor, function)(**numbers, **others, **{name: c})
                except tabor.TaborError as e:
                    assert f"invalid {name} =" not in str(e), e
            with pytest.raises(tabor.InputError, match=f'invalid {name} = "nope": expected one of "{names[0]}"'):
                getattr(tabor, function)(**numbers, **others, **{name: "nope"})
    assert tabor.FORCE_DISPLACEMENT_MODELS == ("jkr", "dmt", "maugis-dugdale")
    with pytest.raises(tabor.InputError, match='expected "jkr", "dmt" or "maugis-dugdale"'):
        tabor.force_displacement("hertz", 1e-7, radius=1e-6, contact_modulus=1e9, work_of_adhesion=0.05)
    with pytest.raises(tabor.InputError, match='expected "raise" or "nan"'):
        tabor.jkr_normalized_loss() and tabor.maugis_dugdale_loss(1.0, errors="ignore")


def test_edges_a_user_touches():
    """Issue 33: thread counts have a ceiling checked before any thread is spawned,
    a missing scene file is a FileNotFoundError, an array where one number belongs
    is a TypeError naming the argument."""
    for threads in (2 ** 63, 100_000, 1025):
        t0 = time.perf_counter()
        with pytest.raises(tabor.InputError, match=r"threads .*<= 1024"):
            tabor.set_num_threads(threads)
        assert time.perf_counter() - t0 < 0.5
    with pytest.raises(tabor.InputError, match=r"<= 1024"):
        tabor.maugis_dugdale_loss([0.5, 2.0], threads=100_000)
    with pytest.raises(FileNotFoundError):
        tabor.Scene.from_path("missing.toml")
    scene = tabor.Scene.from_path(SCENES / "silica.toml")
    with pytest.raises(TypeError, match=r"speed must be one real number"):
        scene.outcome(np.array([0.1, 0.2]))
    assert scene.outcome(np.array([0.1]))["restitution"] == scene.outcome(0.1)["restitution"]


def test_arrays_beyond_the_machine_are_refused_before_any_copy():
    """Issue 33: a zero-stride view of 3e9 elements was copied in full (4 GB within
    seconds); it is refused at once, naming the argument and the ceiling."""
    view = np.broadcast_to(np.float32(0.5), (3 * 10**9,))
    t0 = time.perf_counter()
    with pytest.raises(tabor.InputError, match=r"tabor_parameter: 3000000000 elements"):
        tabor.maugis_dugdale_loss(view)
    with pytest.raises(tabor.InputError, match=r"at most"):
        tabor.maugis_dugdale_loss(np.broadcast_to(0.5, (10**5, 10**5)))
    assert time.perf_counter() - t0 < 1.0


def test_one_name_per_quantity():
    """issue 33: the contact modulus E* is ``contact_modulus`` everywhere (the
    Adhesion package's JKR name); the old names still work, with a
    DeprecationWarning, and give the same numbers."""
    import inspect
    import warnings

    for f in (tabor.jkr, tabor.plastic, tabor.force_displacement, tabor.maugis_parameter):
        names = set(inspect.signature(f).parameters)
        assert "contact_modulus" in names, f.__name__
        assert not names & {"modulus", "elastic_modulus"}, f.__name__
    base = dict(radius=1e-6, work_of_adhesion=0.05, mass=1e-14, speed=1.0)
    new = tabor.jkr(contact_modulus=1e9, **base)
    with pytest.warns(DeprecationWarning, match=r"modulus= is now contact_modulus="):
        old = tabor.jkr(modulus=1e9, **base)
    assert old["restitution"] == new["restitution"]
    with pytest.warns(DeprecationWarning, match=r"elastic_modulus= is now contact_modulus="):
        lam_old = tabor.maugis_parameter(radius=1e-6, elastic_modulus=30e9, work_of_adhesion=0.05,
                                         cohesive_stress=1e8)
    lam = tabor.maugis_parameter(1e-6, 30e9, 0.05, 1e8)
    assert lam_old == lam
    with pytest.warns(DeprecationWarning):
        f_old, _ = tabor.force_displacement("jkr", 1e-8, radius=1e-6, elastic_modulus=30e9, work_of_adhesion=0.05)
    f_new, _ = tabor.force_displacement("jkr", 1e-8, radius=1e-6, contact_modulus=30e9, work_of_adhesion=0.05)
    assert f_old == f_new
    with pytest.raises(TypeError, match="ambiguous"):
        tabor.jkr(modulus=1e9, contact_modulus=1e9, **base)
    with pytest.raises(TypeError, match="unexpected keyword argument 'modulu'"):
        tabor.force_displacement("jkr", 1e-8, radius=1e-6, modulu=30e9, work_of_adhesion=0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        tabor.jkr(contact_modulus=1e9, **base)

"""Issue 33: hostile Python calls as a test suite.

Every public function gets hostile scalars and arrays (NaN, ±inf, huge, subnormal,
negative, zero, wrong dtypes and types, zero-size, 0-d, zero-stride views,
non-contiguous slices, mismatched shapes) in one argument at a time; it must
answer with finite numbers where it reports a point valid, or raise one of the
package's exceptions (``tabor.TaborError`` subclasses, ``TypeError``,
``ValueError``) — never crash, hang, or return a non-finite number for a point it
calls valid.

The short variant runs with the suite (``TABOR_HOSTILE_CASES``, default 150);
the full campaign is opt-in, a few minutes on two cores::

    TABOR_HOSTILE_CASES=20000 cargo xtask test --only python -- -k hostile
"""

import math
import os
import random
import warnings

import numpy as np
import pytest

import tabor
from conftest import SCENES

CASES = int(os.environ.get("TABOR_HOSTILE_CASES", "150"))

SCALARS = [float("nan"), float("inf"), -float("inf"), 1e308, -1e308, 1e-320, 5e-324, 0.0, -0.0, -1.0,
           1e300, 1e-300, 2.0 ** 63, 0.5, 1.0, 3.0]


def hostile_values(rng):
    """A hostile value: a scalar, an array of hostile scalars in some layout, or a
    value of the wrong type."""
    kind = rng.randrange(9)
    if kind == 0:
        return rng.choice(SCALARS)
    if kind == 1:
        return np.array([rng.choice(SCALARS) for _ in range(rng.randrange(1, 6))])
    if kind == 2:
        # a zero-stride view of one value
        return np.lib.stride_tricks.as_strided(np.array([rng.choice(SCALARS)]), shape=(4,), strides=(0,))
    if kind == 3:
        # a non-contiguous slice
        return np.linspace(0.1, 2.0, 12)[::3]
    if kind == 4:
        return np.empty(0)
    if kind == 5:
        return np.array(rng.choice(SCALARS))
    if kind == 6:
        return rng.choice(["1e-6", None, [1.0, "x"], {"a": 1}, object(), b"1", 1 + 2j, True])
    if kind == 7:
        return np.array([[0.1, 0.2], [0.3, 0.4]]) if rng.random() < 0.5 else np.array([1, 2, 3], dtype=np.int8)
    return np.array([0.1, float("nan"), 0.3], dtype=np.float32)


def calls(rng):
    """(name, function, base keyword arguments) of the public API."""
    scene = tabor.Scene.from_path(SCENES / rng.choice(["silica.toml", "silica_oblique.toml",
                                                       "silica_maugis_plastic.toml", "silica_damped.toml"]))
    return [
        ("maugis_dugdale_loss", lambda **k: tabor.maugis_dugdale_loss(**k), {"tabor_parameter": 0.5}),
        ("maugis_dugdale_curve", lambda **k: tabor.maugis_dugdale_curve(**k),
         {"maugis_parameter": 1.0, "contact_radius": 1.0}),
        ("tabor_parameter_from_maugis", lambda **k: tabor.tabor_parameter_from_maugis(**k), {"maugis_parameter": 1.0}),
        ("maugis_parameter", lambda **k: tabor.maugis_parameter(**k),
         {"radius": 1e-6, "contact_modulus": 30e9, "work_of_adhesion": 0.05, "cohesive_stress": 1e8}),
        ("force_displacement", lambda **k: tabor.force_displacement("jkr", **k),
         {"contact_radius": 1e-8, "radius": 1e-6, "contact_modulus": 30e9, "work_of_adhesion": 0.05}),
        ("effective", lambda **k: tabor.effective(**k),
         {"youngs_modulus": 54e9, "poisson_ratio": 0.17, "radius": 1e-6, "density": 2650.0}),
        ("jkr", lambda **k: tabor.jkr(**k),
         {"contact_modulus": 3e10, "radius": 1e-6, "work_of_adhesion": 0.05, "mass": 1e-14, "speed": 0.1}),
        ("plastic", lambda **k: tabor.plastic(**k),
         {"model": "thornton", "contact_modulus": 1e11, "radius": 1e-4, "mass": 1e-8, "yield_stress": 1e9,
          "speed": 1.0}),
        ("visco", lambda **k: tabor.visco(**k), {"model": "kelvin-voigt-flat", "damping_ratio": 0.3}),
        ("Scene.outcome", lambda **k: scene.outcome(**{n: v for n, v in k.items() if n != "errors"}), {"speed": 0.2}),
        ("Scene.restitution", lambda **k: scene.restitution(**k), {"speeds": 0.2}),
    ]


ALLOWED = (tabor.TaborError, TypeError, ValueError, OverflowError)


def finite_where_valid(result):
    """Every float of a result is finite, except at points marked invalid."""
    if isinstance(result, dict):
        valid = result.get("valid")
        for key, value in result.items():
            if isinstance(value, np.ndarray) and value.dtype.kind == "f":
                ok = np.isfinite(value)
                if valid is not None:
                    ok |= ~np.asarray(valid, dtype=bool)
                # columns that are NaN by their documented meaning (not applicable)
                if not ok.all() and key not in NAN_MEANS_ABSENT:
                    return f"{key}: {value}"
            elif isinstance(value, float) and not math.isfinite(value) and key not in NAN_MEANS_ABSENT:
                if valid is None or bool(np.all(valid)):
                    return f"{key}: {value}"
        return None
    values = result if isinstance(result, tuple) else (result,)
    for v in values:
        a = np.asarray(v)
        if a.dtype.kind == "f" and not np.isfinite(a).all():
            return f"{a}"
    return None


# NaN by documentation: the quantity does not apply to this point
NAN_MEANS_ABSENT = {"sticking_velocity", "tabor_parameter", "elastic_sticking_velocity", "adhesion_parameter",
                    "contact_time", "max_overlap", "first_order_restitution", "yield_velocity",
                    "equivalent_kelvin_voigt_damping_ratio", "equivalent_kelvin_voigt_restitution",
                    "tangential_restitution", "rebound_angle", "max_contact_radius", "restitution",
                    "impact_speed", "energy_loss"}


def campaign(cases, seed):
    rng = random.Random(seed)
    answered = refused = 0
    for _ in range(cases):
        name, function, base = rng.choice(calls(rng))
        key = rng.choice(sorted(base))
        kwargs = dict(base)
        kwargs[key] = hostile_values(rng)
        if rng.random() < 0.3:
            kwargs["errors"] = "nan"
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                result = function(**kwargs)
            except ALLOWED:
                refused += 1
                continue
        bad = finite_where_valid(result)
        # errors="nan": an invalid point is NaN in a tuple result, and said so
        if bad is not None and not isinstance(result, dict) and kwargs.get("errors") == "nan":
            if any(issubclass(w.category, tabor.InvalidPointsWarning) for w in caught):
                bad = None
        assert bad is None, f"{name}({key}={kwargs[key]!r}): a non-finite answer at a valid point: {bad}"
        answered += 1
    return answered, refused


def test_hostile_calls_are_answered_or_refused():
    answered, refused = campaign(CASES, seed=int(os.environ.get("TABOR_HOSTILE_SEED", "33")))
    print(f"hostile Python calls: {answered} answered, {refused} refused with a tabor/Type/Value error")
    assert answered > 0 and refused > 0


def test_a_huge_zero_stride_view_is_refused_before_copying():
    # issue 33: 3e9 elements of one value used to be copied in full (4 GB)
    view = np.lib.stride_tricks.as_strided(np.array([0.5]), shape=(3_000_000_000,), strides=(0,))
    with pytest.raises(ALLOWED):
        tabor.maugis_dugdale_loss(view)


def test_thread_counts_beyond_the_ceiling_are_refused():
    with pytest.raises(ALLOWED):
        tabor.set_num_threads(2 ** 63)
    with pytest.raises(ALLOWED):
        tabor.jkr(contact_modulus=3e10, radius=1e-6, work_of_adhesion=0.05, mass=1e-14, threads=100000)

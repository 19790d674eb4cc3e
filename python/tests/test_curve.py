"""maugis_dugdale_curve against ContactEngineering's Adhesion package (the
reference users switch from) and against the closed forms at A = 0 and A → ∞."""

import importlib.util
import math
import os
import warnings

import numpy as np
import pytest

import tabor


def _adhesion_md():
    """Adhesion.ReferenceSolutions.MaugisDugdale, loaded by file path: the package's
    __init__ imports heavy dependencies that are not installed (--no-deps, see
    requirements-nodeps.txt); this module needs only numpy and scipy."""
    spec = importlib.util.find_spec("Adhesion")
    if spec is None or not spec.submodule_search_locations:
        pytest.fail("the Adhesion package is not installed (pip install --no-deps Adhesion==0.93)")
    path = os.path.join(spec.submodule_search_locations[0], "ReferenceSolutions", "MaugisDugdale.py")
    mspec = importlib.util.spec_from_file_location("adhesion_maugis_dugdale", path)
    module = importlib.util.module_from_spec(mspec)
    mspec.loader.exec_module(module)
    return module


MD = _adhesion_md()


def adhesion_curve(lam, radii):
    """Adhesion's (load, displacement) per point; NaN where its brentq fails."""
    load = np.full(radii.shape, np.nan)
    disp = np.full(radii.shape, np.nan)
    for i, a in enumerate(radii):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                p, d = MD._load_and_displacement(float(a), lam)
        except (ValueError, RuntimeError):
            continue
        load[i], disp[i] = p, d
    return load, disp


@pytest.mark.parametrize("lam", [0.3, 1.0, 3.0])
def test_agrees_with_adhesion_to_1e8(lam):
    radii = np.concatenate([np.geomspace(1e-3, 0.1, 20), np.linspace(0.1, 4.0, 200)])
    ref_load, ref_disp = adhesion_curve(lam, radii)
    ok = np.isfinite(ref_load) & np.isfinite(ref_disp)
    assert ok.sum() >= 0.9 * len(radii), "Adhesion's solver converged at too few radii"
    load, disp = tabor.maugis_dugdale_curve(contact_radius=radii, maugis_parameter=lam)
    assert load.shape == disp.shape == radii.shape
    np.testing.assert_allclose(load[ok], ref_load[ok], rtol=1e-8, atol=0)
    # the penetration crosses zero: 1e-8 relative, or 1e-12 absolute next to the
    # crossing (the terms that cancel there are O(1) in Maugis' units)
    np.testing.assert_allclose(disp[ok], ref_disp[ok], rtol=1e-8, atol=1e-12)


@pytest.mark.parametrize("lam", [0.3, 1.0, 3.0])
def test_zero_contact_radius_is_the_junction_with_the_no_contact_branch(lam):
    # at A = 0 the branch meets the no-contact branch at b̂ = K b̂_c (5.46), with
    # F̂ = −2Λb̂², d̂ = (3/2)b̂² − (32Λ/π²)b̂ − 1/Λ (spec maugis-dugdale.md)
    big = tabor.tabor_parameter_from_maugis(lam)
    k = 1 - math.pi / 2 + math.sqrt((1 - math.pi / 2) ** 2 + 3 * math.pi**4 / (512 * big**3))
    b = k * 32 * big / (3 * math.pi**2)
    f_hat = -2 * big * b * b
    d_hat = 1.5 * b * b - 32 * big / math.pi**2 * b - 1 / big
    load, disp = tabor.maugis_dugdale_curve(contact_radius=0.0, maugis_parameter=lam)
    assert load == pytest.approx(1.5 * f_hat, rel=1e-13)
    assert disp == pytest.approx(1.5 ** (2 / 3) / 3 * d_hat, rel=1e-13)


def test_hertz_limit_for_large_contact_radius():
    # far on the compressive side the adhesive terms vanish relative to Hertz
    # P̄ = A³, Δ̄ = A² (Maugis' units; they fall like A^(-3/2))
    a = np.array([1e3, 1e4])
    load, disp = tabor.maugis_dugdale_curve(contact_radius=a, maugis_parameter=1.0)
    np.testing.assert_allclose(load, a**3, rtol=1e-4)
    np.testing.assert_allclose(disp, a**2, rtol=1e-4)


def test_jkr_limit_for_large_maugis_parameter():
    # λ → ∞: JKR, P̄ = A³ − √(6A³), Δ̄ = A² − (2/3)√(6A) (Maugis 1992, eq. (6.5))
    a = np.array([0.5, 1.0, 2.0])
    load, disp = tabor.maugis_dugdale_curve(contact_radius=a, maugis_parameter=1e6)
    np.testing.assert_allclose(load, a**3 - np.sqrt(6 * a**3), rtol=1e-4)
    np.testing.assert_allclose(disp, a**2 - 2 / 3 * np.sqrt(6 * a), rtol=1e-4)


# --- SI force-displacement curves against Adhesion ------------------------------


def _adhesion_module(name):
    spec = importlib.util.find_spec("Adhesion")
    path = os.path.join(spec.submodule_search_locations[0], "ReferenceSolutions", f"{name}.py")
    mspec = importlib.util.spec_from_file_location(f"adhesion_{name}", path)
    module = importlib.util.module_from_spec(mspec)
    mspec.loader.exec_module(module)
    return module


# silica-like: R = 1 µm, E* = 30 GPa, Δγ = 0.05 J/m², σ0 from λ
R, E, W = 1e-6, 30e9, 0.05


def test_jkr_si_curve_against_adhesion():
    jkr = _adhesion_module("JKR")
    a = np.geomspace(1e-10, 1e-6, 60)
    force, pen = tabor.force_displacement("jkr", a, radius=R, contact_modulus=E, work_of_adhesion=W)
    ref_f = jkr.force(contact_radius=a, radius=R, contact_modulus=E, work_of_adhesion=W)
    ref_d = jkr.penetration(contact_radius=a, radius=R, contact_modulus=E, work_of_adhesion=W)
    np.testing.assert_allclose(force, ref_f, rtol=1e-8, atol=0)
    # the penetration crosses zero: 1e-8 of its scale there
    np.testing.assert_allclose(pen, ref_d, rtol=1e-8, atol=1e-8 * np.abs(ref_d).max())


@pytest.mark.parametrize("lam", [0.05, 0.3, 1.0, 3.0])
def test_maugis_dugdale_si_curve_against_adhesion(lam):
    k = 4 * E / 3
    sigma0 = lam / 2 * (math.pi * W * k**2 / R) ** (1 / 3)
    assert tabor.maugis_parameter(R, E, W, sigma0) == pytest.approx(MD.maugis_parameter(R, E, W, sigma0), rel=1e-14)
    assert tabor.maugis_parameter(R, E, W, sigma0) == pytest.approx(lam, rel=1e-14)
    a_unit = (math.pi * W * R**2 / k) ** (1 / 3)
    a = np.linspace(0.05, 3.0, 60) * a_unit
    ref = np.array([_quiet(MD.load_and_displacement, x, R, E, W, sigma0) for x in a])
    ok = np.isfinite(ref).all(axis=1)
    assert ok.sum() >= 50
    force, pen = tabor.force_displacement("maugis-dugdale", a, radius=R, contact_modulus=E, work_of_adhesion=W,
                                          cohesive_stress=sigma0)
    np.testing.assert_allclose(force[ok], ref[ok, 0], rtol=1e-8, atol=0)
    scale = np.abs(ref[ok, 1]).max()
    np.testing.assert_allclose(pen[ok], ref[ok, 1], rtol=1e-8, atol=1e-10 * scale)


def _quiet(f, *args):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return f(*args)
    except (ValueError, RuntimeError):
        return (np.nan, np.nan)


def test_dmt_si_curve_closed_form_and_the_maugis_dugdale_limit():
    a = np.geomspace(1e-9, 1e-6, 20)
    force, pen = tabor.force_displacement("dmt", a, radius=R, contact_modulus=E, work_of_adhesion=W)
    np.testing.assert_allclose(force, 4 * E * a**3 / (3 * R) - 2 * math.pi * W * R, rtol=1e-14)
    np.testing.assert_allclose(pen, a**2 / R, rtol=1e-14)
    # Maugis-Dugdale tends to DMT as lambda -> 0: the load like lambda, the
    # penetration like lambda^(1/2) (seen against Adhesion down to 1e-10)
    k = 4 * E / 3
    errors = []
    for lam in (1e-4, 1e-6, 1e-8):
        sigma0 = lam / 2 * (math.pi * W * k**2 / R) ** (1 / 3)
        f, d = tabor.force_displacement("maugis-dugdale", a, radius=R, contact_modulus=E, work_of_adhesion=W,
                                        cohesive_stress=sigma0)
        errors.append((np.max(np.abs(f - force)) / (2 * math.pi * W * R), np.max(np.abs(d - pen)) / np.max(pen)))
    for (f1, d1), (f2, d2) in zip(errors, errors[1:]):
        assert f2 < f1 / 50 and d2 < d1 / 5


def test_curve_at_extreme_maugis_parameters():
    # the DMT limit in Maugis' units: P = A^3 - 2, Delta = A^2
    a = np.array([0.1, 1.0, 3.0])
    load, disp = tabor.maugis_dugdale_curve(contact_radius=a, maugis_parameter=tabor.MIN_MAUGIS_PARAMETER)
    np.testing.assert_allclose(load, a**3 - 2, rtol=1e-8)
    # the penetration approaches DMT like lambda^(1/2) (1.5e-5 here)
    np.testing.assert_allclose(disp, a**2, rtol=0, atol=20 * tabor.MIN_MAUGIS_PARAMETER**0.5)
    for lam in (1e-11, 1e-20, 1e-30, 1e-40):
        with pytest.raises(tabor.ModelValidityError, match="DMT"):
            tabor.maugis_dugdale_curve(contact_radius=1.0, maugis_parameter=lam)
    # errors="nan" instead of a wrong number
    with pytest.warns(tabor.InvalidPointsWarning):
        load, _ = tabor.maugis_dugdale_curve(contact_radius=1.0, maugis_parameter=[1e-30, 1.0], errors="nan")
    assert np.isnan(load[0]) and np.isfinite(load[1])
    # from the smallest accepted lambda to 1, tabor agrees with Adhesion to 1e-8
    for lam in (1e-10, 1e-8, 1e-6, 1e-3):
        ref_load, ref_disp = adhesion_curve(lam, a)
        load, disp = tabor.maugis_dugdale_curve(contact_radius=a, maugis_parameter=lam)
        np.testing.assert_allclose(load, ref_load, rtol=1e-8)
        np.testing.assert_allclose(disp, ref_disp, rtol=1e-8, atol=1e-12)
    # the JKR side: no overflow at a huge lambda
    load, disp = tabor.maugis_dugdale_curve(contact_radius=1.0, maugis_parameter=1e12)
    assert load == pytest.approx(1 - math.sqrt(6), rel=1e-4)

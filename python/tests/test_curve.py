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

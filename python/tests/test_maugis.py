"""maugis_dugdale_loss and the conversions against independent references: the
mpmath table of the Rust tests, closed forms, and a SciPy re-derivation."""

import math

import numpy as np
import pytest

import tabor
from md_scipy import loss as scipy_loss

# W(Λ)/W_JKR from crates/tabor-maugis/tests/reference/md_reference.py (mpmath at
# 30-40 digits, the contact branch parametrized by â), the table of
# crates/tabor-maugis/tests/maugis.rs.
MPMATH = [
    (0.01, 5.9594875681592662e-10),
    (0.3, 0.014481554790627017),
    (0.45, 0.10996917371535383),
    (0.5, 0.17400415268356964),
    (0.55, 0.23654516983408740),
    (0.6, 0.29569692666850126),
    (0.64, 0.34127887768313726),
    (0.65, 0.35244903739442271),
    (0.7, 0.4021869685735214),
    (1.0, 0.58372826555075422),
    (2.0, 0.78590678131645888),
    (4.0, 0.88980136388456987),
    (10.0, 0.95498725162139189),
    (100.0, 0.99543880705685374),
    (1e3, 0.99954327242668467),
    (1e4, 0.99995432115391564),
]

# (5.36) over F_n d_n: (1 + 864^(1/3))/10 / (3·3^(1/3)/8)
W_JKR = 0.1 * (1 + 864 ** (1 / 3)) / (3 * 3 ** (1 / 3) / 8)


def test_jkr_loss_closed_form():
    assert tabor.jkr_normalized_loss() == pytest.approx(W_JKR, rel=1e-15)


@pytest.mark.parametrize("lam, ratio", MPMATH)
def test_direct_loss_matches_mpmath_to_1e10(lam, ratio):
    w = tabor.maugis_dugdale_loss(lam)
    assert isinstance(w, float)
    assert w == pytest.approx(ratio * W_JKR, rel=1e-10, abs=0)


def test_direct_loss_array_matches_mpmath():
    lam = np.array([x for x, _ in MPMATH])
    ref = np.array([r for _, r in MPMATH]) * W_JKR
    w = tabor.maugis_dugdale_loss(lam, tolerance=1e-12)
    np.testing.assert_allclose(w, ref, rtol=1e-10, atol=0)


def test_fast_tier_matches_mpmath():
    lam = np.array([x for x, _ in MPMATH])
    ref = np.array([r for _, r in MPMATH]) * W_JKR
    w = tabor.maugis_dugdale_loss(lam, fast=True)
    # the fast tier's bound (1e-10 against the direct value) plus the direct
    # value's own 1e-12
    np.testing.assert_allclose(w, ref, rtol=tabor.FAST_TIER_RELATIVE_ERROR + 1e-12, atol=0)


@pytest.mark.parametrize("lam", [1e-3, 0.01, 0.2, 0.4, 0.449])
def test_case_1_closed_form(lam):
    # (5.44): 17·2¹⁹Λ⁵/(3⁴π⁸)
    ref = 17 * 2**19 * lam**5 / (3**4 * math.pi**8)
    assert tabor.maugis_dugdale_loss(lam) == pytest.approx(ref, rel=1e-14)
    assert tabor.maugis_dugdale_loss(lam, fast=True) == pytest.approx(ref, rel=1e-14)


@pytest.mark.parametrize("lam", [0.7, 1.3, 3.0, 7.5])
def test_against_scipy_rederivation(lam):
    # a second derivation (contact branch in â, brentq + quad): agrees to ~1e-14
    # where mpmath was checked; 1e-10 leaves room for quad
    assert tabor.maugis_dugdale_loss(lam) == pytest.approx(scipy_loss(lam), rel=1e-10)


def test_jkr_limit_and_monotone():
    lam = np.geomspace(0.01, 1e8, 400)
    w = tabor.maugis_dugdale_loss(lam, fast=True)
    # increasing (where the steps are far above the tier's 1e-10 error) and below JKR
    assert np.all(np.diff(w[lam < 1e5]) > 0)
    assert np.all(w < W_JKR)
    # 1 − W/W_JKR ≈ 0.4568/Λ (the asymptote of the Rust tests), within 1 %
    big = lam > 1e4
    np.testing.assert_allclose((1 - w[big] / W_JKR) * lam[big], 0.4568, rtol=1e-2)


def test_tolerance_broadcasts_and_loosens():
    w = tabor.maugis_dugdale_loss(2.0, tolerance=np.array([1e-4, 1e-8, 1e-12]))
    assert w.shape == (3,)
    np.testing.assert_allclose(w, 0.78590678131645888 * W_JKR, rtol=1e-4)


def test_conversions():
    k = math.pi * (9 / 4) ** (1 / 3) / 6
    assert tabor.LAMBDA_PER_MAUGIS_PARAMETER == pytest.approx(k, rel=1e-15)
    lam_m = np.array([0.1, 1.0, 3.0])
    np.testing.assert_allclose(tabor.tabor_parameter_from_maugis(lam_m), k * lam_m, rtol=1e-15)
    np.testing.assert_allclose(tabor.maugis_parameter_from_tabor(k * lam_m), lam_m, rtol=1e-15)
    mu = np.array([0.5, 5.0])
    np.testing.assert_allclose(tabor.tabor_parameter_from_tabor_mu(mu), k * 1.157 * mu, rtol=1e-15)
    # seed 000 after (5.46): Λ = 4 is Tabor's μ ≈ 5
    assert tabor.tabor_parameter_from_tabor_mu(5.0) == pytest.approx(4.0, rel=0.01)

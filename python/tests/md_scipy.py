"""An independent SciPy implementation of the Maugis-Dugdale impact loss W(Λ).

Written from the equations of seed 000 section 5.3.2 ((5.40), (5.43)) and the
normalized Maugis-Dugdale contact of ``shared/spec/maugis-dugdale.md``, with the
contact branch parametrized by the contact radius â (tabor parametrizes it by
θ = arccos(â/b̂)): for each â the cohesive radius b̂ is found by ``brentq`` on the
gap condition, dd̂/dâ by implicit differentiation, the jump-in state (d̂ = −1/Λ) and
the snap-off state (dd̂/dâ = 0) by ``brentq``, and the loss

    W(Λ) = |∫ F̂ dd̂| = |∫_{â_c}^{â_in} F̂(â) d̂'(â) dâ|     (5.43)

by ``quad``. Case 3 only (Λ > Λ2 ≈ 0.6435: the impact starts and ends in contact).
Used by the tests as a second, independent path and by ``bench.py`` as the SciPy
baseline ("brentq + quad").
"""

import math

from scipy.integrate import quad
from scipy.optimize import brentq

LAMBDA_2 = (3 * math.pi**4 / (512 * (math.pi - 1))) ** (1 / 3)


def _gap(a, b, lam):
    s = math.sqrt(max(b * b - a * a, 0.0))
    th = math.acos(min(a / b, 1.0))
    return (3 * lam / math.pi) * (a * s + (b * b - 2 * a * a) * th) + (
        32 * lam * lam / math.pi**2
    ) * (s * th - b + a) - 1.0


def cohesive_radius(a, lam):
    """b̂(â): the root of the gap condition in b̂ > â (it grows monotonically)."""
    step = max(a, 1.0)
    hi = a + step
    while _gap(a, hi, lam) <= 0.0:
        step *= 2.0
        hi = a + step
    return brentq(lambda b: _gap(a, b, lam), a, hi, xtol=1e-300, rtol=4 * 2.23e-16, maxiter=500)


def state(a, lam):
    """(d̂, F̂, dd̂/dâ) on the contact branch at contact radius â."""
    b = cohesive_radius(a, lam)
    s = math.sqrt(b * b - a * a)
    th = math.acos(a / b)
    c1, c2 = 3 * lam / math.pi, 32 * lam * lam / math.pi**2
    # partial derivatives of the gap condition
    g_a = c1 * (-4 * a * th) + c2 * (-a * th / s)
    g_b = c1 * (2 * b * th + 2 * a * s / b) + c2 * (b * th / s + a / b - 1)
    db = -g_a / g_b
    depth = 3 * a * a - 16 * lam / math.pi * s
    force = a**3 - 4 * lam / math.pi * (a * s + b * b * th)
    ds = (b * db - a) / s
    slope = 6 * a - 16 * lam / math.pi * ds
    return depth, force, slope


def loss(lam):
    """W(Λ) in units of F_n d_n, case 3 (Λ > Λ2)."""
    if not lam > LAMBDA_2:
        raise ValueError("the SciPy reference covers case 3 only (Lambda > 0.6435)")
    # snap-off: the minimum of d̂(â)
    lo, hi = 1e-6, 1.0
    while state(hi, lam)[2] <= 0:
        hi *= 2
    a_c = brentq(lambda a: state(a, lam)[2], lo, hi, xtol=1e-15, rtol=1e-15)
    # jump-in: d̂ = −1/Λ on the rising part of the branch
    hi = 2 * a_c + 1.0
    while state(hi, lam)[0] <= -1.0 / lam:
        hi *= 2
    a_in = brentq(lambda a: state(a, lam)[0] + 1.0 / lam, a_c, hi, xtol=1e-15, rtol=1e-15)

    def integrand(a):
        _, f, slope = state(a, lam)
        return f * slope

    value, _ = quad(integrand, a_c, a_in, epsabs=0.0, epsrel=1e-12, limit=200)
    return abs(value)

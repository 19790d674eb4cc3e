//! Special functions: Gamma and Beta (from `statrs`), the incomplete beta function,
//! and the Gamma-function ratios of the power-law contact solutions.

use crate::error::require_finite;
use crate::{NumericsError, Result};

/// The Gamma function Γ(x) for x > 0 (Lanczos approximation of `statrs`).
pub fn gamma(x: f64) -> Result<f64> {
    positive("x", x)?;
    finite_result(x, statrs::function::gamma::gamma(x))
}

/// ln Γ(x) for x > 0.
pub fn ln_gamma(x: f64) -> Result<f64> {
    positive("x", x)?;
    finite_result(x, statrs::function::gamma::ln_gamma(x))
}

/// The complete Beta function B(a, b) = Γ(a)Γ(b)/Γ(a+b) for a, b > 0.
pub fn beta(a: f64, b: f64) -> Result<f64> {
    positive("a", a)?;
    positive("b", b)?;
    finite_result(a, statrs::function::beta::beta(a, b))
}

/// The regularized incomplete beta function I_x(a, b) for 0 ≤ x ≤ 1, a, b > 0.
pub fn regularized_incomplete_beta(x: f64, a: f64, b: f64) -> Result<f64> {
    unit_interval(x)?;
    positive("a", a)?;
    positive("b", b)?;
    statrs::function::beta::checked_beta_reg(a, b, x)
        .map_err(|_| NumericsError::InvalidArgument {
            name: "x",
            value: x,
            requirement: "the incomplete beta function is defined for 0 <= x <= 1, a, b > 0",
        })
        .and_then(|v| finite_result(x, v))
}

/// The (non-regularized) incomplete beta function
/// `B(x; a, b) = ∫₀ˣ t^(a−1) (1−t)^(b−1) dt`, as used by seed 000 eqs. (5.11),
/// (5.17), (5.22) and (5.29) for the inverse trajectory t(d) of an elastic impact.
///
/// Seed 000, eq. (9.42) (appendix, not among the seeds) defines it; (5.19) gives the
/// identity `B(z²; 1/2, 1/2) = 2 arcsin z` used in the tests.
///
/// Accuracy (measured against mpmath in the tests): a few ulp for the trajectory
/// parameters `a = n/(2n+1) < 1/2`, `b = 1/2`; about 1e-13 relative when a parameter
/// is of order ten or more (statrs' prefactor through ln Γ).
pub fn incomplete_beta(x: f64, a: f64, b: f64) -> Result<f64> {
    let reg = regularized_incomplete_beta(x, a, b)?;
    Ok(reg * beta(a, b)?)
}

/// The profile factor of a power-law indenter `f(r) = A rⁿ`,
/// `β(n) = √π Γ(n/2 + 1) / Γ(n/2 + 1/2)`, so that `d = β(n) A aⁿ`.
///
/// Seed 000 eqs. (5.15)-(5.16), (5.39); `β(1) = π/2`, `β(2) = 2`.
pub fn power_law_beta(n: f64) -> Result<f64> {
    positive("n", n)?;
    gamma_ratio(0.5 * n + 1.0, 0.5 * n + 0.5).map(|r| std::f64::consts::PI.sqrt() * r)
}

/// The profile factor of a power-law indenter on a power-law graded half-space
/// (modulus ∝ depth^k), `β(n, k) = Γ((1+k)/2) Γ(n/2 + 1) / Γ((n+k+1)/2)`.
///
/// Seed 000 eq. (5.28); reduces to [`power_law_beta`] at k = 0 and
/// `β(2, k) = 2/(1+k)`. Requires n > 0 and −1 < k < 1.
pub fn graded_power_law_beta(n: f64, k: f64) -> Result<f64> {
    positive("n", n)?;
    require_finite("k", k)?;
    if !(k > -1.0 && k < 1.0) {
        return Err(NumericsError::InvalidArgument {
            name: "k",
            value: k,
            requirement: "the gradation exponent must satisfy -1 < k < 1",
        });
    }
    let g = gamma(0.5 * (1.0 + k))?;
    Ok(g * gamma_ratio(0.5 * n + 1.0, 0.5 * (n + k + 1.0))?)
}

/// Γ(x)/Γ(y) for x, y > 0, through ln Γ when Γ itself would overflow.
pub fn gamma_ratio(x: f64, y: f64) -> Result<f64> {
    positive("x", x)?;
    positive("y", y)?;
    if x < 150.0 && y < 150.0 {
        let gx = statrs::function::gamma::gamma(x);
        let gy = statrs::function::gamma::gamma(y);
        finite_result(x, gx / gy)
    } else {
        let lx = statrs::function::gamma::ln_gamma(x);
        let ly = statrs::function::gamma::ln_gamma(y);
        finite_result(x, (lx - ly).exp())
    }
}

fn positive(name: &'static str, v: f64) -> Result<f64> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(NumericsError::InvalidArgument {
            name,
            value: v,
            requirement: "must be finite and > 0",
        })
    }
}

fn unit_interval(x: f64) -> Result<f64> {
    if (0.0..=1.0).contains(&x) {
        Ok(x)
    } else {
        Err(NumericsError::InvalidArgument {
            name: "x",
            value: x,
            requirement: "must lie in [0, 1]",
        })
    }
}

fn finite_result(at: f64, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(NumericsError::NonFinite { at, value })
    }
}

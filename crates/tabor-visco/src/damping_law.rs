//! Generalized damping laws for a sphere, seed 000 eq. (5.72):
//! `F = (16G/3) √(R d³) + λ d^β ḋ`, in the scaling (5.74) of
//! [`crate::kelvin_voigt_sphere`]: `ẍ = −(5/4) x^(3/2) − γ x^β ẋ` with the scaled
//! damping `γ = λ d0^(β+1)/(m v0)`. The impact ends where the force vanishes (or at
//! x = 0 if that comes first, possible for β = 3/2). ε depends on (β, γ) only.
//!
//! Named laws: Lee-Herrmann β = 0, Tsuji β = 1/4 (with (5.73) γ = α √(15/64), independent
//! of speed and system), Hunt-Crossley β = 3/2; β = 1/2 with γ = 8 (15/64)^(3/5) δ
//! is Kuwabara-Kono (5.66).
//!
//! # Heavy damping (γ → ∞)
//!
//! With `p = ẋ + γ x^{β+1}/(β + 1)`, `ṗ = −(5/4) x^{3/2}`: the compression is a
//! relaxation of ẋ at the rate `γ x^β` that stops the indenter at
//! `x∞ = ((β + 1)/γ)^{1/(β+1)}` (p ≈ 1). Then the velocity relaxes, at the same
//! rate, to the creep velocity `v_c(x) = −(5/4) x^{3/2−β}/γ` (the spring balancing
//! the dashpot), and on that slow manifold `F = −ẍ = −v_c' v_c < 0` for β < 3/2: the
//! force changes sign during the relaxation, when `ẋ = v_c`, so the rebound speed
//! is the creep speed,
//!
//! ```text
//! ε = ε∞ [1 − 2 (3/2 − β)/(β + 1) · ε∞ ln(1/ε∞) + O(ε∞)],   ε∞ = (5/4) x∞^{3/2−β}/γ,
//! ```
//!
//! ([`overdamped_restitution`]; β = 0: ε∞ = (5/4) γ^{−5/2}, ≈ 4e-8 at γ = 1e3). The
//! correction has two equal parts, each `(3/2 − β)/(β + 1) · ε ln(1/ε)`: the spring
//! impulse `(5/4) x^{3/2} t*` before the turning point lowers x*, and the creep
//! during the ≈ ln(1/ε) e-folds of the force relaxation lowers x further (ε ∝
//! x^{3/2−β}). For β = 3/2 the creep velocity −5/(4γ) is constant, the force
//! `x^{3/2} (5/4 + γ ẋ)` relaxes to 0 without changing sign, the contact ends at
//! x = 0 and ε = 5/(4γ) up to exponentially small terms.
//!
//! This regime was the hard case of the former explicit integration (module
//! docs of the crate's engine `hertz_damped`): it is solved in a few thousand
//! right-hand-side evaluations at any γ ≤ [`MAX_DAMPING`] and β, with ε accurate
//! relative to itself.

use crate::hertz_damped::{self, Outcome, Restitution};
use crate::scaled::{positive_up_to, ScaledImpact};
use serde::Serialize;
use tabor_numerics::tolerance::ACCURACY;
use tabor_restitution::{validate, Error, Result};

/// Largest scaled damping γ accepted.
pub const MAX_DAMPING: f64 = 1e3;

/// The damping laws the seed names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum DampingLaw {
    /// Linear damping, β = 0 (Lee & Herrmann).
    LeeHerrmann,
    /// β = 1/4 (Tsuji et al.), with (5.73).
    Tsuji,
    /// β = 3/2 (Hunt & Crossley).
    HuntCrossley,
}

tabor_restitution::menu! {
    DampingLaw, "damping law";
    LeeHerrmann => "lee-herrmann", "linear damping, β = 0 (5.72)";
    Tsuji => "tsuji", "β = 1/4 (5.72), with (5.73)";
    HuntCrossley => "hunt-crossley", "β = 3/2 (5.72)";
}

impl DampingLaw {
    /// The exponent β of (5.72).
    ///
    /// Seed 000, eq. (5.72).
    pub fn exponent(self) -> f64 {
        match self {
            DampingLaw::LeeHerrmann => 0.0,
            DampingLaw::Tsuji => 0.25,
            DampingLaw::HuntCrossley => 1.5,
        }
    }
}

/// Tsuji's scaled damping `γ = α √(15/64)` from the dimensionless α of
/// `λ d^(1/4) = α (m G √(R d))^(1/2)`.
///
/// Seed 000, eq. (5.73).
pub fn tsuji_damping(alpha: f64) -> Result<f64> {
    let a = validate::positive("alpha", alpha)?;
    positive_up_to(
        "alpha",
        a,
        MAX_DAMPING / (15.0_f64 / 64.0).sqrt(),
        "must be finite and lie in (0, 2065]",
    )?;
    Ok(a * (15.0_f64 / 64.0).sqrt())
}

/// The scaled damping `γ = λ d0^(β+1)/(m v0)` with d0 of (5.74), from the damping
/// constant λ (SI: N s m^(−1−β)), the exponent β, the mass m, the impact speed v0,
/// the shear modulus G and the radius R.
///
/// Seed 000, eqs. (5.72), (5.74).
pub fn scaled_damping(
    damping_constant: f64,
    exponent: f64,
    mass: f64,
    impact_speed: f64,
    shear_modulus: f64,
    radius: f64,
) -> Result<f64> {
    let lambda = validate::positive("damping_constant", damping_constant)?;
    let b = check_exponent(exponent)?;
    let d0 = crate::kelvin_voigt_sphere::overlap_scale(mass, impact_speed, shear_modulus, radius)?;
    let ln = lambda.ln() + (b + 1.0) * d0.ln() - mass.ln() - impact_speed.ln();
    validate::positive("damping", ln.exp())
}

fn check_exponent(exponent: f64) -> Result<f64> {
    if exponent.is_finite() && (0.0..=1.5).contains(&exponent) {
        Ok(exponent)
    } else {
        Err(Error::invalid(
            "damping_exponent",
            exponent,
            "must lie in [0, 1.5]",
        ))
    }
}

/// The coefficient of restitution of the law (5.72) with exponent β ∈ [0, 3/2] and
/// scaled damping γ ∈ (0, 1e3], integrated with relative tolerance
/// [`ACCURACY`] (1e-10).
///
/// Seed 000, eq. (5.72).
pub fn restitution(exponent: f64, damping: f64) -> Result<f64> {
    Ok(solve(exponent, damping, ACCURACY)?.restitution)
}

/// The impact under the law (5.72) in the scaling (5.74) (module docs), integrated
/// with relative tolerance `tolerance` ∈ [1e-15, 0.5] (tolerances above 1e-3 are
/// tightened to 1e-3). Every γ ∈ (0, 1e3] and β ∈ [0, 3/2] is solved in a few hundred
/// to a few thousand right-hand-side evaluations; ε, x_max and T_S are accurate to
/// about the tolerance relative to themselves (also ε ~ 1e-8 at γ = 1e3, β = 0,
/// where ε ≈ (5/4) γ^{−5/2}, see [`overdamped_restitution`]).
///
/// Seed 000, eqs. (5.72), (5.74).
pub fn solve(exponent: f64, damping: f64, tolerance: f64) -> Result<ScaledImpact> {
    Ok(solve_with_loss(exponent, damping, tolerance)?.impact)
}

/// [`solve`] with the loss 1 − ε accurate relative to itself.
pub(crate) fn solve_with_loss(exponent: f64, damping: f64, tolerance: f64) -> Result<Outcome> {
    let b = check_exponent(exponent)?;
    let gamma = positive_up_to(
        "damping",
        damping,
        MAX_DAMPING,
        "must be finite and lie in (0, 1e3]",
    )?;
    hertz_damped::solve(b, gamma, Restitution::Damped, tolerance, None)
}

/// The overdamped limit γ → ∞ of the restitution (module docs):
/// `ε∞ = (5/4) x∞^{3/2−β}/γ`, `x∞ = ((β + 1)/γ)^{1/(β+1)}` (β = 0: `(5/4) γ^{−5/2}`).
/// Relative error `−2 (3/2 − β)/(β + 1) · ε∞ ln(1/ε∞) + O(ε∞)`: 1.9e-6 (β = 0),
/// 3.9e-5 (β = 1/4), 2.3e-4 (β = 1/2), 1.1e-3 (β = 1) at γ = 1e3; exact up to
/// exponentially small terms for β = 3/2.
///
/// Seed 000, eq. (5.72).
pub fn overdamped_restitution(exponent: f64, damping: f64) -> Result<f64> {
    let b = check_exponent(exponent)?;
    let gamma = validate::positive("damping", damping)?;
    let x = ((b + 1.0).ln() - gamma.ln()) / (b + 1.0);
    let ln = 1.25_f64.ln() + (1.5 - b) * x - gamma.ln();
    Ok(ln.exp().clamp(0.0, 1.0))
}

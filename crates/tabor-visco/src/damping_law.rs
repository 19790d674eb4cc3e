//! Generalized damping laws for a sphere, seed 000 eq. (5.72):
//! `F = (16G/3) √(R d³) + λ d^β ḋ`, in the scaling (5.74) of
//! [`crate::kelvin_voigt_sphere`]: `ẍ = −(5/4) x^(3/2) − γ x^β ẋ` with the scaled
//! damping `γ = λ d0^(β+1)/(m v0)`. The impact ends where the force vanishes (or at
//! x = 0 if that comes first, possible for β = 3/2). ε depends on (β, γ) only.
//!
//! Named laws: Lee-Herrmann β = 0, Tsuji β = 1/4 (with (5.73) γ = α √(15/64), independent
//! of speed and system), Hunt-Crossley β = 3/2; β = 1/2 with γ = 8 (15/64)^(3/5) δ
//! is Kuwabara-Kono (5.66).

use crate::scaled::{
    ode_tolerance, positive_up_to, restitution_from_rebound, run_phase, ScaledImpact,
};
use serde::Serialize;
use tabor_numerics::ode::EventDirection;
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
/// scaled damping γ ∈ (0, 1e3], integrated with relative tolerance 1e-10.
///
/// Seed 000, eq. (5.72).
pub fn restitution(exponent: f64, damping: f64) -> Result<f64> {
    Ok(solve(exponent, damping, 1e-10)?.restitution)
}

/// The impact under the law (5.72) in the scaling (5.74) (module docs), integrated
/// with relative tolerance `tolerance`.
///
/// Seed 000, eqs. (5.72), (5.74).
pub fn solve(exponent: f64, damping: f64, tolerance: f64) -> Result<ScaledImpact> {
    let b = check_exponent(exponent)?;
    let gamma = positive_up_to(
        "damping",
        damping,
        MAX_DAMPING,
        "must be finite and lie in (0, 1e3]",
    )?;
    let tol = ode_tolerance(tolerance, 0.05)?;
    let mut f = |_t: f64, y: &[f64; 2]| {
        let x = y[0].max(0.0);
        [y[1], -1.25 * x.powf(1.5) - gamma * x.powf(b) * y[1]]
    };
    let t_max = 1e4 * (1.0 + gamma);
    let first = run_phase(
        &mut f,
        &mut |_t: f64, y: &[f64; 2]| y[1],
        EventDirection::Falling,
        0.0,
        [0.0, 1.0],
        t_max,
        tol,
        None,
    )?;
    // F / x^β = (5/4) x^(3/2 − β) + γ ẋ; min with x catches a separation at x = 0.
    let mut g = |_t: f64, y: &[f64; 2]| {
        let x = y[0].max(0.0);
        (1.25 * x.powf(1.5 - b) + gamma * y[1]).min(y[0])
    };
    let second = run_phase(
        &mut f,
        &mut g,
        EventDirection::Falling,
        first.t,
        first.y,
        first.t + t_max,
        tol,
        None,
    )?;
    Ok(ScaledImpact {
        restitution: restitution_from_rebound(-second.y[1])?,
        contact_time: second.t,
        max_overlap: first.y[0],
        cost: first.cost + second.cost,
    })
}

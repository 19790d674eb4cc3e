//! Rigid flat punch (radius a, mass m) on an incompressible standard medium
//! `G(t) = G∞ + G1 exp(−t/τ)`, τ = η/G1 (5.75), seed 000 eqs. (5.76)-(5.83).
//!
//! Exact: with the internal variable d̃ of the Maxwell branch (Fig. 5.10), time in
//! 1/ω∞ (ω∞² = 8G∞a/m) and lengths in v0/ω∞ (5.78), (5.76)-(5.77) read
//! `ẍ = −x − x̃/β`, `x̃' = ẋ − x̃/(βδ)`, x(0) = x̃(0) = 0, ẋ(0) = 1 — equivalent to
//! the third-order (5.79) with (5.80); the impact ends where the force
//! `x + x̃/β` (∝ −ẍ) returns to 0 (5.81). β = G∞/G1, δ = η √(8a/(m G∞)).
//!
//! Approximate: the equivalent Kelvin-Voigt medium with the damping ratio (5.83)
//! inserted into (5.61)/(5.62) (see the crate README for its error over (β, δ)).
//!
//! Note: (5.76) as printed reads `8G1 a d`; the force on the Maxwell branch is
//! `8G1 a d̃` (the (5.79) it leads to confirms this).

use crate::kelvin_voigt_flat;
use crate::scaled::{flat_punch_impact, ode_tolerance, positive_up_to, Method, ScaledImpact};
use tabor_numerics::rosenbrock::Jacobian;
use tabor_numerics::tolerance::ACCURACY;
use tabor_restitution::{validate, Error, Result};

/// Range of the modulus ratio β = G∞/G1.
pub const MODULUS_RATIO_RANGE: (f64, f64) = (1e-5, 1e4);
/// Largest viscous parameter δ.
pub const MAX_VISCOUS_PARAMETER: f64 = 1e4;
/// Below this βδ the phases are integrated by the L-stable Rodas5P.
const STIFF_RELAXATION_TIME: f64 = 1e-2;

/// Smallest product βδ (the scaled relaxation time ω∞τ); below it use the
/// Kelvin-Voigt limit (the medium is within O(βδ) of it). Below βδ = 1e-2 the
/// integration is by the L-stable Rodas5P (a few hundred evaluations at this
/// limit; the explicit method needed 5.7e6).
pub const MIN_RELAXATION_TIME: f64 = 1e-6;

pub(crate) fn check_modulus_ratio(beta: f64) -> Result<f64> {
    let (lo, hi) = MODULUS_RATIO_RANGE;
    if beta.is_finite() && (lo..=hi).contains(&beta) {
        Ok(beta)
    } else {
        Err(Error::invalid(
            "modulus_ratio",
            beta,
            "must lie in [1e-5, 1e4]",
        ))
    }
}

fn check(beta: f64, delta: f64) -> Result<(f64, f64)> {
    let b = check_modulus_ratio(beta)?;
    let d = positive_up_to(
        "viscous_parameter",
        delta,
        MAX_VISCOUS_PARAMETER,
        "must be finite and lie in (0, 1e4]",
    )?;
    if b * d < MIN_RELAXATION_TIME {
        return Err(Error::invalid(
            "viscous_parameter",
            d,
            "times modulus_ratio must be >= 1e-6 (too stiff; use the Kelvin-Voigt limit)",
        ));
    }
    Ok((b, d))
}

/// The parameters `β = G∞/G1` and `δ = η √(8a/(m G∞))` from the relaxed modulus
/// G∞, the Maxwell-branch modulus G1, the viscosity η, the punch radius a and the
/// mass m.
///
/// Seed 000, eq. (5.79).
pub fn parameters(
    relaxed_modulus: f64,
    branch_modulus: f64,
    viscosity: f64,
    punch_radius: f64,
    mass: f64,
) -> Result<(f64, f64)> {
    let g_inf = validate::positive("relaxed_modulus", relaxed_modulus)?;
    let g1 = validate::positive("branch_modulus", branch_modulus)?;
    let eta = validate::positive("viscosity", viscosity)?;
    let a = validate::positive("punch_radius", punch_radius)?;
    let m = validate::positive("mass", mass)?;
    let beta = validate::positive("modulus_ratio", g_inf / g1)?;
    let delta = validate::positive("viscous_parameter", eta * (8.0 * a / (m * g_inf)).sqrt())?;
    Ok((beta, delta))
}

/// The exact coefficient of restitution of the flat punch on a standard medium,
/// ε(β, δ), integrated with relative tolerance
/// [`ACCURACY`] (1e-10).
///
/// Seed 000, eqs. (5.76)-(5.81), Fig. 5.11.
pub fn restitution(modulus_ratio: f64, viscous_parameter: f64) -> Result<f64> {
    Ok(solve(modulus_ratio, viscous_parameter, ACCURACY)?.restitution)
}

/// The exact impact (module docs) in the units of (5.78), integrated with
/// relative tolerance `tolerance` (Dormand-Prince 5(4); Rodas5P where βδ < 1e-2).
///
/// Seed 000, eqs. (5.76)-(5.81).
pub fn solve(modulus_ratio: f64, viscous_parameter: f64, tolerance: f64) -> Result<ScaledImpact> {
    let (b, d) = check(modulus_ratio, viscous_parameter)?;
    let relax = b * d;
    let tol = ode_tolerance(tolerance, 0.05)?;
    // The internal variable relaxes on βδ: below STIFF_RELAXATION_TIME the explicit
    // method would be limited by stability (h ≲ 3βδ; 5.7e6 evaluations at βδ = 1e-6).
    let method = if relax < STIFF_RELAXATION_TIME {
        Method::Stiff(Jacobian::Autonomous)
    } else {
        Method::Explicit
    };
    let mut f = |_t: f64, y: &[f64; 3]| [y[1], -y[0] - y[2] / b, y[1] - y[2] / relax];
    let t_max = 1e4 * (1.0 + d);
    flat_punch_impact(
        method,
        &mut f,
        &mut |_t: f64, y: &[f64; 3]| y[0] + y[2] / b,
        t_max,
        tol,
    )
}

/// The damping ratio of the equivalent Kelvin-Voigt medium,
/// `D = (δ/2) / (1 + δ²β² + δ²β)` (loss over storage modulus of the standard
/// medium at ω∞, (5.56)).
///
/// Seed 000, eqs. (5.82), (5.83).
pub fn equivalent_damping_ratio(modulus_ratio: f64, viscous_parameter: f64) -> Result<f64> {
    let b = check_modulus_ratio(modulus_ratio)?;
    let d = positive_up_to(
        "viscous_parameter",
        viscous_parameter,
        MAX_VISCOUS_PARAMETER,
        "must be finite and lie in (0, 1e4]",
    )?;
    Ok(0.5 * d / (1.0 + d * d * b * b + d * d * b))
}

/// The restitution of the equivalent Kelvin-Voigt medium: (5.83) inserted into
/// (5.61)/(5.62) (closed form, no integration).
///
/// Seed 000, eqs. (5.61)-(5.63), (5.83), Fig. 5.12.
pub fn equivalent_restitution(modulus_ratio: f64, viscous_parameter: f64) -> Result<f64> {
    kelvin_voigt_flat::restitution(equivalent_damping_ratio(modulus_ratio, viscous_parameter)?)
}

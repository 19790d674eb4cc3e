//! Rigid sphere (parabolic, radius R, mass m, speed v0) on an incompressible
//! standard medium `G(t) = G∞ + G1 exp(−t/τ)`, τ = η/G1 (5.75), solved by the MDR
//! model with internal variables (5.84), (5.88), (5.89) in its continuum limit (no
//! elements: the internal variables of the whole bedding enter through two
//! integrals along the compression; the private `mdr` module derives it and shows
//! that no element touches again once it has left). ε depends on β = G∞/G1 and
//! `δ = η (R v0/(m² G∞³))^(1/5)` (5.90) only; β → 0 is the rigorous Kelvin-Voigt
//! sphere of [`crate::kelvin_voigt_sphere`].
//!
//! Scaled: τ̂ = v0 τ/d0 = β (64/15)^(2/5) δ (d0 of (5.74) with G = G∞).

use crate::mdr::{self, ScaledMedium};
use crate::scaled::{positive_up_to, ScaledImpact};
use crate::standard_flat::check_modulus_ratio;
use tabor_restitution::{validate, Error, Result};

/// Largest viscous parameter δ accepted (the Kelvin-Voigt sphere's,
/// [`crate::kelvin_voigt_sphere::MAX_VISCOUS_PARAMETER`]); with τ̂ ≥
/// [`MIN_RELAXATION_TIME`] the MDR solution agrees with the discrete MDR there
/// (tests in `src/mdr/tests.rs`).
pub const MAX_VISCOUS_PARAMETER: f64 = crate::kelvin_voigt_sphere::MAX_VISCOUS_PARAMETER;
/// Smallest scaled relaxation time τ̂ = β (64/15)^(2/5) δ. The internal variables
/// relax on τ̂; below τ̂ = 2e-3 the integration is by the L-stable Rodas5P, which
/// takes ≈ 1.3e3-3.9e3 right-hand-side evaluations (≤ 0.5 ms) at this limit (the
/// explicit method needed ≈ 5e5). There the medium is within O(β) of the
/// Kelvin-Voigt limit (β → 0 with δ fixed; ≈ 1e-6 in ε at the boundary), which
/// [`crate::kelvin_voigt_sphere`] solves.
pub const MIN_RELAXATION_TIME: f64 = 1e-5;

fn medium(beta: f64, delta: f64) -> Result<ScaledMedium> {
    let b = check_modulus_ratio(beta)?;
    let d = positive_up_to(
        "viscous_parameter",
        delta,
        MAX_VISCOUS_PARAMETER,
        "must be finite and lie in (0, 1e9]",
    )?;
    let tau = b * (64.0_f64 / 15.0).powf(0.4) * d;
    if tau < MIN_RELAXATION_TIME {
        return Err(Error::invalid(
            "viscous_parameter",
            d,
            "times modulus_ratio must be >= 5.6e-6 (too stiff; use the Kelvin-Voigt limit)",
        ));
    }
    Ok(ScaledMedium {
        beta: b,
        tau,
        tau0: 0.0,
    })
}

/// The parameters `β = G∞/G1` and `δ = η (R v0/(m² G∞³))^(1/5)` from the relaxed
/// modulus G∞, the branch modulus G1, the viscosity η (Pa s), the radius R, the
/// impact speed v0 and the mass m.
///
/// Seed 000, eq. (5.90).
pub fn parameters(
    relaxed_modulus: f64,
    branch_modulus: f64,
    viscosity: f64,
    radius: f64,
    impact_speed: f64,
    mass: f64,
) -> Result<(f64, f64)> {
    let g_inf = validate::positive("relaxed_modulus", relaxed_modulus)?;
    let g1 = validate::positive("branch_modulus", branch_modulus)?;
    let beta = validate::positive("modulus_ratio", g_inf / g1)?;
    let delta = crate::kelvin_voigt_sphere::viscous_parameter(
        viscosity,
        radius,
        impact_speed,
        mass,
        g_inf,
    )?;
    Ok((beta, delta))
}

/// The coefficient of restitution ε(β, δ), relative integration tolerance 1e-8.
///
/// Seed 000, eqs. (5.84)-(5.90), Fig. 5.13.
pub fn restitution(modulus_ratio: f64, viscous_parameter: f64) -> Result<f64> {
    Ok(solve(modulus_ratio, viscous_parameter, 1e-8)?.restitution)
}

/// The impact in the scaling (5.74) (G = G∞), relative integration tolerance
/// `tolerance` (values above 1e-4 are tightened to 1e-4). There is no
/// discretization error: the achieved error in ε and x_max is about the
/// tolerance (≤ 1.6 tol observed), in the contact time a few times it.
///
/// Seed 000, eqs. (5.84)-(5.90).
pub fn solve(modulus_ratio: f64, viscous_parameter: f64, tolerance: f64) -> Result<ScaledImpact> {
    let m = medium(modulus_ratio, viscous_parameter)?;
    validate::tolerance("tolerance", tolerance)?;
    mdr::solve(&m, tolerance)
}

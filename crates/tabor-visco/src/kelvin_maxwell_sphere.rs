//! Rigid sphere on an incompressible Kelvin-Maxwell medium: static modulus G∞, one
//! Maxwell branch G1 whose relaxation time τ is the elastic contact time (5.12)
//! with G = G∞, and a parallel dashpot η0 standing for all faster relaxations
//! (seed 000 section 5.4.4, (5.91)). MDR in its continuum limit as for the
//! standard medium (the private `mdr` module) with the line load (5.91). ε depends on β = G∞/G1 and
//! `δ = η0 (R v0/(m² G∞³))^(1/5)` (5.92) only.
//!
//! Scaled (5.74), G = G∞: τ̂ = T_S v0/d0 = (4/5) B(2/5, 1/2) ≈ 2.943 (5.12),
//! τ̂0 = v0 η0/(G∞ d0) = (64/15)^(2/5) δ.

use crate::mdr::{self, ScaledMedium};
use crate::scaled::{positive_up_to, ScaledImpact};
use crate::standard_flat::check_modulus_ratio;
use tabor_numerics::special::beta;
use tabor_restitution::{validate, Result};

/// Largest viscous parameter δ accepted.
pub const MAX_VISCOUS_PARAMETER: f64 = 1e3;

/// The scaled elastic contact time `T_S v0/d0 = (4/5) B(2/5, 1/2)` of the Hertzian
/// impact, the relaxation time of the Maxwell branch.
///
/// Seed 000, eq. (5.12).
pub fn scaled_relaxation_time() -> Result<f64> {
    Ok(0.8 * beta(0.4, 0.5)?)
}

/// The parameters `β = G∞/G1` and `δ = η0 (R v0/(m² G∞³))^(1/5)` from G∞, G1, the
/// dashpot viscosity η0 (Pa s), the radius R, the impact speed v0 and the mass m.
///
/// Seed 000, eq. (5.92).
pub fn parameters(
    relaxed_modulus: f64,
    branch_modulus: f64,
    dashpot_viscosity: f64,
    radius: f64,
    impact_speed: f64,
    mass: f64,
) -> Result<(f64, f64)> {
    crate::standard_sphere::parameters(
        relaxed_modulus,
        branch_modulus,
        dashpot_viscosity,
        radius,
        impact_speed,
        mass,
    )
}

/// The coefficient of restitution ε(β, δ), relative integration tolerance 1e-8.
///
/// Seed 000, eqs. (5.91), (5.92), Fig. 5.14.
pub fn restitution(modulus_ratio: f64, viscous_parameter: f64) -> Result<f64> {
    Ok(solve(modulus_ratio, viscous_parameter, 1e-8)?.restitution)
}

/// The impact in the scaling (5.74) (G = G∞), relative integration tolerance
/// `tolerance` (values above 1e-4 are tightened to 1e-4). The achieved error in ε
/// and x_max is about the tolerance; the contact time of creeping impacts (δ ~ 1e3,
/// ε < 1e-2) is ill-conditioned and can be off by far more (1e-3 relative at
/// tolerance 1e-8), ε not.
///
/// Seed 000, eqs. (5.84)-(5.92).
pub fn solve(modulus_ratio: f64, viscous_parameter: f64, tolerance: f64) -> Result<ScaledImpact> {
    let b = check_modulus_ratio(modulus_ratio)?;
    let d = positive_up_to(
        "viscous_parameter",
        viscous_parameter,
        MAX_VISCOUS_PARAMETER,
        "must be finite and lie in (0, 1e3]",
    )?;
    validate::tolerance("tolerance", tolerance)?;
    let m = ScaledMedium {
        beta: b,
        tau: scaled_relaxation_time()?,
        tau0: (64.0_f64 / 15.0).powf(0.4) * d,
    };
    mdr::solve(&m, tolerance)
}

//! Rigid flat punch (radius a, mass m) on an incompressible Kelvin-Voigt half-space
//! (shear modulus G, shear viscosity η), seed 000 eqs. (5.54)-(5.63): the impact is
//! the damped oscillator `m d̈ + 8ηa ḋ + 8Ga d = 0` (5.54), ending where the normal
//! force `8Ga d + 8ηa ḋ` vanishes (not at d = 0, seed footnote 6). Restitution and
//! the scaled contact time depend on the damping ratio D of (5.55) only.
//!
//! The three closed forms (5.61) (D < 1), (5.63) (D = 1), (5.62) (D > 1) are one
//! analytic function of z = (1 − D²)/D²: with g(z) = arctan(√z)/√z for z > 0,
//! artanh(√−z)/√−z for z < 0 and g(0) = 1, `ε = exp(−2 g(z))` and
//! `ω0 T_S = 2 g(z)/D`. Near D = 1 (|z| < 0.05) g is summed as its power series
//! `Σ (−z)^k/(2k+1)`, so ε is smooth and finite through D = 1.

use crate::scaled::positive_up_to;
use tabor_restitution::{validate, Result};

/// Largest damping ratio accepted (ε ≈ 1/(4D²) there, still representable).
pub const MAX_DAMPING_RATIO: f64 = 1e150;

const REQUIREMENT: &str = "must be finite and lie in (0, 1e150]";

/// g(z) of the module docs, for z = (1 − D²)/D², given D.
fn damping_integral(d: f64) -> f64 {
    // z = (1 − D)(1 + D)/D², exact enough near D = 1 (1 − D is exact there).
    let z = (1.0 - d) * (1.0 + d) / (d * d);
    if z.abs() < 0.05 {
        // Σ_{k≥0} (−z)^k / (2k + 1); |z|^30 < 1e-39.
        let mut sum = 0.0;
        let mut power = 1.0;
        for k in 0..30 {
            sum += power / (2 * k + 1) as f64;
            power *= -z;
        }
        sum
    } else if d < 1.0 {
        // arctan(√z)/√z = D/s · atan2(s, D), s = √(1 − D²): finite for tiny D.
        let s = ((1.0 - d) * (1.0 + d)).sqrt();
        d / s * s.atan2(d)
    } else {
        // artanh(q)/q with q = √(1 − 1/D²); artanh(q) = ln(D (1 + q)) exactly,
        // since 1 − q² = 1/D². No overflow for large D.
        let inv = 1.0 / d;
        let q = ((1.0 - inv) * (1.0 + inv)).sqrt();
        (d.ln() + q.ln_1p()) / q
    }
}

/// The coefficient of restitution of a rigid flat punch on an incompressible
/// Kelvin-Voigt half-space as a function of the damping ratio D (5.55):
/// `ε = exp[−2D/√(1−D²) · arctan(√(1−D²)/D)]` for D < 1 (5.61), `e⁻²` for D = 1
/// (5.63), `exp[−2D/√(D²−1) · artanh(√(D²−1)/D)]` for D > 1 (5.62); evaluated
/// stably (series in 1 − D² near D = 1, module docs).
///
/// Seed 000, eqs. (5.61), (5.62), (5.63).
pub fn restitution(damping_ratio: f64) -> Result<f64> {
    let d = positive_up_to(
        "damping_ratio",
        damping_ratio,
        MAX_DAMPING_RATIO,
        REQUIREMENT,
    )?;
    Ok((-2.0 * damping_integral(d)).exp().clamp(0.0, 1.0))
}

/// The contact time in units of 1/ω0 (ω0² = 8Ga/m, (5.55)):
/// `ω0 T_S = 2/√(1−D²) · arctan(√(1−D²)/D)` (5.60), continued analytically to
/// D ≥ 1 (artanh; 2 at D = 1).
///
/// Seed 000, eq. (5.60).
pub fn contact_time(damping_ratio: f64) -> Result<f64> {
    let d = positive_up_to(
        "damping_ratio",
        damping_ratio,
        MAX_DAMPING_RATIO,
        REQUIREMENT,
    )?;
    Ok(2.0 * damping_integral(d) / d)
}

/// The damping ratio `D = 4ηa/(m ω0)` with `ω0 = √(8Ga/m)`, i.e.
/// `D = η √(2a/(m G))`, from the shear modulus G (Pa), the shear viscosity η
/// (Pa s), the punch radius a (m) and the mass m (kg).
///
/// Seed 000, eq. (5.55) (and (5.56): 2D = η ω0 / G).
pub fn damping_ratio(
    shear_modulus: f64,
    viscosity: f64,
    punch_radius: f64,
    mass: f64,
) -> Result<f64> {
    let g = validate::positive("shear_modulus", shear_modulus)?;
    let eta = validate::positive("viscosity", viscosity)?;
    let a = validate::positive("punch_radius", punch_radius)?;
    let m = validate::positive("mass", mass)?;
    let d = eta * (2.0 * a / (m * g)).sqrt();
    positive_up_to(
        "damping_ratio",
        d,
        MAX_DAMPING_RATIO,
        "from these inputs (eta sqrt(2a/(m G))) must be finite and lie in (0, 1e150]",
    )
}

/// The angular frequency `ω0 = √(8Ga/m)` (1/s) of the undamped punch.
///
/// Seed 000, eq. (5.55).
pub fn natural_frequency(shear_modulus: f64, punch_radius: f64, mass: f64) -> Result<f64> {
    let g = validate::positive("shear_modulus", shear_modulus)?;
    let a = validate::positive("punch_radius", punch_radius)?;
    let m = validate::positive("mass", mass)?;
    validate::positive("natural_frequency", (8.0 * g * a / m).sqrt())
}

//! Rigid flat punch on a compressible Kelvin-Voigt half-space,
//! `G(t) = G∞ + η δ(t)`, `K(t) = K∞ + ξ δ(t)` (5.93)-(5.94), seed 000 eqs.
//! (5.95)-(5.100). With the auxiliary displacement d̃ of Fig. 5.15, in the units
//! (5.98) (time 1/ω0, lengths v0/ω0, ω0² = 8G∞a/m) and r = 1/(2(1 − ν)):
//!
//! - (5.96): `ẍ = −x̃ − 2D1 x̃'` (the force is `x̃ + 2D1 x̃'`);
//! - (5.97): `[2D2 r + 2D1 (1 − r)] x̃' = r x + 2D2 r ẋ − x̃`,
//!
//! x(0) = x̃(0) = 0, ẋ(0) = 1; the impact ends where the force vanishes. ν → 1/2
//! gives r → 1, x̃ → x: the incompressible medium of [`crate::kelvin_voigt_flat`]
//! with D = D1.
//!
//! Note: (5.96) as printed reads `8G∞ a ũ`; the elastic force acts on d̃ (it is
//! `8a(G∞ d̃ + η ḋ̃)`, the flat-punch stiffness `8aG(3K+G)/(3K+4G)` with the
//! correspondence principle).

use crate::scaled::{flat_punch_impact, ode_tolerance, positive_up_to, Method, ScaledImpact};
use tabor_numerics::tolerance::ACCURACY;
use tabor_restitution::{validate, Error, Result};

/// Largest damping ratios D1, D2 accepted.
pub const MAX_DAMPING_RATIO: f64 = 1e3;
/// Smallest relaxation time `2D2 r + 2D1(1 − r)` of x̃ (scaled): below it the
/// explicit integration gets too stiff (ν too close to 1/2; use the incompressible
/// closed form).
pub const MIN_RELAXATION_TIME: f64 = 1e-6;

/// The static Poisson's ratio `ν = (3K∞ − 2G∞)/(6K∞ + 2G∞)` from the bulk and
/// shear moduli.
///
/// Seed 000, eq. (5.95).
pub fn poisson_ratio(bulk_modulus: f64, shear_modulus: f64) -> Result<f64> {
    let k = validate::positive("bulk_modulus", bulk_modulus)?;
    let g = validate::positive("shear_modulus", shear_modulus)?;
    validate::finite("poisson_ratio", (3.0 * k - 2.0 * g) / (6.0 * k + 2.0 * g))
}

/// The damping ratios `2D1 = η ω0/G∞` and `2D2 = (3ξ + η) ω0/(3K∞ + G∞)`,
/// ω0 = √(8G∞a/m), from G∞, K∞, the shear and bulk viscosities η, ξ, the punch
/// radius a and the mass m.
///
/// Seed 000, eqs. (5.98), (5.99).
pub fn damping_ratios(
    shear_modulus: f64,
    bulk_modulus: f64,
    shear_viscosity: f64,
    bulk_viscosity: f64,
    punch_radius: f64,
    mass: f64,
) -> Result<(f64, f64)> {
    let g = validate::positive("shear_modulus", shear_modulus)?;
    let k = validate::positive("bulk_modulus", bulk_modulus)?;
    let eta = validate::positive("shear_viscosity", shear_viscosity)?;
    let xi = validate::non_negative("bulk_viscosity", bulk_viscosity)?;
    let w0 = crate::kelvin_voigt_flat::natural_frequency(g, punch_radius, mass)?;
    let d1 = validate::positive("shear_damping_ratio", 0.5 * eta * w0 / g)?;
    let d2 = validate::positive(
        "bulk_damping_ratio",
        0.5 * (3.0 * xi + eta) * w0 / (3.0 * k + g),
    )?;
    Ok((d1, d2))
}

/// D2 for equal shear and bulk viscosity, `D2 = (4/3)(1 − 2ν) D1`.
///
/// Seed 000, eq. (5.100).
pub fn bulk_damping_ratio_equal_viscosities(
    poisson_ratio: f64,
    shear_damping_ratio: f64,
) -> Result<f64> {
    let nu = check_poisson(poisson_ratio)?;
    let d1 = check_d("shear_damping_ratio", shear_damping_ratio)?;
    Ok(4.0 / 3.0 * (1.0 - 2.0 * nu) * d1)
}

fn check_poisson(nu: f64) -> Result<f64> {
    validate::in_open_interval(
        "poisson_ratio",
        nu,
        -1.0,
        0.5,
        "must satisfy -1 < nu < 0.5 (nu = 0.5 is the incompressible model)",
    )
}

fn check_d(name: &'static str, d: f64) -> Result<f64> {
    positive_up_to(
        name,
        d,
        MAX_DAMPING_RATIO,
        "must be finite and lie in (0, 1e3]",
    )
}

/// The coefficient of restitution ε(ν, D1, D2), relative integration tolerance
/// 1e-10.
///
/// Seed 000, eqs. (5.96)-(5.99), Fig. 5.16.
pub fn restitution(
    poisson_ratio: f64,
    shear_damping_ratio: f64,
    bulk_damping_ratio: f64,
) -> Result<f64> {
    Ok(solve(
        poisson_ratio,
        shear_damping_ratio,
        bulk_damping_ratio,
        ACCURACY,
    )?
    .restitution)
}

/// The impact in the units (5.98) (module docs), relative integration tolerance
/// `tolerance`.
///
/// Seed 000, eqs. (5.96)-(5.99).
pub fn solve(
    poisson_ratio: f64,
    shear_damping_ratio: f64,
    bulk_damping_ratio: f64,
    tolerance: f64,
) -> Result<ScaledImpact> {
    let nu = check_poisson(poisson_ratio)?;
    let d1 = check_d("shear_damping_ratio", shear_damping_ratio)?;
    let d2 = check_d("bulk_damping_ratio", bulk_damping_ratio)?;
    let r = 0.5 / (1.0 - nu);
    let relax = 2.0 * d2 * r + 2.0 * d1 * (1.0 - r);
    if relax.is_nan() || relax < MIN_RELAXATION_TIME {
        return Err(Error::invalid(
            "poisson_ratio",
            nu,
            "is too close to 0.5 for these damping ratios (stiff; use the incompressible model)",
        ));
    }
    let tol = ode_tolerance(tolerance, 0.05)?;
    let aux_rate = move |y: &[f64; 3]| (r * y[0] + 2.0 * d2 * r * y[1] - y[2]) / relax;
    let mut f = |_t: f64, y: &[f64; 3]| {
        let w = aux_rate(y);
        [y[1], -y[2] - 2.0 * d1 * w, w]
    };
    let t_max = 1e4 * (1.0 + d1 + d2);
    flat_punch_impact(
        Method::Explicit,
        &mut f,
        &mut |_t: f64, y: &[f64; 3]| y[2] + 2.0 * d1 * aux_rate(y),
        t_max,
        tol,
    )
}

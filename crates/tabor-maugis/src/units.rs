//! Physical scales of the normalization and conversions into the Tabor parameter Λ.

use crate::impact::check_lambda;
use tabor_restitution::{validate, Error, Result};

/// The JKR force-controlled critical state that normalizes the Maugis-Dugdale
/// solution (seed 000 eq. (5.43); scales `a_c`, `F_n`, `d_n`, `F_n d_n`): the same
/// type as the JKR sphere's, built by [`JkrScales::new`].
pub use tabor_jkr::JkrScales;

/// `Λ = π (9/4)^(1/3) / 6 ≈ 0.6861` times Maugis' λ.
pub const LAMBDA_PER_MAUGIS_PARAMETER: f64 = 0.686_108_492_583_778_5;

/// Dugdale equivalence of Tabor's μ (Lennard-Jones): `λ ≈ 1.1570 μ`
/// (crate docs, "Normalization"; Johnson & Greenwood 1997 match σ0 = 1.03 σ_th and
/// h = 0.97 z0).
pub const MAUGIS_PER_TABOR_MU: f64 = 1.157;

/// The seed's Tabor parameter from the Dugdale cohesive stress σ0 (Pa):
/// `Λ = σ0 a_c² / (3 R Δγ)` (crate docs, "Normalization").
pub fn tabor_parameter_from_cohesive_stress(
    cohesive_stress: f64,
    work_of_adhesion: f64,
    effective_modulus: f64,
    effective_radius: f64,
) -> Result<f64> {
    let s0 = validate::positive("cohesive_stress", cohesive_stress)?;
    let scales = JkrScales::new(effective_modulus, effective_radius, work_of_adhesion)?;
    // σ0 a_c²/(3RΔγ) = σ0 d_n / Δγ = d_n / h
    check_lambda(s0 * scales.depth / work_of_adhesion)
}

/// The seed's Tabor parameter from the range of adhesion h = Δγ/σ0 (m):
/// `Λ = d_n / h` (crate docs, "Normalization").
pub fn tabor_parameter_from_range(
    range: f64,
    work_of_adhesion: f64,
    effective_modulus: f64,
    effective_radius: f64,
) -> Result<f64> {
    let h = validate::positive("range", range)?;
    let scales = JkrScales::new(effective_modulus, effective_radius, work_of_adhesion)?;
    check_lambda(scales.depth / h)
}

/// The seed's Tabor parameter from Maugis' λ = 2σ0 (R/(πΔγK²))^(1/3), K = 4E*/3:
/// `Λ = π(9/4)^(1/3)/6 · λ ≈ 0.6861 λ` (crate docs, "Normalization").
pub fn tabor_parameter_from_maugis(maugis_parameter: f64) -> Result<f64> {
    let l = validate::positive("maugis_parameter", maugis_parameter)?;
    check_lambda(LAMBDA_PER_MAUGIS_PARAMETER * l)
}

/// The seed's Tabor parameter from Tabor's μ = (RΔγ²/(E*² z0³))^(1/3), through the
/// Dugdale equivalence λ ≈ 1.1570 μ (an approximation: the Dugdale and
/// Lennard-Jones laws are different). So Λ = 4 is μ ≈ 5 (seed 000, after (5.46)).
pub fn tabor_parameter_from_tabor_mu(tabor_mu: f64) -> Result<f64> {
    let mu = validate::positive("tabor_parameter_mu", tabor_mu)?;
    check_lambda(LAMBDA_PER_MAUGIS_PARAMETER * MAUGIS_PER_TABOR_MU * mu)
}

/// Maugis' λ from the seed's Λ (inverse of [`tabor_parameter_from_maugis`]).
pub fn maugis_parameter(tabor_parameter: f64) -> Result<f64> {
    let lambda = check_lambda(tabor_parameter)?;
    let maugis = lambda / LAMBDA_PER_MAUGIS_PARAMETER;
    if !maugis.is_finite() {
        return Err(Error::invalid(
            "tabor_parameter",
            lambda,
            "is so large that Maugis' lambda overflows",
        ));
    }
    Ok(maugis)
}

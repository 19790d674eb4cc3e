//! The normalized trajectory of the elastic impact, seed 000 eqs. (5.31)-(5.32): in
//! `t̂ = v0 t / d_max` and `d̂ = d / d_max` every power-law impact, homogeneous or
//! graded, follows one curve that depends only on ñ = n/(1+k).

use tabor_numerics::special::{beta, incomplete_beta};
use tabor_restitution::{validate, Error, Result};

fn exponent_p(equivalent_exponent: f64) -> Result<f64> {
    let n = validate::positive("equivalent_exponent", equivalent_exponent)?;
    // p = ñ/(2ñ+1) = n/(2n+k+1), in (0, 1/2).
    Ok(n / (2.0 * n + 1.0))
}

/// The normalized inverse trajectory on loading,
/// `t̂(d̂) = p B(d̂^(1/p); p, 1/2)`, `p = ñ/(2ñ+1)`, for 0 ≤ d̂ ≤ 1 and ñ > 0
/// (`equivalent_exponent`; n for homogeneous media).
///
/// Seed 000, eqs. (5.31)-(5.32) with (5.17) (and (5.11) for ñ = 2).
pub fn normalized_time(normalized_overlap: f64, equivalent_exponent: f64) -> Result<f64> {
    let p = exponent_p(equivalent_exponent)?;
    let d = validate::non_negative("normalized_overlap", normalized_overlap)?;
    if d > 1.0 {
        return Err(Error::invalid(
            "normalized_overlap",
            d,
            "must lie in [0, 1]",
        ));
    }
    let xi = d.powf(1.0 / p);
    Ok(p * incomplete_beta(xi, p, 0.5)?)
}

/// The normalized contact time `T̂_S = v0 T_S / d_max = 2p B(1; p, 1/2)`,
/// `p = ñ/(2ñ+1)`; π in the limit ñ → ∞.
///
/// Seed 000, eqs. (5.18), (5.31)-(5.32) (and (5.12) for ñ = 2).
pub fn normalized_contact_time(equivalent_exponent: f64) -> Result<f64> {
    let p = exponent_p(equivalent_exponent)?;
    Ok(2.0 * p * beta(p, 0.5)?)
}

/// The limit ñ → ∞ (flat punch, or k → −1) of the normalized trajectory, the
/// harmonic solution `t̂(d̂) = arcsin d̂`, since `B(z²; 1/2, 1/2) = 2 arcsin z`; in
/// physical units Hunter's `d = d_max sin(π t / T_S)`.
///
/// Seed 000, eqs. (5.19) and (5.14).
pub fn harmonic_normalized_time(normalized_overlap: f64) -> Result<f64> {
    let d = validate::non_negative("normalized_overlap", normalized_overlap)?;
    if d > 1.0 {
        return Err(Error::invalid(
            "normalized_overlap",
            d,
            "must lie in [0, 1]",
        ));
    }
    Ok(d.asin())
}

//! Validity checks of the quasi-static impact theory, seed 000 section 5.1. They are
//! reported as [`Warning`]s: the numbers are still computed, but the user is told
//! that the model's assumptions are stretched.

use crate::{validate, Result};
use serde::Serialize;

/// A validity warning attached to a result.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Warning {
    /// A stable machine-readable code, for example `quasi-static`.
    pub code: &'static str,
    /// A sentence for people.
    pub message: String,
}

/// The speed ratio above which the quasi-static assumption is reported as violated:
/// seed 000 section 5.1 asks for impact speeds about three orders of magnitude below
/// `ṽ_el = √(E/ρ)`.
pub const QUASI_STATIC_SPEED_RATIO: f64 = 1e-3;

/// Result of the quasi-static check (5.4).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct QuasiStaticCheck {
    /// `ṽ_el = √(E/ρ)` (m/s).
    pub wave_speed: f64,
    /// Hunter's parameter `(v0/ṽ_el)^(3/5)`, which must be ≪ 1.
    pub hunter_parameter: f64,
    /// True when `v0 ≤ 1e-3 ṽ_el`.
    pub satisfied: bool,
}

impl QuasiStaticCheck {
    /// A warning when the check fails.
    pub fn warning(&self) -> Option<Warning> {
        (!self.satisfied).then(|| Warning {
            code: "quasi-static",
            message: format!(
                "impact speed is not small against the elastic wave speed {:.3e} m/s: \
                 (v0/v_el)^(3/5) = {:.3e}; energy radiated as elastic waves is neglected \
                 (Willert 2020, eq. (5.4))",
                self.wave_speed, self.hunter_parameter
            ),
        })
    }
}

/// Seed 000 eq. (5.4): the quasi-static treatment needs `(v0/ṽ_el)^(3/5) ≪ 1` with
/// `ṽ_el = √(E/ρ)`. `youngs_modulus` (Pa) and `density` (kg/m³) are those of the
/// body that carries the waves (the softer one).
pub fn quasi_static_check(
    impact_speed: f64,
    youngs_modulus: f64,
    density: f64,
) -> Result<QuasiStaticCheck> {
    let v = validate::positive("impact_speed", impact_speed)?;
    let e = validate::positive("youngs_modulus", youngs_modulus)?;
    let rho = validate::positive("density", density)?;
    let wave_speed = (e / rho).sqrt();
    if !(wave_speed.is_finite() && wave_speed > 0.0) {
        return Err(crate::Error::invalid(
            "density",
            rho,
            "gives an elastic wave speed sqrt(E/rho) that overflows or underflows",
        ));
    }
    let ratio = v / wave_speed;
    let hunter_parameter = ratio.powf(0.6);
    if !(hunter_parameter.is_finite() && hunter_parameter > 0.0) {
        return Err(crate::Error::invalid(
            "impact_speed",
            v,
            "gives a ratio v0/v_el to the elastic wave speed that overflows or underflows",
        ));
    }
    Ok(QuasiStaticCheck {
        wave_speed,
        hunter_parameter,
        satisfied: ratio <= QUASI_STATIC_SPEED_RATIO,
    })
}

/// Result of the elastic-limit check (5.13).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ElasticLimitCheck {
    /// Maximum Hertzian contact pressure during the impact, (5.13) (Pa).
    pub max_pressure: f64,
    /// Pressure at which yield starts, 1.6 σ_Y (Pa).
    pub yield_pressure: f64,
    /// True when `max_pressure ≤ yield_pressure`.
    pub satisfied: bool,
}

impl ElasticLimitCheck {
    /// A warning when the check fails.
    pub fn warning(&self) -> Option<Warning> {
        (!self.satisfied).then(|| Warning {
            code: "elastic-limit",
            message: format!(
                "maximum contact pressure {:.3e} Pa exceeds the yield onset 1.6 sigma_Y = {:.3e} Pa: \
                 the impact is not elastic (Willert 2020, eq. (5.13))",
                self.max_pressure, self.yield_pressure
            ),
        })
    }
}

/// The factor between the yield stress and the maximum Hertz pressure at the onset
/// of yield (von Mises, ν ≈ 0.3): `p_Y = 1.6 σ_Y`.
pub const YIELD_PRESSURE_FACTOR: f64 = 1.6;

/// Seed 000 eq. (5.13): the maximum Hertz pressure of an elastic impact,
/// `p_max = (2/π) (15 E⁴ m v0² / (16 R³))^(1/5)`, against the yield onset
/// `1.6 σ_Y`. Inputs are the effective modulus E* (Pa), radius R (m), mass m (kg),
/// the impact speed (m/s) and the yield stress σ_Y (Pa) of the softer body.
pub fn elastic_limit_check(
    effective_modulus: f64,
    effective_radius: f64,
    effective_mass: f64,
    impact_speed: f64,
    yield_stress: f64,
) -> Result<ElasticLimitCheck> {
    let e = validate::positive("effective_modulus", effective_modulus)?;
    let r = validate::positive("effective_radius", effective_radius)?;
    let m = validate::positive("effective_mass", effective_mass)?;
    let v = validate::positive("impact_speed", impact_speed)?;
    let sy = validate::positive("yield_stress", yield_stress)?;
    // (5.13) written as (2E/π) (d_max/R)^(1/2) with d_max from (5.8), to avoid E⁴.
    let d_max = (15.0 * m * v * v / (16.0 * e * r.sqrt())).powf(0.4);
    let max_pressure = 2.0 * e / std::f64::consts::PI * (d_max / r).sqrt();
    let max_pressure = validate::finite("max_pressure", max_pressure)?;
    let yield_pressure = YIELD_PRESSURE_FACTOR * sy;
    if !yield_pressure.is_finite() {
        return Err(crate::Error::invalid(
            "yield_stress",
            sy,
            "gives a yield pressure 1.6 sigma_Y that overflows",
        ));
    }
    Ok(ElasticLimitCheck {
        max_pressure,
        yield_pressure,
        satisfied: max_pressure <= yield_pressure,
    })
}

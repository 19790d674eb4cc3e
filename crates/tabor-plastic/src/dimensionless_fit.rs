//! The dimensionless restitution model fitted to FEM impacts of an elastic sphere on
//! an elastic-perfectly plastic substrate (seed 001, eqs. (12), (18), (19)).

use crate::util::finite_output;
use serde::Serialize;
use tabor_restitution::{validate, EnergyLoss, Error, ImpactModel, Result};

const MODEL: &str = "dimensionless fit";

/// How the fitted formula was kept inside [0, 1].
///
/// Seed 001, eq. (19) (values outside [0, 1]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Clamping {
    /// The formula gave a value in [0, 1] (or `v0 < v_y`, where `e = 1` by definition).
    None,
    /// The formula gave more than 1 (just above `v_y`): reported as 1.
    ToOne,
    /// The formula gave less than 0 (very high speed): reported as 0 (sticking).
    ToZero,
}

/// The restitution of the fit at one speed, with the raw formula value.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FittedRestitution {
    /// `e` in [0, 1].
    pub restitution: f64,
    /// The value of the formula (12)/(19) before clamping (1 below `v_y`).
    pub formula_value: f64,
    /// Whether and how the value was clamped.
    pub clamping: Clamping,
}

/// Seed 001's model: `e = 1` for `v0 < v_y`, else
/// `e = 1.16 + 0.253 ln(σ_y/E*) + 0.056 ln(E*/(ρ v0²))`, with the yield velocity
/// `v_y = (15.81 σ_y^4.5/(ρ E*^3.5))^0.5` (SI units: `15.81 = c (E*_0)^3.5/σ_0^4.5`
/// with `c = 0.05 Pa`, `σ_0 = 100 MPa`, `E*_0 = 100 GPa`, so `ρ v_y²` is in Pa).
/// `ρ` is the density of the (elastic) sphere, `σ_y` the substrate's yield stress.
///
/// Seed 001, eqs. (12), (18), (19) (fitted for σ_y/E* ≈ 1.5e-3 ... 2.6e-2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DimensionlessFit {
    modulus: f64,
    yield_stress: f64,
    density: f64,
    mass: f64,
    yield_velocity: f64,
}

impl DimensionlessFit {
    /// The model for effective modulus `E*` (Pa), substrate yield stress `σ_y` (Pa,
    /// < E*), sphere density `ρ` (kg/m³) and effective mass `m` (kg, only for the
    /// energy loss), all finite and > 0.
    ///
    /// Seed 001, eqs. (18)-(19).
    pub fn new(
        effective_modulus: f64,
        yield_stress: f64,
        density: f64,
        effective_mass: f64,
    ) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let s = validate::positive("yield_stress", yield_stress)?;
        let rho = validate::positive("density", density)?;
        let m = validate::positive("effective_mass", effective_mass)?;
        if s >= e {
            return Err(Error::invalid(
                "yield_stress",
                s,
                "must be smaller than the effective modulus",
            ));
        }
        // v_y² = 15.81 σ^4.5/(ρ E^3.5) = 15.81 (σ/E)^3.5 σ/ρ, ordered against overflow.
        let v2 = 15.81 * (s / e).powf(3.5) * (s / rho);
        let yield_velocity = finite_output(MODEL, "yield velocity v_y", v2.sqrt())?;
        Ok(DimensionlessFit {
            modulus: e,
            yield_stress: s,
            density: rho,
            mass: m,
            yield_velocity,
        })
    }

    /// The yield velocity `v_y = (15.81 σ_y^4.5/(ρ E*^3.5))^0.5` (m/s).
    ///
    /// Seed 001, eq. (18).
    pub fn yield_velocity(&self) -> f64 {
        self.yield_velocity
    }

    /// The restitution at impact speed `v0` (m/s, > 0), clamped to [0, 1].
    ///
    /// Seed 001, eqs. (12), (19).
    pub fn restitution(&self, impact_speed: f64) -> Result<FittedRestitution> {
        let v = validate::positive("impact_speed", impact_speed)?;
        if v < self.yield_velocity {
            return Ok(FittedRestitution {
                restitution: 1.0,
                formula_value: 1.0,
                clamping: Clamping::None,
            });
        }
        // ln(E/(ρv²)) = ln(E/ρ) − 2 ln v, no overflow.
        let raw = 1.16
            + 0.253 * (self.yield_stress / self.modulus).ln()
            + 0.056 * ((self.modulus / self.density).ln() - 2.0 * v.ln());
        let raw = finite_output(MODEL, "restitution", raw)?;
        let (restitution, clamping) = if raw > 1.0 {
            (1.0, Clamping::ToOne)
        } else if raw < 0.0 {
            (0.0, Clamping::ToZero)
        } else {
            (raw, Clamping::None)
        };
        Ok(FittedRestitution {
            restitution,
            formula_value: raw,
            clamping,
        })
    }
}

impl ImpactModel for DimensionlessFit {
    fn name(&self) -> String {
        "dimensionless FEM fit (Chin. J. Theor. Appl. Mech.)".into()
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    /// `(1 − e²) m v0²/2` with `e` of seed 001, eq. (19) (clamped to [0, 1]).
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let fit = self.restitution(impact_speed)?;
        let e = fit.restitution;
        let kinetic = finite_output(
            MODEL,
            "kinetic energy",
            0.5 * self.mass * impact_speed * impact_speed,
        )?;
        let branch = match fit.clamping {
            Clamping::None if impact_speed < self.yield_velocity => "elastic (v0 < v_y), eq. (12)",
            Clamping::None => "fitted formula, eq. (19) of the dimensionless FEM fit",
            Clamping::ToOne => {
                "fitted formula > 1, clamped to 1 (eq. (19) of the dimensionless FEM fit)"
            }
            Clamping::ToZero => {
                "fitted formula < 0, clamped to 0 (eq. (19) of the dimensionless FEM fit)"
            }
        };
        Ok(EnergyLoss::closed_form((1.0 - e * e) * kinetic, branch))
    }
    fn speed_scale(&self) -> f64 {
        self.yield_velocity.max(f64::MIN_POSITIVE)
    }
}

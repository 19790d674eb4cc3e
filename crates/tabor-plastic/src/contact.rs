//! The rigid sphere on an elastic-perfectly plastic half-space: where yield begins
//! (Thornton's limiting pressure), seed 000 eqs. (5.102)-(5.103).

use crate::util::positive_output;
use std::f64::consts::PI;
use tabor_restitution::{validate, Error, Result};

/// Thornton's limiting contact pressure over the yield stress, `p_Y = 1.6 σ_Y`
/// (the maximum Hertz pressure at first yield for ν ≈ 0.3).
///
/// Seed 000, eq. (5.102) (the factor `4π/5 = π·1.6/2`).
pub const LIMITING_PRESSURE_RATIO: f64 = 1.6;

const MODEL: &str = "elastic-plastic contact";

/// A rigid sphere (effective radius `R`) on an elastic-perfectly plastic half-space
/// (effective modulus `E*`, yield stress `σ_Y`), with Thornton's yield onset:
/// `d_Y = (π p_Y/(2E*))² R`, `F_Y = (4/3) E* √R d_Y^(3/2)`, `a_Y = √(R d_Y)`.
///
/// Seed 000, eq. (5.102) (the chapter-3 relation (3.266) it rests on).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlasticContact {
    modulus: f64,
    radius: f64,
    yield_stress: f64,
    yield_depth: f64,
    yield_force: f64,
}

impl PlasticContact {
    /// A contact of effective modulus `E*` (Pa), effective radius `R` (m) and yield
    /// stress `σ_Y` (Pa) of the softer body, all finite and > 0, with `σ_Y < E*`.
    ///
    /// Seed 000, eq. (5.102).
    pub fn new(effective_modulus: f64, effective_radius: f64, yield_stress: f64) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let r = validate::positive("effective_radius", effective_radius)?;
        let s = validate::positive("yield_stress", yield_stress)?;
        if s >= e {
            return Err(Error::invalid(
                "yield_stress",
                s,
                "must be smaller than the effective modulus",
            ));
        }
        let strain = PI * LIMITING_PRESSURE_RATIO * s / (2.0 * e);
        let d_y = positive_output(MODEL, "yield depth d_Y", strain * strain * r)?;
        // F_Y = (4/3) E √R d_Y^(3/2) = (4/3) E R² strain³
        let f_y = positive_output(
            MODEL,
            "yield force F_Y",
            4.0 / 3.0 * e * strain * strain * strain * r * r,
        )?;
        positive_output(MODEL, "yield energy F_Y d_Y", f_y * d_y)?;
        Ok(PlasticContact {
            modulus: e,
            radius: r,
            yield_stress: s,
            yield_depth: d_y,
            yield_force: f_y,
        })
    }

    /// The effective modulus `E*` (Pa).
    ///
    /// Seed 000, `Ẽ` of (5.102).
    pub fn effective_modulus(&self) -> f64 {
        self.modulus
    }

    /// The effective radius `R` (m).
    ///
    /// Seed 000, `R̃` of (5.102).
    pub fn effective_radius(&self) -> f64 {
        self.radius
    }

    /// The yield stress `σ_Y` (Pa).
    ///
    /// Seed 000, `σ_f` of (5.102).
    pub fn yield_stress(&self) -> f64 {
        self.yield_stress
    }

    /// The indentation depth at first yield, `d_Y = (π p_Y/(2E*))² R` (m).
    ///
    /// Seed 000, eq. (5.102) (chapter 3, (3.266)).
    pub fn yield_depth(&self) -> f64 {
        self.yield_depth
    }

    /// The force at first yield, `F_Y = (4/3) E* √R d_Y^(3/2)` (N).
    ///
    /// Seed 000, eq. (5.102).
    pub fn yield_force(&self) -> f64 {
        self.yield_force
    }

    /// The contact radius at first yield, `a_Y = √(R d_Y)` (m).
    ///
    /// Seed 000, eq. (5.102) with the Hertz relation `a² = R d`.
    pub fn yield_contact_radius(&self) -> f64 {
        (self.radius * self.yield_depth).sqrt()
    }

    /// `F_Y d_Y = (4/3)(4π/5)⁵ (σ_Y/E*)⁵ E* R³` (J).
    ///
    /// Seed 000, eq. (5.102).
    pub fn yield_energy(&self) -> f64 {
        self.yield_force * self.yield_depth
    }

    /// The impact speed at which plastic deformation begins for effective mass `m`
    /// (kg, > 0): `v_Y² = (16/15)(4π/5)⁵ (σ_Y/E*)⁵ E* R³/m`, i.e. `m v_Y²/2 = (2/5) F_Y d_Y`.
    ///
    /// Seed 000, eq. (5.103).
    pub fn yield_velocity(&self, effective_mass: f64) -> Result<f64> {
        let m = validate::positive("effective_mass", effective_mass)?;
        positive_output(
            MODEL,
            "yield velocity v_Y",
            (0.8 * self.yield_energy() / m).sqrt(),
        )
    }
}

//! The bridge from tabor's impact models to penalty laws: take the restitution
//! ε(v0) that any [`ImpactModel`] (adhesive, plastic, viscoelastic) predicts at one
//! impact speed and produce a penalty law (stiffness and damping) that rebounds with
//! the same ε, verified by a time-domain simulation.

use crate::characteristic::{characteristic_loss_speed, ContactCharacteristic};
use crate::damped::{exact_damping_factor, DampedPowerLaw};
use crate::valid;
use serde::Serialize;
use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_elastic::ElasticContact;
use tabor_restitution::{impact, validate, Error, ImpactModel, Result};

/// The elastic part `K δⁿ` of a penalty law.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PenaltyStiffness {
    coefficient: f64,
    exponent: f64,
}

impl PenaltyStiffness {
    /// A user-given stiffness: `coefficient` K > 0 (N/mⁿ) and `exponent` n ∈ (0, 10].
    pub fn new(coefficient: f64, exponent: f64) -> Result<Self> {
        Ok(PenaltyStiffness {
            coefficient: validate::positive("stiffness", coefficient)?,
            exponent: valid::exponent(exponent)?,
        })
    }

    /// The Hertz contact of the same bodies, `K = (4/3) E* √R`, n = 3/2 (seed 000
    /// eq. (5.5), from `tabor_elastic::ElasticContact::hertz`), with `effective_modulus`
    /// E* (Pa) and `effective_radius` R (m).
    pub fn hertz(effective_modulus: f64, effective_radius: f64) -> Result<Self> {
        let contact = ElasticContact::hertz(effective_modulus, effective_radius)?;
        PenaltyStiffness::new(contact.force_coefficient(), contact.force_exponent())
    }

    /// K (N/mⁿ).
    pub fn coefficient(&self) -> f64 {
        self.coefficient
    }

    /// n.
    pub fn exponent(&self) -> f64 {
        self.exponent
    }
}

/// A penalty law calibrated against a model's restitution, with the simulated check.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Calibration<L> {
    /// The calibrated law.
    pub law: L,
    /// The name of the model it reproduces.
    pub model: String,
    /// The calibration speed v0 (m/s).
    pub impact_speed: f64,
    /// The model's effective mass (kg), used for the simulation.
    pub effective_mass: f64,
    /// The model's restitution at v0, seed 000 eq. (5.37).
    pub target_restitution: f64,
    /// The restitution of the calibrated law in a time-domain simulation
    /// (`tabor_dynamics::simulate_impact`) of the same mass at v0.
    pub achieved_restitution: f64,
    /// That simulation (trajectory not recorded).
    pub simulation: ImpactSimulation,
}

fn target<M: ImpactModel + ?Sized>(model: &M, impact_speed: f64) -> Result<(f64, f64, f64)> {
    let v0 = validate::positive("impact_speed", impact_speed)?;
    let outcome = impact(model, v0)?;
    let mass = validate::positive("effective_mass", model.effective_mass())?;
    if outcome.sticks || outcome.restitution <= 0.0 {
        return Err(Error::Model {
            model: "penalty calibration",
            message: format!(
                "{} sticks at impact_speed = {v0:e} m/s (restitution 0); a penalty law \
                 of this kind always rebounds",
                outcome.model
            ),
        });
    }
    Ok((v0, mass, outcome.restitution))
}

fn verified<M: ImpactModel + ?Sized, L: ForceLaw + Clone>(
    model: &M,
    law: L,
    v0: f64,
    mass: f64,
    target_restitution: f64,
    settings: &SimulationSettings,
) -> Result<Calibration<L>> {
    let settings = SimulationSettings {
        record_trajectory: false,
        ..*settings
    };
    let simulation = simulate_impact(&mut law.clone(), mass, v0, &settings)?;
    Ok(Calibration {
        law,
        model: model.name(),
        impact_speed: v0,
        effective_mass: mass,
        target_restitution,
        achieved_restitution: simulation.restitution,
        simulation,
    })
}

/// Calibrates the damping factor χ of `F = K δⁿ (1 + χ δ̇)` (Hunt & Crossley 1975
/// form) so that an impact at `impact_speed` v0 rebounds with `model`'s restitution
/// ε(v0) (seed 000 eq. (5.37)); the stiffness is `stiffness` (for example
/// [`PenaltyStiffness::hertz`] of the same bodies).
///
/// χ is the root of the law's exact first integral ([`exact_damping_factor`]), so it
/// does not depend on K, n or the mass; the law is then simulated with `settings`
/// and the model's effective mass, and the simulated restitution is reported as
/// [`Calibration::achieved_restitution`]. A model that sticks at v0 (ε = 0) is an
/// error: this law always rebounds.
pub fn calibrate_damped_law<M: ImpactModel + ?Sized>(
    model: &M,
    impact_speed: f64,
    stiffness: PenaltyStiffness,
    settings: &SimulationSettings,
) -> Result<Calibration<DampedPowerLaw>> {
    let (v0, mass, e) = target(model, impact_speed)?;
    let chi = exact_damping_factor(e, v0)?;
    let law = DampedPowerLaw::new(stiffness.coefficient, stiffness.exponent, chi)?;
    verified(model, law, v0, mass, e, settings)
}

/// Calibrates the loss speed V of seed 002's characteristic `F = k κ(h, ε) l(v, V)`
/// so that an impact at `impact_speed` v0 rebounds with `model`'s restitution ε(v0)
/// ([`characteristic_loss_speed`]; independent of k, the rounding and the mass),
/// with spring constant `stiffness` k (N/m) and `rounding` ε (m), and verifies it by
/// simulation as [`calibrate_damped_law`] does.
pub fn calibrate_characteristic<M: ImpactModel + ?Sized>(
    model: &M,
    impact_speed: f64,
    stiffness: f64,
    rounding: f64,
    settings: &SimulationSettings,
) -> Result<Calibration<ContactCharacteristic>> {
    let k = validate::positive("stiffness", stiffness)?;
    let eps = validate::non_negative("rounding", rounding)?;
    let (v0, mass, e) = target(model, impact_speed)?;
    let big_v = characteristic_loss_speed(e, v0)?;
    let law = ContactCharacteristic::new(k, eps, big_v)?;
    verified(model, law, v0, mass, e, settings)
}

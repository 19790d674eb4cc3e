//! Penalty contact laws for multibody codes (`tabor penalty`, `tabor.penalty`): the
//! parameters of the seed-002 contact characteristic or of a Hunt-Crossley,
//! Lankarani-Nikravesh or Flores law for a nominal restitution, and the restitution
//! the law actually achieves in a simulated impact.

use super::{Error, Naming};
pub use crate::penalty::PenaltyLaw;
use crate::penalty::{
    characteristic_loss_speed, exact_damping_factor, simulate_impact, ContactCharacteristic,
    DampedPowerLaw, ForceLaw, ImpactSimulation, SimulationSettings,
};
use serde::Serialize;

/// The inputs of `tabor penalty`, named like its flags.
#[derive(Clone, Copy, Debug)]
pub struct PenaltyArgs {
    /// The penalty law.
    pub law: PenaltyLaw,
    /// Nominal coefficient of restitution e, in (0, 1].
    pub restitution: f64,
    /// Stiffness K (N/m^n; N/m for the characteristic).
    pub stiffness: f64,
    /// Force exponent n of K δⁿ (default 1.5; the characteristic is linear).
    pub exponent: Option<f64>,
    /// Rounding half-width ε of the characteristic (m), ≥ 0.
    pub rounding: f64,
    /// Effective (reduced) mass m (kg).
    pub mass: f64,
    /// Impact speed v0 (m/s).
    pub speed: f64,
}

/// The result record of `tabor penalty`.
#[derive(Clone, Debug, Serialize)]
pub struct Penalty {
    /// The law's name.
    pub law: &'static str,
    /// The nominal restitution e.
    pub nominal_restitution: f64,
    /// From the simulated impact.
    pub achieved_restitution: f64,
    /// From the law's exact first integral.
    pub closed_form_restitution: f64,
    /// Stiffness K.
    pub stiffness: f64,
    /// Force exponent n.
    pub exponent: f64,
    /// Effective mass m (kg).
    pub effective_mass: f64,
    /// Impact speed v0 (m/s).
    pub impact_speed: f64,
    /// χ (s/m) of a damped power law.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping_factor: Option<f64>,
    /// The damping coefficient χ K (N s/m^(n+1)) of a damped power law.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping_coefficient: Option<f64>,
    /// The χ that would give the nominal restitution exactly.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact_damping_factor: Option<f64>,
    /// V (m/s); null when infinite (e = 1).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub loss_speed: Option<f64>,
    /// Rounding half-width ε (m) of the characteristic.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rounding: Option<f64>,
    /// Maximum overlap (m).
    pub max_overlap: f64,
    /// Maximum force (N).
    pub max_force: f64,
    /// Contact time (s), if contact ended.
    pub contact_time: Option<f64>,
    /// Relative energy error of the simulation.
    pub energy_error: f64,
}

fn simulate<L: ForceLaw>(law: &mut L, a: &PenaltyArgs) -> Result<ImpactSimulation, Error> {
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    };
    Ok(simulate_impact(law, a.mass, a.speed, &settings)?)
}

/// Validates `a` and computes the record of `tabor penalty`; an exponent other
/// than 1 for the characteristic is named in `naming`.
pub fn penalty(a: &PenaltyArgs, naming: Naming) -> Result<Penalty, Error> {
    let e = a.restitution;
    Ok(match a.law.damping_model() {
        None => {
            if let Some(n) = a.exponent {
                if n != 1.0 {
                    let value = match naming {
                        Naming::Flags => format!("{n}"),
                        Naming::Keywords => format!("{n:e}"),
                    };
                    return Err(Error::Input(format!(
                        "invalid {} = {value}: the contact characteristic is linear (n = 1)",
                        naming.input("exponent")
                    )));
                }
            }
            let big_v = characteristic_loss_speed(e, a.speed)?;
            let mut law = ContactCharacteristic::new(a.stiffness, a.rounding, big_v)?;
            let closed = law.restitution(a.speed)?;
            let sim = simulate(&mut law, a)?;
            Penalty {
                law: "numpedia contact characteristic",
                nominal_restitution: e,
                achieved_restitution: sim.restitution,
                closed_form_restitution: closed,
                stiffness: a.stiffness,
                exponent: 1.0,
                effective_mass: a.mass,
                impact_speed: a.speed,
                damping_factor: None,
                damping_coefficient: None,
                exact_damping_factor: None,
                loss_speed: big_v.is_finite().then_some(big_v),
                rounding: Some(a.rounding),
                max_overlap: sim.max_overlap,
                max_force: sim.max_force,
                contact_time: sim.contact_time,
                energy_error: sim.energy_error,
            }
        }
        Some(model) => {
            let n = a.exponent.unwrap_or(1.5);
            let mut law = DampedPowerLaw::from_model(model, a.stiffness, n, e, a.speed)?;
            let exact = exact_damping_factor(e, a.speed)?;
            let closed = law.restitution(a.speed)?;
            let sim = simulate(&mut law, a)?;
            Penalty {
                law: model.name(),
                nominal_restitution: e,
                achieved_restitution: sim.restitution,
                closed_form_restitution: closed,
                stiffness: law.stiffness(),
                exponent: law.exponent(),
                effective_mass: a.mass,
                impact_speed: a.speed,
                damping_factor: Some(law.damping_factor()),
                damping_coefficient: Some(law.damping_coefficient()),
                exact_damping_factor: Some(exact),
                loss_speed: None,
                rounding: None,
                max_overlap: sim.max_overlap,
                max_force: sim.max_force,
                contact_time: sim.contact_time,
                energy_error: sim.energy_error,
            }
        }
    })
}

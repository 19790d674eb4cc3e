//! The JKR adhesive impact of a sphere (`tabor jkr`, `tabor.jkr`): the adhesive
//! energy loss, the sticking velocity and, for a given impact speed, the maximum
//! contact radius and the coefficient of restitution.

use crate::jkr::{AdhesiveContact, JkrImpact, JkrSphere, SeparationRule};
use crate::restitution::{impact, sticking_velocity, Error, ImpactModel};
use serde::Serialize;

/// The inputs of `tabor jkr`, named like its flags. All are effective quantities
/// of the collision.
#[derive(Clone, Copy, Debug)]
pub struct JkrArgs {
    /// Effective modulus E* (Pa).
    pub modulus: f64,
    /// Effective radius R (m).
    pub radius: f64,
    /// Work of adhesion Δγ (J/m²).
    pub work_of_adhesion: f64,
    /// Effective (reduced) mass m (kg).
    pub mass: f64,
    /// Relative impact speed v0 (m/s); adds the maximum contact radius and the
    /// restitution.
    pub speed: Option<f64>,
    /// Where contact breaks.
    pub separation: SeparationRule,
    /// Relative tolerance of quadratures and root searches, in [1e-15, 0.5].
    pub tolerance: f64,
}

/// The result record of `tabor jkr`.
#[derive(Clone, Debug, Serialize)]
pub struct Jkr {
    /// The model's name.
    pub model: String,
    /// The branch of the loss computation.
    pub branch: String,
    /// Where contact breaks (the separation rule's name).
    pub separation: &'static str,
    /// |ΔU_kin| (J).
    pub energy_loss: f64,
    /// Error estimate of the energy loss (J).
    pub energy_loss_error: f64,
    /// v_c (m/s).
    pub sticking_velocity: f64,
    /// Force where contact breaks (N, negative: tensile).
    pub separation_force: f64,
    /// Contact radius where contact breaks (m).
    pub separation_contact_radius: f64,
    /// Contact radius at first touch (m).
    pub first_touch_contact_radius: f64,
    /// The impact speed (m/s), if given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impact_speed: Option<f64>,
    /// The maximum contact radius (m) at the impact speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_contact_radius: Option<f64>,
    /// The coefficient of restitution at the impact speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub restitution: Option<f64>,
    /// Whether the sphere sticks at the impact speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sticks: Option<bool>,
    /// Function evaluations spent on the loss (0 for the closed form).
    pub evaluations: u64,
}

/// Validates `args` and computes the record of `tabor jkr`.
pub fn jkr(args: &JkrArgs) -> Result<Jkr, Error> {
    let rule = args.separation;
    let sphere = JkrSphere::new(args.modulus, args.radius, args.work_of_adhesion)?;
    let model = JkrImpact::new(sphere, args.mass)?
        .with_separation(rule)
        .with_tolerance(args.tolerance)?;
    let loss = model.adhesive_energy_loss()?;
    let v_c = sticking_velocity(&model, args.tolerance.max(1e-15))?;
    let separation = sphere.critical_state(rule)?;
    let touch = sphere.first_touch()?;
    let (max_radius, outcome) = match args.speed {
        Some(v) => (Some(model.max_contact_radius(v)?), Some(impact(&model, v)?)),
        None => (None, None),
    };
    Ok(Jkr {
        model: ImpactModel::name(&model),
        branch: loss.branch.clone(),
        separation: rule.as_str(),
        energy_loss: loss.joules,
        energy_loss_error: loss.error_estimate,
        sticking_velocity: v_c.speed,
        separation_force: separation.force,
        separation_contact_radius: separation.contact_radius,
        first_touch_contact_radius: touch.contact_radius,
        impact_speed: args.speed,
        max_contact_radius: max_radius.map(|m| m.contact_radius),
        restitution: outcome.as_ref().map(|o| o.restitution),
        sticks: outcome.as_ref().map(|o| o.sticks),
        evaluations: loss.cost.evaluations,
    })
}

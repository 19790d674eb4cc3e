//! The JKR adhesive impact of a sphere (`tabor jkr`, `tabor.jkr`): the adhesive
//! energy loss, the sticking velocity and, for a given impact speed, the maximum
//! contact radius and the coefficient of restitution.

use crate::jkr::{AdhesiveContact, JkrImpact, JkrSphere, SeparationRule};
use crate::numerics::tolerance::FINEST_TOLERANCE;
use crate::restitution::{restitution_from_loss, sticking_velocity, Error, ImpactModel};
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
    let prepared = prepare(args)?;
    match args.speed {
        Some(v) => Ok(prepared.at_speed(v)?.completing(prepared.record.clone())),
        None => Ok(prepared.record),
    }
}

/// The speed-independent part of `tabor jkr` (everything but the impact speed's
/// fields), computed once for any number of impact speeds ([`JkrPrepared::at_speed`]):
/// a batch over speeds with the other inputs fixed pays for the model once.
#[derive(Clone, Debug)]
pub struct JkrPrepared {
    model: JkrImpact<JkrSphere>,
    record: Jkr,
}

/// The fields of the record of `tabor jkr` that depend on the impact speed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct JkrAtSpeed {
    /// The impact speed (m/s).
    pub impact_speed: f64,
    /// The maximum contact radius (m), seed 000 eq. (5.35).
    pub max_contact_radius: f64,
    /// The coefficient of restitution, seed 000 eq. (5.37).
    pub restitution: f64,
    /// Whether the sphere sticks (the loss reaches the kinetic energy).
    pub sticks: bool,
}

impl JkrAtSpeed {
    /// `record` with this speed's fields filled in.
    pub fn completing(self, record: Jkr) -> Jkr {
        Jkr {
            impact_speed: Some(self.impact_speed),
            max_contact_radius: Some(self.max_contact_radius),
            restitution: Some(self.restitution),
            sticks: Some(self.sticks),
            ..record
        }
    }
}

/// Validates `args` but the speed (which is ignored) and computes the
/// speed-independent part of the record of `tabor jkr`.
pub fn prepare(args: &JkrArgs) -> Result<JkrPrepared, Error> {
    let rule = args.separation;
    let sphere = JkrSphere::new(args.modulus, args.radius, args.work_of_adhesion)?;
    let model = JkrImpact::new(sphere, args.mass)?
        .with_separation(rule)
        .with_tolerance(args.tolerance)?;
    let loss = model.adhesive_energy_loss()?;
    let v_c = sticking_velocity(&model, args.tolerance.max(FINEST_TOLERANCE))?;
    let separation = sphere.critical_state(rule)?;
    let touch = sphere.first_touch()?;
    let record = Jkr {
        model: ImpactModel::name(&model),
        branch: loss.branch.clone(),
        separation: rule.as_str(),
        energy_loss: loss.joules,
        energy_loss_error: loss.error_estimate,
        sticking_velocity: v_c.speed,
        separation_force: separation.force,
        separation_contact_radius: separation.contact_radius,
        first_touch_contact_radius: touch.contact_radius,
        impact_speed: None,
        max_contact_radius: None,
        restitution: None,
        sticks: None,
        evaluations: loss.cost.evaluations,
    };
    Ok(JkrPrepared { model, record })
}

impl JkrPrepared {
    /// The record without the impact speed's fields.
    pub fn record(&self) -> &Jkr {
        &self.record
    }

    /// The fields of impact speed `v0` (m/s, > 0): the maximum contact radius of the
    /// energy balance (5.35) and the restitution (5.37) of the speed-independent
    /// loss (5.36), as [`impact`](crate::restitution::impact) gives it.
    pub fn at_speed(&self, v0: f64) -> Result<JkrAtSpeed, Error> {
        self.at_speed_near(v0, None)
    }

    /// [`JkrPrepared::at_speed`] with the maximum contact radius started from
    /// `near`'s (the fields of a nearby speed: a batch over sorted speeds); equal to
    /// the cold start's to the rounding of the last step.
    pub fn at_speed_near(&self, v0: f64, near: Option<&JkrAtSpeed>) -> Result<JkrAtSpeed, Error> {
        let max = self
            .model
            .max_contact_radius_near(v0, near.map(|n| n.max_contact_radius))?;
        let restitution =
            restitution_from_loss(self.record.energy_loss, self.model.effective_mass(), v0)?;
        Ok(JkrAtSpeed {
            impact_speed: v0,
            max_contact_radius: max.contact_radius,
            restitution,
            // ε = 0 exactly when the loss reaches m v0²/2 ((5.37), `impact`'s `sticks`)
            sticks: restitution == 0.0,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::restitution::impact;

    /// The split record is the record of `impact` (5.37) and of the contact's own
    /// energy balance (5.35), computed independently of `prepare`.
    #[test]
    fn at_speed_matches_impact_and_the_energy_balance() {
        let args = JkrArgs {
            modulus: 27.8e9,
            radius: 5e-7,
            work_of_adhesion: 0.05,
            mass: 5.55e-15,
            speed: None,
            separation: SeparationRule::FixedGrip,
            tolerance: 1e-12,
        };
        let sphere = JkrSphere::new(args.modulus, args.radius, args.work_of_adhesion).unwrap();
        let model = JkrImpact::new(sphere, args.mass).unwrap();
        let p = prepare(&args).unwrap();
        for v in [0.01, 0.0866, 0.1, 1.0, 30.0] {
            let s = p.at_speed(v).unwrap();
            let o = impact(&model, v).unwrap();
            assert_eq!(s.restitution, o.restitution, "v = {v}");
            assert_eq!(s.sticks, o.sticks, "v = {v}");
            let m = model.max_contact_radius(v).unwrap().contact_radius;
            assert_eq!(s.max_contact_radius, m, "v = {v}");
            let full = jkr(&JkrArgs {
                speed: Some(v),
                ..args
            })
            .unwrap();
            assert_eq!(full.restitution, Some(o.restitution));
            assert_eq!(full.model, o.model);
        }
        assert!(p.at_speed(0.01).unwrap().sticks && !p.at_speed(1.0).unwrap().sticks);
        assert!(p.at_speed(-1.0).is_err() && p.at_speed(f64::NAN).is_err());
    }
}

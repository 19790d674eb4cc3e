//! The oblique impact of a scene: [`Scene::oblique`], the impact simulated with
//! translation and rotation through the normal force law of the model the scene
//! selects (`tabor_tangential::oblique`), with the friction, angle and spins that
//! `friction.rs` validates.

use crate::combination::{EffectKind, Rule};
use crate::error::{impact_speed, SceneError};
use crate::friction::{check_angle, friction_of};
use crate::models::AdhesiveModel;
use crate::scene::Scene;
use crate::simulate::outcome_set;
use tabor_dynamics::{ForceLaw, SimulationSettings};
use tabor_maugis::MaugisDugdaleForceLaw;
use tabor_numerics::tolerance::SIMULATION_ACCURACY_FLOOR;
use tabor_restitution::{Error, Warning};
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact, ObliqueOutcome};
use tabor_tangential::{Friction, TangentialModel};

/// The oblique fields added to the central-impact ones.
#[derive(serde::Serialize)]
struct ObliqueFields<'a> {
    angle: f64,
    normal_restitution: f64,
    tangential_restitution: Option<f64>,
    rebound_angle: Option<f64>,
    energy_lost_by_mechanism: &'a tabor_tangential::oblique::EnergyLosses,
    after: &'a tabor_tangential::oblique::AfterImpact,
    oblique: ObliqueSummary<'a>,
}

#[derive(serde::Serialize)]
struct ObliqueSummary<'a> {
    law: &'a str,
    speed: f64,
    sticks: bool,
    energy_loss: f64,
    kinetic_energy: f64,
    energy_error: f64,
    contact_time: f64,
    slip_switches: usize,
    normal_turn: f64,
}

/// The turn of the line of centres (degrees) above which an oblique report warns
/// that the bodies rolled round each other: the rebound quantities are then read
/// in the final line of centres, far from the first-touch axes that the
/// small-turn literature (Maw-Barber-Fawcett, Thornton) uses.
pub const NORMAL_TURN_WARNING_DEGREES: f64 = 1.0;

/// The warnings of an oblique outcome beside its central one: a sticking
/// decision that differs from the central impact at the normal speed (code
/// `oblique-sticking`), and a line of centres that turned by more than
/// [`NORMAL_TURN_WARNING_DEGREES`] (code `normal-turn`).
fn oblique_warnings(o: &ObliqueOutcome, central: &crate::Outcome) -> Vec<Warning> {
    let mut warnings = Vec::new();
    if o.sticks != central.sticks {
        let (oblique, normal) = if o.sticks {
            ("sticks", "rebounds")
        } else {
            ("separates", "sticks")
        };
        warnings.push(Warning {
            code: "oblique-sticking",
            message: format!(
                "the oblique simulation {oblique}, while the central impact at the normal speed \
                 v cos α (the fields restitution, sticks, energy_loss) {normal}: the tangential \
                 motion decides (see oblique.sticks and normal_restitution)"
            ),
        });
    }
    if o.normal_turn > NORMAL_TURN_WARNING_DEGREES {
        warnings.push(Warning {
            code: "normal-turn",
            message: format!(
                "the line of centres turned by {:.3}° during the contact (the bodies rolled \
                 round each other): normal_restitution, tangential_restitution and \
                 rebound_angle are read in the final line of centres",
                o.normal_turn
            ),
        });
    }
    warnings
}

impl Scene {
    /// The scene's friction (`[friction]`), validated; `None` without the section.
    pub fn friction(&self) -> Result<Option<Friction>, SceneError> {
        friction_of(&self.data)
    }

    /// The impact angle of the scene file (`[impact] angle`, degrees), if given.
    pub fn angle(&self) -> Option<f64> {
        self.data.impact.as_ref().and_then(|i| i.angle)
    }

    /// True when the scene asks for an oblique impact: a `[friction]` section, a
    /// non-zero `[impact] angle` or an initial spin.
    pub fn is_oblique(&self) -> bool {
        let spin = self.data.impact.as_ref().is_some_and(|i| {
            i.sphere_spin.is_some_and(|s| s != [0.0; 3])
                || i.target_spin.is_some_and(|s| s != [0.0; 3])
        });
        self.data.friction.is_some() || self.angle().is_some_and(|a| a != 0.0) || spin
    }

    /// The oblique impact at relative speed `speed` (m/s) and angle `angle`
    /// (degrees, [0, 90)), simulated with translation and rotation
    /// (`tabor_tangential::oblique`) through the normal force law of the model the
    /// scene selects at the normal speed `v cos α`, with the scene's adhesion even
    /// where the central loss finds it negligible (it sets the friction limits
    /// and the contact at first touch) (Hertz, JKR with the scene's
    /// separation rule, Maugis-Dugdale, the elasto-plastic laws, the
    /// viscous-adhesive model with its Kuwabara-Kono damping, and any of these with
    /// the scene's `[damping]`: its normal damping `c a^β ḋ`, β = 1 for
    /// `viscoelastic`, 1/2 for the Tsuji form), with the scene's
    /// friction (none: frictionless) and initial spins. Combinations that are sums
    /// of losses without a force law are refused with a message naming them.
    ///
    /// The Coulomb limits use `F_n0` of `tabor_tangential::critical_force`: the
    /// pull-off force is `(3/2)π w R` for JKR and, for Maugis-Dugdale, the most
    /// tensile force on its impact branch.
    pub fn oblique(&self, speed: f64, angle: f64) -> Result<ObliqueOutcome, SceneError> {
        let v = impact_speed(speed)?;
        let alpha = check_angle(angle).map_err(SceneError::model)?;
        let normal_speed = v * alpha.to_radians().cos();
        let prepared = self.prepared()?;
        let mut outcome = prepared.outcome_at(normal_speed)?;
        // the law of every effect the oblique impact needs (adhesion kept where
        // the central loss found it negligible: it sets the friction limits)
        outcome.combination = prepared.oblique_combination(&outcome.combination, normal_speed)?;
        let rule = outcome.combination.rule;
        let models = prepared.models();
        let adhesive = outcome.combination.effects.contains(&EffectKind::Adhesion);
        let err = SceneError::model;
        let (mut law, (damping, damping_exponent)): (Box<dyn ForceLaw>, (f64, f64)) = match rule {
            Rule::ViscousAdhesive => {
                let m = models
                    .viscous_adhesive
                    .as_ref()
                    .ok_or_else(|| SceneError::field("scene", "no viscous-adhesive model"))?;
                let law = m.force_law();
                (
                    Box::new(law.inner().clone()),
                    (2.0 * m.contact_viscosity(), 1.0),
                )
            }
            Rule::Damped => {
                let (law, damping) = models.damped_parts(&outcome_set(&outcome))?;
                (law, damping.power_law(self.effective_mass))
            }
            Rule::AdhesiveInterpolation
            | Rule::AdhesivePlasticExcess
            | Rule::Superposition
            | Rule::SuperpositionBound => {
                return Err(SceneError::model(Error::Model {
                    model: "oblique impact",
                    message: format!(
                        "the {} rule has no force law with a known pull-off force for the \
                         friction limit (it is a loss-level combination): no oblique impact",
                        rule.as_str()
                    ),
                }))
            }
            _ => (prepared.force_law(&outcome)?, (0.0, 1.0)),
        };
        let pull_off_force = if adhesive || rule == Rule::ViscousAdhesive {
            // the adhesive interpolation law's pull-off is its JKR one
            match models.adhesive.as_ref().map(|a| &a.model) {
                Some(AdhesiveModel::Jkr(_)) | None => {
                    let w = self.adhesion.as_ref().map_or(0.0, |a| a.work_of_adhesion);
                    1.5 * std::f64::consts::PI * w * self.effective_radius
                }
                Some(AdhesiveModel::Maugis(md, _)) => maugis_pull_off(md).map_err(err)?,
                Some(AdhesiveModel::Graded(_)) => {
                    return Err(SceneError::model(Error::Model {
                        model: "oblique impact",
                        message: "JKR on a graded medium has no force law".into(),
                    }))
                }
            }
        } else {
            0.0
        };
        let sphere_body = |radius: Option<f64>, mass: Option<f64>| -> Result<Body, SceneError> {
            match (radius, mass) {
                (Some(r), Some(m)) => Body::sphere(r, m, 0.4 * m * r * r).map_err(err),
                (Some(r), None) => Ok(Body {
                    radius: r,
                    mass: f64::INFINITY,
                    moment_of_inertia: f64::INFINITY,
                }),
                _ => Ok(Body::flat()),
            }
        };
        let sphere = sphere_body(self.sphere.radius, self.sphere.mass)?;
        let target = sphere_body(self.target.radius, self.target.mass)?;
        let impact = self.data.impact.clone().unwrap_or_default();
        let problem = ObliqueImpact {
            sphere,
            target,
            normal: NormalContact {
                pull_off_force,
                damping,
                damping_exponent,
            },
            friction: self.friction()?,
            sphere_spin: impact.sphere_spin.unwrap_or([0.0; 3]),
            target_spin: impact.target_spin.unwrap_or([0.0; 3]),
        };
        let settings =
            SimulationSettings::with_tolerance(self.accuracy.max(SIMULATION_ACCURACY_FLOOR))
                .map_err(err)?;
        problem
            .simulate(law.as_mut(), v, alpha, &settings)
            .map_err(err)
    }

    /// The report of `tabor impact --json` (and Python's `Scene.outcome`) at
    /// relative speed `speed` (m/s) and angle `angle` (degrees): `None` for a
    /// central impact without friction or spin (angle 0, not
    /// [`Scene::is_oblique`]: today's outcome answers), else the central-impact
    /// fields of the normal speed `v cos α` plus `angle`, `normal_restitution`,
    /// `tangential_restitution`, `rebound_angle`, `energy_lost_by_mechanism`,
    /// `after` (CoM frame, SI) and `oblique` (law, energy error, contact time,
    /// stick/slip switches), with the central outcome for its warnings.
    pub fn oblique_report(
        &self,
        speed: f64,
        angle: f64,
    ) -> Result<Option<(serde_json::Value, crate::Outcome)>, SceneError> {
        if angle == 0.0 && !self.is_oblique() {
            return Ok(None);
        }
        let o = self.oblique(speed, angle)?;
        let mut central = self.outcome_at(speed * angle.to_radians().cos())?;
        central.warnings.extend(self.oblique_accuracy_warning());
        central.warnings.extend(oblique_warnings(&o, &central));
        let json = |e: serde_json::Error| SceneError::field("scene", e.to_string());
        let mut value = serde_json::to_value(&central).map_err(json)?;
        let extra = serde_json::to_value(ObliqueFields {
            angle: o.angle,
            normal_restitution: o.normal_restitution,
            tangential_restitution: o.tangential_restitution,
            rebound_angle: o.rebound_angle,
            energy_lost_by_mechanism: &o.losses,
            after: &o.after,
            oblique: ObliqueSummary {
                law: &o.law,
                speed: o.speed,
                sticks: o.sticks,
                energy_loss: o.energy_loss,
                kinetic_energy: o.kinetic_energy,
                energy_error: o.energy_error,
                contact_time: o.contact_time,
                slip_switches: o.slip_switches,
                normal_turn: o.normal_turn,
            },
        })
        .map_err(json)?;
        if let (Some(map), serde_json::Value::Object(more)) = (value.as_object_mut(), extra) {
            map.extend(more);
        }
        Ok(Some((value, central)))
    }
}

/// The Maugis-Dugdale pull-off force of the impact branch (N, a magnitude),
/// `MaugisDugdaleForceLaw::pull_off_force`, the plugin's too.
fn maugis_pull_off(md: &tabor_maugis::MaugisDugdaleImpact) -> Result<f64, Error> {
    MaugisDugdaleForceLaw::new(md)?.pull_off_force()
}

impl Scene {
    /// The warnings of an oblique impact ([`Scene::oblique`]) when the scene's
    /// `accuracy` is finer than the simulation resolves
    /// (`tabor_numerics::tolerance::SIMULATION_ACCURACY_FLOOR`, 1e-13) or, with
    /// `mindlin_deresiewicz`, than its spring bed does (`MICRO_SLIP_RESOLUTION`,
    /// 1e-4): the oblique reports carry them with the central outcome's warnings.
    pub fn oblique_accuracy_warning(&self) -> Vec<Warning> {
        let micro_slip = self
            .friction()
            .ok()
            .flatten()
            .is_some_and(|f| f.tangential.model == TangentialModel::MindlinDeresiewicz);
        crate::floors::oblique_floors(self.accuracy, micro_slip)
    }
}

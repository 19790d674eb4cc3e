//! The oblique impact of a scene: the `[friction]` section, `[impact] angle` and
//! the initial spins, and [`Scene::oblique`], the impact simulated with translation
//! and rotation through the normal force law of the model the scene selects
//! (`tabor_tangential::oblique`).

use crate::combination::{EffectKind, Rule};
use crate::error::{impact_speed, SceneError};
use crate::file::{FrictionFile, SceneFile, TwistingFile};
use crate::models::AdhesiveModel;
use crate::scene::Scene;
use tabor_dynamics::{ForceLaw, SimulationSettings};
use tabor_maugis::MaugisDugdaleForceLaw;
use tabor_restitution::{validate, Error};
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact, ObliqueOutcome};
use tabor_tangential::{
    EffectiveShear, Friction, Rolling, Tangential, TangentialModel, Twisting, TwistingModel,
};

fn field_error(field: &str) -> impl Fn(Error) -> SceneError + '_ {
    move |e| SceneError::field_model(field.to_string(), e)
}

/// The validated friction of scene data (`None` without a `[friction]` section),
/// with the Mindlin stiffness `8 G*` from the bodies' materials unless
/// `tangential_stiffness` is given.
pub(crate) fn friction_of(data: &SceneFile) -> Result<Option<Friction>, SceneError> {
    let Some(f) = &data.friction else {
        return Ok(None);
    };
    let model = match &f.tangential {
        None => TangentialModel::Mindlin,
        Some(name) => name
            .parse::<TangentialModel>()
            .map_err(|e| SceneError::field("friction.tangential", e.to_string()))?,
    };
    let stiffness = match (model, f.tangential_stiffness) {
        (_, Some(k)) => k,
        (TangentialModel::LinearHistory, None) => {
            return Err(SceneError::field(
                "friction.tangential_stiffness",
                "is required for linear_history (N/m)",
            ))
        }
        (_, None) => 8.0 * shear_of(data)?.modulus(),
    };
    let tangential = Tangential::new(
        model,
        stiffness,
        f.tangential_damping.unwrap_or(0.0),
        f.coefficient,
    )
    .map_err(|e| friction_field(f, e))?;
    let mut friction = Friction::sliding(tangential);
    if let Some(r) = &f.rolling {
        friction = friction.with_rolling(
            Rolling::sds(r.stiffness, r.damping.unwrap_or(0.0), r.coefficient)
                .map_err(field_error("friction.rolling"))?,
        );
    }
    friction.twisting = match &f.twisting {
        None => None,
        Some(TwistingFile::Name(name)) => {
            match name
                .parse::<TwistingModel>()
                .map_err(|e| SceneError::field("friction.twisting", e.to_string()))?
            {
                TwistingModel::Marshall => Some(Twisting::Marshall),
                TwistingModel::Sds => {
                    return Err(SceneError::field(
                        "friction.twisting",
                        "sds needs { stiffness, damping, coefficient }",
                    ))
                }
            }
        }
        Some(TwistingFile::Sds(t)) => Some(
            Twisting::sds(t.stiffness, t.damping.unwrap_or(0.0), t.coefficient)
                .map_err(field_error("friction.twisting"))?,
        ),
    };
    Ok(Some(friction))
}

fn friction_field(f: &FrictionFile, e: Error) -> SceneError {
    let field = match &e {
        Error::InvalidParameter { parameter, .. } if *parameter == "coefficient" => {
            "friction.coefficient"
        }
        Error::InvalidParameter { parameter, .. } if *parameter == "tangential_damping" => {
            "friction.tangential_damping"
        }
        _ if f.tangential_stiffness.is_some() => "friction.tangential_stiffness",
        _ => "friction",
    };
    SceneError::field_model(field, e)
}

/// G* of the two bodies (Mindlin), the flat of its own material.
fn shear_of(data: &SceneFile) -> Result<EffectiveShear, SceneError> {
    EffectiveShear::of_pair(
        data.sphere.youngs_modulus,
        data.sphere.poisson_ratio,
        data.target.youngs_modulus,
        data.target.poisson_ratio,
    )
    .map_err(field_error("friction"))
}

/// Checks the oblique keys of scene data (for the load-time validation).
pub(crate) fn validate_data(data: &SceneFile) -> Result<(), SceneError> {
    friction_of(data)?;
    if let Some(i) = &data.impact {
        if let Some(a) = i.angle {
            check_angle(a).map_err(|e| SceneError::field("impact.angle", e.to_string()))?;
        }
        for (name, spin) in [
            ("impact.sphere_spin", i.sphere_spin),
            ("impact.target_spin", i.target_spin),
        ] {
            if let Some(s) = spin {
                for v in s {
                    validate::finite("spin", v).map_err(field_error(name))?;
                }
            }
        }
    }
    Ok(())
}

fn check_angle(angle: f64) -> Result<f64, Error> {
    if angle.is_finite() && (0.0..90.0).contains(&angle) {
        Ok(angle)
    } else {
        Err(Error::invalid(
            "angle",
            angle,
            "must be in [0, 90) degrees between the relative velocity and the line of centres",
        ))
    }
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
    /// scene selects at the normal speed `v cos α` (Hertz, JKR with the scene's
    /// separation rule, Maugis-Dugdale, the elasto-plastic laws, the
    /// viscous-adhesive model with its Kuwabara-Kono damping), with the scene's
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
        let outcome = prepared.outcome_at(normal_speed)?;
        let rule = outcome.combination.rule;
        let models = prepared.models();
        let adhesive = outcome.combination.effects.contains(&EffectKind::Adhesion);
        let err = SceneError::model;
        let (mut law, damping): (Box<dyn ForceLaw>, f64) = match rule {
            Rule::ViscousAdhesive => {
                let m = models
                    .viscous_adhesive
                    .as_ref()
                    .ok_or_else(|| SceneError::field("scene", "no viscous-adhesive model"))?;
                let law = m.force_law();
                (Box::new(law.inner().clone()), 2.0 * law.contact_viscosity())
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
            _ => (prepared.force_law(&outcome)?, 0.0),
        };
        let pull_off_force = if adhesive || rule == Rule::ViscousAdhesive {
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
            },
            friction: self.friction()?,
            sphere_spin: impact.sphere_spin.unwrap_or([0.0; 3]),
            target_spin: impact.target_spin.unwrap_or([0.0; 3]),
        };
        let settings = SimulationSettings::with_tolerance(self.accuracy.max(1e-9)).map_err(err)?;
        problem
            .simulate(law.as_mut(), v, alpha, &settings)
            .map_err(err)
    }
}

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
}

impl Scene {
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
        let central = self.outcome_at(speed * angle.to_radians().cos())?;
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

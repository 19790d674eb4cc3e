//! The outcome of a scene at one speed: restitution, sticking, losses, the effects
//! used and skipped, the combination rule and the warnings.

use crate::combination::{Combination, EffectKind, Rule};
use crate::models::{err, AdhesiveModel, Plastic};
use crate::scene::{Scene, SceneError};
use crate::select::{is_superposed, Prepared, Selection};
use serde::Serialize;
use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_elastic::ElasticContact;
use tabor_jkr::JkrForceLaw;
use tabor_maugis::MaugisDugdaleForceLaw;
use tabor_numerics::Cost;
use tabor_restitution::checks::{elastic_limit_check, quasi_static_check};
use tabor_restitution::{restitution_from_loss, Error, ImpactModel, Warning};

/// One physical effect and whether the scene uses it at the impact speed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Effect {
    /// The effect.
    pub name: EffectKind,
    /// Whether the effect enters the result.
    pub used: bool,
    /// Why it is used or skipped.
    pub reason: String,
    /// The model computing it (when its parameters are given).
    pub model: Option<String>,
    /// Its share of the total loss (J), when the total is a sum of the effects'
    /// losses (the shares add up to the total); `None` when the effects are coupled
    /// (their loss is not a sum) or the effect is not used.
    pub energy_loss: Option<f64>,
}

/// The result of a scene at one impact speed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Outcome {
    /// The scene's name.
    pub scene: String,
    /// Impact speed (m/s).
    pub impact_speed: f64,
    /// Coefficient of restitution (5.37).
    pub restitution: f64,
    /// Whether the bodies stick (ε = 0; equivalently the speed is below the
    /// sticking velocity).
    pub sticks: bool,
    /// The sticking velocity (m/s) of the scene's model: the root of ε(v) = 0 of
    /// the model that answers at each speed; `None` when the bodies never stick.
    pub sticking_velocity: Option<f64>,
    /// Kinetic energy lost (J), total (at most the kinetic energy).
    pub energy_loss: f64,
    /// Kinetic energy before impact (J).
    pub kinetic_energy: f64,
    /// The model that produced the result.
    pub model: String,
    /// The formula or branch inside that model.
    pub branch: String,
    /// The rule that combined the effects, and its source.
    pub combination: Combination,
    /// The Tabor parameter Λ, when the interface has a range.
    pub tabor_parameter: Option<f64>,
    /// Effects used and skipped, with their reasons and shares of the loss.
    pub effects: Vec<Effect>,
    /// The requested relative accuracy.
    pub accuracy: f64,
    /// Estimated absolute error of the energy loss (J).
    pub energy_loss_error: f64,
    /// Work spent: evaluations and iterations.
    pub cost: Cost,
    /// Validity warnings.
    pub warnings: Vec<Warning>,
}

fn effect_list(prepared: &Prepared, selection: &Selection) -> Vec<Effect> {
    let models = &prepared.models;
    let scene = prepared.scene;
    let mut effects = vec![Effect {
        name: EffectKind::Elasticity,
        used: true,
        reason: "always: the elastic contact carries the load; it loses no energy".into(),
        model: Some(models.elastic.name()),
        energy_loss: Some(0.0),
    }];
    let given: [(EffectKind, Option<String>, Option<String>, &str); 3] = [
        (
            EffectKind::Adhesion,
            models.adhesive.as_ref().map(|a| a.model.model().name()),
            models.adhesive.as_ref().map(|a| a.why.clone()),
            match &scene.adhesion {
                None => "no [adhesion] section: the surfaces do not adhere",
                Some(_) => "the work of adhesion is 0",
            },
        ),
        (
            EffectKind::Plasticity,
            models.plastic.as_ref().map(|p| p.model().name()),
            models
                .plastic
                .as_ref()
                .map(|_| "yield stress given".to_string()),
            "no yield_stress given: the bodies stay elastic",
        ),
        (
            EffectKind::Viscoelasticity,
            models.visco.as_ref().map(|v| v.model.name()),
            models.visco.as_ref().map(|v| v.why.clone()),
            "no viscosity given",
        ),
    ];
    for (kind, model, why, absent) in given {
        let Some(model) = model else {
            effects.push(Effect {
                name: kind,
                used: false,
                reason: absent.into(),
                model: None,
                energy_loss: None,
            });
            continue;
        };
        if let Some(d) = selection.dropped.iter().find(|d| d.effect == kind) {
            effects.push(Effect {
                name: kind,
                used: false,
                reason: d.reason.clone(),
                model: Some(model),
                energy_loss: None,
            });
            continue;
        }
        let share = selection
            .evaluation
            .parts
            .iter()
            .find(|(k, _)| *k == kind)
            .and_then(|(_, l)| *l);
        let coupled = if share.is_none() {
            format!(
                "; coupled in the {} model",
                selection.evaluation.rule.as_str()
            )
        } else {
            String::new()
        };
        effects.push(Effect {
            name: kind,
            used: true,
            reason: format!("{}{coupled}", why.unwrap_or_default()),
            model: Some(model),
            energy_loss: share,
        });
    }
    effects
}

/// The superposition's warning: which effects are added, and its measured error
/// against a coupled reference where one exists.
fn superposition_warning(prepared: &Prepared, selection: &Selection, speed: f64) -> Warning {
    let models = &prepared.models;
    let used = &selection.used;
    let mut message = format!(
        "the losses of {} are added (superposition (5.109))",
        selection
            .combination()
            .effects
            .iter()
            .map(|e| e.as_str())
            .collect::<Vec<_>>()
            .join(" and ")
    );
    let reference = match (used.adhesion, used.plasticity, used.viscoelasticity) {
        (Some(_), Some(_), None) => models.adhesive_interpolation.as_ref().map(|ai| {
            (
                ai.energy_loss(speed).map(|l| l.joules),
                "the adhesive interpolation model (5.111)-(5.126)",
            )
        }),
        _ => None,
    };
    match reference {
        Some((Ok(coupled), name)) if coupled > 0.0 => {
            let total = selection.evaluation.loss.joules;
            message.push_str(&format!(
                "; against {name} at this speed its loss differs by {:+.3e} relative ({total:e} J vs {coupled:e} J)",
                total / coupled - 1.0
            ));
        }
        _ => message
            .push_str("; no coupled model exists for this combination, so its error is unknown"),
    }
    Warning {
        code: "superposed-losses",
        message,
    }
}

fn viscous_adhesive_remark(prepared: &Prepared, speed: f64) -> Option<Warning> {
    let s = prepared
        .models
        .viscous_adhesive
        .as_ref()?
        .superposition(speed)
        .ok()?;
    Some(Warning {
        code: "coupled-model",
        message: format!(
            "adhesion + viscoelasticity by the coupled model (ours, tabor-viscoadhesive); the superposition (5.109) of the adhesive and Kuwabara-Kono losses would differ from it by {:+.3e} of the kinetic energy (restitution {:.6} vs {:.6})",
            -s.relative_difference, s.restitution_superposed, s.restitution_coupled
        ),
    })
}

impl Prepared<'_> {
    /// The outcome at `speed` (validated, > 0).
    pub(crate) fn outcome_at(&self, speed: f64) -> Result<Outcome, SceneError> {
        let scene = self.scene;
        let v = tabor_restitution::validate::positive("speed", speed)
            .map_err(|e| SceneError::field("impact.speed", e.to_string()))?;
        let selection = self.select(v)?;
        let m = self.models.mass;
        let kinetic = 0.5 * m * v * v;
        let joules = tabor_restitution::validate::non_negative(
            "energy_loss",
            selection.evaluation.loss.joules,
        )
        .map_err(err)?;
        let restitution = restitution_from_loss(joules, m, v).map_err(err)?;
        let (sticking, sticking_cost) = self.sticking()?;
        let mut warnings = Vec::new();
        if let Some((e, rho)) = scene.wave_speed_body() {
            if let Some(w) = quasi_static_check(v, e, rho).map_err(err)?.warning() {
                warnings.push(w);
            }
            if let Some(vc) = sticking {
                if let Some(w) = quasi_static_check(vc, e, rho).map_err(err)?.warning() {
                    warnings.push(Warning {
                        code: "sticking-velocity-not-quasi-static",
                        message: format!(
                            "the sticking velocity {vc:e} m/s is not small against the elastic wave speed: {}",
                            w.message
                        ),
                    });
                }
            }
        }
        if let (Some(sy), false) = (scene.yield_stress(), selection.used.plasticity.is_some()) {
            let check =
                elastic_limit_check(scene.effective_modulus, scene.effective_radius, m, v, sy)
                    .map_err(err)?;
            if let Some(w) = check.warning() {
                warnings.push(w);
            }
        }
        if is_superposed(selection.evaluation.rule) {
            warnings.push(superposition_warning(self, &selection, v));
        }
        if selection.evaluation.rule == Rule::ViscousAdhesive {
            warnings.extend(viscous_adhesive_remark(self, v));
        }
        let effects = effect_list(self, &selection);
        let combination = selection.combination();
        let e = selection.evaluation;
        Ok(Outcome {
            scene: scene.name.clone(),
            impact_speed: v,
            restitution,
            sticks: restitution == 0.0,
            sticking_velocity: sticking,
            energy_loss: joules.min(kinetic),
            kinetic_energy: kinetic,
            model: e.model,
            branch: e.loss.branch,
            combination,
            tabor_parameter: scene.tabor_parameter(),
            effects,
            accuracy: scene.accuracy,
            energy_loss_error: e.loss.error_estimate,
            cost: e.loss.cost + sticking_cost,
            warnings,
        })
    }

    /// The loss (J) when it does not depend on the speed (elastic adhesion alone,
    /// [`SceneModel`](crate::select::SceneModel)), else `None`.
    pub(crate) fn constant_loss(&self) -> Result<Option<f64>, SceneError> {
        use tabor_restitution::ImpactModel;
        let whole = crate::select::SceneModel { prepared: self };
        if !whole.loss_is_speed_independent() {
            return Ok(None);
        }
        let reference = whole.speed_scale();
        Ok(Some(
            self.models
                .evaluate(&self.models.candidates, reference)
                .map_err(|e| self.scene.locate(e))?
                .loss
                .joules,
        ))
    }

    /// The restitution at `speed` for the speed-independent loss `loss` (J): what
    /// [`Prepared::restitution`] computes, without re-evaluating the model. The
    /// selection's rule: a loss below `accuracy` × the kinetic energy is dropped.
    pub(crate) fn restitution_with_constant_loss(
        &self,
        loss: f64,
        speed: f64,
    ) -> Result<f64, SceneError> {
        let kinetic = 0.5 * self.models.mass * speed * speed;
        if !(speed > 0.0 && kinetic.is_finite() && kinetic > 0.0) {
            // the full path reports the exact error
            return self.restitution(speed);
        }
        if loss.abs() < self.models.accuracy * kinetic {
            return Ok(1.0);
        }
        restitution_from_loss(loss, self.models.mass, speed).map_err(err)
    }

    /// The restitution at `speed`, without the outcome's reports.
    pub(crate) fn restitution(&self, speed: f64) -> Result<f64, SceneError> {
        Ok(self.restitution_with_error(speed)?.0)
    }

    /// The restitution at `speed` and the estimated error of the loss as a
    /// fraction of the kinetic energy (the error of 1 − ε²).
    pub(crate) fn restitution_with_error(&self, speed: f64) -> Result<(f64, f64), SceneError> {
        let v = tabor_restitution::validate::positive("speed", speed)
            .map_err(|e| SceneError::field("impact.speed", e.to_string()))?;
        let selection = self.select(v)?;
        let loss = &selection.evaluation.loss;
        let kinetic = 0.5 * self.models.mass * v * v;
        Ok((
            restitution_from_loss(loss.joules, self.models.mass, v).map_err(err)?,
            loss.error_estimate / kinetic,
        ))
    }
}

impl Scene {
    /// The outcome at the scene's impact speed (an error names `impact.speed` when
    /// the scene has none).
    pub fn outcome(&self) -> Result<Outcome, SceneError> {
        let v = self
            .speed
            .ok_or_else(|| SceneError::field("impact.speed", "is required for an impact (m/s)"))?;
        self.outcome_at(v)
    }

    /// The outcome at impact speed `speed` (m/s).
    pub fn outcome_at(&self, speed: f64) -> Result<Outcome, SceneError> {
        Prepared::new(self)?.outcome_at(speed)
    }

    /// The coefficient of restitution at `speed` (m/s) with the estimated error of
    /// the loss as a fraction of the kinetic energy (the error of 1 − ε²), without
    /// the outcome's sticking velocity and reports.
    pub fn restitution_with_error(&self, speed: f64) -> Result<(f64, f64), SceneError> {
        Prepared::new(self)?.restitution_with_error(speed)
    }

    /// The combination (rule and effects used) that answers at impact speed `speed`
    /// (m/s), without computing the outcome's sticking velocity.
    pub fn combination_at(&self, speed: f64) -> Result<Combination, SceneError> {
        let v = tabor_restitution::validate::positive("speed", speed)
            .map_err(|e| SceneError::field("impact.speed", e.to_string()))?;
        Ok(Prepared::new(self)?.select(v)?.combination())
    }

    /// The sticking velocity (m/s) of the scene's model (the root of ε(v) = 0 of the
    /// model that answers at each speed), or `None` when the bodies never stick.
    pub fn sticking_velocity(&self) -> Result<Option<f64>, SceneError> {
        Ok(Prepared::new(self)?.sticking()?.0)
    }

    /// Simulates the impact at `speed` in the time domain with the force law of the
    /// model the scene selects at that speed, and returns the simulation with the
    /// analytic outcome of the same model.
    pub fn simulate(
        &self,
        speed: f64,
        settings: &SimulationSettings,
    ) -> Result<(ImpactSimulation, Outcome), SceneError> {
        let prepared = Prepared::new(self)?;
        let outcome = prepared.outcome_at(speed)?;
        let models = &prepared.models;
        // the rule and the effects used at this speed, as the outcome reports them
        let rule = outcome.combination.rule;
        let uses = |effect| outcome.combination.effects.contains(&effect);
        let no_law = |what: &str| {
            SceneError::model(Error::Model {
                model: "scene",
                message: format!("no time-domain force law for {what}"),
            })
        };
        let mut law: Box<dyn ForceLaw> = match rule {
            Rule::Elastic => Box::new(match self.target.gradation {
                Some((k, c)) => {
                    ElasticContact::graded_sphere(c, k, self.effective_radius).map_err(err)?
                }
                None => ElasticContact::hertz(self.effective_modulus, self.effective_radius)
                    .map_err(err)?,
            }),
            Rule::Single if uses(EffectKind::Adhesion) => {
                match models.adhesive.as_ref().map(|a| &a.model) {
                    // the rule of the selected model (fixed grip when it stands in for
                    // Maugis-Dugdale)
                    Some(AdhesiveModel::Jkr(j)) => {
                        Box::new(JkrForceLaw::new(*j.contact(), j.separation()))
                    }
                    Some(AdhesiveModel::Maugis(md)) => {
                        Box::new(MaugisDugdaleForceLaw::new(md).map_err(err)?)
                    }
                    Some(AdhesiveModel::Graded(_)) => return Err(no_law("JKR on a graded medium")),
                    None => return Err(no_law("this scene")),
                }
            }
            Rule::Single if uses(EffectKind::Plasticity) => match &models.plastic {
                Some(Plastic::Thornton(p)) => Box::new(p.force_law()),
                Some(Plastic::Interpolation(p)) => Box::new(p.force_law()),
                Some(Plastic::JacksonGreen(_)) => Box::new(
                    tabor_plastic::PlasticContact::new(
                        self.effective_modulus,
                        self.effective_radius,
                        self.yield_stress().unwrap_or(f64::NAN),
                    )
                    .and_then(|contact| {
                        tabor_plastic::JacksonGreen::new(contact, self.plastic_poisson_ratio())
                    })
                    .map_err(err)?
                    .force_law(),
                ),
                _ => return Err(no_law("seed 001's dimensionless fit")),
            },
            Rule::AdhesiveInterpolation => match &models.adhesive_interpolation {
                Some(a) => Box::new(a.force_law()),
                None => return Err(no_law("this combination")),
            },
            Rule::ViscousAdhesive => crate::viscous_adhesive::force_law(models)?,
            Rule::Single => {
                return Err(no_law(
                    "the viscoelastic contact (its models are solved in scaled form by the MDR)",
                ))
            }
            Rule::AdhesivePlasticExcess | Rule::Superposition => {
                return Err(no_law(&format!(
                    "the {} rule (a sum of losses, not of forces)",
                    rule.as_str()
                )))
            }
        };
        let sim =
            simulate_impact(law.as_mut(), self.effective_mass, speed, settings).map_err(err)?;
        Ok((sim, outcome))
    }
}

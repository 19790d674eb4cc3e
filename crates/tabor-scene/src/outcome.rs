//! The outcome of a scene at one speed: restitution, sticking, losses, the effects
//! used and skipped, the combination rule and the warnings.

use crate::combination::{Combination, EffectKind, Rule};
use crate::error::SceneError;
use crate::select::{is_superposed, Prepared, Selection, Sticking};
use serde::Serialize;
use tabor_numerics::Cost;
use tabor_restitution::checks::{elastic_limit_check, quasi_static_check};
use tabor_restitution::{restitution_from_loss, ImpactModel, Warning};

fn err(e: tabor_restitution::Error) -> SceneError {
    SceneError::model(e)
}

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
    /// (their loss is not a sum) or the effect is not used. When the bodies stick
    /// the whole kinetic energy is lost and the effects' losses add up to more: each
    /// share is then its loss scaled by (kinetic energy)/(sum of the losses), a
    /// proportional split.
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

fn effect_list(prepared: &Prepared, selection: &Selection, kinetic: f64) -> Vec<Effect> {
    let models = prepared.models();
    // sticking: the effects' losses exceed the kinetic energy, all of which is
    // lost; split it in proportion to them
    let total = selection.evaluation.loss.joules;
    let split = if total > kinetic {
        kinetic / total
    } else {
        1.0
    };
    let inputs = prepared.inputs();
    let mut effects = vec![Effect {
        name: EffectKind::Elasticity,
        used: true,
        reason: "always: the elastic contact carries the load; it loses no energy".into(),
        model: Some(models.elastic.name()),
        energy_loss: Some(0.0),
    }];
    let given: [(EffectKind, Option<String>, Option<String>, &str); 4] = [
        (
            EffectKind::Adhesion,
            models.adhesive.as_ref().map(|a| a.model.model().name()),
            models.adhesive.as_ref().map(|a| a.why.clone()),
            match &inputs.adhesion {
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
        (
            EffectKind::Damping,
            models.damped.as_ref().map(|d| d.damping.describe()),
            models.damped.as_ref().map(|_| {
                "[damping]: a DEM damping law (LAMMPS pair granular) on the scene's force law"
                    .to_string()
            }),
            "no [damping] section",
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
            .and_then(|(_, l)| *l)
            .map(|l| l * split);
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
    let models = prepared.models();
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
        .models()
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
    /// The outcome at `v` (a validated speed, m/s).
    pub(crate) fn outcome_at(&self, v: f64) -> Result<Outcome, SceneError> {
        let scene = self.inputs();
        let selection = self.select(v)?;
        let m = self.models().mass;
        let kinetic = 0.5 * m * v * v;
        let joules = tabor_restitution::validate::non_negative(
            "energy_loss",
            selection.evaluation.loss.joules,
        )
        .map_err(err)?;
        let restitution = restitution_from_loss(joules, m, v).map_err(err)?;
        let mut warnings = Vec::new();
        // the answer at v never fails because of another speed: a sticking velocity
        // that cannot be found is reported, not raised
        let mut can_stick = true;
        let (sticking, sticking_cost) = match self.sticking() {
            Ok((s, cost)) => {
                can_stick = s.sticks_ever();
                if let Sticking::UpToLimit { limit, reason } = s {
                    warnings.push(Warning {
                        code: "sticks-up-to-limit",
                        message: format!(
                            "sticks at every speed up to {limit:.6e} m/s ({reason}): no sticking velocity within the model's validity"
                        ),
                    });
                }
                if let Sticking::Below {
                    velocity,
                    rebounds_from: Some([lower, again]),
                } = s
                {
                    warnings.push(Warning {
                        code: "restitution-not-monotone",
                        message: format!(
                            "e(v) is not monotone: the bodies stick below {lower:.6e} m/s, rebound just above it, stick again at {again:.6e} m/s and rebound above the sticking velocity {velocity:.6e} m/s (the upper edge of the sticking set)"
                        ),
                    });
                }
                (s.velocity(), cost)
            }
            Err(e) => {
                warnings.push(Warning {
                    code: "sticking-velocity-unknown",
                    message: format!("the sticking velocity could not be found: {e}"),
                });
                (None, Cost::ZERO)
            }
        };
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
        if restitution == 0.0 && !can_stick {
            // ε from the loss, √(1 − L/E_kin), does not resolve ε below ~1e-8 (a
            // strongly damped viscoelastic sphere: 3e-11 at δ = 1e6); such a scene
            // never sticks
            warnings.push(Warning {
                code: "restitution-unresolved",
                message: "the loss equals the kinetic energy to rounding: the restitution is below about 1e-8 and reported as 0, but the bodies do not stick (nothing holds them together)".to_string(),
            });
        }
        if is_superposed(selection.evaluation.rule) {
            warnings.push(superposition_warning(self, &selection, v));
        }
        if selection.evaluation.rule == Rule::ViscousAdhesive {
            warnings.extend(viscous_adhesive_remark(self, v));
        }
        warnings.extend(crate::floors::outcome_floors(self, &selection));
        let effects = effect_list(self, &selection, kinetic);
        let combination = selection.combination();
        let e = selection.evaluation;
        Ok(Outcome {
            scene: self.name.to_string(),
            impact_speed: v,
            restitution,
            sticks: restitution == 0.0 && can_stick,
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
            self.models()
                .evaluate(&self.models().candidates, reference)
                .map_err(|e| self.locate(e))?
                .loss
                .joules,
        ))
    }

    /// The restitution at `v` (a validated speed) for the speed-independent loss
    /// `loss` (J): what [`Prepared::restitution_with_error`] computes, without
    /// re-evaluating the model. The selection's rule: a loss below `accuracy` × the
    /// kinetic energy is dropped.
    pub(crate) fn restitution_with_constant_loss(
        &self,
        loss: f64,
        v: f64,
    ) -> Result<f64, SceneError> {
        let models = self.models();
        let kinetic = 0.5 * models.mass * v * v;
        if !(kinetic.is_finite() && kinetic > 0.0) {
            // the full path reports the exact error
            return Ok(self.restitution_with_error(v)?.0);
        }
        if loss.abs() < models.accuracy * kinetic {
            return Ok(1.0);
        }
        restitution_from_loss(loss, models.mass, v).map_err(err)
    }

    /// The restitution at `v` (a validated speed) and the estimated error of the
    /// loss as a fraction of the kinetic energy (the error of 1 − ε²), without the
    /// outcome's reports.
    pub(crate) fn restitution_with_error(&self, v: f64) -> Result<(f64, f64), SceneError> {
        let selection = self.select(v)?;
        let loss = &selection.evaluation.loss;
        let mass = self.models().mass;
        let kinetic = 0.5 * mass * v * v;
        Ok((
            restitution_from_loss(loss.joules, mass, v).map_err(err)?,
            loss.error_estimate / kinetic,
        ))
    }
}

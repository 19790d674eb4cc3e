//! Selecting, at one impact speed, the effects that matter, and the scene's model
//! as a whole (the model that answers at every speed, whose root of ε(v) = 0 is the
//! sticking velocity).

use crate::combination::{Combination, EffectKind, EffectSet, Rule};
use crate::error::{located, SceneError, Source};
use crate::inputs::Inputs;
use crate::models::{Evaluation, Models};
use std::fmt;
use std::sync::{Arc, OnceLock};
use tabor_numerics::Cost;
use tabor_restitution::{sticking_velocity, EnergyLoss, ImpactModel, StickingMethod};

/// Why an effect given by the scene does not enter the result at one speed.
pub(crate) struct Dropped {
    pub effect: EffectKind,
    pub reason: String,
}

/// The effects used at one speed and their combined loss.
pub(crate) struct Selection {
    pub used: EffectSet,
    pub evaluation: Evaluation,
    pub dropped: Vec<Dropped>,
}

impl Selection {
    pub(crate) fn combination(&self) -> Combination {
        Combination::of(self.evaluation.rule, &self.used)
    }
}

/// A scene's models, built once from its inputs, and its sticking velocity,
/// computed on first use and kept.
pub(crate) struct Built {
    inputs: Inputs,
    models: Models,
    sticking: OnceLock<Result<(Option<f64>, Cost), SceneError>>,
}

impl Built {
    fn new(inputs: Inputs) -> Result<Arc<Built>, SceneError> {
        Ok(Arc::new(Built {
            models: Models::build(&inputs)?,
            inputs,
            sticking: OnceLock::new(),
        }))
    }
}

/// The models of a scene, built on first use and shared by every call on the scene
/// and its copies at other speeds (the models do not depend on the speed). Keyed by
/// the inputs they were built from: a scene whose inputs differ builds its own.
#[derive(Clone, Default)]
pub(crate) struct Cache(Arc<OnceLock<Entry>>);

/// The inputs a cache entry was built from, and what was built.
type Entry = (Inputs, Result<Arc<Built>, SceneError>);

impl Cache {
    /// The models of `inputs` (the cached ones when they were built from equal
    /// inputs); errors not yet located.
    pub(crate) fn get(&self, inputs: Inputs) -> Result<Arc<Built>, SceneError> {
        let (key, built) = self
            .0
            .get_or_init(|| (inputs.clone(), Built::new(inputs.clone())));
        if *key == inputs {
            built.clone()
        } else {
            Built::new(inputs)
        }
    }
}

impl fmt::Debug for Cache {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let state = if self.0.get().is_some() {
            "built"
        } else {
            "empty"
        };
        write!(f, "Cache({state})")
    }
}

impl PartialEq for Cache {
    /// A cache is derived data: it never makes two scenes differ.
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// A scene ready to answer: its name, where its text came from (to locate errors)
/// and its models.
pub(crate) struct Prepared<'a> {
    pub name: &'a str,
    source: Option<&'a Source>,
    built: Arc<Built>,
}

impl<'a> Prepared<'a> {
    /// The scene named `name` read from `source`, with the models of `inputs`
    /// (from `cache`).
    pub(crate) fn new(
        name: &'a str,
        source: Option<&'a Source>,
        cache: &Cache,
        inputs: Inputs,
    ) -> Result<Self, SceneError> {
        Ok(Prepared {
            name,
            source,
            built: cache.get(inputs).map_err(|e| located(source, e))?,
        })
    }

    /// The validated inputs the models were built from.
    pub(crate) fn inputs(&self) -> &Inputs {
        &self.built.inputs
    }

    /// The scene's models.
    pub(crate) fn models(&self) -> &Models {
        &self.built.models
    }

    /// `e` with the line of its field in the scene text, when known.
    pub(crate) fn locate(&self, e: SceneError) -> SceneError {
        located(self.source, e)
    }

    /// The effects that enter the result at `speed`, by these rules in this order:
    /// plasticity only above its yield onset (below it the elastic model of the
    /// other effects is exact); then viscoelasticity and adhesion are dropped when
    /// leaving them out changes the combined loss by less than the requested
    /// accuracy times the kinetic energy (so a drop changes ε by at most about the
    /// accuracy).
    pub(crate) fn select(&self, speed: f64) -> Result<Selection, SceneError> {
        let models = self.models();
        let kinetic = 0.5 * models.mass * speed * speed;
        let threshold = models.accuracy * kinetic;
        let mut used = models.candidates;
        let mut dropped = Vec::new();
        if let Some((onset, name)) = models.yield_onset(&used) {
            if speed <= onset {
                used = used.without(EffectKind::Plasticity);
                dropped.push(Dropped {
                    effect: EffectKind::Plasticity,
                    reason: format!(
                        "impact speed {speed:e} m/s does not exceed the {name} {onset:e} m/s: below it the contact stays elastic"
                    ),
                });
            }
        }
        let locate = |e| self.locate(e);
        let mut evaluation = models.evaluate(&used, speed).map_err(locate)?;
        for effect in [EffectKind::Viscoelasticity, EffectKind::Adhesion] {
            if !used.contains(effect) {
                continue;
            }
            let without = used.without(effect);
            let reduced = models.evaluate(&without, speed).map_err(locate)?;
            let marginal = evaluation.loss.joules - reduced.loss.joules;
            if marginal.abs() < threshold {
                dropped.push(Dropped {
                    effect,
                    reason: format!(
                        "leaving it out changes the loss by {marginal:e} J, {:e} of the kinetic energy, below the requested accuracy {:e}",
                        marginal.abs() / kinetic,
                        models.accuracy
                    ),
                });
                used = without;
                evaluation = reduced;
            }
        }
        Ok(Selection {
            used,
            evaluation,
            dropped,
        })
    }

    /// The sticking velocity of the scene's model (the root of ε(v) = 0 of the
    /// model that answers at each speed), `None` when the bodies never stick.
    pub(crate) fn sticking(&self) -> Result<(Option<f64>, Cost), SceneError> {
        self.built
            .sticking
            .get_or_init(|| {
                let whole = SceneModel { prepared: self };
                let vc = sticking_velocity(&whole, self.inputs().accuracy.max(1e-14))
                    .map_err(SceneError::model)?;
                Ok(match vc.method {
                    StickingMethod::NeverSticks => (None, vc.cost),
                    _ => (Some(vc.speed), vc.cost),
                })
            })
            .clone()
    }
}

/// The scene as one [`ImpactModel`]: at each speed, the loss of the effects that
/// matter there, combined by the table's rule.
pub(crate) struct SceneModel<'p, 'a> {
    pub prepared: &'p Prepared<'a>,
}

impl ImpactModel for SceneModel<'_, '_> {
    fn name(&self) -> String {
        format!("scene {}", self.prepared.name)
    }
    fn effective_mass(&self) -> f64 {
        self.prepared.models().mass
    }
    fn energy_loss(&self, impact_speed: f64) -> tabor_restitution::Result<EnergyLoss> {
        self.prepared
            .select(impact_speed)
            .map(|s| s.evaluation.loss)
            .map_err(|e| tabor_restitution::Error::Model {
                model: "scene",
                message: e.to_string(),
            })
    }
    fn loss_is_speed_independent(&self) -> bool {
        let m = self.prepared.models();
        let c = m.candidates;
        c.plasticity.is_none()
            && c.viscoelasticity.is_none()
            && m.adhesive
                .as_ref()
                .is_some_and(|a| a.model.model().loss_is_speed_independent())
    }
    fn speed_scale(&self) -> f64 {
        let m = self.prepared.models();
        if let Some(a) = &m.adhesive {
            a.model.model().speed_scale()
        } else if let Some(p) = &m.plastic {
            p.model().speed_scale()
        } else if let Some(v) = &m.visco {
            v.model.speed_scale()
        } else {
            1.0
        }
    }
}

/// Whether a rule's result is a superposition that deserves a warning.
pub(crate) fn is_superposed(rule: Rule) -> bool {
    rule == Rule::Superposition
}

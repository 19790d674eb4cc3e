//! The scene in the time domain (for `tabor trajectory`): one dispatch from the
//! rule that answers at a speed to the force law that reproduces it. A rule with a
//! force law of its own is simulated exactly (agreeing with the outcome to the
//! simulation's tolerance); a loss-level rule (a sum or a bound of losses) has
//! none, and the trajectory simulates a named model of the same effects instead,
//! with a warning stating by how much its restitution differs.

use crate::combination::{EffectKind, Rule};
use crate::error::SceneError;
use crate::models::{AdhesiveModel, Models, Plastic};
use crate::outcome::Outcome;
use crate::select::Prepared;
use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_elastic::ElasticContact;
use tabor_jkr::JkrForceLaw;
use tabor_maugis::MaugisDugdaleForceLaw;
use tabor_restitution::{Error, Warning};

fn err(e: Error) -> SceneError {
    SceneError::model(e)
}

/// The effects an outcome used, as the set its damped law is built from (the
/// kinds that choose the law: adhesion's and plasticity's from the scene).
pub(crate) fn outcome_set(outcome: &Outcome) -> crate::combination::EffectSet {
    let uses = |e| outcome.combination.effects.contains(&e);
    crate::combination::EffectSet {
        adhesion: uses(EffectKind::Adhesion)
            .then_some(crate::combination::AdhesionKind::JkrFixedGrip),
        plasticity: uses(EffectKind::Plasticity)
            .then_some(crate::combination::PlasticityKind::Interpolation),
        damping: uses(EffectKind::Damping),
        ..Default::default()
    }
}

/// The force law the trajectory simulates.
struct Law {
    law: Box<dyn ForceLaw>,
    /// `None` when the law is the answering rule's own; else why another model
    /// is simulated.
    substitute: Option<String>,
}

impl Law {
    fn exact(law: Box<dyn ForceLaw>) -> Self {
        Law {
            law,
            substitute: None,
        }
    }
}

impl Prepared<'_> {
    /// The elastic contact (Hertz or the graded medium), (5.5)-(5.23).
    fn elastic_law(&self) -> Result<ElasticContact, SceneError> {
        let inputs = self.inputs();
        match inputs.target.gradation {
            Some((k, c)) => ElasticContact::graded_sphere(c, k, inputs.effective_radius),
            None => ElasticContact::hertz(inputs.effective_modulus, inputs.effective_radius),
        }
        .map_err(err)
    }

    /// The force law of the scene's elastic adhesive model, when it has one.
    fn adhesive_law(&self) -> Result<Option<Box<dyn ForceLaw>>, SceneError> {
        Ok(match self.models().adhesive.as_ref().map(|a| &a.model) {
            // the rule of the selected model (fixed grip when it stands in for
            // Maugis-Dugdale)
            Some(AdhesiveModel::Jkr(j)) => {
                Some(Box::new(JkrForceLaw::new(*j.contact(), j.separation())))
            }
            Some(AdhesiveModel::Maugis(md, _)) => {
                Some(Box::new(MaugisDugdaleForceLaw::new(md).map_err(err)?))
            }
            Some(AdhesiveModel::Graded(_)) | None => None,
        })
    }

    /// The force law of the scene's non-adhesive plastic model, when it has one.
    fn plastic_law(&self) -> Result<Option<Box<dyn ForceLaw>>, SceneError> {
        let inputs = self.inputs();
        Ok(match &self.models().plastic {
            Some(Plastic::Thornton(p)) => Some(Box::new(p.force_law())),
            Some(Plastic::Interpolation(p)) => Some(Box::new(p.force_law())),
            Some(Plastic::JacksonGreen(_)) => Some(Box::new(
                tabor_plastic::PlasticContact::new(
                    inputs.effective_modulus,
                    inputs.effective_radius,
                    inputs.yield_stress().unwrap_or(f64::NAN),
                )
                .and_then(|contact| {
                    tabor_plastic::JacksonGreen::new(contact, inputs.plastic_poisson_ratio())
                })
                .map_err(err)?
                .force_law(),
            )),
            Some(Plastic::Fit(_)) | None => None,
        })
    }

    /// The one dispatch from the answering rule to its force law: the rule's own,
    /// or (for a loss-level rule, or a model solved without a force law) the first
    /// of these that the scene has, named: the adhesive interpolation model, the
    /// viscous-adhesive model, the plastic model, the adhesive model, the elastic
    /// contact.
    fn law(&self, outcome: &Outcome) -> Result<Law, SceneError> {
        let models: &Models = self.models();
        let rule = outcome.combination.rule;
        let uses = |effect| outcome.combination.effects.contains(&effect);
        let own: Option<Box<dyn ForceLaw>> = match rule {
            Rule::Elastic => Some(Box::new(self.elastic_law()?)),
            Rule::Single if uses(EffectKind::Adhesion) => self.adhesive_law()?,
            Rule::Single if uses(EffectKind::Plasticity) => self.plastic_law()?,
            Rule::AdhesiveInterpolation => models
                .adhesive_interpolation
                .as_ref()
                .map(|a| Box::new(a.force_law()) as Box<dyn ForceLaw>),
            Rule::Damped => Some(models.damped_law(&outcome_set(outcome))?),
            Rule::ViscousAdhesive => models
                .viscous_adhesive
                .as_ref()
                .map(|m| Box::new(m.force_law()) as Box<dyn ForceLaw>),
            // the viscoelastic spheres are solved in scaled form (MDR), the other
            // rules are sums or bounds of losses
            Rule::Single
            | Rule::AdhesivePlasticExcess
            | Rule::Superposition
            | Rule::SuperpositionBound => None,
        };
        if let Some(law) = own {
            return Ok(Law::exact(law));
        }
        let why = match rule {
            Rule::Single => "the viscoelastic sphere is solved in scaled form (MDR) or the model (the dimensionless FEM fit, JKR on a graded medium) has no time-domain force law".to_string(),
            other => format!("the {} rule combines losses, not forces", other.as_str()),
        };
        let candidates: [Option<Box<dyn ForceLaw>>; 4] = [
            (uses(EffectKind::Adhesion) && uses(EffectKind::Plasticity))
                .then_some(models.adhesive_interpolation.as_ref())
                .flatten()
                .map(|a| Box::new(a.force_law()) as Box<dyn ForceLaw>),
            (uses(EffectKind::Adhesion) && uses(EffectKind::Viscoelasticity))
                .then_some(models.viscous_adhesive.as_ref())
                .flatten()
                .map(|m| Box::new(m.force_law()) as Box<dyn ForceLaw>),
            if uses(EffectKind::Plasticity) {
                self.plastic_law()?
            } else {
                None
            },
            if uses(EffectKind::Adhesion) {
                self.adhesive_law()?
            } else {
                None
            },
        ];
        let law = match candidates.into_iter().flatten().next() {
            Some(law) => law,
            None => Box::new(self.elastic_law()?),
        };
        Ok(Law {
            law,
            substitute: Some(why),
        })
    }

    /// The answering rule's own force law, or an error naming why it has none (the
    /// oblique impact simulates only the rule's own law, never a substitute).
    pub(crate) fn force_law(&self, outcome: &Outcome) -> Result<Box<dyn ForceLaw>, SceneError> {
        let Law { law, substitute } = self.law(outcome)?;
        match substitute {
            None => Ok(law),
            Some(why) => Err(SceneError::model(Error::Model {
                model: "scene",
                message: format!("no time-domain force law for this scene at this speed: {why}"),
            })),
        }
    }

    /// Simulates the impact at `speed` (validated, m/s) with the force law of the
    /// rule that answers there ([`Prepared::law`]), and returns the simulation with
    /// the outcome at that speed. When another model is simulated, the outcome
    /// carries a `trajectory-other-model` warning naming it and the difference.
    pub(crate) fn simulate(
        &self,
        speed: f64,
        settings: &SimulationSettings,
    ) -> Result<(ImpactSimulation, Outcome), SceneError> {
        let mut outcome = self.outcome_at(speed)?;
        let Law {
            mut law,
            substitute,
        } = self.law(&outcome)?;
        let sim = simulate_impact(law.as_mut(), self.inputs().effective_mass, speed, settings)
            .map_err(err)?;
        if let Some(why) = substitute {
            outcome.warnings.push(Warning {
                code: "trajectory-other-model",
                message: format!(
                    "{why}: the trajectory simulates {} instead, whose restitution {:.6} differs from the outcome's {:.6} ({}) by {:+.3e}",
                    sim.law,
                    sim.restitution,
                    outcome.restitution,
                    outcome.combination.rule.as_str(),
                    sim.restitution - outcome.restitution
                ),
            });
        }
        Ok((sim, outcome))
    }
}

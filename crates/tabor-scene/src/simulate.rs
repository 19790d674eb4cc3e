//! The scene in the time domain: the force law of the model that answers at one
//! speed, simulated (for `tabor trajectory`).

use crate::combination::{EffectKind, Rule};
use crate::error::SceneError;
use crate::models::{AdhesiveModel, Models, Plastic};
use crate::outcome::Outcome;
use crate::select::Prepared;
use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_elastic::ElasticContact;
use tabor_jkr::JkrForceLaw;
use tabor_maugis::MaugisDugdaleForceLaw;
use tabor_restitution::Error;

fn err(e: Error) -> SceneError {
    SceneError::model(e)
}

impl Prepared<'_> {
    /// Simulates the impact at `speed` (validated, m/s) with the force law of the
    /// model the scene selects there, and returns the simulation with the analytic
    /// outcome of the same model.
    pub(crate) fn simulate(
        &self,
        speed: f64,
        settings: &SimulationSettings,
    ) -> Result<(ImpactSimulation, Outcome), SceneError> {
        let outcome = self.outcome_at(speed)?;
        let models = self.models();
        let inputs = self.inputs();
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
            Rule::Elastic => Box::new(match inputs.target.gradation {
                Some((k, c)) => {
                    ElasticContact::graded_sphere(c, k, inputs.effective_radius).map_err(err)?
                }
                None => ElasticContact::hertz(inputs.effective_modulus, inputs.effective_radius)
                    .map_err(err)?,
            }),
            Rule::Single if uses(EffectKind::Adhesion) => {
                match models.adhesive.as_ref().map(|a| &a.model) {
                    // the rule of the selected model (fixed grip when it stands in for
                    // Maugis-Dugdale)
                    Some(AdhesiveModel::Jkr(j)) => {
                        Box::new(JkrForceLaw::new(*j.contact(), j.separation()))
                    }
                    Some(AdhesiveModel::Maugis(md, _)) => {
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
                        inputs.effective_modulus,
                        inputs.effective_radius,
                        inputs.yield_stress().unwrap_or(f64::NAN),
                    )
                    .and_then(|contact| {
                        tabor_plastic::JacksonGreen::new(contact, inputs.plastic_poisson_ratio())
                    })
                    .map_err(err)?
                    .force_law(),
                ),
                _ => return Err(no_law("the dimensionless FEM fit")),
            },
            Rule::AdhesiveInterpolation => match &models.adhesive_interpolation {
                Some(a) => Box::new(a.force_law()),
                None => return Err(no_law("this combination")),
            },
            Rule::ViscousAdhesive => match &models.viscous_adhesive {
                Some(m) => Box::new(m.force_law()),
                None => return Err(Models::missing("viscous-adhesive")),
            },
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
            simulate_impact(law.as_mut(), inputs.effective_mass, speed, settings).map_err(err)?;
        Ok((sim, outcome))
    }
}

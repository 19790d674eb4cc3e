//! A DEM damping law on the scene's force law (`[damping]`, the `dem-damping`
//! rule): the damped law of a set of effects and its simulated loss.
//!
//! The law is `tabor_viscoadhesive::ViscousDamping` around the force law of the
//! other effects: the adhesive laws through `ViscoadhesiveImpact::damped` (its
//! energy criterion ends a sticking contact, its loss of a sticking impact
//! includes the well depth, as for the viscous-adhesive rule), every other law
//! (Hertz, the elasto-plastic laws, the adhesive interpolation law) boxed.

use super::types::{Adhesive, AdhesiveModel, Damped, Evaluation, Models, Plastic};
use crate::combination::{EffectKind, EffectSet, Rule};
use crate::error::SceneError;
use crate::inputs::Inputs;
use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_elastic::ElasticContact;
use tabor_plastic::{JacksonGreen, PlasticContact};
use tabor_restitution::{validate, EnergyLoss, Error, ImpactModel};
use tabor_viscoadhesive::{
    AdhesiveImpact, NormalDamping, SeparationPotential, ViscoadhesiveImpact, ViscousDamping,
};

const MODEL: &str = "dem-damping";

fn err(e: Error) -> SceneError {
    SceneError::model(e)
}

impl Damped {
    /// The damping of `scene` (`None` without `[damping]`), with the adhesive
    /// impact `adhesive` and plastic model `plastic` it damps.
    pub(crate) fn build(
        scene: &Inputs,
        adhesive: Option<&Adhesive>,
        plastic: Option<&Plastic>,
    ) -> Result<Option<Damped>, SceneError> {
        let Some(damping) = scene.damping else {
            return Ok(None);
        };
        let accuracy = scene.accuracy.max(1e-12);
        let in_damping = |e: Error| SceneError::field_model("damping", e);
        let adhesive = match adhesive.map(|a| &a.model) {
            Some(AdhesiveModel::Jkr(j)) => Some(AdhesiveImpact::Jkr(j.clone())),
            Some(AdhesiveModel::Maugis(md, sphere)) => {
                Some(AdhesiveImpact::MaugisDugdale(md.clone(), *sphere))
            }
            Some(AdhesiveModel::Graded(_)) | None => None,
        }
        .map(|a| ViscoadhesiveImpact::damped(a, damping, accuracy))
        .transpose()
        .map_err(in_damping)?;
        let jackson_green = match plastic {
            Some(Plastic::JacksonGreen(_)) => Some(
                PlasticContact::new(
                    scene.effective_modulus,
                    scene.effective_radius,
                    scene.yield_stress().unwrap_or(f64::NAN),
                )
                .and_then(|c| JacksonGreen::new(c, scene.plastic_poisson_ratio()))
                .map_err(err)?
                .force_law(),
            ),
            Some(Plastic::Fit(_)) => {
                return Err(SceneError::field(
                    "damping",
                    "a DEM damping law needs a time-domain force law: the dimensionless FEM fit (plasticity model \"dimensionless-fit\") has none; choose thornton, interpolation or jackson-green",
                ))
            }
            _ => None,
        };
        let mut settings = SimulationSettings::with_tolerance(accuracy).map_err(err)?;
        settings.record_trajectory = false;
        Ok(Some(Damped {
            damping,
            adhesive,
            elastic: ElasticContact::hertz(scene.effective_modulus, scene.effective_radius)
                .map_err(err)?,
            jackson_green,
            settings,
            accuracy,
        }))
    }
}

impl Models {
    fn damped(&self) -> Result<&Damped, SceneError> {
        self.damped.as_ref().ok_or_else(|| Self::missing("damped"))
    }

    /// The undamped force law of the effects of `set` other than the damping
    /// (boxed), for the sets the adhesive impact does not cover: Hertz, the
    /// elasto-plastic laws, the adhesive interpolation law (JKR fixed grip +
    /// interpolation plasticity).
    fn undamped_law(&self, set: &EffectSet) -> Result<Box<dyn ForceLaw>, SceneError> {
        let d = self.damped()?;
        if set.plasticity.is_none() {
            return Ok(Box::new(d.elastic));
        }
        if set.adhesion.is_some() {
            let ai = self
                .adhesive_interpolation
                .as_ref()
                .ok_or_else(|| Self::missing("adhesive interpolation"))?;
            return Ok(Box::new(ai.force_law()));
        }
        Ok(match &self.plastic {
            Some(Plastic::Thornton(p)) => Box::new(p.force_law()),
            Some(Plastic::Interpolation(p)) => Box::new(p.force_law()),
            Some(Plastic::JacksonGreen(_)) => Box::new(
                d.jackson_green
                    .clone()
                    .ok_or_else(|| Self::missing("Jackson-Green law"))?,
            ),
            Some(Plastic::Fit(_)) | None => return Err(Self::missing("plastic force law")),
        })
    }

    /// The damped force law of the effects `set` (`dem-damping`): the adhesive
    /// law's (JKR, Maugis-Dugdale) with its energy criterion, or the boxed law of
    /// [`Models::undamped_law`], plus `c(m, a) ḋ`.
    pub(crate) fn damped_law(&self, set: &EffectSet) -> Result<Box<dyn ForceLaw>, SceneError> {
        let d = self.damped()?;
        if set.adhesion.is_some() && set.plasticity.is_none() {
            let a = d
                .adhesive
                .as_ref()
                .ok_or_else(|| Self::missing("damped adhesive"))?;
            return Ok(Box::new(a.force_law()));
        }
        let law = ViscousDamping::damped(self.undamped_law(set)?, d.damping).map_err(err)?;
        Ok(Box::new(law))
    }

    /// The undamped force law of `set` and the damping law that acts on it (for
    /// the oblique impact, which adds the damping itself: its work is the
    /// `normal_damping` mechanism).
    pub(crate) fn damped_parts(
        &self,
        set: &EffectSet,
    ) -> Result<(Box<dyn ForceLaw>, NormalDamping), SceneError> {
        let d = self.damped()?;
        if set.adhesion.is_some() && set.plasticity.is_none() {
            let a = d
                .adhesive
                .as_ref()
                .ok_or_else(|| Self::missing("damped adhesive"))?;
            return Ok((Box::new(a.force_law().inner().clone()), d.damping));
        }
        Ok((self.undamped_law(set)?, d.damping))
    }

    /// The simulated impact of the damped law of `set` at `speed` with `settings`.
    pub(crate) fn simulate_damped(
        &self,
        set: &EffectSet,
        speed: f64,
        settings: &SimulationSettings,
    ) -> Result<ImpactSimulation, SceneError> {
        let mut law = self.damped_law(set)?;
        simulate_impact(law.as_mut(), self.mass, speed, settings)
            .map_err(|e| self.fields.error(EffectKind::Damping, e))
    }

    /// The loss of the effects `set` under the `dem-damping` rule at `speed`: the
    /// simulated damped law, `(1 − ε²) m v0²/2` (seed 000 eq. (5.37) read
    /// backwards); when the bodies stick, `m v0²/2` plus the depth of the adhesive
    /// well (as the viscous-adhesive rule: the sticking-velocity search sees
    /// ε² < 0). The shares: the adhesive hysteresis of the elastic adhesive model
    /// (the work of its conservative force from first contact to separation, the
    /// same on every path along its branch) and the rest, the damping work; with
    /// plasticity the two are coupled (no shares).
    pub(crate) fn damped_loss(
        &self,
        set: &EffectSet,
        speed: f64,
    ) -> Result<Evaluation, SceneError> {
        let d = self.damped()?;
        let f = self.fields;
        let (loss, name) = if let (Some(_), None, Some(a)) =
            (set.adhesion, set.plasticity, d.adhesive.as_ref())
        {
            let loss = a
                .energy_loss(speed)
                .map_err(|e| f.error(EffectKind::Damping, e))?;
            (loss, a.name())
        } else {
            let sim = self.simulate_damped(set, speed, &d.settings)?;
            let kinetic = sim.kinetic_energy;
            let joules = if sim.sticks {
                let well = d
                    .adhesive
                    .as_ref()
                    .and_then(|a| a.force_law().inner().well_depth())
                    .unwrap_or(0.0);
                kinetic + well
            } else {
                sim.energy_loss.clamp(0.0, kinetic)
            };
            let error = (sim.energy_error + 2.0 * sim.restitution * d.accuracy) * kinetic;
            (
                EnergyLoss {
                    joules: validate::finite_output(MODEL, "energy loss", joules).map_err(err)?,
                    error_estimate: validate::finite_output(MODEL, "error estimate", error)
                        .map_err(err)?,
                    branch: format!("time-domain simulation of {}", sim.law),
                    cost: sim.cost,
                },
                format!("{} (time-domain simulation)", sim.law),
            )
        };
        let parts = match (set.adhesion, set.plasticity) {
            (None, None) => vec![(EffectKind::Damping, Some(loss.joules))],
            (Some(_), None) => {
                let adhesive = self
                    .adhesive_model()?
                    .energy_loss(speed)
                    .map_err(|e| f.error(EffectKind::Adhesion, e))?
                    .joules;
                vec![
                    (EffectKind::Adhesion, Some(adhesive)),
                    (EffectKind::Damping, Some((loss.joules - adhesive).max(0.0))),
                ]
            }
            (a, Some(_)) => {
                let mut parts = vec![(EffectKind::Plasticity, None), (EffectKind::Damping, None)];
                if a.is_some() {
                    parts.insert(0, (EffectKind::Adhesion, None));
                }
                parts
            }
        };
        Ok(Evaluation {
            loss,
            model: name,
            rule: Rule::Damped,
            parts,
        })
    }
}

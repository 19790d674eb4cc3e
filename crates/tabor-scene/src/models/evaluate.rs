//! Evaluating the loss of a set of effects by the rule of the combination table.

use super::types::{Evaluation, Models};
use crate::combination::{rule, AdhesionKind, EffectKind, EffectSet, Rule, ViscoKind};
use crate::error::SceneError;
use tabor_plastic::AdhesiveInterpolationImpact;
use tabor_restitution::{EnergyLoss, ImpactModel};

impl Models {
    /// The speed above which plasticity enters for the effects `set` (the adhesive
    /// yield onset (5.111) when the rule is built on the adhesive interpolation
    /// model, else v_Y (5.103) of the plastic model).
    pub(crate) fn yield_onset(&self, set: &EffectSet) -> Option<(f64, &'static str)> {
        let plastic = self.plastic.as_ref()?;
        set.plasticity?;
        let v_y = plastic.model().yield_velocity();
        match self.coupled_plastic_part(set) {
            // the plastic part max(L_AI − L_JKR, L_plastic) starts at the earlier of
            // the two onsets
            Some(ai) if ai.yield_velocity() < v_y => {
                Some((ai.yield_velocity(), "adhesive yield onset (5.111)"))
            }
            _ => Some((v_y, "yield onset v_Y (5.103)")),
        }
    }

    /// The adhesive interpolation model, when the plastic part of `set` comes from
    /// it (adhesion + the interpolation model, no superposition requested).
    fn coupled_plastic_part(&self, set: &EffectSet) -> Option<&AdhesiveInterpolationImpact> {
        match rule(&set.without(EffectKind::Viscoelasticity)) {
            Ok(Rule::AdhesiveInterpolation | Rule::AdhesivePlasticExcess) => {
                self.adhesive_interpolation.as_ref()
            }
            // the damped adhesive interpolation law yields at its own onset
            Ok(Rule::Damped) if set.adhesion.is_some() => self.adhesive_interpolation.as_ref(),
            _ => None,
        }
    }

    /// The plastic part of the loss of `set` at `speed`: with adhesion and the
    /// interpolation model, the adhesive interpolation model's excess over its own
    /// elastic (fixed-grip JKR) loss, but at least the non-adhesive plastic loss
    /// (the superposition (5.109) bounds it from below: the model's JKR unloading
    /// would otherwise let adhesion raise ε, tabor-plastic README); otherwise the
    /// plastic model's loss. 0 at the yield onset, so adding it last keeps every
    /// combination continuous there.
    /// The flag is true where the superposition bound answers (the coupled excess
    /// is below the non-adhesive plastic loss).
    fn plastic_part(
        &self,
        set: &EffectSet,
        speed: f64,
    ) -> Result<(EnergyLoss, String, bool), SceneError> {
        let f = self.fields;
        let plastic_error = |e| f.error(EffectKind::Plasticity, e);
        let plastic = self.plastic_model()?;
        let pl = plastic.energy_loss(speed).map_err(plastic_error)?;
        let Some(ai) = self.coupled_plastic_part(set) else {
            return Ok((pl, plastic.name(), false));
        };
        let jkr = self
            .jkr_fixed_grip
            .as_ref()
            .ok_or_else(|| Self::missing("fixed-grip JKR"))?;
        let coupled = ai.energy_loss(speed).map_err(plastic_error)?;
        let elastic_part = jkr
            .energy_loss(speed)
            .map_err(|e| f.error(EffectKind::Adhesion, e))?;
        let excess = coupled.joules - elastic_part.joules;
        // range-aware: the adhesive interpolation model is built on JKR, whose
        // adhesive pressure makes the contact yield early; a Maugis-Dugdale range
        // spreads the adhesive stress outside the contact (the DMT limit Λ → 0 adds
        // none), so the early-yield excess over the non-adhesive plastic loss is
        // weighted by φ = ΔU_MD/ΔU_JKR,fg ∈ [0, 1] (1 in the JKR limit, where the
        // rule is the seed's model; 0 in the DMT limit, where it is the
        // superposition); crates/tabor-scene/README.md
        let weight = match set.adhesion {
            Some(AdhesionKind::MaugisDugdale) => {
                let md = self
                    .adhesive_model()?
                    .energy_loss(speed)
                    .map_err(|e| f.error(EffectKind::Adhesion, e))?;
                (md.joules / elastic_part.joules).clamp(0.0, 1.0)
            }
            _ => 1.0,
        };
        let name = format!(
            "plastic part of the adhesive interpolation model (5.111)-(5.126), at least {}",
            plastic.name()
        );
        let cost = coupled.cost + elastic_part.cost + pl.cost;
        let error_estimate =
            coupled.error_estimate + elastic_part.error_estimate + pl.error_estimate;
        Ok(if excess >= pl.joules {
            let (joules, branch) = if weight < 1.0 {
                (
                    pl.joules + weight * (excess - pl.joules),
                    format!(
                        "{} + {weight:.6e} x (plastic excess of {} over {}, less it) (range weight MD/JKR loss)",
                        pl.branch, coupled.branch, elastic_part.branch
                    ),
                )
            } else {
                (
                    excess,
                    format!(
                        "plastic excess of {} over {}",
                        coupled.branch, elastic_part.branch
                    ),
                )
            };
            (
                EnergyLoss {
                    joules,
                    error_estimate,
                    branch,
                    cost,
                },
                name,
                false,
            )
        } else {
            (
                EnergyLoss {
                    joules: pl.joules,
                    error_estimate,
                    branch: format!("{} (superposition bound)", pl.branch),
                    cost,
                },
                name,
                true,
            )
        })
    }

    /// The loss of the effects `set` at `speed`, by the rule of the table.
    pub(crate) fn evaluate(&self, set: &EffectSet, speed: f64) -> Result<Evaluation, SceneError> {
        let r = rule(set).map_err(|r| SceneError::field(self.fields.field(r.effect), r.message))?;
        let f = self.fields;
        let single = |kind: EffectKind, model: &(dyn ImpactModel + Send + Sync)| {
            let loss = model.energy_loss(speed).map_err(|e| f.error(kind, e))?;
            Ok::<_, SceneError>(Evaluation {
                parts: vec![(kind, Some(loss.joules))],
                model: model.name(),
                rule: r,
                loss,
            })
        };
        match r {
            Rule::Elastic => Ok(Evaluation {
                loss: self.elastic.energy_loss(speed).map_err(SceneError::model)?,
                model: self.elastic.name(),
                rule: r,
                parts: Vec::new(),
            }),
            Rule::Single => {
                if set.adhesion.is_some() {
                    single(EffectKind::Adhesion, self.adhesive_model()?)
                } else if set.plasticity.is_some() {
                    single(EffectKind::Plasticity, self.plastic_model()?)
                } else {
                    single(EffectKind::Viscoelasticity, self.visco_model()?)
                }
            }
            Rule::Damped => self.damped_loss(set, speed),
            Rule::ViscousAdhesive => {
                let m = self
                    .viscous_adhesive
                    .as_ref()
                    .ok_or_else(|| Self::missing("viscous-adhesive"))?;
                let loss = m
                    .energy_loss(speed)
                    .map_err(|e| f.error(EffectKind::Viscoelasticity, e))?;
                Ok(Evaluation {
                    loss,
                    model: m.name(),
                    rule: r,
                    parts: vec![
                        (EffectKind::Adhesion, None),
                        (EffectKind::Viscoelasticity, None),
                    ],
                })
            }
            Rule::AdhesiveInterpolation
            | Rule::AdhesivePlasticExcess
            | Rule::Superposition
            | Rule::SuperpositionBound => {
                let kinetic = 0.5 * self.mass * speed * speed;
                // Which effect comes last, and how it adds:
                // - adhesion and plasticity alone: the plastic part is added to the
                //   adhesive loss (5.109) (0 at the yield onset);
                // - with viscoelasticity, the last effect acts on the energy the others
                //   leave, ΔU = ΔU_rest + ΔU_last (1 − ΔU_rest/U): a fraction of the
                //   kinetic energy, never making bodies stick that the others let
                //   go (without adhesion they never stick); the last effect is
                //   plasticity when the rest is the coupled adhesion + Kelvin-Voigt
                //   model (so the rule is continuous at the yield onset), else the
                //   viscoelastic loss.
                let coupled_rest =
                    set.adhesion.is_some() && set.viscoelasticity == Some(ViscoKind::KelvinVoigt);
                let mut bound = false;
                let (mut inner, (kind, extra, name), as_fraction) = if set.plasticity.is_some()
                    && (set.viscoelasticity.is_none() || coupled_rest)
                {
                    let (l, name, is_bound) = self.plastic_part(set, speed)?;
                    bound = is_bound;
                    (
                        self.evaluate(&set.without(EffectKind::Plasticity), speed)?,
                        (EffectKind::Plasticity, l, name),
                        set.viscoelasticity.is_some(),
                    )
                } else {
                    let visco = self.visco_model()?;
                    (
                        self.evaluate(&set.without(EffectKind::Viscoelasticity), speed)?,
                        (
                            EffectKind::Viscoelasticity,
                            visco
                                .energy_loss(speed)
                                .map_err(|e| f.error(EffectKind::Viscoelasticity, e))?,
                            visco.name(),
                        ),
                        true,
                    )
                };
                let share = if as_fraction {
                    extra.joules * (1.0 - inner.loss.joules / kinetic).max(0.0)
                } else {
                    extra.joules
                };
                inner.loss.joules += share;
                inner.loss.error_estimate += extra.error_estimate;
                inner.loss.cost += extra.cost;
                inner.loss.branch = if as_fraction {
                    format!("{} + (1 - rest/U) x {}", inner.loss.branch, extra.branch)
                } else {
                    format!("{} + {}", inner.loss.branch, extra.branch)
                };
                inner.model = format!("{} + {name}", inner.model);
                // where the adhesive rules take their lower bound, the superposition
                // (5.109) answers: named as such
                inner.rule = match r {
                    Rule::AdhesiveInterpolation | Rule::AdhesivePlasticExcess if bound => {
                        Rule::SuperpositionBound
                    }
                    _ => r,
                };
                inner.parts.push((kind, Some(share)));
                Ok(inner)
            }
        }
    }
}

//! Building the models a scene can use, once per scene, and evaluating the loss of
//! a set of effects by the rule of the combination table.

use crate::combination::{
    rule, AdhesionKind, EffectKind, EffectSet, PlasticityKind, Rule, ViscoKind,
};
use crate::scene::{AdhesionRange, AdhesivePlasticity, PlasticityModel, Scene, SceneError};
use tabor_dynamics::SimulationSettings;
use tabor_elastic::{ElasticContact, ElasticImpact};
use tabor_jkr::{GradedSphere, JkrImpact, JkrSphere, SeparationRule};
use tabor_maugis::{normalized_loss, MaugisContact, MaugisDugdaleImpact, LAMBDA_1};
use tabor_plastic::YieldVelocity;
use tabor_plastic::{
    AdhesiveInterpolationImpact, AdhesivePlasticContact, DimensionlessFit, Interpolation,
    JacksonGreen, JacksonGreenImpact, PlasticContact, PlasticImpact, Thornton,
};
use tabor_restitution::{EnergyLoss, Error, ImpactModel};

pub(crate) fn err(e: Error) -> SceneError {
    SceneError::model(e)
}

/// The elastic adhesive models.
#[derive(Clone, Debug)]
pub(crate) enum AdhesiveModel {
    Jkr(JkrImpact<JkrSphere>),
    Graded(JkrImpact<GradedSphere>),
    Maugis(MaugisDugdaleImpact),
}

impl AdhesiveModel {
    pub(crate) fn model(&self) -> &(dyn ImpactModel + Send + Sync) {
        match self {
            AdhesiveModel::Jkr(m) => m,
            AdhesiveModel::Graded(m) => m,
            AdhesiveModel::Maugis(m) => m,
        }
    }
}

/// The scene's elastic adhesive model, its kind and why it was chosen.
#[derive(Clone, Debug)]
pub(crate) struct Adhesive {
    pub model: AdhesiveModel,
    pub kind: AdhesionKind,
    pub why: String,
}

/// The non-adhesive plastic models.
#[derive(Clone, Debug)]
pub(crate) enum Plastic {
    Thornton(PlasticImpact<Thornton>),
    Interpolation(PlasticImpact<Interpolation>),
    JacksonGreen(Box<JacksonGreenImpact>),
    Fit(DimensionlessFit),
}

/// A plastic impact model with its yield onset.
pub(crate) trait PlasticModel: ImpactModel + YieldVelocity + Send + Sync {}

impl<T: ImpactModel + YieldVelocity + Send + Sync> PlasticModel for T {}

impl Plastic {
    pub(crate) fn model(&self) -> &dyn PlasticModel {
        match self {
            Plastic::Thornton(m) => m,
            Plastic::Interpolation(m) => m,
            Plastic::JacksonGreen(m) => m.as_ref(),
            Plastic::Fit(m) => m,
        }
    }

    fn kind(&self) -> PlasticityKind {
        match self {
            Plastic::Interpolation(_) => PlasticityKind::Interpolation,
            _ => PlasticityKind::WithoutAdhesiveCounterpart,
        }
    }
}

/// The viscoelastic contact model and its kind.
pub(crate) struct Visco {
    pub kind: ViscoKind,
    pub model: Box<dyn ImpactModel + Send + Sync>,
    /// (E*, η_c) of a Kelvin-Voigt contact E*(s) = E* + η_c s.
    pub kelvin_voigt: Option<(f64, f64)>,
    pub why: String,
}

/// Everything a scene can use, built once.
pub(crate) struct Models {
    pub mass: f64,
    pub accuracy: f64,
    pub elastic: ElasticImpact,
    pub adhesive: Option<Adhesive>,
    pub plastic: Option<Plastic>,
    /// The adhesive interpolation model (5.111)-(5.126), for homogeneous adhesion
    /// with plasticity.
    pub adhesive_interpolation: Option<AdhesiveInterpolationImpact>,
    /// The fixed-grip JKR impact the adhesive interpolation model contains (its
    /// elastic part, for the adhesive-plastic excess).
    pub jkr_fixed_grip: Option<JkrImpact<JkrSphere>>,
    pub visco: Option<Visco>,
    pub viscous_adhesive: Option<tabor_viscoadhesive::ViscoadhesiveImpact>,
    /// The scene field each effect's model errors point at.
    pub fields: EffectFields,
    /// The effects whose parameters the scene gives.
    pub candidates: EffectSet,
}

/// The scene field that a model's error points at, per effect.
#[derive(Clone, Copy, Debug)]
pub(crate) struct EffectFields {
    pub adhesion: &'static str,
    pub plasticity: &'static str,
    pub viscoelasticity: &'static str,
}

impl EffectFields {
    pub(crate) fn of(scene: &Scene) -> Self {
        EffectFields {
            adhesion: "adhesion.work_of_adhesion",
            plasticity: scene.yield_stress_field(),
            viscoelasticity: if scene.target.viscosity.is_some() {
                "target.viscosity"
            } else {
                "sphere.viscosity"
            },
        }
    }

    /// The field of `effect`'s parameter.
    pub fn field(&self, effect: EffectKind) -> &'static str {
        match effect {
            EffectKind::Adhesion => self.adhesion,
            EffectKind::Plasticity => self.plasticity,
            EffectKind::Viscoelasticity => self.viscoelasticity,
            EffectKind::Elasticity => "sphere.youngs_modulus",
        }
    }

    /// An error of the model of `effect`, pointing at its field.
    pub fn error(&self, effect: EffectKind, e: Error) -> SceneError {
        SceneError::field(self.field(effect), e.to_string())
    }
}

/// A loss, the model that produced it, and each effect's share of it (`None` when
/// the effects are coupled and the total is not a sum).
pub(crate) struct Evaluation {
    pub loss: EnergyLoss,
    pub model: String,
    pub rule: Rule,
    pub parts: Vec<(EffectKind, Option<f64>)>,
}

fn jkr_impact(
    scene: &Scene,
    work_of_adhesion: f64,
    rule: SeparationRule,
) -> Result<JkrImpact<JkrSphere>, SceneError> {
    let s = JkrSphere::new(
        scene.effective_modulus,
        scene.effective_radius,
        work_of_adhesion,
    )
    .map_err(err)?;
    JkrImpact::new(s, scene.effective_mass)
        .map_err(err)?
        .with_separation(rule)
        .with_tolerance(scene.accuracy)
        .map_err(err)
}

fn build_adhesive(scene: &Scene) -> Result<Option<Adhesive>, SceneError> {
    let (e, r, m) = (
        scene.effective_modulus,
        scene.effective_radius,
        scene.effective_mass,
    );
    let acc = scene.accuracy;
    let Some(a) = scene.adhesion.as_ref().filter(|a| a.work_of_adhesion > 0.0) else {
        return Ok(None);
    };
    let jkr_kind = match a.separation {
        SeparationRule::FixedGrip => AdhesionKind::JkrFixedGrip,
        SeparationRule::LoadControlled => AdhesionKind::JkrLoadControlled,
    };
    Ok(Some(match (scene.target.gradation, a.range) {
        (Some((k, c)), _) => {
            let g = GradedSphere::new(c, k, r, a.work_of_adhesion).map_err(err)?;
            let model = JkrImpact::new(g, m)
                .map_err(err)?
                .with_separation(a.separation)
                .with_tolerance(acc)
                .map_err(err)?;
            Adhesive {
                model: AdhesiveModel::Graded(model),
                kind: AdhesionKind::GradedJkr,
                why: "JKR on a power-law graded medium (5.47)-(5.51); Maugis-Dugdale is not available for graded media".into(),
            }
        }
        (None, AdhesionRange::Jkr) => Adhesive {
            model: AdhesiveModel::Jkr(jkr_impact(scene, a.work_of_adhesion, a.separation)?),
            kind: jkr_kind,
            why: "JKR: no range of adhesion given".into(),
        },
        (None, AdhesionRange::TaborParameter(lambda)) => {
            let md = JkrSphere::new(e, r, a.work_of_adhesion)
                .and_then(|sphere| MaugisContact::new(sphere, lambda))
                .and_then(|contact| MaugisDugdaleImpact::new(contact, m))
                .map_err(err)?
                .with_tolerance(acc)
                .map_err(err)?;
            if lambda <= LAMBDA_1 {
                Adhesive {
                    model: AdhesiveModel::Maugis(md),
                    kind: AdhesionKind::MaugisDugdale,
                    why: format!(
                        "Maugis-Dugdale case-1 closed form (5.44): Lambda = {lambda:e} <= Lambda1"
                    ),
                }
            } else {
                let w = normalized_loss(lambda, acc).map_err(err)?;
                // relative to the fixed-grip JKR loss, the Λ → ∞ limit of the
                // Maugis-Dugdale loss (seed 000 Fig. 5.2)
                let difference = (1.0 - w.loss_over_jkr).abs();
                if difference < acc {
                    // the stand-in is that limit: the fixed-grip rule (a range with
                    // the load-controlled rule is refused when the scene is read)
                    Adhesive {
                        model: AdhesiveModel::Jkr(jkr_impact(
                            scene,
                            a.work_of_adhesion,
                            SeparationRule::FixedGrip,
                        )?),
                        kind: AdhesionKind::MaugisDugdale,
                        why: format!("JKR closed form (fixed grip), standing in for Maugis-Dugdale: its loss at Lambda = {lambda:e} differs from JKR by {difference:e} < accuracy {acc:e}"),
                    }
                } else {
                    Adhesive {
                        model: AdhesiveModel::Maugis(md),
                        kind: AdhesionKind::MaugisDugdale,
                        why: format!("Maugis-Dugdale, numerical (case {}): Lambda = {lambda:e}, differs from JKR by {difference:e} >= accuracy {acc:e}", w.case.number()),
                    }
                }
            }
        }
    }))
}

fn build_plastic(scene: &Scene) -> Result<Option<Plastic>, SceneError> {
    let (e, r, m) = (
        scene.effective_modulus,
        scene.effective_radius,
        scene.effective_mass,
    );
    let Some(sy) = scene.yield_stress() else {
        return Ok(None);
    };
    let in_yield = |e: Error| SceneError::field(scene.yield_stress_field(), e.to_string());
    Ok(Some(match scene.plasticity {
        PlasticityModel::Thornton => Plastic::Thornton(
            PlasticImpact::new(
                PlasticContact::new(e, r, sy).map_err(in_yield)?,
                Thornton,
                m,
            )
            .map_err(err)?,
        ),
        PlasticityModel::Auto | PlasticityModel::Interpolation => Plastic::Interpolation(
            PlasticImpact::new(
                PlasticContact::new(e, r, sy).map_err(in_yield)?,
                Interpolation::default(),
                m,
            )
            .map_err(err)?,
        ),
        PlasticityModel::JacksonGreen => Plastic::JacksonGreen(Box::new(
            PlasticContact::new(e, r, sy)
                .and_then(|contact| JacksonGreen::new(contact, scene.plastic_poisson_ratio()))
                .map_err(in_yield)?
                .impact(m, SimulationSettings::default())
                .map_err(err)?,
        )),
        PlasticityModel::DimensionlessFit => {
            let rho = scene.sphere.density.ok_or_else(|| {
                SceneError::field(
                    "sphere.density",
                    "the dimensionless fit needs the sphere's density",
                )
            })?;
            Plastic::Fit(DimensionlessFit::new(e, sy, rho, m).map_err(in_yield)?)
        }
    }))
}

impl Models {
    /// Builds every model the scene's parameters call for.
    pub(crate) fn build(scene: &Scene) -> Result<Models, SceneError> {
        // the elastic contact first: its errors (an overflowing force coefficient)
        // concern the moduli or the gradation
        let elastic = ElasticImpact::new(
            match scene.target.gradation {
                Some((k, c)) => ElasticContact::graded_sphere(c, k, scene.effective_radius)
                    .map_err(|e| {
                        SceneError::field("target.gradation.modulus_factor", e.to_string())
                    })?,
                None => ElasticContact::hertz(scene.effective_modulus, scene.effective_radius)
                    .map_err(|e| {
                        SceneError::field(
                            "sphere.youngs_modulus",
                            format!(
                                "with the target's, E* = {:e} Pa and R = {:e} m: {e}",
                                scene.effective_modulus, scene.effective_radius
                            ),
                        )
                    })?,
            },
            scene.effective_mass,
        )
        .map_err(err)?;
        let adhesive = build_adhesive(scene)?;
        let plastic = build_plastic(scene)?;
        let (visco, visco_kind) = match crate::visco_contact::build(scene)? {
            Ok(v) => {
                let kind = v.as_ref().map(|v| v.kind);
                (v, kind)
            }
            Err(kind) => (None, Some(kind)),
        };
        let candidates = EffectSet {
            adhesion: adhesive.as_ref().map(|a| a.kind),
            plasticity: plastic.as_ref().map(Plastic::kind),
            viscoelasticity: visco_kind,
            graded: scene.target.gradation.is_some(),
            superposition_requested: scene.adhesive_plasticity == AdhesivePlasticity::Superposition,
        };
        // every refusal is structural: the full set is the worst case
        let fields = EffectFields::of(scene);
        rule(&candidates).map_err(|r| SceneError::field(fields.field(r.effect), r.message))?;
        let homogeneous_adhesion = adhesive
            .as_ref()
            .filter(|a| a.kind != AdhesionKind::GradedJkr)
            .and(scene.adhesion.as_ref());
        let (adhesive_interpolation, jkr_fixed_grip) = match (
            homogeneous_adhesion,
            scene.yield_stress(),
            &plastic,
        ) {
            (Some(a), Some(sy), Some(p)) => {
                let ai = JkrSphere::new(
                    scene.effective_modulus,
                    scene.effective_radius,
                    a.work_of_adhesion,
                )
                .and_then(|sphere| AdhesivePlasticContact::from_yield_stress(sphere, sy))
                .and_then(|contact| {
                    AdhesiveInterpolationImpact::new(contact, scene.effective_mass)
                });
                let ai = match (ai, p.kind()) {
                        (Ok(ai), _) => Some(ai),
                        // the rule needs it: the scene is outside its range
                        (Err(e), PlasticityKind::Interpolation)
                            if !candidates.superposition_requested =>
                        {
                            return Err(SceneError::field(
                                "adhesion.work_of_adhesion",
                                format!("adhesion with plasticity (the adhesive interpolation model (5.111)-(5.126)): {e}"),
                            ))
                        }
                        // only used to measure the superposition's error
                        (Err(_), _) => None,
                    };
                (
                    ai,
                    Some(jkr_impact(
                        scene,
                        a.work_of_adhesion,
                        SeparationRule::FixedGrip,
                    )?),
                )
            }
            _ => (None, None),
        };
        let viscous_adhesive = match (&adhesive, &visco) {
            (Some(a), Some(v)) if v.kind == ViscoKind::KelvinVoigt => {
                let (_, eta_c) = v.kelvin_voigt.ok_or_else(|| {
                    err(Error::Model {
                        model: "scene",
                        message: "a Kelvin-Voigt contact without its viscous coefficient".into(),
                    })
                })?;
                Some(crate::viscous_adhesive::build(scene, a, eta_c)?)
            }
            _ => None,
        };

        Ok(Models {
            mass: scene.effective_mass,
            accuracy: scene.accuracy,
            elastic,
            adhesive,
            plastic,
            adhesive_interpolation,
            jkr_fixed_grip,
            visco,
            viscous_adhesive,
            fields,
            candidates,
        })
    }

    fn missing(what: &str) -> SceneError {
        err(Error::Model {
            model: "scene",
            message: format!("internal: the {what} model was not built"),
        })
    }

    fn adhesive_model(&self) -> Result<&(dyn ImpactModel + Send + Sync), SceneError> {
        self.adhesive
            .as_ref()
            .map(|a| a.model.model())
            .ok_or_else(|| Self::missing("adhesive"))
    }

    fn plastic_model(&self) -> Result<&(dyn ImpactModel + Send + Sync), SceneError> {
        self.plastic
            .as_ref()
            .map(|p| p.model() as &(dyn ImpactModel + Send + Sync))
            .ok_or_else(|| Self::missing("plastic"))
    }

    fn visco_model(&self) -> Result<&(dyn ImpactModel + Send + Sync), SceneError> {
        self.visco
            .as_ref()
            .map(|v| v.model.as_ref())
            .ok_or_else(|| Self::missing("viscoelastic"))
    }

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
    fn plastic_part(
        &self,
        set: &EffectSet,
        speed: f64,
    ) -> Result<(EnergyLoss, String), SceneError> {
        let f = self.fields;
        let plastic_error = |e| f.error(EffectKind::Plasticity, e);
        let plastic = self.plastic_model()?;
        let pl = plastic.energy_loss(speed).map_err(plastic_error)?;
        let Some(ai) = self.coupled_plastic_part(set) else {
            return Ok((pl, plastic.name()));
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
        let name = format!(
            "plastic part of the adhesive interpolation model (5.111)-(5.126), at least {}",
            plastic.name()
        );
        let cost = coupled.cost + elastic_part.cost + pl.cost;
        let error_estimate =
            coupled.error_estimate + elastic_part.error_estimate + pl.error_estimate;
        Ok(if excess >= pl.joules {
            (
                EnergyLoss {
                    joules: excess,
                    error_estimate,
                    branch: format!(
                        "plastic excess of {} over {}",
                        coupled.branch, elastic_part.branch
                    ),
                    cost,
                },
                name,
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
                loss: self.elastic.energy_loss(speed).map_err(err)?,
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
            Rule::AdhesiveInterpolation | Rule::AdhesivePlasticExcess | Rule::Superposition => {
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
                let coupled_rest = set.adhesion.is_some()
                    && set.viscoelasticity == Some(crate::combination::ViscoKind::KelvinVoigt);
                let (mut inner, (kind, extra, name), as_fraction) = if set.plasticity.is_some()
                    && (set.viscoelasticity.is_none() || coupled_rest)
                {
                    let (l, name) = self.plastic_part(set, speed)?;
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
                inner.rule = r;
                inner.parts.push((kind, Some(share)));
                Ok(inner)
            }
        }
    }
}

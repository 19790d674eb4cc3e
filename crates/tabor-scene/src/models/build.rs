//! Building the models a scene can use, once per scene, from its validated inputs.

use super::types::{Adhesive, AdhesiveModel, EffectFields, Models, Plastic, Visco};
use crate::combination::{rule, AdhesionKind, EffectKind, EffectSet, PlasticityKind, ViscoKind};
use crate::error::SceneError;
use crate::inputs::{AdhesionRange, AdhesivePlasticity, Body, Inputs, PlasticModel};
use tabor_dynamics::SimulationSettings;
use tabor_elastic::{ElasticContact, ElasticImpact};
use tabor_jkr::{GradedSphere, JkrImpact, JkrSphere, SeparationRule};
use tabor_maugis::{normalized_loss, MaugisContact, MaugisDugdaleImpact, LAMBDA_1};
use tabor_numerics::tolerance::MODEL_ACCURACY_FLOOR;
use tabor_plastic::{
    AdhesiveInterpolationImpact, AdhesivePlasticContact, DimensionlessFit, Interpolation,
    JacksonGreen, PlasticContact, PlasticImpact, Thornton,
};
use tabor_restitution::Error;
use tabor_visco::contact::{Body as ViscoBody, ViscoelasticContact};
use tabor_viscoadhesive::{AdhesiveImpact, ViscoadhesiveImpact};

fn err(e: Error) -> SceneError {
    SceneError::model(e)
}

fn jkr_impact(
    scene: &Inputs,
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

fn build_adhesive(scene: &Inputs) -> Result<Option<Adhesive>, SceneError> {
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
            let sphere = JkrSphere::new(e, r, a.work_of_adhesion).map_err(err)?;
            let md = MaugisContact::new(sphere, lambda)
                .and_then(|contact| MaugisDugdaleImpact::new(contact, m))
                .map_err(err)?
                .with_tolerance(acc)
                .map_err(err)?;
            if lambda <= LAMBDA_1 {
                Adhesive {
                    model: AdhesiveModel::Maugis(md, sphere),
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
                        model: AdhesiveModel::Maugis(md, sphere),
                        kind: AdhesionKind::MaugisDugdale,
                        why: format!("Maugis-Dugdale, numerical (case {}): Lambda = {lambda:e}, differs from JKR by {difference:e} >= accuracy {acc:e}", w.case.number()),
                    }
                }
            }
        }
    }))
}

fn build_plastic(scene: &Inputs) -> Result<Option<Plastic>, SceneError> {
    let (e, r, m) = (
        scene.effective_modulus,
        scene.effective_radius,
        scene.effective_mass,
    );
    let Some(sy) = scene.yield_stress() else {
        return Ok(None);
    };
    let in_yield = |e: Error| SceneError::field_model(scene.yield_stress_field(), e);
    Ok(Some(match scene.plasticity {
        Some(PlasticModel::Thornton) => Plastic::Thornton(
            PlasticImpact::new(
                PlasticContact::new(e, r, sy).map_err(in_yield)?,
                Thornton,
                m,
            )
            .map_err(err)?,
        ),
        None | Some(PlasticModel::Interpolation) => Plastic::Interpolation(
            PlasticImpact::new(
                PlasticContact::new(e, r, sy).map_err(in_yield)?,
                Interpolation::default(),
                m,
            )
            .map_err(err)?,
        ),
        Some(PlasticModel::JacksonGreen) => Plastic::JacksonGreen(Box::new(
            PlasticContact::new(e, r, sy)
                .and_then(|contact| JacksonGreen::new(contact, scene.plastic_poisson_ratio()))
                .map_err(in_yield)?
                .impact(
                    m,
                    // the scene's accuracy, as every other model it builds
                    SimulationSettings::with_tolerance(scene.accuracy).map_err(err)?,
                )
                .map_err(err)?,
        )),
        Some(PlasticModel::DimensionlessFit) => {
            let rho = scene.sphere.density.ok_or_else(|| {
                SceneError::field(
                    "sphere.density",
                    "the dimensionless fit needs the sphere's density",
                )
            })?;
            Plastic::Fit(DimensionlessFit::new(e, sy, rho, m).map_err(in_yield)?)
        }
        Some(adhesive @ (PlasticModel::AdhesiveInterpolation | PlasticModel::Superposition)) => {
            return Err(SceneError::field(
                "plasticity.model",
                format!("\"{adhesive}\" includes adhesion: give a non-adhesive model and adhesive_model"),
            ))
        }
    }))
}

impl Models {
    /// Builds every model the scene's parameters call for.
    pub(crate) fn build(scene: &Inputs) -> Result<Models, SceneError> {
        // the elastic contact first: its errors (an overflowing force coefficient)
        // concern the moduli or the gradation
        let elastic = ElasticImpact::new(
            match scene.target.gradation {
                Some((k, c)) => ElasticContact::graded_sphere(c, k, scene.effective_radius)
                    .map_err(|e| SceneError::field_model("target.gradation.modulus_factor", e))?,
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
        let (visco, visco_kind) = match build_visco(scene)? {
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
            damping: scene.damping.is_some(),
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
                                format!("adhesion with plasticity (the adhesive interpolation model (5.111)-(5.126)): {e}; the model does not cover this scene: set [plasticity] adhesive_model = \"superposition\" to add the adhesive and the plastic losses instead (Willert 2020 (5.109), reported with a warning)"),
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
                Some(build_viscous_adhesive(scene, a, eta_c)?)
            }
            _ => None,
        };

        let damped = super::types::Damped::build(scene, adhesive.as_ref(), plastic.as_ref())?;
        Ok(Models {
            damped,
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
}

fn body(section: &str, b: &Body) -> Result<ViscoBody, SceneError> {
    ViscoBody::new(
        b.material.youngs_modulus(),
        b.material.poisson_ratio(),
        b.viscosity,
    )
    .map_err(|e| SceneError::field_model(format!("{section}.viscosity"), e))
}

/// The scene's viscoelastic contact model, by the correspondence principle
/// (`tabor_visco::contact`: the contact compliance is the sum of both bodies'
/// (1 − ν²)/E(s)), `None` when neither body is viscous;
/// `Err(ViscoKind::TwoRelaxationTimes)` inside for two viscous bodies with
/// different relaxation times (the combination table refuses them).
fn build_visco(scene: &Inputs) -> Result<Result<Option<Visco>, ViscoKind>, SceneError> {
    if scene.sphere.viscosity.is_none() && scene.target.viscosity.is_none() {
        return Ok(Ok(None));
    }
    let field = if scene.target.viscosity.is_some() {
        "target.viscosity"
    } else {
        "sphere.viscosity"
    };
    let in_field = |e: Error| SceneError::field_model(field, e);
    let contact = match ViscoelasticContact::of(
        &body("sphere", &scene.sphere)?,
        &body("target", &scene.target)?,
    ) {
        Ok(c) => c,
        // two relaxation times (the only error of a valid pair of bodies)
        Err(_) => return Ok(Err(ViscoKind::TwoRelaxationTimes)),
    };
    let (kind, kelvin_voigt, why) = match contact {
        ViscoelasticContact::Elastic { .. } => return Ok(Ok(None)),
        ViscoelasticContact::StandardMedium {
            relaxed_modulus,
            branch_modulus,
            viscosity,
        } => (
            ViscoKind::StandardMedium,
            None,
            format!("one Kelvin-Voigt body on an elastic one: a standard medium (5.75) with G_inf = {relaxed_modulus:e} Pa, G1 = {branch_modulus:e} Pa, eta = {viscosity:e} Pa s (correspondence principle)"),
        ),
        ViscoelasticContact::KelvinVoigt {
            shear_modulus,
            viscosity,
        } => (
            ViscoKind::KelvinVoigt,
            // E*(s) = 4 (G* + η* s)
            Some((4.0 * shear_modulus, 4.0 * viscosity)),
            format!("two Kelvin-Voigt bodies with equal relaxation times: a Kelvin-Voigt contact (5.64) with G* = {shear_modulus:e} Pa, eta* = {viscosity:e} Pa s (correspondence principle)"),
        ),
    };
    // at the scene's accuracy, as every other model it builds (floored at
    // MODEL_ACCURACY_FLOOR, as the viscous-adhesive model)
    let Some(model) = contact
        .impact_model_with_tolerance(
            scene.effective_radius,
            scene.effective_mass,
            scene.accuracy.max(MODEL_ACCURACY_FLOOR),
        )
        .map_err(in_field)?
    else {
        return Ok(Ok(None));
    };
    Ok(Ok(Some(Visco {
        kind,
        model,
        kelvin_voigt,
        why,
    })))
}

/// Adhesion + viscoelasticity on a Kelvin-Voigt contact: the coupled model of
/// `tabor-viscoadhesive` (adhesive force + Kuwabara-Kono force (5.66) with the
/// adhesive contact radius) on the scene's own adhesive impact and the contact's
/// viscous coefficient η_c (Pa s) of E*(s) = E* + η_c s.
fn build_viscous_adhesive(
    scene: &Inputs,
    adhesive: &Adhesive,
    contact_viscosity: f64,
) -> Result<ViscoadhesiveImpact, SceneError> {
    let impact = match &adhesive.model {
        // the JKR stand-in of Maugis-Dugdale is fixed grip (its impact's rule)
        AdhesiveModel::Jkr(j) => AdhesiveImpact::Jkr(j.clone()),
        AdhesiveModel::Maugis(md, sphere) => AdhesiveImpact::MaugisDugdale(md.clone(), *sphere),
        AdhesiveModel::Graded(_) => {
            return Err(err(Error::Model {
                model: "scene",
                message: "adhesion on a graded medium with viscoelasticity has no model".into(),
            }))
        }
    };
    ViscoadhesiveImpact::of(
        impact,
        contact_viscosity,
        scene.accuracy.max(MODEL_ACCURACY_FLOOR),
    )
    .map_err(|e| EffectFields::of(scene).error(EffectKind::Viscoelasticity, e))
}

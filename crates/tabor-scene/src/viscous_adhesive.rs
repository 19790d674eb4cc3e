//! Adhesion + viscoelasticity on a Kelvin-Voigt contact: the coupled model of
//! `tabor-viscoadhesive` (adhesive force + Kuwabara-Kono force (5.66) with the
//! adhesive contact radius), built from the scene.

use crate::combination::AdhesionKind;
use crate::models::{err, Adhesive, AdhesiveModel, Models};
use crate::scene::{Scene, SceneError};
use tabor_dynamics::ForceLaw;
use tabor_jkr::SeparationRule;
use tabor_restitution::Error;
use tabor_viscoadhesive::{Adhesion, ViscoadhesiveImpact};

/// The coupled model for the scene's adhesive model and the contact's viscous
/// coefficient η_c (Pa s) of E*(s) = E* + η_c s.
pub(crate) fn build(
    scene: &Scene,
    adhesive: &Adhesive,
    contact_viscosity: f64,
) -> Result<ViscoadhesiveImpact, SceneError> {
    let adhesion = match (&adhesive.model, adhesive.kind) {
        (AdhesiveModel::Maugis(md), _) => Adhesion::MaugisDugdale {
            tabor_parameter: md.tabor_parameter(),
        },
        // the JKR stand-in of Maugis-Dugdale is fixed grip
        (AdhesiveModel::Jkr(_), AdhesionKind::MaugisDugdale | AdhesionKind::JkrFixedGrip) => {
            Adhesion::Jkr(SeparationRule::FixedGrip)
        }
        (AdhesiveModel::Jkr(_), _) => Adhesion::Jkr(SeparationRule::LoadControlled),
        (AdhesiveModel::Graded(_), _) => {
            return Err(err(Error::Model {
                model: "scene",
                message: "adhesion on a graded medium with viscoelasticity has no model".into(),
            }))
        }
    };
    let work = scene
        .adhesion
        .as_ref()
        .map_or(f64::NAN, |a| a.work_of_adhesion);
    ViscoadhesiveImpact::new(
        scene.effective_modulus,
        scene.effective_radius,
        scene.effective_mass,
        work,
        adhesion,
        contact_viscosity,
        scene.accuracy.max(1e-12),
    )
    .map_err(|e| {
        SceneError::field(
            crate::models::EffectFields::of(scene)
                .field(crate::combination::EffectKind::Viscoelasticity),
            e.to_string(),
        )
    })
}

/// The coupled force law, for `Scene::simulate`.
pub(crate) fn force_law(models: &Models) -> Result<Box<dyn ForceLaw>, SceneError> {
    match &models.viscous_adhesive {
        Some(m) => Ok(Box::new(m.force_law())),
        None => Err(err(Error::Model {
            model: "scene",
            message: "internal: the viscous-adhesive model was not built".into(),
        })),
    }
}

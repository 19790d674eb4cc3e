//! The viscoelastic contact of the scene's two bodies, by the correspondence
//! principle (`tabor_visco::contact`): the contact compliance is the sum of both
//! bodies' (1 − ν²)/E(s).

use crate::combination::ViscoKind;
use crate::models::Visco;
use crate::scene::{Body, Scene, SceneError};
use tabor_restitution::Error;
use tabor_visco::contact::{Body as ViscoBody, ViscoelasticContact};

fn body(section: &str, b: &Body) -> Result<ViscoBody, SceneError> {
    ViscoBody::new(
        b.material.youngs_modulus(),
        b.material.poisson_ratio(),
        b.viscosity,
    )
    .map_err(|e| SceneError::field(format!("{section}.viscosity"), e.to_string()))
}

/// The scene's viscoelastic contact model, `None` when neither body is viscous;
/// `Err(ViscoKind::TwoRelaxationTimes)` inside for two viscous bodies with
/// different relaxation times (the combination table refuses them).
pub(crate) fn build(scene: &Scene) -> Result<Result<Option<Visco>, ViscoKind>, SceneError> {
    if scene.sphere.viscosity.is_none() && scene.target.viscosity.is_none() {
        return Ok(Ok(None));
    }
    let field = if scene.target.viscosity.is_some() {
        "target.viscosity"
    } else {
        "sphere.viscosity"
    };
    let in_field = |e: Error| SceneError::field(field, e.to_string());
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
    let Some(model) = contact
        .impact_model(scene.effective_radius, scene.effective_mass)
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

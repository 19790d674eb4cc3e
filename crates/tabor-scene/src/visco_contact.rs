//! The viscoelastic contact of the scene's two bodies (correspondence principle).
//! Temporary: moves to `tabor_visco::contact`.

use crate::combination::ViscoKind;
use crate::models::{err, Visco};
use crate::scene::{Scene, SceneError};
use tabor_visco::models::{KelvinVoigtSphere, MaxwellBranchSphere};
use tabor_visco::SphereModel;

pub(crate) fn build(scene: &Scene) -> Result<Option<Visco>, SceneError> {
    let body = |b: &crate::scene::Body| (b.material.plane_strain_modulus(), b.viscosity);
    let (ms, es) = body(&scene.sphere);
    let (mt, et) = body(&scene.target);
    let (r, m) = (scene.effective_radius, scene.effective_mass);
    Ok(match (es, et) {
        (None, None) => None,
        (Some(eta), None) | (None, Some(eta)) => {
            let (ma, mb) = if es.is_some() { (ms, mt) } else { (mt, ms) };
            let (ga, gb) = (ma / 4.0, mb / 4.0);
            let relaxed = ga * gb / (ga + gb);
            let branch = gb * gb / (ga + gb);
            let viscosity = eta * (gb / (ga + gb)).powi(2);
            Some(Visco {
                kind: ViscoKind::StandardMedium,
                model: Box::new(
                    MaxwellBranchSphere::standard(relaxed, branch, viscosity, r, m).map_err(err)?,
                ),
                kelvin_voigt: None,
                why: format!("one Kelvin-Voigt body on an elastic one: a standard medium, G_inf = {relaxed:e} Pa, G1 = {branch:e} Pa, eta = {viscosity:e} Pa s"),
            })
        }
        (Some(a), Some(b)) => {
            let (ta, tb) = (4.0 * a / ms, 4.0 * b / mt);
            let e = scene.effective_modulus;
            if (ta - tb).abs() <= 1e-12 * ta.max(tb) {
                let g = e / 4.0;
                Some(Visco {
                    kind: ViscoKind::KelvinVoigt,
                    model: Box::new(
                        KelvinVoigtSphere::new(g, g * ta, r, m, SphereModel::Rigorous)
                            .map_err(err)?,
                    ),
                    kelvin_voigt: Some((e, e * ta)),
                    why: format!("two Kelvin-Voigt bodies with equal relaxation times {ta:e} s: a Kelvin-Voigt contact"),
                })
            } else {
                Some(Visco {
                    kind: ViscoKind::TwoRelaxationTimes,
                    model: Box::new(
                        KelvinVoigtSphere::new(e / 4.0, e / 4.0 * ta, r, m, SphereModel::Rigorous)
                            .map_err(err)?,
                    ),
                    kelvin_voigt: None,
                    why: format!("relaxation times {ta:e} s and {tb:e} s"),
                })
            }
        }
    })
}

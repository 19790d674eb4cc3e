//! The scene's `[friction]` as LAMMPS keywords: `pair granular`'s tangential,
//! rolling and twisting sub-models (`tangential mindlin NULL x_γ,t μ rolling sds k γ
//! μ twisting marshall`, written by `tabor_tangential::Friction::lammps_keywords`),
//! the same keywords for `pair_style tabor` (which reads them with `pair
//! granular`'s syntax), and what the export leaves out of them.

use crate::report::{model_err, ExportError, Limit};
use tabor_scene::Scene;
use tabor_tangential::{Friction, TangentialModel};

/// The sub-model keywords of a frictionless central impact.
pub const FRICTIONLESS: &str = "tangential linear_nohistory 0.0 0.0";

/// Whether LAMMPS's `mindlin NULL` gives the scene's Mindlin stiffness 8G*, when
/// it computes G* from the modulus `e` and Poisson ratio `nu` of one material:
/// G = E/(2(1 + ν)), 1/G* = 2(2 − ν)/G (`pair granular`'s mixing of one
/// `pair_coeff`; `pair_style tabor` computes E*(1 − ν)/(2(2 − ν)) from its
/// E* = E/(2(1 − ν²)), the same). Only when the scene gives no stiffness of its own.
pub(crate) fn null_stiffness_fits(scene: &Scene, f: &Friction, e: f64, nu: f64) -> bool {
    let given = scene
        .data()
        .friction
        .as_ref()
        .is_some_and(|f| f.tangential_stiffness.is_some());
    let mindlin = matches!(
        f.tangential.model,
        TangentialModel::Mindlin
            | TangentialModel::MindlinRescale
            | TangentialModel::MindlinDeresiewicz
    );
    let lammps = 8.0 * e / (4.0 * (1.0 + nu) * (2.0 - nu));
    !given && mindlin && (lammps / f.tangential.stiffness - 1.0).abs() <= 1e-9
}

/// The scene's validated friction, `None` without a `[friction]` section, for
/// `pair granular` (`plugin` false) or `pair_style tabor` (`plugin` true).
/// Mindlin-Deresiewicz micro-slip is refused for `pair granular`, none of whose
/// tangential models has it; `pair_style tabor` takes it
/// (`tangential mindlin_deresiewicz`, the per-contact spring bed of
/// `tabor_tangential::Friction::step`).
pub(crate) fn scene_friction(scene: &Scene, plugin: bool) -> Result<Option<Friction>, ExportError> {
    let friction = scene.friction().map_err(model_err)?;
    if !plugin
        && friction.is_some_and(|f| f.tangential.model == TangentialModel::MindlinDeresiewicz)
    {
        return Err(ExportError::Unrepresentable {
            effect: "tangential = \"mindlin_deresiewicz\"".into(),
            reason: "no tangential model of LAMMPS's pair granular has Mindlin-Deresiewicz micro-slip (its mindlin is a no-slip spring on the total displacement); export with --plugin for pair_style tabor's tangential mindlin_deresiewicz, or with tangential = \"mindlin\" for pair granular's nearest model".into(),
        });
    }
    Ok(friction)
}

/// What the friction keywords of a calibrated export leave out: the Coulomb limit
/// μ F_n0 uses LAMMPS's `jkr` pull-off of the exported γ where the scene's is
/// another, and a tangential damping x_γ,t multiplies the calibrated η_n0.
pub(crate) fn friction_limits(
    f: Option<&Friction>,
    pull_off: Option<(f64, f64)>,
    damped: bool,
) -> Vec<Limit> {
    let Some(f) = f else {
        return vec![Limit {
            effect: "friction".into(),
            from_speed: None,
            note: format!("tangential, rolling and twisting contact: the scene has no [friction], the fragment is for frictionless central impact ({FRICTIONLESS}); set your own"),
        }];
    };
    let mut limits = Vec::new();
    if let Some((lammps, tabor)) = pull_off.filter(|(l, t)| (l / t - 1.0).abs() > 1e-6) {
        limits.push(Limit {
            effect: "friction limit".into(),
            from_speed: None,
            note: format!(
                "the Coulomb limits mu F_n0 with F_n0 = |F_n + 2 F_pulloff|: LAMMPS's jkr pull-off is 3 pi gamma R* = {lammps:.4e} N with the exported gamma, tabor's oblique model uses {tabor:.4e} N; sliding, rolling and twisting limits near zero normal load differ accordingly"
            ),
        });
    }
    if damped && f.tangential.damping_ratio > 0.0 {
        limits.push(Limit {
            effect: "tangential damping".into(),
            from_speed: None,
            note: format!(
                "x_gamma,t = {} multiplies LAMMPS's normal damping, here the calibrated eta_n0, not the scene's own viscous damping",
                f.tangential.damping_ratio
            ),
        });
    }
    limits
}

//! From a tabor scene to calibrated LAMMPS `pair_style granular` parameters
//! (`crates/tabor-lammps/README.md` derives every calibration): a short pipeline of
//! [`crate::calibrate`] (what the scene calls for, the calibrations), then
//! [`crate::verify`] (the claim), then [`crate::fragment`] (the text).

use crate::calibrate::{
    calibrate_adhesion, calibrate_damping, lammps_sticking_velocity, setup, undamped_model, Setup,
};
use crate::fragment::{commands, keywords};
use crate::friction::{friction_limits, null_stiffness_fits, scene_friction, FRICTIONLESS};
use crate::impact::STICKING_TOLERANCE;
use crate::law::GranularModel;
use crate::report::{
    model_err, Bodies, Export, ExportError, Limit, Parameter, Scope, TIME_STEP_FRACTION,
};
use crate::verify::verify;
use tabor_scene::Scene;

/// Exports `scene` to LAMMPS, calibrated at `speed` (m/s; default the scene's
/// `[impact] speed`). Errors: [`ExportError::Unrepresentable`] for what LAMMPS
/// cannot represent or a calibration that cannot be made, decided before any
/// calibration where possible.
pub fn export(scene: &Scene, speed: Option<f64>) -> Result<Export, ExportError> {
    let s = setup(scene, speed)?;
    refuse_damping_with_adhesion(scene, s.adhesive)?;
    let mut parameters = vec![modulus_parameter(&s)];
    let mut limits = Vec::new();
    let adhesion = if s.adhesive {
        Some(calibrate_adhesion(&s, &mut parameters, &mut limits)?)
    } else {
        None
    };
    let v_ref = s
        .v_scene
        .or(adhesion.as_ref().map(|a| 2.0 * a.sticking_velocity))
        .unwrap_or(1.0)
        .min(s.v_small_strain);
    // tabor's sticking velocity: of the whole scene when a damping is calibrated
    // (the joint fit matches it), else of its elastic-adhesive part
    let sticking = match &adhesion {
        Some(_) if !s.lossy.is_empty() => match scene.sticking_velocity() {
            Ok(v) => v,
            Err(e) => {
                limits.push(Limit {
                    effect: "sticking velocity".into(),
                    from_speed: None,
                    note: format!("tabor's sticking velocity of the scene could not be computed ({e}): the damping matches the restitution at the calibration speed only"),
                });
                None
            }
        },
        Some(a) => Some(a.sticking_velocity),
        None => None,
    };
    let undamped = undamped_model(&s, adhesion.as_ref().map(|a| a.gamma));
    let model = if let Some(d) = scene.damping {
        dem_damping(undamped, d, &mut parameters)?
    } else if s.lossy.is_empty() {
        undamped
    } else {
        let (model, eta) = calibrate_damping(&s, undamped, sticking, &mut parameters)?;
        parameters.push(eta);
        model
    };
    // the Tsuji form on Hertz is self-similar: its restitution holds at every speed
    let speed_independent_damping = scene.damping.is_none_or(|d| {
        adhesion.is_none() && d.model() != Some(tabor_scene::DampingModel::Viscoelastic)
    });
    let scope = if s.lossy.is_empty()
        && speed_independent_damping
        && adhesion.as_ref().is_none_or(|a| a.speed_independent)
    {
        Scope::SpeedIndependent
    } else {
        Scope::CalibrationSpeed
    };
    let lammps_sticking = if s.adhesive {
        lammps_sticking_velocity(&model, &s, sticking.unwrap_or(v_ref), STICKING_TOLERANCE)?
    } else {
        None
    };
    let verification = verify(&s, &model, scope, v_ref, (sticking, lammps_sticking))?;
    limits.extend(verification.limits);
    let friction = scene_friction(scene, false)?;
    let friction_kw = friction.as_ref().map(|f| {
        f.lammps_keywords(
            s.geometry == crate::report::Geometry::Pair
                && null_stiffness_fits(scene, f, s.e_lammps, s.nu),
        )
    });
    limits.extend(friction_limits(
        friction.as_ref(),
        adhesion
            .as_ref()
            .map(|a| (lammps_pull_off(&model, s.r), a.pull_off)),
        !s.lossy.is_empty(),
    ));
    let contact_time = contact_time(&s, &model, v_ref)?;
    let keywords = keywords(&model, friction_kw.as_deref().unwrap_or(FRICTIONLESS));
    Ok(Export {
        scene: scene.name.clone(),
        geometry: s.geometry,
        model,
        commands: commands(s.geometry, &keywords),
        model_keywords: keywords,
        friction: friction_kw,
        parameters,
        reproduces: verification.claim,
        does_not_reproduce: limits,
        bodies: Bodies {
            sphere_radius: scene.sphere.radius.unwrap_or(f64::NAN),
            sphere_density: scene.sphere.density.unwrap_or(f64::NAN),
            target_radius: scene.target.radius,
            target_density: scene.target.radius.and(scene.target.density),
        },
        effective_modulus: s.e_star,
        effective_radius: s.r,
        effective_mass: s.m,
        small_strain_speed: s.v_small_strain,
        sticking_velocity: sticking,
        lammps_sticking_velocity: lammps_sticking,
        contact_time,
        time_step: contact_time * TIME_STEP_FRACTION,
        comparison: verification.comparison,
    })
}

/// The scene's DEM damping law (`[damping]`) on the LAMMPS normal model
/// `undamped`: `damping <model>` with the scene's value as LAMMPS reads it (η_n0,
/// the Tsuji damping value, the restitution e), no calibration (the law is
/// LAMMPS's own; LAMMPS documentation `pair_granular`, "Damping"); the refusal
/// with adhesion is [`refuse_damping_with_adhesion`]'s, before any calibration.
fn dem_damping(
    undamped: GranularModel,
    damping: tabor_scene::NormalDamping,
    parameters: &mut Vec<Parameter>,
) -> Result<GranularModel, ExportError> {
    use crate::law::DampingModel as Lammps;
    use tabor_scene::DampingModel as Dem;
    let model = damping
        .model()
        .ok_or_else(|| model_err("a Kuwabara-Kono damping is not a [damping] law"))?;
    let lammps = match model {
        Dem::Viscoelastic => Lammps::Viscoelastic,
        Dem::Tsuji => Lammps::Tsuji,
        Dem::CoeffRestitution => Lammps::CoeffRestitution,
    };
    let value = damping.value();
    parameters.push(Parameter {
        name: "damping".into(),
        value,
        unit: match model {
            Dem::Viscoelastic => "1/(m s)".into(),
            _ => "1".into(),
        },
        derivation: format!(
            "the scene's [damping] {model} as LAMMPS reads it ({}): no calibration, the law is LAMMPS's own",
            damping.describe()
        ),
    });
    Ok(GranularModel {
        damp: value,
        damping: lammps,
        limit_damping: false,
        ..undamped
    })
}

/// LAMMPS refuses `damping tsuji` and `coeff_restitution` with `jkr` (an error at
/// `pair_coeff`): so does the export of a scene whose adhesion enters
/// (`adhesive`), naming the rule tabor uses instead.
fn refuse_damping_with_adhesion(scene: &Scene, adhesive: bool) -> Result<(), ExportError> {
    let Some(model) = scene.damping.and_then(|d| d.model()) else {
        return Ok(());
    };
    if adhesive && model != tabor_scene::DampingModel::Viscoelastic {
        return Err(crate::report::unrepresentable(
            &format!("damping {model} with adhesion"),
            format!("LAMMPS refuses damping {model} with a cohesive normal model (jkr, dmt: an error at pair_coeff; lammps/lammps issue 4180); tabor computes it with the Tsuji damping of the adhesive contact radius, k_n = (4/3) E* a (the dem-damping rule): use damping viscoelastic, a scene without adhesion, or the --plugin export once pair_style tabor takes a damping keyword"),
        ));
    }
    Ok(())
}

/// The pull-off force of LAMMPS's `jkr` (N): 3πγR*.
fn lammps_pull_off(model: &GranularModel, r: f64) -> f64 {
    match model.normal {
        crate::law::NormalModel::Jkr { surface_energy, .. } => {
            3.0 * std::f64::consts::PI * surface_energy * r
        }
        _ => 0.0,
    }
}

/// E = 2E*(1 − ν²), so that one `pair_coeff * *` mixes back to the scene's E*.
fn modulus_parameter(s: &Setup) -> Parameter {
    Parameter {
        name: "E".into(),
        value: s.e_lammps,
        unit: "Pa".into(),
        derivation: format!(
            "E = 2 E* (1 - nu^2) with E* = {:.6e} Pa{} and nu = {}: one pair_coeff * * (or the wall) mixes 1/E_mix = 2 (1 - nu^2)/E, so E_mix = E*",
            s.e_star,
            if s.scene.target.gradation.is_some() {
                " (c_N of the k = 0 graded medium)"
            } else {
                " (1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2)"
            },
            s.nu
        ),
    }
}

/// The LAMMPS model's contact time at `v_ref` (s), or where it sticks the elastic
/// Hertz contact time of seed 000 (5.12).
fn contact_time(s: &Setup, model: &GranularModel, v_ref: f64) -> Result<f64, ExportError> {
    let reference = model.impact(s.r, s.m, v_ref).map_err(model_err)?;
    Ok(match reference.contact_time {
        Some(t) if !reference.sticks => t,
        _ => 2.868 * (s.m * s.m / (s.r * s.e_star * s.e_star * v_ref)).powf(0.2),
    })
}

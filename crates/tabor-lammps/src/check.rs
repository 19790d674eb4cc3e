//! `--check`: the restitution LAMMPS will really produce for a user's granular
//! model line, before running LAMMPS (nominal versus achieved).

use crate::calibrate::small_strain_speed;
use crate::law::GranularModel;
use crate::parse::{parse_line, substitute_variables, LineKind, ParsedLine};
use crate::report::{time_step_error, unrepresentable, ExportError, TIME_STEP_ERROR};
use serde::Serialize;
use tabor_scene::Scene;

/// The predicted restitution at one speed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CheckPoint {
    /// Impact speed (m/s).
    pub speed: f64,
    /// The restitution of the LAMMPS model (time-domain integration of its force
    /// law, no time-step error); 0 when the bodies stick.
    pub lammps: f64,
    /// Whether the LAMMPS model sticks.
    pub sticks: bool,
    /// The contact time of the LAMMPS model (s), when it rebounds.
    pub contact_time: Option<f64>,
    /// tabor's restitution for the scene at this speed, for comparison (0 when
    /// the bodies stick; `None` where the scene has no answer).
    pub tabor: Option<f64>,
    /// The error of a LAMMPS run against `lammps` at a time step of at most
    /// contact time/5000 ([`crate::time_step_error`]).
    pub time_step_error: f64,
}

/// The prediction for a checked line.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Check {
    /// The line as given.
    pub line: String,
    /// The line as read, LAMMPS variables substituted.
    pub substituted: String,
    /// What was read from it.
    pub parsed: ParsedLine,
    /// The restitution the line names (`tsuji`, `coeff_restitution`), if any.
    pub nominal_restitution: Option<f64>,
    /// The damping prefactor coefficient LAMMPS derives (α for tsuji and
    /// coeff_restitution, the coefficient itself otherwise).
    pub damping_coefficient: f64,
    /// Effective radius (m) and reduced mass (kg) of the scene's bodies.
    pub effective_radius: f64,
    /// Reduced mass (kg).
    pub effective_mass: f64,
    /// The prediction at the requested speed.
    pub at_speed: CheckPoint,
    /// The prediction over a decade of speeds around it, inside small strain.
    pub decade: Vec<CheckPoint>,
    /// The highest speed inside small strain (Hertz d_max = R*, m/s): the decade
    /// stops there.
    pub small_strain_speed: f64,
    /// The error of a LAMMPS run against the prediction at a time step of at most
    /// contact time/5000, away from the sticking velocity (see each point's).
    pub time_step_error: f64,
    /// Notes (ignored sub-models, what the line does).
    pub notes: Vec<String>,
}

fn point(model: &GranularModel, scene: &Scene, v: f64) -> Result<CheckPoint, ExportError> {
    let s = model
        .impact(scene.effective_radius, scene.effective_mass, v)
        .map_err(|e| ExportError::Model(e.to_string()))?;
    let tabor = scene.restitution_with_error(v).ok().map(|(e, _)| e);
    let e = if s.sticks { 0.0 } else { s.restitution };
    let adhesive = matches!(model.normal, crate::law::NormalModel::Jkr { surface_energy, .. } if surface_energy > 0.0);
    Ok(CheckPoint {
        time_step_error: time_step_error(e, adhesive),
        speed: v,
        lammps: if s.sticks { 0.0 } else { s.restitution },
        sticks: s.sticks,
        contact_time: s.contact_time,
        tabor,
    })
}

/// Predicts the restitution of LAMMPS line `line` (a `pair_coeff` or a
/// `fix wall/gran granular` line, or a legacy `pair_style gran/…` or
/// `fix wall/gran hooke|hooke/history|hertz/history` line, with LAMMPS variables
/// `$x`, `${name}` taken from `variables`) for the bodies of `scene` at `speed`
/// (m/s; default the scene's speed, else 1 m/s), and over a decade around it
/// inside small strain. A speed beyond small strain is refused.
pub fn check(
    scene: &Scene,
    line: &str,
    speed: Option<f64>,
    variables: &[(String, String)],
) -> Result<Check, ExportError> {
    let substituted = substitute_variables(line, variables)
        .map_err(|e| ExportError::Model(format!("--check: {e}")))?;
    let parsed =
        parse_line(&substituted).map_err(|e| ExportError::Model(format!("--check: {e}")))?;
    let wall = scene.target.radius.is_none();
    let mut notes = Vec::new();
    match (parsed.kind, wall) {
        (LineKind::PairCoeff, true) => notes.push(
            "the scene's target is flat: the pair line is evaluated for the scene's sphere-on-flat contact (a wall/gran line would be the LAMMPS equivalent)".into(),
        ),
        (LineKind::WallGran, false) => notes.push(
            "the scene's target is a sphere: the wall/gran line is evaluated for the scene's sphere-sphere contact".into(),
        ),
        _ => {}
    }
    if parsed.style != "granular" {
        notes.push(format!(
            "legacy style {}: read as pair_style granular's {} with damping {} (LAMMPS's pair_gran formulas)",
            parsed.style,
            parsed.model.normal.keyword(),
            parsed.model.damping.keyword()
        ));
    }
    for i in &parsed.ignored {
        notes.push(format!(
            "\"{i}\" has no effect on a frictionless central impact"
        ));
    }
    let e_star = scene
        .target
        .gradation
        .map_or(scene.effective_modulus, |(_, c)| c);
    let v_max = small_strain_speed(e_star, scene.effective_radius, scene.effective_mass);
    let v = speed.or(scene.speed).unwrap_or(1.0_f64.min(v_max));
    if v > v_max {
        return Err(unrepresentable(
            "an impact beyond small strain",
            format!("at {v:.4e} m/s the Hertz overlap d_max of the scene's bodies exceeds their effective radius (from {v_max:.4e} m/s on): give --speed below it"),
        ));
    }
    let model = parsed.model;
    let at_speed = point(&model, scene, v)?;
    let decade = (-4..=4)
        .map(|k| v * 10f64.powf(f64::from(k) / 8.0))
        .filter(|&u| u <= v_max)
        .map(|u| point(&model, scene, u))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Check {
        line: line.trim().to_string(),
        substituted: substituted.trim().to_string(),
        nominal_restitution: model.nominal_restitution(),
        damping_coefficient: model.damping_coefficient(),
        effective_radius: scene.effective_radius,
        effective_mass: scene.effective_mass,
        parsed,
        at_speed,
        decade,
        small_strain_speed: v_max,
        time_step_error: TIME_STEP_ERROR,
        notes,
    })
}

//! `--check` of a `pair_style tabor` line (`pair_coeff I J maugis E* w Λ | range h
//! | stress s0 …`, `jkr/fixed-grip|jkr/load-controlled E* w …`, or the material
//! form `material E ν γ` before the model, one material against itself): the restitution
//! LAMMPS will produce with the plugin for the scene's bodies — the plugin's own
//! force law (`tabor_ffi`, built from the line exactly as `pair_coeff` builds it)
//! integrated by velocity Verlet at the time step the plugin was verified at — beside
//! tabor's restitution for the scene, and the Tabor parameter the scene's contact
//! gets from the line.

use crate::calibrate::small_strain_speed;
use crate::parse::substitute_variables;
use crate::plugin::{PluginModel, PLUGIN_RESTITUTION_ERROR, PLUGIN_TIME_STEP_FRACTION};
use crate::report::{unrepresentable, ExportError};
use serde::Serialize;
use tabor_ffi::{law_from_params, ContactLaw, TaborHistory, TaborLawParams};
use tabor_scene::Scene;

/// The prediction at one speed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PluginCheckPoint {
    /// Impact speed (m/s).
    pub speed: f64,
    /// The restitution LAMMPS produces with the line (velocity Verlet of the
    /// plugin's force law at contact time/20000); 0 when the bodies stick.
    pub lammps: f64,
    /// tabor's restitution for the scene (0 when it sticks; `None` where the scene
    /// has no answer).
    pub tabor: Option<f64>,
}

/// The prediction for a `pair_style tabor` line.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PluginCheck {
    /// The line as given.
    pub line: String,
    /// The line as read, LAMMPS variables substituted.
    pub substituted: String,
    /// The normal law of the line.
    pub model: PluginModel,
    /// E* (Pa) of the line.
    pub effective_modulus: f64,
    /// w (J/m²) of the line.
    pub work_of_adhesion: f64,
    /// The Dugdale range h (m) of `range h` or `stress s0` (h = w/s0).
    pub dugdale_range: Option<f64>,
    /// The Tabor parameter the scene's contact gets (the line's Λ, or d_n(R*)/h).
    pub tabor_parameter: Option<f64>,
    /// Effective radius (m) and reduced mass (kg) of the scene's bodies.
    pub effective_radius: f64,
    /// Reduced mass (kg).
    pub effective_mass: f64,
    /// The prediction at the requested speed.
    pub at_speed: PluginCheckPoint,
    /// The prediction over a decade of speeds around it, inside small strain.
    pub decade: Vec<PluginCheckPoint>,
    /// The bound of a LAMMPS run at timestep ≤ contact time/20000 against `lammps`.
    pub time_step_error: f64,
    /// Notes (keywords without effect on a central impact).
    pub notes: Vec<String>,
}

/// Whether `line` is a `pair_style tabor` line (`pair_coeff I J` followed by one of
/// the plugin's adhesive models, whose names `pair_style granular` does not use,
/// or by the material form `material E nu gamma` and one of them).
pub fn is_plugin_line(line: &str) -> bool {
    let w: Vec<&str> = line.split_whitespace().collect();
    let model = if w.get(3) == Some(&"material") { 7 } else { 3 };
    w.len() > model
        && w[0] == "pair_coeff"
        && matches!(
            w[model],
            "maugis" | "jkr/fixed-grip" | "jkr/load-controlled"
        )
}

fn bad(message: String) -> ExportError {
    ExportError::Model(format!("--check: {message}"))
}

/// Reads the line as `pair_coeff` of the plugin reads it, into the C ABI's
/// parameters; the friction keywords are skipped with a note.
fn read(line: &str, notes: &mut Vec<String>) -> Result<(PluginModel, TaborLawParams), ExportError> {
    let w: Vec<&str> = line.split_whitespace().collect();
    let num = |i: &mut usize, what: &str| -> Result<f64, ExportError> {
        let t = w.get(*i).ok_or_else(|| bad(format!("missing {what}")))?;
        *i += 1;
        t.parse::<f64>()
            .map_err(|_| bad(format!("{what}: expected a number, got {t}")))
    };
    // the material form: E, nu, gamma of one material (the pair's own line, or
    // both types of one material), E* = E/(2(1 − nu²)) and w = 2 gamma as the
    // plugin computes them
    let material = if w[3] == "material" {
        let mut j = 4;
        let (e, nu, gamma) = (num(&mut j, "E")?, num(&mut j, "nu")?, num(&mut j, "gamma")?);
        if !(e > 0.0 && e.is_finite()) {
            return Err(bad(format!(
                "material E = {e}: must be positive and finite"
            )));
        }
        if !(nu > -1.0 && nu < 0.5) {
            return Err(bad(format!("material nu = {nu}: must be in (-1, 0.5)")));
        }
        if !(gamma >= 0.0 && gamma.is_finite()) {
            return Err(bad(format!(
                "material gamma = {gamma}: must be non-negative and finite"
            )));
        }
        // as the plugin's tabor_mix_modulus of a material with itself, to the bit
        let f = (1.0 - nu * nu) / e;
        let (e_star, w_adh) = (1.0 / (f + f), 2.0 * gamma);
        notes.push(format!(
            "material {e} {nu} {gamma}: one material against itself, E* = E/(2(1 - nu^2)) \
             = {e_star:e} Pa, w = 2 gamma = {w_adh:e} J/m^2 (a pair of two materials is \
             mixed by the plugin from both types' lines)"
        ));
        Some((e_star, w_adh))
    } else {
        None
    };
    let at = if material.is_some() { 7 } else { 3 };
    let mut i = at + 1;
    let (model, code) = match w[at] {
        "maugis" => (PluginModel::Maugis, tabor_ffi::TABOR_MODEL_MAUGIS_DUGDALE),
        "jkr/fixed-grip" => (
            PluginModel::JkrFixedGrip,
            tabor_ffi::TABOR_MODEL_JKR_FIXED_GRIP,
        ),
        _ => (
            PluginModel::JkrLoadControlled,
            tabor_ffi::TABOR_MODEL_JKR_LOAD_CONTROLLED,
        ),
    };
    let mut p = TaborLawParams {
        model: code,
        effective_modulus: match material {
            Some((e_star, _)) => e_star,
            None => num(&mut i, "E*")?,
        },
        effective_radius: 1.0,
        work_of_adhesion: match material {
            Some((_, w_adh)) => w_adh,
            None => num(&mut i, "w")?,
        },
        tabor_parameter: 0.0,
        damping_time: 0.0,
        damping_model: tabor_ffi::TABOR_DAMPING_KUWABARA_KONO,
        damping_value: 0.0,
        dugdale_range: 0.0,
        cohesive_stress: 0.0,
    };
    if model == PluginModel::Maugis && !matches!(w.get(i), Some(&"range") | Some(&"stress")) {
        p.tabor_parameter = num(&mut i, "Lambda (or range h | stress s0)")?;
    }
    while let Some(key) = w.get(i).copied() {
        let start = i;
        i += 1;
        let skipped = match key {
            "range" | "stress" if model == PluginModel::Maugis => {
                let v = num(&mut i, key)?;
                if key == "range" {
                    p.dugdale_range = v;
                } else {
                    p.cohesive_stress = v;
                }
                0
            }
            "damping" => {
                match w.get(i).copied() {
                    Some(m @ ("viscoelastic" | "tsuji" | "coeff_restitution")) => {
                        i += 1;
                        p.damping_model = match m {
                            "viscoelastic" => tabor_ffi::TABOR_DAMPING_VISCOELASTIC,
                            "tsuji" => tabor_ffi::TABOR_DAMPING_TSUJI,
                            _ => tabor_ffi::TABOR_DAMPING_COEFF_RESTITUTION,
                        };
                        p.damping_value = num(&mut i, "damping value")?;
                    }
                    _ => p.damping_time = num(&mut i, "damping time A")?,
                }
                0
            }
            "poisson" => 1,
            "tangential" | "rolling" => 4,
            "twisting" if w.get(i) == Some(&"sds") => 4,
            "twisting" => 1,
            other => return Err(bad(format!("unknown keyword {other} of pair_style tabor"))),
        };
        if skipped > 0 {
            i = (i + skipped).min(w.len());
            notes.push(format!(
                "\"{}\" has no effect on a frictionless central impact",
                w[start..i].join(" ")
            ));
        }
    }
    Ok((model, p))
}

/// The restitution of one central impact of reduced mass `m` at `v` (m/s) under
/// `law` at effective radius `r`, by velocity Verlet with time step `dt` (s) from
/// outside the interaction range, as LAMMPS runs the plugin; 0 when the bodies
/// are still together after 50 contact times.
fn verlet(law: &ContactLaw, r: f64, m: f64, v: f64, dt: f64, tc: f64) -> Result<f64, ExportError> {
    let err = |e: tabor_restitution::Error| ExportError::Model(e.to_string());
    let s = law.scales(r).map_err(err)?;
    let mut h = TaborHistory::default();
    let mut d = -law.interaction_range_at(&s) - 20.0 * v * dt;
    let mut rate = v;
    let mut f = law
        .evaluate_with_mass(&s, d, rate, m, &mut h)
        .map_err(err)?
        .force;
    let mut formed = false;
    let steps = ((50.0 * tc + (-d) / v) / dt) as usize;
    for _ in 0..steps {
        let half = rate - 0.5 * dt * f / m;
        d += dt * half;
        f = law
            .evaluate_with_mass(&s, d, half, m, &mut h)
            .map_err(err)?
            .force;
        rate = half - 0.5 * dt * f / m;
        formed |= h.contact != 0.0;
        if formed && h.contact == 0.0 && rate < 0.0 {
            return Ok(-rate / v);
        }
    }
    Ok(0.0)
}

/// Predicts the restitution of the `pair_style tabor` line `line` for the bodies
/// of `scene` (a sphere pair) at `speed` (m/s; default the scene's, else 1 m/s) and
/// over a decade around it inside small strain.
pub fn check_plugin(
    scene: &Scene,
    line: &str,
    speed: Option<f64>,
    variables: &[(String, String)],
) -> Result<PluginCheck, ExportError> {
    let substituted = substitute_variables(line, variables).map_err(|e| bad(e.to_string()))?;
    if scene.target.radius.is_none() {
        return Err(unrepresentable(
            "a flat target with pair_style tabor",
            "the plugin's pair style acts between spheres".into(),
        ));
    }
    let mut notes = Vec::new();
    let (model, mut p) = read(&substituted, &mut notes)?;
    let (r, m) = (scene.effective_radius, scene.effective_mass);
    p.effective_radius = r;
    let law = law_from_params(&p).map_err(|e| bad(e.to_string()))?;
    let scales = law.scales(r).map_err(|e| bad(e.to_string()))?;
    let dugdale_range = match (p.dugdale_range, p.cohesive_stress) {
        (h, _) if h > 0.0 => Some(h),
        (_, s0) if s0 > 0.0 => Some(p.work_of_adhesion / s0),
        _ => None,
    };
    let e_star = p.effective_modulus;
    let v_max = small_strain_speed(e_star, r, m);
    let v = speed.or(scene.speed).unwrap_or(1.0_f64.min(v_max));
    if v > v_max {
        return Err(unrepresentable(
            "an impact beyond small strain",
            format!("at {v:.4e} m/s the Hertz overlap of the scene's bodies exceeds their effective radius (from {v_max:.4e} m/s on): give --speed below it"),
        ));
    }
    let point = |u: f64| -> Result<PluginCheckPoint, ExportError> {
        // seed 000 (5.12): t_c = 2.868 (m*²/(R* E*² v))^(1/5)
        let tc = 2.868 * (m * m / (r * e_star * e_star * u)).powf(0.2);
        let tabor = scene
            .outcome_at(u)
            .ok()
            .map(|o| if o.sticks { 0.0 } else { o.restitution });
        Ok(PluginCheckPoint {
            speed: u,
            lammps: verlet(&law, r, m, u, tc * PLUGIN_TIME_STEP_FRACTION, tc)?,
            tabor,
        })
    };
    let decade = (-4..=4)
        .map(|k| v * 10f64.powf(f64::from(k) / 8.0))
        .filter(|&u| u <= v_max)
        .map(point)
        .collect::<Result<Vec<_>, _>>()?;
    Ok(PluginCheck {
        line: line.trim().to_string(),
        substituted: substituted.trim().to_string(),
        model,
        effective_modulus: e_star,
        work_of_adhesion: p.work_of_adhesion,
        dugdale_range,
        tabor_parameter: law.tabor_parameter_at(&scales),
        effective_radius: r,
        effective_mass: m,
        at_speed: point(v)?,
        decade,
        time_step_error: PLUGIN_RESTITUTION_ERROR,
        notes,
    })
}

//! From a tabor scene to calibrated LAMMPS `pair_style granular` parameters
//! (`crates/tabor-lammps/README.md` derives every calibration).

use crate::law::{jkr_pulloff_distance, DampingModel, GranularModel, NormalModel};
use serde::Serialize;
use std::fmt;
use tabor_jkr::{JkrImpact, JkrSphere, SeparationRule};
use tabor_numerics::root_finding::brent;
use tabor_numerics::RootTolerance;
use tabor_scene::{Outcome, Scene};

/// The time step, as a fraction of the contact time, at which the claims of an
/// export are verified by running LAMMPS (`integrations/lammps`).
pub const TIME_STEP_FRACTION: f64 = 1.0 / 5000.0;

/// The error LAMMPS's velocity-Verlet integration adds to the restitution at a time
/// step of [`TIME_STEP_FRACTION`] of the contact time (measured in
/// `integrations/lammps`: at most a few 1e-4 away from the sticking velocity).
pub const TIME_STEP_ERROR: f64 = 1e-3;

/// The relative error of the adhesive (`jkr`) loss per impact that LAMMPS's time
/// stepping adds at a time step of [`TIME_STEP_FRACTION`] of the contact time
/// (measured 1.0e-3 for pairs, 1.3e-3 for walls in `integrations/lammps`; it
/// falls as the time step). Through e² = 1 − 2W/(m v²) it becomes an error of
/// e of (1 − e²)/(2e) times this, which grows without bound at the sticking
/// velocity.
pub const LOSS_STEP_ERROR: f64 = 2e-3;

/// The error of a LAMMPS restitution `e` (> 0) at a time step of
/// [`TIME_STEP_FRACTION`] of the contact time: [`TIME_STEP_ERROR`], or for an
/// adhesive contact the larger [`LOSS_STEP_ERROR`] (1 − e²)/(2e) near the sticking
/// velocity (infinite at e = 0, where sticking or not is decided by the step).
pub fn time_step_error(restitution: f64, adhesive: bool) -> f64 {
    if !adhesive {
        return TIME_STEP_ERROR;
    }
    if restitution <= 0.0 {
        return f64::INFINITY;
    }
    let e = restitution.min(1.0);
    TIME_STEP_ERROR.max(LOSS_STEP_ERROR * (1.0 - e * e) / (2.0 * e))
}

/// A calibration error below which an export claims to reproduce tabor's
/// restitution (it is then small against [`TIME_STEP_ERROR`]).
pub const REPRODUCES: f64 = 1e-4;

/// Why a scene cannot be exported.
#[derive(Clone, Debug, PartialEq)]
pub enum ExportError {
    /// An effect of the scene that LAMMPS's granular models cannot represent.
    Unrepresentable {
        /// The effect (for example "graded medium").
        effect: String,
        /// Why (one line).
        reason: String,
    },
    /// The scene or a model computation failed.
    Model(String),
}

impl fmt::Display for ExportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExportError::Unrepresentable { effect, reason } => {
                write!(f, "LAMMPS cannot represent {effect}: {reason}")
            }
            ExportError::Model(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for ExportError {}

fn model_err(e: impl fmt::Display) -> ExportError {
    ExportError::Model(e.to_string())
}

fn unrepresentable(effect: &str, reason: String) -> ExportError {
    ExportError::Unrepresentable {
        effect: effect.into(),
        reason,
    }
}

/// Sphere–sphere (`pair_coeff`) or sphere–wall (`fix wall/gran`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Geometry {
    /// Two spheres: `pair_style granular` + `pair_coeff * *`.
    Pair,
    /// A sphere on a flat target: `fix … wall/gran granular … zplane`.
    Wall,
}

/// One calibrated or derived number of an export.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Parameter {
    /// Its name in the LAMMPS line (or a derived quantity).
    pub name: String,
    /// Value (SI).
    pub value: f64,
    /// Unit.
    pub unit: String,
    /// How it was obtained (one line).
    pub derivation: String,
}

/// Over which speeds an export reproduces tabor's restitution.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scope {
    /// e(v) and the sticking velocity at every speed (a speed-independent loss).
    EverySpeed,
    /// The restitution at the calibration speed only.
    CalibrationSpeed,
}

/// tabor's and the LAMMPS model's restitution at one speed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SpeedComparison {
    /// Impact speed (m/s).
    pub speed: f64,
    /// tabor's restitution (`Scene::outcome_at`).
    pub tabor: f64,
    /// The restitution of the exported LAMMPS model, integrated in the time domain
    /// without time-step error ([`GranularModel::impact`]).
    pub lammps: f64,
    /// lammps − tabor.
    pub difference: f64,
    /// The error the export states for a LAMMPS run at this speed with a time step
    /// of at most [`TIME_STEP_FRACTION`] of the contact time:
    /// |difference| + [`time_step_error`] (infinite where LAMMPS's model sticks
    /// only marginally: at e = 0 both stick, up to the step's resolution of v_c).
    pub tolerance: f64,
}

/// What an export reproduces.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Claim {
    /// Every speed or the calibration speed.
    pub scope: Scope,
    /// The reference (calibration) speed (m/s).
    pub speed: f64,
    /// Speeds around the reference where |lammps − tabor| ≤ [`REPRODUCES`]
    /// (on the comparison grid), m/s.
    pub reproduced_range: [f64; 2],
    /// Speeds around the reference where the restitution is within 1 % of tabor's.
    pub one_percent_range: [f64; 2],
    /// Largest |lammps − tabor| over a decade of speeds around the reference
    /// (v/√10 … v√10).
    pub decade_error: f64,
    /// The sentence the fragment prints.
    pub statement: String,
}

/// The masses and radii LAMMPS needs for the bodies (`set atom … diameter … density`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bodies {
    /// Sphere radius (m).
    pub sphere_radius: f64,
    /// Sphere density (kg/m³).
    pub sphere_density: f64,
    /// Target radius (m), `None` for a wall.
    pub target_radius: Option<f64>,
    /// Target density (kg/m³), `None` for a wall.
    pub target_density: Option<f64>,
}

/// A scene exported to LAMMPS.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Export {
    /// The scene's name.
    pub scene: String,
    /// Pair or wall.
    pub geometry: Geometry,
    /// The LAMMPS normal contact.
    pub model: GranularModel,
    /// The model keywords (after `pair_coeff * *` or `wall/gran granular`).
    pub model_keywords: String,
    /// The LAMMPS commands of the fragment.
    pub commands: Vec<String>,
    /// Every calibrated number and how it was obtained.
    pub parameters: Vec<Parameter>,
    /// What LAMMPS reproduces.
    pub reproduces: Claim,
    /// What it does not.
    pub does_not_reproduce: Vec<String>,
    /// The bodies.
    pub bodies: Bodies,
    /// Effective modulus E* (Pa) of the exported contact.
    pub effective_modulus: f64,
    /// Effective radius (m).
    pub effective_radius: f64,
    /// Reduced mass (kg).
    pub effective_mass: f64,
    /// tabor's sticking velocity (m/s), when the bodies can stick.
    pub sticking_velocity: Option<f64>,
    /// The LAMMPS model's sticking velocity (m/s), when it can stick.
    pub lammps_sticking_velocity: Option<f64>,
    /// Contact time of the LAMMPS model at the reference speed (s).
    pub contact_time: f64,
    /// The time step at which the claims are verified, `TIME_STEP_FRACTION` × contact time (s).
    pub time_step: f64,
    /// tabor versus the LAMMPS model over speeds around the reference.
    pub comparison: Vec<SpeedComparison>,
}

/// The load-controlled JKR loss (J) of LAMMPS's `jkr` with work of adhesion `w`:
/// the integral of F dd from first touch to the load-controlled pull-off point
/// (`tabor_jkr`, seed 000 (5.36) integrated to F' = 0), ∝ w^(5/3).
pub fn load_controlled_loss(
    modulus: f64,
    radius: f64,
    mass: f64,
    w: f64,
) -> Result<f64, ExportError> {
    let s = JkrSphere::new(modulus, radius, w).map_err(model_err)?;
    let l = JkrImpact::new(s, mass)
        .map_err(model_err)?
        .with_separation(SeparationRule::LoadControlled)
        .with_tolerance(1e-13)
        .map_err(model_err)?
        .adhesive_energy_loss()
        .map_err(model_err)?;
    Ok(l.joules)
}

/// The work of adhesion w_eff whose load-controlled JKR loss is `loss` (J):
/// w_eff = w_ref (loss / W_LC(w_ref))^(3/5), exact because W_LC ∝ w^(5/3) at fixed
/// E*, R (seed 000 (5.36): loss ∝ F_n d_n ∝ w · w^(2/3)).
pub fn effective_work_of_adhesion(
    modulus: f64,
    radius: f64,
    mass: f64,
    loss: f64,
    w_ref: f64,
) -> Result<f64, ExportError> {
    let l = load_controlled_loss(modulus, radius, mass, w_ref)?;
    Ok(w_ref * (loss / l).powf(0.6))
}

fn outcome(scene: &Scene, v: f64) -> Result<Outcome, ExportError> {
    scene.outcome_at(v).map_err(model_err)
}

/// The scene with only its elastic and adhesive effects (yield stresses and
/// viscosities removed): its loss is the adhesive loss LAMMPS's `jkr` must carry.
fn adhesive_only(scene: &Scene) -> Result<Scene, ExportError> {
    let mut data = scene.data().clone();
    for b in [&mut data.sphere, &mut data.target] {
        b.yield_stress = None;
        b.viscosity = None;
    }
    data.plasticity = None;
    let mut s = Scene::from_data(data).map_err(model_err)?;
    s.name = scene.name.clone();
    Ok(s)
}

fn used(o: &Outcome, name: &str) -> bool {
    o.effects.iter().any(|e| e.name == name && e.used)
}

fn fmt_num(x: f64) -> String {
    format!("{x:.10e}")
}

/// The model keywords LAMMPS reads after `pair_coeff * *` or `wall/gran granular`.
pub fn model_keywords(m: &GranularModel) -> String {
    let normal = match m.normal {
        NormalModel::Hooke { stiffness } => {
            format!("hooke {} {}", fmt_num(stiffness), fmt_num(m.damp))
        }
        NormalModel::Hertz { stiffness } => {
            format!("hertz {} {}", fmt_num(stiffness), fmt_num(m.damp))
        }
        NormalModel::HertzMaterial {
            youngs_modulus,
            poisson_ratio,
        } => format!(
            "hertz/material {} {} {}",
            fmt_num(youngs_modulus),
            fmt_num(m.damp),
            poisson_ratio
        ),
        NormalModel::Dmt {
            youngs_modulus,
            poisson_ratio,
            surface_energy,
        } => format!(
            "dmt {} {} {} {}",
            fmt_num(youngs_modulus),
            fmt_num(m.damp),
            poisson_ratio,
            fmt_num(surface_energy)
        ),
        NormalModel::Jkr {
            youngs_modulus,
            poisson_ratio,
            surface_energy,
        } => format!(
            "jkr {} {} {} {}",
            fmt_num(youngs_modulus),
            fmt_num(m.damp),
            poisson_ratio,
            fmt_num(surface_energy)
        ),
    };
    format!(
        "{normal} tangential linear_nohistory 0.0 0.0 damping {}{}",
        m.damping.keyword(),
        if m.limit_damping {
            " limit_damping"
        } else {
            ""
        }
    )
}

/// Speeds v_ref · 10^(k/8), k = −16 … 16 (two decades each side).
fn grid(v_ref: f64) -> Vec<f64> {
    (-16..=16)
        .map(|k| v_ref * 10f64.powf(k as f64 / 8.0))
        .collect()
}

/// The contiguous range of grid speeds around index `mid` where `ok` holds.
fn contiguous(speeds: &[f64], ok: &[bool], mid: usize) -> [f64; 2] {
    if !ok[mid] {
        return [speeds[mid], speeds[mid]];
    }
    let mut lo = mid;
    while lo > 0 && ok[lo - 1] {
        lo -= 1;
    }
    let mut hi = mid;
    while hi + 1 < speeds.len() && ok[hi + 1] {
        hi += 1;
    }
    [speeds[lo], speeds[hi]]
}

/// The restitution of `model` at `v`, 0 when it sticks.
fn lammps_restitution(model: &GranularModel, r: f64, m: f64, v: f64) -> Result<f64, ExportError> {
    let s = model.impact(r, m, v).map_err(model_err)?;
    Ok(if s.sticks { 0.0 } else { s.restitution })
}

/// The sticking velocity of a LAMMPS model (m/s): where its restitution first
/// becomes positive, by bisection between a sticking and a rebounding speed.
fn lammps_sticking_velocity(
    model: &GranularModel,
    r: f64,
    m: f64,
    guess: f64,
) -> Result<Option<f64>, ExportError> {
    sticking_velocity_to(model, r, m, guess, 1e-10)
}

/// [`lammps_sticking_velocity`] to relative tolerance `tol`.
fn sticking_velocity_to(
    model: &GranularModel,
    r: f64,
    m: f64,
    guess: f64,
    tol: f64,
) -> Result<Option<f64>, ExportError> {
    let mut lo = guess;
    let mut tries = 0;
    while lammps_restitution(model, r, m, lo)? > 0.0 {
        lo /= 2.0;
        tries += 1;
        if tries > 60 {
            return Ok(None);
        }
    }
    let mut hi = guess.max(lo * 2.0);
    tries = 0;
    while lammps_restitution(model, r, m, hi)? == 0.0 {
        hi *= 2.0;
        tries += 1;
        if tries > 60 {
            return Err(model_err("the LAMMPS model sticks at every speed tried"));
        }
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if lammps_restitution(model, r, m, mid)? > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo < tol * hi {
            break;
        }
    }
    Ok(Some(0.5 * (lo + hi)))
}

/// `model` with surface energy `gamma` (jkr) and damping coefficient `eta`.
fn with_gamma_eta(model: &GranularModel, gamma: f64, eta: f64) -> GranularModel {
    let mut m = *model;
    if let NormalModel::Jkr {
        youngs_modulus,
        poisson_ratio,
        ..
    } = model.normal
    {
        m.normal = NormalModel::Jkr {
            youngs_modulus,
            poisson_ratio,
            surface_energy: gamma,
        };
    }
    m.damp = eta;
    m
}

/// Brent's root of the restitution of `model(x)` at `v` minus `target` over
/// x ∈ [0, hi·4^k], growing hi until the restitution falls below the target.
fn fit_restitution(
    make: impl Fn(f64) -> GranularModel,
    r: f64,
    m: f64,
    v: f64,
    target: f64,
    hi: f64,
) -> Option<f64> {
    let f = |x: f64| match lammps_restitution(&make(x), r, m, v) {
        Ok(e) => e - target,
        Err(_) => f64::NAN,
    };
    if f(0.0).is_nan() || f(0.0) <= 0.0 {
        return None;
    }
    let mut hi = hi;
    let mut tries = 0;
    while f(hi) > 0.0 {
        hi *= 4.0;
        tries += 1;
        if tries > 40 {
            return None;
        }
    }
    brent(f, 0.0, hi, RootTolerance::relative(1e-12))
        .ok()
        .map(|root| root.value)
}

/// Adhesion with a speed-dependent loss: γ and η_n0 together, such that the LAMMPS
/// model rebounds with tabor's `target` at `v` *and* sticks below tabor's sticking
/// velocity `vc`. For each η, γ(η) matches the restitution; η is then the root of
/// v_c,LAMMPS(γ(η), η) − v_c (η = 0: all loss adhesive, v_c too high; η at the
/// purely viscous fit: γ = 0, v_c → 0). `None` when no bracket exists.
fn fit_gamma_and_eta(
    model: &GranularModel,
    r: f64,
    m: f64,
    v: f64,
    target: f64,
    vc: f64,
    (gamma_scale, eta_scale): (f64, f64),
) -> Option<(f64, f64)> {
    let eta_max = fit_restitution(
        |eta| with_gamma_eta(model, 0.0, eta),
        r,
        m,
        v,
        target,
        eta_scale,
    )?;
    let gamma_of = |eta: f64| {
        fit_restitution(
            |g| with_gamma_eta(model, g, eta),
            r,
            m,
            v,
            target,
            gamma_scale,
        )
    };
    let g = |eta: f64| -> f64 {
        let Some(gamma) = gamma_of(eta) else {
            return f64::NAN;
        };
        match sticking_velocity_to(&with_gamma_eta(model, gamma, eta), r, m, vc, 1e-9) {
            Ok(Some(v_l)) => v_l / vc - 1.0,
            Ok(None) => -1.0,
            Err(_) => f64::NAN,
        }
    };
    let hi = eta_max * (1.0 - 1e-6);
    if !(g(0.0) > 0.0 && g(hi) < 0.0) {
        return None;
    }
    let eta = brent(g, 0.0, hi, RootTolerance::relative(1e-12))
        .ok()?
        .value;
    Some((gamma_of(eta)?, eta))
}

/// Exports `scene` to LAMMPS, calibrated at `speed` (m/s; default the scene's
/// `[impact] speed`). Errors: [`ExportError::Unrepresentable`] for what LAMMPS
/// cannot represent.
pub fn export(scene: &Scene, speed: Option<f64>) -> Result<Export, ExportError> {
    let geometry = if scene.target.radius.is_some() {
        Geometry::Pair
    } else {
        Geometry::Wall
    };
    let mut e_star = scene.effective_modulus;
    if let Some((k, c)) = scene.target.gradation {
        if k != 0.0 {
            return Err(unrepresentable(
                "a graded medium",
                format!("gradation exponent k = {k} != 0: LAMMPS's granular normal models are homogeneous (Hertz, JKR), and a modulus growing as depth^k has no homogeneous equivalent (only k = 0, modulus c_N, has)"),
            ));
        }
        e_star = c;
    }
    let r = scene.effective_radius;
    let m = scene.effective_mass;
    let nu = scene.sphere.material.poisson_ratio();
    // one pair_coeff * * (or the wall) mixes E_mix = E/(2(1-ν²)) = E*
    let e_lammps = 2.0 * e_star * (1.0 - nu * nu);
    let v_scene = speed.or(scene.speed);
    let scene_outcome = v_scene.map(|v| outcome(scene, v)).transpose()?;
    // viscoelasticity whenever a viscosity is given (its loss acts at every speed,
    // even where the scene's outcome drops it because adhesion alone makes the
    // bodies stick); plasticity where the scene uses it at the calibration speed
    let viscous = scene.sphere.viscosity.is_some() || scene.target.viscosity.is_some();
    let plastic = match &scene_outcome {
        Some(o) => used(o, "plasticity"),
        None => scene.yield_stress().is_some(),
    };
    let lossy_effects: Vec<&str> = [(plastic, "plasticity"), (viscous, "viscoelasticity")]
        .into_iter()
        .filter_map(|(on, name)| on.then_some(name))
        .collect();
    if !lossy_effects.is_empty() && v_scene.is_none() {
        return Err(unrepresentable(
            &lossy_effects.join(" and "),
            "LAMMPS's damping reproduces a speed-dependent loss at one impact speed only: give [impact] speed in the scene or --speed".into(),
        ));
    }
    let adhesive = match (&scene.adhesion, &scene_outcome) {
        (Some(a), _) if a.work_of_adhesion == 0.0 => false,
        (Some(_), Some(o)) => used(o, "adhesion"),
        (Some(_), None) => true,
        (None, _) => false,
    };
    let mut parameters = Vec::new();
    let mut not_reproduced = Vec::new();
    parameters.push(Parameter {
        name: "E".into(),
        value: e_lammps,
        unit: "Pa".into(),
        derivation: format!(
            "E = 2 E* (1 - nu^2) with E* = {e_star:.6e} Pa{} and nu = {nu}: one pair_coeff * * (or the wall) mixes 1/E_mix = 2 (1 - nu^2)/E, so E_mix = E*",
            if scene.target.gradation.is_some() { " (c_N of the k = 0 graded medium)" } else { " (1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2)" }
        ),
    });
    // --- adhesion: effective γ from the loss
    let mut gamma = 0.0;
    let mut sticking_tabor = None;
    let mut loss_speed_independent = true;
    if adhesive {
        let sub = adhesive_only(scene)?;
        let a = scene
            .adhesion
            .as_ref()
            .ok_or_else(|| model_err("adhesion expected"))?;
        let vc = sub.sticking_velocity().map_err(model_err)?.ok_or_else(|| {
            model_err("the adhesive part of the scene never sticks: no adhesive loss to calibrate")
        })?;
        let w_a = outcome(&sub, 2.0 * vc)?.energy_loss;
        let w_b = outcome(&sub, 20.0 * vc)?.energy_loss;
        if (w_a - w_b).abs() > 1e-6 * w_a {
            loss_speed_independent = false;
        }
        let w_eff = effective_work_of_adhesion(e_star, r, m, w_a, a.work_of_adhesion)?;
        gamma = 0.5 * w_eff;
        let w_check = load_controlled_loss(e_star, r, m, w_eff)?;
        let source = match (scene.tabor_parameter(), a.separation) {
            (Some(l), _) => format!("Maugis-Dugdale at Lambda = {l:.4e}"),
            (None, SeparationRule::FixedGrip) => "JKR, fixed grip".into(),
            (None, SeparationRule::LoadControlled) => "JKR, load-controlled".into(),
        };
        parameters.push(Parameter {
            name: "gamma".into(),
            value: gamma,
            unit: "J/m^2".into(),
            derivation: format!(
                "gamma = w_eff/2 (LAMMPS's gamma is per surface); w_eff = w (W_tabor/W_LC(w))^(3/5) = {w_eff:.6e} J/m^2 so that LAMMPS's load-controlled JKR loss W_LC(w_eff) = {w_check:.6e} J equals tabor's adhesive loss W_tabor = {w_a:.6e} J ({source}, w = {} J/m^2; relative mismatch {:.1e})",
                a.work_of_adhesion,
                (w_check / w_a - 1.0).abs()
            ),
        });
        sticking_tabor = Some(vc);
        let true_gamma = 0.5 * a.work_of_adhesion;
        if (gamma / true_gamma - 1.0).abs() > 1e-6 {
            not_reproduced.push(format!(
                "the pull-off force: LAMMPS's 3 pi gamma R* = {:.4e} N with the effective gamma, not the {} pull-off force of w = {} J/m^2 (3 pi gamma R* = {:.4e} N at the true gamma); the adhesive force history in contact",
                3.0 * std::f64::consts::PI * gamma * r,
                source,
                a.work_of_adhesion,
                3.0 * std::f64::consts::PI * true_gamma * r
            ));
        }
        if scene.tabor_parameter().is_some() {
            not_reproduced.push("the attraction before contact and the jump-in of the Maugis-Dugdale range: LAMMPS's jkr touches at zero overlap".into());
        }
        parameters.push(Parameter {
            name: "pulloff_distance".into(),
            value: jkr_pulloff_distance(gamma, r, e_star),
            unit: "m".into(),
            derivation: "LAMMPS keeps the jkr contact to the load-controlled point delta = -(3 pi^2 gamma^2 R*/(16 E*^2))^(1/3); the neighbor list must reach it (pair granular extends its cutoff itself)".into(),
        });
    }
    let mut model = GranularModel {
        normal: if adhesive {
            NormalModel::Jkr {
                youngs_modulus: e_lammps,
                poisson_ratio: nu,
                surface_energy: gamma,
            }
        } else {
            NormalModel::HertzMaterial {
                youngs_modulus: e_lammps,
                poisson_ratio: nu,
            }
        },
        damp: 0.0,
        damping: DampingModel::Viscoelastic,
        // limit_damping would also remove jkr's attraction
        limit_damping: !adhesive && !lossy_effects.is_empty(),
    };
    // --- the reference speed
    let v_ref = match (v_scene, sticking_tabor) {
        (Some(v), _) => v,
        (None, Some(vc)) => 2.0 * vc,
        (None, None) => 1.0,
    };
    // --- damping: η_n0 from the restitution at the scene speed
    if !lossy_effects.is_empty() {
        let o = scene_outcome
            .as_ref()
            .ok_or_else(|| model_err("a calibration speed is needed"))?;
        if o.sticks {
            return Err(unrepresentable(
                &lossy_effects.join(" and "),
                format!(
                    "the bodies stick at the calibration speed {:.4e} m/s: a damping calibrated on restitution needs a speed where they rebound (give --speed above the sticking velocity {})",
                    o.impact_speed,
                    o.sticking_velocity.map_or("?".into(), |v| format!("{v:.4e} m/s"))
                ),
            ));
        }
        let target = o.restitution;
        let elastic = model.impact(r, m, v_ref).map_err(model_err)?;
        let e0 = if elastic.sticks {
            0.0
        } else {
            elastic.restitution
        };
        if e0 <= target {
            return Err(model_err(format!(
                "the undamped LAMMPS model already rebounds with {e0:.6} <= tabor's {target:.6} at {v_ref:.4e} m/s: no damping to calibrate"
            )));
        }
        // η scale: 1/(t_c a_max) makes η m a ḋ comparable to the elastic force
        let tc = elastic.contact_time.unwrap_or(f64::NAN);
        let a_max = (r * elastic.max_overlap).sqrt();
        let scale = 1.0 / (tc * a_max);
        let f = |eta: f64| -> f64 {
            let mut mm = model;
            mm.damp = eta;
            match lammps_restitution(&mm, r, m, v_ref) {
                Ok(e) => e - target,
                Err(_) => f64::NAN,
            }
        };
        let mut hi = scale;
        let mut tries = 0;
        while f(hi) > 0.0 {
            hi *= 4.0;
            tries += 1;
            if tries > 40 {
                return Err(model_err(
                    "no damping coefficient found that brings the LAMMPS restitution down to tabor's",
                ));
            }
        }
        let root = brent(f, 0.0, hi, RootTolerance::relative(1e-12)).map_err(model_err)?;
        model.damp = root.value;
        if adhesive {
            if let Some(vc) = o.sticking_velocity {
                if let Some((g2, eta2)) =
                    fit_gamma_and_eta(&model, r, m, v_ref, target, vc, (gamma.max(1e-12), scale))
                {
                    let gamma_adhesive = gamma;
                    model = with_gamma_eta(&model, g2, eta2);
                    for p in parameters.iter_mut() {
                        if p.name == "gamma" {
                            p.value = g2;
                            p.derivation = format!(
                                "gamma and eta_n0 fitted together (Brent in gamma inside Brent in eta_n0, each step a time-domain run of the LAMMPS law) so that LAMMPS rebounds with tabor's {target:.10} at {v_ref:.4e} m/s and sticks below tabor's sticking velocity {vc:.6e} m/s (the adhesive loss alone would give gamma = {:.6e})",
                                gamma_adhesive
                            );
                        }
                        if p.name == "pulloff_distance" {
                            p.value = jkr_pulloff_distance(g2, r, e_star);
                        }
                    }
                }
            }
        }
        let kk = scene
            .target
            .viscosity
            .or(scene.sphere.viscosity)
            .map(|eta| format!("; for comparison, the Kuwabara-Kono value of a Kelvin-Voigt half-space of viscosity eta = {eta:e} Pa s on a rigid partner would be 8 eta/m* = {:.6e} (seed 000 (5.66))", 8.0 * eta / m))
            .unwrap_or_default();
        parameters.push(Parameter {
            name: "eta_n0".into(),
            value: model.damp,
            unit: "1/(m s)".into(),
            derivation: format!(
                "damping viscoelastic F = eta_n0 m* a v_n: eta_n0 solves e_LAMMPS(eta_n0; {v_ref:.4e} m/s) = tabor's {target:.10} ({}) by Brent's method on the time-domain LAMMPS law{}{}{kk}",
                lossy_effects.join(" + "),
                if model.limit_damping { " with limit_damping" } else { " (no limit_damping: LAMMPS refuses it with jkr)" },
                if (model.damp / root.value - 1.0).abs() > 1e-9 { format!("; then refitted with gamma to match the sticking velocity too (eta_n0 = {:.6e} with the adhesive-loss gamma)", root.value) } else { String::new() },
            ),
        });
        not_reproduced.push(format!(
            "the speed dependence of the {} loss: the damping is calibrated at {v_ref:.4e} m/s (see the comparison)",
            lossy_effects.join(" and ")
        ));
        if lossy_effects.contains(&"plasticity") {
            not_reproduced.push("plastic deformation: the residual indentation, the flattened contact and the plastic force history".into());
        }
    }
    not_reproduced.push("tangential, rolling and twisting contact: the fragment is for frictionless central impact (tangential linear_nohistory 0 0); set your own".into());
    if geometry == Geometry::Pair && (scene.sphere.material != scene.target.material) {
        not_reproduced.push("the individual moduli of two different materials: one pair_coeff * * carries the equivalent modulus E = 2 E* (1 - nu^2)".into());
    }
    // --- comparison over speeds
    let speeds = grid(v_ref);
    let mut comparison = Vec::with_capacity(speeds.len());
    for &v in &speeds {
        let t = outcome(scene, v)?;
        let te = if t.sticks { 0.0 } else { t.restitution };
        let le = lammps_restitution(&model, r, m, v)?;
        comparison.push(SpeedComparison {
            speed: v,
            tabor: te,
            lammps: le,
            difference: le - te,
            tolerance: (le - te).abs()
                + if le == 0.0 && te == 0.0 {
                    0.0
                } else {
                    time_step_error(le.max(te), adhesive)
                },
        });
    }
    let mid = speeds.len() / 2;
    let ok_exact: Vec<bool> = comparison
        .iter()
        .map(|c| c.difference.abs() <= REPRODUCES)
        .collect();
    let ok_percent: Vec<bool> = comparison
        .iter()
        .map(|c| {
            c.difference.abs() <= 0.01 * c.tabor.max(1e-300) || (c.tabor == 0.0 && c.lammps == 0.0)
        })
        .collect();
    let reproduced_range = contiguous(&speeds, &ok_exact, mid);
    let coarse = contiguous(&speeds, &ok_percent, mid);
    // refine the 1 % edges between grid points by bisection in log(speed)
    let within = |v: f64| -> Result<bool, ExportError> {
        let t = outcome(scene, v)?;
        let te = if t.sticks { 0.0 } else { t.restitution };
        let le = lammps_restitution(&model, r, m, v)?;
        Ok((le - te).abs() <= 0.01 * te.max(1e-300) || (te == 0.0 && le == 0.0))
    };
    let step = 10f64.powf(1.0 / 8.0);
    let mut one_percent_range = coarse;
    if ok_percent[mid] {
        for (edge, outward) in [(0usize, 1.0 / step), (1usize, step)] {
            let (mut good, mut bad) = (coarse[edge], coarse[edge] * outward);
            let inside_grid =
                bad >= speeds[0] * (1.0 - 1e-12) && bad <= speeds[speeds.len() - 1] * (1.0 + 1e-12);
            if !inside_grid {
                continue;
            }
            for _ in 0..10 {
                let trial = (good * bad).sqrt();
                if within(trial)? {
                    good = trial;
                } else {
                    bad = trial;
                }
            }
            one_percent_range[edge] = good;
        }
    }
    let decade_error = comparison
        .iter()
        .filter(|c| {
            c.speed >= v_ref / 10f64.sqrt() * (1.0 - 1e-12)
                && c.speed <= v_ref * 10f64.sqrt() * (1.0 + 1e-12)
        })
        .map(|c| c.difference.abs())
        .fold(0.0, f64::max);
    let scope = if lossy_effects.is_empty() && loss_speed_independent {
        Scope::EverySpeed
    } else {
        Scope::CalibrationSpeed
    };
    let reference = model.impact(r, m, v_ref).map_err(model_err)?;
    let contact_time = match reference.contact_time {
        Some(t) if !reference.sticks => t,
        _ => {
            // sticking at the reference: the elastic Hertz contact time, seed 000 (5.12)
            2.868 * (m * m / (r * e_star * e_star * v_ref)).powf(0.2)
        }
    };
    let lammps_sticking = if adhesive {
        lammps_sticking_velocity(&model, r, m, sticking_tabor.unwrap_or(v_ref))?
    } else {
        None
    };
    let at_ref = comparison[mid];
    let statement = match scope {
        Scope::EverySpeed => format!(
            "reproduces tabor's restitution e(v){} at every speed: |e_LAMMPS - e_tabor| <= {:.1e} over {:.4e} ... {:.4e} m/s on the comparison grid (largest {:.1e}), plus LAMMPS's time-step error (<= {:.0e} at timestep <= contact time/5000; near the sticking velocity 2e-3 (1 - e^2)/(2e))",
            if sticking_tabor.is_some() { " and the sticking velocity" } else { "" },
            REPRODUCES, reproduced_range[0], reproduced_range[1],
            comparison.iter().filter(|c| c.speed >= reproduced_range[0] && c.speed <= reproduced_range[1]).map(|c| c.difference.abs()).fold(0.0, f64::max),
            TIME_STEP_ERROR
        ),
        Scope::CalibrationSpeed => format!(
            "reproduces tabor's restitution {:.6} at {:.4e} m/s only (calibration error {:.1e}, plus LAMMPS's time-step error <= {:.0e} at timestep <= contact time/5000{}); over a decade of speeds ({:.4e} ... {:.4e} m/s) the difference reaches {:.2e}; within 1 % of tabor for {:.4e} ... {:.4e} m/s",
            at_ref.tabor, v_ref, at_ref.difference.abs(), TIME_STEP_ERROR,
            if adhesive { "; near the sticking velocity 2e-3 (1 - e^2)/(2e)" } else { "" },
            v_ref / 10f64.sqrt(), v_ref * 10f64.sqrt(), decade_error,
            one_percent_range[0], one_percent_range[1]
        ),
    };
    let keywords = model_keywords(&model);
    let commands = match geometry {
        Geometry::Pair => vec![
            "comm_modify vel yes".to_string(),
            "pair_style granular".to_string(),
            format!("pair_coeff * * {keywords}"),
        ],
        Geometry::Wall => vec![
            "comm_modify vel yes".to_string(),
            format!("fix tabor_wall all wall/gran granular {keywords} zplane 0.0 NULL"),
        ],
    };
    let bodies = Bodies {
        sphere_radius: scene.sphere.radius.unwrap_or(f64::NAN),
        sphere_density: scene.sphere.density.unwrap_or(f64::NAN),
        target_radius: scene.target.radius,
        target_density: scene.target.radius.and(scene.target.density),
    };
    Ok(Export {
        scene: scene.name.clone(),
        geometry,
        model,
        model_keywords: keywords,
        commands,
        parameters,
        reproduces: Claim {
            scope,
            speed: v_ref,
            reproduced_range,
            one_percent_range,
            decade_error,
            statement,
        },
        does_not_reproduce: not_reproduced,
        bodies,
        effective_modulus: e_star,
        effective_radius: r,
        effective_mass: m,
        // the full scene's (all effects); the adhesive part's when no speed is given
        sticking_velocity: scene_outcome
            .and_then(|o| o.sticking_velocity)
            .or(sticking_tabor),
        lammps_sticking_velocity: lammps_sticking,
        contact_time,
        time_step: contact_time * TIME_STEP_FRACTION,
        comparison,
    })
}

impl Export {
    /// The LAMMPS input fragment: comment lines stating the model, every calibrated
    /// number and its derivation, what is and is not reproduced, then the commands.
    pub fn fragment(&self) -> String {
        let mut s = String::new();
        let mut line = |t: &str| {
            s.push_str(t);
            s.push('\n');
        };
        line(&format!(
            "# tabor export lammps: scene \"{}\" ({})",
            self.scene,
            match self.geometry {
                Geometry::Pair => "sphere-sphere: pair_style granular",
                Geometry::Wall => "sphere on a flat wall: fix wall/gran granular",
            }
        ));
        line("# Include after atom_style sphere / create_box (units si). Frictionless central impact.");
        line(&format!(
            "# LAMMPS model: {} + damping {}{}",
            self.model.normal.keyword(),
            self.model.damping.keyword(),
            if self.model.limit_damping {
                " + limit_damping"
            } else {
                ""
            }
        ));
        line(&format!(
            "# effective E* = {:.6e} Pa, R* = {:.6e} m, m* = {:.6e} kg",
            self.effective_modulus, self.effective_radius, self.effective_mass
        ));
        for p in &self.parameters {
            line(&format!(
                "# {} = {:.10e} {}: {}",
                p.name, p.value, p.unit, p.derivation
            ));
        }
        line(&format!("# REPRODUCES: {}", self.reproduces.statement));
        if let (Some(t), Some(l)) = (self.sticking_velocity, self.lammps_sticking_velocity) {
            line(&format!(
                "# sticking velocity: tabor {t:.6e} m/s, this LAMMPS model {l:.6e} m/s"
            ));
        }
        for n in &self.does_not_reproduce {
            line(&format!("# DOES NOT REPRODUCE: {n}"));
        }
        line(&format!(
            "# contact time at {:.4e} m/s: {:.4e} s; claims verified with timestep {:.4e} s (contact time/5000)",
            self.reproduces.speed, self.contact_time, self.time_step
        ));
        line("# speed (m/s)   e_tabor        e_LAMMPS       difference");
        let lo = self.reproduces.speed / 10f64.sqrt() * (1.0 - 1e-12);
        let hi = self.reproduces.speed * 10f64.sqrt() * (1.0 + 1e-12);
        for c in self
            .comparison
            .iter()
            .filter(|c| c.speed >= lo && c.speed <= hi)
        {
            line(&format!(
                "#   {:.4e}   {:.10}   {:.10}   {:+.2e}",
                c.speed, c.tabor, c.lammps, c.difference
            ));
        }
        if self.geometry == Geometry::Wall {
            line("# the wall is the plane z = 0 with the sphere above it: change zplane to your geometry");
        }
        for c in &self.commands {
            line(c);
        }
        s
    }
}

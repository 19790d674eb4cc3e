//! The calibrations of an export (`crates/tabor-lammps/README.md` derives each):
//! what the scene calls for and what can be calibrated ([`Setup`]), an effective
//! surface energy for the adhesive loss ([`calibrate_adhesion`]), and a
//! `damping viscoelastic` coefficient for a speed-dependent loss
//! ([`calibrate_damping`]).

use crate::impact::LammpsImpact;
use crate::law::{jkr_pulloff_distance, DampingModel, GranularModel, NormalModel};
use crate::report::SMALL_STRAIN_OVERLAP;
use crate::report::{model_err, unrepresentable, ExportError, Geometry, Limit, Parameter};
use std::f64::consts::PI;
use tabor_jkr::{JkrImpact, JkrSphere, SeparationRule};
use tabor_numerics::root_finding::brent;
use tabor_numerics::RootTolerance;
use tabor_scene::{EffectKind, Scene};

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

/// The highest impact speed (m/s) inside small strain: the Hertz overlap d_max of
/// seed 000 (5.8), (15 m v²/(16 E* √R))^(2/5), equals [`SMALL_STRAIN_OVERLAP`] R,
/// i.e. v² = 16 E* R³ s^(5/2)/(15 m) with s that fraction.
pub fn small_strain_speed(modulus: f64, radius: f64, mass: f64) -> f64 {
    (16.0 * modulus * radius.powi(3) * SMALL_STRAIN_OVERLAP.powf(2.5) / (15.0 * mass)).sqrt()
}

/// What the scene calls for, decided before any calibration, with the refusals
/// that need no calibration (each in well under a second).
pub(crate) struct Setup<'a> {
    pub scene: &'a Scene,
    pub geometry: Geometry,
    /// The effective modulus of the homogeneous contact (c_N of a k = 0 medium).
    pub e_star: f64,
    pub r: f64,
    pub m: f64,
    pub nu: f64,
    /// E = 2E*(1 − ν²): one `pair_coeff * *` mixes it back to E*.
    pub e_lammps: f64,
    /// The calibration speed (`--speed` or the scene's), when given.
    pub v_scene: Option<f64>,
    /// The highest speed inside small strain.
    pub v_small_strain: f64,
    /// Adhesion enters at the calibration speed (or, without one, w > 0).
    pub adhesive: bool,
    /// The speed-dependent losses LAMMPS's damping is calibrated for.
    pub lossy: Vec<&'static str>,
    /// tabor's restitution at the calibration speed, when there is a loss to
    /// calibrate (> 0: the bodies rebound).
    pub target: Option<f64>,
}

pub(crate) fn setup(scene: &Scene, speed: Option<f64>) -> Result<Setup<'_>, ExportError> {
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
    let (r, m) = (scene.effective_radius, scene.effective_mass);
    let nu = scene.sphere.material.poisson_ratio();
    let v_small_strain = small_strain_speed(e_star, r, m);
    let v_scene = speed.or(scene.speed);
    if let Some(v) = v_scene {
        if !(v.is_finite() && v > 0.0) {
            return Err(model_err(format!(
                "speed = {v}: the calibration speed must be finite and > 0 (m/s)"
            )));
        }
        if v > v_small_strain {
            return Err(unrepresentable(
                "an impact beyond small strain",
                format!("at the calibration speed {v:.4e} m/s the Hertz overlap d_max exceeds the effective radius R = {r:.4e} m (from {v_small_strain:.4e} m/s on): tabor's models do not apply there (give --speed below {v_small_strain:.4e} m/s)"),
            ));
        }
    }
    let combination = v_scene
        .map(|v| scene.combination_at(v))
        .transpose()
        .map_err(model_err)?;
    let uses = |e: EffectKind| combination.as_ref().map(|c| c.effects.contains(&e));
    // viscoelasticity whenever a viscosity is given (its loss acts at every speed,
    // even where the scene's outcome drops it because adhesion alone makes the
    // bodies stick); plasticity where the scene uses it at the calibration speed
    let viscous = scene.sphere.viscosity.is_some() || scene.target.viscosity.is_some();
    let plastic = uses(EffectKind::Plasticity).unwrap_or(scene.yield_stress().is_some());
    let lossy: Vec<&'static str> = [(plastic, "plasticity"), (viscous, "viscoelasticity")]
        .into_iter()
        .filter_map(|(on, name)| on.then_some(name))
        .collect();
    let adhesive = match &scene.adhesion {
        Some(a) if a.work_of_adhesion > 0.0 => uses(EffectKind::Adhesion).unwrap_or(true),
        _ => false,
    };
    let mut target = None;
    if !lossy.is_empty() {
        let Some(v) = v_scene else {
            return Err(unrepresentable(
                &lossy.join(" and "),
                "LAMMPS's damping reproduces a speed-dependent loss at one impact speed only: give [impact] speed in the scene or --speed".into(),
            ));
        };
        let (e, _) = scene.restitution_with_error(v).map_err(model_err)?;
        if e <= 0.0 {
            return Err(unrepresentable(
                &lossy.join(" and "),
                format!("the bodies stick at the calibration speed {v:.4e} m/s (tabor's restitution is 0 there): a damping calibrated on the restitution needs a speed where they rebound (give --speed above the sticking velocity that `tabor impact` reports)"),
            ));
        }
        target = Some(e);
    }
    Ok(Setup {
        scene,
        geometry,
        e_star,
        r,
        m,
        nu,
        e_lammps: 2.0 * e_star * (1.0 - nu * nu),
        v_scene,
        v_small_strain,
        adhesive,
        lossy,
        target,
    })
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

/// The adhesive calibration: γ, tabor's adhesive sticking velocity, and whether the
/// adhesive loss is speed-independent.
pub(crate) struct Adhesion {
    pub gamma: f64,
    /// The sticking velocity of the scene's elastic-adhesive part (m/s).
    pub sticking_velocity: f64,
    /// The scene's own pull-off force (N, > 0): (3/2)πwR* for JKR, the most
    /// tensile force of the Maugis-Dugdale impact branch.
    pub pull_off: f64,
    pub speed_independent: bool,
}

/// γ = w_eff/2 from the adhesive loss (README, calibration 1), with its parameters
/// and limits.
pub(crate) fn calibrate_adhesion(
    s: &Setup,
    parameters: &mut Vec<Parameter>,
    limits: &mut Vec<Limit>,
) -> Result<Adhesion, ExportError> {
    let (e_star, r, m) = (s.e_star, s.r, s.m);
    let sub = adhesive_only(s.scene)?;
    let a = s
        .scene
        .adhesion
        .as_ref()
        .ok_or_else(|| model_err("adhesion expected"))?;
    let vc = sub.sticking_velocity().map_err(model_err)?.ok_or_else(|| {
        model_err("the adhesive part of the scene never sticks: no adhesive loss to calibrate")
    })?;
    let loss_at = |v: f64| -> Result<f64, ExportError> {
        Ok(sub.outcome_at(v).map_err(model_err)?.energy_loss)
    };
    let w_a = loss_at(2.0 * vc)?;
    let w_b = loss_at((20.0 * vc).min(s.v_small_strain))?;
    let speed_independent = (w_a - w_b).abs() <= 1e-6 * w_a;
    let w_eff = effective_work_of_adhesion(e_star, r, m, w_a, a.work_of_adhesion)?;
    let gamma = 0.5 * w_eff;
    let w_check = load_controlled_loss(e_star, r, m, w_eff)?;
    let source = match (s.scene.tabor_parameter(), a.separation) {
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
    let true_gamma = 0.5 * a.work_of_adhesion;
    if (gamma / true_gamma - 1.0).abs() > 1e-6 {
        limits.push(Limit {
            effect: "pull-off force".into(),
            from_speed: None,
            note: format!(
                "LAMMPS's 3 pi gamma R* = {:.4e} N with the effective gamma, not the {} pull-off force of w = {} J/m^2 (3 pi gamma R* = {:.4e} N at the true gamma); the adhesive force history in contact",
                3.0 * PI * gamma * r,
                source,
                a.work_of_adhesion,
                3.0 * PI * true_gamma * r
            ),
        });
    }
    if s.scene.tabor_parameter().is_some() {
        limits.push(Limit {
            effect: "adhesion range".into(),
            from_speed: None,
            note: "the attraction before contact and the jump-in of the Maugis-Dugdale range: LAMMPS's jkr touches at zero overlap (the loss per impact, which sets e(v), is carried by gamma)".into(),
        });
    }
    parameters.push(Parameter {
        name: "pulloff_distance".into(),
        value: jkr_pulloff_distance(gamma, r, e_star),
        unit: "m".into(),
        derivation: "LAMMPS keeps the jkr contact to the load-controlled point delta = -(3 pi^2 gamma^2 R*/(16 E*^2))^(1/3); the neighbor list must reach it (pair granular extends its cutoff itself)".into(),
    });
    let pull_off = match s.scene.tabor_parameter() {
        Some(l) => -tabor_ffi::ContactLaw::maugis_dugdale(e_star, r, a.work_of_adhesion, l)
            .map_err(model_err)?
            .pull_off_force(),
        None => 1.5 * PI * a.work_of_adhesion * r,
    };
    Ok(Adhesion {
        gamma,
        sticking_velocity: vc,
        pull_off,
        speed_independent,
    })
}

/// The LAMMPS normal contact before damping: `jkr` with γ, or `hertz/material`
/// (with `limit_damping` when it will be damped: LAMMPS refuses it with `jkr`).
pub(crate) fn undamped_model(s: &Setup, gamma: Option<f64>) -> GranularModel {
    GranularModel {
        normal: match gamma {
            Some(g) => NormalModel::Jkr {
                youngs_modulus: s.e_lammps,
                poisson_ratio: s.nu,
                surface_energy: g,
            },
            None => NormalModel::HertzMaterial {
                youngs_modulus: s.e_lammps,
                poisson_ratio: s.nu,
            },
        },
        damp: 0.0,
        damping: DampingModel::Viscoelastic,
        limit_damping: gamma.is_none() && !s.lossy.is_empty(),
    }
}

/// The restitution of `model` at `v`, 0 when it sticks.
pub(crate) fn lammps_restitution(
    model: &GranularModel,
    s: &Setup,
    v: f64,
) -> Result<f64, ExportError> {
    LammpsImpact::new(*model, s.r, s.m)
        .and_then(|i| i.restitution(v))
        .map_err(model_err)
}

/// The sticking velocity of a LAMMPS model (m/s) to relative tolerance `tol`,
/// searched from `guess`.
pub(crate) fn lammps_sticking_velocity(
    model: &GranularModel,
    s: &Setup,
    guess: f64,
    tol: f64,
) -> Result<Option<f64>, ExportError> {
    LammpsImpact::new(*model, s.r, s.m)
        .map(|i| i.with_speed_scale(guess))
        .and_then(|i| i.sticking_velocity(tol))
        .map_err(model_err)
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

/// The relative tolerance of the fitted coefficients (and of the LAMMPS sticking
/// velocity inside the joint fit): their effect on the restitution is far below
/// LAMMPS's time-step error [`crate::TIME_STEP_ERROR`].
const FIT_TOLERANCE: f64 = 1e-8;

/// The relative tolerance of the sticking-velocity match of the joint γ-η fit
/// (LAMMPS resolves a sticking velocity to about its time-step error, 1e-3).
const STICKING_FIT_TOLERANCE: f64 = 1e-6;

/// Brent's root of the restitution of `model(x)` at `v` minus `target` over
/// x ∈ [0, hi·4^k], growing hi until the restitution falls below the target.
fn fit_restitution(
    make: impl Fn(f64) -> GranularModel,
    s: &Setup,
    v: f64,
    target: f64,
    hi: f64,
) -> Result<f64, ExportError> {
    let f = |x: f64| match lammps_restitution(&make(x), s, v) {
        Ok(e) => e - target,
        Err(_) => f64::NAN,
    };
    let at_zero = f(0.0);
    if at_zero.is_nan() || at_zero <= 0.0 {
        return Err(model_err(format!(
            "the undamped LAMMPS model already rebounds with at most tabor's {target:.6} at {v:.4e} m/s: no damping to calibrate"
        )));
    }
    let mut hi = hi;
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
    Ok(brent(f, 0.0, hi, RootTolerance::relative(FIT_TOLERANCE))?.value)
}

/// Adhesion with a speed-dependent loss: γ and η_n0 together, such that the LAMMPS
/// model rebounds with tabor's `target` at `v` *and* sticks below tabor's sticking
/// velocity `vc`. For each η, γ(η) matches the restitution; η is then the root of
/// v_c,LAMMPS(γ(η), η) − v_c (η = 0: all loss adhesive, v_c too high; η at the
/// purely viscous fit: γ = 0, v_c → 0). `None` when no bracket exists.
fn fit_gamma_and_eta(
    model: &GranularModel,
    s: &Setup,
    v: f64,
    target: f64,
    vc: f64,
    (gamma_scale, eta_scale): (f64, f64),
) -> Option<(f64, f64)> {
    let eta_max = fit_restitution(
        |eta| with_gamma_eta(model, 0.0, eta),
        s,
        v,
        target,
        eta_scale,
    )
    .ok()?;
    let gamma_of = |eta: f64| {
        fit_restitution(|g| with_gamma_eta(model, g, eta), s, v, target, gamma_scale).ok()
    };
    let g = |eta: f64| -> f64 {
        let Some(gamma) = gamma_of(eta) else {
            return f64::NAN;
        };
        match lammps_sticking_velocity(
            &with_gamma_eta(model, gamma, eta),
            s,
            vc,
            STICKING_FIT_TOLERANCE,
        ) {
            Ok(Some(v_l)) => v_l / vc - 1.0,
            Ok(None) => -1.0,
            Err(_) => f64::NAN,
        }
    };
    let hi = eta_max * (1.0 - 1e-6);
    if !(g(0.0) > 0.0 && g(hi) < 0.0) {
        return None;
    }
    let eta = brent(g, 0.0, hi, RootTolerance::relative(STICKING_FIT_TOLERANCE))
        .ok()?
        .value;
    Some((gamma_of(eta)?, eta))
}

/// η_n0 of `damping viscoelastic` such that LAMMPS rebounds with tabor's
/// restitution at the calibration speed (README, calibration 2); with adhesion,
/// γ and η_n0 are refitted together to match tabor's sticking velocity
/// `sticking_velocity` as well. Returns the damped model.
pub(crate) fn calibrate_damping(
    s: &Setup,
    undamped: GranularModel,
    sticking_velocity: Option<f64>,
    parameters: &mut [Parameter],
) -> Result<(GranularModel, Parameter), ExportError> {
    let (r, m) = (s.r, s.m);
    let (v_ref, target) = match (s.v_scene, s.target) {
        (Some(v), Some(t)) => (v, t),
        _ => return Err(model_err("a calibration speed is needed")),
    };
    let elastic = undamped.impact(r, m, v_ref).map_err(model_err)?;
    // η scale: 1/(t_c a_max) makes η m a ḋ comparable to the elastic force
    let tc = elastic.contact_time.unwrap_or(f64::NAN);
    let a_max = (r * elastic.max_overlap).sqrt();
    let scale = 1.0 / (tc * a_max);
    let first = fit_restitution(
        |eta| with_gamma_eta(&undamped, gamma_of(&undamped), eta),
        s,
        v_ref,
        target,
        scale,
    )?;
    let mut model = undamped;
    model.damp = first;
    if let (NormalModel::Jkr { surface_energy, .. }, Some(vc)) =
        (undamped.normal, sticking_velocity)
    {
        if let Some((g2, eta2)) = fit_gamma_and_eta(
            &model,
            s,
            v_ref,
            target,
            vc,
            (surface_energy.max(1e-12), scale),
        ) {
            model = with_gamma_eta(&model, g2, eta2);
            for p in parameters.iter_mut() {
                if p.name == "gamma" {
                    p.value = g2;
                    p.derivation = format!(
                        "gamma and eta_n0 fitted together (Brent in gamma inside Brent in eta_n0, each step a time-domain run of the LAMMPS law) so that LAMMPS rebounds with tabor's {target:.10} at {v_ref:.4e} m/s and sticks below tabor's sticking velocity {vc:.6e} m/s (the adhesive loss alone would give gamma = {surface_energy:.6e})"
                    );
                }
                if p.name == "pulloff_distance" {
                    p.value = jkr_pulloff_distance(g2, r, s.e_star);
                }
            }
        }
    }
    let kk = s
        .scene
        .target
        .viscosity
        .or(s.scene.sphere.viscosity)
        .map(|eta| format!("; for comparison, the Kuwabara-Kono value of a Kelvin-Voigt half-space of viscosity eta = {eta:e} Pa s on a rigid partner would be 8 eta/m* = {:.6e} (Willert 2020, eq. (5.66))", 8.0 * eta / m))
        .unwrap_or_default();
    let parameter = Parameter {
        name: "eta_n0".into(),
        value: model.damp,
        unit: "1/(m s)".into(),
        derivation: format!(
            "damping viscoelastic F = eta_n0 m* a v_n: eta_n0 solves e_LAMMPS(eta_n0; {v_ref:.4e} m/s) = tabor's {target:.10} ({}) by Brent's method on the time-domain LAMMPS law{}{}{kk}",
            s.lossy.join(" + "),
            if model.limit_damping { " with limit_damping" } else { " (no limit_damping: LAMMPS refuses it with jkr)" },
            if (model.damp / first - 1.0).abs() > 1e-9 { format!("; then refitted with gamma to match the sticking velocity too (eta_n0 = {first:.6e} with the adhesive-loss gamma)") } else { String::new() },
        ),
    };
    Ok((model, parameter))
}

fn gamma_of(model: &GranularModel) -> f64 {
    match model.normal {
        NormalModel::Jkr { surface_energy, .. } => surface_energy,
        _ => 0.0,
    }
}

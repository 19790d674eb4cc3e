//! Rigid parabolic indenter (radius R, mass m, speed v0) on an incompressible
//! Kelvin-Voigt half-space (G, η), seed 000 eqs. (5.64)-(5.71), in the scaling
//! (5.74): lengths in `d0 = (15 m v0²/(64 G √R))^(2/5)` (the elastic d_max, (5.8)
//! with E* = 4G), times in d0/v0, forces in m v0²/d0. Both models depend on
//! δ (5.68) only.
//!
//! Scaled equations (x = d/d0, c = 8 (15/64)^(3/5) δ, τ̂ = v0 η/(G d0) = 8c/15):
//!
//! - compression (ẋ > 0), both models: `ẍ = −(5/4) x^(3/2) − c √x ẋ` (5.66), the
//!   contact radius `a² = R d` (5.65);
//! - restitution, [`SphereModel::KuwabaraKono`]: the same equation (5.66) until the
//!   force `(5/4) x^(3/2) + c √x ẋ` vanishes;
//! - restitution, [`SphereModel::Rigorous`]: the contact radius follows (5.67), which
//!   for the Kelvin-Voigt medium is `a² = R (d + τ ḋ)` (the MDR edge condition: the
//!   line load vanishes at |x| = a; (5.67) integrated by parts), and the force is
//!   `F = 16 G a³/(3R)`, i.e. `ẍ = −(5/4) (x + τ̂ ẋ)^(3/2)`, until a = 0.
//!
//! The rigorous restitution force is never smaller than Kuwabara-Kono's
//! (`(2/3)(1+y)^(3/2) ≥ 2/3 + y` for y = τ̂ẋ/x), which is why Kuwabara-Kono slightly
//! underestimates ε (seed, Fig. 5.4).

use crate::scaled::{
    ode_tolerance, positive_up_to, restitution_from_rebound, run_phase, ScaledImpact, ScaledPoint,
};
use serde::Serialize;
use tabor_numerics::ode::EventDirection;
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_numerics::special::beta;
use tabor_restitution::{validate, Error, Result};

/// Largest viscous parameter δ accepted.
pub const MAX_VISCOUS_PARAMETER: f64 = 1e3;
const REQUIREMENT: &str = "must be finite and lie in (0, 1e3]";

/// Which equation of motion holds during restitution.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SphereModel {
    /// Kuwabara & Kono: (5.66) during the whole impact.
    KuwabaraKono,
    /// Compression (5.64)-(5.66) and restitution (5.64), (5.67) apart (MDR).
    Rigorous,
}

impl SphereModel {
    /// A short name ("kuwabara-kono", "rigorous").
    pub fn as_str(self) -> &'static str {
        match self {
            SphereModel::KuwabaraKono => "kuwabara-kono",
            SphereModel::Rigorous => "rigorous",
        }
    }
}

/// The scaled damping coefficient `c = 8 (15/64)^(3/5) δ` of the scaled (5.66).
fn damping_coefficient(delta: f64) -> f64 {
    8.0 * (15.0_f64 / 64.0).powf(0.6) * delta
}

/// The viscous parameter `δ = η (R v0 / (m² G³))^(1/5)` from the viscosity η
/// (Pa s), the indenter radius R (m), the impact speed v0 (m/s), the mass m (kg)
/// and the shear modulus G (Pa).
///
/// Seed 000, eq. (5.68).
pub fn viscous_parameter(
    viscosity: f64,
    radius: f64,
    impact_speed: f64,
    mass: f64,
    shear_modulus: f64,
) -> Result<f64> {
    let eta = validate::positive("viscosity", viscosity)?;
    let r = validate::positive("radius", radius)?;
    let v = validate::positive("impact_speed", impact_speed)?;
    let m = validate::positive("mass", mass)?;
    let g = validate::positive("shear_modulus", shear_modulus)?;
    // Logarithms avoid overflow of m² G³.
    let ln = eta.ln() + 0.2 * (r.ln() + v.ln() - 2.0 * m.ln() - 3.0 * g.ln());
    validate::positive("viscous_parameter", ln.exp())
}

/// The length scale `d0 = (15 m v0² / (64 G √R))^(2/5)` (m) of the scaling (5.74).
///
/// Seed 000, eq. (5.74).
pub fn overlap_scale(mass: f64, impact_speed: f64, shear_modulus: f64, radius: f64) -> Result<f64> {
    let m = validate::positive("mass", mass)?;
    let v = validate::positive("impact_speed", impact_speed)?;
    let g = validate::positive("shear_modulus", shear_modulus)?;
    let r = validate::positive("radius", radius)?;
    let ln = 0.4 * ((15.0_f64 / 64.0).ln() + m.ln() + 2.0 * v.ln() - g.ln() - 0.5 * r.ln());
    validate::positive("overlap_scale", ln.exp())
}

/// The first-order restitution for small losses,
/// `ε ≈ 1 − (32/5) B(3/5, 3/2) (15/64)^(3/5) δ` (Kuwabara & Kono; equal for both
/// models at this order), floored at 0.
///
/// Seed 000, eqs. (5.70), (5.71).
pub fn first_order_restitution(viscous_parameter: f64) -> Result<f64> {
    let delta = positive_up_to(
        "viscous_parameter",
        viscous_parameter,
        MAX_VISCOUS_PARAMETER,
        REQUIREMENT,
    )?;
    let slope = 32.0 / 5.0 * beta(0.6, 1.5)? * (15.0_f64 / 64.0).powf(0.6);
    Ok((1.0 - slope * delta).clamp(0.0, 1.0))
}

/// The coefficient of restitution ε(δ) of a sphere on a Kelvin-Voigt half-space,
/// integrated with relative tolerance 1e-10.
///
/// Seed 000, eqs. (5.64)-(5.68), Fig. 5.4.
pub fn restitution(viscous_parameter: f64, model: SphereModel) -> Result<f64> {
    Ok(solve(viscous_parameter, model, 1e-10)?.restitution)
}

/// The impact of a sphere on a Kelvin-Voigt half-space in the scaled variables of
/// (5.74) (module docs), integrated by Dormand-Prince 5(4) with relative tolerance
/// `tolerance` ∈ [1e-15, 0.5].
///
/// Seed 000, eqs. (5.64)-(5.68), (5.74).
pub fn solve(viscous_parameter: f64, model: SphereModel, tolerance: f64) -> Result<ScaledImpact> {
    integrate(viscous_parameter, model, tolerance, None)
}

/// The scaled trajectory (5.74): time, indentation, rate and force from first
/// contact to separation, a few points per integration step.
///
/// Seed 000, eqs. (5.64)-(5.68), (5.74), Figs. 5.6-5.9.
pub fn trajectory(
    viscous_parameter: f64,
    model: SphereModel,
    tolerance: f64,
) -> Result<Vec<ScaledPoint>> {
    let mut points = Vec::new();
    integrate(viscous_parameter, model, tolerance, Some(&mut points))?;
    Ok(points)
}

/// The viscous parameter δ at which the model gives the restitution `restitution`
/// ∈ (0, 1) (Brent on ε(δ), which decreases monotonically).
///
/// Seed 000, eq. (5.68) and Table 5.1 (models scaled to a measured ε_z).
pub fn viscous_parameter_for_restitution(
    restitution: f64,
    model: SphereModel,
    tolerance: f64,
) -> Result<f64> {
    let target = restitution;
    if !(target.is_finite() && target > 0.0 && target < 1.0) {
        return Err(Error::invalid(
            "restitution",
            target,
            "must be finite and lie in (0, 1)",
        ));
    }
    let tol = validate::tolerance("tolerance", tolerance)?;
    let inner = (tol * 1e-2).max(1e-13);
    let mut failure = None;
    let mut f = |ln_delta: f64| match solve(ln_delta.exp(), model, inner) {
        Ok(s) => s.restitution - target,
        Err(e) => {
            failure.get_or_insert(e);
            f64::NAN
        }
    };
    let root = brent(
        &mut f,
        (1e-6_f64).ln(),
        MAX_VISCOUS_PARAMETER.ln(),
        RootTolerance::absolute(tol),
    );
    if let Some(e) = failure {
        return Err(e);
    }
    Ok(root?.value.exp())
}

type Record<'a> = Option<&'a mut Vec<ScaledPoint>>;
/// A restitution-phase force F̂(y, c, τ̂).
type PhaseForce = fn(&[f64; 2], f64, f64) -> f64;

fn integrate(
    viscous_parameter: f64,
    model: SphereModel,
    tolerance: f64,
    record: Record<'_>,
) -> Result<ScaledImpact> {
    let delta = positive_up_to(
        "viscous_parameter",
        viscous_parameter,
        MAX_VISCOUS_PARAMETER,
        REQUIREMENT,
    )?;
    let c = damping_coefficient(delta);
    let tau = 8.0 * c / 15.0;
    let tol = ode_tolerance(tolerance, 0.05)?;
    let kk_force = move |y: &[f64; 2]| {
        let x = y[0].max(0.0);
        x.sqrt() * (1.25 * x + c * y[1])
    };
    let rig_force = move |y: &[f64; 2]| 1.25 * (y[0] + tau * y[1]).max(0.0).powf(1.5);
    let mut raw: Vec<(f64, [f64; 2])> = Vec::new();
    let want = record.is_some();
    // Compression (5.66) until the turning point ẋ = 0.
    let mut f1 = |_t: f64, y: &[f64; 2]| [y[1], -kk_force(y)];
    let t_max = 1e3 * (1.0 + tau);
    let first = run_phase(
        &mut f1,
        &mut |_t: f64, y: &[f64; 2]| y[1],
        EventDirection::Falling,
        0.0,
        [0.0, 1.0],
        t_max,
        tol,
        want.then_some(&mut raw),
    )?;
    let max_overlap = first.y[0];
    let (second, forces): (_, PhaseForce) = match model {
        SphereModel::KuwabaraKono => {
            let mut f2 = |_t: f64, y: &[f64; 2]| [y[1], -kk_force(y)];
            let end = run_phase(
                &mut f2,
                &mut |_t: f64, y: &[f64; 2]| 1.25 * y[0] + c * y[1],
                EventDirection::Falling,
                first.t,
                first.y,
                first.t + t_max,
                tol,
                want.then_some(&mut raw),
            )?;
            (end, |y, c, _| {
                let x = y[0].max(0.0);
                x.sqrt() * (1.25 * x + c * y[1])
            })
        }
        SphereModel::Rigorous => {
            let mut f2 = |_t: f64, y: &[f64; 2]| [y[1], -rig_force(y)];
            let end = run_phase(
                &mut f2,
                &mut |_t: f64, y: &[f64; 2]| y[0] + tau * y[1],
                EventDirection::Falling,
                first.t,
                first.y,
                first.t + t_max,
                tol,
                want.then_some(&mut raw),
            )?;
            (end, |y, _, tau| {
                1.25 * (y[0] + tau * y[1]).max(0.0).powf(1.5)
            })
        }
    };
    if let Some(points) = record {
        let split = first.t;
        points.extend(raw.iter().map(|&(t, y)| ScaledPoint {
            time: t,
            overlap: y[0],
            overlap_rate: y[1],
            force: if t <= split {
                kk_force(&y)
            } else {
                forces(&y, c, tau).max(0.0)
            },
        }));
    }
    Ok(ScaledImpact {
        restitution: restitution_from_rebound(-second.y[1])?,
        contact_time: second.t,
        max_overlap,
        cost: first.cost + second.cost,
    })
}

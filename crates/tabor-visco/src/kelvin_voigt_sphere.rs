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
//!
//! Heavy damping (δ ≫ 1): the velocity relaxes after the turning point to the
//! creep velocity, and the force vanishes on the way (see [`crate::damping_law`],
//! of which Kuwabara-Kono is the case β = 1/2, γ = c); the rigorous restitution
//! ends at `z = x + τ̂ẋ = 0`, i.e. ε → x*/τ̂ = 15x*/(8c), 3/2 of Kuwabara-Kono's
//! (5/4)x*/c. More precisely (derived for the tests): in the rigorous
//! restitution `ẋ = −(x − z)/τ̂`, and while z falls from x* to 0 the overlap
//! drops by `Δx = ∫_0^{x*} A/(A + (5/4)τ̂ z^{3/2}) dz`, `A = (x* − z)/τ̂`; the
//! integrand is ≈ 1 below `z_c = (4x*/(5τ̂²))^{2/3}` and decays as z^{-3/2} above,
//! so `Δx = (4π/(3√3)) z_c (1 + O(z_c/x*))` and
//! `ε = (x* − Δx)/τ̂ = (x*/τ̂)[1 − (4π/(3√3))(4/5)^{2/3} x*^{-1/3} τ̂^{-4/3}]`
//! up to O(τ̂^{-2} x*^{-1/2}) (a relative 5.3e-4 correction at δ = 1e3, 4.1e-5
//! at 1e4), with `x* = (3/(2c))^{2/3}` to a relative O(ε ln(1/ε)). The restitution is integrated with the reduced force (resp. z) as a
//! state, so the end of contact is a state crossing zero and not a cancellation of
//! two nearly equal terms, with a pure relative error control.

use crate::hertz_damped::{self, Outcome, Restitution};
use crate::scaled::{positive_up_to, ScaledImpact, ScaledPoint};
use serde::Serialize;
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_numerics::special::beta;
use tabor_numerics::tolerance::{ACCURACY, MODEL_ACCURACY_FLOOR, SIMULATION_ACCURACY_FLOOR};
use tabor_restitution::{validate, Error, Result};

/// Largest viscous parameter δ accepted. Both models are solved up to here in a
/// few thousand to ~1e4 evaluations (Kuwabara-Kono reaches the step limit from
/// δ ≈ 1e10), and agree with the large-δ asymptotics (module docs) to within
/// their remainders (tests/heavy_damping.rs).
pub const MAX_VISCOUS_PARAMETER: f64 = 1e9;
const REQUIREMENT: &str = "must be finite and lie in (0, 1e9]";

/// Which equation of motion holds during restitution.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SphereModel {
    /// Kuwabara & Kono: (5.66) during the whole impact.
    KuwabaraKono,
    /// Compression (5.64)-(5.66) and restitution (5.64), (5.67) apart (MDR).
    Rigorous,
}

tabor_restitution::menu! {
    SphereModel, "Kelvin-Voigt sphere model";
    KuwabaraKono => "kuwabara-kono", "Kuwabara-Kono: (5.66) during the whole impact";
    Rigorous => "rigorous", "compression (5.64)-(5.66) and restitution (5.64), (5.67) apart (MDR)";
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
/// integrated with relative tolerance
/// [`ACCURACY`] (1e-10).
///
/// Seed 000, eqs. (5.64)-(5.68), Fig. 5.4.
pub fn restitution(viscous_parameter: f64, model: SphereModel) -> Result<f64> {
    Ok(solve(viscous_parameter, model, ACCURACY)?.restitution)
}

/// The impact of a sphere on a Kelvin-Voigt half-space in the scaled variables of
/// (5.74) (module docs), integrated by Dormand-Prince 5(4) with relative tolerance
/// `tolerance` ∈ [1e-15, 0.5] (above 1e-3 tightened to 1e-3; Kuwabara-Kono above
/// δ = 1e6 to 1e-9, where a looser integration of its creep misses the end of
/// contact). ε, x_max and T_S are
/// accurate to about the tolerance relative to themselves over the whole range of
/// δ, also where ε is tiny (δ = 1e3: ε = 2.18e-6 Kuwabara-Kono, 3.27e-6 rigorous;
/// δ = 1e9: 2.18e-16, 3.28e-16,
/// which tend to `(5/4) x*/c` and `15 x*/(8c)`, c = 8 (15/64)^{3/5} δ); a few
/// thousand right-hand-side evaluations at most (module docs of the crate's
/// engine, README).
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

/// The viscous parameter δ at which the model gives the restitution `restitution`,
/// to a relative accuracy of about `max(tolerance, 1e-12)` (Brent on ln δ).
///
/// The root function is `logit ε(δ) − logit ε_target` with `logit ε = ln ε − ln(1 − ε)`,
/// ε from the rebound speed and 1 − ε from the dissipated energy, both accurate
/// relative to themselves: so the answer is accurate at both ends, ε → 1 (δ → 0,
/// where (5.71) `1 − ε ≈ s δ`, s = (32/5) B(3/5, 3/2) (15/64)^{3/5} ≈ 3.38) and
/// ε → 0. The bracket starts at the first-order estimate `(1 − ε)/s` for ε ≥ 1/2,
/// else at the overdamped estimate (δ from `ε ≈ (5/4) (3/(2c))^{2/3}/c`,
/// c = 8 (15/64)^{3/5} δ; see [`crate::damping_law::overdamped_restitution`]), and
/// is widened by factors of 2.
///
/// Accepted restitution: `ε(δ_max) < restitution < 1` with δ_max =
/// [`MAX_VISCOUS_PARAMETER`], i.e. above ≈ 2.18e-16 (Kuwabara-Kono) or ≈ 3.28e-16
/// (rigorous); a smaller one would need δ > 1e9 and is answered with
/// [`Error::InvalidParameter`] naming `restitution`.
///
/// Seed 000, eqs. (5.68), (5.71) and Table 5.1 (models scaled to a measured ε_z).
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
    let inner = (0.1 * tol).max(SIMULATION_ACCURACY_FLOOR);
    // The forward solutions carry relative errors ~1e-13 at best: no point in
    // asking for more than 1e-12 in ln δ.
    let accuracy = tol.max(MODEL_ACCURACY_FLOOR);
    let logit_target = target.ln() - (1.0 - target).ln();
    let mut failure = None;
    let mut memo: Vec<(f64, f64)> = Vec::new();
    // h(ln δ) = logit ε(δ) − logit ε_target, decreasing.
    let mut h = |ln_delta: f64| {
        if let Some(&(_, v)) = memo.iter().find(|(u, _)| *u == ln_delta) {
            return v;
        }
        let v = match solve_with_loss(
            ln_delta.exp().min(MAX_VISCOUS_PARAMETER),
            model,
            inner,
            None,
        ) {
            // |dh/d ln δ| ≳ 1 everywhere (→ 1 as ε → 1, 5/3 as ε → 0) and the
            // noise of h is a few `inner`: |h| ≤ `accuracy` is a root to the
            // tolerance and ends the search (Brent, converging from one side, would
            // otherwise bisect down from the far end of the bracket).
            Ok(o) => match o.impact.restitution.ln() - o.loss.ln() - logit_target {
                v if v.abs() <= accuracy => 0.0,
                v => v,
            },
            Err(e) => {
                failure.get_or_insert(e);
                f64::NAN
            }
        };
        memo.push((ln_delta, v));
        v
    };
    let ln_max = MAX_VISCOUS_PARAMETER.ln();
    let slope = 32.0 / 5.0 * beta(0.6, 1.5)? * (15.0_f64 / 64.0).powf(0.6);
    let first_order = ((1.0 - target) / slope).ln();
    // ε ≈ (5/4) (3/(2c))^{2/3} / c  ⇒  c = ((5/4) (3/2)^{2/3} / ε)^{3/5}.
    let c = (1.25 * 1.5_f64.powf(2.0 / 3.0) / target).powf(0.6);
    let overdamped = (c / damping_coefficient(1.0)).ln();
    let guess = if target >= 0.5 {
        first_order
    } else {
        overdamped
    }
    .min(ln_max);
    let step = std::f64::consts::LN_2;
    let (mut lo, mut hi) = (guess, guess);
    let h0 = h(guess);
    if h0.is_nan() {
        return Err(failure.unwrap_or_else(|| no_bracket(target)));
    }
    if h0 > 0.0 {
        // ε too large: more damping.
        loop {
            if hi >= ln_max {
                return Err(Error::invalid(
                    "restitution",
                    target,
                    "must exceed ε(δ = 1e9) (≈ 2.18e-16 Kuwabara-Kono, ≈ 3.28e-16 rigorous): \
                     a smaller restitution needs a viscous parameter above its maximum 1e9",
                ));
            }
            lo = hi;
            hi = (hi + step).min(ln_max);
            let v = h(hi);
            if v.is_nan() {
                return Err(failure.unwrap_or_else(|| no_bracket(target)));
            }
            if v <= 0.0 {
                break;
            }
        }
    } else {
        // ε too small: less damping (terminates: 1 − ε ∝ δ as δ → 0).
        loop {
            hi = lo;
            lo -= step;
            let v = h(lo);
            if v.is_nan() {
                return Err(failure.unwrap_or_else(|| no_bracket(target)));
            }
            if v >= 0.0 || lo < f64::MIN_POSITIVE.ln() {
                break;
            }
        }
    }
    let root = brent(&mut h, lo, hi, RootTolerance::absolute(accuracy));
    if let Some(e) = failure {
        return Err(e);
    }
    Ok(root?.value.exp().min(MAX_VISCOUS_PARAMETER))
}

fn no_bracket(target: f64) -> Error {
    Error::Model {
        model: "Kelvin-Voigt sphere",
        message: format!("no viscous parameter found for the restitution {target:e}"),
    }
}

type Record<'a> = Option<&'a mut Vec<ScaledPoint>>;

/// The impact with the loss 1 − ε accurate relative to itself.
pub(crate) fn solve_with_loss(
    viscous_parameter: f64,
    model: SphereModel,
    tolerance: f64,
    record: Record<'_>,
) -> Result<Outcome> {
    let delta = positive_up_to(
        "viscous_parameter",
        viscous_parameter,
        MAX_VISCOUS_PARAMETER,
        REQUIREMENT,
    )?;
    let c = damping_coefficient(delta);
    let (law, tolerance) = match model {
        // Kuwabara-Kono's creep phase, integrated loosely at large δ, misses the
        // end of contact and runs into the step limit (tol 1e-3 from δ ≈ 3e6,
        // 1e-4 from 1e7, 1e-6 from 1e8; 1e-9 and tighter solve every δ ≤ 1e9 in
        // ≤ 8.7e3 evaluations at 1e-9): tightened there.
        SphereModel::KuwabaraKono if delta > KUWABARA_KONO_LOOSE_LIMIT => (
            Restitution::Damped,
            tolerance.min(KUWABARA_KONO_TIGHT_TOLERANCE),
        ),
        SphereModel::KuwabaraKono => (Restitution::Damped, tolerance),
        SphereModel::Rigorous => (
            Restitution::Rigorous {
                tau: 8.0 * c / 15.0,
            },
            tolerance,
        ),
    };
    hertz_damped::solve(0.5, c, law, tolerance, record)
}

/// Above this δ the Kuwabara-Kono integration runs at [`KUWABARA_KONO_TIGHT_TOLERANCE`]
/// at most (module docs of [`solve`]).
const KUWABARA_KONO_LOOSE_LIMIT: f64 = 1e6;
const KUWABARA_KONO_TIGHT_TOLERANCE: f64 = 1e-9;

fn integrate(
    viscous_parameter: f64,
    model: SphereModel,
    tolerance: f64,
    record: Record<'_>,
) -> Result<ScaledImpact> {
    Ok(solve_with_loss(viscous_parameter, model, tolerance, record)?.impact)
}

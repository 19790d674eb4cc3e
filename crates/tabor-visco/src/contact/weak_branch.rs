//! The standard-medium sphere with a weak Maxwell branch (β = G∞/G1 → ∞ at a fixed
//! scaled relaxation time τ̂): the loss to first order in 1/β,
//! `1 − ε² = λ(τ̂)/β + O(β⁻²)`, from the dissipation of the branch along the Hertz
//! impact (seed 000 eqs. (5.84)-(5.89) linearised in G1).
//!
//! # Derivation
//!
//! In the MDR scaling of [`crate::standard_sphere`] (lengths d0, times d0/v0, line
//! loads 4G∞d0) the element at ξ carries `q = (x − ξ²) + ũ/β`, with the branch
//! extension `ũ' = ẋ − ũ/τ̂`, ũ = 0 when the element enters. The kinetic energy lost
//! is the work done on the medium, `1 − ε² = 2 ∫ F̂ ẋ dt`, F̂ = (15/8) ∫_0^a q dξ.
//! The elastic part returns its work up to the energy left in elements that leave
//! with a non-zero spring, O(β⁻²); the branch part is O(1/β) and may, to that order,
//! be evaluated on the Hertz impact (x_max = 1, contact [0, √x], contact time
//! `T = (4/5) B(2/5, 1/2)`). With `W' = ẋ − W/τ̂`, `A' = √x ẋ − A/τ̂` (W(0) = A(0) = 0)
//! an element entering at t_ξ has `ũ = W(t) − e^{−(t−t_ξ)/τ̂} W(t_ξ)`; so
//! `Σ = ∫_0^T ẋ ∫_0^{√x} ũ dξ dt` is, in compression, `∫ ẋ A dt`, and in restitution
//! (the element at the edge entered at the mirror time T − t)
//! `∫ ẋ [√x W + e^{−(2t−T)/τ̂} (A − √x W)(T − t)] dt`. Moving the mirror term onto the
//! compression (t → T − t):
//!
//! ```text
//! Σ = ∫_C ẋ [A − e^{−(T−2t)/τ̂} (A − √x W)] dt + ∫_R ẋ √x W dt,   λ = (15/4) Σ.
//! ```
//!
//! Equivalently `Σ = ∬ √min(x(s), x(t)) ẋ(s) ẋ(t) e^{−|t−s|/τ̂} ds dt / 2 ≥ 0`.
//! Limits: τ̂ → 0 is the Kelvin-Voigt dashpot η = G1τ, `λ → 3 B(3/5, 3/2) τ̂`
//! (the first order (5.71)); τ̂ → ∞ is a spring that creeps a little,
//! `λ → (8/5) B(7/5, 1/2)/τ̂`.
//!
//! # Numerics
//!
//! Both phases in the arc parameter of the MDR compression (regular at first
//! contact and at the end). For τ̂ < 1 the states are W/τ̂, A/τ̂, Σ/τ̂ (all O(1) as
//! τ̂ → 0; Rodas5P below τ̂ = 2e-3, where they relax much faster than the motion).
//! For τ̂ ≥ 1 the states are `w = τ̂(x − W)`, `α = τ̂((2/3)x^{3/2} − A)` and τ̂Σ: in
//! the plain form Σ ~ 1/τ̂ would be a cancellation of O(1) terms, in this one the
//! O(1) parts cancel analytically,
//! `τ̂Σ = −∫_C ẋ√x w dt + ∫_C ẋ τ̂(1 − e^{−(T−2t)/τ̂})(A − √x W) dt − ∫_R ẋ√x w dt`,
//! `A − √x W = −x^{3/2}/3 + (√x w − α)/τ̂`, `w' = x − w/τ̂`, `α' = (2/3)x^{3/2} − α/τ̂`.

use crate::scaled::{ode_tolerance, run_phase_with, Method};
use tabor_numerics::ode::EventDirection;
use tabor_numerics::rosenbrock::Jacobian;
use tabor_numerics::special::beta;
use tabor_numerics::Cost;
use tabor_restitution::Result;

/// Below this τ̂ the phases are integrated by Rodas5P.
const STIFF_RELAXATION_TIME: f64 = 2e-3;
/// From this τ̂ on, the form without the O(1) cancellation.
const LONG_RELAXATION_TIME: f64 = 1.0;
/// Largest step in the arc parameter (the whole impact is ≈ 4.5 long).
const MAX_STEP: f64 = 0.25;
/// Bound on the arc parameter of a phase (never reached: each is ≈ 2.2).
const PHASE_BOUND: f64 = 100.0;

/// dt/dp and da/dp of the arc parameter, `N = √(ẋ² + 4a²)`.
fn arc(a: f64, xdot: f64) -> (f64, f64) {
    let n = xdot.hypot(2.0 * a);
    (2.0 * a / n, xdot / n)
}

/// The Hertz contact time (scaled), `T = (4/5) B(2/5, 1/2)`.
pub(crate) fn hertz_contact_time() -> Result<f64> {
    Ok(0.8 * beta(0.4, 0.5)?)
}

/// `λ(τ̂) = lim_{β→∞} β (1 − ε²)` at the scaled relaxation time τ̂ > 0 (finite), with
/// relative integration tolerance `tolerance`; and the cost.
pub(crate) fn loss_coefficient(tau: f64, tolerance: f64) -> Result<(f64, Cost)> {
    let t_hertz = hertz_contact_time()?;
    let tol = ode_tolerance(tolerance, MAX_STEP)?;
    let method = if tau < STIFF_RELAXATION_TIME {
        Method::Stiff(Jacobian::Autonomous)
    } else {
        Method::Explicit
    };
    let long = tau >= LONG_RELAXATION_TIME;
    // Compression: (t, a, ẋ, W-state, A-state, Σ-state).
    let mut f = |_p: f64, y: &[f64; 6]| {
        let (t, a, xdot, w, s) = (y[0], y[1], y[2], y[3], y[4]);
        let (dt, da) = arc(a, xdot);
        let x = a * a;
        let lag = (t_hertz - 2.0 * t).max(0.0);
        let (dw, ds, dsigma) = if long {
            let mirror = -a * x / 3.0 + (a * w - s) / tau;
            let weight = -tau * (-lag / tau).exp_m1();
            (
                x - w / tau,
                2.0 / 3.0 * a * x - s / tau,
                -xdot * a * w + xdot * weight * mirror,
            )
        } else {
            let e = (-lag / tau).exp();
            (
                (xdot - w) / tau,
                (a * xdot - s) / tau,
                xdot * (s - e * (s - a * w)),
            )
        };
        [dt, da, -1.25 * a * x * dt, dw * dt, ds * dt, dsigma * dt]
    };
    let first = run_phase_with(
        method,
        &mut f,
        &mut |_p: f64, y: &[f64; 6]| y[2],
        EventDirection::Falling,
        0.0,
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
        PHASE_BOUND,
        tol,
        None,
    )?;
    // Restitution: (t, a, ẋ, W-state, Σ-state) until a = 0.
    let mut g = |_p: f64, y: &[f64; 5]| {
        let (a, xdot, w) = (y[1], y[2], y[3]);
        let (dt, da) = arc(a, xdot);
        let x = a * a;
        let (dw, dsigma) = if long {
            (x - w / tau, -xdot * a * w)
        } else {
            ((xdot - w) / tau, xdot * a * w)
        };
        [dt, da, -1.25 * a * x * dt, dw * dt, dsigma * dt]
    };
    let y = first.y;
    let second = run_phase_with(
        method,
        &mut g,
        &mut |_p: f64, y: &[f64; 5]| y[1],
        EventDirection::Falling,
        first.t,
        [y[0], y[1], y[2], y[3], y[5]],
        first.t + PHASE_BOUND,
        tol,
        None,
    )?;
    let sigma = if long {
        second.y[4] / tau
    } else {
        second.y[4] * tau
    };
    Ok((3.75 * sigma, first.cost + second.cost))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// Σ = ∬ √min(x(s), x(t)) ẋ(s) ẋ(t) e^{−|t−s|/τ̂} ds dt / 2 by a product
    /// Gauss-Legendre rule on the Hertz impact tabulated independently (ẋ from
    /// energy conservation, t(x) by quadrature): another route to λ.
    fn double_integral(tau: f64) -> f64 {
        // Compression in x ∈ [0, 1]: t(x) = ∫_0^x (1 − u^{5/2})^{-1/2} du. Substitute
        // x = 1 − (1 − θ)² to remove the end singularity: dx = 2(1 − θ) dθ.
        let (nodes, weights) = gauss_legendre(100);
        let t_hertz = hertz_contact_time().unwrap();
        // t(x(θ)) by cumulative Gauss on sub-intervals.
        let time_of = |theta: f64| {
            let (n2, w2) = gauss_legendre(40);
            let mut s = 0.0;
            for (u, wu) in n2.iter().zip(&w2) {
                let th = 0.5 * theta * (u + 1.0);
                let x: f64 = 1.0 - (1.0 - th) * (1.0 - th);
                s += 0.5 * theta * wu * 2.0 * (1.0 - th) / (1.0 - x.powf(2.5)).sqrt();
            }
            s
        };
        // Σ = ∬_{[0,1]²} √min(x, y) [e^{−|t_x − t_y|/τ̂} − e^{−(T − t_x − t_y)/τ̂}] dx dy
        //   = 2 ∫_0^1 dx ∫_0^x √y [e^{−(t_x − t_y)/τ̂} − e^{−(T − t_x − t_y)/τ̂}] dy,
        // each in θ (x = 1 − (1 − θ)²), so the kinks on the diagonal are at the ends.
        let point = |th: f64| (1.0 - (1.0 - th) * (1.0 - th), 2.0 * (1.0 - th), time_of(th));
        let mut sum = 0.0;
        for (u, w) in nodes.iter().zip(&weights) {
            let th_x = 0.5 * (u + 1.0);
            let (_, jx, tx) = point(th_x);
            let mut inner = 0.0;
            for (v, wv) in nodes.iter().zip(&weights) {
                let th_y = 0.5 * th_x * (v + 1.0);
                let (y, jy, ty) = point(th_y);
                let k = (-(tx - ty) / tau).exp() - (-(t_hertz - tx - ty) / tau).exp();
                inner += 0.5 * th_x * wv * jy * y.sqrt() * k;
            }
            sum += 2.0 * 0.5 * w * jx * inner;
        }
        sum
    }

    fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
        let mut x = vec![0.0; n];
        let mut w = vec![0.0; n];
        for i in 0..n {
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            for _ in 0..100 {
                let (mut p1, mut p2) = (1.0, 0.0);
                for j in 0..n {
                    let p3 = p2;
                    p2 = p1;
                    p1 = ((2 * j + 1) as f64 * z * p2 - j as f64 * p3) / (j + 1) as f64;
                }
                let pp = n as f64 * (z * p1 - p2) / (z * z - 1.0);
                let dz = p1 / pp;
                z -= dz;
                if dz.abs() < 1e-15 {
                    w[i] = 2.0 / ((1.0 - z * z) * pp * pp);
                    break;
                }
            }
            x[i] = z;
        }
        (x, w)
    }

    #[test]
    fn loss_coefficient_equals_the_double_integral() {
        // Gauss-Legendre on the triangle below the diagonal (the kernel's kinks on
        // its edge); the kernel's width τ̂ must be resolved: τ̂ ≥ 0.1.
        for &tau in &[0.1, 0.3, 1.0, 3.0, 10.0] {
            let (l, _) = loss_coefficient(tau, 1e-11).unwrap();
            let reference = 3.75 * double_integral(tau);
            let rel = (l - reference).abs() / reference;
            println!("tau {tau}: λ {l:.10e} double integral {reference:.10e} rel {rel:.2e}");
        }
        for &tau in &[0.1, 0.3, 1.0, 3.0, 10.0] {
            let (l, _) = loss_coefficient(tau, 1e-11).unwrap();
            let reference = 3.75 * double_integral(tau);
            let rel = (l - reference).abs() / reference;
            assert!(rel < 5e-7, "tau {tau}: {l} vs {reference}");
        }
    }

    #[test]
    fn both_forms_agree_at_the_switch() {
        // τ̂ just below and at LONG_RELAXATION_TIME: two algebraically different
        // state sets.
        let below = loss_coefficient(LONG_RELAXATION_TIME * (1.0 - 1e-12), 1e-12)
            .unwrap()
            .0;
        let at = loss_coefficient(LONG_RELAXATION_TIME, 1e-12).unwrap().0;
        println!("λ(1−) {below:.14e}, λ(1) {at:.14e}");
        assert!((below - at).abs() < 1e-9 * at);
    }
}

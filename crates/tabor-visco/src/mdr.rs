//! The MDR model of a sphere on an incompressible medium with one Maxwell branch
//! (and, for the Kelvin-Maxwell medium, a parallel dashpot), seed 000 eqs.
//! (5.84)-(5.92), shared by [`crate::standard_sphere`] and
//! [`crate::kelvin_maxwell_sphere`]. It is solved in the continuum limit of the
//! MDR bedding: no discretization into elements, a 5-dimensional compression ODE
//! and a 4- to 5-dimensional restitution ODE.
//!
//! # Scaled model
//!
//! Scaling (5.74) with G = G∞: x = d/d0, times in d0/v0, forces in m v0²/d0,
//! element coordinates ξ = x_MDR/√(R d0) (profile g = ξ², (5.84)). The element at
//! ξ carries the line load (5.89)/(5.91), scaled by 4G∞d0,
//! `q = (x − ξ²) + ũ/β + τ̂0 ẋ`, with the internal variable of (5.88) (ũ/d0)
//! obeying `ũ' = ẋ − ũ/τ̂` while in contact; the force is the integral of the line
//! load over the contact, `F̂ = (15/16) · 2 ∫ q dξ = (15/8) ∫_0^a q dξ`, and
//! `ẍ = −F̂`. (With ũ = 0, τ̂0 = 0: `F̂ = (5/4) x^{3/2}`, Hertz.) The discrete
//! version of the seed (elements on a grid, each with its ũ) is kept in the unit
//! tests as the reference.
//!
//! # Compression (ẋ > 0, up to the turning time t*)
//!
//! The element at ξ enters at t_ξ with x(t_ξ) = ξ², ũ = 0, and stays in contact
//! (q ≥ x − ξ² > 0). With `W' = ẋ − W/τ̂`, W(0) = 0, its internal variable is
//! `ũ(ξ, t) = W(t) − e^{−(t−t_ξ)/τ̂} W(t_ξ)`. The force only needs
//! `P(t) = ∫_0^{√x} ũ dξ`, which obeys `P' = √x ẋ − P/τ̂` (the element entering at
//! the edge has ũ = 0). With `V = W/β`, `R = P/β` (line-load units) and a = √x:
//!
//! ```text
//! F̂ = (15/8) [ (2/3) a³ + R + τ̂0 a ẋ ],   ẍ = −F̂,   V' = ẋ/β − V/τ̂,   R' = a ẋ/β − R/τ̂.
//! ```
//!
//! In time this has a √t singularity at first contact (a = √x). It is integrated
//! instead in the arc parameter p with `dt/dp = 2a/N`, `da/dp = ẋ/N`,
//! `N = √(ẋ² + 4a²)`, state (t, a, ẋ, V, R): smooth from p = 0 (a = 0, ẋ = 1)
//! through the turning point (ẋ = 0, dt/dp = 1), where the phase ends. Its dense
//! output is kept (five samples per step, which reproduce the quartic continuous
//! extension exactly) as the compression record.
//!
//! # Restitution
//!
//! An element still in contact follows the same formula for ũ; written with the
//! compression parameter p of the element (its entry time t(p), x(p) = a(p)²,
//! V(p), R(p) from the record) its line load is
//! `q(p, t) = x + V + τ̂0 ẋ − a(p)² − e^{−(t−t(p))/τ̂} V(p)`. Then:
//!
//! - `∂q/∂p = −(1 + e^{−(t−t(p))/τ̂}/β) ẋ(p) dt/dp < 0`: q decreases outwards;
//! - for a fixed element, `q' = G + τ̂0 ẍ` with `G = (1 + 1/β) ẋ − ũ/(β τ̂)`, and
//!   `G' = −G/τ̂ + (1 + 1/β) ẍ + ẋ/τ̂`. At t*, G = −ũ/(β τ̂) ≤ 0; afterwards ẋ < 0
//!   and ẍ = −F̂ ≤ 0, so G < 0 and q' < 0: every element's line load falls
//!   monotonically during restitution (and after it);
//! - an element that has left never touches again. After it leaves at t_l (q = 0),
//!   the difference e between the indenter's depth at ξ and the free element's
//!   compression solves `L[e] = q_c`, where L is the element's (linear, causal)
//!   load-from-displacement law and q_c ≤ 0, falling from q_c(t_l) = 0, is the line
//!   load the element would carry had it been kept in contact. With the element's
//!   creep compliance J (≥ 0 and non-decreasing for springs and dashpots with
//!   positive constants), `e(t) = ∫_{t_l}^t J(t − σ) q_c'(σ) dσ ≤ 0`: the indenter
//!   stays above the free surface. This holds for both media, with or without the
//!   dashpot τ̂0, and the discrete reference confirms it (no renewed contact in any
//!   test case).
//!
//! So the contact is `[0, a(p_e)]`, the edge parameter p_e(t) being the unique
//! root of `q(p, t) = 0` in [0, p*] (p_e = p* at the turning point, falling), and
//!
//! ```text
//! F̂ = (15/8) [ a (x + V + τ̂0 ẋ) − a³/3 − e^{−(t−t(p_e))/τ̂} (a V(p_e) − R(p_e)) ],   a = a(p_e),
//! ```
//!
//! using `∫_0^a e^{−(t(p_e)−t_ξ)/τ̂} V(t_ξ) dξ = a V(p_e) − R(p_e)`. F̂ depends on
//! p_e only to second order (q vanishes at the edge). The restitution state is
//! (x, ẋ, V, U) with `V' = U`, `U' = −F̂/β − U/τ̂` (U = V' = ẋ/β − V/τ̂ is carried as
//! a state so that it stays accurate where τ̂ is small). Two phases:
//!
//! 1. in time, with p_e by safeguarded Newton on the record, from t* until p_e has
//!    fallen to p*/2 (near t* the root search is well posed while a continuation
//!    of the edge is not: for τ̂0 = 0 both ∂q/∂p and ∂q/∂t vanish there);
//! 2. in σ = p*/2 − p_e down to the centre (p_e = 0), with t as a state:
//!    `dt/dσ = −(∂q/∂p)/(∂q/∂t)`, which keeps q = 0 at the edge, ∂q/∂t = G + τ̂0 ẍ
//!    < 0 at the edge element. In time the end of contact is a square-root
//!    singularity (a ∝ √(t_end − t), F̂ ∝ (t_end − t)^{3/2}); in σ it is regular
//!    and ends exactly where the line load at the centre, `x + V + τ̂0 ẋ`, is 0
//!    (seed footnote 6). The rebound speed is −ẋ there.
//!
//! Should phase 2 fail (∂q/∂t ≥ 0 from a poor integration; not observed), phase 1
//! continues in time to the zero of the centre line load.
//!
//! # Accuracy and cost
//!
//! No discretization error: ε, the contact time and x_max carry the errors of the
//! integrations (relative tolerance `tol` on all of them; the compression at
//! tol/10, so that its record is accurate to the tolerance). Requested tolerances
//! above 1e-4 are tightened to 1e-4. Observed against tolerance 1e-13 over
//! β ∈ [1e-5, 1e3], δ ∈ [1e-3, 1e3]: |Δε| and |Δx_max| ≤ 1.53 tol for tol = 1e-4,
//! 1e-6, 1e-8; the relative error of the contact time ≤ 5.5 tol, except for the
//! creeping Kelvin-Maxwell impacts (δ ~ 1e3, ε < 1e-2), whose contact end is
//! ill-conditioned (the centre unloads at a rate ~1e-5, so T may be off by up to
//! 1e-3 relative at tol 1e-8 while ε is not). Against the discrete MDR of the
//! seed (200-800 elements, Richardson-extrapolated): |Δε| ≤ 1.6e-8, limited by the
//! discrete integrations (the 200-element discretization error itself is below
//! 1e-7 in ε). Cost at tolerance 1e-8: 350-650 right-hand-side evaluations
//! (≈ 0.1 ms) for τ̂ ≥ 0.1. Small τ̂ makes V, U, R stiff (they relax at the rate
//! 1/τ̂ while the motion takes a time ~3): the explicit integration was limited by
//! its stability bound (≈ 3e4 evaluations at τ̂ = 1e-4, 5e5 at 1e-5, 60-95 ms).
//! Below τ̂ = 2e-3 all phases are therefore integrated by the L-stable Rodas5P
//! (`tabor_numerics::rosenbrock`, Jacobian by differences): 1.2e3-1.2e4
//! evaluations (≤ 1.3 ms) for τ̂ ∈ [1e-5, 2e-3), 1.3e3-3.9e3 (≤ 0.5 ms) at
//! τ̂ = 1e-5 (above 2e-3 the explicit method is as cheap or cheaper), with the same accuracy (tests: agreement with the discrete MDR and
//! with tolerance 1e-13 as above). Its dense output is a quartic too. The
//! evaluation count does not include the root searches of phase 1 (a few record
//! evaluations each).

use crate::scaled::{
    ode_tolerance, restitution_from_rebound, run_phase_with, Method, ScaledImpact, SAMPLES_PER_STEP,
};
use std::cell::RefCell;
use tabor_numerics::ode::EventDirection;
use tabor_numerics::rosenbrock::Jacobian;
use tabor_numerics::tolerance::FINEST_TOLERANCE;
use tabor_restitution::{validate, Error, Result};

#[cfg(test)]
mod reference;
#[cfg(test)]
mod tests;

/// A medium in scaled form.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScaledMedium {
    /// β = G∞/G1.
    pub beta: f64,
    /// Relaxation time of the Maxwell branch, scaled by d0/v0.
    pub tau: f64,
    /// Viscosity of the parallel dashpot (Kelvin-Maxwell), as τ̂0 = v0 η0/(G∞ d0).
    pub tau0: f64,
}

impl ScaledMedium {
    /// The line load at the centre, `q(ξ = 0) = x + V + τ̂0 ẋ`, in the restitution
    /// state (x, ẋ, V, U): positive while any element is in contact.
    fn centre_load(&self, y: &[f64; 4]) -> f64 {
        y[0] + y[2] + self.tau0 * y[1]
    }
}

/// F̂ = FORCE · ∫_0^a q dξ.
const FORCE: f64 = 15.0 / 8.0;
/// The compression is integrated at this fraction of the requested tolerance.
const RECORD_TOLERANCE_FACTOR: f64 = 0.1;
/// Restitution switches from time to the edge parameter when the edge parameter
/// has fallen to this fraction of its value at the turning point.
const SWITCH: f64 = 0.5;
/// Relative accuracy (in units of p*) of the edge parameter found by root search.
/// F̂ depends on it only to second order.
const EDGE_TOLERANCE: f64 = 1e-14;
const MAX_EDGE_ITERATIONS: usize = 100;
/// Requested tolerances above this are tightened to it (coarser integrations can
/// wander off for heavily damped media and cost little less).
pub(crate) const LOOSEST_TOLERANCE: f64 = 1e-4;
/// Below this scaled relaxation time the phases are integrated by the L-stable
/// Rodas5P (the explicit method would be limited by the stability bound h ≲ 3τ̂).
const STIFF_RELAXATION_TIME: f64 = 2e-3;
/// Largest step of the integrations (scaled time or arc parameter; the elastic
/// contact time is ≈ 2.94).
const MAX_STEP: f64 = 0.25;

/// Index of the components of a compression state.
const T: usize = 0;
const A: usize = 1;
const XDOT: usize = 2;
const V: usize = 3;
const R: usize = 4;

/// dt/dp and da/dp of the compression parameter p: `dt/dp = 2a/N`, `da/dp = ẋ/N`,
/// `N = √(ẋ² + 4a²)` (so that da/dt = ẋ/(2a), a = √x).
fn arc(a: f64, xdot: f64) -> (f64, f64) {
    let n = xdot.hypot(2.0 * a);
    (2.0 * a / n, xdot / n)
}

/// Compression right-hand side in the parameter p, state (t, a, ẋ, V, R).
fn compression_rhs(m: &ScaledMedium, y: &[f64; 5]) -> [f64; 5] {
    let (a, xdot) = (y[A], y[XDOT]);
    let (dt, da) = arc(a, xdot);
    let force = FORCE * (2.0 / 3.0 * a * a * a + y[R] + m.tau0 * a * xdot);
    [
        dt,
        da,
        -force * dt,
        (xdot / m.beta - y[V] / m.tau) * dt,
        (a * xdot / m.beta - y[R] / m.tau) * dt,
    ]
}

// The record keeps five samples per step: the start and `run_phase`'s four.
const _: () = assert!(SAMPLES_PER_STEP == 4);

/// The compression phase as recorded: the dense output of every step, sampled at
/// five equidistant points (the continuous extension is a quartic, so the samples
/// reproduce it exactly).
struct Compression {
    /// `1 + 4k` samples (p, (t, a, ẋ, V, R)); step j spans samples 4j ..= 4j + 4.
    samples: Vec<(f64, [f64; 5])>,
    /// The parameter p* of the turning point.
    end: f64,
}

impl Compression {
    fn steps(&self) -> usize {
        (self.samples.len() - 1) / 4
    }

    /// The step containing p (clamped to the record), searched from `hint`.
    fn step_of(&self, p: f64, hint: &mut usize) -> usize {
        let n = self.steps();
        let start = |j: usize| self.samples[4 * j].0;
        let end = |j: usize| self.samples[4 * j + 4].0;
        let j = (*hint).min(n - 1);
        let found = if p >= start(j) && p <= end(j) {
            j
        } else if j + 1 < n && p >= start(j + 1) && p <= end(j + 1) {
            j + 1
        } else if j > 0 && p >= start(j - 1) && p <= end(j - 1) {
            j - 1
        } else {
            // First step whose end is not before p.
            let (mut lo, mut hi) = (0, n - 1);
            while lo < hi {
                let mid = (lo + hi) / 2;
                if end(mid) < p {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            lo
        };
        *hint = found;
        found
    }

    /// The compression state (t, a, ẋ, V, R) at the parameter p ∈ [0, p*].
    fn state(&self, p: f64, hint: &mut usize) -> [f64; 5] {
        let j = self.step_of(p, hint);
        let nodes = &self.samples[4 * j..4 * j + 5];
        let (lo, hi) = (nodes[0].0, nodes[4].0);
        if hi <= lo {
            return nodes[0].1;
        }
        // Lagrange basis on u = 0, 1, 2, 3, 4.
        let u = 4.0 * ((p - lo) / (hi - lo)).clamp(0.0, 1.0);
        let d = [u, u - 1.0, u - 2.0, u - 3.0, u - 4.0];
        let w = [
            d[1] * d[2] * d[3] * d[4] / 24.0,
            -d[0] * d[2] * d[3] * d[4] / 6.0,
            d[0] * d[1] * d[3] * d[4] / 4.0,
            -d[0] * d[1] * d[2] * d[4] / 6.0,
            d[0] * d[1] * d[2] * d[3] / 24.0,
        ];
        let mut out = [0.0; 5];
        for (i, o) in out.iter_mut().enumerate() {
            *o = (0..5).map(|k| w[k] * nodes[k].1[i]).sum();
        }
        out
    }
}

/// The restitution phase: the contact edge and the force.
struct Restitution<'a> {
    m: ScaledMedium,
    record: &'a Compression,
    /// Edge parameter at the last root search (start of the next one).
    edge: f64,
    hint: usize,
}

impl Restitution<'_> {
    /// e^{−(t − t_c)/τ̂}: the relaxation since the edge element entered at t_c.
    fn decay(&self, t: f64, c: &[f64; 5]) -> f64 {
        (-(t - c[T]).max(0.0) / self.m.tau).exp()
    }

    /// The line load of the element with compression parameter p at time t, and
    /// its derivative in p; `centre` = x + V + τ̂0 ẋ is the line load at ξ = 0.
    fn line_load(&mut self, t: f64, centre: f64, p: f64) -> (f64, f64, [f64; 5]) {
        let c = self.record.state(p, &mut self.hint);
        let e = self.decay(t, &c);
        let q = centre - c[A] * c[A] - e * c[V];
        let (dt, _) = arc(c[A], c[XDOT]);
        let dq = -c[XDOT].max(0.0) * dt * (1.0 + e / self.m.beta);
        (q, dq, c)
    }

    /// The compression parameter p ∈ [0, p*] of the element at the contact edge:
    /// the root of the line load (falling in p), by Newton's method safeguarded by
    /// bisection (Numerical Recipes' `rtsafe`). Returns p and the record there.
    ///
    /// Written out rather than `tabor_numerics::root_finding::newton_safeguarded`:
    /// it runs inside every right-hand-side evaluation, where the signs at both ends
    /// are known (q(0) = centre load > 0, q(p*) from the caller), so the two end
    /// evaluations and the typed errors of the general routine would only add cost.
    fn edge(&mut self, t: f64, centre: f64) -> (f64, [f64; 5]) {
        let p_star = self.record.end;
        let (q_end, _, c_end) = self.line_load(t, centre, p_star);
        if q_end.is_nan() || q_end >= 0.0 {
            self.edge = p_star;
            return (p_star, c_end);
        }
        let (mut lo, mut hi) = (0.0, p_star);
        let tolerance = EDGE_TOLERANCE * p_star;
        let mut p = self.edge;
        if !(p > lo && p < hi) {
            p = 0.5 * (lo + hi);
        }
        let mut dx_old = hi - lo;
        let mut dx = dx_old;
        for _ in 0..MAX_EDGE_ITERATIONS {
            let (q, dq, c) = self.line_load(t, centre, p);
            if q.is_nan() || q == 0.0 {
                self.edge = p;
                return (p, c);
            }
            if q > 0.0 {
                lo = p;
            } else {
                hi = p;
            }
            let newton = p - q / dq;
            if !(newton > lo && newton < hi) || (2.0 * q).abs() > (dx_old * dq).abs() {
                dx_old = dx;
                dx = 0.5 * (hi - lo);
                p = lo + dx;
            } else {
                dx_old = dx;
                dx = q / dq;
                p = newton;
            }
            if dx.abs() <= tolerance || hi - lo <= tolerance {
                break;
            }
        }
        self.edge = p;
        let c = self.record.state(p, &mut self.hint);
        (p, c)
    }

    /// F̂ with the contact edge at the element recorded as `c`, the line load at the
    /// centre `centre`.
    fn force_at(&self, t: f64, centre: f64, c: &[f64; 5]) -> f64 {
        let a = c[A];
        let e = self.decay(t, c);
        FORCE * (a * centre - a * a * a / 3.0 - e * (a * c[V] - c[R]))
    }

    /// Phase 1, in time, state (x, ẋ, V, U): F̂ (edge by root search).
    fn force(&mut self, t: f64, y: &[f64; 4]) -> f64 {
        let centre = self.m.centre_load(y);
        if centre.is_nan() {
            return f64::NAN;
        }
        if centre <= 0.0 {
            return 0.0;
        }
        let (_, c) = self.edge(t, centre);
        self.force_at(t, centre, &c)
    }

    /// Phase 1 right-hand side: `x' = ẋ, ẋ' = −F̂, V' = U, U' = −F̂/β − U/τ̂`.
    fn rhs_time(&mut self, t: f64, y: &[f64; 4]) -> [f64; 4] {
        let force = self.force(t, y);
        [y[1], -force, y[3], -force / self.m.beta - y[3] / self.m.tau]
    }

    /// The edge parameter at time t in state y (phase 1's event function).
    fn edge_of(&mut self, t: f64, y: &[f64; 4]) -> f64 {
        let centre = self.m.centre_load(y);
        if centre.is_nan() {
            return f64::NAN;
        }
        if centre <= 0.0 {
            return 0.0;
        }
        self.edge(t, centre).0
    }

    /// Phase 2 right-hand side in σ = p_switch − p (p the edge parameter), state
    /// (t, x, ẋ, V, U): the phase-1 equations times dt/dσ = ∂q/∂p / ∂q/∂t, which
    /// keeps the line load at the edge at 0 (NaN if ∂q/∂t ≥ 0, impossible in the
    /// exact solution).
    fn rhs_edge(&mut self, p: f64, y: &[f64; 5]) -> [f64; 5] {
        let (t, x, xdot, v, u) = (y[0], y[1], y[2], y[3], y[4]);
        let c = self.record.state(p.max(0.0), &mut self.hint);
        let centre = x + v + self.m.tau0 * xdot;
        let force = self.force_at(t, centre, &c);
        let e = self.decay(t, &c);
        // ∂q/∂t at the edge (< 0) and ∂q/∂p (< 0).
        let q_t = xdot + u + e * c[V] / self.m.tau - self.m.tau0 * force;
        let (dt_dp, _) = arc(c[A], c[XDOT]);
        let q_p = -c[XDOT] * dt_dp * (1.0 + e / self.m.beta);
        let dt = if q_t < 0.0 { q_p / q_t } else { f64::NAN };
        [
            dt,
            xdot * dt,
            -force * dt,
            u * dt,
            (-force / self.m.beta - u / self.m.tau) * dt,
        ]
    }
}

/// The impact (module docs): compression, then restitution on the recorded
/// compression, relative tolerance `tolerance` (tightened to at most
/// [`LOOSEST_TOLERANCE`]).
pub(crate) fn solve(m: &ScaledMedium, tolerance: f64) -> Result<ScaledImpact> {
    let tol = validate::tolerance("tolerance", tolerance)?.min(LOOSEST_TOLERANCE);
    let method = method_for(m);
    Ok(solve_with(
        m,
        (tol * RECORD_TOLERANCE_FACTOR).max(FINEST_TOLERANCE),
        tol,
        false,
        method,
    )?
    .0)
}

/// The integrator for a medium: Rodas5P below [`STIFF_RELAXATION_TIME`], where the
/// internal variables relax much faster than the motion, else Dormand-Prince.
fn method_for(m: &ScaledMedium) -> Method {
    if m.tau < STIFF_RELAXATION_TIME {
        Method::Stiff(Jacobian::NonAutonomous)
    } else {
        Method::Explicit
    }
}

/// How the restitution was integrated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Route {
    /// Phase 1 in time, phase 2 in the edge parameter.
    Edge,
    /// Phase 2 failed; phase 1 continued in time to the end.
    Time,
}

/// [`solve`] with separate tolerances for the compression (record) and the
/// restitution; `time_only` skips phase 2 (the fallback route, for tests).
fn solve_with(
    m: &ScaledMedium,
    compression: f64,
    restitution: f64,
    time_only: bool,
    method: Method,
) -> Result<(ScaledImpact, Route)> {
    // The compression right-hand side does not depend on p.
    let method_p = match method {
        Method::Stiff(_) => Method::Stiff(Jacobian::Autonomous),
        Method::Explicit => Method::Explicit,
    };
    let tol = ode_tolerance(restitution, MAX_STEP)?;
    let tol_record = ode_tolerance(compression, MAX_STEP)?;
    let t_max = 1e4 * (1.0 + m.tau + m.tau0);
    // Compression in the parameter p, to ẋ = 0.
    let mut samples = Vec::new();
    let mut f1 = |_p: f64, y: &[f64; 5]| compression_rhs(m, y);
    let first = run_phase_with(
        method_p,
        &mut f1,
        &mut |_p: f64, y: &[f64; 5]| y[XDOT],
        EventDirection::Falling,
        0.0,
        [0.0, 0.0, 1.0, 0.0, 0.0],
        t_max,
        tol_record,
        Some(&mut samples),
    )?;
    if samples.len() < 5 || (samples.len() - 1) % 4 != 0 || first.t <= 0.0 {
        return Err(model_error("the compression record is incomplete"));
    }
    let record = Compression {
        samples,
        end: first.t,
    };
    let (t_star, a_star, v_star) = (first.y[T], first.y[A], first.y[V]);
    let phase = RefCell::new(Restitution {
        m: *m,
        record: &record,
        edge: first.t,
        hint: record.steps() - 1,
    });
    let mut f2 = |t: f64, y: &[f64; 4]| phase.borrow_mut().rhs_time(t, y);
    // Phase 1: in time, edge by root search, until the edge parameter falls to
    // SWITCH · p*.
    let p_switch = SWITCH * first.t;
    let start = [
        a_star * a_star,
        first.y[XDOT],
        v_star,
        first.y[XDOT] / m.beta - v_star / m.tau,
    ];
    let second = run_phase_with(
        method,
        &mut f2,
        &mut |t: f64, y: &[f64; 4]| phase.borrow_mut().edge_of(t, y) - p_switch,
        EventDirection::Falling,
        t_star,
        start,
        t_star + t_max,
        tol,
        None,
    )?;
    // Phase 2: in σ = p_switch − p down to the centre (p = 0).
    let mut f3 = |sigma: f64, y: &[f64; 5]| phase.borrow_mut().rhs_edge(p_switch - sigma, y);
    let third = if time_only {
        Err(model_error("phase 2 skipped"))
    } else {
        run_phase_with(
            method,
            &mut f3,
            &mut |sigma: f64, _y: &[f64; 5]| p_switch - sigma,
            EventDirection::Falling,
            0.0,
            [second.t, second.y[0], second.y[1], second.y[2], second.y[3]],
            p_switch,
            tol,
            None,
        )
    };
    let (rebound, contact_time, cost, route) = match third {
        Ok(end) => (-end.y[2], end.y[0], end.cost, Route::Edge),
        Err(_) => {
            // Fallback: phase 1's equations in time to the end of contact.
            let end = run_phase_with(
                method,
                &mut f2,
                &mut |_t: f64, y: &[f64; 4]| m.centre_load(y),
                EventDirection::Falling,
                second.t,
                second.y,
                second.t + t_max,
                tol,
                None,
            )?;
            (-end.y[1], end.t, end.cost, Route::Time)
        }
    };
    Ok((
        ScaledImpact {
            restitution: restitution_from_rebound(rebound)?,
            contact_time,
            max_overlap: a_star * a_star,
            cost: first.cost + second.cost + cost,
        },
        route,
    ))
}

fn model_error(what: &str) -> Error {
    Error::Model {
        model: "viscoelastic impact",
        message: format!("MDR continuum solution: {what}"),
    }
}

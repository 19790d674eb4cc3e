//! The impact of a Hertzian sphere with a power-law dashpot in the scaling (5.74),
//! shared by [`crate::damping_law`] and [`crate::kelvin_voigt_sphere`]:
//!
//! - compression (ẋ > 0): `ẍ = −F`, `F = (5/4) x^{3/2} + γ x^β ẋ` (seed 000 (5.72);
//!   with β = 1/2, γ = c it is Kuwabara-Kono's (5.66));
//! - restitution, [`Restitution::Damped`]: the same law until F = 0 (or x = 0);
//! - restitution, [`Restitution::Rigorous`]: `F = (5/4) (x + τ̂ ẋ)^{3/2}` until
//!   `x + τ̂ ẋ = 0` (the Kelvin-Voigt sphere with the MDR edge condition (5.67)).
//!
//! # Why the formulation matters (large damping)
//!
//! After the turning point the velocity relaxes at the rate `γ x^β` towards the
//! creep velocity `v_c(x) = −(5/4) x^{3/2−β}/γ`, and on that slow manifold the force
//! is `F = −ẍ ≈ −v_c' v_c < 0` (for β < 3/2): F crosses zero during the relaxation,
//! a few `ln`-e-folds `1/(γ x^β)` after the turning point, and the rebound speed is
//! ε ≈ |v_c(x*)| (for γ = 1e3 and β = 0, ε ≈ (5/4) γ^{−5/2} ≈ 4e-8). Two things
//! broke the former integration there:
//!
//! 1. The absolute tolerance equalled the relative one (1e-8 on a velocity of
//!    4e-8): ε came out wrong by O(1) factors (δ = 1e3: 1.4e-7 instead of 2.2e-6).
//! 2. The event function `F/x^β = (5/4) x^{3/2−β} + γ ẋ` is, near its zero, the
//!    difference of two terms ~γ^{2.5} times larger than its quasi-steady value
//!    (β = 0). Its sign was set by the integration error, not by the physics; the
//!    explicit method then ran along the creep manifold at its stability limit
//!    (h γ x^β ≈ 3.31, where the Dormand-Prince stability function R → +1, so the
//!    positive force transient is carried along undamped) and never saw F < 0:
//!    4e6 steps and an error.
//!
//! So the integration uses a pure relative error control (absolute tolerance
//! [`ABSOLUTE`]: every component is resolved relative to its own size, down to
//! ε ~ 1e-8), and in the overdamped regime (creep speed at the turning point
//! `ρ = |v_c(x*)| < 1`) the restitution carries `φ = F/x^β` as a state with
//! `φ' = (5/4)(3/2 − β) x^{1/2−β} ẋ − γ x^β φ`: the end of contact is a state
//! crossing zero, no cancellation. That equation is singular at x = 0 for
//! β > 1/2; if x falls to x*/2 before φ vanishes (β near 3/2 with moderate γ: the
//! force then vanishes only at tiny x) the direct form `(5/4) x^{3/2−β} + γ ẋ`,
//! well conditioned there, takes over. For β = 3/2, `φ' = −γ x^β φ`: φ never
//! changes sign and the contact ends at x = 0. The rigorous restitution carries
//! `z = x + τ̂ẋ` as a state for the same reason. After the reformulation the phases
//! are short (the relaxation has to be resolved anyway to locate F = 0): the
//! explicit method needs a few thousand right-hand-side evaluations at any
//! damping, so no stiff integrator is needed here (the only stability-limited
//! stretch, the creep of β ≈ 3/2 at γ = 1e3 over T_S ≈ 70, takes ≈ 600 steps).
//!
//! # Energy loss
//!
//! The dissipated energy `D` (`D' = γ x^β ẋ²`, resp. `(5/4)(x^{3/2} − z^{3/2})(−ẋ)`
//! for the rigorous restitution, z = x + τ̂ẋ) is integrated along, so that the loss
//! `1 − ε = (2D + x_e^{5/2})/(1 + ε)` (energy balance with the Hertz potential
//! `x^{5/2}/2`, x_e the overlap at separation) is accurate relative to itself even
//! where ε → 1. The inverse problems use it. D is carried with an offset (its
//! elastic estimate), because D itself starts as t^{β+1}, whose relative error no
//! step size reduces.

use crate::scaled::{restitution_from_rebound, run_phase, PhaseEnd, ScaledImpact, ScaledPoint};
use tabor_numerics::ode::{EventDirection, OdeTolerance};
use tabor_numerics::{special, tolerance};
use tabor_restitution::{validate, Error, Result};

/// Absolute tolerance of the integrations: negligible against every component
/// (pure relative error control), but above the subnormal range.
const ABSOLUTE: f64 = 1e-300;
/// The requested tolerance is tightened by this factor for the integration, so
/// that the global errors of ε, x_max and T_S stay below the tolerance.
const TIGHTEN: f64 = 0.1;
/// Tolerances looser than this are tightened to it (a looser integration saves
/// nothing worth the risk).
const LOOSEST: f64 = 1e-3;
/// Largest step of the integrations (scaled time; the elastic contact time is
/// ≈ 2.94).
const MAX_STEP: f64 = 0.25;
/// Step limit of each phase (never approached: a few thousand at most).
const MAX_STEPS: u64 = 200_000;
/// Below this creep speed at the turning point the restitution uses the φ state.
const OVERDAMPED: f64 = 1.0;

/// The restitution law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Restitution {
    /// The compression law (5.72) until F = 0 or x = 0.
    Damped,
    /// `F = (5/4) (x + τ̂ ẋ)^{3/2}` until `x + τ̂ ẋ = 0`; τ̂ > 0.
    Rigorous {
        /// The scaled relaxation time τ̂.
        tau: f64,
    },
}

/// An impact and its loss.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Outcome {
    /// The impact.
    pub impact: ScaledImpact,
    /// `1 − ε`, accurate relative to itself.
    pub loss: f64,
}

/// The integration tolerance for a requested tolerance.
fn integration_tolerance(tolerance: f64) -> Result<OdeTolerance> {
    let tol = validate::tolerance("tolerance", tolerance)?.min(LOOSEST) * TIGHTEN;
    Ok(
        OdeTolerance::new(tol.max(tolerance::FINEST_TOLERANCE), ABSOLUTE)
            .with_max_step(MAX_STEP)
            .with_max_steps(MAX_STEPS),
    )
}

/// `x^p` for the overlap x clamped at 0. The exponents the laws of seed 000 use
/// (β = 1/2 of Kuwabara-Kono (5.66), the Hertz 3/2 and the energy's 5/2) by a
/// square root, which costs a tenth of `powf` and is correctly rounded (the two
/// differ by at most an ulp); `powf` for any other exponent.
fn pow(x: f64, p: f64) -> f64 {
    let x = x.max(0.0);
    if p == 0.5 {
        x.sqrt()
    } else if p == 1.5 {
        x * x.sqrt()
    } else if p == 2.5 {
        x * x * x.sqrt()
    } else {
        x.powf(p)
    }
}

/// The dissipated energy of the elastic (γ → 0) impact per unit γ:
/// `∫ x^β ẋ² dt = 2 ∫_0^1 x^β √(1 − x^{5/2}) dx = (4/5) B(2(β + 1)/5, 3/2)`.
fn elastic_dissipation(beta: f64) -> Result<f64> {
    Ok(0.8 * special::beta(0.4 * (beta + 1.0), 1.5)?)
}

/// The φ state is carried as `Q = φ + FLOOR · φ*` (φ* its value at the turning
/// point): the relative error control then resolves φ relative to itself while
/// it is above `FLOOR · φ*` and to `tol · FLOOR · φ*` absolute beyond, where its
/// effect on ε (`∫ x^β δφ dt`) is negligible. Without it the control follows the
/// exponential decay of φ to underflow (β = 3/2: 6e5 evaluations at γ = 1e3).
const FLOOR: f64 = 1e-6;

/// The integration tolerance with a first step `h0` (the automatic choice is
/// unreliable under a pure relative error control when a component starts at 0).
fn first_step(tol: OdeTolerance, h0: f64) -> OdeTolerance {
    let mut tol = tol;
    if h0.is_finite() && h0 > 0.0 {
        tol.initial_step = Some(h0.min(MAX_STEP));
    }
    tol
}

/// Appends the recorded states of a phase with their forces.
fn extend<const N: usize>(
    points: &mut Vec<ScaledPoint>,
    raw: &[(f64, [f64; N])],
    force: impl Fn(&[f64; N]) -> f64,
) {
    points.extend(raw.iter().map(|(t, y)| ScaledPoint {
        time: *t,
        overlap: y[0],
        overlap_rate: y[1],
        force: force(y).max(0.0),
    }));
}

/// The law (5.72): exponent β and scaled damping γ.
#[derive(Clone, Copy)]
struct Law {
    beta: f64,
    gamma: f64,
}

impl Law {
    /// `F = (5/4) x^{3/2} + γ x^β ẋ`.
    fn force(self, x: f64, v: f64) -> f64 {
        1.25 * pow(x, 1.5) + self.gamma * pow(x, self.beta) * v
    }

    /// `(ẋ, −F, D')` for the state (x, ẋ).
    fn damped(self, x: f64, v: f64) -> [f64; 3] {
        let damping = self.gamma * pow(x, self.beta);
        [v, -1.25 * pow(x, 1.5) - damping * v, damping * v * v]
    }

    /// `F/x^β`, computed directly.
    fn reduced_force(self, x: f64, v: f64) -> f64 {
        1.25 * pow(x, 1.5 - self.beta) + self.gamma * v
    }
}

/// The problem: the law, tolerance, what to record.
struct Problem<'a> {
    law: Law,
    tol: OdeTolerance,
    record: Option<&'a mut Vec<ScaledPoint>>,
}

impl Problem<'_> {
    /// One phase from `start` until `g` falls through zero, recording the states
    /// with their forces `force(y)` when a trajectory is wanted.
    fn phase<F, G, const N: usize>(
        &mut self,
        mut f: F,
        mut g: G,
        start: (f64, [f64; N]),
        t_end: f64,
        force: impl Fn(&[f64; N]) -> f64,
    ) -> Result<PhaseEnd<N>>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
        G: FnMut(f64, &[f64; N]) -> f64,
    {
        let mut raw = Vec::new();
        let want = self.record.is_some();
        let end = run_phase(
            &mut f,
            &mut g,
            EventDirection::Falling,
            start.0,
            start.1,
            t_end,
            self.tol,
            want.then_some(&mut raw),
        )?;
        if let Some(points) = self.record.as_deref_mut() {
            extend(points, &raw, force);
        }
        Ok(end)
    }

    /// Compression in the state (x, ẋ, E) from first contact to ẋ = 0.
    fn direct_until_turning(&mut self, offset: f64, t_max: f64) -> Result<PhaseEnd<3>> {
        let law = self.law;
        self.phase(
            |_t: f64, y: &[f64; 3]| law.damped(y[0], y[1]),
            |_t: f64, y: &[f64; 3]| y[1],
            (0.0, [0.0, 1.0, offset]),
            t_max,
            |y| law.force(y[0], y[1]),
        )
    }

    /// The law (5.72) in the state (x, ẋ, E) from `start` until F = 0 or x = 0.
    fn direct(&mut self, start: (f64, [f64; 3]), t_end: f64) -> Result<PhaseEnd<3>> {
        let law = self.law;
        self.phase(
            |_t: f64, y: &[f64; 3]| law.damped(y[0], y[1]),
            |_t: f64, y: &[f64; 3]| law.reduced_force(y[0], y[1]).min(y[0]),
            start,
            t_end,
            |y| law.force(y[0], y[1]),
        )
    }
}

/// The impact with damping exponent `beta` ∈ [0, 3/2], scaled damping `gamma` > 0
/// and the given restitution law; `record` receives the trajectory.
pub(crate) fn solve(
    beta: f64,
    gamma: f64,
    law: Restitution,
    tolerance: f64,
    record: Option<&mut Vec<ScaledPoint>>,
) -> Result<Outcome> {
    let tol = integration_tolerance(tolerance)?;
    // The dissipated energy is carried as E = D + D_s, D_s ≈ its final value, so
    // that the relative error control bounds its error by tol·D_final (D itself
    // starts as t^{β+1}, whose relative error no step size reduces).
    let offset = (gamma * elastic_dissipation(beta)?).min(0.5);
    // Compression: (x, ẋ, E); first step a small fraction of the time to reach the
    // overdamped overlap x∞ = ((β + 1)/γ)^{1/(β+1)} (or of the elastic time).
    let x_inf = ((beta + 1.0) / gamma).powf(1.0 / (beta + 1.0));
    let t_max = 1e4 * (1.0 + gamma);
    let mut p = Problem {
        law: Law { beta, gamma },
        tol: first_step(tol, 1e-4 * x_inf.min(1.0)),
        record,
    };
    let first = p.direct_until_turning(offset, t_max)?;
    let (t_star, x_star, e_star) = (first.t, first.y[0], first.y[2]);
    if !(x_star > 0.0 && x_star.is_finite()) {
        return Err(model_error("the compression found no turning point"));
    }
    // Restitution. First step: a small fraction of the elastic time √(x*/F*) and
    // of the relaxation time 1/(γ x*^β).
    let elastic_time = (x_star / (1.25 * pow(x_star, 1.5))).sqrt();
    let relaxation_time = 1.0 / (gamma * pow(x_star, beta));
    p.tol = first_step(tol, 1e-4 * elastic_time.min(relaxation_time));
    let t_end = t_star + t_max;
    let turning = (t_star, [x_star, 0.0, e_star]);
    let (end, mut cost) = match law {
        Restitution::Damped if 1.25 * pow(x_star, 1.5 - beta) / gamma < OVERDAMPED => {
            let a = p.overdamped(turning, t_end)?;
            match a {
                (end, true) => (end, first.cost),
                (switch, false) => {
                    let cost = first.cost + switch.cost;
                    (p.direct((switch.t, switch.y), t_end)?, cost)
                }
            }
        }
        Restitution::Damped => (p.direct(turning, t_end)?, first.cost),
        Restitution::Rigorous { tau } => (p.rigorous(tau, turning, t_end)?, first.cost),
    };
    cost += end.cost;
    let restitution = restitution_from_rebound(-end.y[1])?;
    let dissipated = (end.y[2] - offset).max(0.0);
    let loss = (2.0 * dissipated + pow(end.y[0], 2.5)) / (1.0 + restitution);
    Ok(Outcome {
        impact: ScaledImpact {
            restitution,
            contact_time: end.t,
            max_overlap: x_star,
            cost,
        },
        loss: validate::finite("energy loss", loss)?.clamp(0.0, 1.0),
    })
}

impl Problem<'_> {
    /// Overdamped restitution in the state (x, ẋ, Q, E), `Q = φ + FLOOR φ*`, from
    /// the turning point until φ = 0 (returns `true`) or x = x*/2 (`false`; then
    /// the direct form takes over: the contact can end near x = 0, where φ' is
    /// singular for β > 1/2). For β = 3/2, `φ' = −γ x^β φ` never changes sign and
    /// the phase runs to x = 0 (`true`).
    fn overdamped(&mut self, start: (f64, [f64; 3]), t_end: f64) -> Result<(PhaseEnd<3>, bool)> {
        let Law { beta, gamma } = self.law;
        let x_star = start.1[0];
        let source = 1.25 * (1.5 - beta);
        let phi_star = 1.25 * pow(x_star, 1.5 - beta);
        let floor = FLOOR * phi_star;
        let switch = if source > 0.0 { 0.5 * x_star } else { 0.0 };
        let f = |_t: f64, y: &[f64; 4]| {
            let xb = pow(y[0], beta);
            let phi = y[2] - floor;
            // (d/dt)(5/4) x^{3/2−β}: regular for x ≥ x*/2; 0 in trial stages
            // beyond x = 0 (β = 3/2: 0).
            let creep = if source > 0.0 && y[0] > 0.0 {
                source * pow(y[0], 0.5 - beta) * y[1]
            } else {
                0.0
            };
            [
                y[1],
                -xb * phi,
                creep - gamma * xb * phi,
                gamma * xb * y[1] * y[1],
            ]
        };
        let g = |_t: f64, y: &[f64; 4]| {
            if source > 0.0 {
                (y[2] - floor).min(y[0] - switch)
            } else {
                y[0]
            }
        };
        let end = self.phase(
            f,
            g,
            (start.0, [x_star, 0.0, phi_star + floor, start.1[2]]),
            t_end,
            |y| pow(y[0], beta) * (y[2] - floor),
        )?;
        let phi = end.y[2] - floor;
        let done = switch == 0.0 || phi <= end.y[0] - switch;
        Ok((
            PhaseEnd {
                t: end.t,
                y: [end.y[0], end.y[1], end.y[3]],
                cost: end.cost,
            },
            done,
        ))
    }

    /// Rigorous Kelvin-Voigt restitution (β = 1/2) in the state (x, ẋ, z, E),
    /// z = x + τ̂ ẋ (a²/(R d0)), `z' = ẋ − (5/4) τ̂ z^{3/2}`, until z = 0 (as a state,
    /// the end is not the difference of x and −τ̂ẋ, ≈ x* each for large τ̂, which
    /// put the contact time off by ~tol·τ̂).
    fn rigorous(&mut self, tau: f64, start: (f64, [f64; 3]), t_end: f64) -> Result<PhaseEnd<3>> {
        let f = |_t: f64, y: &[f64; 4]| {
            let (x, v) = (y[0].max(0.0), y[1]);
            let force = 1.25 * pow(y[2], 1.5);
            // x^{3/2} − z^{3/2} = x^{3/2} (1 − (1 + u)^{3/2}), u = τ̂ẋ/x ∈ [−1, 0]
            // (from ẋ: accurate also where τ̂ẋ ≪ x).
            let u = if x > 0.0 {
                (tau * v / x).clamp(-1.0, 0.0)
            } else {
                -1.0
            };
            let excess = -pow(x, 1.5) * (1.5 * u.ln_1p()).exp_m1();
            [v, -force, v - tau * force, -1.25 * excess * v]
        };
        let x_star = start.1[0];
        let end = self.phase(
            f,
            |_t: f64, y: &[f64; 4]| y[2],
            (start.0, [x_star, 0.0, x_star, start.1[2]]),
            t_end,
            |y| 1.25 * pow(y[2], 1.5),
        )?;
        Ok(PhaseEnd {
            t: end.t,
            y: [end.y[0], end.y[1], end.y[3]],
            cost: end.cost,
        })
    }
}

fn model_error(what: &str) -> Error {
    Error::Model {
        model: "viscoelastic impact",
        message: format!("sphere with power-law damping: {what}"),
    }
}

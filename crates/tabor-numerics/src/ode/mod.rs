//! Adaptive integrators for small ODE systems `y' = f(t, y)`, `y ∈ ℝᴺ`, with dense
//! output and event location. This module holds what every method shares; the
//! methods live in their own modules:
//!
//! - [`DormandPrince`] (module `dormand_prince`): explicit Runge-Kutta 5(4) with a
//!   4th-order dense output, for non-stiff systems; [`solve`] and
//!   [`solve_until_event`] integrate with it;
//! - [`DormandPrince853`] (module `dop853`): explicit Runge-Kutta of order 8 with a
//!   7th-order dense output prepared on demand, for tight tolerances (the impact
//!   simulator of `tabor-dynamics`);
//! - [`rosenbrock`]: the L-stable Rosenbrock methods Rodas5P (default) and RODAS4,
//!   for stiff systems.
//!
//! Shared here:
//!
//! - [`OdeTolerance`]: the error norm, tolerances and step limits of every method;
//! - [`EventDirection`], [`EventPoint`] and [`locate_event_in_step`]: the sign
//!   changes of a user function `g(t, y)`, located on the dense output of the last
//!   step with Brent's method ([`crate::root_finding::brent`]), so locating them
//!   costs no evaluations of `f`;
//! - [`DenseStepper`]: the interface of a one-step integrator with dense output;
//! - [`drive`] and [`drive_events`]: the one step-and-locate-event loop (one event
//!   function, or several of which the earliest crossing wins), with an observer
//!   called after every accepted step (to record a trajectory or watch the state);
//!   every solver, phase integration and the impact simulator of the workspace is
//!   built on it;
//! - [`OdeSolution`], [`Integration`]: what a driver returns.
//!
//! The state is a fixed-size array `[f64; N]` (no allocation per step).

#![allow(clippy::needless_range_loop)] // component loops over small fixed arrays

mod dop853;
mod dormand_prince;
pub mod rosenbrock;

pub use dop853::DormandPrince853;
pub use dormand_prince::{solve, solve_until_event, DormandPrince};

use crate::root_finding::{brent, RootTolerance};
use crate::{Cost, NumericsError, Result};

/// Accuracy and limits of an integration. A step is accepted when the embedded
/// error estimate satisfies `|err_i| ≤ absolute + relative · max(|y_i|, |y_i,new|)`
/// in the root-mean-square norm over the components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdeTolerance {
    /// Relative tolerance (≥ 1e-15 after raising; must be finite and ≥ 0).
    pub relative: f64,
    /// Absolute tolerance (finite, ≥ 0; relative and absolute may not both be 0).
    pub absolute: f64,
    /// Limit on the number of steps (accepted plus rejected).
    pub max_steps: u64,
    /// Largest step allowed (> 0, may be infinite).
    pub max_step: f64,
    /// First trial step; `None` chooses it automatically (Hairer's `HINIT`).
    pub initial_step: Option<f64>,
}

impl OdeTolerance {
    /// Relative tolerance `relative`, absolute tolerance `absolute`, at most one
    /// million steps, no step limit, automatic first step.
    pub fn new(relative: f64, absolute: f64) -> Self {
        OdeTolerance {
            relative,
            absolute,
            max_steps: 1_000_000,
            max_step: f64::INFINITY,
            initial_step: None,
        }
    }

    /// The same tolerance with a largest step `max_step`.
    pub fn with_max_step(mut self, max_step: f64) -> Self {
        self.max_step = max_step;
        self
    }

    /// The same tolerance with at most `max_steps` steps.
    pub fn with_max_steps(mut self, max_steps: u64) -> Self {
        self.max_steps = max_steps;
        self
    }

    pub(crate) fn validate(&self) -> Result<()> {
        let check = |name: &'static str, v: f64| {
            if v.is_finite() && v >= 0.0 {
                Ok(())
            } else {
                Err(NumericsError::InvalidArgument {
                    name,
                    value: v,
                    requirement: "must be finite and >= 0",
                })
            }
        };
        check("relative tolerance", self.relative)?;
        check("absolute tolerance", self.absolute)?;
        if self.relative == 0.0 && self.absolute == 0.0 {
            return Err(NumericsError::InvalidArgument {
                name: "absolute tolerance",
                value: 0.0,
                requirement: "relative and absolute tolerance may not both be 0",
            });
        }
        if self.max_step.is_nan() || self.max_step <= 0.0 {
            return Err(NumericsError::InvalidArgument {
                name: "max_step",
                value: self.max_step,
                requirement: "must be > 0",
            });
        }
        if self.max_steps == 0 {
            return Err(NumericsError::InvalidArgument {
                name: "max_steps",
                value: 0.0,
                requirement: "must be at least 1",
            });
        }
        if let Some(h) = self.initial_step {
            if !(h.is_finite() && h > 0.0) {
                return Err(NumericsError::InvalidArgument {
                    name: "initial_step",
                    value: h,
                    requirement: "must be finite and > 0",
                });
            }
        }
        Ok(())
    }

    /// The error scale of a component that was `a` before and `b` after a step.
    pub(crate) fn error_scale(&self, a: f64, b: f64) -> f64 {
        self.absolute + self.relative_effective() * a.abs().max(b.abs())
    }

    pub(crate) fn relative_effective(&self) -> f64 {
        self.relative.max(1e-15)
    }
}

impl Default for OdeTolerance {
    /// `relative` = [`ODE_TOLERANCE`](crate::tolerance::ODE_TOLERANCE) (1e-11),
    /// `absolute` = [`ODE_ABSOLUTE_TOLERANCE`](crate::tolerance::ODE_ABSOLUTE_TOLERANCE)
    /// (1e-13): the default of every simulated impact
    /// (`tabor_dynamics::SimulationSettings::default`).
    fn default() -> Self {
        OdeTolerance::new(
            crate::tolerance::ODE_TOLERANCE,
            crate::tolerance::ODE_ABSOLUTE_TOLERANCE,
        )
    }
}

/// Which sign changes of an event function count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventDirection {
    /// From `g > 0` to `g ≤ 0`.
    Falling,
    /// From `g < 0` to `g ≥ 0`.
    Rising,
    /// Either of the two.
    Either,
}

impl EventDirection {
    /// True when going from `before` to `after` is a crossing in this direction.
    /// A value that starts at exactly 0 never triggers, so an integration restarted
    /// at an event does not find the same event again.
    pub fn is_crossing(self, before: f64, after: f64) -> bool {
        let falling = before > 0.0 && after <= 0.0;
        let rising = before < 0.0 && after >= 0.0;
        match self {
            EventDirection::Falling => falling,
            EventDirection::Rising => rising,
            EventDirection::Either => falling || rising,
        }
    }
}

/// A located event: where the event function changed sign.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventPoint<const N: usize> {
    /// Time of the sign change.
    pub t: f64,
    /// State there (from the dense output).
    pub y: [f64; N],
}

/// The result of a driver ([`solve`], [`solve_until_event`], [`drive`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdeSolution<const N: usize> {
    /// Where the integration stopped: the final time, or the event time.
    pub t: f64,
    /// State at `t`.
    pub y: [f64; N],
    /// True when an event stopped the integration.
    pub event_found: bool,
    /// Accepted steps.
    pub accepted_steps: u64,
    /// Rejected steps.
    pub rejected_steps: u64,
    /// Right-hand-side evaluations (`evaluations`) and steps (`iterations`).
    pub cost: Cost,
}

/// A one-step integrator with a dense output on its last accepted step
/// ([`DormandPrince`], [`rosenbrock::Rosenbrock`]): what event location
/// ([`locate_event_in_step`]) and the driver ([`drive`]) need.
pub trait DenseStepper<const N: usize> {
    /// Current time and state.
    fn current(&self) -> (f64, [f64; N]);
    /// Start of the last accepted step.
    fn step_start(&self) -> f64;
    /// The dense output on the last accepted step.
    fn dense(&self, t: f64) -> [f64; N];
    /// One accepted step, not beyond `t_limit`.
    fn advance<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N];
    /// Accepted and rejected steps.
    fn step_counts(&self) -> (u64, u64);
    /// Evaluations of f and steps so far.
    fn spent(&self) -> Cost;
    /// Makes [`DenseStepper::dense`] available on the last accepted step. Methods
    /// whose continuous extension needs extra evaluations of f
    /// ([`DormandPrince853`]) do them here, once per step, only when asked; for the
    /// others it does nothing. [`drive`] calls it before it locates an event or
    /// hands a step to its observer, [`drive_events`] only on the step that
    /// contains an event.
    fn prepare_dense<F>(&mut self, _f: &mut F) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        Ok(())
    }
}

/// The accessors, the event search on the last step and the [`DenseStepper`]
/// implementation that every one-step method of this module shares, written once:
/// the method provides `core: StepperCore<N>`, `dense_output(&self, t)` and
/// `step(&mut self, f, t_limit)` (and, for a lazily prepared dense output,
/// `prepare_dense_output(&mut self, f)`).
macro_rules! one_step_method {
    ($method:ident $(, prepare = $prepare:ident)?) => {
        impl<const N: usize> $method<N> {
            /// Current time (end of the last accepted step).
            pub fn t(&self) -> f64 {
                self.core.t
            }

            /// Current state.
            pub fn y(&self) -> [f64; N] {
                self.core.y
            }

            /// Start of the last accepted step (equal to the current time right after
            /// a (re)start).
            pub fn previous_t(&self) -> f64 {
                self.core.t_old
            }

            /// Accepted and rejected steps so far.
            pub fn steps(&self) -> (u64, u64) {
                self.core.steps()
            }

            /// Right-hand-side evaluations (`evaluations`, including those of a
            /// Jacobian by differences) and steps, accepted plus rejected
            /// (`iterations`), so far.
            pub fn cost(&self) -> Cost {
                self.core.cost()
            }

            /// Searches the last accepted step for a crossing of the event function
            /// `g` in `direction`, given its values `g_before` at the start and
            /// `g_after` at the end of the step. Returns the crossing located by
            /// Brent's method on the dense output to `time_tolerance` (absolute, in
            /// t), with the evaluations of `g` spent, or `None` when the step has no
            /// such crossing ([`locate_event_in_step`]).
            pub fn locate_event<G>(
                &self,
                mut g: G,
                direction: EventDirection,
                g_before: f64,
                g_after: f64,
                time_tolerance: f64,
            ) -> Result<Option<(EventPoint<N>, Cost)>>
            where
                G: FnMut(f64, &[f64; N]) -> f64,
            {
                locate_event_in_step(self, &mut g, direction, g_before, g_after, time_tolerance)
            }
        }

        impl<const N: usize> DenseStepper<N> for $method<N> {
            fn current(&self) -> (f64, [f64; N]) {
                (self.core.t, self.core.y)
            }
            fn step_start(&self) -> f64 {
                self.core.t_old
            }
            fn dense(&self, t: f64) -> [f64; N] {
                self.dense_output(t)
            }
            fn advance<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
            where
                F: FnMut(f64, &[f64; N]) -> [f64; N],
            {
                self.step(f, t_limit)
            }
            fn step_counts(&self) -> (u64, u64) {
                self.core.steps()
            }
            fn spent(&self) -> Cost {
                self.core.cost()
            }
            $(
            fn prepare_dense<F>(&mut self, f: &mut F) -> Result<()>
            where
                F: FnMut(f64, &[f64; N]) -> [f64; N],
            {
                self.$prepare(f)
            }
            )?
        }
    };
}
pub(crate) use one_step_method;

/// The crossing of `g` in `direction` on the last accepted step of `stepper`,
/// located by Brent's method on the dense output to `time_tolerance` (absolute,
/// in t), with the evaluations of `g` spent; `None` when the step has none.
pub fn locate_event_in_step<S, G, const N: usize>(
    stepper: &S,
    g: &mut G,
    direction: EventDirection,
    g_before: f64,
    g_after: f64,
    time_tolerance: f64,
) -> Result<Option<(EventPoint<N>, Cost)>>
where
    S: DenseStepper<N>,
    G: FnMut(f64, &[f64; N]) -> f64,
{
    if !direction.is_crossing(g_before, g_after) {
        return Ok(None);
    }
    let (b, y_b) = stepper.current();
    let a = stepper.step_start();
    locate_crossing(stepper, g, (a, g_before), (b, g_after, y_b), time_tolerance).map(Some)
}

/// The sign change of `g` between `(a, g_a)` and `(b, g_b)` (state `y_b` at b) inside
/// the last accepted step of `stepper`, by Brent's method on the dense output.
fn locate_crossing<S, G, const N: usize>(
    stepper: &S,
    g: &mut G,
    (a, g_a): (f64, f64),
    (b, g_b, y_b): (f64, f64, [f64; N]),
    time_tolerance: f64,
) -> Result<(EventPoint<N>, Cost)>
where
    S: DenseStepper<N>,
    G: FnMut(f64, &[f64; N]) -> f64,
{
    if g_b == 0.0 {
        return Ok((EventPoint { t: b, y: y_b }, Cost::ZERO));
    }
    let tol = RootTolerance {
        absolute: time_tolerance.max(0.0),
        relative: 4.0 * f64::EPSILON,
        max_iterations: 200,
    };
    let root = brent(
        |s| {
            if s <= a {
                g_a
            } else if s >= b {
                g_b
            } else {
                g(s, &stepper.dense(s))
            }
        },
        a,
        b,
        tol,
    )?;
    let t = root.value;
    Ok((
        EventPoint {
            t,
            y: stepper.dense(t),
        },
        root.cost(),
    ))
}

/// What [`drive`] returns: the solution and what locating the event cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integration<const N: usize> {
    /// Where the integration stopped, the steps taken and the evaluations of f
    /// (`solution.cost`).
    pub solution: OdeSolution<N>,
    /// Evaluations of the event function on the dense output and Brent iterations
    /// spent locating the event ([`Cost::ZERO`] when none was found).
    pub event_cost: Cost,
}

/// The step-and-locate-event loop: advances `stepper` from its current point until
/// the event function `g(t, y)` crosses zero in `direction` (located on the dense
/// output of the step to a few ulps of t), or until `t_end` when it does not.
///
/// After every accepted step, `observer(stepper, stop)` is called with the stepper
/// (its last step, dense output and current state) and the time `stop` where the
/// integration ends within that step: the step's end, or the event time on the step
/// that contains the event. Use it to record a trajectory (sample
/// [`DenseStepper::dense`] on `[step_start, stop]`) or to watch the state at the step
/// ends; pass `&mut |_: &S, _: f64| {}` when nothing is to be observed.
///
/// Every solver of this module ([`solve_until_event`],
/// [`rosenbrock::solve_until_event`]) is this loop, and so is every integration with
/// several event functions ([`drive_events`], which the impact simulator of
/// `tabor-dynamics` runs segment by segment). `g` is evaluated once at the start,
/// once per step end, and on the dense output of the step that contains the
/// crossing.
pub fn drive<S, F, G, O, const N: usize>(
    stepper: &mut S,
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    t_end: f64,
    observer: &mut O,
) -> Result<Integration<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
    O: FnMut(&S, f64),
{
    let run = event_loop(
        stepper,
        f,
        &mut |t: f64, y: &[f64; N]| [g(t, y)],
        [direction],
        t_end,
        true,
        &mut |s: &mut S, f: &mut F, stop: f64| {
            s.prepare_dense(f)?;
            observer(s, stop);
            Ok(())
        },
    )?;
    Ok(Integration {
        solution: run.solution,
        event_cost: run.event_cost,
    })
}

/// What [`drive_events`] returns: the solution, which event stopped it (if any) and
/// what locating it cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventsIntegration<const N: usize> {
    /// Where the integration stopped, the steps taken and the evaluations of f.
    pub solution: OdeSolution<N>,
    /// The index of the event function that crossed first (the lowest index when
    /// several cross at the same time); `None` when `t_end` was reached.
    pub event: Option<usize>,
    /// Evaluations of the event functions on the dense output and Brent iterations
    /// spent locating the event ([`Cost::ZERO`] when none was found).
    pub event_cost: Cost,
}

/// [`drive`] with `M` event functions `g(t, y) = [g_0, …, g_{M−1}]`, each with its
/// direction: stops at the earliest crossing of any of them (each located on the
/// dense output to a few ulps of t; on a tie, the lowest index), or at `t_end`.
/// An event function that is NaN at a step end is an error
/// ([`NumericsError::NonFinite`]).
///
/// `observer(t, y)` sees the end of every accepted step that contains no event
/// (the event point itself is returned); the dense output is prepared only on the
/// step that contains the event ([`DenseStepper::prepare_dense`]), so a method
/// whose dense output costs evaluations ([`DormandPrince853`]) pays for it once.
pub fn drive_events<S, F, G, O, const N: usize, const M: usize>(
    stepper: &mut S,
    f: &mut F,
    g: &mut G,
    directions: [EventDirection; M],
    t_end: f64,
    observer: &mut O,
) -> Result<EventsIntegration<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> [f64; M],
    O: FnMut(f64, &[f64; N]),
{
    event_loop(
        stepper,
        f,
        g,
        directions,
        t_end,
        false,
        &mut |s: &mut S, _: &mut F, _: f64| {
            let (t, y) = s.current();
            observer(t, &y);
            Ok(())
        },
    )
}

/// The one step-and-locate-event loop behind [`drive`] and [`drive_events`]:
/// `after_step(stepper, f, stop)` runs after every accepted step (on the step that
/// contains the event, after the dense output was prepared, with `stop` the event
/// time) when `event_step_too` (for [`drive`]), else on the steps without an
/// event only (for [`drive_events`]).
fn event_loop<S, F, G, A, const N: usize, const M: usize>(
    stepper: &mut S,
    f: &mut F,
    g: &mut G,
    directions: [EventDirection; M],
    t_end: f64,
    event_step_too: bool,
    after_step: &mut A,
) -> Result<EventsIntegration<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> [f64; M],
    A: FnMut(&mut S, &mut F, f64) -> Result<()>,
{
    let (t0, y0) = stepper.current();
    let mut g_prev = finite_events(g(t0, &y0), t0)?;
    while stepper.current().0 < t_end {
        stepper.advance(f, t_end)?;
        let (t, y) = stepper.current();
        let g_new = finite_events(g(t, &y), t)?;
        let crossing = (0..M).any(|i| directions[i].is_crossing(g_prev[i], g_new[i]));
        if !crossing {
            after_step(stepper, f, t)?;
            g_prev = g_new;
            continue;
        }
        stepper.prepare_dense(f)?;
        let (index, point, event_cost) = earliest_crossing(stepper, g, directions, g_prev, g_new)?;
        if event_step_too {
            after_step(stepper, f, point.t)?;
        }
        return Ok(EventsIntegration {
            solution: solution_of(stepper, point.t, point.y, true),
            event: Some(index),
            event_cost,
        });
    }
    let (t, y) = stepper.current();
    Ok(EventsIntegration {
        solution: solution_of(stepper, t, y, false),
        event: None,
        event_cost: Cost::ZERO,
    })
}

/// The earliest crossing on the last step of `stepper`, given that at least one of
/// the event functions crosses between its values `g_prev` at the step's start and
/// `g_new` at its end: each such crossing is located; then every function is also
/// checked at the earliest point found, so that one which crosses and crosses back
/// within the step (no sign change at the ends) is still found when it crossed
/// before that point (a body that passes a branch end and turns back within one
/// step). Returns the index, the point and the evaluations of g spent.
fn earliest_crossing<S, G, const N: usize, const M: usize>(
    stepper: &S,
    g: &mut G,
    directions: [EventDirection; M],
    g_prev: [f64; M],
    g_new: [f64; M],
) -> Result<(usize, EventPoint<N>, Cost)>
where
    S: DenseStepper<N>,
    G: FnMut(f64, &[f64; N]) -> [f64; M],
{
    let a = stepper.step_start();
    let (b, y_b) = stepper.current();
    let mut first: Option<(usize, EventPoint<N>)> = None;
    let mut cost = Cost::ZERO;
    for i in 0..M {
        if directions[i].is_crossing(g_prev[i], g_new[i]) {
            let mut gi = |t: f64, y: &[f64; N]| g(t, y)[i];
            let (point, c) =
                locate_crossing(stepper, &mut gi, (a, g_prev[i]), (b, g_new[i], y_b), 0.0)?;
            cost += c;
            if first.as_ref().is_none_or(|(_, p)| point.t < p.t) {
                first = Some((i, point));
            }
        }
    }
    let Some((mut index, mut point)) = first else {
        return Err(NumericsError::NoConvergence {
            method: "event location: no crossing on a step whose ends show one",
            iterations: 0,
            estimate: b,
            error: 0.0,
        });
    };
    // At most M rounds: each moves the event to an earlier one of another function.
    for _ in 0..M {
        let at_point = g(point.t, &point.y);
        cost += Cost::new(1, 0);
        let earlier =
            (0..M).find(|&i| i != index && directions[i].is_crossing(g_prev[i], at_point[i]));
        let Some(i) = earlier else {
            break;
        };
        let mut gi = |t: f64, y: &[f64; N]| g(t, y)[i];
        let (p, c) = locate_crossing(
            stepper,
            &mut gi,
            (a, g_prev[i]),
            (point.t, at_point[i], point.y),
            0.0,
        )?;
        cost += c;
        if p.t > point.t || (p.t == point.t && i > index) {
            break;
        }
        index = i;
        point = p;
    }
    Ok((index, point, cost))
}

/// The event values at time `t`, or an error naming the first that is NaN.
fn finite_events<const M: usize>(g: [f64; M], t: f64) -> Result<[f64; M]> {
    match g.iter().find(|v| v.is_nan()) {
        Some(&value) => Err(NumericsError::NonFinite { at: t, value }),
        None => Ok(g),
    }
}

fn solution_of<S: DenseStepper<N>, const N: usize>(
    stepper: &S,
    t: f64,
    y: [f64; N],
    event_found: bool,
) -> OdeSolution<N> {
    let (accepted, rejected) = stepper.step_counts();
    OdeSolution {
        t,
        y,
        event_found,
        accepted_steps: accepted,
        rejected_steps: rejected,
        cost: stepper.spent(),
    }
}

/// An event function that never crosses: [`drive`] then integrates to `t_end`.
pub(crate) fn no_event<const N: usize>(_: f64, _: &[f64; N]) -> f64 {
    1.0
}

/// The names a method gives its step failures ([`StepperCore::trial_step`]).
pub(crate) struct FailureNames {
    pub(crate) step_limit: &'static str,
    pub(crate) underflow: &'static str,
}

/// The state every one-step method keeps: the current point, the start and length
/// of the last accepted step, the proposed step size and the counters. The methods
/// add their own controller memory and dense-output coefficients.
#[derive(Clone, Debug)]
pub(crate) struct StepperCore<const N: usize> {
    pub(crate) tol: OdeTolerance,
    /// Current time and state (end of the last accepted step).
    pub(crate) t: f64,
    pub(crate) y: [f64; N],
    /// Start of the last accepted step.
    pub(crate) t_old: f64,
    /// Proposed next step size.
    pub(crate) h: f64,
    /// Length of the last accepted step (0 before the first).
    pub(crate) h_last: f64,
    pub(crate) last_rejected: bool,
    pub(crate) accepted: u64,
    pub(crate) rejected: u64,
    pub(crate) evaluations: u64,
}

impl<const N: usize> StepperCore<N> {
    /// Validates `tol` and starts at `(t0, y0)` (the method then restarts there).
    pub(crate) fn new(tol: OdeTolerance, t0: f64, y0: [f64; N]) -> Result<Self> {
        tol.validate()?;
        Ok(StepperCore {
            tol,
            t: t0,
            y: y0,
            t_old: t0,
            h: 0.0,
            h_last: 0.0,
            last_rejected: false,
            accepted: 0,
            rejected: 0,
            evaluations: 0,
        })
    }

    /// Checks a (re)start at `(t, y)` aiming at `t_hint`, moves there and forgets
    /// the last step; returns the span `t_hint − t`.
    pub(crate) fn restart(&mut self, t: f64, y: [f64; N], t_hint: f64) -> Result<f64> {
        finite("t", t)?;
        for &v in &y {
            finite("y", v)?;
        }
        let span = t_hint - t;
        if !(span.is_finite() && span > 0.0) {
            return Err(NumericsError::InvalidArgument {
                name: "t_hint",
                value: t_hint,
                requirement: "must be finite and later than the current time",
            });
        }
        self.t = t;
        self.t_old = t;
        self.y = y;
        self.h_last = 0.0;
        self.last_rejected = false;
        Ok(span)
    }

    /// `f(t, y)`, counted.
    pub(crate) fn eval<F>(&mut self, f: &mut F, t: f64, y: &[f64; N]) -> [f64; N]
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.evaluations += 1;
        f(t, y)
    }

    /// `f(t, y)` at the current point, counted; an error if it is not finite.
    pub(crate) fn eval_current<F>(&mut self, f: &mut F) -> Result<[f64; N]>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let (t, y) = (self.t, self.y);
        let dy = self.eval(f, t, &y);
        match first_non_finite(&dy) {
            Some(bad) => Err(NumericsError::NonFinite { at: t, value: bad }),
            None => Ok(dy),
        }
    }

    /// The error scale of a component that was `a` before and `b` after a step.
    pub(crate) fn scale(&self, a: f64, b: f64) -> f64 {
        self.tol.error_scale(a, b)
    }

    /// The largest first step after a restart spanning `span`.
    pub(crate) fn first_step_limit(&self, span: f64) -> f64 {
        self.tol.max_step.min(span)
    }

    /// The first guess of Hairer's `HINIT` from the sizes of y and `dy = f(t, y)`:
    /// `0.01 ‖y‖/‖f‖`, or 1e-6 when either is tiny; with `‖f‖²·N` (`dnf`) for the
    /// second stage of `HINIT`.
    pub(crate) fn first_guess(&self, dy: &[f64; N]) -> (f64, f64) {
        let mut dnf = 0.0;
        let mut dny = 0.0;
        for i in 0..N {
            let sk = self.scale(self.y[i], self.y[i]);
            dnf += (dy[i] / sk).powi(2);
            dny += (self.y[i] / sk).powi(2);
        }
        let h = if dnf <= 1e-10 || dny <= 1e-10 {
            1e-6
        } else {
            (dny / dnf).sqrt() * 0.01
        };
        (h, dnf)
    }

    /// The restart every stepper shares: checks and moves to `(t, y)` (forgetting the
    /// last step), evaluates `f(t, y)` (returned) and sets the first step `h`: the
    /// tolerance's `initial_step` if given (at most the span to `t_hint` and
    /// `max_step`), else Hairer's `HINIT` for a method of order `order`, or only its
    /// first guess (`order = None`, for the Rosenbrock methods).
    pub(crate) fn restart_at<F>(
        &mut self,
        f: &mut F,
        t: f64,
        y: [f64; N],
        t_hint: f64,
        order: Option<u32>,
    ) -> Result<[f64; N]>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let span = self.restart(t, y, t_hint)?;
        let dy = self.eval_current(f)?;
        let h_max = self.first_step_limit(span);
        self.h = match (self.tol.initial_step, order) {
            (Some(h), _) => h.min(h_max),
            (None, Some(order)) => self.hinit(f, &dy, h_max, order),
            (None, None) => {
                let (h, _) = self.first_guess(&dy);
                if h.is_finite() && h > 0.0 {
                    h.min(h_max)
                } else {
                    h_max.min(1e-6)
                }
            }
        };
        Ok(dy)
    }

    /// Hairer's `HINIT` for a method of order `order`: a first step from the sizes
    /// of y, `dy = f(t, y)` and an estimate of y'' (one more evaluation), at most
    /// `h_max`; 1e-6 (or `h_max`) when that is not informative.
    fn hinit<F>(&mut self, f: &mut F, dy: &[f64; N], h_max: f64, order: u32) -> f64
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let n = N.max(1) as f64;
        let (h, dnf) = self.first_guess(dy);
        let h = h.min(h_max);
        let (t, y) = (self.t, self.y);
        let mut y1 = y;
        for i in 0..N {
            y1[i] += h * dy[i];
        }
        let f1 = self.eval(f, t + h, &y1);
        let mut der2 = 0.0;
        for i in 0..N {
            let sk = self.scale(y[i], y[i]);
            der2 += ((f1[i] - dy[i]) / sk).powi(2);
        }
        let der2 = (der2 / n).sqrt() / h;
        let der12 = der2.max((dnf / n).sqrt());
        let h1 = if der12 <= 1e-15 || !der12.is_finite() {
            (h * 1e-3).max(1e-6)
        } else {
            (0.01 / der12).powf(1.0 / f64::from(order))
        };
        let h = (100.0 * h).min(h1).min(h_max);
        if h.is_finite() && h > 0.0 {
            h
        } else {
            h_max.min(1e-6)
        }
    }

    /// Checks the target of a step.
    pub(crate) fn check_limit(&self, t_limit: f64) -> Result<()> {
        if t_limit.is_finite() && t_limit > self.t {
            Ok(())
        } else {
            Err(NumericsError::InvalidArgument {
                name: "t_limit",
                value: t_limit,
                requirement: "must be finite and later than the current time",
            })
        }
    }

    /// The size of the next trial step towards `t_limit` and whether it is the last
    /// one (it then reaches `t_limit` exactly). Errors when the step limit is
    /// reached, or when the step underflows (`h` below 16 ε |t`|; then the first
    /// non-finite value met, if any, is reported).
    pub(crate) fn trial_step(
        &self,
        t_limit: f64,
        non_finite: Option<(f64, f64)>,
        names: &FailureNames,
    ) -> Result<(f64, bool)> {
        if self.accepted + self.rejected >= self.tol.max_steps {
            return Err(NumericsError::NoConvergence {
                method: names.step_limit,
                iterations: self.accepted + self.rejected,
                estimate: self.t,
                error: self.h,
            });
        }
        let remaining = t_limit - self.t;
        let mut h = self.h.min(self.tol.max_step);
        let last = h >= remaining * (1.0 - 4.0 * f64::EPSILON);
        if last {
            h = remaining;
        }
        let h_min = 16.0 * f64::EPSILON * self.t.abs().max(f64::MIN_POSITIVE);
        if h <= h_min && !last {
            return Err(match non_finite {
                Some((at, value)) => NumericsError::NonFinite { at, value },
                None => NumericsError::NoConvergence {
                    method: names.underflow,
                    iterations: self.accepted + self.rejected,
                    estimate: self.t,
                    error: h,
                },
            });
        }
        Ok((h, last))
    }

    /// Counts a rejected trial step and proposes `h_next`.
    pub(crate) fn reject(&mut self, h_next: f64) {
        self.rejected += 1;
        self.h = h_next;
        self.last_rejected = true;
    }

    /// Accepts a step of size `h` to `(t_new, y_new)` and proposes `h_proposed` for
    /// the next one (not larger than `h` right after a rejection).
    pub(crate) fn accept(&mut self, h: f64, t_new: f64, y_new: [f64; N], h_proposed: f64) {
        let h_new = if self.last_rejected {
            h_proposed.min(h)
        } else {
            h_proposed
        };
        self.t_old = self.t;
        self.h_last = t_new - self.t;
        self.t = t_new;
        self.y = y_new;
        self.h = h_new.min(self.tol.max_step);
        self.accepted += 1;
        self.last_rejected = false;
    }

    /// The position `θ ∈ [0, 1]` of `t` in the last accepted step, or `None` before
    /// the first step (the dense output is then the current state).
    pub(crate) fn theta(&self, t: f64) -> Option<f64> {
        (self.h_last > 0.0).then(|| (t - self.t_old) / self.h_last)
    }

    pub(crate) fn steps(&self) -> (u64, u64) {
        (self.accepted, self.rejected)
    }

    pub(crate) fn cost(&self) -> Cost {
        Cost::new(self.evaluations, self.accepted + self.rejected)
    }
}

pub(crate) fn first_non_finite<const N: usize>(v: &[f64; N]) -> Option<f64> {
    v.iter().copied().find(|x| !x.is_finite())
}

pub(crate) fn finite(name: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(NumericsError::InvalidArgument {
            name,
            value: v,
            requirement: "must be finite",
        })
    }
}

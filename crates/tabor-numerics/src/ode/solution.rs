//! What a driver returns: [`OdeSolution`], [`Integration`] ([`drive`](super::drive)),
//! [`EventsIntegration`] ([`drive_events`](super::drive_events)).

use super::DenseStepper;
use crate::Cost;

/// The result of a driver ([`solve`](super::solve), [`solve_until_event`](super::solve_until_event), [`drive`](super::drive)).
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

/// What [`drive`](super::drive) returns: the solution and what locating the event cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integration<const N: usize> {
    /// Where the integration stopped, the steps taken and the evaluations of f
    /// (`solution.cost`).
    pub solution: OdeSolution<N>,
    /// Evaluations of the event function on the dense output and Brent iterations
    /// spent locating the event ([`Cost::ZERO`] when none was found).
    pub event_cost: Cost,
}

/// What [`drive_events`](super::drive_events) returns: the solution, which event stopped it (if any) and
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

pub(super) fn solution_of<S: DenseStepper<N>, const N: usize>(
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

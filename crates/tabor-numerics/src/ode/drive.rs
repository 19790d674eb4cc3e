//! [`drive`] and [`drive_events`]: the one step-and-locate-event loop (one event
//! function, or several of which the earliest crossing wins), with an observer
//! called after every accepted step.

use super::events::{earliest_crossing, finite_events};
use super::solution::solution_of;
use super::{DenseStepper, EventDirection, EventsIntegration, Integration, OdeSolution};
use crate::{Cost, Result};

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
/// Every solver of this module ([`solve_until_event`](super::solve_until_event),
/// [`rosenbrock::solve_until_event`](super::rosenbrock::solve_until_event)) is this loop, and so is every integration with
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

/// [`drive`] with nothing observed, to its solution: the body of every
/// `solve_until_event` ([`solve_until_event`](super::solve_until_event),
/// [`rosenbrock::solve_until_event`](super::rosenbrock::solve_until_event)), the
/// stepper started at their initial point.
pub(crate) fn drive_unobserved<S, F, G, const N: usize>(
    stepper: &mut S,
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    t_end: f64,
) -> Result<OdeSolution<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    let run = drive(stepper, f, g, direction, t_end, &mut |_: &S, _: f64| {})?;
    Ok(run.solution)
}

/// [`drive`] with `M` event functions `g(t, y) = [g_0, …, g_{M−1}]`, each with its
/// direction: stops at the earliest crossing of any of them (each located on the
/// dense output to a few ulps of t; on a tie, the lowest index), or at `t_end`.
/// An event function that is NaN at a step end is an error
/// ([`NumericsError::NonFinite`](crate::NumericsError::NonFinite)).
///
/// `observer(t, y)` sees the end of every accepted step that contains no event
/// (the event point itself is returned); the dense output is prepared only on the
/// step that contains the event ([`DenseStepper::prepare_dense`]), so a method
/// whose dense output costs evaluations ([`DormandPrince853`](super::DormandPrince853)) pays for it once.
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

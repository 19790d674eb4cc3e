//! Events: the sign changes of a user function `g(t, y)` ([`EventDirection`],
//! [`EventPoint`]), located on the dense output of the last accepted step with
//! Brent's method ([`locate_event_in_step`]; the earliest of several crossings for
//! [`drive_events`](super::drive_events)), so locating them costs no evaluations of `f`.

#![allow(clippy::needless_range_loop)] // loops over small fixed arrays of event functions

use super::DenseStepper;
use crate::root_finding::{brent, RootTolerance};
use crate::{Cost, NumericsError, Result};

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

/// The earliest crossing on the last step of `stepper`, given that at least one of
/// the event functions crosses between its values `g_prev` at the step's start and
/// `g_new` at its end: each such crossing is located; then every function is also
/// checked at the earliest point found, so that one which crosses and crosses back
/// within the step (no sign change at the ends) is still found when it crossed
/// before that point (a body that passes a branch end and turns back within one
/// step). Returns the index, the point and the evaluations of g spent.
pub(super) fn earliest_crossing<S, G, const N: usize, const M: usize>(
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
pub(super) fn finite_events<const M: usize>(g: [f64; M], t: f64) -> Result<[f64; M]> {
    match g.iter().find(|v| v.is_nan()) {
        Some(&value) => Err(NumericsError::NonFinite { at: t, value }),
        None => Ok(g),
    }
}

/// An event function that never crosses: [`drive`] then integrates to `t_end`.
pub(crate) fn no_event<const N: usize>(_: f64, _: &[f64; N]) -> f64 {
    1.0
}

//! What every scaled (dimensionless) impact solution reports, the input checks of
//! the dimensionless parameters, the event-driven phase integration on top of the
//! driver of `tabor_numerics::ode`, and the two-phase run of the flat-punch models.

use serde::Serialize;
use tabor_numerics::ode::{drive, DenseStepper, DormandPrince, EventDirection, OdeTolerance};
use tabor_numerics::rosenbrock::{Jacobian, Rosenbrock, Scheme};
use tabor_numerics::Cost;
use tabor_restitution::{validate, Error, Result};

/// The outcome of one impact in a model's scaled variables (the model's docs say
/// which length, time and force units it uses).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ScaledImpact {
    /// Coefficient of restitution ε_z = rebound speed / impact speed, in [0, 1].
    pub restitution: f64,
    /// Contact time T_S (scaled), from first contact to vanishing normal force.
    pub contact_time: f64,
    /// Largest indentation (scaled).
    pub max_overlap: f64,
    /// Right-hand-side evaluations and steps of the integration ([`Cost::ZERO`] for
    /// closed forms).
    pub cost: Cost,
}

/// One point of a scaled trajectory.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ScaledPoint {
    /// Time since first contact (scaled).
    pub time: f64,
    /// Indentation d (scaled).
    pub overlap: f64,
    /// Indentation rate ḋ (scaled; 1 at first contact).
    pub overlap_rate: f64,
    /// Normal force (scaled, repulsive > 0).
    pub force: f64,
}

/// A dimensionless parameter that must be finite and lie in (0, upper].
pub(crate) fn positive_up_to(
    parameter: &'static str,
    value: f64,
    upper: f64,
    requirement: &'static str,
) -> Result<f64> {
    if value.is_finite() && value > 0.0 && value <= upper {
        Ok(value)
    } else {
        Err(Error::invalid(parameter, value, requirement))
    }
}

/// The relative tolerance of an integration.
pub(crate) fn ode_tolerance(tolerance: f64, max_step: f64) -> Result<OdeTolerance> {
    let tol = validate::tolerance("tolerance", tolerance)?;
    Ok(OdeTolerance::new(tol, tol)
        .with_max_step(max_step)
        .with_max_steps(4_000_000))
}

/// A restitution value from a rebound speed, forced into [0, 1] (a separation
/// with an inward speed cannot occur; rounding may leave it at −1e-17).
pub(crate) fn restitution_from_rebound(rebound_speed: f64) -> Result<f64> {
    let r = validate::finite("rebound speed", rebound_speed)?;
    Ok(r.clamp(0.0, 1.0))
}

/// Where a phase ended.
pub(crate) struct PhaseEnd<const N: usize> {
    pub t: f64,
    pub y: [f64; N],
    pub cost: Cost,
}

/// Dense-output points per accepted step that [`run_phase`] records, equidistant
/// in the step (the last at its end).
pub(crate) const SAMPLES_PER_STEP: usize = 4;

/// The integrator of a phase.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Method {
    /// Dormand-Prince 5(4) (`tabor_numerics::ode`).
    Explicit,
    /// The L-stable Rosenbrock method Rodas5P (`tabor_numerics::rosenbrock`) with a
    /// Jacobian by differences, for phases whose relaxation rates far exceed the
    /// inverse time scale of the motion (the explicit method is then limited by
    /// stability, not accuracy).
    Stiff(Jacobian),
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` with Dormand-Prince 5(4) until the
/// event function `g` crosses zero in `direction`: [`run_phase_with`] with
/// [`Method::Explicit`].
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_phase<F, G, const N: usize>(
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    t0: f64,
    y0: [f64; N],
    t_max: f64,
    tol: OdeTolerance,
    record: Option<&mut Vec<(f64, [f64; N])>>,
) -> Result<PhaseEnd<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    run_phase_with(
        Method::Explicit,
        f,
        g,
        direction,
        t0,
        y0,
        t_max,
        tol,
        record,
    )
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` with `method` until the event function
/// `g` crosses zero in `direction` (located on the dense output), at the latest at
/// `t_max` (then an error: the phase did not end). With `record`, the start and
/// then, for every accepted step (the last one cut at the event),
/// [`SAMPLES_PER_STEP`] dense-output points.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_phase_with<F, G, const N: usize>(
    method: Method,
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    t0: f64,
    y0: [f64; N],
    t_max: f64,
    tol: OdeTolerance,
    record: Option<&mut Vec<(f64, [f64; N])>>,
) -> Result<PhaseEnd<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    match method {
        Method::Explicit => {
            let mut stepper = DormandPrince::new(f, t0, y0, t_max, tol)?;
            phase(&mut stepper, f, g, direction, t_max, record)
        }
        Method::Stiff(jacobian) => {
            let mut stepper = Rosenbrock::new(f, t0, y0, t_max, tol, jacobian, Scheme::Rodas5P)?;
            phase(&mut stepper, f, g, direction, t_max, record)
        }
    }
}

/// One phase on `stepper`: the driver of `tabor_numerics::ode`, its observer
/// sampling the dense output into `record`.
fn phase<S, F, G, const N: usize>(
    stepper: &mut S,
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    t_max: f64,
    mut record: Option<&mut Vec<(f64, [f64; N])>>,
) -> Result<PhaseEnd<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    if let Some(rec) = record.as_deref_mut() {
        rec.push(stepper.current());
    }
    let mut sample = |s: &S, stop: f64| {
        if let Some(rec) = record.as_deref_mut() {
            let a = s.step_start();
            for i in 1..=SAMPLES_PER_STEP {
                let t = a + (stop - a) * i as f64 / SAMPLES_PER_STEP as f64;
                rec.push((t, s.dense(t)));
            }
        }
    };
    let run = drive(stepper, f, g, direction, t_max, &mut sample)?;
    let end = run.solution;
    if !end.event_found {
        return Err(Error::Model {
            model: "viscoelastic impact",
            message: format!(
                "the contact did not end within the scaled time {t_max:e} (cost {} evaluations)",
                end.cost.evaluations
            ),
        });
    }
    Ok(PhaseEnd {
        t: end.t,
        y: end.y,
        cost: end.cost + run.event_cost,
    })
}

/// The impact of a flat punch in two phases, each ending where a quantity falls
/// through zero: compression from first contact (x = 0, ẋ = 1, internal
/// variables 0 at t = 0) until ẋ = 0, then restitution until the normal force
/// `force(t, y)` vanishes. The state is (x, ẋ, internal variables…); each phase may
/// last `t_max`. Restitution is the rebound speed −ẋ at the end, the largest
/// indentation is x at the turning point.
pub(crate) fn flat_punch_impact<F, P, const N: usize>(
    method: Method,
    f: &mut F,
    force: &mut P,
    t_max: f64,
    tol: OdeTolerance,
) -> Result<ScaledImpact>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    P: FnMut(f64, &[f64; N]) -> f64,
{
    let mut y0 = [0.0; N];
    y0[1] = 1.0;
    let first = run_phase_with(
        method,
        f,
        &mut |_t: f64, y: &[f64; N]| y[1],
        EventDirection::Falling,
        0.0,
        y0,
        t_max,
        tol,
        None,
    )?;
    let second = run_phase_with(
        method,
        f,
        force,
        EventDirection::Falling,
        first.t,
        first.y,
        first.t + t_max,
        tol,
        None,
    )?;
    Ok(ScaledImpact {
        restitution: restitution_from_rebound(-second.y[1])?,
        contact_time: second.t,
        max_overlap: first.y[0],
        cost: first.cost + second.cost,
    })
}

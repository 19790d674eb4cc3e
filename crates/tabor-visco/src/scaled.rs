//! What every scaled (dimensionless) impact solution reports, the input checks of
//! the dimensionless parameters, and the event-driven phase integration on top of
//! `tabor_numerics::ode`.

use serde::Serialize;
use tabor_numerics::ode::{
    locate_event_in_step, DenseStepper, DormandPrince, EventDirection, OdeTolerance,
};
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
            let stepper = DormandPrince::new(f, t0, y0, t_max, tol)?;
            drive(stepper, f, g, direction, (t0, y0), t_max, record)
        }
        Method::Stiff(jacobian) => {
            let stepper = Rosenbrock::new(f, t0, y0, t_max, tol, jacobian, Scheme::Rodas5P)?;
            drive(stepper, f, g, direction, (t0, y0), t_max, record)
        }
    }
}

fn drive<S, F, G, const N: usize>(
    mut stepper: S,
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    (t0, y0): (f64, [f64; N]),
    t_max: f64,
    mut record: Option<&mut Vec<(f64, [f64; N])>>,
) -> Result<PhaseEnd<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    let mut g_prev = g(t0, &y0);
    if let Some(rec) = record.as_deref_mut() {
        rec.push((t0, y0));
    }
    while stepper.current().0 < t_max {
        stepper.advance(f, t_max)?;
        let (t, y) = stepper.current();
        let g_new = g(t, &y);
        let hit = locate_event_in_step(&stepper, &mut *g, direction, g_prev, g_new, 0.0)?;
        let t_end = hit.as_ref().map_or(t, |(p, _)| p.t);
        if let Some(rec) = record.as_deref_mut() {
            let (a, b) = (stepper.step_start(), t_end);
            for i in 1..=SAMPLES_PER_STEP {
                let s = a + (b - a) * i as f64 / SAMPLES_PER_STEP as f64;
                rec.push((s, stepper.dense(s)));
            }
        }
        if let Some((point, cost)) = hit {
            return Ok(PhaseEnd {
                t: point.t,
                y: point.y,
                cost: stepper.spent() + cost,
            });
        }
        g_prev = g_new;
    }
    Err(Error::Model {
        model: "viscoelastic impact",
        message: format!(
            "the contact did not end within the scaled time {t_max:e} (cost {} evaluations)",
            stepper.spent().evaluations
        ),
    })
}

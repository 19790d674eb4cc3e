//! What every scaled (dimensionless) impact solution reports, the input checks of
//! the dimensionless parameters, and the event-driven phase integration on top of
//! `tabor_numerics::ode`.

use serde::Serialize;
use tabor_numerics::ode::{DormandPrince, EventDirection, OdeTolerance};
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

/// Integrates `y' = f(t, y)` from `(t0, y0)` until the event function `g` crosses
/// zero in `direction` (located on the dense output), at the latest at `t_max`
/// (then an error: the phase did not end). With `record`, the start and then, for
/// every accepted step (the last one cut at the event), [`SAMPLES_PER_STEP`]
/// dense-output points.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_phase<F, G, const N: usize>(
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    t0: f64,
    y0: [f64; N],
    t_max: f64,
    tol: OdeTolerance,
    mut record: Option<&mut Vec<(f64, [f64; N])>>,
) -> Result<PhaseEnd<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    let mut stepper = DormandPrince::new(f, t0, y0, t_max, tol)?;
    let mut g_prev = g(t0, &y0);
    if let Some(rec) = record.as_deref_mut() {
        rec.push((t0, y0));
    }
    while stepper.t() < t_max {
        stepper.step(f, t_max)?;
        let g_new = g(stepper.t(), &stepper.y());
        let hit = stepper.locate_event(&mut *g, direction, g_prev, g_new, 0.0)?;
        let t_end = hit.as_ref().map_or(stepper.t(), |(p, _)| p.t);
        if let Some(rec) = record.as_deref_mut() {
            let (a, b) = (stepper.previous_t(), t_end);
            for i in 1..=SAMPLES_PER_STEP {
                let s = a + (b - a) * i as f64 / SAMPLES_PER_STEP as f64;
                rec.push((s, stepper.dense_output(s)));
            }
        }
        if let Some((point, cost)) = hit {
            return Ok(PhaseEnd {
                t: point.t,
                y: point.y,
                cost: stepper.cost() + cost,
            });
        }
        g_prev = g_new;
    }
    Err(Error::Model {
        model: "viscoelastic impact",
        message: format!(
            "the contact did not end within the scaled time {t_max:e} (cost {} evaluations)",
            stepper.cost().evaluations
        ),
    })
}

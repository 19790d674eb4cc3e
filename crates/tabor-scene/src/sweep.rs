//! Sweeps: the outcome of a scene over many values of one parameter, in parallel.

use crate::error::SceneError;
use crate::outcome::Outcome;
use crate::parameter::SweepParameter;
use crate::scene::Scene;
use rayon::prelude::*;

/// The outcome of `scene` for each value of `parameter`, computed in parallel on
/// rayon's pool (deterministic: each point is independent of the others and of the
/// number of threads). `on_point` is called once per finished point (for progress).
pub fn sweep<F>(
    scene: &Scene,
    parameter: SweepParameter,
    values: &[f64],
    on_point: F,
) -> Vec<Result<Outcome, SceneError>>
where
    F: Fn() + Sync,
{
    if parameter == SweepParameter::Speed {
        // one scene: its models and its sticking velocity are built once
        // a long sweep of a coupled viscous-adhesive scene answers from a
        // certified speed table (tabor_viscoadhesive::table)
        let batch = match scene.speed_batch(values) {
            Ok(b) => b,
            Err(e) => return values.iter().map(|_| Err(e.clone())).collect(),
        };
        return values
            .par_iter()
            .map(|&v| {
                let result = batch.outcome_at(v);
                on_point();
                result
            })
            .collect();
    }
    values
        .par_iter()
        .map(|&value| {
            let result = scene
                .with_parameter(parameter, value)
                .and_then(|s| s.outcome());
            on_point();
            result
        })
        .collect()
}

/// `points` values from `from` to `to`, evenly or logarithmically spaced.
pub fn spaced(from: f64, to: f64, points: usize, log: bool) -> Result<Vec<f64>, SceneError> {
    if points < 2 || !from.is_finite() || !to.is_finite() || (log && !(from > 0.0 && to > 0.0)) {
        return Err(SceneError::field(
            "sweep",
            format!("invalid range {from}:{to}:{points} (need finite ends, >= 2 points, positive ends with --log)"),
        ));
    }
    let (lo, hi) = (from.min(to), from.max(to));
    Ok((0..points)
        .map(|i| {
            if i == 0 {
                return from;
            }
            if i == points - 1 {
                return to;
            }
            let f = i as f64 / (points - 1) as f64;
            // fallbacks for ends so far apart that to/from or to − from overflows
            let x = if log {
                let ratio = to / from;
                if ratio.is_finite() && ratio > 0.0 {
                    from * ratio.powf(f)
                } else {
                    (from.ln() + (to.ln() - from.ln()) * f).exp()
                }
            } else {
                let span = to - from;
                if span.is_finite() {
                    from + span * f
                } else {
                    from * (1.0 - f) + to * f
                }
            };
            // rounding must not step outside the range (to near f64::MAX gave inf)
            x.clamp(lo, hi)
        })
        .collect())
}

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
    // one scene: its models and its sticking velocity are built once; a long
    // sweep of a coupled viscous-adhesive scene answers from a certified speed
    // table (tabor_viscoadhesive::table)
    let batch = (parameter == SweepParameter::Speed).then(|| scene.speed_batch(values));
    outcomes(scene, parameter, batch.as_ref(), values, &on_point)
}

/// The outcomes at `values` in parallel: from the speed `batch` for a speed sweep,
/// else from the scene with each value of `parameter` (the one evaluation of
/// [`sweep`] and [`sweep_streamed`]).
fn outcomes<F>(
    scene: &Scene,
    parameter: SweepParameter,
    batch: Option<&Result<crate::scene::SpeedBatch<'_>, SceneError>>,
    values: &[f64],
    on_point: &F,
) -> Vec<Result<Outcome, SceneError>>
where
    F: Fn() + Sync,
{
    let point = |result| {
        on_point();
        result
    };
    match batch {
        Some(Ok(b)) => values.par_iter().map(|&v| point(b.outcome_at(v))).collect(),
        Some(Err(e)) => values.iter().map(|_| Err(e.clone())).collect(),
        None => values
            .par_iter()
            .map(|&value| {
                point(
                    scene
                        .with_parameter(parameter, value)
                        .and_then(|s| s.outcome()),
                )
            })
            .collect(),
    }
}

/// [`sweep`] over the values of a [`Spacing`], in chunks of `chunk` points: each
/// chunk's values and outcomes are handed to `sink` in order, so memory does not
/// grow with the number of points (a speed sweep prepares the scene once for the
/// whole range, as [`sweep`] does). The first error of `sink` ends the sweep.
pub fn sweep_streamed<F, S, E>(
    scene: &Scene,
    parameter: SweepParameter,
    spacing: &Spacing,
    chunk: usize,
    on_point: F,
    mut sink: S,
) -> Result<(), E>
where
    F: Fn() + Sync,
    S: FnMut(&[f64], Vec<Result<Outcome, SceneError>>) -> Result<(), E>,
{
    let n = spacing.len();
    let chunk = chunk.max(1);
    let batch = (parameter == SweepParameter::Speed).then(|| {
        // the range of the valid (finite, positive) speeds, as Scene::speed_batch
        let (lo, hi) = spacing.bounds();
        let lower = if lo > 0.0 {
            lo
        } else {
            (0..n)
                .map(|i| spacing.value(i))
                .filter(|v| *v > 0.0)
                .fold(f64::INFINITY, f64::min)
        };
        scene.speed_batch_over(lower, hi.max(0.0), n)
    });
    for start in (0..n).step_by(chunk) {
        let values = spacing.values(start..(start + chunk).min(n));
        let results = outcomes(scene, parameter, batch.as_ref(), &values, &on_point);
        sink(&values, results)?;
    }
    Ok(())
}

/// The largest number of points of a sweep (10⁷): a range asking for more is
/// refused before anything is allocated.
pub const MAX_SWEEP_POINTS: usize = 10_000_000;

/// `points` values from `from` to `to`, evenly or logarithmically spaced, computed
/// one by one ([`Spacing::value`]): a sweep of any length needs no array of them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spacing {
    from: f64,
    to: f64,
    points: usize,
    log: bool,
}

impl Spacing {
    /// A validated spacing: finite ends, 2 to [`MAX_SWEEP_POINTS`] points, positive
    /// ends when `log`.
    pub fn new(from: f64, to: f64, points: usize, log: bool) -> Result<Self, SceneError> {
        if points < 2 || !from.is_finite() || !to.is_finite() || (log && !(from > 0.0 && to > 0.0))
        {
            return Err(SceneError::field(
                "sweep",
                format!("invalid range {from}:{to}:{points} (need finite ends, >= 2 points, positive ends with --log)"),
            ));
        }
        if points > MAX_SWEEP_POINTS {
            return Err(SceneError::field(
                "sweep",
                format!("invalid range {from}:{to}:{points}: at most {MAX_SWEEP_POINTS} points"),
            ));
        }
        Ok(Spacing {
            from,
            to,
            points,
            log,
        })
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.points
    }

    /// Never true (a spacing has at least 2 points).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The smallest and largest value.
    pub fn bounds(&self) -> (f64, f64) {
        (self.from.min(self.to), self.from.max(self.to))
    }

    /// The `i`-th value (`i < len()`): the ends exactly, between them the even or
    /// logarithmic interpolation, never outside the range.
    pub fn value(&self, i: usize) -> f64 {
        let (from, to, points) = (self.from, self.to, self.points);
        if i == 0 {
            return from;
        }
        if i >= points - 1 {
            return to;
        }
        let (lo, hi) = self.bounds();
        let f = i as f64 / (points - 1) as f64;
        // fallbacks for ends so far apart that to/from or to − from overflows
        let x = if self.log {
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
    }

    /// The values `range` (indices), as a vector.
    pub fn values(&self, range: std::ops::Range<usize>) -> Vec<f64> {
        range.map(|i| self.value(i)).collect()
    }
}

/// `points` values from `from` to `to`, evenly or logarithmically spaced (at most
/// [`MAX_SWEEP_POINTS`]; [`Spacing`] computes them one by one).
pub fn spaced(from: f64, to: f64, points: usize, log: bool) -> Result<Vec<f64>, SceneError> {
    let s = Spacing::new(from, to, points, log)?;
    Ok(s.values(0..points))
}

//! Sweeps: the outcome of a scene over many values of one parameter, in parallel.

use crate::file::AdhesionFile;
use crate::outcome::Outcome;
use crate::scene::{Scene, SceneError};
use crate::select::Prepared;
use rayon::prelude::*;
use serde::Serialize;

/// A scene parameter that a sweep varies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SweepParameter {
    /// The impact speed (m/s).
    Speed,
    /// The sphere's radius (m).
    SphereRadius,
    /// The work of adhesion (J/m²).
    WorkOfAdhesion,
    /// The Tabor parameter Λ (replaces any range given).
    TaborParameter,
    /// The target's yield stress (Pa).
    YieldStress,
}

impl SweepParameter {
    /// The parameter named as on the command line (`speed`, `sphere-radius`,
    /// `work-of-adhesion`, `tabor-parameter`, `yield-stress`).
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "speed" => SweepParameter::Speed,
            "sphere-radius" => SweepParameter::SphereRadius,
            "work-of-adhesion" => SweepParameter::WorkOfAdhesion,
            "tabor-parameter" => SweepParameter::TaborParameter,
            "yield-stress" => SweepParameter::YieldStress,
            _ => return None,
        })
    }

    /// The name as on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            SweepParameter::Speed => "speed",
            SweepParameter::SphereRadius => "sphere-radius",
            SweepParameter::WorkOfAdhesion => "work-of-adhesion",
            SweepParameter::TaborParameter => "tabor-parameter",
            SweepParameter::YieldStress => "yield-stress",
        }
    }
}

impl Scene {
    /// The same scene with `parameter` set to `value`, validated again.
    pub fn with_parameter(
        &self,
        parameter: SweepParameter,
        value: f64,
    ) -> Result<Scene, SceneError> {
        let mut data = self.data.clone();
        match parameter {
            SweepParameter::Speed => return self.with_speed(value),
            SweepParameter::SphereRadius => data.sphere.radius = Some(value),
            SweepParameter::WorkOfAdhesion => {
                data.adhesion
                    .get_or_insert_with(AdhesionFile::default)
                    .work_of_adhesion = value
            }
            SweepParameter::TaborParameter => {
                let a = data.adhesion.get_or_insert_with(AdhesionFile::default);
                a.range = None;
                a.cohesive_stress = None;
                a.maugis_parameter = None;
                a.tabor_mu = None;
                a.tabor_parameter = Some(value);
            }
            SweepParameter::YieldStress => data.target.yield_stress = Some(value),
        }
        let mut s = Scene::from_data(data).map_err(|e| self.locate(e))?;
        s.name = self.name.clone();
        Ok(s)
    }
}

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
        let prepared = match Prepared::new(scene) {
            Ok(p) => p,
            Err(e) => return values.iter().map(|_| Err(e.clone())).collect(),
        };
        return values
            .par_iter()
            .map(|&v| {
                let result = prepared.outcome_at(v);
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

impl Scene {
    /// The coefficient of restitution (5.37) at each of `speeds` (m/s), computed in
    /// parallel on rayon's pool, by the same model and combination rule as
    /// [`Scene::outcome_at`] at that speed (the models are built once). The first
    /// invalid speed or failing point is returned with its index.
    ///
    /// When the scene's loss does not depend on the speed (elastic adhesion alone),
    /// the loss is computed once and each point is the closed form (5.37) with the
    /// same negligible-effect rule as the outcome (bit-identical to it).
    pub fn restitutions(&self, speeds: &[f64]) -> Result<Vec<f64>, (usize, SceneError)> {
        let prepared = Prepared::new(self).map_err(|e| (0, e))?;
        match prepared.constant_loss().map_err(|e| (0, e))? {
            Some(loss) => speeds
                .par_iter()
                .enumerate()
                .map(|(i, &v)| {
                    prepared
                        .restitution_with_constant_loss(loss, v)
                        .map_err(|e| (i, e))
                })
                .collect(),
            None => speeds
                .par_iter()
                .enumerate()
                .map(|(i, &v)| prepared.restitution(v).map_err(|e| (i, e)))
                .collect(),
        }
    }
}

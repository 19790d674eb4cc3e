//! `tabor._tabor.Scene`: a scene file bound through the public scene API. A single
//! outcome keeps the shape of `tabor impact --json` (through serde, so new
//! `Outcome` fields reach Python without a change here); batches (`restitution`,
//! `sweep`) run on the batch engine in chunks, each chunk preparing the scene's
//! models once. New methods follow the same pattern: compute detached, map errors
//! with [`Failure::scene`], emit the outcome's warnings.

use crate::batch::{guarded, Options};
use crate::columns::Warnings;
use crate::convert::json_to_py;
use crate::failure::Failure;
use crate::output::{push, Call};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::path::PathBuf;
use tabor::dynamics::{BranchChange, ForceLaw, SimulationSettings};
use tabor::scene::{Format, Outcome, SceneError, SweepParameter};

/// The force of `law` (begun for an impact of mass `mass` at `speed`) at overlap
/// `d` and rate `rate` on the loading path: the branch the overlap reaches from
/// the start (a branch that ends before `d`, such as Maugis-Dugdale's approach at
/// its jump into contact, hands over to the next); the law is begun again after a
/// change of branch. An overlap the loading path does not reach (before first
/// touch, say) is a validity error.
fn loading_force(
    law: &mut dyn ForceLaw,
    mass: f64,
    speed: f64,
    d: f64,
    rate: f64,
) -> Result<f64, Failure> {
    let library = |e: tabor::restitution::Error| {
        let m = e.to_string();
        Failure::library(&e, m)
    };
    let mut switched = false;
    let mut result = Err(Failure {
        kind: crate::failure::Kind::Validity,
        message: format!("overlap = {d:e} m: beyond the branches of the loading path"),
    });
    for _ in 0..MAX_BRANCHES {
        match law.branch_end(d, rate).map_err(library) {
            Ok(end) if end >= 0.0 => {
                result = law.force(d, rate).map_err(library);
                break;
            }
            Ok(_) => {}
            Err(f) => {
                result = Err(f);
                break;
            }
        }
        switched = true;
        match law.on_branch_end(d, rate) {
            Ok(BranchChange::Continue) => {}
            Ok(_) => {
                result = Err(Failure {
                    kind: crate::failure::Kind::Validity,
                    message: format!(
                        "overlap = {d:e} m: not on the loading path of {} (the bodies are not in contact there)",
                        law.name()
                    ),
                });
                break;
            }
            Err(e) => {
                result = Err(library(e));
                break;
            }
        }
    }
    if switched {
        law.begin_impact(mass, speed).map_err(library)?;
    }
    result
}

/// Branches a loading path passes at most (approach, contact, ...).
const MAX_BRANCHES: usize = 8;

/// A collision described once (the native half of `tabor.Scene`).
#[pyclass(module = "tabor._tabor", frozen)]
pub struct Scene {
    inner: tabor::scene::Scene,
}

fn scene_error(e: SceneError) -> PyErr {
    Failure::scene(&e).into_pyerr_static()
}

/// Runs `f` with the GIL released and a panic turned into an exception.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, Failure> + Send) -> PyResult<T> {
    py.detach(|| guarded(f)).map_err(|e| e.into_pyerr(py, None))
}

/// `scene` prepared for the `count` impact speeds `speeds` (m/s) without the GIL
/// (`tabor::scene::Scene::speed_batch_over`: the range of the finite, positive
/// ones), or `None` when it cannot be (the chunks then meet the scene's error
/// themselves).
fn speed_batch<'s>(
    py: Python<'_>,
    scene: &'s tabor::scene::Scene,
    speeds: impl Iterator<Item = f64>,
    count: usize,
) -> Option<tabor::scene::SpeedBatch<'s>> {
    let (lower, upper) = speeds
        .filter(|x| x.is_finite() && *x > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
    py.detach(|| scene.speed_batch_over(lower, upper, count).ok())
}

/// Emits the warnings of `outcomes` (code, message) through Python's `warnings`.
fn warn(
    py: Python<'_>,
    outcomes: &[&Outcome],
    total: usize,
    index: impl Fn(usize) -> String,
) -> PyResult<()> {
    let mut w = Warnings::default();
    for (i, o) in outcomes.iter().enumerate() {
        for x in &o.warnings {
            w.add(x.code, &x.message, i);
        }
    }
    w.emit(py, total, index)
}

#[pymethods]
impl Scene {
    /// A scene from TOML text.
    #[staticmethod]
    fn from_toml(text: &str) -> PyResult<Scene> {
        tabor::scene::Scene::from_str(text, Format::Toml)
            .map(|inner| Scene { inner })
            .map_err(scene_error)
    }

    /// A scene from JSON text.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Scene> {
        tabor::scene::Scene::from_str(text, Format::Json)
            .map(|inner| Scene { inner })
            .map_err(scene_error)
    }

    /// A scene from a .toml or .json file.
    #[staticmethod]
    fn from_path(path: PathBuf) -> PyResult<Scene> {
        tabor::scene::Scene::from_path(&path)
            .map(|inner| Scene { inner })
            .map_err(|e| {
                let mut f = Failure::scene(&e);
                f.message = format!("{}: {}", path.display(), f.message);
                f.into_pyerr_static()
            })
    }

    /// The scene's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name.clone()
    }

    /// The scene's impact speed (m/s), or None.
    #[getter]
    fn speed(&self) -> Option<f64> {
        self.inner.speed
    }

    /// The Tabor parameter Λ when the interface has a range, else None.
    #[getter]
    fn tabor_parameter(&self) -> Option<f64> {
        self.inner.tabor_parameter()
    }

    /// The outcome as a dict (keys of `tabor impact --json`); warnings emitted.
    /// With an angle (or a scene with `[friction]`, an angle or a spin) the
    /// oblique report of `tabor impact --angle --json` (`Scene::oblique_report`).
    #[pyo3(signature = (speed=None, angle=None))]
    fn outcome<'py>(
        &self,
        py: Python<'py>,
        speed: Option<f64>,
        angle: Option<f64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let angle = angle.or(self.inner.angle()).unwrap_or(0.0);
        if angle != 0.0 || self.inner.is_oblique() {
            let report = detached(py, || {
                let v = speed.or(self.inner.speed).ok_or_else(|| {
                    Failure::scene(&SceneError::field(
                        "impact.speed",
                        "is required for an impact (m/s)",
                    ))
                })?;
                self.inner
                    .oblique_report(v, angle)
                    .map_err(|e| Failure::scene(&e))
            })?;
            if let Some((value, central)) = report {
                warn(py, &[&central], 1, |_| String::new())?;
                return json_to_py(py, &value);
            }
        }
        let o = detached(py, || {
            match speed {
                Some(v) => self.inner.outcome_at(v),
                None => self.inner.outcome(),
            }
            .map_err(|e| Failure::scene(&e))
        })?;
        warn(py, &[&o], 1, |_| String::new())?;
        let value = serde_json::to_value(&o)
            .map_err(|e| Failure::input(e.to_string()).into_pyerr(py, None))?;
        json_to_py(py, &value)
    }

    /// Restitution at each speed, flat in and out; the warnings of the slowest and
    /// the fastest point are emitted.
    #[pyo3(signature = (speeds, n, shape, errors, threads))]
    fn restitution<'py>(
        &self,
        py: Python<'py>,
        speeds: PyReadonlyArray1<'py, f64>,
        n: usize,
        shape: Vec<usize>,
        errors: &str,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let call = Call {
            n,
            shape: &shape,
            options: Options::new(errors, threads)?,
        };
        let cols = call.columns(&[("speed", &speeds)])?;
        let v = cols[0];
        let scene = &self.inner;
        // the whole array prepared once: the models, and for a long array of a
        // coupled viscous-adhesive scene its certified speed table
        let batch = speed_batch(py, scene, (0..n).map(|i| v.at(i)), n);
        let restitutions = |speeds: &[f64]| match &batch {
            Some(b) => b.restitutions(speeds),
            None => scene.restitutions(speeds),
        };
        let result = call.chunked_floats(
            py,
            |range| {
                let speeds: Vec<f64> = range.clone().map(|i| v.at(i)).collect();
                restitutions(&speeds).map_err(|(j, e)| (range.start + j, Failure::scene(&e)))
            },
            |i| {
                restitutions(&[v.at(i)])
                    .map(|r| r[0])
                    .map_err(|(_, e)| Failure::scene(&e))
            },
        )?;
        // the warnings of the extreme speeds (the validity checks grow with speed)
        let finite: Vec<f64> = (0..n)
            .map(|i| v.at(i))
            .filter(|x| x.is_finite() && *x > 0.0)
            .collect();
        if let (Some(lo), Some(hi)) = (
            finite.iter().copied().reduce(f64::min),
            finite.iter().copied().reduce(f64::max),
        ) {
            let outs: Vec<Outcome> = py.detach(|| {
                [hi, lo]
                    .iter()
                    .filter_map(|&s| scene.outcome_at(s).ok())
                    .collect()
            });
            let refs: Vec<&Outcome> = outs.iter().collect();
            warn(py, &refs, 1, |k| {
                if k == 0 {
                    format!("the fastest speed {hi:e} m/s")
                } else {
                    format!("the slowest speed {lo:e} m/s")
                }
            })?;
        }
        Ok(result)
    }

    /// The force F(d) (N) of the scene's force law at each overlap d (m) and
    /// overlap rate (m/s), flat in and out: the law of the rule that answers at
    /// `speed` (default the scene's), on the branch the impact starts on
    /// (`tabor::scene::Scene::force_law`).
    #[pyo3(signature = (overlaps, rates, speed, n, shape, errors, threads))]
    #[allow(clippy::too_many_arguments)]
    fn force<'py>(
        &self,
        py: Python<'py>,
        overlaps: PyReadonlyArray1<'py, f64>,
        rates: PyReadonlyArray1<'py, f64>,
        speed: Option<f64>,
        n: usize,
        shape: Vec<usize>,
        errors: &str,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let speed = speed.or(self.inner.speed).ok_or_else(|| {
            Failure::input("give speed, or [impact] speed in the scene (m/s)").into_pyerr(py, None)
        })?;
        let scene = &self.inner;
        // a rule without a force law of its own fails once, before the batch
        detached(py, || {
            scene
                .force_law(speed)
                .map(drop)
                .map_err(|e| Failure::scene(&e))
        })?;
        let call = Call {
            n,
            shape: &shape,
            options: Options::new(errors, threads)?,
        };
        let cols = call.columns(&[("overlap", &overlaps), ("overlap_rate", &rates)])?;
        let (d, rate) = (cols[0], cols[1]);
        let mass = scene.effective_mass;
        let force =
            |law: &mut dyn ForceLaw, i: usize| loading_force(law, mass, speed, d.at(i), rate.at(i));
        // one law per chunk (a law keeps its branch: it is not shared)
        call.chunked_floats(
            py,
            |range| {
                let mut law = scene
                    .force_law(speed)
                    .map_err(|e| (range.start, Failure::scene(&e)))?;
                range
                    .map(|i| force(law.as_mut(), i).map_err(|f| (i, f)))
                    .collect()
            },
            |i| {
                let mut law = scene.force_law(speed).map_err(|e| Failure::scene(&e))?;
                force(law.as_mut(), i)
            },
        )
    }

    /// The sticking velocity (m/s) or None.
    fn sticking_velocity(&self, py: Python<'_>) -> PyResult<Option<f64>> {
        detached(py, || {
            self.inner
                .sticking_velocity()
                .map_err(|e| Failure::scene(&e))
        })
    }

    /// Outcomes over values of one parameter, as columns.
    #[pyo3(signature = (parameter, values, n, shape, errors, threads))]
    #[allow(clippy::too_many_arguments)]
    fn sweep<'py>(
        &self,
        py: Python<'py>,
        parameter: &str,
        values: PyReadonlyArray1<'py, f64>,
        n: usize,
        shape: Vec<usize>,
        errors: &str,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let which = SweepParameter::from_name(&parameter.replace('_', "-")).ok_or_else(|| {
            let names: Vec<String> = sweep_parameters()
                .iter()
                .map(|n| format!("\"{n}\""))
                .collect();
            Failure::input(format!(
                "invalid parameter = \"{parameter}\": expected one of {}",
                names.join(", ")
            ))
            .into_pyerr_static()
        })?;
        // the scene's own check: a sweep never adds an effect the scene lacks
        self.inner.check_parameter(which).map_err(|e| {
            let mut f = Failure::scene(&e);
            f.message = format!("invalid parameter = \"{parameter}\": {}", f.message);
            f.into_pyerr_static()
        })?;
        let call = Call {
            n,
            shape: &shape,
            options: Options::new(errors, threads)?,
        };
        let cols = call.columns(&[("values", &values)])?;
        let v = cols[0];
        let scene = &self.inner;
        // a sweep over speeds prepares the whole array once (as `tabor::scene::sweep`
        // does): the models, and for a long sweep of a coupled viscous-adhesive
        // scene its certified speed table
        let batch = (which == SweepParameter::Speed)
            .then(|| speed_batch(py, scene, (0..n).map(|i| v.at(i)), n))
            .flatten();
        call.chunked_records(
            py,
            |range| match &batch {
                Some(b) => range
                    .map(|i| b.outcome_at(v.at(i)).map_err(|e| Failure::scene(&e)))
                    .collect(),
                None => {
                    let values: Vec<f64> = range.map(|i| v.at(i)).collect();
                    tabor::scene::sweep(scene, which, &values, || {})
                        .into_iter()
                        .map(|r| r.map_err(|e| Failure::scene(&e)))
                        .collect()
                }
            },
            |out, o: Outcome| push(out, &o),
        )
    }

    /// The impact simulated in the time domain: the trajectory and its summary.
    /// `tolerance` defaults to `tabor_numerics::tolerance::COSTLY_TOLERANCE`.
    #[pyo3(signature = (speed=None, tolerance=None))]
    fn trajectory<'py>(
        &self,
        py: Python<'py>,
        speed: Option<f64>,
        tolerance: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let tolerance = tolerance.unwrap_or(tabor::numerics::tolerance::COSTLY_TOLERANCE);
        let speed = speed.or(self.inner.speed).ok_or_else(|| {
            Failure::input("give speed, or [impact] speed in the scene (m/s)").into_pyerr(py, None)
        })?;
        let (sim, outcome) = detached(py, || {
            let settings = SimulationSettings::with_tolerance(tolerance).map_err(|e| {
                let m = e.to_string();
                Failure::library(&e, m)
            })?;
            self.inner
                .simulate(speed, &settings)
                .map_err(|e| Failure::scene(&e))
        })?;
        warn(py, &[&outcome], 1, |_| String::new())?;
        let d = PyDict::new(py);
        let col = |f: fn(&tabor::dynamics::TrajectoryPoint) -> f64| {
            PyArray1::from_vec(py, sim.trajectory.iter().map(f).collect())
        };
        d.set_item("t", col(|p| p.time))?;
        d.set_item("d", col(|p| p.overlap))?;
        d.set_item("d_dot", col(|p| p.overlap_rate))?;
        d.set_item("F", col(|p| p.force))?;
        d.set_item("a", col(|p| p.contact_radius))?;
        d.set_item("contact_work", col(|p| p.contact_work))?;
        d.set_item("scene", &self.inner.name)?;
        d.set_item("law", &sim.law)?;
        d.set_item("impact_speed", speed)?;
        d.set_item("restitution", sim.restitution)?;
        d.set_item("restitution_analytic", outcome.restitution)?;
        d.set_item("contact_time", sim.contact_time)?;
        d.set_item("sticks", sim.sticks)?;
        d.set_item("max_overlap", sim.max_overlap)?;
        d.set_item("max_force", sim.max_force)?;
        d.set_item("energy_loss", sim.energy_loss)?;
        d.set_item("energy_error", sim.energy_error)?;
        d.set_item("points", sim.trajectory.len())?;
        Ok(d)
    }

    fn __repr__(&self) -> String {
        format!("Scene(name={:?})", self.inner.name)
    }
}

/// The parameters `Scene.sweep` takes, as Python spells them (snake_case of
/// `SweepParameter::ALL`'s names).
pub fn sweep_parameters() -> Vec<String> {
    SweepParameter::ALL
        .iter()
        .map(|p| p.name().replace('-', "_"))
        .collect()
}

//! `tabor._tabor.Scene`: a scene file bound through the public scene API and serde
//! (so that new `Outcome` fields reach Python without a change here).

use crate::convert::{columns, exception, guarded, json_to_py, records_to_columns, Failure};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use tabor::dynamics::SimulationSettings;
use tabor::scene::{Format, SweepParameter};

/// A collision described once (the native half of `tabor.Scene`).
#[pyclass(module = "tabor._tabor", frozen)]
pub struct Scene {
    inner: tabor::scene::Scene,
}

fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Runs `f` with the GIL released and a panic turned into an exception.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, String> + Send) -> PyResult<T> {
    py.detach(|| guarded(f)).map_err(|e| exception(0, &[], e))
}

fn to_json<T: serde::Serialize>(v: &T) -> Result<serde_json::Value, String> {
    let mut value = serde_json::to_value(v).map_err(|e| e.to_string())?;
    // every output carries the tabor version, as the CLI's JSON does
    if let serde_json::Value::Object(o) = &mut value {
        o.insert("tabor_version".into(), tabor::VERSION.into());
    }
    Ok(value)
}

#[pymethods]
impl Scene {
    /// A scene from TOML text.
    #[staticmethod]
    fn from_toml(text: &str) -> PyResult<Scene> {
        tabor::scene::Scene::from_str(text, Format::Toml)
            .map(|inner| Scene { inner })
            .map_err(value_error)
    }

    /// A scene from JSON text.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Scene> {
        tabor::scene::Scene::from_str(text, Format::Json)
            .map(|inner| Scene { inner })
            .map_err(value_error)
    }

    /// A scene from a .toml or .json file.
    #[staticmethod]
    fn from_path(path: PathBuf) -> PyResult<Scene> {
        tabor::scene::Scene::from_path(&path)
            .map(|inner| Scene { inner })
            .map_err(|e| PyValueError::new_err(format!("{}: {e}", path.display())))
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

    /// The outcome as a dict (keys of `tabor impact --json`).
    #[pyo3(signature = (speed=None))]
    fn outcome<'py>(&self, py: Python<'py>, speed: Option<f64>) -> PyResult<Bound<'py, PyAny>> {
        let value = detached(py, || {
            let o = match speed {
                Some(v) => self.inner.outcome_at(v),
                None => self.inner.outcome(),
            }
            .map_err(|e| e.to_string())?;
            to_json(&o)
        })?;
        json_to_py(py, &value)
    }

    /// Restitution at each speed, flat in and out.
    fn restitution<'py>(
        &self,
        py: Python<'py>,
        speeds: PyReadonlyArray1<'py, f64>,
        shape: Vec<usize>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let args = [("speed", &speeds)];
        let (c, _) = columns(&args)?;
        let speeds = c[0].0;
        let result = py.detach(|| {
            guarded(|| Ok(self.inner.restitutions(speeds)))
                .map_err(|e| (0, e))
                .and_then(|r| r.map_err(|(i, e)| (i, Failure::Value(e.to_string()))))
        });
        match result {
            Ok(v) => Ok(PyArray1::from_vec(py, v)),
            Err((i, e)) => Err(exception(i, &shape, e)),
        }
    }

    /// The sticking velocity (m/s) or None.
    fn sticking_velocity(&self, py: Python<'_>) -> PyResult<Option<f64>> {
        detached(py, || {
            self.inner.sticking_velocity().map_err(|e| e.to_string())
        })
    }

    /// Outcomes over values of one parameter, as a dict of flat columns.
    fn sweep<'py>(
        &self,
        py: Python<'py>,
        parameter: &str,
        values: PyReadonlyArray1<'py, f64>,
        shape: Vec<usize>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let which = SweepParameter::from_name(&parameter.replace('_', "-")).ok_or_else(|| {
            PyValueError::new_err(format!(
                "invalid parameter = \"{parameter}\": expected speed, sphere_radius, \
                 work_of_adhesion, tabor_parameter or yield_stress"
            ))
        })?;
        let args = [("values", &values)];
        let (c, _) = columns(&args)?;
        let values = c[0].0;
        let records = py.detach(|| {
            let results = guarded(|| Ok(tabor::scene::sweep(&self.inner, which, values, || {})))
                .map_err(|e| (0, e))?;
            let mut records = Vec::with_capacity(results.len());
            for (i, r) in results.into_iter().enumerate() {
                let o = r.map_err(|e| (i, Failure::Value(e.to_string())))?;
                // the version is added once to the whole result (tabor/__init__.py)
                records.push(
                    serde_json::to_value(&o).map_err(|e| (i, Failure::Value(e.to_string())))?,
                );
            }
            Ok(records)
        });
        let records = records.map_err(|(i, e)| exception(i, &shape, e))?;
        records_to_columns(py, &records)
    }

    /// The impact simulated in the time domain: the trajectory and its summary.
    #[pyo3(signature = (speed=None, tolerance=1e-9))]
    fn trajectory<'py>(
        &self,
        py: Python<'py>,
        speed: Option<f64>,
        tolerance: f64,
    ) -> PyResult<Bound<'py, PyDict>> {
        let speed = speed.or(self.inner.speed).ok_or_else(|| {
            PyValueError::new_err("give speed, or [impact] speed in the scene (m/s)")
        })?;
        let (sim, outcome) = detached(py, || {
            let settings =
                SimulationSettings::with_tolerance(tolerance).map_err(|e| e.to_string())?;
            self.inner
                .simulate(speed, &settings)
                .map_err(|e| e.to_string())
        })?;
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

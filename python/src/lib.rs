//! `tabor._tabor`: the native core of the Python package `tabor`.
//!
//! The Python layer (`python/tabor/__init__.py`) checks the argument types,
//! broadcasts every array argument with numpy and hands this module flat,
//! contiguous float64 arrays of length 1 or n (a length-1 array stands for a
//! broadcast scalar) with the broadcast shape, which is used only to name the
//! index of a bad element. Every batch fills typed output columns directly
//! ([`output`], [`columns`]) in chunks on rayon's pool with the GIL released,
//! checking for Ctrl-C while it works ([`batch`]). Failures become
//! `tabor.InputError`, `tabor.ModelValidityError` or `tabor.ConvergenceError`
//! ([`failure`]); a panic inside the library is a `RuntimeError`, never a crash.

mod batch;
mod columns;
mod convert;
mod failure;
mod maugis;
mod models;
mod output;
mod scene;

use pyo3::prelude::*;

/// Sets the default number of threads of every batch (None: rayon's global pool,
/// sized by `RAYON_NUM_THREADS` or the number of cores).
#[pyfunction]
#[pyo3(signature = (threads=None))]
fn set_num_threads(threads: Option<usize>) -> PyResult<()> {
    batch::set_default_threads(threads).map_err(|m| failure::Failure::input(m).into_pyerr_static())
}

/// The number of threads a batch uses by default.
#[pyfunction]
fn get_num_threads() -> usize {
    batch::default_threads()
}

/// The native module `tabor._tabor`.
#[pymodule]
fn _tabor(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(maugis::maugis_dugdale_loss, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::maugis_dugdale_curve, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::tabor_parameter_from_maugis, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::tabor_parameter_from_tabor_mu, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::maugis_parameter_from_tabor, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::maugis_parameter, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::force_displacement, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::jkr_normalized_loss, m)?)?;
    m.add_function(wrap_pyfunction!(models::model, m)?)?;
    m.add_function(wrap_pyfunction!(set_num_threads, m)?)?;
    m.add_function(wrap_pyfunction!(get_num_threads, m)?)?;
    m.add_class::<scene::Scene>()?;
    m.add("SPECS", models::specs(m.py())?)?;
    m.add("VERSION", env!("CARGO_PKG_VERSION"))?;
    m.add("LIBRARY_VERSION", tabor::VERSION)?;
    m.add(
        "DEFAULT_TOLERANCE",
        tabor::numerics::tolerance::DEFAULT_TOLERANCE,
    )?;
    m.add("ACCURACY", tabor::numerics::tolerance::ACCURACY)?;
    m.add(
        "COSTLY_TOLERANCE",
        tabor::numerics::tolerance::COSTLY_TOLERANCE,
    )?;
    m.add("ERRORS", batch::ERRORS.map(|(name, _)| name))?;
    m.add("SWEEP_PARAMETERS", scene::sweep_parameters())?;
    m.add(
        "FORCE_DISPLACEMENT_MODELS",
        tabor::maugis::CurveModel::ALL.map(|c| (c.as_str(), c.description())),
    )?;
    m.add("MIN_MAUGIS_PARAMETER", tabor::maugis::MIN_MAUGIS_PARAMETER)?;
    m.add(
        "LAMBDA_PER_MAUGIS_PARAMETER",
        tabor::maugis::units::LAMBDA_PER_MAUGIS_PARAMETER,
    )?;
    m.add(
        "MAUGIS_PER_TABOR_MU",
        tabor::maugis::units::MAUGIS_PER_TABOR_MU,
    )?;
    m.add(
        "FAST_TIER_RELATIVE_ERROR",
        tabor::maugis::FAST_TIER_RELATIVE_ERROR,
    )?;
    Ok(())
}

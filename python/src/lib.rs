//! `tabor._tabor`: the native core of the Python package `tabor`.
//!
//! The Python layer (`python/tabor/__init__.py`) broadcasts every array argument
//! with numpy and hands this module flat, contiguous float64 arrays of length 1 or
//! n (a length-1 array stands for a broadcast scalar) together with the broadcast
//! shape, which is used only to name the index of a bad element. Every batch runs
//! with the GIL released, in parallel on rayon's pool; the first failing element
//! (lowest index) is reported as a `ValueError` with the library's message, which
//! names the parameter and its value. A panic inside the library is caught per
//! element and raised as a `RuntimeError` instead of crossing the boundary.

mod convert;
mod maugis;
mod models;
mod scene;

use pyo3::prelude::*;

/// The native module `tabor._tabor`.
#[pymodule]
fn _tabor(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(maugis::maugis_dugdale_loss, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::maugis_dugdale_curve, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::tabor_parameter_from_maugis, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::tabor_parameter_from_tabor_mu, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::maugis_parameter, m)?)?;
    m.add_function(wrap_pyfunction!(maugis::jkr_normalized_loss, m)?)?;
    m.add_function(wrap_pyfunction!(models::effective, m)?)?;
    m.add_function(wrap_pyfunction!(models::jkr, m)?)?;
    m.add_function(wrap_pyfunction!(models::plastic, m)?)?;
    m.add_function(wrap_pyfunction!(models::visco, m)?)?;
    m.add_function(wrap_pyfunction!(models::penalty, m)?)?;
    m.add_class::<scene::Scene>()?;
    m.add("VERSION", tabor::VERSION)?;
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

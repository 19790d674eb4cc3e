//! The single-model functions `effective`, `jkr`, `plastic`, `visco`, `penalty`
//! (the CLI subcommands of the same names, computed by `tabor::single`), driven by
//! one table per model: each keyword once, with its kind, default and help line.
//! The Python layer builds the functions' signatures, docs and type stubs from the
//! same tables (`_tabor.SPECS`); a library error names the keyword through
//! `tabor::single::input_name`.

//!
//! One file a concern: `types` (the shape of a table), `tables` (the tables, one
//! per model), `spec` (the tables in Python), `parse` (a call's keywords read
//! against a table), `run` (a model over a batch); this file: `_tabor.model`.

mod parse;
mod run;
mod spec;
mod tables;
mod types;

pub use spec::specs;
pub use tables::{EFFECTIVE, JKR, JKR_BY_SPEED, PENALTY, PLASTIC, VISCO};
pub use types::{Input, Kind, Model, Split};

use crate::batch::Options;
use crate::output::Call;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use run::{run_model, run_split};

/// `_tabor.model(name, args, shape, errors, threads)`: the model `name` over the
/// flat float64 arrays (length 1 or n) and scalars of `args`.
#[pyfunction]
#[pyo3(signature = (name, args, n, shape, errors="raise", threads=None))]
pub fn model<'py>(
    py: Python<'py>,
    name: &str,
    args: &Bound<'py, PyDict>,
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
    match name {
        "effective" => run_model(py, &EFFECTIVE, args, &call),
        "jkr" => run_split(py, &JKR, &JKR_BY_SPEED, args, &call),
        "plastic" => run_model(py, &PLASTIC, args, &call),
        "visco" => run_model(py, &VISCO, args, &call),
        "penalty" => run_model(py, &PENALTY, args, &call),
        other => Err(PyTypeError::new_err(format!("no model function {other}"))),
    }
}

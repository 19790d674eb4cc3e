//! The tables in Python: `_tabor.SPECS`, from which the Python layer builds the
//! functions' signatures, docs and type stubs.

use super::{Input, Kind, EFFECTIVE, JKR, PENALTY, PLASTIC, VISCO};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

fn spec<'py, A>(py: Python<'py>, inputs: &[Input<A>]) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for i in inputs {
        let none = py.None().into_bound(py);
        let (kind, default, choices): (&str, Bound<'py, PyAny>, Bound<'py, PyAny>) = match &i.kind {
            Kind::Number { default, .. } => (
                "number",
                default.into_pyobject(py)?.into_any(),
                none.clone(),
            ),
            Kind::Optional { .. } => ("optional", none.clone(), none.clone()),
            Kind::Flag { .. } => (
                "flag",
                false.into_pyobject(py)?.to_owned().into_any(),
                none.clone(),
            ),
            Kind::Choice { default, menu, .. } => (
                "choice",
                default.map(|d| d()).into_pyobject(py)?.into_any(),
                PyTuple::new(py, menu())?.into_any(),
            ),
        };
        list.append((i.name, kind, default, choices, i.help))?;
    }
    Ok(list)
}

/// `{name: [(keyword, kind, default, choices, help), …]}` for the Python layer.
pub fn specs(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    d.set_item(EFFECTIVE.name, spec(py, EFFECTIVE.inputs)?)?;
    d.set_item(JKR.name, spec(py, JKR.inputs)?)?;
    d.set_item(PLASTIC.name, spec(py, PLASTIC.inputs)?)?;
    d.set_item(VISCO.name, spec(py, VISCO.inputs)?)?;
    d.set_item(PENALTY.name, spec(py, PENALTY.inputs)?)?;
    Ok(d)
}

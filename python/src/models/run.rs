//! Running a model over a batch: one record per element ([`run_model`]) or, for
//! a [`Split`] model, the shared part once per distinct set of the other inputs
//! ([`run_split`]).

use super::parse::{element, given, parse};
use super::{Model, Split};
use crate::columns::OwnFields;
use crate::output::{push, Call, Col};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

pub(super) fn run_model<'py, A: Sync + Clone + 'static, R: serde::Serialize>(
    py: Python<'py>,
    model: &Model<A, R>,
    args: &Bound<'py, PyDict>,
    call: &Call<'_>,
) -> PyResult<Bound<'py, PyTuple>> {
    let parsed = parse(model, args)?;
    let given = given(model, &parsed, call)?;
    let (inputs, compute, base) = (model.inputs, model.compute, &parsed.base);
    call.records(py, |i, out| {
        push(out, &compute(&element(inputs, base, &given, i))?)
    })
}

pub(super) fn run_split<'py, A, P, R, V>(
    py: Python<'py>,
    model: &Model<A, R>,
    split: &Split<A, P, R, V>,
    args: &Bound<'py, PyDict>,
    call: &Call<'_>,
) -> PyResult<Bound<'py, PyTuple>>
where
    A: Sync + Clone + 'static,
    P: Send,
    R: serde::Serialize,
    V: OwnFields + Copy,
{
    let parsed = parse(model, args)?;
    let given = given(model, &parsed, call)?;
    // the columns that can change the shared part (a broadcast scalar cannot)
    let key: Vec<Col<'_>> = given
        .iter()
        .filter(|(k, _)| model.inputs[*k].name != split.varying)
        .filter_map(|(_, g)| g.column())
        .filter(|c| c.0.len() > 1)
        .collect();
    let varying: Option<Col<'_>> = given
        .iter()
        .find(|(k, _)| model.inputs[*k].name == split.varying)
        .and_then(|(_, g)| g.column());
    let (inputs, base) = (model.inputs, &parsed.base);
    call.split_columns(
        py,
        |i, j| key.iter().all(|c| c.at(i).to_bits() == c.at(j).to_bits()),
        |i| key.iter().map(|c| c.at(i).to_bits()).collect(),
        |i| (split.prepare)(&element(inputs, base, &given, i)),
        split.record,
        |p, i, near| (split.own)(p, varying.map(|c| c.at(i)), near),
    )
}

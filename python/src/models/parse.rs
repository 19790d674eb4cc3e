//! A call's keywords read against a model's table: the scalars set in the base
//! inputs, the arrays kept as columns, and the inputs of each element.

use super::{Input, Kind, Model};
use crate::failure::Failure;
use crate::output::{Call, Col};
use numpy::PyReadonlyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

fn type_error(name: &str, what: &str, value: &Bound<'_, PyAny>) -> PyErr {
    let t = value
        .get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "?".into());
    PyTypeError::new_err(format!("{name} must be {what}, not {t}"))
}

/// The choice `value` of keyword `name`: its name on `menu`.
fn choose(
    name: &str,
    value: &Bound<'_, PyAny>,
    menu: &[(&'static str, &'static str)],
) -> PyResult<&'static str> {
    let text: String = value
        .extract::<String>()
        .map_err(|_| type_error(name, "a str", value))?;
    let wanted = text.replace('_', "-");
    menu.iter()
        .map(|(c, _)| *c)
        .find(|c| *c == wanted)
        .ok_or_else(|| {
            let list: Vec<String> = menu.iter().map(|(c, _)| format!("\"{c}\"")).collect();
            Failure::input(format!(
                "invalid {name} = \"{text}\": expected one of {}",
                list.join(", ")
            ))
            .into_pyerr_static()
        })
}

/// A keyword's value for one element.
pub(super) enum Given<'a> {
    Number(Col<'a>),
    Optional(Option<Col<'a>>),
}

impl<'a> Given<'a> {
    /// The column, when given.
    pub(super) fn column(&self) -> Option<Col<'a>> {
        match self {
            Given::Number(c) | Given::Optional(Some(c)) => Some(*c),
            Given::Optional(None) => None,
        }
    }
}

/// The scalars of a call set in `base`, and its array keywords (index into the
/// table, array).
pub(super) struct Parsed<'py, A> {
    pub(super) base: A,
    pub(super) arrays: Vec<(usize, PyReadonlyArray1<'py, f64>)>,
}

pub(super) fn parse<'py, A: 'static, R>(
    model: &Model<A, R>,
    args: &Bound<'py, PyDict>,
) -> PyResult<Parsed<'py, A>> {
    let mut base = (model.blank)();
    let mut arrays: Vec<(usize, PyReadonlyArray1<'py, f64>)> = Vec::new();
    for (k, input) in model.inputs.iter().enumerate() {
        let value = args.get_item(input.name)?;
        match &input.kind {
            Kind::Number { .. } | Kind::Optional { .. } => {
                if let Some(v) = value.filter(|v| !v.is_none()) {
                    let a: PyReadonlyArray1<'py, f64> = v
                        .extract()
                        .map_err(|_| type_error(input.name, "a float64 array", &v))?;
                    arrays.push((k, a));
                } else if matches!(input.kind, Kind::Number { .. }) {
                    return Err(PyTypeError::new_err(format!(
                        "{}() missing the keyword argument {}",
                        model.name, input.name
                    )));
                }
            }
            Kind::Flag { set } => {
                let b = match value {
                    None => false,
                    Some(v) => v
                        .cast::<pyo3::types::PyBool>()
                        .map_err(|_| type_error(input.name, "True or False", &v))?
                        .is_true(),
                };
                set(&mut base, b);
            }
            Kind::Choice { menu, default, set } => {
                let k = match (value, default) {
                    (Some(v), _) => choose(input.name, &v, &menu())?,
                    (None, Some(d)) => d(),
                    (None, None) => {
                        return Err(PyTypeError::new_err(format!(
                            "{}() missing the keyword argument {}",
                            model.name, input.name
                        )))
                    }
                };
                set(&mut base, k).map_err(|e| {
                    Failure::input(format!("invalid {} = \"{k}\": {e}", input.name))
                        .into_pyerr_static()
                })?;
            }
        }
    }
    Ok(Parsed { base, arrays })
}

/// The number keywords of a call: (index into the table, its column).
pub(super) fn given<'a, A: 'static, R>(
    model: &Model<A, R>,
    parsed: &'a Parsed<'_, A>,
    call: &Call<'_>,
) -> PyResult<Vec<(usize, Given<'a>)>> {
    let named: Vec<(&str, &PyReadonlyArray1<'_, f64>)> = parsed
        .arrays
        .iter()
        .map(|(k, a)| (model.inputs[*k].name, a))
        .collect();
    let cols = call.columns(&named)?;
    let mut given = Vec::new();
    for (k, input) in model.inputs.iter().enumerate() {
        let pos = parsed.arrays.iter().position(|(j, _)| *j == k);
        match &input.kind {
            Kind::Number { .. } => {
                if let Some(p) = pos {
                    given.push((k, Given::Number(cols[p])));
                }
            }
            Kind::Optional { .. } => given.push((k, Given::Optional(pos.map(|p| cols[p])))),
            _ => {}
        }
    }
    Ok(given)
}

/// The inputs of element `i`.
pub(super) fn element<A: Clone>(
    inputs: &[Input<A>],
    base: &A,
    given: &[(usize, Given<'_>)],
    i: usize,
) -> A {
    let mut a = base.clone();
    for (k, g) in given {
        match (&inputs[*k].kind, g) {
            (Kind::Number { set, .. }, Given::Number(c)) => set(&mut a, c.at(i)),
            (Kind::Optional { set }, Given::Optional(c)) => set(&mut a, c.map(|c| c.at(i))),
            _ => {}
        }
    }
    a
}

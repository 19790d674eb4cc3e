//! [`Merged`]: the columns of a whole batch, and their conversion to a dict of
//! numpy arrays (string and JSON columns as object arrays).

use super::data::Data;
use super::sink::Merge;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::Value;
use std::borrow::Cow;

/// The columns of a whole batch.
pub struct Merged {
    pub(super) columns: Vec<(Cow<'static, str>, Merge)>,
    pub(super) strings: Vec<String>,
    pub(super) json: Vec<String>,
}

impl Merged {
    /// The columns as a dict: float64, bool and int64 arrays; string and object
    /// columns as object arrays (None where missing); an all-None column as
    /// `("null", n)`. Each column's codes are freed as soon as its array is
    /// made.
    pub fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let dict = PyDict::new(py);
        let mut strings = None;
        let mut json = None;
        for (name, data) in self.columns {
            match data {
                Merge::Plain(Data::Null(n)) => dict.set_item(name.as_ref(), ("null", n))?,
                Merge::Plain(Data::F64(v)) => {
                    dict.set_item(name.as_ref(), PyArray1::from_vec(py, v))?
                }
                Merge::Plain(Data::Bool(v)) => {
                    dict.set_item(name.as_ref(), PyArray1::from_vec(py, v))?
                }
                Merge::Plain(Data::I64(v)) => {
                    dict.set_item(name.as_ref(), PyArray1::from_vec(py, v))?
                }
                Merge::Str(codes) => {
                    if strings.is_none() {
                        strings = Some(object_table(py, &self.strings, false)?);
                    }
                    let table = strings.as_deref().unwrap_or_default();
                    let array = objects(py, table, codes.len(), |i| codes.get(i));
                    dict.set_item(name.as_ref(), array)?;
                }
                Merge::Json(codes) => {
                    if json.is_none() {
                        json = Some(object_table(py, &self.json, true)?);
                    }
                    let table = json.as_deref().unwrap_or_default();
                    let array = objects(py, table, codes.len(), |i| codes.get(i));
                    dict.set_item(name.as_ref(), array)?;
                }
                // the sink keeps string and JSON columns as codes: never here
                Merge::Plain(Data::Str(_) | Data::Json(_)) => {
                    return Err(pyo3::exceptions::PyRuntimeError::new_err(format!(
                        "column {name}: string codes outside a merged column"
                    )))
                }
            }
        }
        Ok(dict)
    }
}

/// The Python objects of a string table (`json`: of a JSON table), led by None
/// (code 0).
pub(super) fn object_table<'py>(
    py: Python<'py>,
    values: &[String],
    json: bool,
) -> PyResult<Vec<Bound<'py, PyAny>>> {
    let mut table = Vec::with_capacity(values.len() + 1);
    table.push(py.None().into_bound(py));
    for s in values {
        table.push(if json {
            let value: Value = serde_json::from_str(s).unwrap_or(Value::Null);
            crate::convert::json_to_py(py, &value)?
        } else {
            s.into_pyobject(py)?.into_any()
        });
    }
    Ok(table)
}

/// An object array of `n` references, element `i` to `table[code(i)]` (None
/// for a code outside the table), in numpy's memory: what `numpy.take` of the
/// table gives, without the codes' cast to intp or numpy's None fill.
pub(super) fn objects<'py>(
    py: Python<'py>,
    table: &[Bound<'py, PyAny>],
    n: usize,
    code: impl Fn(usize) -> u32,
) -> Bound<'py, PyAny> {
    let none = py.None().into_bound(py);
    // SAFETY: a fresh contiguous array of `n` object slots, which numpy
    // allocates zeroed (NULL, no reference held); each slot is written once
    // with a reference of its own, before Python sees the array.
    unsafe {
        let array = PyArray1::<Py<PyAny>>::new(py, n, false);
        let data = array.data();
        for i in 0..n {
            let item = table.get(code(i) as usize).unwrap_or(&none);
            std::ptr::write(data.add(i), item.clone().unbind());
        }
        array.into_any()
    }
}

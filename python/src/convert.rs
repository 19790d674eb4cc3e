//! Batches over flat arrays, error messages with the index of a bad element, and
//! JSON values into Python objects.

use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rayon::prelude::*;
use serde_json::Value;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// A flat input column: length 1 (a broadcast scalar) or the batch length.
#[derive(Clone, Copy)]
pub struct Col<'a>(pub &'a [f64]);

impl Col<'_> {
    /// The value at flat index `i`.
    #[inline]
    pub fn at(&self, i: usize) -> f64 {
        if self.0.len() == 1 {
            self.0[0]
        } else {
            self.0[i]
        }
    }
}

/// Why an element failed.
pub enum Failure {
    /// Bad input or a failed computation: `ValueError`.
    Value(String),
    /// A panic in the library (a bug): `RuntimeError`.
    Panic(String),
}

/// The slices of `arrays` with their common batch length (each has length 1 or n).
pub fn columns<'a>(
    arrays: &'a [(&'static str, &'a PyReadonlyArray1<'a, f64>)],
) -> PyResult<(Vec<Col<'a>>, usize)> {
    let mut n = 1;
    let mut out = Vec::with_capacity(arrays.len());
    for (name, a) in arrays {
        let s = a
            .as_slice()
            .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
        if s.len() != 1 {
            if n != 1 && s.len() != n {
                return Err(PyValueError::new_err(format!(
                    "{name}: length {} does not match the batch length {n}",
                    s.len()
                )));
            }
            n = s.len();
        }
        out.push(Col(s));
    }
    Ok((out, n))
}

/// The index `flat` in an array of shape `shape`, as numpy prints it.
pub fn index_text(flat: usize, shape: &[usize]) -> String {
    match shape.len() {
        0 => String::new(),
        1 => format!("{flat}"),
        _ => {
            let mut rest = flat;
            let mut idx = vec![0usize; shape.len()];
            for (k, &d) in shape.iter().enumerate().rev() {
                if d > 0 {
                    idx[k] = rest % d;
                    rest /= d;
                }
            }
            let parts: Vec<String> = idx.iter().map(|i| i.to_string()).collect();
            format!("({})", parts.join(", "))
        }
    }
}

/// The Python exception of element `i` failing with `failure`.
pub fn exception(i: usize, shape: &[usize], failure: Failure) -> PyErr {
    let at = |m: String| {
        if shape.is_empty() {
            m
        } else {
            format!("{m} (at index {})", index_text(i, shape))
        }
    };
    match failure {
        Failure::Value(m) => PyValueError::new_err(at(m)),
        Failure::Panic(m) => {
            PyRuntimeError::new_err(at(format!("internal error in tabor (please report): {m}")))
        }
    }
}

fn panic_text(payload: Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "panic".to_string()
    }
}

/// Runs `f` on one element, turning a panic into a [`Failure::Panic`].
pub fn guarded<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, Failure> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(m)) => Err(Failure::Value(m)),
        Err(p) => Err(Failure::Panic(panic_text(p))),
    }
}

/// `f(i)` for i in 0..n, in parallel with the GIL released; the failure of the
/// lowest index is raised.
pub fn batch<T, F>(py: Python<'_>, n: usize, shape: &[usize], f: F) -> PyResult<Vec<T>>
where
    T: Send + Sync + Clone + Default,
    F: Fn(usize) -> Result<T, String> + Sync + Send,
{
    const CHUNK: usize = 256;
    let mut out = vec![T::default(); n];
    let first_failure = py.detach(|| {
        out.par_chunks_mut(CHUNK)
            .enumerate()
            .filter_map(|(c, chunk)| {
                // one unwind guard per chunk (not per element: it would cost in
                // the fast tier); `current` tells which element panicked
                let mut current = c * CHUNK;
                let run = catch_unwind(AssertUnwindSafe(|| {
                    for (j, slot) in chunk.iter_mut().enumerate() {
                        current = c * CHUNK + j;
                        match f(current) {
                            Ok(v) => *slot = v,
                            Err(m) => return Some((current, Failure::Value(m))),
                        }
                    }
                    None
                }));
                match run {
                    Ok(failure) => failure,
                    Err(p) => Some((current, Failure::Panic(panic_text(p)))),
                }
            })
            .min_by_key(|(i, _)| *i)
    });
    match first_failure {
        Some((i, e)) => Err(exception(i, shape, e)),
        None => Ok(out),
    }
}

/// A JSON value as a Python object (numbers that are integers become `int`).
pub fn json_to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(x) => {
            if let Some(u) = x.as_u64() {
                u.into_pyobject(py)?.into_any()
            } else if let Some(s) = x.as_i64() {
                s.into_pyobject(py)?.into_any()
            } else {
                x.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any()
            }
        }
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(a) => {
            let list = PyList::empty(py);
            for x in a {
                list.append(json_to_py(py, x)?)?;
            }
            list.into_any()
        }
        Value::Object(o) => {
            let dict = PyDict::new(py);
            for (k, x) in o {
                dict.set_item(k, json_to_py(py, x)?)?;
            }
            dict.into_any()
        }
    })
}

/// Per-element JSON objects as a dict of flat columns: numbers (null and missing
/// as NaN) become float64 arrays, booleans bool arrays, anything else a list.
pub fn records_to_columns<'py>(py: Python<'py>, records: &[Value]) -> PyResult<Bound<'py, PyDict>> {
    let mut keys: Vec<String> = Vec::new();
    for r in records {
        if let Value::Object(o) = r {
            for k in o.keys() {
                if !keys.iter().any(|x| x == k) {
                    keys.push(k.clone());
                }
            }
        }
    }
    let dict = PyDict::new(py);
    for k in keys {
        let values: Vec<&Value> = records
            .iter()
            .map(|r| r.get(&k).unwrap_or(&Value::Null))
            .collect();
        let numeric = values.iter().all(|v| v.is_number() || v.is_null())
            && values.iter().any(|v| v.is_number());
        let boolean = values.iter().all(|v| v.is_boolean());
        if numeric {
            let col: Vec<f64> = values
                .iter()
                .map(|v| v.as_f64().unwrap_or(f64::NAN))
                .collect();
            dict.set_item(&k, PyArray1::from_vec(py, col))?;
        } else if boolean {
            let col: Vec<bool> = values
                .iter()
                .map(|v| v.as_bool().unwrap_or(false))
                .collect();
            dict.set_item(&k, PyArray1::from_vec(py, col))?;
        } else {
            let list = PyList::empty(py);
            for v in values {
                list.append(json_to_py(py, v)?)?;
            }
            dict.set_item(&k, list)?;
        }
    }
    Ok(dict)
}

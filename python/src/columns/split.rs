//! Split records: a part shared by many elements (one row per distinct record)
//! and a few fields of each element's own ([`OwnFields`]), put together as
//! numpy arrays by [`split_into_py`].

use super::data::{same_name, Data};
use super::merged::{object_table, objects};
use super::{numpy_zeros, Columns, Fresh};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// The code of a row without a shared record (a failed element).
pub const NO_RECORD: u32 = u32::MAX;

/// The kind of an element's own field ([`OwnFields`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OwnKind {
    /// A float64 column.
    Float,
    /// A bool column (stored as 0.0/1.0 while the batch runs).
    Bool,
}

/// The fields of each element's own in a model whose record splits into a part
/// shared by many elements and a few per-element fields (the impact speed's):
/// written by position straight into the output columns, with no per-element
/// record. `FIELDS` must be the record's serde field names in order (a test
/// checks it against the serializer).
pub trait OwnFields {
    /// The fields in order: name and kind.
    const FIELDS: &'static [(&'static str, OwnKind)];
    /// Writes the fields' values in the order of `FIELDS` (bool as 0.0/1.0).
    fn write(&self, out: &mut [f64]);
}

/// `out[i] = values[codes[i]]` (`missing` for a code without a value) in
/// parallel on the batch's pool, or `out` filled with `values[0]` when
/// `constant`.
fn gather_into<T: Copy + Send + Sync>(
    out: &mut [std::mem::MaybeUninit<T>],
    values: &[T],
    codes: &[u32],
    missing: T,
    constant: bool,
) {
    use rayon::prelude::*;
    let pieces = out.par_chunks_mut(crate::batch::CHUNK);
    if constant {
        let v = values.first().copied().unwrap_or(missing);
        pieces.for_each(|o| {
            for x in o {
                x.write(v);
            }
        });
    } else {
        pieces
            .zip(codes.par_chunks(crate::batch::CHUNK))
            .for_each(|(o, c)| {
                for (x, &k) in o.iter_mut().zip(c) {
                    x.write(values.get(k as usize).copied().unwrap_or(missing));
                }
            });
    }
}

/// Whether every value of a shared column is the same (floats by their bits).
fn constant(d: &Data) -> bool {
    fn all_equal<T: PartialEq>(v: &[T]) -> bool {
        v.windows(2).all(|w| w[0] == w[1])
    }
    match d {
        Data::Null(_) => true,
        Data::F64(v) => v.windows(2).all(|w| w[0].to_bits() == w[1].to_bits()),
        Data::Bool(v) => all_equal(v),
        Data::I64(v) => all_equal(v),
        Data::Str(v) | Data::Json(v) => all_equal(v),
    }
}

/// The columns of a batch of split records as the dict [`Merged::into_py`]
/// returns: the shared records' fields (`shared`, one row per record) gathered
/// by `codes` (`NO_RECORD`: missing) into fresh numpy arrays, in parallel on the
/// pool of `threads` with the GIL released, each replaced by the own column of
/// the same name (`own`, numpy arrays already filled), then the other own
/// columns and `valid` (when given). A shared field with the same value in
/// every record is filled rather than gathered; string and object fields come
/// as object arrays, as from [`Merged::into_py`].
pub fn split_into_py<'py>(
    py: Python<'py>,
    shared: Columns,
    codes: &[u32],
    own: Vec<(&'static str, Bound<'py, PyAny>)>,
    valid: Option<Bound<'py, PyAny>>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    if !shared.warnings.entries.is_empty() {
        return Err(pyo3::exceptions::PyRuntimeError::new_err(
            "a shared record carries warnings",
        ));
    }
    let n = codes.len();
    let complete = !codes.contains(&NO_RECORD);
    let parallel = |f: &mut (dyn FnMut() + Send)| -> PyResult<()> {
        py.detach(|| crate::batch::install(threads, &mut *f))
            .map_err(pyo3::exceptions::PyRuntimeError::new_err)
    };
    fn gathered<'py, T: numpy::Element + Copy + Send + Sync>(
        py: Python<'py>,
        values: &[T],
        codes: &[u32],
        missing: T,
        constant: bool,
        is_zero: fn(&T) -> bool,
        parallel: &dyn Fn(&mut (dyn FnMut() + Send)) -> PyResult<()>,
    ) -> PyResult<Bound<'py, PyAny>> {
        // a zeroed array holds a constant of zero bits already (an exact-form
        // loss's error estimate, its evaluation count): its pages stay untouched
        // (a read maps the kernel's zero page)
        if constant && values.first().is_some_and(is_zero) {
            return Ok(numpy_zeros::<T>(py, codes.len()).into_any());
        }
        // every element is written (filled or gathered)
        let mut array = Fresh::<T>::new(py, codes.len());
        let out = array.slots();
        parallel(&mut || gather_into(out, values, codes, missing, constant))?;
        Ok(array.into_array().into_any())
    }
    let dict = PyDict::new(py);
    let mut strings: Option<Vec<Bound<'py, PyAny>>> = None;
    let mut json: Option<Vec<Bound<'py, PyAny>>> = None;
    let mut own: Vec<Option<(&'static str, Bound<'py, PyAny>)>> =
        own.into_iter().map(Some).collect();
    for c in &shared.columns {
        let mine = own
            .iter_mut()
            .find(|o| o.as_ref().is_some_and(|(name, _)| same_name(name, &c.name)))
            .and_then(Option::take);
        if let Some((_, array)) = mine {
            dict.set_item(c.name.as_ref(), array)?;
            continue;
        }
        let fill = complete && constant(&c.data);
        let value: Bound<'py, PyAny> = match &c.data {
            Data::Null(_) => PyTuple::new(
                py,
                [
                    "null".into_pyobject(py)?.into_any(),
                    n.into_pyobject(py)?.into_any(),
                ],
            )?
            .into_any(),
            Data::F64(v) => gathered(
                py,
                v,
                codes,
                f64::NAN,
                fill,
                |x| x.to_bits() == 0,
                &parallel,
            )?,
            Data::Bool(v) => gathered(py, v, codes, false, fill, |x| !*x, &parallel)?,
            Data::I64(v) => gathered(py, v, codes, -1, fill, |x| *x == 0, &parallel)?,
            Data::Str(v) | Data::Json(v) => {
                let is_str = matches!(c.data, Data::Str(_));
                let table = if is_str { &mut strings } else { &mut json };
                if table.is_none() {
                    *table = Some(if is_str {
                        object_table(py, &shared.strings.values, false)?
                    } else {
                        object_table(py, &shared.json.values, true)?
                    });
                }
                let table = table.as_deref().unwrap_or_default();
                if fill {
                    let only = v.first().copied().unwrap_or(0);
                    objects(py, table, n, |_| only)
                } else {
                    objects(py, table, n, |i| {
                        v.get(codes[i] as usize).copied().unwrap_or(0)
                    })
                }
            }
        };
        dict.set_item(c.name.as_ref(), value)?;
    }
    for (name, array) in own.into_iter().flatten() {
        dict.set_item(name, array)?;
    }
    if let Some(v) = valid {
        dict.set_item("valid", v)?;
    }
    Ok(dict)
}

//! Records into columns without per-element JSON: a `serde::Serializer` that
//! writes each field of a result record (`tabor::single::*` records, the scene's
//! `Outcome`) straight into a typed column: f64, bool, int64, or a string column
//! of codes into a table of distinct strings (so 10⁶ equal model names cost 4
//! bytes each). Nested structs flatten to dotted keys (`cost.evaluations`); a list
//! of structs led by a `name` field flattens by that name
//! (`effects.adhesion.used`); a `warnings` list goes to the warning tally (Python's
//! `warnings` module) and its column keeps the codes; any other list or map is
//! stored once per distinct value (as JSON, turned into Python objects at the
//! end). New record fields reach Python without a change here.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use serde::ser::{self, Impossible, Serialize};
use serde_json::Value;
use std::borrow::Cow;
use std::collections::HashMap;
use std::fmt;
use std::sync::Mutex;

/// A column's values.
pub enum Data {
    /// Only missing values so far (None).
    Null(usize),
    /// Floats (NaN missing).
    F64(Vec<f64>),
    /// Bools (False missing).
    Bool(Vec<bool>),
    /// Integers (-1 missing).
    I64(Vec<i64>),
    /// Codes into the string table (0 is None).
    Str(Vec<u32>),
    /// Codes into the JSON table (0 is None).
    Json(Vec<u32>),
}

impl Data {
    fn len(&self) -> usize {
        match self {
            Data::Null(n) => *n,
            Data::F64(v) => v.len(),
            Data::Bool(v) => v.len(),
            Data::I64(v) => v.len(),
            Data::Str(v) | Data::Json(v) => v.len(),
        }
    }

    fn push_missing(&mut self, count: usize) {
        match self {
            Data::Null(n) => *n += count,
            Data::F64(v) => v.resize(v.len() + count, f64::NAN),
            Data::Bool(v) => v.resize(v.len() + count, false),
            Data::I64(v) => v.resize(v.len() + count, -1),
            Data::Str(v) | Data::Json(v) => v.resize(v.len() + count, 0),
        }
    }

    fn empty_like(&self, capacity: usize) -> Data {
        match self {
            Data::Null(_) => Data::Null(0),
            Data::F64(_) => Data::F64(Vec::with_capacity(capacity)),
            Data::Bool(_) => Data::Bool(Vec::with_capacity(capacity)),
            Data::I64(_) => Data::I64(Vec::with_capacity(capacity)),
            Data::Str(_) => Data::Str(Vec::with_capacity(capacity)),
            Data::Json(_) => Data::Json(Vec::with_capacity(capacity)),
        }
    }

    fn reserve(&mut self, more: usize) {
        match self {
            Data::Null(_) => {}
            Data::F64(v) => v.reserve(more),
            Data::Bool(v) => v.reserve(more),
            Data::I64(v) => v.reserve(more),
            Data::Str(v) | Data::Json(v) => v.reserve(more),
        }
    }

    fn kind(&self) -> &'static str {
        match self {
            Data::Null(_) => "null",
            Data::F64(_) => "float",
            Data::Bool(_) => "bool",
            Data::I64(_) => "int",
            Data::Str(_) => "str",
            Data::Json(_) => "object",
        }
    }
}

/// Distinct strings with their codes (code 0 is None).
#[derive(Default)]
struct Table {
    codes: HashMap<String, u32>,
    values: Vec<String>,
}

impl Table {
    fn code(&mut self, s: &str) -> u32 {
        if let Some(&c) = self.codes.get(s) {
            return c;
        }
        self.values.push(s.to_string());
        let c = self.values.len() as u32;
        self.codes.insert(s.to_string(), c);
        c
    }
}

struct Column {
    name: Cow<'static, str>,
    data: Data,
    /// The last string code written (a cheap repeat check).
    last: u32,
}

/// A warning tally: per code, how many elements warned, the first index and
/// message.
#[derive(Default)]
pub struct Warnings {
    /// (code, count, first element, first message), in order of first appearance.
    pub entries: Vec<(String, usize, usize, String)>,
}

impl Warnings {
    /// Counts one warning of element `index`.
    pub fn add(&mut self, code: &str, message: &str, index: usize) {
        if let Some(e) = self.entries.iter_mut().find(|e| e.0 == code) {
            e.1 += 1;
            if index < e.2 {
                e.2 = index;
                e.3 = message.to_string();
            }
        } else {
            self.entries
                .push((code.to_string(), 1, index, message.to_string()));
        }
    }

    /// Adds another tally.
    pub fn merge(&mut self, other: Warnings) {
        for (code, count, index, message) in other.entries {
            if let Some(e) = self.entries.iter_mut().find(|e| e.0 == code) {
                e.1 += count;
                if index < e.2 {
                    e.2 = index;
                    e.3 = message;
                }
            } else {
                self.entries.push((code, count, index, message));
            }
        }
    }

    /// Emits one Python warning per code (`tabor._errors._warn`).
    pub fn emit(
        &self,
        py: Python<'_>,
        total: usize,
        index: impl Fn(usize) -> String,
    ) -> PyResult<()> {
        if self.entries.is_empty() {
            return Ok(());
        }
        let warn = crate::failure::errors_module(py)?.getattr("_warn")?;
        for (code, count, first, message) in &self.entries {
            warn.call1((code, message, *count, total, index(*first)))?;
        }
        Ok(())
    }
}

/// The columns of one chunk of records.
#[derive(Default)]
pub struct Columns {
    columns: Vec<Column>,
    strings: Table,
    json: Table,
    rows: usize,
    hint: usize,
    /// The warnings of the chunk's records.
    pub warnings: Warnings,
    /// The flat index of the chunk's first row (for the warning tally).
    pub offset: usize,
    /// Per row: false where the element failed.
    valid: Vec<bool>,
    /// Rows expected (room reserved when a column gets its type).
    capacity: usize,
}

/// Whether two column names are equal (a field's name is a `&'static str`, so
/// the same pointer is the common case).
#[inline]
fn same_name(a: &str, b: &str) -> bool {
    (a.as_ptr() == b.as_ptr() && a.len() == b.len()) || a == b
}

/// Serialization can fail only on a type mismatch between rows (a bug).
#[derive(Debug)]
pub struct Error(String);

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Error {}

impl ser::Error for Error {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Error(msg.to_string())
    }
}

/// Whether the strings of column `name` are split into a template and numbers:
/// a scene's effect reasons, which quote the numbers that decided them (a speed,
/// a yield onset), so that a sweep stores one template per kind of reason, not
/// one string per point.
fn templated(name: &str) -> bool {
    name.ends_with(".reason")
}

/// `text` with each number in Rust's `{:e}` notation (`1.25e-3`, `-4e0`: a token
/// with an exponent, not inside a word) replaced by `{}` and appended to
/// `numbers`; braces already in the text doubled (so that Python's `str.format`
/// with the numbers gives the text back, the numbers printed Python's way).
fn split_numbers(text: &str, numbers: &mut Vec<f64>) -> String {
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let mut copied = 0;
    let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_' || b == b'.';
    while i < bytes.len() {
        let starts = (bytes[i].is_ascii_digit()
            || (bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)))
            && (i == 0 || !word(bytes[i - 1]));
        if starts {
            let mut j = i + 1;
            while j < bytes.len() && bytes[j].is_ascii_digit() {
                j += 1;
            }
            if j + 1 < bytes.len() && bytes[j] == b'.' && bytes[j + 1].is_ascii_digit() {
                j += 1;
                while j < bytes.len() && bytes[j].is_ascii_digit() {
                    j += 1;
                }
            }
            if j < bytes.len() && bytes[j] == b'e' {
                let mut k = j + 1;
                if k < bytes.len() && bytes[k] == b'-' {
                    k += 1;
                }
                let digits = k;
                while k < bytes.len() && bytes[k].is_ascii_digit() {
                    k += 1;
                }
                let ends = k == bytes.len() || !bytes[k].is_ascii_alphanumeric();
                if k > digits && ends {
                    if let Ok(x) = text[i..k].parse::<f64>() {
                        out.push_str(&text[copied..i].replace('{', "{{").replace('}', "}}"));
                        out.push_str("{}");
                        numbers.push(x);
                        copied = k;
                        i = k;
                        continue;
                    }
                }
            }
            i = j;
            continue;
        }
        i += 1;
    }
    out.push_str(&text[copied..].replace('{', "{{").replace('}', "}}"));
    out
}

/// Marks a list or map value, which is stored as a whole (see the module doc).
const COMPOUND: &str = "\u{0}compound";

enum Scalar<'a> {
    Missing,
    F64(f64),
    Bool(bool),
    I64(i64),
    Str(&'a str),
}

impl Columns {
    /// An empty chunk whose first row has flat index `offset`.
    pub fn at(offset: usize) -> Self {
        Columns {
            offset,
            ..Columns::default()
        }
    }

    /// Appends one record as a row.
    pub fn push<T: Serialize>(&mut self, record: &T) -> Result<(), Error> {
        record.serialize(Row {
            cols: self,
            prefix: None,
        })?;
        self.valid.push(true);
        self.end_row();
        Ok(())
    }

    /// Appends an empty row (a failed element).
    pub fn push_missing(&mut self) {
        self.valid.push(false);
        self.end_row();
    }

    fn end_row(&mut self) {
        self.rows += 1;
        for c in &mut self.columns {
            let short = self.rows - c.data.len();
            if short > 0 {
                c.data.push_missing(short);
            }
        }
        self.hint = 0;
    }

    fn column(&mut self, name: Cow<'static, str>) -> usize {
        let n = self.columns.len();
        if self.hint < n && same_name(&self.columns[self.hint].name, &name) {
            self.hint += 1;
            return self.hint - 1;
        }
        if let Some(i) = self.columns.iter().position(|c| c.name == name) {
            self.hint = i + 1;
            return i;
        }
        self.columns.push(Column {
            name,
            data: Data::Null(self.rows),
            last: 0,
        });
        self.hint = n + 1;
        n
    }

    /// Reserves room for `rows` more rows in every typed column (and in those
    /// typed later).
    pub fn reserve(&mut self, rows: usize) {
        self.capacity = self.rows + rows;
        for c in &mut self.columns {
            c.data.reserve(rows);
        }
    }

    fn put(&mut self, name: Cow<'static, str>, value: Scalar<'_>) -> Result<(), Error> {
        if let Scalar::Str(text) = value {
            if templated(&name) {
                let mut numbers = Vec::new();
                let template = split_numbers(text, &mut numbers);
                for (k, x) in numbers.into_iter().enumerate() {
                    self.put_scalar(Cow::Owned(format!("{name}_values.{k}")), Scalar::F64(x))?;
                }
                return self.put_scalar(name, Scalar::Str(&template));
            }
        }
        self.put_scalar(name, value)
    }

    fn put_scalar(&mut self, name: Cow<'static, str>, value: Scalar<'_>) -> Result<(), Error> {
        let i = self.column(name);
        let rows = self.rows;
        let Column { data, last, name } = &mut self.columns[i];
        if data.len() > rows {
            return Err(Error(format!("field {name} written twice in one record")));
        }
        if let Data::Null(k) = *data {
            *data = match value {
                Scalar::Missing => return Ok(()),
                Scalar::F64(_) => Data::F64(vec![f64::NAN; k]),
                Scalar::Bool(_) => Data::Bool(vec![false; k]),
                Scalar::I64(_) => Data::I64(vec![-1; k]),
                Scalar::Str(_) => Data::Str(vec![0; k]),
            };
            data.reserve(self.capacity.saturating_sub(k));
        }
        match (data, value) {
            (d, Scalar::Missing) => d.push_missing(1),
            (Data::F64(v), Scalar::F64(x)) => v.push(x),
            (Data::F64(v), Scalar::I64(x)) => v.push(x as f64),
            (Data::I64(v), Scalar::I64(x)) => v.push(x),
            (Data::Bool(v), Scalar::Bool(x)) => v.push(x),
            (Data::Str(v), Scalar::Str(s)) => {
                let code = if *last != 0 && self.strings.values[*last as usize - 1] == s {
                    *last
                } else {
                    self.strings.code(s)
                };
                *last = code;
                v.push(code);
            }
            (d, _) => {
                return Err(Error(format!(
                    "field {name} changes type between records (was {})",
                    d.kind()
                )))
            }
        }
        Ok(())
    }

    fn put_json(&mut self, name: Cow<'static, str>, value: &Value) -> Result<(), Error> {
        if value.is_null() {
            return self.put(name, Scalar::Missing);
        }
        let text = value.to_string();
        let i = self.column(name);
        let rows = self.rows;
        let code = self.json.code(&text);
        let Column { data, name, .. } = &mut self.columns[i];
        if let Data::Null(k) = *data {
            *data = Data::Json(vec![0; k]);
        }
        match data {
            Data::Json(v) if v.len() == rows => {
                v.push(code);
                Ok(())
            }
            d => Err(Error(format!(
                "field {name} changes type between records (was {})",
                d.kind()
            ))),
        }
    }

    /// A list or map field: flattened, tallied or stored whole (module doc).
    fn compound(&mut self, key: Cow<'static, str>, value: Value) -> Result<(), Error> {
        if key == "warnings" {
            return self.warnings_field(value);
        }
        if let Value::Array(items) = &value {
            let named = !items.is_empty()
                && items
                    .iter()
                    .all(|x| x.get("name").is_some_and(Value::is_string));
            if named {
                for item in items {
                    let Value::Object(fields) = item else {
                        continue;
                    };
                    let name = fields.get("name").and_then(Value::as_str).unwrap_or("");
                    for (k, v) in fields {
                        if k != "name" {
                            self.value(Cow::Owned(format!("{key}.{name}.{k}")), v)?;
                        }
                    }
                }
                return Ok(());
            }
        }
        self.put_json(key, &value)
    }

    fn value(&mut self, key: Cow<'static, str>, v: &Value) -> Result<(), Error> {
        match v {
            Value::Null => self.put(key, Scalar::Missing),
            Value::Bool(b) => self.put(key, Scalar::Bool(*b)),
            Value::Number(x) => match x.as_i64() {
                Some(i) if !x.is_f64() => self.put(key, Scalar::I64(i)),
                _ => self.put(key, Scalar::F64(x.as_f64().unwrap_or(f64::NAN))),
            },
            Value::String(s) => self.put(key, Scalar::Str(s)),
            _ => self.put_json(key, v),
        }
    }

    /// A `warnings` list: structs with `code` and `message`, or plain strings (the
    /// string is its own code). The column keeps the codes.
    fn warnings_field(&mut self, value: Value) -> Result<(), Error> {
        let index = self.offset + self.rows;
        let mut codes = Vec::new();
        if let Value::Array(items) = value {
            for w in items {
                let (code, message) = match &w {
                    Value::String(s) => (s.as_str(), s.as_str()),
                    other => (
                        other.get("code").and_then(Value::as_str).unwrap_or(""),
                        other.get("message").and_then(Value::as_str).unwrap_or(""),
                    ),
                };
                self.warnings.add(code, message, index);
                codes.push(Value::String(code.to_string()));
            }
        }
        self.put_json(Cow::Borrowed("warnings"), &Value::Array(codes))
    }
}

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

/// An output column of `n` elements allocated by numpy (zeroed): numpy's
/// allocator asks the kernel for huge pages for large arrays, so that filling a
/// fresh column costs far fewer page faults than a `Vec` of the same size.
pub fn numpy_zeros<T: numpy::Element>(py: Python<'_>, n: usize) -> Bound<'_, PyArray1<T>> {
    PyArray1::<T>::zeros(py, n, false)
}

/// A fresh numpy array of `n` elements (numpy's allocator, huge pages for large
/// arrays) whose memory is not initialized: no zeroing pass (the kernel's or
/// `calloc`'s) for an output that is written in full anyway. Its elements are
/// written through [`Fresh::slots`]; every one must be before
/// [`Fresh::into_array`] hands the array to Python.
pub struct Fresh<'py, T: numpy::Element> {
    array: Bound<'py, PyArray1<T>>,
    n: usize,
}

impl<'py, T: numpy::Element> Fresh<'py, T> {
    /// An array of `n` uninitialized elements.
    pub fn new(py: Python<'py>, n: usize) -> Self {
        // SAFETY: the elements are only written (as `MaybeUninit`) until
        // `into_array`, whose callers have written every one.
        let array = unsafe { PyArray1::<T>::new(py, n, false) };
        Fresh { array, n }
    }

    /// The elements, to be written.
    pub fn slots(&mut self) -> &mut [std::mem::MaybeUninit<T>] {
        // SAFETY: a fresh, contiguous array of `n` elements, not yet seen by
        // Python; the exclusive borrow of `self` is the only access.
        unsafe {
            std::slice::from_raw_parts_mut(
                self.array.data().cast::<std::mem::MaybeUninit<T>>(),
                self.n,
            )
        }
    }

    /// The array, once every element is written.
    pub fn into_array(self) -> Bound<'py, PyArray1<T>> {
        self.array
    }
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

/// The rows of `columns`.
pub fn shared_rows(columns: &Columns) -> u32 {
    columns.rows as u32
}

/// The names of a record's fields as the serializer writes them (for the check
/// of [`OwnFields::FIELDS`]).
#[cfg(test)]
pub fn field_names<T: Serialize>(record: &T) -> Vec<String> {
    let mut c = Columns::default();
    c.push(record).unwrap();
    c.columns.iter().map(|c| c.name.to_string()).collect()
}

/// The columns of a whole batch, filled as chunks finish: each chunk's rows are
/// copied to their place in full-length columns and the chunk freed at once, so
/// that a batch holds little more than its outputs (no second copy of them).
pub struct Sink {
    state: Mutex<SinkState>,
}

struct SinkColumn {
    name: Cow<'static, str>,
    data: Merge,
    /// Where the column first appeared (chunk offset, position): the order of
    /// the merged columns.
    first: (usize, usize),
}

struct SinkState {
    n: usize,
    columns: Vec<SinkColumn>,
    strings: Table,
    json: Table,
    valid: Vec<bool>,
    warnings: Warnings,
}

/// A column of a whole batch: string and JSON columns keep their codes in the
/// narrowest unsigned type that holds them ([`Codes`]).
pub enum Merge {
    /// Floats, bools, integers or only missing values.
    Plain(Data),
    /// Codes into the string table (0 is None).
    Str(Codes),
    /// Codes into the JSON table (0 is None).
    Json(Codes),
}

/// The codes of a merged string or JSON column, one byte each while the table
/// has at most 255 entries, two up to 65 535, else four, widened as the table
/// grows: the codes are held until the column's object array is made, and a
/// sweep has 15 string columns (60 bytes per point at four bytes a code).
pub enum Codes {
    /// Tables of up to 255 entries.
    U8(Vec<u8>),
    /// Tables of up to 65 535 entries.
    U16(Vec<u16>),
    /// Larger tables.
    U32(Vec<u32>),
}

impl Codes {
    /// `n` missing values (code 0).
    fn missing(n: usize) -> Self {
        Codes::U8(vec![0; n])
    }

    fn len(&self) -> usize {
        match self {
            Codes::U8(v) => v.len(),
            Codes::U16(v) => v.len(),
            Codes::U32(v) => v.len(),
        }
    }

    /// The code of row `i`.
    #[inline]
    fn get(&self, i: usize) -> u32 {
        match self {
            Codes::U8(v) => u32::from(v[i]),
            Codes::U16(v) => u32::from(v[i]),
            Codes::U32(v) => v[i],
        }
    }

    /// Widened, if needed, to hold codes up to `max`.
    fn fit(&mut self, max: usize) {
        let wide: Option<Codes> = match self {
            Codes::U8(v) if max > usize::from(u8::MAX) => Some(if max <= usize::from(u16::MAX) {
                Codes::U16(v.iter().map(|&c| u16::from(c)).collect())
            } else {
                Codes::U32(v.iter().map(|&c| u32::from(c)).collect())
            }),
            Codes::U16(v) if max > usize::from(u16::MAX) => {
                Some(Codes::U32(v.iter().map(|&c| u32::from(c)).collect()))
            }
            _ => None,
        };
        if let Some(w) = wide {
            *self = w;
        }
    }

    /// Writes a chunk's codes, mapped by `map` (chunk code → merged code, all
    /// within the width: [`Codes::fit`] first), from row `at`.
    fn put(&mut self, at: usize, codes: &[u32], map: &[u32]) {
        let mapped = codes.iter().map(|&c| map[c as usize]);
        match self {
            Codes::U8(v) => {
                for (x, c) in v[at..at + codes.len()].iter_mut().zip(mapped) {
                    *x = c as u8;
                }
            }
            Codes::U16(v) => {
                for (x, c) in v[at..at + codes.len()].iter_mut().zip(mapped) {
                    *x = c as u16;
                }
            }
            Codes::U32(v) => {
                for (x, c) in v[at..at + codes.len()].iter_mut().zip(mapped) {
                    *x = c;
                }
            }
        }
    }
}

/// A typed column of `n` missing values, like `like`.
fn missing_like(like: &Data, n: usize) -> Data {
    let mut d = like.empty_like(n);
    d.push_missing(n);
    d
}

/// Writes `data` (a chunk's float, bool or integer column) into `d` from row
/// `at`; a type that differs between chunks (a bug) stays missing.
fn write_at(d: &mut Data, at: usize, data: Data) {
    fn put<T: Copy>(a: &mut [T], at: usize, b: impl ExactSizeIterator<Item = T>) {
        for (x, y) in a[at..at + b.len()].iter_mut().zip(b) {
            *x = y;
        }
    }
    match (d, data) {
        (_, Data::Null(_)) => {}
        (Data::F64(a), Data::F64(b)) => a[at..at + b.len()].copy_from_slice(&b),
        (Data::Bool(a), Data::Bool(b)) => a[at..at + b.len()].copy_from_slice(&b),
        (Data::I64(a), Data::I64(b)) => a[at..at + b.len()].copy_from_slice(&b),
        (Data::F64(a), Data::I64(b)) => put(a, at, b.iter().map(|&x| x as f64)),
        _ => {}
    }
}

impl Sink {
    /// Columns of `n` rows, every value missing so far.
    pub fn new(n: usize) -> Self {
        Sink {
            state: Mutex::new(SinkState {
                n,
                columns: Vec::new(),
                strings: Table::default(),
                json: Table::default(),
                valid: vec![false; n],
                warnings: Warnings::default(),
            }),
        }
    }

    /// Copies a finished chunk into place (its first row is `chunk.offset`) and
    /// frees it.
    pub fn absorb(&self, chunk: Columns) {
        let Ok(mut state) = self.state.lock() else {
            return;
        };
        let state = &mut *state;
        let at = chunk.offset;
        if at + chunk.rows > state.n {
            return;
        }
        let smap: Vec<u32> = std::iter::once(0)
            .chain(chunk.strings.values.iter().map(|v| state.strings.code(v)))
            .collect();
        let jmap: Vec<u32> = std::iter::once(0)
            .chain(chunk.json.values.iter().map(|v| state.json.code(v)))
            .collect();
        let (max_string, max_json) = (state.strings.values.len(), state.json.values.len());
        state.valid[at..at + chunk.valid.len()].copy_from_slice(&chunk.valid);
        state.warnings.merge(chunk.warnings);
        for (pos, c) in chunk.columns.into_iter().enumerate() {
            let n = state.n;
            let i = match state
                .columns
                .iter()
                .position(|x| same_name(&x.name, &c.name))
            {
                Some(i) => i,
                None => {
                    state.columns.push(SinkColumn {
                        name: c.name,
                        data: Merge::Plain(Data::Null(n)),
                        first: (at, pos),
                    });
                    state.columns.len() - 1
                }
            };
            let column = &mut state.columns[i];
            column.first = column.first.min((at, pos));
            if let Merge::Plain(Data::Null(_)) = column.data {
                column.data = match &c.data {
                    Data::Null(_) => Merge::Plain(Data::Null(n)),
                    Data::Str(_) => Merge::Str(Codes::missing(n)),
                    Data::Json(_) => Merge::Json(Codes::missing(n)),
                    other => Merge::Plain(missing_like(other, n)),
                };
            }
            if let (Merge::Plain(Data::I64(v)), Data::F64(_)) = (&column.data, &c.data) {
                // integers so far, a float now: the column becomes float
                column.data = Merge::Plain(Data::F64(
                    v.iter()
                        .map(|&x| if x == -1 { f64::NAN } else { x as f64 })
                        .collect(),
                ));
            }
            match (&mut column.data, c.data) {
                (Merge::Plain(d), data) => write_at(d, at, data),
                (Merge::Str(codes), Data::Str(b)) => {
                    codes.fit(max_string);
                    codes.put(at, &b, &smap);
                }
                (Merge::Json(codes), Data::Json(b)) => {
                    codes.fit(max_json);
                    codes.put(at, &b, &jmap);
                }
                // a type that differs between chunks (a bug) stays missing
                _ => {}
            }
        }
    }

    /// The merged columns (with `valid`, a bool column `valid`: false where an
    /// element failed or did not run) and the warning tally.
    pub fn finish(self, valid: bool) -> (Merged, Warnings) {
        let state = match self.state.into_inner() {
            Ok(s) => s,
            Err(poisoned) => poisoned.into_inner(),
        };
        let mut columns = state.columns;
        columns.sort_by_key(|c| c.first);
        let mut out: Vec<(Cow<'static, str>, Merge)> =
            columns.into_iter().map(|c| (c.name, c.data)).collect();
        if valid {
            out.push((
                Cow::Borrowed("valid"),
                Merge::Plain(Data::Bool(state.valid)),
            ));
        }
        (
            Merged {
                columns: out,
                strings: state.strings.values,
                json: state.json.values,
            },
            state.warnings,
        )
    }
}

/// The columns of a whole batch.
pub struct Merged {
    columns: Vec<(Cow<'static, str>, Merge)>,
    strings: Vec<String>,
    json: Vec<String>,
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
fn object_table<'py>(
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
fn objects<'py>(
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

// ---------------------------------------------------------------------------------
// the serializer

/// Serializes a record (a struct) into the current row.
struct Row<'a> {
    cols: &'a mut Columns,
    prefix: Option<Cow<'static, str>>,
}

fn key(prefix: &Option<Cow<'static, str>>, field: &'static str) -> Cow<'static, str> {
    match prefix {
        None => Cow::Borrowed(field),
        Some(p) => Cow::Owned(format!("{p}.{field}")),
    }
}

macro_rules! not_a_record {
    ($($f:ident: $t:ty),*) => {
        $(fn $f(self, _v: $t) -> Result<(), Error> {
            Err(Error("a record must be a struct".into()))
        })*
    };
}

impl<'a> ser::Serializer for Row<'a> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Impossible<(), Error>;
    type SerializeTuple = Impossible<(), Error>;
    type SerializeTupleStruct = Impossible<(), Error>;
    type SerializeTupleVariant = Impossible<(), Error>;
    type SerializeMap = Impossible<(), Error>;
    type SerializeStruct = Self;
    type SerializeStructVariant = Impossible<(), Error>;

    not_a_record!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_f32: f32, serialize_f64: f64, serialize_char: char,
        serialize_str: &str, serialize_bytes: &[u8]);

    fn serialize_none(self) -> Result<(), Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_some<T: ?Sized + Serialize>(self, v: &T) -> Result<(), Error> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        v: &T,
    ) -> Result<(), Error> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<(), Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_tuple_struct(
        self,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleStruct, Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleVariant, Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Error> {
        Err(Error("a record must be a struct".into()))
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, Error> {
        Ok(self)
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStructVariant, Error> {
        Err(Error("a record must be a struct".into()))
    }
}

impl ser::SerializeStruct for Row<'_> {
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        field: &'static str,
        value: &T,
    ) -> Result<(), Error> {
        let k = key(&self.prefix, field);
        match value.serialize(Field {
            cols: self.cols,
            key: k.clone(),
        }) {
            Err(Error(m)) if m == COMPOUND => {
                let v = serde_json::to_value(value).map_err(|e| Error(e.to_string()))?;
                self.cols.compound(k, v)
            }
            other => other,
        }
    }

    fn skip_field(&mut self, _: &'static str) -> Result<(), Error> {
        Ok(())
    }

    fn end(self) -> Result<(), Error> {
        Ok(())
    }
}

/// Serializes one field's value into its column.
struct Field<'a> {
    cols: &'a mut Columns,
    key: Cow<'static, str>,
}

fn compound<T>() -> Result<T, Error> {
    Err(Error(COMPOUND.into()))
}

impl<'a> ser::Serializer for Field<'a> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Impossible<(), Error>;
    type SerializeTuple = Impossible<(), Error>;
    type SerializeTupleStruct = Impossible<(), Error>;
    type SerializeTupleVariant = Impossible<(), Error>;
    type SerializeMap = Impossible<(), Error>;
    type SerializeStruct = Row<'a>;
    type SerializeStructVariant = Impossible<(), Error>;

    fn serialize_bool(self, v: bool) -> Result<(), Error> {
        self.cols.put(self.key, Scalar::Bool(v))
    }
    fn serialize_i8(self, v: i8) -> Result<(), Error> {
        self.serialize_i64(v.into())
    }
    fn serialize_i16(self, v: i16) -> Result<(), Error> {
        self.serialize_i64(v.into())
    }
    fn serialize_i32(self, v: i32) -> Result<(), Error> {
        self.serialize_i64(v.into())
    }
    fn serialize_i64(self, v: i64) -> Result<(), Error> {
        self.cols.put(self.key, Scalar::I64(v))
    }
    fn serialize_u8(self, v: u8) -> Result<(), Error> {
        self.serialize_i64(v.into())
    }
    fn serialize_u16(self, v: u16) -> Result<(), Error> {
        self.serialize_i64(v.into())
    }
    fn serialize_u32(self, v: u32) -> Result<(), Error> {
        self.serialize_i64(v.into())
    }
    fn serialize_u64(self, v: u64) -> Result<(), Error> {
        match i64::try_from(v) {
            Ok(i) => self.serialize_i64(i),
            Err(_) => self.serialize_f64(v as f64),
        }
    }
    fn serialize_f32(self, v: f32) -> Result<(), Error> {
        self.serialize_f64(v.into())
    }
    fn serialize_f64(self, v: f64) -> Result<(), Error> {
        self.cols.put(self.key, Scalar::F64(v))
    }
    fn serialize_char(self, v: char) -> Result<(), Error> {
        let mut b = [0u8; 4];
        self.serialize_str(v.encode_utf8(&mut b))
    }
    fn serialize_str(self, v: &str) -> Result<(), Error> {
        self.cols.put(self.key, Scalar::Str(v))
    }
    fn serialize_bytes(self, _: &[u8]) -> Result<(), Error> {
        compound()
    }
    fn serialize_none(self) -> Result<(), Error> {
        self.cols.put(self.key, Scalar::Missing)
    }
    fn serialize_some<T: ?Sized + Serialize>(self, v: &T) -> Result<(), Error> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Error> {
        self.serialize_none()
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), Error> {
        self.serialize_none()
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<(), Error> {
        self.serialize_str(variant)
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        v: &T,
    ) -> Result<(), Error> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<(), Error> {
        compound()
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Error> {
        compound()
    }
    fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Error> {
        compound()
    }
    fn serialize_tuple_struct(
        self,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleStruct, Error> {
        compound()
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleVariant, Error> {
        compound()
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Error> {
        compound()
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Row<'a>, Error> {
        Ok(Row {
            cols: self.cols,
            prefix: Some(self.key),
        })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStructVariant, Error> {
        compound()
    }
}

#[cfg(test)]
mod tests {
    use super::{split_numbers, Codes};

    #[test]
    fn codes_widen_as_the_table_grows() {
        let map: Vec<u32> = (0..70_000).collect();
        let mut c = Codes::missing(5);
        c.fit(3);
        c.put(0, &[1, 2], &map);
        assert!(matches!(c, Codes::U8(_)));
        c.fit(300);
        c.put(2, &[299], &map);
        assert!(matches!(c, Codes::U16(_)));
        c.fit(70_000);
        c.put(3, &[69_999], &map);
        assert!(matches!(c, Codes::U32(_)));
        let all: Vec<u32> = (0..c.len()).map(|i| c.get(i)).collect();
        assert_eq!(all, [1, 2, 299, 69_999, 0]);
    }

    #[test]
    fn reasons_split_into_a_template_and_numbers() {
        let mut x = Vec::new();
        let t = split_numbers(
            "impact speed 1.2617695852173827e-1 m/s does not exceed the adhesive yield onset (5.111) 1.9449639560565972e0 m/s: {below}",
            &mut x,
        );
        assert_eq!(
            t,
            "impact speed {} m/s does not exceed the adhesive yield onset (5.111) {} m/s: {{below}}"
        );
        assert_eq!(x, [1.2617695852173827e-1, 1.9449639560565972e0]);
        // no exponent, inside a word, or a bare sign: not a number
        let mut y = Vec::new();
        let t = split_numbers("case 1, (5.44), x2e5, Q = 5, -e3, -5e-2.", &mut y);
        assert_eq!(t, "case 1, (5.44), x2e5, Q = 5, -e3, {}.");
        assert_eq!(y, [-5e-2]);
        assert_eq!(split_numbers("", &mut y), "");
    }
}

//! The column types: a column's values ([`Data`]), the table of distinct strings
//! behind a string column's codes ([`Table`]), a named column ([`Column`]).

use std::borrow::Cow;
use std::collections::HashMap;

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
    pub(super) fn len(&self) -> usize {
        match self {
            Data::Null(n) => *n,
            Data::F64(v) => v.len(),
            Data::Bool(v) => v.len(),
            Data::I64(v) => v.len(),
            Data::Str(v) | Data::Json(v) => v.len(),
        }
    }

    pub(super) fn push_missing(&mut self, count: usize) {
        match self {
            Data::Null(n) => *n += count,
            Data::F64(v) => v.resize(v.len() + count, f64::NAN),
            Data::Bool(v) => v.resize(v.len() + count, false),
            Data::I64(v) => v.resize(v.len() + count, -1),
            Data::Str(v) | Data::Json(v) => v.resize(v.len() + count, 0),
        }
    }

    pub(super) fn empty_like(&self, capacity: usize) -> Data {
        match self {
            Data::Null(_) => Data::Null(0),
            Data::F64(_) => Data::F64(Vec::with_capacity(capacity)),
            Data::Bool(_) => Data::Bool(Vec::with_capacity(capacity)),
            Data::I64(_) => Data::I64(Vec::with_capacity(capacity)),
            Data::Str(_) => Data::Str(Vec::with_capacity(capacity)),
            Data::Json(_) => Data::Json(Vec::with_capacity(capacity)),
        }
    }

    pub(super) fn reserve(&mut self, more: usize) {
        match self {
            Data::Null(_) => {}
            Data::F64(v) => v.reserve(more),
            Data::Bool(v) => v.reserve(more),
            Data::I64(v) => v.reserve(more),
            Data::Str(v) | Data::Json(v) => v.reserve(more),
        }
    }

    pub(super) fn kind(&self) -> &'static str {
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
pub(super) struct Table {
    pub(super) codes: HashMap<String, u32>,
    pub(super) values: Vec<String>,
}

impl Table {
    pub(super) fn code(&mut self, s: &str) -> u32 {
        if let Some(&c) = self.codes.get(s) {
            return c;
        }
        self.values.push(s.to_string());
        let c = self.values.len() as u32;
        self.codes.insert(s.to_string(), c);
        c
    }
}

pub(super) struct Column {
    pub(super) name: Cow<'static, str>,
    pub(super) data: Data,
    /// The last string code written (a cheap repeat check).
    pub(super) last: u32,
}

/// Whether two column names are equal (a field's name is a `&'static str`, so
/// the same pointer is the common case).
#[inline]
pub(super) fn same_name(a: &str, b: &str) -> bool {
    (a.as_ptr() == b.as_ptr() && a.len() == b.len()) || a == b
}

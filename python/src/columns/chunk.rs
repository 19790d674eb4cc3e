//! [`Columns`]: the columns of one chunk of records, written row by row by the
//! serializer (`serializer.rs`): scalars into typed columns, strings as codes,
//! lists and maps flattened, tallied or stored whole (the module doc).

use super::data::{same_name, Column, Data, Table};
use super::reasons::{split_numbers, templated};
use super::Warnings;
use serde::ser;
#[cfg(test)]
use serde::Serialize;
use serde_json::Value;
use std::borrow::Cow;
use std::fmt;

/// Serialization can fail only on a type mismatch between rows (a bug).
#[derive(Debug)]
pub struct Error(pub(super) String);

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

/// The columns of one chunk of records.
#[derive(Default)]
pub struct Columns {
    pub(super) columns: Vec<Column>,
    pub(super) strings: Table,
    pub(super) json: Table,
    pub(super) rows: usize,
    pub(super) hint: usize,
    /// The warnings of the chunk's records.
    pub warnings: Warnings,
    /// The flat index of the chunk's first row (for the warning tally).
    pub offset: usize,
    /// Per row: false where the element failed.
    pub(super) valid: Vec<bool>,
    /// Rows expected (room reserved when a column gets its type).
    pub(super) capacity: usize,
}

/// Marks a list or map value, which is stored as a whole (see the module doc).
pub(super) const COMPOUND: &str = "\u{0}compound";

pub(super) enum Scalar<'a> {
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

    /// Appends an empty row (a failed element).
    pub fn push_missing(&mut self) {
        self.valid.push(false);
        self.end_row();
    }

    pub(super) fn end_row(&mut self) {
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

    pub(super) fn put(&mut self, name: Cow<'static, str>, value: Scalar<'_>) -> Result<(), Error> {
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
    pub(super) fn compound(&mut self, key: Cow<'static, str>, value: Value) -> Result<(), Error> {
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

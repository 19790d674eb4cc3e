//! [`Sink`]: the columns of a whole batch, filled as its chunks finish, and
//! [`Merge`], a column of the whole batch.

use super::codes::Codes;
use super::data::{same_name, Data, Table};
use super::{Columns, Merged, Warnings};
use std::borrow::Cow;
use std::sync::Mutex;

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

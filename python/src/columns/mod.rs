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

//!
//! One file a concern: `data` (the column types and the string table), `chunk`
//! (the columns of one chunk, written row by row), `serializer` (the
//! `serde::Serializer` that writes them), `reasons` (strings stored as a template
//! and numbers), `warnings` (the warning tally), `sink` (the columns of a whole
//! batch, filled as chunks finish), `codes` (a merged column's codes, as narrow as
//! they fit), `merged` (the whole batch as numpy arrays), `split` (records split
//! into a shared part and each element's own fields), `alloc` (numpy-allocated
//! output arrays).

mod alloc;
mod chunk;
mod codes;
mod data;
mod merged;
mod reasons;
mod serializer;
mod sink;
mod split;
mod warnings;

pub use alloc::{numpy_zeros, Fresh};
#[cfg(test)]
pub use chunk::field_names;
pub use chunk::Error;
pub use chunk::{shared_rows, Columns};
pub use merged::Merged;
pub use sink::Sink;
pub use split::{split_into_py, OwnFields, OwnKind, NO_RECORD};
pub use warnings::Warnings;

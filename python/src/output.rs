//! The two shapes of a batch's output: `K` float64 arrays filled in place, or the
//! columns of a record per element ([`crate::columns`]); both return the failure
//! count and the warning tally to the Python layer.

use crate::batch::{chunks_of, run, Chunk, Options, Report, Stop, CHUNK};
use crate::columns::{
    numpy_zeros, shared_rows, split_into_py, Columns, Fresh, OwnFields, OwnKind, Sink, Warnings,
    NO_RECORD,
};
use crate::failure::Failure;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use serde::Serialize;
use std::collections::HashMap;
use std::mem::MaybeUninit;

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

/// The index `flat` in an array of shape `shape`, as numpy prints it (None for a
/// scalar call).
pub fn index_text(flat: usize, shape: &[usize]) -> Option<String> {
    match shape.len() {
        0 => None,
        1 => Some(format!("{flat}")),
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
            Some(format!("({})", parts.join(", ")))
        }
    }
}

/// The batch context of one call: the flat inputs' length, the broadcast shape
/// (for error indices) and the options.
pub struct Call<'s> {
    /// Elements.
    pub n: usize,
    /// Broadcast shape (empty for a scalar call).
    pub shape: &'s [usize],
    /// errors= and threads=.
    pub options: Options,
}

impl Call<'_> {
    /// Slices of the flat inputs, each of length 1 or `n`.
    pub fn columns<'a>(
        &self,
        arrays: &[(&str, &'a PyReadonlyArray1<'_, f64>)],
    ) -> PyResult<Vec<Col<'a>>> {
        let mut out = Vec::with_capacity(arrays.len());
        for (name, a) in arrays {
            let s = a
                .as_slice()
                .map_err(|e| Failure::input(format!("{name}: {e}")).into_pyerr_static())?;
            if s.len() != 1 && s.len() != self.n {
                return Err(Failure::input(format!(
                    "{name}: length {} does not match the batch length {}",
                    s.len(),
                    self.n
                ))
                .into_pyerr_static());
            }
            out.push(Col(s));
        }
        Ok(out)
    }

    fn stop(&self, py: Python<'_>, s: Stop) -> PyErr {
        s.into_pyerr(py, |i| index_text(i, self.shape))
    }

    fn report<'py>(
        &self,
        py: Python<'py>,
        report: Report,
        warnings: &Warnings,
    ) -> PyResult<Bound<'py, PyTuple>> {
        warnings.emit(py, self.n, |i| {
            index_text(i, self.shape).unwrap_or_default()
        })?;
        let first = report.first.map(|(i, f)| {
            let at = index_text(i, self.shape).map(|t| format!(" (at index {t})"));
            format!("{}{}", f.message, at.unwrap_or_default())
        });
        PyTuple::new(
            py,
            [
                report.failed.into_pyobject(py)?.into_any(),
                first.into_pyobject(py)?.into_any(),
            ],
        )
    }

    /// `f(i)` → `K` floats per element, in `K` float64 arrays (NaN where an
    /// element failed); returns `(arrays, (failed, first message))`.
    pub fn floats<'py, const K: usize>(
        &self,
        py: Python<'py>,
        f: impl Fn(usize) -> Result<[f64; K], Failure> + Sync,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let mut outs: Vec<Vec<f64>> = (0..K).map(|_| vec![f64::NAN; self.n]).collect();
        let k_chunks = chunks_of(self.n, CHUNK);
        let mut iters: Vec<_> = outs.iter_mut().map(|v| v.chunks_mut(CHUNK)).collect();
        let slices: Vec<Vec<&mut [f64]>> = (0..k_chunks)
            .map(|_| {
                iters
                    .iter_mut()
                    .map(|it| it.next().unwrap_or_default())
                    .collect()
            })
            .collect();
        let result = run(py, self.n, CHUNK, slices, self.options, |chunk| {
            chunk.each(
                &f,
                |out, j, v: [f64; K]| {
                    for (k, x) in v.into_iter().enumerate() {
                        out[k][j] = x;
                    }
                },
                |_, _| {},
            )
        });
        drop(iters);
        let report = match result {
            Ok((_, report)) => report,
            Err(s) => return Err(self.stop(py, s)),
        };
        let arrays: Vec<Bound<'py, PyAny>> = outs
            .into_iter()
            .map(|v| PyArray1::from_vec(py, v).into_any())
            .collect();
        let report = self.report(py, report, &Warnings::default())?;
        PyTuple::new(
            py,
            [PyTuple::new(py, arrays)?.into_any(), report.into_any()],
        )
    }

    /// `f(i, columns)` appends one record per element (or fails); returns
    /// `(columns, (failed, first message))`, the columns as [`Merged::into_py`]
    /// gives them. Warnings of the records are emitted through Python's `warnings`.
    ///
    /// [`Merged::into_py`]: crate::columns::Merged::into_py
    pub fn records<'py>(
        &self,
        py: Python<'py>,
        f: impl Fn(usize, &mut Columns) -> Result<(), Failure> + Sync,
    ) -> PyResult<Bound<'py, PyTuple>> {
        self.record_chunks(py, CHUNK, |chunk| {
            let range = chunk.range.clone();
            for i in range {
                if !chunk.go(i) {
                    return;
                }
                let r = crate::batch::guarded(|| f(i, &mut chunk.out));
                if let Err(e) = r {
                    // a failed element leaves an empty row (its partial fields are
                    // overwritten: the row is completed as missing)
                    chunk.out.push_missing();
                    chunk.fail(i, e);
                }
            }
        })
    }
}

impl Call<'_> {
    /// Like [`Call::floats`], with one call of `chunk` per chunk of elements
    /// (which can share work between them); a chunk that fails is redone element
    /// by element with `single` (for the failure of the lowest index, or the NaNs).
    pub fn chunked_floats<'py>(
        &self,
        py: Python<'py>,
        chunk: impl Fn(std::ops::Range<usize>) -> Result<Vec<f64>, (usize, Failure)> + Sync,
        single: impl Fn(usize) -> Result<f64, Failure> + Sync,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let mut out = vec![f64::NAN; self.n];
        let slices: Vec<&mut [f64]> = if self.n == 0 {
            vec![&mut []]
        } else {
            out.chunks_mut(CHUNK).collect()
        };
        let result = run(py, self.n, CHUNK, slices, self.options, |c| {
            let range = c.range.clone();
            if range.is_empty() || !c.go(range.start) {
                return;
            }
            match crate::batch::guarded(|| chunk(range.clone()).map_err(|(_, f)| f)) {
                Ok(v) => c.out.copy_from_slice(&v),
                Err(_) => c.each(
                    |i| single(i).map(|x| [x]),
                    |o, j, v: [f64; 1]| o[j] = v[0],
                    |_, _| {},
                ),
            }
        });
        let report = match result {
            Ok((_, report)) => report,
            Err(s) => return Err(self.stop(py, s)),
        };
        let report = self.report(py, report, &Warnings::default())?;
        let arrays = PyTuple::new(py, [PyArray1::from_vec(py, out).into_any()])?;
        PyTuple::new(py, [arrays.into_any(), report.into_any()])
    }

    /// Like [`Call::records`], with one call of `chunk` per [`RECORDS_PER_CALL`]
    /// elements returning each element's result (which can share work between
    /// them); `put` appends a result as a row. The results of one call are all
    /// that is held besides the columns.
    pub fn chunked_records<'py, T>(
        &self,
        py: Python<'py>,
        chunk: impl Fn(std::ops::Range<usize>) -> Vec<Result<T, Failure>> + Sync,
        put: impl Fn(&mut Columns, T) -> Result<(), Failure> + Sync,
    ) -> PyResult<Bound<'py, PyTuple>> {
        self.record_chunks(py, RECORD_CHUNK, |c| {
            let whole = c.range.clone();
            for start in whole.clone().step_by(RECORDS_PER_CALL) {
                let range = start..(start + RECORDS_PER_CALL).min(whole.end);
                if !c.go(range.start) {
                    return;
                }
                let results = match crate::batch::guarded(|| Ok(chunk(range.clone()))) {
                    Ok(r) => r,
                    Err(f) => {
                        c.fail(range.start, f);
                        return;
                    }
                };
                for (i, r) in range.zip(results) {
                    if !c.go(i) {
                        return;
                    }
                    match r.and_then(|t| put(&mut c.out, t)) {
                        Ok(()) => {}
                        Err(f) => {
                            c.out.push_missing();
                            c.fail(i, f);
                        }
                    }
                }
            }
        })
    }
}

/// Elements per call of [`Call::chunked_records`]'s `chunk`: enough to share its
/// set-up (a scene's models), few enough that the records held at once (a
/// scene's outcome is about 2 kB, so 32 kB per thread) stay small: a sweep of
/// 10⁴ speeds held about 480 kB more per worker thread at 256 per call, 230 kB
/// at 64, with the same time at 16 (the scene's models are built once, cached).
pub const RECORDS_PER_CALL: usize = 16;

/// Rows per chunk of [`Call::chunked_records`]: each chunk's rows wait in a
/// chunk of columns until the chunk is done, so this bounds the memory held
/// besides the outputs (a scene's outcome has about 30 columns, 245 bytes a row:
/// 63 kB per chunk in work), which at [`CHUNK`] rows was 1 MB per thread, the
/// fixed cost that dominated a sweep of 10⁴ points.
pub const RECORD_CHUNK: usize = 256;

impl Call<'_> {
    /// Runs `work` on every chunk of `rows` rows (each chunk's `out` starts
    /// empty), each finished chunk copied into the batch's columns at once
    /// ([`Sink`]); returns `(columns, (failed, first message))`, the warnings
    /// emitted.
    fn record_chunks<'py>(
        &self,
        py: Python<'py>,
        rows: usize,
        work: impl Fn(&mut Chunk<'_, Columns>) + Sync,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let k_chunks = chunks_of(self.n, rows);
        let outs: Vec<Columns> = (0..k_chunks)
            .map(|c| {
                let mut cols = Columns::at(c * rows);
                cols.reserve(rows.min(self.n.saturating_sub(c * rows)));
                cols
            })
            .collect();
        let sink = Sink::new(self.n);
        let result = run(py, self.n, rows, outs, self.options, |chunk| {
            work(chunk);
            sink.absorb(std::mem::take(&mut chunk.out));
        });
        let report = match result {
            Ok((_, report)) => report,
            Err(s) => return Err(self.stop(py, s)),
        };
        let valid = self.options.errors == crate::batch::Errors::Nan;
        let (merged, warnings) = py.detach(|| sink.finish(valid));
        let report = self.report(py, report, &warnings)?;
        let dict: Bound<'py, PyDict> = merged.into_py(py)?;
        PyTuple::new(py, [dict.into_any(), report.into_any()])
    }

    /// Like [`Call::records`] for a model whose record splits into a part shared
    /// by the elements with equal `key` and fields of each element's own (the
    /// impact speed's, say), written straight into the output columns: per chunk,
    /// `prepare(i)` runs once per distinct key (`same(i, j)` recognises an element
    /// that shares the previous one's key without building it) and each element
    /// stores the code of its prepared part and, from `own(&prepared, i, near)`
    /// (`None`: no fields of its own, NaN; `near`: a warm start, the own fields
    /// of the last element before it in its run of the chunk (a chunk is
    /// [`LANES`] contiguous runs, visited in turn) that had them, when it shares
    /// the prepared part), its [`OwnFields`] by position. The shared
    /// records are serialized once each, at the end, and gathered by code.
    #[allow(clippy::too_many_arguments)]
    pub fn split_columns<'py, P, R, V>(
        &self,
        py: Python<'py>,
        same: impl Fn(usize, usize) -> bool + Sync,
        key: impl Fn(usize) -> Vec<u64> + Sync,
        prepare: impl Fn(usize) -> Result<P, Failure> + Sync,
        record: impl Fn(&P) -> &R,
        own: impl Fn(&P, usize, Option<&V>) -> Result<Option<V>, Failure> + Sync,
    ) -> PyResult<Bound<'py, PyTuple>>
    where
        P: Send,
        R: Serialize,
        V: OwnFields + Copy,
    {
        let internal = |e: crate::columns::Error| Failure {
            kind: crate::failure::Kind::Internal,
            message: e.to_string(),
        };
        let k = V::FIELDS.len();
        let n = self.n;
        // the output columns are numpy's from the start (huge pages, no copy at
        // the end); every row is written, NaN/false where the element failed
        let mut codes = vec![0u32; n];
        let valid_array = numpy_zeros::<bool>(py, n);
        // written in full: every element that runs, and those that do not
        // after the batch (NaN, false)
        let mut own_arrays: Vec<OwnArray<'py>> = V::FIELDS
            .iter()
            .map(|(_, kind)| match kind {
                OwnKind::Float => OwnArray::Float(Fresh::new(py, n)),
                OwnKind::Bool => OwnArray::Bool(Fresh::new(py, n)),
            })
            .collect();
        let mut valid_guard = valid_array.readwrite();
        let not_contiguous =
            |e: numpy::AsSliceError| pyo3::exceptions::PyRuntimeError::new_err(e.to_string());
        let outs: Vec<SplitChunk<'_, P>> = {
            let mut codes_it = codes.chunks_mut(CHUNK);
            let mut valid_it = valid_guard
                .as_slice_mut()
                .map_err(not_contiguous)?
                .chunks_mut(CHUNK);
            let mut own_its: Vec<OwnChunks<'_>> = own_arrays
                .iter_mut()
                .map(|a| match a {
                    OwnArray::Float(a) => OwnChunks::Float(a.slots().chunks_mut(CHUNK)),
                    OwnArray::Bool(a) => OwnChunks::Bool(a.slots().chunks_mut(CHUNK)),
                })
                .collect();
            (0..chunks_of(n, CHUNK))
                .map(|_| SplitChunk {
                    codes: codes_it.next().unwrap_or_default(),
                    valid: valid_it.next().unwrap_or_default(),
                    own: own_its.iter_mut().map(OwnChunks::next).collect(),
                    prepared: Vec::new(),
                })
                .collect()
        };
        let result = run(py, n, CHUNK, outs, self.options, |chunk| {
            let range = chunk.range.clone();
            let mut by_key: HashMap<Vec<u64>, Result<u32, Failure>> = HashMap::new();
            let mut row = vec![f64::NAN; k];
            // the chunk in LANES contiguous runs, visited in turn (element k of
            // each run, then element k + 1): each run warm-starts from its own
            // previous element, its neighbour, and the runs do not wait on one
            // another, so the processor overlaps their root searches
            let run_len = range.len().div_ceil(LANES);
            let mut lanes: [Lane<V>; LANES] = std::array::from_fn(|_| Lane {
                last: None,
                near: None,
            });
            for step in 0..run_len {
                for (l, lane) in lanes.iter_mut().enumerate() {
                    let i = range.start + l * run_len + step;
                    if i >= range.end || !chunk.go(i) {
                        continue;
                    }
                    let prepared = &mut chunk.out.prepared;
                    let code = match &lane.last {
                        Some((j, Ok(c))) if same(i, *j) => Ok(*c),
                        Some((j, r)) if same(i, *j) => r.clone(),
                        _ => by_key
                            .entry(key(i))
                            .or_insert_with(|| {
                                let p = crate::batch::guarded(|| prepare(i))?;
                                prepared.push(p);
                                Ok(prepared.len() as u32 - 1)
                            })
                            .clone(),
                    };
                    let values = match code {
                        Ok(c) => {
                            let p = &chunk.out.prepared[c as usize];
                            let previous = lane
                                .near
                                .as_ref()
                                .filter(|(pc, _)| *pc == c)
                                .map(|(_, v)| v);
                            crate::batch::guarded(|| own(p, i, previous)).map(|v| (c, v))
                        }
                        Err(ref f) => Err(f.clone()),
                    };
                    lane.last = Some((i, code));
                    let j = i - range.start;
                    let out = &mut chunk.out;
                    match values {
                        Ok((c, v)) => {
                            out.codes[j] = c;
                            out.valid[j] = true;
                            if let Some(v) = v {
                                v.write(&mut row);
                                lane.near = Some((c, v));
                            } else {
                                row.fill(f64::NAN);
                            }
                            for (col, x) in out.own.iter_mut().zip(&row) {
                                col.set(j, *x);
                            }
                        }
                        Err(f) => {
                            for col in out.own.iter_mut() {
                                col.set(j, f64::NAN);
                            }
                            chunk.fail(i, f)
                        }
                    }
                }
            }
        });
        let (outs, report) = match result {
            Ok(r) => r,
            Err(s) => return Err(self.stop(py, s)),
        };
        // the shared records, serialized once each; chunk codes made global
        let mut shared = Columns::default();
        for mut out in outs {
            let base = shared_rows(&shared);
            for p in &out.prepared {
                shared
                    .push(record(p))
                    .map_err(|e| internal(e).into_pyerr(py, None))?;
            }
            for (j, (c, ok)) in out.codes.iter_mut().zip(out.valid.iter()).enumerate() {
                if *ok {
                    *c += base;
                } else {
                    // failed, or did not run (after a panic elsewhere in nan mode)
                    *c = NO_RECORD;
                    for col in out.own.iter_mut() {
                        col.set(j, f64::NAN);
                    }
                }
            }
        }
        // the columns are written: their borrows end before Python sees them
        drop(valid_guard);
        let with_valid = self.options.errors == crate::batch::Errors::Nan;
        let own: Vec<(&'static str, Bound<'py, PyAny>)> = V::FIELDS
            .iter()
            .zip(own_arrays)
            .map(|(&(name, _), a)| (name, a.into_any()))
            .collect();
        let dict = split_into_py(
            py,
            shared,
            &codes,
            own,
            with_valid.then(|| valid_array.into_any()),
            self.options.threads,
        )?;
        drop(codes);
        let report = self.report(py, report, &Warnings::default())?;
        PyTuple::new(py, [dict.into_any(), report.into_any()])
    }
}

/// Runs of a chunk of [`Call::split_columns`] visited in turn (see there).
const LANES: usize = 4;

/// The state of one run of a chunk of [`Call::split_columns`]: its previous
/// element and that element's prepared code, and its last own fields with their
/// code (the warm start).
struct Lane<V> {
    last: Option<(usize, Result<u32, Failure>)>,
    near: Option<(u32, V)>,
}

/// An own output column of [`Call::split_columns`].
enum OwnArray<'py> {
    Float(Fresh<'py, f64>),
    Bool(Fresh<'py, bool>),
}

impl<'py> OwnArray<'py> {
    /// The array, once every element is written.
    fn into_any(self) -> Bound<'py, PyAny> {
        match self {
            OwnArray::Float(a) => a.into_array().into_any(),
            OwnArray::Bool(a) => a.into_array().into_any(),
        }
    }
}

/// The chunks of an own output column.
enum OwnChunks<'a> {
    Float(std::slice::ChunksMut<'a, MaybeUninit<f64>>),
    Bool(std::slice::ChunksMut<'a, MaybeUninit<bool>>),
}

impl<'a> OwnChunks<'a> {
    fn next(&mut self) -> OwnSlice<'a> {
        match self {
            OwnChunks::Float(it) => OwnSlice::Float(it.next().unwrap_or_default()),
            OwnChunks::Bool(it) => OwnSlice::Bool(it.next().unwrap_or_default()),
        }
    }
}

/// One chunk of an own output column (a bool column takes 1.0 as true).
enum OwnSlice<'a> {
    Float(&'a mut [MaybeUninit<f64>]),
    Bool(&'a mut [MaybeUninit<bool>]),
}

impl OwnSlice<'_> {
    #[inline]
    fn set(&mut self, j: usize, x: f64) {
        match self {
            OwnSlice::Float(s) => {
                s[j].write(x);
            }
            OwnSlice::Bool(s) => {
                s[j].write(x == 1.0);
            }
        }
    }
}

/// One chunk's slices of the outputs of [`Call::split_columns`] and its prepared
/// parts.
struct SplitChunk<'a, P> {
    codes: &'a mut [u32],
    valid: &'a mut [bool],
    own: Vec<OwnSlice<'a>>,
    prepared: Vec<P>,
}

/// Appends `record` as a row, a serialization problem being an internal failure.
pub fn push<T: Serialize>(cols: &mut Columns, record: &T) -> Result<(), Failure> {
    cols.push(record).map_err(|e| Failure {
        kind: crate::failure::Kind::Internal,
        message: e.to_string(),
    })
}

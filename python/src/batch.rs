//! The batch engine: elements in chunks on rayon's pool with the GIL released;
//! Ctrl-C checked every 50 ms while the pool works; `errors="raise"` (the failure
//! of the lowest index) or `errors="nan"` (failed elements left empty, counted);
//! `threads=` or `tabor.set_num_threads` (else rayon's global pool, which honours
//! `RAYON_NUM_THREADS`).

use crate::failure::{Failure, Kind};
use pyo3::prelude::*;
use rayon::prelude::*;
use rayon::{ThreadPool, ThreadPoolBuilder};
use std::collections::HashMap;
use std::ops::Range;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::time::Duration;

/// Elements per chunk: small enough that the work spreads over the threads and a
/// cancellation is seen soon, large enough that a chunk's bookkeeping is
/// negligible.
pub const CHUNK: usize = 4096;

/// How often the waiting thread checks for Ctrl-C.
const SIGNAL_INTERVAL: Duration = Duration::from_millis(50);

/// What a batch does with an element that fails.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Errors {
    /// Raise the failure of the lowest index.
    Raise,
    /// Leave the element empty (NaN, None) and count it.
    Nan,
}

/// The values of the keyword `errors=` of every batch (the first is the default;
/// the Python layer and the stubs take them from here, `_tabor.ERRORS`).
pub const ERRORS: [(&str, Errors); 2] = [("raise", Errors::Raise), ("nan", Errors::Nan)];

/// The options every batch takes from Python.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// Failure handling.
    pub errors: Errors,
    /// Threads for this call; `None`: the default pool.
    pub threads: Option<usize>,
}

impl Options {
    /// From the Python arguments `errors` ("raise" | "nan") and `threads`.
    pub fn new(errors: &str, threads: Option<usize>) -> PyResult<Self> {
        let errors = ERRORS
            .iter()
            .find(|(name, _)| *name == errors)
            .map(|(_, e)| *e)
            .ok_or_else(|| {
                let names: Vec<String> = ERRORS.iter().map(|(n, _)| format!("\"{n}\"")).collect();
                Failure::input(format!(
                    "invalid errors = \"{errors}\": expected {}",
                    names.join(" or ")
                ))
                .into_pyerr_static()
            })?;
        if threads == Some(0) {
            return Err(Failure::input("invalid threads = 0: must be >= 1").into_pyerr_static());
        }
        Ok(Options { errors, threads })
    }
}

impl Failure {
    /// The exception of an argument error raised before any element ran.
    pub fn into_pyerr_static(self) -> PyErr {
        Python::attach(|py| self.into_pyerr(py, None))
    }
}

/// The pools of `threads=` (by size) and the default set by `set_num_threads`.
struct Pools {
    sized: HashMap<usize, Arc<ThreadPool>>,
    default: Option<Arc<ThreadPool>>,
}

static POOLS: Mutex<Option<Pools>> = Mutex::new(None);

/// The most threads a batch may use (checked before any is spawned; the Python
/// layer checks the same ceiling, `tabor._core.MAX_THREADS`).
pub const MAX_THREADS: usize = 1024;

fn pool(threads: Option<usize>) -> Result<Option<Arc<ThreadPool>>, String> {
    let mut guard = POOLS
        .lock()
        .map_err(|_| "thread-pool registry poisoned".to_string())?;
    let pools = guard.get_or_insert_with(|| Pools {
        sized: HashMap::new(),
        default: None,
    });
    let Some(k) = threads else {
        return Ok(pools.default.clone());
    };
    if k == 0 || k > MAX_THREADS {
        return Err(format!(
            "invalid threads = {k}: must be >= 1 and <= {MAX_THREADS}"
        ));
    }
    if let Some(p) = pools.sized.get(&k) {
        return Ok(Some(p.clone()));
    }
    let p = Arc::new(
        ThreadPoolBuilder::new()
            .num_threads(k)
            .build()
            .map_err(|e| e.to_string())?,
    );
    pools.sized.insert(k, p.clone());
    Ok(Some(p))
}

/// Sets the default number of threads of every batch (`None`: rayon's global
/// pool, `RAYON_NUM_THREADS` or the number of cores).
pub fn set_default_threads(threads: Option<usize>) -> Result<(), String> {
    let p = match threads {
        Some(0) => return Err("invalid threads = 0: must be >= 1".into()),
        Some(k) => pool(Some(k))?,
        None => None,
    };
    let mut guard = POOLS
        .lock()
        .map_err(|_| "thread-pool registry poisoned".to_string())?;
    if let Some(pools) = guard.as_mut() {
        pools.default = p;
    }
    Ok(())
}

/// The number of threads a batch uses by default.
pub fn default_threads() -> usize {
    match pool(None) {
        Ok(Some(p)) => p.current_num_threads(),
        _ => rayon::current_num_threads(),
    }
}

/// The shared state of one batch, seen by every element.
pub struct Control {
    errors: Errors,
    cancelled: AtomicBool,
    /// Raise mode: the lowest failing index so far (elements above it are skipped).
    first_failure: AtomicUsize,
}

impl Control {
    /// Whether element `i` should still run.
    #[inline]
    pub fn go(&self, i: usize) -> bool {
        !self.cancelled.load(Ordering::Relaxed) && i < self.first_failure.load(Ordering::Relaxed)
    }
}

/// The failures of one chunk: the first (lowest index) and the count.
#[derive(Default)]
pub struct Failures {
    first: Option<(usize, Failure)>,
    count: usize,
}

impl Failures {
    fn add(&mut self, control: &Control, i: usize, f: Failure) {
        self.count += 1;
        if control.errors == Errors::Raise || f.kind == Kind::Internal {
            control.first_failure.fetch_min(i, Ordering::Relaxed);
        }
        if self.first.as_ref().is_none_or(|(j, _)| i < *j) {
            self.first = Some((i, f));
        }
    }

    fn merge(&mut self, other: Failures) {
        self.count += other.count;
        if let Some((i, f)) = other.first {
            if self.first.as_ref().is_none_or(|(j, _)| i < *j) {
                self.first = Some((i, f));
            }
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

/// Runs element `i` through `f`, a panic becoming an internal failure.
#[inline]
pub fn guarded<T>(f: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(p) => Err(Failure {
            kind: Kind::Internal,
            message: panic_text(p),
        }),
    }
}

/// One chunk of work: the element range and the chunk's output.
pub struct Chunk<'c, O> {
    /// Flat indices of the chunk's elements.
    pub range: Range<usize>,
    /// Where the chunk's results go.
    pub out: O,
    control: &'c Control,
    failures: Failures,
}

impl<O> Chunk<'_, O> {
    /// Runs `f` for every element of the chunk: `Ok` results go to `put(out, j, v)`,
    /// failures to `missing(out, j)` (j is the index within the chunk). Stops early
    /// on cancellation or, in raise mode, past an earlier failure.
    pub fn each<T>(
        &mut self,
        mut f: impl FnMut(usize) -> Result<T, Failure>,
        mut put: impl FnMut(&mut O, usize, T),
        mut missing: impl FnMut(&mut O, usize),
    ) {
        for (j, i) in self.range.clone().enumerate() {
            if !self.control.go(i) {
                return;
            }
            match guarded(|| f(i)) {
                Ok(v) => put(&mut self.out, j, v),
                Err(e) => {
                    missing(&mut self.out, j);
                    self.failures.add(self.control, i, e);
                }
            }
        }
    }

    /// Whether element `i` should still run (for chunks that loop themselves).
    pub fn go(&self, i: usize) -> bool {
        self.control.go(i)
    }

    /// Records the failure of element `i` (for chunks that loop themselves).
    pub fn fail(&mut self, i: usize, f: Failure) {
        self.failures.add(self.control, i, f);
    }
}

/// What a batch reports besides its outputs.
pub struct Report {
    /// Failed elements (nan mode; in raise mode the batch returns the error).
    pub failed: usize,
    /// The first failure (lowest index) in nan mode.
    pub first: Option<(usize, Failure)>,
}

/// Why a batch did not finish.
pub enum Stop {
    /// An element failed (raise mode, or a panic): its index and failure.
    Failed(usize, Failure),
    /// Ctrl-C (or another signal handler raising).
    Interrupted(PyErr),
    /// The pool could not be set up.
    Pool(String),
}

impl Stop {
    /// The Python exception; `index` renders an element index.
    pub fn into_pyerr(self, py: Python<'_>, index: impl Fn(usize) -> Option<String>) -> PyErr {
        match self {
            Stop::Failed(i, f) => f.into_pyerr(py, index(i)),
            Stop::Interrupted(e) => e,
            Stop::Pool(m) => pyo3::exceptions::PyRuntimeError::new_err(m),
        }
    }
}

/// Runs `work` on every chunk of `outs` (one output per chunk of `CHUNK`
/// elements of `0..n`, in order) on the pool, with the GIL released; returns the
/// outputs in order. Checks for Ctrl-C while the pool works.
pub fn run<O, F>(
    py: Python<'_>,
    n: usize,
    chunk: usize,
    outs: Vec<O>,
    options: Options,
    work: F,
) -> Result<(Vec<O>, Report), Stop>
where
    O: Send,
    F: Fn(&mut Chunk<'_, O>) + Sync,
{
    let control = Control {
        errors: options.errors,
        cancelled: AtomicBool::new(false),
        first_failure: AtomicUsize::new(usize::MAX),
    };
    let pool = pool(options.threads).map_err(Stop::Pool)?;
    let chunks: Vec<Chunk<'_, O>> = outs
        .into_iter()
        .enumerate()
        .map(|(c, out)| Chunk {
            range: (c * chunk).min(n)..((c + 1) * chunk).min(n),
            out,
            control: &control,
            failures: Failures::default(),
        })
        .collect();
    let compute = |chunks| compute(chunks, &pool, &work);
    let mut interrupted = None;
    let done: Vec<Chunk<'_, O>> = if chunks.len() <= 1 {
        // one chunk: no watcher thread (a scalar call stays cheap)
        py.detach(|| compute(chunks))
    } else {
        py.detach(|| {
            std::thread::scope(|s| {
                let (tx, rx) = mpsc::channel::<()>();
                let handle = s.spawn(move || {
                    let out = compute(chunks);
                    let _ = tx.send(());
                    out
                });
                while let Err(mpsc::RecvTimeoutError::Timeout) = rx.recv_timeout(SIGNAL_INTERVAL) {
                    if interrupted.is_none() {
                        if let Err(e) = Python::attach(|py| py.check_signals()) {
                            control.cancelled.store(true, Ordering::Relaxed);
                            interrupted = Some(e);
                        }
                    }
                }
                handle.join().ok()
            })
        })
        .ok_or_else(|| Stop::Pool("a worker thread of the batch panicked".into()))?
    };
    if let Some(e) = interrupted {
        return Err(Stop::Interrupted(e));
    }
    let mut failures = Failures::default();
    let mut outs = Vec::with_capacity(done.len());
    for c in done {
        failures.merge(c.failures);
        outs.push(c.out);
    }
    if let Some((i, f)) = failures.first.take() {
        if options.errors == Errors::Raise || f.kind == Kind::Internal {
            return Err(Stop::Failed(i, f));
        }
        failures.first = Some((i, f));
    }
    Ok((
        outs,
        Report {
            failed: failures.count,
            first: failures.first,
        },
    ))
}

fn compute<'c, O, F>(
    chunks: Vec<Chunk<'c, O>>,
    pool: &Option<Arc<ThreadPool>>,
    work: &F,
) -> Vec<Chunk<'c, O>>
where
    O: Send,
    F: Fn(&mut Chunk<'_, O>) + Sync,
{
    let go = || {
        chunks
            .into_par_iter()
            .with_max_len(1)
            .map(|mut c| {
                work(&mut c);
                c
            })
            .collect()
    };
    match pool {
        Some(p) => p.install(go),
        None => go(),
    }
}

/// Runs `f` on the pool of `threads` (`None`: the default pool), for the
/// parallel passes that follow a batch (filling its output columns).
pub fn install<R: Send>(threads: Option<usize>, f: impl FnOnce() -> R + Send) -> Result<R, String> {
    Ok(match pool(threads)? {
        Some(p) => p.install(f),
        None => f(),
    })
}

/// The number of chunks of `n` elements.
pub fn chunks_of(n: usize, chunk: usize) -> usize {
    n.div_ceil(chunk).max(1)
}

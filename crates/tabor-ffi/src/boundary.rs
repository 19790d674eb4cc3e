//! The glue of the C boundary: the thread's last error message, panics caught,
//! owned pointers handed out and freed, and a per-contact step that leaves the
//! history unchanged on error.

use crate::{TABOR_ERR_INVALID, TABOR_ERR_MODEL, TABOR_ERR_PANIC, TABOR_OK};
use std::cell::RefCell;
use std::panic::{catch_unwind, AssertUnwindSafe};

thread_local! {
    pub(crate) static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

pub(crate) fn set_error(message: String) {
    LAST_ERROR.with(|e| *e.borrow_mut() = message);
}

pub(crate) fn status_of(e: &tabor_restitution::Error) -> i32 {
    set_error(e.to_string());
    match e {
        tabor_restitution::Error::InvalidParameter { .. } => TABOR_ERR_INVALID,
        _ => TABOR_ERR_MODEL,
    }
}

/// Runs `f` with panics caught: a panic becomes [`TABOR_ERR_PANIC`].
pub(crate) fn guard(f: impl FnOnce() -> i32) -> i32 {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(status) => status,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_string());
            set_error(format!("panic inside tabor-ffi: {what}"));
            TABOR_ERR_PANIC
        }
    }
}

/// Hands `made` to C as an owned pointer in `*out` (free with [`free_boxed`]), or
/// returns the error's status.
///
/// # Safety
/// `out` non-null and writable.
pub(crate) unsafe fn hand_out<T>(made: tabor_restitution::Result<T>, out: *mut *mut T) -> i32 {
    match made {
        Ok(value) => {
            // SAFETY: non-null and writable per the contract
            unsafe { *out = Box::into_raw(Box::new(value)) };
            TABOR_OK
        }
        Err(e) => status_of(&e),
    }
}

/// Frees a pointer from [`hand_out`]; null is ignored; nothing unwinds.
///
/// # Safety
/// `p` null or from [`hand_out`], not yet freed.
pub(crate) unsafe fn free_boxed<T>(p: *mut T) {
    if p.is_null() {
        return;
    }
    let _ = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: from Box::into_raw in hand_out, freed once per the contract
        drop(unsafe { Box::from_raw(p) });
    }));
}

/// One step of a per-contact evaluation: `step` works on a copy of `*history`;
/// on success the copy and the result are written back, on error `*out` is zeroed,
/// the history left unchanged and the error's status returned.
pub(crate) fn advance<H: Copy, O: Default>(
    history: &mut H,
    out: &mut O,
    step: impl FnOnce(&mut H) -> tabor_restitution::Result<O>,
) -> i32 {
    let mut h = *history;
    match step(&mut h) {
        Ok(o) => {
            *history = h;
            *out = o;
            TABOR_OK
        }
        Err(e) => {
            *out = O::default();
            status_of(&e)
        }
    }
}

/// Records `message` as the last error and returns [`TABOR_ERR_INVALID`]: the
/// status of a boundary check ([`crate::check`]) that failed.
pub(crate) fn refuse(message: String) -> i32 {
    set_error(message);
    TABOR_ERR_INVALID
}

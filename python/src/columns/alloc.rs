//! Output columns allocated by numpy: zeroed ([`numpy_zeros`]) or uninitialized
//! and written in full ([`Fresh`]).

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;

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

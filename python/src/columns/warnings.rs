//! [`Warnings`]: the tally of the records' warnings, emitted once per code.

use pyo3::prelude::*;

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

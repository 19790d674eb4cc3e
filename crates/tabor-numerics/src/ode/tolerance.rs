//! [`OdeTolerance`]: the error norm, tolerances and step limits of every method.

use crate::{NumericsError, Result};

/// Accuracy and limits of an integration. A step is accepted when the embedded
/// error estimate satisfies `|err_i| ≤ absolute + relative · max(|y_i|, |y_i,new|)`
/// in the root-mean-square norm over the components (the first
/// [`OdeTolerance::error_components`] of them, when given).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdeTolerance {
    /// Relative tolerance (≥ 1e-15 after raising; must be finite and ≥ 0).
    pub relative: f64,
    /// Absolute tolerance (finite, ≥ 0; relative and absolute may not both be 0).
    pub absolute: f64,
    /// Limit on the number of steps (accepted plus rejected).
    pub max_steps: u64,
    /// Largest step allowed (> 0, may be infinite).
    pub max_step: f64,
    /// First trial step; `None` chooses it automatically (Hairer's `HINIT`).
    pub initial_step: Option<f64>,
    /// The number of leading components the error norm (and `HINIT`) covers;
    /// `None`: all. The components after them are integrated with the same
    /// steps but do not choose them: quadratures `w' = p(t, y)` of quantities of
    /// the state (a work, a dissipated energy) that the motion's steps resolve
    /// and that should not shorten them.
    pub error_components: Option<usize>,
}

impl OdeTolerance {
    /// Relative tolerance `relative`, absolute tolerance `absolute`, at most one
    /// million steps, no step limit, automatic first step.
    pub fn new(relative: f64, absolute: f64) -> Self {
        OdeTolerance {
            relative,
            absolute,
            max_steps: 1_000_000,
            max_step: f64::INFINITY,
            initial_step: None,
            error_components: None,
        }
    }

    /// The same tolerance with the error norm over the first `components`
    /// components only ([`OdeTolerance::error_components`]).
    pub fn with_error_components(mut self, components: usize) -> Self {
        self.error_components = Some(components);
        self
    }

    /// The same tolerance with a largest step `max_step`.
    pub fn with_max_step(mut self, max_step: f64) -> Self {
        self.max_step = max_step;
        self
    }

    /// The same tolerance with at most `max_steps` steps.
    pub fn with_max_steps(mut self, max_steps: u64) -> Self {
        self.max_steps = max_steps;
        self
    }

    pub(crate) fn validate(&self) -> Result<()> {
        let check = |name: &'static str, v: f64| {
            if v.is_finite() && v >= 0.0 {
                Ok(())
            } else {
                Err(NumericsError::InvalidArgument {
                    name,
                    value: v,
                    requirement: "must be finite and >= 0",
                })
            }
        };
        check("relative tolerance", self.relative)?;
        check("absolute tolerance", self.absolute)?;
        if self.relative == 0.0 && self.absolute == 0.0 {
            return Err(NumericsError::InvalidArgument {
                name: "absolute tolerance",
                value: 0.0,
                requirement: "relative and absolute tolerance may not both be 0",
            });
        }
        if self.max_step.is_nan() || self.max_step <= 0.0 {
            return Err(NumericsError::InvalidArgument {
                name: "max_step",
                value: self.max_step,
                requirement: "must be > 0",
            });
        }
        if self.max_steps == 0 {
            return Err(NumericsError::InvalidArgument {
                name: "max_steps",
                value: 0.0,
                requirement: "must be at least 1",
            });
        }
        if self.error_components == Some(0) {
            return Err(NumericsError::InvalidArgument {
                name: "error_components",
                value: 0.0,
                requirement: "must be at least 1",
            });
        }
        if let Some(h) = self.initial_step {
            if !(h.is_finite() && h > 0.0) {
                return Err(NumericsError::InvalidArgument {
                    name: "initial_step",
                    value: h,
                    requirement: "must be finite and > 0",
                });
            }
        }
        Ok(())
    }

    /// The error scale of a component that was `a` before and `b` after a step.
    pub(crate) fn error_scale(&self, a: f64, b: f64) -> f64 {
        self.absolute + self.relative_effective() * a.abs().max(b.abs())
    }

    /// The number of components of a state of `n` that the error norm covers.
    pub(crate) fn controlled(&self, n: usize) -> usize {
        self.error_components.map_or(n, |m| m.min(n)).max(1).min(n)
    }

    pub(crate) fn relative_effective(&self) -> f64 {
        self.relative.max(crate::tolerance::FINEST_TOLERANCE)
    }
}

impl Default for OdeTolerance {
    /// `relative` = [`ODE_TOLERANCE`](crate::tolerance::ODE_TOLERANCE) (1e-11),
    /// `absolute` = [`ODE_ABSOLUTE_TOLERANCE`](crate::tolerance::ODE_ABSOLUTE_TOLERANCE)
    /// (1e-13): the default of every simulated impact
    /// (`tabor_dynamics::SimulationSettings::default`).
    fn default() -> Self {
        OdeTolerance::new(
            crate::tolerance::ODE_TOLERANCE,
            crate::tolerance::ODE_ABSOLUTE_TOLERANCE,
        )
    }
}

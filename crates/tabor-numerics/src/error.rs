use thiserror::Error;

/// Why a numerical routine could not deliver a finite, converged value.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum NumericsError {
    /// The function has the same sign at both ends of the interval (after any
    /// allowed expansion), so the interval does not bracket a root.
    #[error("no root bracketed: f({lower:e}) = {f_lower:e} and f({upper:e}) = {f_upper:e} have the same sign")]
    NoBracket {
        /// Lower end of the last interval tried.
        lower: f64,
        /// Upper end of the last interval tried.
        upper: f64,
        /// Function value at `lower`.
        f_lower: f64,
        /// Function value at `upper`.
        f_upper: f64,
    },
    /// The iteration limit was reached before the tolerance was met.
    #[error("{method} did not converge in {iterations} iterations (estimate {estimate:e}, error estimate {error:e})")]
    NoConvergence {
        /// The algorithm that gave up.
        method: &'static str,
        /// Iterations (or refinement levels) spent.
        iterations: u64,
        /// The last estimate of the answer.
        estimate: f64,
        /// The error estimate of that answer.
        error: f64,
    },
    /// The function returned NaN or an infinity.
    #[error("the function returned the non-finite value {value} at x = {at:e}")]
    NonFinite {
        /// Where the function was evaluated.
        at: f64,
        /// What it returned.
        value: f64,
    },
    /// An argument is outside the domain of the routine.
    #[error("invalid argument {name} = {value:e}: {requirement}")]
    InvalidArgument {
        /// Name of the argument.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What it must satisfy.
        requirement: &'static str,
    },
}

/// Checks that `value` is finite, else returns [`NumericsError::InvalidArgument`].
pub(crate) fn require_finite(name: &'static str, value: f64) -> Result<f64, NumericsError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(NumericsError::InvalidArgument {
            name,
            value,
            requirement: "must be finite",
        })
    }
}

/// Checks that an absolute and a relative tolerance are finite and ≥ 0.
pub(crate) fn require_tolerances(absolute: f64, relative: f64) -> Result<(), NumericsError> {
    for (name, value) in [
        ("absolute tolerance", absolute),
        ("relative tolerance", relative),
    ] {
        if !(value >= 0.0 && value.is_finite()) {
            return Err(NumericsError::InvalidArgument {
                name,
                value,
                requirement: "must be finite and >= 0",
            });
        }
    }
    Ok(())
}

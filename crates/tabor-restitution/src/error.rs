use tabor_numerics::NumericsError;
use thiserror::Error;

/// Why a tabor computation failed: bad input (named, with its value), a numerical
/// failure, or a model outside its domain.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum Error {
    /// A parameter is outside its physical or mathematical domain.
    #[error("invalid {parameter} = {}: {requirement}", tabor_numerics::readable::plain(*.value))]
    InvalidParameter {
        /// The parameter's name, as the public API spells it.
        parameter: &'static str,
        /// The value given.
        value: f64,
        /// What it must satisfy.
        requirement: &'static str,
    },
    /// The numerical layer could not deliver a converged, finite value.
    #[error("numerical failure: {0}")]
    Numerics(#[from] NumericsError),
    /// A model cannot answer for this input (outside its domain of validity).
    #[error("{model}: {message}")]
    Model {
        /// The model's name.
        model: &'static str,
        /// What went wrong.
        message: String,
    },
}

impl Error {
    /// Shorthand for [`Error::InvalidParameter`].
    pub fn invalid(parameter: &'static str, value: f64, requirement: &'static str) -> Self {
        Error::InvalidParameter {
            parameter,
            value,
            requirement,
        }
    }
}

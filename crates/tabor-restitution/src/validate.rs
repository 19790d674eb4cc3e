//! Input checks shared by all models. Each returns the value when it is valid and an
//! [`Error::InvalidParameter`] naming the parameter and its value otherwise, so that
//! NaN, infinities, zeros and negative values never reach a formula.
//!
//! And the output checks ([`finite_output`], [`positive_output`]): a computed value
//! that overflows or underflows for valid but extreme inputs becomes an
//! [`Error::Model`] naming the model and the quantity, never a NaN or ∞ result.

use crate::{Error, Result};

/// A finite value (any sign).
pub fn finite(parameter: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::invalid(parameter, value, "must be finite"))
    }
}

/// A finite value > 0.
pub fn positive(parameter: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::invalid(parameter, value, "must be finite and > 0"))
    }
}

/// A finite value ≥ 0.
pub fn non_negative(parameter: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::invalid(parameter, value, "must be finite and >= 0"))
    }
}

/// A finite value in the open interval (lower, upper).
pub fn in_open_interval(
    parameter: &'static str,
    value: f64,
    lower: f64,
    upper: f64,
    requirement: &'static str,
) -> Result<f64> {
    if value.is_finite() && value > lower && value < upper {
        Ok(value)
    } else {
        Err(Error::invalid(parameter, value, requirement))
    }
}

/// A Poisson's ratio, −1 < ν ≤ 1/2.
pub fn poisson_ratio(parameter: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > -1.0 && value <= 0.5 {
        Ok(value)
    } else {
        Err(Error::invalid(
            parameter,
            value,
            "must satisfy -1 < nu <= 0.5",
        ))
    }
}

/// A relative tolerance, 1e-15 ≤ tol ≤ 0.5.
pub fn tolerance(parameter: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && (1e-15..=0.5).contains(&value) {
        Ok(value)
    } else {
        Err(Error::invalid(parameter, value, "must lie in [1e-15, 0.5]"))
    }
}

/// A computed value that must be finite, else an [`Error::Model`] naming `model`
/// and the `quantity`.
pub fn finite_output(model: &'static str, quantity: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::Model {
            model,
            message: format!(
                "the {quantity} is not representable ({value:e}) for these parameters"
            ),
        })
    }
}

/// A computed value that must be finite and > 0 (a scale), else an
/// [`Error::Model`] naming `model` and the `quantity`.
pub fn positive_output(model: &'static str, quantity: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::Model {
            model,
            message: format!("the {quantity} under- or overflows ({value:e}) for these parameters"),
        })
    }
}

//! Input checks of this crate beyond `tabor_restitution::validate`.

use tabor_restitution::{Error, Result};

/// A coefficient of restitution ε ∈ (0, 1].
pub(crate) fn restitution(value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 && value <= 1.0 {
        Ok(value)
    } else {
        Err(Error::invalid("restitution", value, "must lie in (0, 1]"))
    }
}

/// A loss speed V > 0; `+∞` is the lossless limit.
pub(crate) fn loss_speed(value: f64) -> Result<f64> {
    if value > 0.0 && !value.is_nan() {
        Ok(value)
    } else {
        Err(Error::invalid(
            "loss_speed",
            value,
            "must be > 0 (+inf for no loss)",
        ))
    }
}

/// A force exponent n ∈ (0, 10].
pub(crate) fn exponent(value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 && value <= 10.0 {
        Ok(value)
    } else {
        Err(Error::invalid("exponent", value, "must lie in (0, 10]"))
    }
}

//! Cancellation-free forms of the three functions that the first integrals of the
//! penalty laws need (private helpers, no physics).

/// `ψ(x) = (x − ln(1 + x)) / x²` for x > −1, with ψ(0) = 1/2.
///
/// The power series `Σ (−x)^k / (k + 2)` below |x| = 0.05 (16 terms: truncation
/// below 1e-22), the direct form above.
pub(crate) fn log_remainder(x: f64) -> f64 {
    if x.abs() < 0.05 {
        let mut sum = 0.0;
        for k in (0..16).rev() {
            sum = sum * (-x) + 1.0 / f64::from(k + 2);
        }
        sum
    } else {
        (1.0 - x.ln_1p() / x) / x
    }
}

/// `ω(z) = (z − 1 + e^(−z)) / z²` for z ≥ 0, with ω(0) = 1/2.
///
/// The power series `Σ (−z)^k / (k + 2)!` below z = 0.05, the direct form above.
pub(crate) fn exp_remainder(z: f64) -> f64 {
    if z.abs() < 0.05 {
        let mut sum = 0.0;
        let mut factorials = [0.0; 14];
        let mut f = 1.0;
        for (k, slot) in factorials.iter_mut().enumerate() {
            // (k + 2)!
            f *= if k == 0 { 2.0 } else { (k + 2) as f64 };
            *slot = f;
        }
        for k in (0..14).rev() {
            sum = sum * (-z) + 1.0 / factorials[k];
        }
        sum
    } else {
        (1.0 + (-z).exp_m1() / z) / z
    }
}

/// `q(z) = (1 − e^(−z)) / z` for z ≥ 0, with q(0) = 1.
pub(crate) fn exp_ratio(z: f64) -> f64 {
    if z == 0.0 {
        1.0
    } else {
        -(-z).exp_m1() / z
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_and_direct_forms_agree_at_the_switch() {
        for &x in &[0.049_999_999, 0.050_000_001, -0.049_999_999, -0.050_000_001] {
            let direct = (x - f64::ln_1p(x)) / (x * x);
            assert!((log_remainder(x) - direct).abs() < 1e-12, "psi at {x}");
            let z = x.abs();
            let direct = (z - 1.0 + (-z).exp()) / (z * z);
            assert!((exp_remainder(z) - direct).abs() < 1e-12, "omega at {z}");
        }
        assert!((log_remainder(0.0) - 0.5).abs() < 1e-16);
        assert!((exp_remainder(0.0) - 0.5).abs() < 1e-16);
        assert!((exp_ratio(1e-300) - 1.0).abs() < 1e-16);
    }
}

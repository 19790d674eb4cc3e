//! Maugis-Dugdale: the normalized impact loss W(Λ) and the equilibrium curve in
//! Maugis' units.

use crate::convert::{batch, columns};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use std::f64::consts::FRAC_PI_2;
use tabor::maugis::branch::contact_state;
use tabor::maugis::units;
use tabor::numerics::root_finding::{brent, RootTolerance};

/// `a_c / (πΔγR²/K)^(1/3) = (3/2)^(1/3)`: Maugis' contact radius A = (3/2)^(1/3) â.
fn radius_factor() -> f64 {
    1.5f64.cbrt()
}

/// W(Λ) in units of F_n d_n, flat in and out (see `tabor.maugis_dugdale_loss`).
#[pyfunction]
pub fn maugis_dugdale_loss<'py>(
    py: Python<'py>,
    tabor_parameter: PyReadonlyArray1<'py, f64>,
    tolerance: PyReadonlyArray1<'py, f64>,
    fast: bool,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let args = [
        ("tabor_parameter", &tabor_parameter),
        ("tolerance", &tolerance),
    ];
    let (c, n) = columns(&args)?;
    let (lambda, tol) = (c[0], c[1]);
    let w_jkr = tabor::maugis::jkr_normalized_loss();
    let out = if fast {
        batch(py, n, &shape, |i| {
            tabor::maugis::loss_over_jkr_fast(lambda.at(i))
                .map(|r| r * w_jkr)
                .map_err(|e| e.to_string())
        })?
    } else {
        batch(py, n, &shape, |i| {
            tabor::maugis::normalized_loss(lambda.at(i), tol.at(i))
                .map(|w| w.loss)
                .map_err(|e| e.to_string())
        })?
    };
    Ok(PyArray1::from_vec(py, out))
}

/// Load and penetration in Maugis' units at Maugis parameter λ and contact radius A.
fn curve_point(maugis_parameter: f64, contact_radius: f64) -> Result<(f64, f64), String> {
    let lambda = units::tabor_parameter_from_maugis(maugis_parameter).map_err(|e| e.to_string())?;
    if !(contact_radius.is_finite() && contact_radius >= 0.0) {
        return Err(format!(
            "invalid contact_radius = {contact_radius}: must be finite and non-negative"
        ));
    }
    let a_hat = contact_radius / radius_factor();
    let theta = if a_hat == 0.0 {
        FRAC_PI_2
    } else {
        // â(θ) falls monotonically from +∞ (θ → 0) to 0 (θ = π/2): bracket from below
        let f = |t: f64| contact_state(lambda, t).contact_radius - a_hat;
        let mut lo = 0.5;
        while f(lo) <= 0.0 {
            lo *= 0.125;
            if lo < 1e-300 {
                return Err(format!(
                    "invalid contact_radius = {contact_radius}: too large for maugis_parameter = {maugis_parameter}"
                ));
            }
        }
        let hi = FRAC_PI_2;
        if f(hi) >= 0.0 {
            hi
        } else {
            brent(f, lo, hi, RootTolerance::relative(0.0))
                .map_err(|e| e.to_string())?
                .value
        }
    };
    let s = contact_state(lambda, theta);
    // F̂ = F/F_n with F_n = (3/2)πΔγR; d̂ = d/d_n with d_n = (3/2)^(2/3)/3 (π²Δγ²R/K²)^(1/3)
    let load = 1.5 * s.force;
    let penetration = s.depth * radius_factor() * radius_factor() / 3.0;
    if !(load.is_finite() && penetration.is_finite()) {
        return Err(format!(
            "invalid contact_radius = {contact_radius}: load or penetration overflows for maugis_parameter = {maugis_parameter}"
        ));
    }
    Ok((load, penetration))
}

/// (load, penetration) in Maugis' units, flat in and out (see
/// `tabor.maugis_dugdale_curve`).
#[pyfunction]
#[allow(clippy::type_complexity)]
pub fn maugis_dugdale_curve<'py>(
    py: Python<'py>,
    maugis_parameter: PyReadonlyArray1<'py, f64>,
    contact_radius: PyReadonlyArray1<'py, f64>,
    shape: Vec<usize>,
) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>)> {
    let args = [
        ("maugis_parameter", &maugis_parameter),
        ("contact_radius", &contact_radius),
    ];
    let (c, n) = columns(&args)?;
    let points = batch(py, n, &shape, |i| curve_point(c[0].at(i), c[1].at(i)))?;
    let (load, penetration): (Vec<f64>, Vec<f64>) = points.into_iter().unzip();
    Ok((
        PyArray1::from_vec(py, load),
        PyArray1::from_vec(py, penetration),
    ))
}

macro_rules! unary {
    ($name:ident, $f:path, $lib:literal, $arg:literal) => {
        /// Flat element-wise conversion (see the Python function of the same name).
        #[pyfunction]
        pub fn $name<'py>(
            py: Python<'py>,
            x: PyReadonlyArray1<'py, f64>,
            shape: Vec<usize>,
        ) -> PyResult<Bound<'py, PyArray1<f64>>> {
            let args = [($arg, &x)];
            let (c, n) = columns(&args)?;
            let out = batch(py, n, &shape, |i| {
                $f(c[0].at(i)).map_err(|e| e.to_string().replacen($lib, $arg, 1))
            })?;
            Ok(PyArray1::from_vec(py, out))
        }
    };
}

unary!(
    tabor_parameter_from_maugis,
    units::tabor_parameter_from_maugis,
    "maugis_parameter",
    "maugis_parameter"
);
unary!(
    tabor_parameter_from_tabor_mu,
    units::tabor_parameter_from_tabor_mu,
    "tabor_parameter_mu",
    "tabor_mu"
);
unary!(
    maugis_parameter,
    units::maugis_parameter,
    "tabor_parameter",
    "tabor_parameter"
);

/// W_JKR / (F_n d_n), the JKR loss (5.36) in the seed's units.
#[pyfunction]
pub fn jkr_normalized_loss() -> f64 {
    tabor::maugis::jkr_normalized_loss()
}

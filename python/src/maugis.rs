//! Maugis-Dugdale: the normalized impact loss W(Λ), the equilibrium curve in
//! Maugis' units, the conversions between Λ, Maugis' λ and Tabor's μ, and the
//! force-displacement curves of JKR, DMT and Maugis-Dugdale in SI units (the
//! names and argument meanings of ContactEngineering's `Adhesion` package).

use crate::batch::Options;
use crate::failure::{Failure, Kind};
use crate::output::Call;
use numpy::PyReadonlyArray1;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::f64::consts::{FRAC_PI_2, PI};
use tabor::maugis::branch::contact_state;
use tabor::maugis::units;
use tabor::numerics::root_finding::{brent, RootTolerance};

type Arr<'py> = PyReadonlyArray1<'py, f64>;

/// `a_c / (πΔγR²/K)^(1/3) = (3/2)^(1/3)`: Maugis' contact radius A = (3/2)^(1/3) â.
fn radius_factor() -> f64 {
    1.5f64.cbrt()
}

/// Below this Maugis parameter the θ-parametrized branch loses digits (its terms
/// cancel): at λ = 1e-15 the load is off by 1e-8 relative, at 1e-30 by 23 %. The
/// curve is refused there; its DMT limit (`force_displacement("dmt", …)`) differs
/// from it by O(λ^(1/2)) in the penetration.
pub const MIN_MAUGIS_PARAMETER: f64 = 1e-10;

fn failure(e: tabor::restitution::Error, rename: Option<(&str, &str)>) -> Failure {
    let mut m = e.to_string();
    if let Some((lib, py)) = rename {
        m = m.replacen(lib, py, 1);
    }
    Failure::library(&e, m)
}

fn call<'s>(
    n: usize,
    shape: &'s [usize],
    errors: &str,
    threads: Option<usize>,
) -> PyResult<Call<'s>> {
    Ok(Call {
        n,
        shape,
        options: Options::new(errors, threads)?,
    })
}

/// W(Λ) in units of F_n d_n (see `tabor.maugis_dugdale_loss`).
#[pyfunction]
#[pyo3(signature = (tabor_parameter, tolerance, fast, n, shape, errors, threads))]
#[allow(clippy::too_many_arguments)]
pub fn maugis_dugdale_loss<'py>(
    py: Python<'py>,
    tabor_parameter: Arr<'py>,
    tolerance: Arr<'py>,
    fast: bool,
    n: usize,
    shape: Vec<usize>,
    errors: &str,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyTuple>> {
    let c = call(n, &shape, errors, threads)?;
    let cols = c.columns(&[
        ("tabor_parameter", &tabor_parameter),
        ("tolerance", &tolerance),
    ])?;
    let (lambda, tol) = (cols[0], cols[1]);
    let w_jkr = tabor::maugis::jkr_normalized_loss();
    if fast {
        c.floats(py, |i| {
            tabor::maugis::loss_over_jkr_fast(lambda.at(i))
                .map(|r| [r * w_jkr])
                .map_err(|e| failure(e, None))
        })
    } else {
        c.floats(py, |i| {
            tabor::maugis::normalized_loss(lambda.at(i), tol.at(i))
                .map(|w| [w.loss])
                .map_err(|e| failure(e, None))
        })
    }
}

/// Load and penetration in Maugis' units at Maugis parameter λ and contact radius A.
fn curve_point(maugis_parameter: f64, contact_radius: f64) -> Result<(f64, f64), Failure> {
    let lambda =
        units::tabor_parameter_from_maugis(maugis_parameter).map_err(|e| failure(e, None))?;
    if maugis_parameter < MIN_MAUGIS_PARAMETER {
        return Err(Failure {
            kind: Kind::Validity,
            message: format!(
                "maugis_parameter = {maugis_parameter:e} is below {MIN_MAUGIS_PARAMETER:e}, where the \
                 Maugis-Dugdale branch can no longer be evaluated to full precision; the DMT limit \
                 (force_displacement(\"dmt\", ...)) is off from it by O(maugis_parameter^(1/2)) in the penetration"
            ),
        });
    }
    if !(contact_radius.is_finite() && contact_radius >= 0.0) {
        return Err(Failure::input(format!(
            "invalid contact_radius = {contact_radius:e}: must be finite and >= 0"
        )));
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
                return Err(Failure::input(format!(
                    "invalid contact_radius = {contact_radius:e}: too large for maugis_parameter = {maugis_parameter:e}"
                )));
            }
        }
        let hi = FRAC_PI_2;
        if f(hi) >= 0.0 {
            hi
        } else {
            brent(f, lo, hi, RootTolerance::relative(0.0))
                .map_err(|e| Failure {
                    kind: Kind::Convergence,
                    message: e.to_string(),
                })?
                .value
        }
    };
    let s = contact_state(lambda, theta);
    // F̂ = F/F_n with F_n = (3/2)πΔγR; d̂ = d/d_n with d_n = (3/2)^(2/3)/3 (π²Δγ²R/K²)^(1/3)
    let load = 1.5 * s.force;
    let penetration = s.depth * radius_factor() * radius_factor() / 3.0;
    if !(load.is_finite() && penetration.is_finite()) {
        return Err(Failure {
            kind: Kind::Validity,
            message: format!(
                "load or penetration overflows at contact_radius = {contact_radius:e}, maugis_parameter = {maugis_parameter:e}"
            ),
        });
    }
    Ok((load, penetration))
}

/// (load, penetration) in Maugis' units (see `tabor.maugis_dugdale_curve`).
#[pyfunction]
#[pyo3(signature = (contact_radius, maugis_parameter, n, shape, errors, threads))]
#[allow(clippy::too_many_arguments)]
pub fn maugis_dugdale_curve<'py>(
    py: Python<'py>,
    contact_radius: Arr<'py>,
    maugis_parameter: Arr<'py>,
    n: usize,
    shape: Vec<usize>,
    errors: &str,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyTuple>> {
    let c = call(n, &shape, errors, threads)?;
    let cols = c.columns(&[
        ("contact_radius", &contact_radius),
        ("maugis_parameter", &maugis_parameter),
    ])?;
    c.floats(py, |i| {
        let (p, d) = curve_point(cols[1].at(i), cols[0].at(i))?;
        Ok([p, d])
    })
}

macro_rules! unary {
    ($name:ident, $f:path, $lib:literal, $arg:literal) => {
        /// Flat element-wise conversion (see the Python function of the same name).
        #[pyfunction]
        #[pyo3(signature = (x, n, shape, errors, threads))]
        pub fn $name<'py>(
            py: Python<'py>,
            x: Arr<'py>,
            n: usize,
            shape: Vec<usize>,
            errors: &str,
            threads: Option<usize>,
        ) -> PyResult<Bound<'py, PyTuple>> {
            let c = call(n, &shape, errors, threads)?;
            let cols = c.columns(&[($arg, &x)])?;
            c.floats(py, |i| {
                $f(cols[0].at(i))
                    .map(|v| [v])
                    .map_err(|e| failure(e, Some(($lib, $arg))))
            })
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
    maugis_parameter_from_tabor,
    units::maugis_parameter,
    "tabor_parameter",
    "tabor_parameter"
);

/// W_JKR / (F_n d_n), the JKR loss (5.36) in the seed's units.
#[pyfunction]
pub fn jkr_normalized_loss() -> f64 {
    tabor::maugis::jkr_normalized_loss()
}

fn positive(name: &str, x: f64) -> Result<f64, Failure> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(Failure::input(format!(
            "invalid {name} = {x:e}: must be finite and > 0"
        )))
    }
}

/// Maugis' λ = 2σ0 / (πΔγK²/R)^(1/3), K = 4E*/3 (Maugis 1992; the argument order
/// and meaning of `Adhesion.ReferenceSolutions.MaugisDugdale.maugis_parameter`).
fn maugis_lambda(radius: f64, modulus: f64, work: f64, stress: f64) -> Result<f64, Failure> {
    let (r, e, w, s) = (
        positive("radius", radius)?,
        positive("elastic_modulus", modulus)?,
        positive("work_of_adhesion", work)?,
        positive("cohesive_stress", stress)?,
    );
    let k = 4.0 * e / 3.0;
    let lam = 2.0 * s / (PI * w * k * k / r).cbrt();
    if lam.is_finite() && lam > 0.0 {
        Ok(lam)
    } else {
        Err(Failure {
            kind: Kind::Validity,
            message: format!("maugis parameter 2σ0/(πΔγK²/R)^(1/3) = {lam:e} is not representable"),
        })
    }
}

/// Maugis' λ from SI quantities (see `tabor.maugis_parameter`).
#[pyfunction]
#[pyo3(signature = (radius, elastic_modulus, work_of_adhesion, cohesive_stress, n, shape, errors, threads))]
#[allow(clippy::too_many_arguments)]
pub fn maugis_parameter<'py>(
    py: Python<'py>,
    radius: Arr<'py>,
    elastic_modulus: Arr<'py>,
    work_of_adhesion: Arr<'py>,
    cohesive_stress: Arr<'py>,
    n: usize,
    shape: Vec<usize>,
    errors: &str,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyTuple>> {
    let c = call(n, &shape, errors, threads)?;
    let k = c.columns(&[
        ("radius", &radius),
        ("elastic_modulus", &elastic_modulus),
        ("work_of_adhesion", &work_of_adhesion),
        ("cohesive_stress", &cohesive_stress),
    ])?;
    c.floats(py, |i| {
        Ok([maugis_lambda(
            k[0].at(i),
            k[1].at(i),
            k[2].at(i),
            k[3].at(i),
        )?])
    })
}

/// The contact models of [`force_displacement`].
const CURVE_MODELS: [&str; 3] = ["jkr", "dmt", "maugis-dugdale"];

/// Force (N, compression positive) and penetration (m) at contact radius `a` (m).
fn si_point(
    model: usize,
    a: f64,
    r: f64,
    e: f64,
    w: f64,
    stress: Option<f64>,
) -> Result<[f64; 2], Failure> {
    let contact_radius = if a.is_finite() && a >= 0.0 {
        a
    } else {
        return Err(Failure::input(format!(
            "invalid contact_radius = {a:e}: must be finite and >= 0"
        )));
    };
    match model {
        0 => {
            let (r, e, w) = (
                positive("radius", r)?,
                positive("elastic_modulus", e)?,
                positive("work_of_adhesion", w)?,
            );
            let s = tabor::jkr::JkrSphere::new(e, r, w).map_err(|e| failure(e, None))?;
            let lib = |x: tabor::restitution::Error| failure(x, None);
            Ok([
                s.force(contact_radius).map_err(lib)?,
                s.depth(contact_radius).map_err(lib)?,
            ])
        }
        1 => {
            let (r, e, w) = (
                positive("radius", r)?,
                positive("elastic_modulus", e)?,
                positive("work_of_adhesion", w)?,
            );
            // DMT: the Hertz contact plus the constant adhesive force 2πΔγR
            let f = 4.0 * e * contact_radius.powi(3) / (3.0 * r) - 2.0 * PI * w * r;
            let d = contact_radius * contact_radius / r;
            if f.is_finite() && d.is_finite() {
                Ok([f, d])
            } else {
                Err(Failure {
                    kind: Kind::Validity,
                    message: format!("force or penetration overflows at contact_radius = {a:e}"),
                })
            }
        }
        _ => {
            let s = match stress {
                Some(s) => s,
                None => {
                    return Err(Failure::input(
                        "missing cohesive_stress: required by model=\"maugis-dugdale\"",
                    ))
                }
            };
            let lam = maugis_lambda(r, e, w, s)?;
            let k = 4.0 * e / 3.0;
            let a_unit = (PI * w * r * r / k).cbrt();
            let d_unit = (PI * PI * w * w * r / (k * k)).cbrt();
            let (p, d) = curve_point(lam, contact_radius / a_unit)?;
            Ok([p * PI * w * r, d * d_unit])
        }
    }
}

/// SI force and penetration of `model` over contact radii (see
/// `tabor.force_displacement`).
#[pyfunction]
#[pyo3(signature = (model, contact_radius, radius, elastic_modulus, work_of_adhesion, cohesive_stress, n, shape, errors, threads))]
#[allow(clippy::too_many_arguments)]
pub fn force_displacement<'py>(
    py: Python<'py>,
    model: &str,
    contact_radius: Arr<'py>,
    radius: Arr<'py>,
    elastic_modulus: Arr<'py>,
    work_of_adhesion: Arr<'py>,
    cohesive_stress: Option<Arr<'py>>,
    n: usize,
    shape: Vec<usize>,
    errors: &str,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyTuple>> {
    let which = CURVE_MODELS
        .iter()
        .position(|m| *m == model.replace('_', "-"))
        .ok_or_else(|| {
            Failure::input(format!(
                "invalid model = \"{model}\": expected \"jkr\", \"dmt\" or \"maugis-dugdale\""
            ))
            .into_pyerr_static()
        })?;
    let c = call(n, &shape, errors, threads)?;
    let k = c.columns(&[
        ("contact_radius", &contact_radius),
        ("radius", &radius),
        ("elastic_modulus", &elastic_modulus),
        ("work_of_adhesion", &work_of_adhesion),
    ])?;
    let stress = match &cohesive_stress {
        Some(s) => Some(c.columns(&[("cohesive_stress", s)])?[0]),
        None => None,
    };
    if which != 2 && stress.is_some() {
        return Err(Failure::input(format!(
            "cohesive_stress is a parameter of model=\"maugis-dugdale\", not of model=\"{}\"",
            CURVE_MODELS[which]
        ))
        .into_pyerr_static());
    }
    c.floats(py, |i| {
        si_point(
            which,
            k[0].at(i),
            k[1].at(i),
            k[2].at(i),
            k[3].at(i),
            stress.map(|s| s.at(i)),
        )
    })
}

//! Maugis-Dugdale: the normalized impact loss W(Λ), the equilibrium curve in
//! Maugis' units, the conversions between Λ, Maugis' λ and Tabor's μ, and the
//! force-displacement curves of JKR, DMT and Maugis-Dugdale in SI units (the
//! names and argument meanings of ContactEngineering's `Adhesion` package).

use crate::batch::Options;
use crate::failure::Failure;
use crate::output::Call;
use numpy::PyReadonlyArray1;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use tabor::maugis::{units, CurveModel};

type Arr<'py> = PyReadonlyArray1<'py, f64>;

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
        tabor::maugis::maugis_curve_point(cols[1].at(i), cols[0].at(i))
            .map(|p| [p.load, p.penetration])
            .map_err(|e| failure(e, None))
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

/// The library's SI parameter names as the Python keywords spell them
/// (Adhesion's vocabulary).
const SI_NAMES: [(&str, &str); 2] = [
    ("effective_modulus", "contact_modulus"),
    ("effective_radius", "radius"),
];

/// A library error of an SI curve, its parameter renamed to the Python keyword.
fn si_failure(e: tabor::restitution::Error) -> Failure {
    let rename = match &e {
        tabor::restitution::Error::InvalidParameter { parameter, .. } => {
            SI_NAMES.into_iter().find(|(lib, _)| lib == parameter)
        }
        _ => None,
    };
    failure(e, rename)
}

/// The Maugis-Dugdale sphere of the Python arguments (Adhesion's order).
fn sphere(
    radius: f64,
    modulus: f64,
    work: f64,
    stress: f64,
) -> Result<tabor::maugis::MaugisDugdaleSphere, Failure> {
    tabor::maugis::MaugisDugdaleSphere::new(modulus, radius, work, stress).map_err(si_failure)
}

/// Maugis' λ from SI quantities (see `tabor.maugis_parameter`).
#[pyfunction]
#[pyo3(signature = (radius, contact_modulus, work_of_adhesion, cohesive_stress, n, shape, errors, threads))]
#[allow(clippy::too_many_arguments)]
pub fn maugis_parameter<'py>(
    py: Python<'py>,
    radius: Arr<'py>,
    contact_modulus: Arr<'py>,
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
        ("contact_modulus", &contact_modulus),
        ("work_of_adhesion", &work_of_adhesion),
        ("cohesive_stress", &cohesive_stress),
    ])?;
    c.floats(py, |i| {
        Ok([sphere(k[0].at(i), k[1].at(i), k[2].at(i), k[3].at(i))?.maugis_parameter()])
    })
}

/// Force (N, compression positive) and penetration (m) at contact radius `a` (m).
fn si_point(
    model: CurveModel,
    a: f64,
    r: f64,
    e: f64,
    w: f64,
    stress: Option<f64>,
) -> Result<[f64; 2], Failure> {
    match model {
        CurveModel::Jkr => {
            let s = tabor::jkr::JkrSphere::new(e, r, w).map_err(si_failure)?;
            Ok([
                s.force(a).map_err(si_failure)?,
                s.depth(a).map_err(si_failure)?,
            ])
        }
        CurveModel::Dmt => {
            let p = tabor::maugis::dmt_curve_point(e, r, w, a).map_err(si_failure)?;
            Ok([p.force, p.penetration])
        }
        CurveModel::MaugisDugdale => {
            let s = match stress {
                Some(s) => s,
                None => {
                    return Err(Failure::input(format!(
                        "missing cohesive_stress: required by model=\"{model}\""
                    )))
                }
            };
            let p = sphere(r, e, w, s)?.curve_point(a).map_err(si_failure)?;
            Ok([p.force, p.penetration])
        }
    }
}

/// SI force and penetration of `model` over contact radii (see
/// `tabor.force_displacement`).
#[pyfunction]
#[pyo3(signature = (model, contact_radius, radius, contact_modulus, work_of_adhesion, cohesive_stress, n, shape, errors, threads))]
#[allow(clippy::too_many_arguments)]
pub fn force_displacement<'py>(
    py: Python<'py>,
    model: &str,
    contact_radius: Arr<'py>,
    radius: Arr<'py>,
    contact_modulus: Arr<'py>,
    work_of_adhesion: Arr<'py>,
    cohesive_stress: Option<Arr<'py>>,
    n: usize,
    shape: Vec<usize>,
    errors: &str,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyTuple>> {
    let which: CurveModel = model.replace('_', "-").parse().map_err(|e| {
        Failure::input(format!("invalid model = \"{model}\": {e}")).into_pyerr_static()
    })?;
    let c = call(n, &shape, errors, threads)?;
    let k = c.columns(&[
        ("contact_radius", &contact_radius),
        ("radius", &radius),
        ("contact_modulus", &contact_modulus),
        ("work_of_adhesion", &work_of_adhesion),
    ])?;
    let stress = match &cohesive_stress {
        Some(s) => Some(c.columns(&[("cohesive_stress", s)])?[0]),
        None => None,
    };
    if which != CurveModel::MaugisDugdale && stress.is_some() {
        return Err(Failure::input(format!(
            "cohesive_stress is a parameter of model=\"{}\", not of model=\"{which}\"",
            CurveModel::MaugisDugdale
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

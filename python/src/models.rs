//! The single-model functions, mirroring the CLI subcommands `effective`, `jkr`,
//! `plastic`, `visco` and `penalty` (crates/tabor-cli/src/cmd): the same inputs (as
//! keyword arguments named like the flags), the same outputs (as columns), the
//! same validation. The computations are shared with the CLI in `tabor::single`;
//! this module only broadcasts the numpy inputs and converts the records.

use crate::convert::{batch, records_to_columns, Col};
use numpy::PyReadonlyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde::Serialize;
use serde_json::Value;
use tabor::restitution::Error;
use tabor::single::effective::{effective as effective_record, EffectiveArgs};
use tabor::single::jkr::{jkr as jkr_record, JkrArgs};
use tabor::single::penalty::{penalty as penalty_record, PenaltyArgs, PenaltyLaw};
use tabor::single::plastic::{plastic as plastic_record, PlasticArgs, PlasticModel};
use tabor::single::visco::{visco as visco_record, ViscoArgs, ViscoModel};
use tabor::single::Naming;

type Arr<'py> = PyReadonlyArray1<'py, f64>;

/// Flat columns of the required and optional arguments, and the batch length.
struct Inputs<'a> {
    required: Vec<Col<'a>>,
    optional: Vec<Option<Col<'a>>>,
    n: usize,
}

fn inputs<'a>(
    required: &[(&str, &'a Arr<'a>)],
    optional: &[(&str, Option<&'a Arr<'a>>)],
) -> PyResult<Inputs<'a>> {
    let mut n = 1usize;
    let mut check = |name: &str, a: &'a Arr<'a>| -> PyResult<Col<'a>> {
        let s = a
            .as_slice()
            .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
        if s.len() != 1 {
            if n != 1 && s.len() != n {
                return Err(PyValueError::new_err(format!(
                    "{name}: length {} does not match the batch length {n}",
                    s.len()
                )));
            }
            n = s.len();
        }
        Ok(Col(s))
    };
    let mut req = Vec::new();
    for (name, a) in required {
        req.push(check(name, a)?);
    }
    let mut opt = Vec::new();
    for (name, a) in optional {
        opt.push(match a {
            Some(a) => Some(check(name, a)?),
            None => None,
        });
    }
    Ok(Inputs {
        required: req,
        optional: opt,
        n,
    })
}

/// The library error with its parameter renamed to the Python keyword.
fn renamed(map: &'static [(&'static str, &'static str)]) -> impl Fn(Error) -> String + Copy {
    move |e| match e {
        Error::InvalidParameter {
            parameter,
            value,
            requirement,
        } => {
            let name = map
                .iter()
                .find(|(lib, _)| *lib == parameter)
                .map_or(parameter, |(_, py)| *py);
            format!("invalid {name} = {value:e}: {requirement}")
        }
        other => other.to_string(),
    }
}

fn json<T: Serialize>(v: &T) -> Result<Value, String> {
    serde_json::to_value(v).map_err(|e| e.to_string())
}

fn opt_at(c: &Option<Col<'_>>, i: usize) -> Option<f64> {
    c.as_ref().map(|c| c.at(i))
}

// ---------------------------------------------------------------------------------
// effective

/// `tabor effective` per element (see `tabor.effective`).
#[pyfunction]
#[pyo3(signature = (youngs_modulus, poisson_ratio, radius, density, mass, target_youngs_modulus,
    target_poisson_ratio, rigid_target, target_radius, target_density, target_mass, shape))]
#[allow(clippy::too_many_arguments)]
pub fn effective<'py>(
    py: Python<'py>,
    youngs_modulus: Arr<'py>,
    poisson_ratio: Arr<'py>,
    radius: Arr<'py>,
    density: Option<Arr<'py>>,
    mass: Option<Arr<'py>>,
    target_youngs_modulus: Option<Arr<'py>>,
    target_poisson_ratio: Option<Arr<'py>>,
    rigid_target: bool,
    target_radius: Option<Arr<'py>>,
    target_density: Option<Arr<'py>>,
    target_mass: Option<Arr<'py>>,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    if density.is_some() && mass.is_some() {
        return Err(PyValueError::new_err("give density or mass, not both"));
    }
    if rigid_target && (target_youngs_modulus.is_some() || target_poisson_ratio.is_some()) {
        return Err(PyValueError::new_err(
            "rigid_target=True conflicts with target_youngs_modulus and target_poisson_ratio",
        ));
    }
    if target_density.is_some() && target_mass.is_some() {
        return Err(PyValueError::new_err(
            "give target_density or target_mass, not both",
        ));
    }
    let inp = inputs(
        &[
            ("youngs_modulus", &youngs_modulus),
            ("poisson_ratio", &poisson_ratio),
            ("radius", &radius),
        ],
        &[
            ("density", density.as_ref()),
            ("mass", mass.as_ref()),
            ("target_youngs_modulus", target_youngs_modulus.as_ref()),
            ("target_poisson_ratio", target_poisson_ratio.as_ref()),
            ("target_radius", target_radius.as_ref()),
            ("target_density", target_density.as_ref()),
            ("target_mass", target_mass.as_ref()),
        ],
    )?;
    let records = batch(py, inp.n, &shape, |i| {
        let [e1, nu1, r1] = [0, 1, 2].map(|k| inp.required[k].at(i));
        let o = |k: usize| opt_at(&inp.optional[k], i);
        let a = EffectiveArgs {
            youngs_modulus: e1,
            poisson_ratio: nu1,
            radius: r1,
            density: o(0),
            mass: o(1),
            target_youngs_modulus: o(2),
            target_poisson_ratio: o(3),
            rigid_target,
            target_radius: o(4),
            target_density: o(5),
            target_mass: o(6),
        };
        json(&effective_record(&a, Naming::Keywords).map_err(|e| e.message(|e| e.to_string()))?)
    })?;
    records_to_columns(py, &records)
}

// ---------------------------------------------------------------------------------
// jkr

const JKR_NAMES: &[(&str, &str)] = &[
    ("effective_modulus", "modulus"),
    ("effective_radius", "radius"),
    ("effective_mass", "mass"),
    ("impact_speed", "speed"),
];

fn separation_rule(name: &str) -> PyResult<tabor::jkr::SeparationRule> {
    match name.replace('_', "-").as_str() {
        "fixed-grip" => Ok(tabor::jkr::SeparationRule::FixedGrip),
        "load-controlled" => Ok(tabor::jkr::SeparationRule::LoadControlled),
        _ => Err(PyValueError::new_err(format!(
            "invalid separation = \"{name}\": expected \"fixed-grip\" or \"load-controlled\""
        ))),
    }
}

/// `tabor jkr` per element (see `tabor.jkr`).
#[pyfunction]
#[pyo3(signature = (modulus, radius, work_of_adhesion, mass, speed, separation, tolerance, shape))]
#[allow(clippy::too_many_arguments)]
pub fn jkr<'py>(
    py: Python<'py>,
    modulus: Arr<'py>,
    radius: Arr<'py>,
    work_of_adhesion: Arr<'py>,
    mass: Arr<'py>,
    speed: Option<Arr<'py>>,
    separation: &str,
    tolerance: Arr<'py>,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let rule = separation_rule(separation)?;
    let inp = inputs(
        &[
            ("modulus", &modulus),
            ("radius", &radius),
            ("work_of_adhesion", &work_of_adhesion),
            ("mass", &mass),
            ("tolerance", &tolerance),
        ],
        &[("speed", speed.as_ref())],
    )?;
    let message = renamed(JKR_NAMES);
    let records = batch(py, inp.n, &shape, |i| {
        let [e, r, w, m, tol] = [0, 1, 2, 3, 4].map(|k| inp.required[k].at(i));
        let v0 = opt_at(&inp.optional[0], i);
        json(
            &jkr_record(&JkrArgs {
                modulus: e,
                radius: r,
                work_of_adhesion: w,
                mass: m,
                speed: v0,
                separation: rule,
                tolerance: tol,
            })
            .map_err(message)?,
        )
    })?;
    records_to_columns(py, &records)
}

// ---------------------------------------------------------------------------------
// plastic

fn plastic_model(name: &str, what: &str) -> PyResult<PlasticModel> {
    Ok(match name.replace('_', "-").as_str() {
        "thornton" => PlasticModel::Thornton,
        "interpolation" => PlasticModel::Interpolation,
        "jackson-green" => PlasticModel::JacksonGreen,
        "dimensionless-fit" => PlasticModel::DimensionlessFit,
        "adhesive-interpolation" if what == "model" => PlasticModel::AdhesiveInterpolation,
        "superposition" if what == "model" => PlasticModel::Superposition,
        _ => {
            let expected = if what == "model" {
                "thornton, interpolation, jackson-green, dimensionless-fit, adhesive-interpolation or superposition"
            } else {
                "thornton, interpolation, jackson-green or dimensionless-fit"
            };
            return Err(PyValueError::new_err(format!(
                "invalid {what} = \"{name}\": expected {expected}"
            )));
        }
    })
}

const PLASTIC_NAMES: &[(&str, &str)] = &[
    ("effective_modulus", "modulus"),
    ("effective_radius", "radius"),
    ("effective_mass", "mass"),
    ("impact_speed", "speed"),
];

/// `tabor plastic` per element (see `tabor.plastic`).
#[pyfunction]
#[pyo3(signature = (model, modulus, radius, mass, yield_stress, speed, poisson_ratio, density,
    work_of_adhesion, adhesion_parameter, plastic_model, shape))]
#[allow(clippy::too_many_arguments)]
pub fn plastic<'py>(
    py: Python<'py>,
    model: &str,
    modulus: Arr<'py>,
    radius: Arr<'py>,
    mass: Arr<'py>,
    yield_stress: Arr<'py>,
    speed: Arr<'py>,
    poisson_ratio: Option<Arr<'py>>,
    density: Option<Arr<'py>>,
    work_of_adhesion: Option<Arr<'py>>,
    adhesion_parameter: Option<Arr<'py>>,
    plastic_model: &str,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let which = self::plastic_model(model, "model")?;
    let under = self::plastic_model(plastic_model, "plastic_model")?;
    let inp = inputs(
        &[
            ("modulus", &modulus),
            ("radius", &radius),
            ("mass", &mass),
            ("yield_stress", &yield_stress),
            ("speed", &speed),
        ],
        &[
            ("poisson_ratio", poisson_ratio.as_ref()),
            ("density", density.as_ref()),
            ("work_of_adhesion", work_of_adhesion.as_ref()),
            ("adhesion_parameter", adhesion_parameter.as_ref()),
        ],
    )?;
    let records = batch(py, inp.n, &shape, |i| {
        let r = |k: usize| inp.required[k].at(i);
        let o = |k: usize| opt_at(&inp.optional[k], i);
        let a = PlasticArgs {
            model: which,
            modulus: r(0),
            radius: r(1),
            mass: r(2),
            yield_stress: r(3),
            speed: r(4),
            poisson_ratio: o(0),
            density: o(1),
            work_of_adhesion: o(2),
            adhesion_parameter: o(3),
            plastic_model: under,
        };
        json(&plastic_record(&a, Naming::Keywords).map_err(|e| e.message(renamed(PLASTIC_NAMES)))?)
    })?;
    records_to_columns(py, &records)
}

// ---------------------------------------------------------------------------------
// visco

const VISCO_NAMES: &[(&str, &str)] = &[("shear_damping_ratio", "damping_ratio")];

/// `tabor visco` per element (see `tabor.visco`).
#[pyfunction]
#[pyo3(signature = (model, damping_ratio, viscous_parameter, modulus_ratio, damping,
    damping_exponent, alpha, poisson_ratio, bulk_damping_ratio, tolerance, shape))]
#[allow(clippy::too_many_arguments)]
pub fn visco<'py>(
    py: Python<'py>,
    model: &str,
    damping_ratio: Option<Arr<'py>>,
    viscous_parameter: Option<Arr<'py>>,
    modulus_ratio: Option<Arr<'py>>,
    damping: Option<Arr<'py>>,
    damping_exponent: Option<Arr<'py>>,
    alpha: Option<Arr<'py>>,
    poisson_ratio: Option<Arr<'py>>,
    bulk_damping_ratio: Option<Arr<'py>>,
    tolerance: Arr<'py>,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let wanted = model.replace('_', "-");
    let which = ViscoModel::ALL
        .into_iter()
        .find(|m| m.as_str() == wanted)
        .ok_or_else(|| {
            let names: Vec<&str> = ViscoModel::ALL.iter().map(|m| m.as_str()).collect();
            PyValueError::new_err(format!(
                "invalid model = \"{model}\": expected one of {}",
                names.join(", ")
            ))
        })?;
    let inp = inputs(
        &[("tolerance", &tolerance)],
        &[
            ("damping_ratio", damping_ratio.as_ref()),
            ("viscous_parameter", viscous_parameter.as_ref()),
            ("modulus_ratio", modulus_ratio.as_ref()),
            ("damping", damping.as_ref()),
            ("damping_exponent", damping_exponent.as_ref()),
            ("alpha", alpha.as_ref()),
            ("poisson_ratio", poisson_ratio.as_ref()),
            ("bulk_damping_ratio", bulk_damping_ratio.as_ref()),
        ],
    )?;
    let records = batch(py, inp.n, &shape, |i| {
        let o = |k: usize| opt_at(&inp.optional[k], i);
        let a = ViscoArgs {
            model: which,
            damping_ratio: o(0),
            viscous_parameter: o(1),
            modulus_ratio: o(2),
            damping: o(3),
            damping_exponent: o(4),
            alpha: o(5),
            poisson_ratio: o(6),
            bulk_damping_ratio: o(7),
            tolerance: inp.required[0].at(i),
        };
        json(&visco_record(&a, Naming::Keywords).map_err(|e| e.message(renamed(VISCO_NAMES)))?)
    })?;
    records_to_columns(py, &records)
}

// ---------------------------------------------------------------------------------
// penalty

const PENALTY_NAMES: &[(&str, &str)] = &[("effective_mass", "mass"), ("impact_speed", "speed")];

/// `tabor penalty` per element (see `tabor.penalty`).
#[pyfunction]
#[pyo3(signature = (law, restitution, stiffness, exponent, rounding, mass, speed, shape))]
#[allow(clippy::too_many_arguments)]
pub fn penalty<'py>(
    py: Python<'py>,
    law: &str,
    restitution: Arr<'py>,
    stiffness: Arr<'py>,
    exponent: Option<Arr<'py>>,
    rounding: Arr<'py>,
    mass: Arr<'py>,
    speed: Arr<'py>,
    shape: Vec<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let which = match law.replace('_', "-").as_str() {
        "characteristic" => PenaltyLaw::Characteristic,
        "hunt-crossley" => PenaltyLaw::HuntCrossley,
        "lankarani-nikravesh" => PenaltyLaw::LankaraniNikravesh,
        "flores" => PenaltyLaw::Flores,
        _ => {
            return Err(PyValueError::new_err(format!(
                "invalid law = \"{law}\": expected characteristic, hunt-crossley, \
                 lankarani-nikravesh or flores"
            )))
        }
    };
    let inp = inputs(
        &[
            ("restitution", &restitution),
            ("stiffness", &stiffness),
            ("rounding", &rounding),
            ("mass", &mass),
            ("speed", &speed),
        ],
        &[("exponent", exponent.as_ref())],
    )?;
    let records = batch(py, inp.n, &shape, |i| {
        let r = |k: usize| inp.required[k].at(i);
        let a = PenaltyArgs {
            law: which,
            restitution: r(0),
            stiffness: r(1),
            exponent: opt_at(&inp.optional[0], i),
            rounding: r(2),
            mass: r(3),
            speed: r(4),
        };
        json(&penalty_record(&a, Naming::Keywords).map_err(|e| e.message(renamed(PENALTY_NAMES)))?)
    })?;
    records_to_columns(py, &records)
}

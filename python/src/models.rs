//! The single-model functions `effective`, `jkr`, `plastic`, `visco`, `penalty`
//! (the CLI subcommands of the same names, computed by `tabor::single`), driven by
//! one table per model: each keyword once, with its kind, default and help line.
//! The Python layer builds the functions' signatures, docs and type stubs from the
//! same tables (`_tabor.SPECS`); a library error names the keyword through
//! `tabor::single::input_name`.

use crate::batch::Options;
use crate::columns::{OwnFields, OwnKind};
use crate::failure::Failure;
use crate::output::{push, Call, Col};
use numpy::PyReadonlyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use tabor::jkr::SeparationRule;
use tabor::numerics::tolerance;
use tabor::restitution::{Error, Menu, UnknownChoice};
use tabor::single::effective::{effective, EffectiveArgs};
use tabor::single::jkr::{jkr, prepare as prepare_jkr, JkrArgs, JkrAtSpeed, JkrPrepared};
use tabor::single::penalty::{penalty, PenaltyArgs, PenaltyLaw};
use tabor::single::plastic::{plastic, PlasticArgs, PlasticModel};
use tabor::single::visco::{visco, ViscoArgs, ViscoModel};
use tabor::single::{input_name, Naming};

/// How a keyword is given.
pub enum Kind<A> {
    /// A number (array_like); required when `default` is None.
    Number {
        /// The default value.
        default: Option<f64>,
        /// Stores the element's value.
        set: fn(&mut A, f64),
    },
    /// An optional number (array_like or None).
    Optional {
        /// Stores the element's value.
        set: fn(&mut A, Option<f64>),
    },
    /// A bool (strictly `True`/`False`), default False.
    Flag {
        /// Stores the value.
        set: fn(&mut A, bool),
    },
    /// One of a menu of the model crates (a str: its `as_str` name; underscores
    /// may stand for hyphens); required when `default` is None.
    Choice {
        /// The menu: each choice's name and description (from the crate's `ALL`,
        /// `as_str`, `description`).
        menu: fn() -> Vec<(&'static str, &'static str)>,
        /// The default choice's name.
        default: Option<fn() -> &'static str>,
        /// Parses a name of `menu` (the menu's `FromStr`) and stores it.
        set: fn(&mut A, &str) -> Result<(), UnknownChoice>,
    },
}

/// One keyword of a model function.
pub struct Input<A> {
    /// The keyword (snake_case, the CLI flag without `--`).
    pub name: &'static str,
    /// The help line (with the unit).
    pub help: &'static str,
    /// How it is given.
    pub kind: Kind<A>,
}

/// A model function: its keywords and its computation.
pub struct Model<A: 'static, R> {
    /// The function's name (= the CLI subcommand).
    pub name: &'static str,
    /// The keywords, in the order of the signature.
    pub inputs: &'static [Input<A>],
    /// The inputs before the keywords are applied.
    pub blank: fn() -> A,
    /// Validates and computes one element.
    pub compute: fn(&A) -> Result<R, Failure>,
}

/// Every choice of menu `M`: (name, description).
fn menu<M: Menu>() -> Vec<(&'static str, &'static str)> {
    M::ALL
        .iter()
        .map(|m| (m.as_str(), m.description()))
        .collect()
}

/// A library error with its parameter named as the keyword that gives it.
fn library(e: Error) -> Failure {
    let message = match &e {
        Error::InvalidParameter {
            parameter,
            value,
            requirement,
        } => format!(
            "invalid {} = {value:e}: {requirement}",
            input_name(parameter)
        ),
        other => other.to_string(),
    };
    Failure::library(&e, message)
}

fn single(e: tabor::single::Error) -> Failure {
    match e {
        tabor::single::Error::Library(e) => library(e),
        tabor::single::Error::Input(m) => Failure::input(m),
    }
}

// ---------------------------------------------------------------------------------
// the tables

/// `effective` names the library's own parameters (its keywords differ between the
/// two bodies), so its errors are not renamed.
pub static EFFECTIVE: Model<EffectiveArgs, tabor::single::effective::Effective> = Model {
    name: "effective",
    inputs: &[
        Input {
            name: "youngs_modulus",
            help: "Young's modulus of the sphere (Pa)",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.youngs_modulus = x,
            },
        },
        Input {
            name: "poisson_ratio",
            help: "Poisson's ratio of the sphere",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.poisson_ratio = x,
            },
        },
        Input {
            name: "radius",
            help: "radius of the sphere (m)",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.radius = x,
            },
        },
        Input {
            name: "density",
            help: "density of the sphere (kg/m³); or give mass",
            kind: Kind::Optional {
                set: |a, x| a.density = x,
            },
        },
        Input {
            name: "mass",
            help: "mass of the sphere (kg)",
            kind: Kind::Optional {
                set: |a, x| a.mass = x,
            },
        },
        Input {
            name: "target_youngs_modulus",
            help: "Young's modulus of the target (Pa); default: the sphere's",
            kind: Kind::Optional {
                set: |a, x| a.target_youngs_modulus = x,
            },
        },
        Input {
            name: "target_poisson_ratio",
            help: "Poisson's ratio of the target; default: the sphere's",
            kind: Kind::Optional {
                set: |a, x| a.target_poisson_ratio = x,
            },
        },
        Input {
            name: "rigid_target",
            help: "the target is rigid",
            kind: Kind::Flag {
                set: |a, x| a.rigid_target = x,
            },
        },
        Input {
            name: "target_radius",
            help: "radius of the target (m); omit for a flat half-space",
            kind: Kind::Optional {
                set: |a, x| a.target_radius = x,
            },
        },
        Input {
            name: "target_density",
            help: "density of the target (kg/m³); default: the sphere's",
            kind: Kind::Optional {
                set: |a, x| a.target_density = x,
            },
        },
        Input {
            name: "target_mass",
            help: "mass of the target (kg); omit for an immovable target",
            kind: Kind::Optional {
                set: |a, x| a.target_mass = x,
            },
        },
    ],
    blank: || EffectiveArgs {
        youngs_modulus: f64::NAN,
        poisson_ratio: f64::NAN,
        radius: f64::NAN,
        density: None,
        mass: None,
        target_youngs_modulus: None,
        target_poisson_ratio: None,
        rigid_target: false,
        target_radius: None,
        target_density: None,
        target_mass: None,
    },
    compute: |a| {
        if a.density.is_some() && a.mass.is_some() {
            return Err(Failure::input("give density or mass, not both"));
        }
        if a.rigid_target && (a.target_youngs_modulus.is_some() || a.target_poisson_ratio.is_some())
        {
            return Err(Failure::input(
                "rigid_target=True conflicts with target_youngs_modulus and target_poisson_ratio",
            ));
        }
        if a.target_density.is_some() && a.target_mass.is_some() {
            return Err(Failure::input(
                "give target_density or target_mass, not both",
            ));
        }
        effective(a, Naming::Keywords).map_err(|e| match e {
            tabor::single::Error::Library(e) => {
                let m = e.to_string();
                Failure::library(&e, m)
            }
            tabor::single::Error::Input(m) => Failure::input(m),
        })
    },
};

/// `jkr`.
pub static JKR: Model<JkrArgs, tabor::single::jkr::Jkr> = Model {
    name: "jkr",
    inputs: &[
        Input {
            name: "modulus",
            help: "effective modulus E* (Pa)",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.modulus = x,
            },
        },
        Input {
            name: "radius",
            help: "effective radius R (m)",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.radius = x,
            },
        },
        Input {
            name: "work_of_adhesion",
            help: "work of adhesion Δγ (J/m²)",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.work_of_adhesion = x,
            },
        },
        Input {
            name: "mass",
            help: "effective (reduced) mass m (kg)",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.mass = x,
            },
        },
        Input {
            name: "speed",
            help:
                "impact speed v0 (m/s); adds impact_speed, max_contact_radius, restitution, sticks",
            kind: Kind::Optional {
                set: |a, x| a.speed = x,
            },
        },
        Input {
            name: "separation",
            help: "where contact breaks",
            kind: Kind::Choice {
                menu: menu::<SeparationRule>,
                default: Some(|| SeparationRule::FixedGrip.as_str()),
                set: |a, k| {
                    a.separation = k.parse()?;
                    Ok(())
                },
            },
        },
        Input {
            name: "tolerance",
            help: "relative tolerance, in [1e-15, 0.5]",
            kind: Kind::Number {
                default: Some(tolerance::DEFAULT_TOLERANCE),
                set: |a, x| a.tolerance = x,
            },
        },
    ],
    blank: || JkrArgs {
        modulus: f64::NAN,
        radius: f64::NAN,
        work_of_adhesion: f64::NAN,
        mass: f64::NAN,
        speed: None,
        separation: SeparationRule::FixedGrip,
        tolerance: f64::NAN,
    },
    compute: |a| jkr(a).map_err(library),
};

/// `jkr` over speeds: the model once per distinct set of the other inputs
/// (`tabor::single::jkr::prepare`).
pub static JKR_BY_SPEED: Split<JkrArgs, JkrPrepared, tabor::single::jkr::Jkr, JkrAtSpeed> = Split {
    varying: "speed",
    prepare: |a| prepare_jkr(a).map_err(library),
    record: JkrPrepared::record,
    own: |p, speed, near| {
        speed
            .map(|v| p.at_speed_near(v, near))
            .transpose()
            .map_err(library)
    },
};

impl OwnFields for JkrAtSpeed {
    const FIELDS: &'static [(&'static str, OwnKind)] = &[
        ("impact_speed", OwnKind::Float),
        ("max_contact_radius", OwnKind::Float),
        ("restitution", OwnKind::Float),
        ("sticks", OwnKind::Bool),
    ];

    fn write(&self, out: &mut [f64]) {
        out[0] = self.impact_speed;
        out[1] = self.max_contact_radius;
        out[2] = self.restitution;
        out[3] = if self.sticks { 1.0 } else { 0.0 };
    }
}

/// The non-adhesive plastic models (the menu of `plastic_model`).
fn non_adhesive() -> Vec<(&'static str, &'static str)> {
    PlasticModel::NON_ADHESIVE
        .iter()
        .map(|m| (m.as_str(), m.description()))
        .collect()
}

/// `plastic`.
pub static PLASTIC: Model<PlasticArgs, tabor::single::plastic::Plastic> = Model {
    name: "plastic",
    inputs: &[
        Input { name: "model", help: "the elasto-plastic model; jackson-green needs poisson_ratio, dimensionless-fit density, adhesive-interpolation work_of_adhesion or adhesion_parameter, superposition work_of_adhesion", kind: Kind::Choice { menu: menu::<PlasticModel>, default: None, set: |a, k| { a.model = k.parse()?; Ok(()) } } },
        Input { name: "modulus", help: "effective modulus E* (Pa)", kind: Kind::Number { default: None, set: |a, x| a.modulus = x } },
        Input { name: "radius", help: "effective radius R (m)", kind: Kind::Number { default: None, set: |a, x| a.radius = x } },
        Input { name: "mass", help: "effective (reduced) mass m (kg)", kind: Kind::Number { default: None, set: |a, x| a.mass = x } },
        Input { name: "yield_stress", help: "yield stress σ_Y of the yielding body (Pa)", kind: Kind::Number { default: None, set: |a, x| a.yield_stress = x } },
        Input { name: "speed", help: "impact speed v0 (m/s)", kind: Kind::Number { default: None, set: |a, x| a.speed = x } },
        Input { name: "poisson_ratio", help: "Poisson's ratio of the yielding body (jackson-green)", kind: Kind::Optional { set: |a, x| a.poisson_ratio = x } },
        Input { name: "density", help: "density of the sphere, kg/m³ (dimensionless-fit)", kind: Kind::Optional { set: |a, x| a.density = x } },
        Input { name: "work_of_adhesion", help: "work of adhesion Δγ (J/m²)", kind: Kind::Optional { set: |a, x| a.work_of_adhesion = x } },
        Input { name: "adhesion_parameter", help: "adhesion parameter Φ, instead of computing it (adhesive-interpolation)", kind: Kind::Optional { set: |a, x| a.adhesion_parameter = x } },
        Input { name: "plastic_model", help: "the non-adhesive model under superposition", kind: Kind::Choice { menu: non_adhesive, default: Some(|| PlasticModel::Interpolation.as_str()), set: |a, k| { a.plastic_model = k.parse()?; Ok(()) } } },
    ],
    blank: || PlasticArgs {
        model: PlasticModel::Interpolation,
        modulus: f64::NAN,
        radius: f64::NAN,
        mass: f64::NAN,
        yield_stress: f64::NAN,
        speed: f64::NAN,
        poisson_ratio: None,
        density: None,
        work_of_adhesion: None,
        adhesion_parameter: None,
        plastic_model: PlasticModel::Interpolation,
    },
    compute: |a| plastic(a, Naming::Keywords).map_err(single),
};

/// `visco`.
pub static VISCO: Model<ViscoArgs, tabor::single::visco::Visco> = Model {
    name: "visco",
    inputs: &[
        Input { name: "model", help: "the viscoelastic model; kelvin-voigt-flat needs damping_ratio, kuwabara-kono, kelvin-voigt-sphere viscous_parameter, lee-herrmann, hunt-crossley damping, tsuji alpha, power-damping damping_exponent and damping, kelvin-maxwell-sphere modulus_ratio and viscous_parameter, compressible-flat poisson_ratio, damping_ratio and optionally bulk_damping_ratio", kind: Kind::Choice { menu: menu::<ViscoModel>, default: None, set: |a, k| { a.model = k.parse()?; Ok(()) } } },
        Input { name: "damping_ratio", help: "damping ratio D (> 0)", kind: Kind::Optional { set: |a, x| a.damping_ratio = x } },
        Input { name: "viscous_parameter", help: "viscous parameter δ (> 0)", kind: Kind::Optional { set: |a, x| a.viscous_parameter = x } },
        Input { name: "modulus_ratio", help: "modulus ratio β = G∞/G1, in [1e-5, 1e4]", kind: Kind::Optional { set: |a, x| a.modulus_ratio = x } },
        Input { name: "damping", help: "scaled damping γ of (5.72), in (0, 1e3]", kind: Kind::Optional { set: |a, x| a.damping = x } },
        Input { name: "damping_exponent", help: "damping exponent β of (5.72), in [0, 1.5]", kind: Kind::Optional { set: |a, x| a.damping_exponent = x } },
        Input { name: "alpha", help: "Tsuji's α of (5.73), > 0", kind: Kind::Optional { set: |a, x| a.alpha = x } },
        Input { name: "poisson_ratio", help: "static Poisson's ratio ν, in (-1, 0.5)", kind: Kind::Optional { set: |a, x| a.poisson_ratio = x } },
        Input { name: "bulk_damping_ratio", help: "bulk damping ratio D2; default (5.100)", kind: Kind::Optional { set: |a, x| a.bulk_damping_ratio = x } },
        Input { name: "tolerance", help: "relative integration tolerance, in [1e-15, 0.5]", kind: Kind::Number { default: Some(tolerance::ACCURACY), set: |a, x| a.tolerance = x } },
    ],
    blank: || ViscoArgs {
        model: ViscoModel::KelvinVoigtFlat,
        damping_ratio: None,
        viscous_parameter: None,
        modulus_ratio: None,
        damping: None,
        damping_exponent: None,
        alpha: None,
        poisson_ratio: None,
        bulk_damping_ratio: None,
        tolerance: f64::NAN,
    },
    compute: |a| visco(a, Naming::Keywords).map_err(single),
};

/// `penalty`.
pub static PENALTY: Model<PenaltyArgs, tabor::single::penalty::Penalty> = Model {
    name: "penalty",
    inputs: &[
        Input {
            name: "law",
            help: "the penalty contact law",
            kind: Kind::Choice {
                menu: menu::<PenaltyLaw>,
                default: None,
                set: |a, k| {
                    a.law = k.parse()?;
                    Ok(())
                },
            },
        },
        Input {
            name: "restitution",
            help: "nominal restitution e, in (0, 1]",
            kind: Kind::Number {
                default: None,
                set: |a, x| a.restitution = x,
            },
        },
        Input {
            name: "stiffness",
            help: "stiffness K (N/m^n; N/m for the characteristic)",
            kind: Kind::Number {
                default: Some(1e7),
                set: |a, x| a.stiffness = x,
            },
        },
        Input {
            name: "exponent",
            help: "force exponent n of K δⁿ (default 1.5; the characteristic is linear)",
            kind: Kind::Optional {
                set: |a, x| a.exponent = x,
            },
        },
        Input {
            name: "rounding",
            help: "rounding half-width ε of the characteristic (m)",
            kind: Kind::Number {
                default: Some(0.0),
                set: |a, x| a.rounding = x,
            },
        },
        Input {
            name: "mass",
            help: "effective mass (kg)",
            kind: Kind::Number {
                default: Some(1.0),
                set: |a, x| a.mass = x,
            },
        },
        Input {
            name: "speed",
            help: "impact speed v0 (m/s)",
            kind: Kind::Number {
                default: Some(1.0),
                set: |a, x| a.speed = x,
            },
        },
    ],
    blank: || PenaltyArgs {
        law: PenaltyLaw::HuntCrossley,
        restitution: f64::NAN,
        stiffness: f64::NAN,
        exponent: None,
        rounding: f64::NAN,
        mass: f64::NAN,
        speed: f64::NAN,
    },
    compute: |a| penalty(a, Naming::Keywords).map_err(single),
};

// ---------------------------------------------------------------------------------
// the tables in Python

fn spec<'py, A>(py: Python<'py>, inputs: &[Input<A>]) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for i in inputs {
        let none = py.None().into_bound(py);
        let (kind, default, choices): (&str, Bound<'py, PyAny>, Bound<'py, PyAny>) = match &i.kind {
            Kind::Number { default, .. } => (
                "number",
                default.into_pyobject(py)?.into_any(),
                none.clone(),
            ),
            Kind::Optional { .. } => ("optional", none.clone(), none.clone()),
            Kind::Flag { .. } => (
                "flag",
                false.into_pyobject(py)?.to_owned().into_any(),
                none.clone(),
            ),
            Kind::Choice { default, menu, .. } => (
                "choice",
                default.map(|d| d()).into_pyobject(py)?.into_any(),
                PyTuple::new(py, menu())?.into_any(),
            ),
        };
        list.append((i.name, kind, default, choices, i.help))?;
    }
    Ok(list)
}

/// `{name: [(keyword, kind, default, choices, help), …]}` for the Python layer.
pub fn specs(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    d.set_item(EFFECTIVE.name, spec(py, EFFECTIVE.inputs)?)?;
    d.set_item(JKR.name, spec(py, JKR.inputs)?)?;
    d.set_item(PLASTIC.name, spec(py, PLASTIC.inputs)?)?;
    d.set_item(VISCO.name, spec(py, VISCO.inputs)?)?;
    d.set_item(PENALTY.name, spec(py, PENALTY.inputs)?)?;
    Ok(d)
}

// ---------------------------------------------------------------------------------
// running a model over a batch

fn type_error(name: &str, what: &str, value: &Bound<'_, PyAny>) -> PyErr {
    let t = value
        .get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "?".into());
    PyTypeError::new_err(format!("{name} must be {what}, not {t}"))
}

/// The choice `value` of keyword `name`: its name on `menu`.
fn choose(
    name: &str,
    value: &Bound<'_, PyAny>,
    menu: &[(&'static str, &'static str)],
) -> PyResult<&'static str> {
    let text: String = value
        .extract::<String>()
        .map_err(|_| type_error(name, "a str", value))?;
    let wanted = text.replace('_', "-");
    menu.iter()
        .map(|(c, _)| *c)
        .find(|c| *c == wanted)
        .ok_or_else(|| {
            let list: Vec<String> = menu.iter().map(|(c, _)| format!("\"{c}\"")).collect();
            Failure::input(format!(
                "invalid {name} = \"{text}\": expected one of {}",
                list.join(", ")
            ))
            .into_pyerr_static()
        })
}

/// A keyword's value for one element.
enum Given<'a> {
    Number(Col<'a>),
    Optional(Option<Col<'a>>),
}

impl<'a> Given<'a> {
    /// The column, when given.
    fn column(&self) -> Option<Col<'a>> {
        match self {
            Given::Number(c) | Given::Optional(Some(c)) => Some(*c),
            Given::Optional(None) => None,
        }
    }
}

/// The scalars of a call set in `base`, and its array keywords (index into the
/// table, array).
struct Parsed<'py, A> {
    base: A,
    arrays: Vec<(usize, PyReadonlyArray1<'py, f64>)>,
}

fn parse<'py, A: 'static, R>(
    model: &Model<A, R>,
    args: &Bound<'py, PyDict>,
) -> PyResult<Parsed<'py, A>> {
    let mut base = (model.blank)();
    let mut arrays: Vec<(usize, PyReadonlyArray1<'py, f64>)> = Vec::new();
    for (k, input) in model.inputs.iter().enumerate() {
        let value = args.get_item(input.name)?;
        match &input.kind {
            Kind::Number { .. } | Kind::Optional { .. } => {
                if let Some(v) = value.filter(|v| !v.is_none()) {
                    let a: PyReadonlyArray1<'py, f64> = v
                        .extract()
                        .map_err(|_| type_error(input.name, "a float64 array", &v))?;
                    arrays.push((k, a));
                } else if matches!(input.kind, Kind::Number { .. }) {
                    return Err(PyTypeError::new_err(format!(
                        "{}() missing the keyword argument {}",
                        model.name, input.name
                    )));
                }
            }
            Kind::Flag { set } => {
                let b = match value {
                    None => false,
                    Some(v) => v
                        .cast::<pyo3::types::PyBool>()
                        .map_err(|_| type_error(input.name, "True or False", &v))?
                        .is_true(),
                };
                set(&mut base, b);
            }
            Kind::Choice { menu, default, set } => {
                let k = match (value, default) {
                    (Some(v), _) => choose(input.name, &v, &menu())?,
                    (None, Some(d)) => d(),
                    (None, None) => {
                        return Err(PyTypeError::new_err(format!(
                            "{}() missing the keyword argument {}",
                            model.name, input.name
                        )))
                    }
                };
                set(&mut base, k).map_err(|e| {
                    Failure::input(format!("invalid {} = \"{k}\": {e}", input.name))
                        .into_pyerr_static()
                })?;
            }
        }
    }
    Ok(Parsed { base, arrays })
}

/// The number keywords of a call: (index into the table, its column).
fn given<'a, A: 'static, R>(
    model: &Model<A, R>,
    parsed: &'a Parsed<'_, A>,
    call: &Call<'_>,
) -> PyResult<Vec<(usize, Given<'a>)>> {
    let named: Vec<(&str, &PyReadonlyArray1<'_, f64>)> = parsed
        .arrays
        .iter()
        .map(|(k, a)| (model.inputs[*k].name, a))
        .collect();
    let cols = call.columns(&named)?;
    let mut given = Vec::new();
    for (k, input) in model.inputs.iter().enumerate() {
        let pos = parsed.arrays.iter().position(|(j, _)| *j == k);
        match &input.kind {
            Kind::Number { .. } => {
                if let Some(p) = pos {
                    given.push((k, Given::Number(cols[p])));
                }
            }
            Kind::Optional { .. } => given.push((k, Given::Optional(pos.map(|p| cols[p])))),
            _ => {}
        }
    }
    Ok(given)
}

/// The inputs of element `i`.
fn element<A: Clone>(inputs: &[Input<A>], base: &A, given: &[(usize, Given<'_>)], i: usize) -> A {
    let mut a = base.clone();
    for (k, g) in given {
        match (&inputs[*k].kind, g) {
            (Kind::Number { set, .. }, Given::Number(c)) => set(&mut a, c.at(i)),
            (Kind::Optional { set }, Given::Optional(c)) => set(&mut a, c.map(|c| c.at(i))),
            _ => {}
        }
    }
    a
}

fn run_model<'py, A: Sync + Clone + 'static, R: serde::Serialize>(
    py: Python<'py>,
    model: &Model<A, R>,
    args: &Bound<'py, PyDict>,
    call: &Call<'_>,
) -> PyResult<Bound<'py, PyTuple>> {
    let parsed = parse(model, args)?;
    let given = given(model, &parsed, call)?;
    let (inputs, compute, base) = (model.inputs, model.compute, &parsed.base);
    call.records(py, |i, out| {
        push(out, &compute(&element(inputs, base, &given, i))?)
    })
}

/// The own fields of one element of a [`Split`] model: from the prepared part,
/// the varying input and the previous element's own fields.
pub type OwnFn<P, V> = fn(&P, Option<f64>, Option<&V>) -> Result<Option<V>, Failure>;

/// A model whose record splits into a part that depends on all inputs but
/// `varying` (computed once per distinct set of them: a batch over speeds pays for
/// the model once) and the fields of each element's own.
pub struct Split<A: 'static, P: 'static, R: 'static, V: 'static> {
    /// The keyword of the element's own fields (a number or optional number).
    pub varying: &'static str,
    /// Validates the other inputs and computes the shared part.
    pub prepare: fn(&A) -> Result<P, Failure>,
    /// The shared part's record (the own fields unset).
    pub record: fn(&P) -> &R,
    /// The element's own fields from the varying input (None when it is not
    /// given) and the previous element's own fields when it shares the prepared
    /// part (a warm start).
    pub own: OwnFn<P, V>,
}

fn run_split<'py, A, P, R, V>(
    py: Python<'py>,
    model: &Model<A, R>,
    split: &Split<A, P, R, V>,
    args: &Bound<'py, PyDict>,
    call: &Call<'_>,
) -> PyResult<Bound<'py, PyTuple>>
where
    A: Sync + Clone + 'static,
    P: Send,
    R: serde::Serialize,
    V: OwnFields + Copy,
{
    let parsed = parse(model, args)?;
    let given = given(model, &parsed, call)?;
    // the columns that can change the shared part (a broadcast scalar cannot)
    let key: Vec<Col<'_>> = given
        .iter()
        .filter(|(k, _)| model.inputs[*k].name != split.varying)
        .filter_map(|(_, g)| g.column())
        .filter(|c| c.0.len() > 1)
        .collect();
    let varying: Option<Col<'_>> = given
        .iter()
        .find(|(k, _)| model.inputs[*k].name == split.varying)
        .and_then(|(_, g)| g.column());
    let (inputs, base) = (model.inputs, &parsed.base);
    call.split_columns(
        py,
        |i, j| key.iter().all(|c| c.at(i).to_bits() == c.at(j).to_bits()),
        |i| key.iter().map(|c| c.at(i).to_bits()).collect(),
        |i| (split.prepare)(&element(inputs, base, &given, i)),
        split.record,
        |p, i, near| (split.own)(p, varying.map(|c| c.at(i)), near),
    )
}

/// `_tabor.model(name, args, shape, errors, threads)`: the model `name` over the
/// flat float64 arrays (length 1 or n) and scalars of `args`.
#[pyfunction]
#[pyo3(signature = (name, args, n, shape, errors="raise", threads=None))]
pub fn model<'py>(
    py: Python<'py>,
    name: &str,
    args: &Bound<'py, PyDict>,
    n: usize,
    shape: Vec<usize>,
    errors: &str,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyTuple>> {
    let call = Call {
        n,
        shape: &shape,
        options: Options::new(errors, threads)?,
    };
    match name {
        "effective" => run_model(py, &EFFECTIVE, args, &call),
        "jkr" => run_split(py, &JKR, &JKR_BY_SPEED, args, &call),
        "plastic" => run_model(py, &PLASTIC, args, &call),
        "visco" => run_model(py, &VISCO, args, &call),
        "penalty" => run_model(py, &PENALTY, args, &call),
        other => Err(PyTypeError::new_err(format!("no model function {other}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The positional fields of `JkrAtSpeed` are its serde fields, in order.
    #[test]
    fn jkr_own_fields_are_the_serde_fields() {
        let v = JkrAtSpeed {
            impact_speed: 1.0,
            max_contact_radius: 2.0,
            restitution: 0.5,
            sticks: false,
        };
        let names: Vec<&str> = JkrAtSpeed::FIELDS.iter().map(|(n, _)| *n).collect();
        assert_eq!(crate::columns::field_names(&v), names);
    }
}

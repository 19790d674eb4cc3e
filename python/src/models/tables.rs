//! The tables: one per model, each keyword once, with its kind, default and help
//! line; and the errors of the library renamed to the keywords.

use super::{Input, Kind, Model, Split};
use crate::columns::{OwnFields, OwnKind};
use crate::failure::Failure;
use tabor::jkr::SeparationRule;
use tabor::numerics::tolerance;
use tabor::restitution::{Error, Menu};
use tabor::single::effective::{effective, EffectiveArgs};
use tabor::single::jkr::{jkr, prepare as prepare_jkr, JkrArgs, JkrAtSpeed, JkrPrepared};
use tabor::single::penalty::{penalty, PenaltyArgs, PenaltyLaw};
use tabor::single::plastic::{plastic, PlasticArgs, PlasticModel};
use tabor::single::visco::{visco, ViscoArgs, ViscoModel};
use tabor::single::{input_name, Naming};

/// Every choice of menu `M`: (name, description).
pub(super) fn menu<M: Menu>() -> Vec<(&'static str, &'static str)> {
    M::ALL
        .iter()
        .map(|m| (m.as_str(), m.description()))
        .collect()
}

/// A library error with its parameter named as the keyword that gives it.
pub(super) fn library(e: Error) -> Failure {
    let message = match &e {
        Error::InvalidParameter {
            parameter,
            value,
            requirement,
        } => format!(
            "invalid {} = {}: {requirement}",
            Naming::Keywords.input(input_name(parameter)),
            tabor::numerics::readable::plain(*value)
        ),
        other => other.to_string(),
    };
    Failure::library(&e, message)
}

pub(super) fn single(e: tabor::single::Error) -> Failure {
    match e {
        tabor::single::Error::Library(e) => library(e),
        tabor::single::Error::Input(m) => Failure::input(m),
    }
}

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
            name: tabor::single::PYTHON_CONTACT_MODULUS,
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
        Input { name: tabor::single::PYTHON_CONTACT_MODULUS, help: "effective modulus E* (Pa)", kind: Kind::Number { default: None, set: |a, x| a.modulus = x } },
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

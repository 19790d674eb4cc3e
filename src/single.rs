//! The single-model computations behind the command-line subcommands (`tabor jkr`,
//! …) and the Python package's functions of the same names: for each model a plain
//! value type of its inputs, named like the flags, and a function that validates
//! them and computes the result record (a [`Serialize`](serde::Serialize) struct,
//! printed by the CLI as a table or JSON, turned into columns by Python).
//!
//! A bad input is reported as the library's
//! [`Error`](crate::restitution::Error) (which names the library parameter, e.g.
//! `effective_modulus`); [`INPUT_NAMES`] is the one table from those names to the
//! inputs' names, and [`Naming`] spells an input as each front end does
//! (`--modulus` on the command line, `modulus` in Python): [`Error::render`].

pub mod effective;
pub mod jkr;
pub mod penalty;
pub mod plastic;
pub mod visco;

use crate::restitution;

/// The library's parameter names (as [`restitution::Error::InvalidParameter`]
/// spells them) and the input (flag or keyword, snake_case) that gives each: the
/// one table of every front end (`--modulus` on the command line, `modulus` in
/// Python, through [`Naming::input`]). `effective` names its own inputs, as they
/// differ between the two bodies. A name without an entry is its own input.
pub const INPUT_NAMES: &[(&str, &str)] = &[
    ("effective_modulus", "modulus"),
    ("effective_radius", "radius"),
    ("effective_mass", "mass"),
    ("impact_speed", "speed"),
    ("shear_damping_ratio", "damping_ratio"),
    ("tabor_parameter_mu", "tabor_mu"),
];

/// The Python keyword of the effective (contact) modulus E*: `contact_modulus`,
/// the name of the Adhesion package's JKR solutions; the command line keeps
/// `--modulus`.
pub const PYTHON_CONTACT_MODULUS: &str = "contact_modulus";

/// The input that gives the library parameter `parameter` ([`INPUT_NAMES`]).
pub fn input_name(parameter: &str) -> &str {
    INPUT_NAMES
        .iter()
        .find(|(library, _)| *library == parameter)
        .map_or(parameter, |(_, input)| input)
}

/// How a front end names the inputs in messages and warnings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Naming {
    /// Command-line flags: `--poisson-ratio`, `--model jackson-green`.
    Flags,
    /// Python keyword arguments: `poisson_ratio`, `model="jackson-green"`.
    Keywords,
}

impl Naming {
    /// A library error as one line, its bad parameter named as this front end
    /// spells the input.
    pub fn library_error(self, e: restitution::Error) -> String {
        match e {
            restitution::Error::InvalidParameter {
                parameter,
                value,
                requirement,
            } => format!(
                "invalid {} = {}: {requirement}",
                self.parameter(parameter),
                crate::numerics::readable::plain(value)
            ),
            other => other.to_string(),
        }
    }

    /// The input `name` (snake_case) as this front end spells it.
    pub fn input(self, name: &str) -> String {
        match self {
            Naming::Flags => format!("--{}", name.replace('_', "-")),
            // Python spells the effective modulus E* as the Adhesion package's
            // JKR does: one name for the quantity across the package
            Naming::Keywords if name == "modulus" => PYTHON_CONTACT_MODULUS.to_string(),
            Naming::Keywords => name.to_string(),
        }
    }

    /// The library parameter `parameter` as this front end spells its input.
    pub fn parameter(self, parameter: &str) -> String {
        self.input(input_name(parameter))
    }

    /// A choice `value` mentioned on its own: as is for flags, quoted for keywords.
    pub fn value(self, value: &str) -> String {
        match self {
            Naming::Flags => value.to_string(),
            Naming::Keywords => format!("\"{value}\""),
        }
    }

    /// The choice `value` of the input `name` (snake_case) as this front end
    /// spells it.
    pub fn choice(self, name: &str, value: &str) -> String {
        match self {
            Naming::Flags => format!("{} {value}", self.input(name)),
            Naming::Keywords => format!("{name}=\"{value}\""),
        }
    }
}

/// Why a single-model computation failed.
#[derive(Debug)]
pub enum Error {
    /// A library error (a bad parameter is named as the library spells it; the
    /// front end renames it).
    Library(restitution::Error),
    /// A problem with the inputs, already worded in the front end's [`Naming`].
    Input(String),
}

impl From<restitution::Error> for Error {
    fn from(e: restitution::Error) -> Self {
        Error::Library(e)
    }
}

impl Error {
    /// One line, a library error's parameter named as `naming` spells the input
    /// ([`Naming::library_error`]).
    pub fn render(self, naming: Naming) -> String {
        self.message(|e| naming.library_error(e))
    }

    /// One line: `library` renders a library error, an input problem is as is.
    pub fn message(self, library: impl FnOnce(restitution::Error) -> String) -> String {
        match self {
            Error::Library(e) => library(e),
            Error::Input(m) => m,
        }
    }
}
/// `value`, or the error that `model` needs the input `name`.
pub(crate) fn required(
    value: Option<f64>,
    name: &str,
    model: impl std::fmt::Display,
    naming: Naming,
) -> Result<f64, Error> {
    value.ok_or_else(|| {
        Error::Input(format!(
            "missing {}: required by {}",
            naming.input(name),
            naming.choice("model", &model.to_string())
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_library_name_has_one_input() {
        for (i, (name, _)) in INPUT_NAMES.iter().enumerate() {
            assert!(
                INPUT_NAMES[i + 1..].iter().all(|(other, _)| other != name),
                "{name} twice"
            );
        }
        assert_eq!(Naming::Flags.parameter("effective_modulus"), "--modulus");
        assert_eq!(Naming::Keywords.parameter("impact_speed"), "speed");
        assert_eq!(Naming::Flags.parameter("tabor_parameter_mu"), "--tabor-mu");
        let e = restitution::Error::invalid("effective_mass", -1.0, "must be > 0");
        assert_eq!(
            Error::from(e.clone()).render(Naming::Flags),
            "invalid --mass = -1: must be > 0"
        );
        assert_eq!(
            Error::from(e).render(Naming::Keywords),
            "invalid mass = -1: must be > 0"
        );
    }
}

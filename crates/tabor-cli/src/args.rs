//! Arguments shared by the subcommands, spelled by the library rather than here:
//!
//! - choice flags (`--model`, `--law`, `--separation`, …) parsed by the library's
//!   menus: the names, their order and their one-line help come from the model
//!   crate's enum (`ALL`, `as_str`, `description`, `FromStr`);
//! - `--tolerance` values ([`Tolerance`]), whose defaults are the constants of
//!   `tabor::numerics::tolerance`.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use tabor::restitution::Menu;
use tabor::single::Naming;

/// A value parser over `choices` (a menu's `ALL` or a part of it), each choice
/// with its description and `extra` help (e.g. the flags it needs).
pub fn menu<T: Menu + Clone>(
    choices: &'static [T],
    extra: impl Fn(T) -> String,
) -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(choices.iter().map(|&c| {
        let more = extra(c);
        let help = if more.is_empty() {
            c.description().to_string()
        } else {
            format!("{}; {more}", c.description())
        };
        PossibleValue::new(c.as_str()).help(help)
    }))
    .try_map(|name| T::parse_choice(&name))
}

/// `needs --a, --b` for the snake_case input names `inputs` ("" for none).
pub fn needs(inputs: &[&str]) -> String {
    if inputs.is_empty() {
        return String::new();
    }
    let flags: Vec<String> = inputs.iter().map(|i| Naming::Flags.input(i)).collect();
    format!("needs {}", flags.join(", "))
}

/// A `--tolerance` value: a relative tolerance, printed in exponent form (so that
/// `--help` shows the default as `1e-12`); range-checked by the library.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance(pub f64);

impl std::str::FromStr for Tolerance {
    type Err = std::num::ParseFloatError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        s.parse().map(Tolerance)
    }
}

impl std::fmt::Display for Tolerance {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:e}", self.0)
    }
}

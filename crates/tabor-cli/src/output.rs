//! Printing results: aligned `key  value` lines for people, one JSON object for
//! programs, CSV through the `csv` crate; the one table from library parameter
//! names to flags; and the quiet end on a closed pipe.
//!
//! Conventions (documented in the crate README):
//!
//! - numbers are printed in Rust's shortest round-trip form (`{:e}` for tables,
//!   `ryu` in JSON, [`number`] in CSV), so a value read back is the value computed;
//! - every JSON object carries `tabor_version`, every CSV row a last column
//!   `tabor_version`;
//! - CSV headers are snake_case names; a dimensional quantity ends in its SI unit
//!   (`speed_m_per_s`, `energy_loss_j`), a dimensionless one has no suffix.

use serde::Serialize;
use std::fmt;
use std::io::{self, BufWriter, Stdout, Write};

/// The tabor version written into every output.
pub const VERSION: &str = tabor::VERSION;

/// Why a subcommand stopped: bad input or a failed computation (one line on
/// stderr, exit 2), or stdout closed by its reader (quiet end).
#[derive(Debug)]
pub enum Failure {
    /// One line for stderr.
    Message(String),
    /// Stdout was closed (`tabor … | head -1`): nothing more to say.
    ClosedPipe,
}

impl From<String> for Failure {
    fn from(message: String) -> Self {
        Failure::Message(message)
    }
}

impl From<&str> for Failure {
    fn from(message: &str) -> Self {
        Failure::Message(message.to_string())
    }
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Self {
        if e.kind() == io::ErrorKind::BrokenPipe {
            Failure::ClosedPipe
        } else {
            Failure::Message(format!("cannot write to stdout: {e}"))
        }
    }
}

impl From<csv::Error> for Failure {
    fn from(e: csv::Error) -> Self {
        match e.into_kind() {
            csv::ErrorKind::Io(e) => e.into(),
            other => Failure::Message(format!("cannot write CSV: {other:?}")),
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::Message(m) => f.write_str(m),
            Failure::ClosedPipe => f.write_str("stdout closed"),
        }
    }
}

/// What a subcommand returns.
pub type Outcome = Result<(), Failure>;

/// Buffered stdout; write with `writeln!` and `?` (a closed pipe becomes
/// [`Failure::ClosedPipe`]); call [`Out::finish`] at the end to flush.
pub struct Out(BufWriter<Stdout>);

impl Out {
    /// Flushes; a closed pipe is reported, not panicked on.
    pub fn finish(mut self) -> Outcome {
        self.0.flush()?;
        Ok(())
    }
}

impl Write for Out {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.0.write(buf)
    }
    fn flush(&mut self) -> io::Result<()> {
        self.0.flush()
    }
}

/// Stdout, buffered.
pub fn stdout() -> Out {
    Out(BufWriter::new(io::stdout()))
}

/// A value with the tabor version as an extra first field.
#[derive(Serialize)]
struct Versioned<'a, T: Serialize> {
    tabor_version: &'static str,
    #[serde(flatten)]
    value: &'a T,
}

/// Prints `value` (a struct or map) as one pretty JSON object on stdout, with a
/// `tabor_version` field.
pub fn print_json<T: Serialize>(value: &T) -> Outcome {
    let text = serde_json::to_string_pretty(&Versioned {
        tabor_version: VERSION,
        value,
    })
    .map_err(|e| e.to_string())?;
    let mut out = stdout();
    writeln!(out, "{text}")?;
    out.finish()
}

/// Prints `values` as a pretty JSON array of objects, each with a
/// `tabor_version` field.
pub fn print_json_array<T: Serialize>(values: &[T]) -> Outcome {
    let versioned: Vec<_> = values
        .iter()
        .map(|value| Versioned {
            tabor_version: VERSION,
            value,
        })
        .collect();
    let text = serde_json::to_string_pretty(&versioned).map_err(|e| e.to_string())?;
    let mut out = stdout();
    writeln!(out, "{text}")?;
    out.finish()
}

/// Prints `(name, value, unit)` rows aligned, each value in shortest round-trip
/// form (`{:e}`).
pub fn print_table(out: &mut Out, rows: &[(&str, f64, &str)]) -> Outcome {
    let width = rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
    for (name, value, unit) in rows {
        let value = format!("{value:e}");
        writeln!(out, "{name:<width$}  {value:<24} {unit}")?;
    }
    Ok(())
}

/// A number for a CSV field, in shortest round-trip form: plain decimal
/// (`0.505`) for magnitudes in [1e-5, 1e16), exponent form (`2.775e-19`)
/// otherwise; either reads back as the same f64.
pub fn number(value: f64) -> String {
    let magnitude = value.abs();
    if magnitude == 0.0 || (1e-5..1e16).contains(&magnitude) || !value.is_finite() {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// An optional number for a CSV field: empty when absent.
pub fn optional(value: Option<f64>) -> String {
    value.map_or(String::new(), number)
}

/// The library's parameter names (as `tabor_restitution::Error::InvalidParameter`
/// spells them) in the spelling of the flags: the one table of every subcommand
/// that takes model inputs (`effective` names its own, as its flags differ between
/// the two bodies). A name without an entry is printed as the library spells it.
const FLAGS: &[(&str, &str)] = &[
    ("effective_modulus", "--modulus"),
    ("effective_radius", "--radius"),
    ("effective_mass", "--mass"),
    ("mass", "--mass"),
    ("work_of_adhesion", "--work-of-adhesion"),
    ("impact_speed", "--speed"),
    ("tolerance", "--tolerance"),
    ("yield_stress", "--yield-stress"),
    ("poisson_ratio", "--poisson-ratio"),
    ("density", "--density"),
    ("adhesion_parameter", "--adhesion-parameter"),
    ("restitution", "--restitution"),
    ("stiffness", "--stiffness"),
    ("exponent", "--exponent"),
    ("rounding", "--rounding"),
    ("damping_ratio", "--damping-ratio"),
    ("shear_damping_ratio", "--damping-ratio"),
    ("viscous_parameter", "--viscous-parameter"),
    ("modulus_ratio", "--modulus-ratio"),
    ("damping", "--damping"),
    ("damping_exponent", "--damping-exponent"),
    ("alpha", "--alpha"),
    ("bulk_damping_ratio", "--bulk-damping-ratio"),
    ("maugis_parameter", "--maugis-parameter"),
    ("tabor_parameter_mu", "--tabor-mu"),
];

/// The flag of a library parameter name (the name itself if the table has none).
pub fn flag(parameter: &str) -> &str {
    FLAGS
        .iter()
        .find(|(name, _)| *name == parameter)
        .map_or(parameter, |(_, flag)| flag)
}

/// A library error as one line, naming the flag of a bad parameter.
pub fn message(e: tabor::restitution::Error) -> String {
    match e {
        tabor::restitution::Error::InvalidParameter {
            parameter,
            value,
            requirement,
        } => format!("invalid {} = {value:e}: {requirement}", flag(parameter)),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_has_one_flag() {
        for (i, (name, _)) in FLAGS.iter().enumerate() {
            assert!(
                FLAGS[i + 1..].iter().all(|(other, _)| other != name),
                "{name} twice"
            );
        }
        assert_eq!(flag("effective_modulus"), "--modulus");
        assert_eq!(flag("unknown_name"), "unknown_name");
    }

    #[test]
    fn numbers_round_trip() {
        for x in [
            0.1,
            1.0 / 3.0,
            6.02214076e23,
            -2.2250738585072014e-308,
            5e-324,
        ] {
            assert_eq!(number(x).parse::<f64>().ok(), Some(x));
            assert_eq!(format!("{x:e}").parse::<f64>().ok(), Some(x));
        }
    }
}

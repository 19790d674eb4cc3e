//! Printing results: aligned `key  value` lines for people, one JSON object for
//! programs, CSV through the `csv` crate; library errors with the flag of the bad
//! parameter; and the quiet end on a closed pipe.
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
pub use tabor::numerics::readable::{human, humanize, meaningful_digits, READABLE_DIGITS};
use tabor::single::Naming;

/// The rounding of a text report: values at the digits a result's relative
/// accuracy supports ([`meaningful_digits`]), with SI prefixes ([`human`]), and
/// the numbers inside messages rounded alike ([`humanize`]).
#[derive(Clone, Copy, Debug)]
pub struct Rounding {
    digits: usize,
}

impl Rounding {
    /// The rounding for a result of relative accuracy `accuracy`.
    pub fn at(accuracy: f64) -> Self {
        Rounding {
            digits: meaningful_digits(accuracy),
        }
    }

    /// `value` in `unit`, rounded.
    pub fn value(&self, value: f64, unit: &str) -> String {
        human(value, unit, self.digits)
    }

    /// `text` with every number in it rounded.
    pub fn text(&self, text: &str) -> String {
        humanize(text, self.digits)
    }
}

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

/// `value` (a struct or map) as one pretty JSON object with a `tabor_version`
/// field: the one JSON shape of a command, whether printed or written to a file.
pub fn json_text<T: Serialize>(value: &T) -> Result<String, Failure> {
    Ok(serde_json::to_string_pretty(&Versioned {
        tabor_version: VERSION,
        value,
    })
    .map_err(|e| e.to_string())?)
}

/// Prints `value` (a struct or map) as one pretty JSON object on stdout, with a
/// `tabor_version` field ([`json_text`]).
pub fn print_json<T: Serialize>(value: &T) -> Outcome {
    let text = json_text(value)?;
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

/// Prints a single-model result, the one shape of every model subcommand: with
/// `--json` (`json`) the object `value` ([`print_json`]), else the `header`
/// lines (`model   thornton`), the aligned `rows` ([`print_table`]) and a
/// `warning: …` line per warning.
pub fn print_result<T: Serialize>(
    json: bool,
    value: &T,
    header: &[String],
    rows: &[(&str, f64, &str)],
    warnings: &[String],
) -> Outcome {
    if json {
        return print_json(value);
    }
    let mut out = stdout();
    for line in header {
        writeln!(out, "{line}")?;
    }
    print_table(&mut out, rows)?;
    for w in warnings {
        writeln!(out, "warning: {}", humanize(w, READABLE_DIGITS))?;
    }
    out.finish()
}

/// Prints `(name, value, unit)` rows aligned, each value for people
/// ([`human`], [`READABLE_DIGITS`] significant digits; `--json` has every digit).
pub fn print_table(out: &mut Out, rows: &[(&str, f64, &str)]) -> Outcome {
    let width = rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
    for (name, value, unit) in rows {
        let value = human(*value, unit, READABLE_DIGITS);
        writeln!(out, "{name:<width$}  {}", value.trim_end())?;
    }
    Ok(())
}

/// A number for a CSV field, in shortest round-trip form
/// (`tabor::numerics::readable::plain`: `0.505`, `2.775e-19`); it reads back as
/// the same f64.
pub fn number(value: f64) -> String {
    tabor::numerics::readable::plain(value)
}

/// An optional number for a CSV field: empty when absent.
pub fn optional(value: Option<f64>) -> String {
    value.map_or(String::new(), number)
}

/// A library error as one line, naming the flag of a bad parameter (the one
/// name table is `tabor::single::INPUT_NAMES`).
pub fn message(e: tabor::restitution::Error) -> String {
    Naming::Flags.library_error(e)
}

#[cfg(test)]
mod tests {
    use super::*;

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

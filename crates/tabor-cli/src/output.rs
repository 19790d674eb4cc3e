//! Printing results: aligned `key  value` lines for people, one JSON object for
//! programs.

use serde::Serialize;

/// Prints `value` as one pretty JSON object on stdout.
pub fn print_json<T: Serialize>(value: &T) -> Result<(), String> {
    let text = serde_json::to_string_pretty(value).map_err(|e| e.to_string())?;
    println!("{text}");
    Ok(())
}

/// Prints `(name, value, unit)` rows aligned, with 15 significant digits.
pub fn print_table(rows: &[(&str, f64, &str)]) {
    let width = rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
    for (name, value, unit) in rows {
        println!("{name:<width$}  {value:<24.15e} {unit}");
    }
}

//! Shared by the bad-input tests (`bad_input.rs`, `bad_input_scenes.rs`): running
//! the `tabor` binary, the check of a one-line error (exit code 2, one `error:`
//! line, no panic) and of clap's usage errors, and the bad numbers every flag is
//! given.

use std::process::{Command, Output};

pub fn tabor(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .env("RUST_BACKTRACE", "1")
        .output()
        .expect("the tabor binary runs")
}

/// Exit code 2, exactly one non-empty stderr line starting with `error:`, no panic,
/// nothing on stdout; returns the line.
pub fn one_line_error(args: &[&str]) -> String {
    let out = tabor(args);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{args:?}: exit {:?}, stderr {stderr}",
        out.status
    );
    assert!(
        !stderr.contains("panicked") && !stderr.contains("backtrace"),
        "{args:?}: panic: {stderr}"
    );
    let lines: Vec<&str> = stderr.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "{args:?}: not one line: {stderr}");
    assert!(lines[0].starts_with("error: "), "{args:?}: {stderr}");
    assert!(lines[0].len() > "error: ".len() + 10, "{args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "{args:?}: stdout {:?}", out.stdout);
    lines[0].to_string()
}

/// Argument-syntax errors (clap): exit code 2, an `error:` first line, no panic.
/// (clap adds a usage hint below its first line.)
pub fn usage_error(args: &[&str]) {
    let out = tabor(args);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert!(stderr.starts_with("error: "), "{args:?}: {stderr}");
}

/// `--flag=value` as one argument.
pub fn kv(flag: &str, value: &str) -> &'static str {
    Box::leak(format!("{flag}={value}").into_boxed_str())
}

pub const BAD_NUMBERS: [&str; 6] = ["-1", "0", "nan", "inf", "-inf", "1e999"];

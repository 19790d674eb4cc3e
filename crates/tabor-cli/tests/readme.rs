#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The README's examples cannot go stale: every ```console block of the
//! workspace README whose command is `$ tabor …` is run, and its output must be
//! what the README shows — exactly, line for line, or, where the README elides
//! with a line `...`, the README's lines must appear in the output in order.
//!
//! After a change that moves the printed numbers, regenerate the exact blocks
//! with `TABOR_BLESS_README=1 cargo test -p tabor-cli --test readme` and review
//! the diff (elided blocks are checked, never rewritten).

use std::path::Path;
use std::process::Command;

/// A ```console block: its command (without `$ `), the output shown, and the
/// line range of that output in the README.
struct Block {
    command: String,
    shown: Vec<String>,
    lines: std::ops::Range<usize>,
}

/// The ```console blocks of `text` that start with a `$ ` command line.
fn console_blocks(text: &str) -> Vec<Block> {
    let lines: Vec<&str> = text.lines().collect();
    let mut blocks = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        if lines[i].trim() == "```console" {
            if let Some(command) = lines.get(i + 1).and_then(|l| l.strip_prefix("$ ")) {
                let start = i + 2;
                let end = (start..lines.len())
                    .find(|&j| lines[j].trim() == "```")
                    .unwrap_or(lines.len());
                blocks.push(Block {
                    command: command.to_string(),
                    shown: lines[start..end].iter().map(|l| l.to_string()).collect(),
                    lines: start..end,
                });
                i = end;
            }
        }
        i += 1;
    }
    blocks
}

/// Whether `shown` (the README's lines, `...` eliding any number of lines) is
/// what `actual` printed.
fn matches(shown: &[String], actual: &[&str]) -> bool {
    if !shown.iter().any(|l| l.trim() == "...") {
        return shown.len() == actual.len() && shown.iter().zip(actual).all(|(s, a)| s == a);
    }
    let mut rest = actual.iter();
    shown
        .iter()
        .filter(|l| l.trim() != "...")
        .all(|s| rest.any(|a| a.trim_end_matches(',') == s.trim_end_matches(',')))
}

#[test]
fn readme_console_examples_are_what_tabor_prints() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let bless = std::env::var_os("TABOR_BLESS_README").is_some();
    let mut lines: Vec<String> = readme.lines().map(str::to_string).collect();
    let mut checked = 0;
    // from the last block, so that a rewritten block leaves the earlier ranges
    for block in console_blocks(&readme).iter().rev() {
        let Some(args) = block.command.strip_prefix("tabor ") else {
            continue;
        };
        let out = Command::new(env!("CARGO_BIN_EXE_tabor"))
            .args(args.split_whitespace())
            .current_dir(&root)
            .output()
            .unwrap();
        assert!(out.status.success(), "README: $ {}: {out:?}", block.command);
        // warnings go to stderr after the result; the README shows both
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        let actual: Vec<&str> = text.lines().collect();
        checked += 1;
        if matches(&block.shown, &actual) {
            continue;
        }
        let elided = block.shown.iter().any(|l| l.trim() == "...");
        if bless && !elided {
            lines.splice(block.lines.clone(), actual.iter().map(|l| l.to_string()));
            continue;
        }
        panic!(
            "README: $ {}\n--- shown ---\n{}\n--- printed ---\n{text}\n(regenerate: \
             TABOR_BLESS_README=1 cargo test -p tabor-cli --test readme)",
            block.command,
            block.shown.join("\n")
        );
    }
    if bless {
        let mut text = lines.join("\n");
        text.push('\n');
        if text != readme {
            std::fs::write(root.join("README.md"), text).unwrap();
        }
    }
    // the scene, the combined scene, effective, jkr, maugis-loss
    assert!(checked >= 5, "only {checked} README examples found");
}

#[test]
fn elision_matches_in_order_only() {
    let shown: Vec<String> = ["{", "  \"a\": 1,", "  ...", "}"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert!(matches(
        &shown,
        &["{", "  \"x\": 0,", "  \"a\": 1,", "  \"b\": 2", "}"]
    ));
    assert!(!matches(&shown, &["{", "  \"a\": 2,", "}"]));
    let exact = vec!["a".to_string(), "b".to_string()];
    assert!(matches(&exact, &["a", "b"]));
    assert!(!matches(&exact, &["a", "b", "c"]));
}

#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The README and the guide cannot go stale: every ```console block of the
//! workspace README and of every Markdown file under `docs/` whose command is
//! `$ tabor …` is run, and its output must be what the page shows — exactly,
//! line for line, or, where the page elides with a line `...`, the page's lines
//! must appear in the output in order; a block that shows only the command must
//! run successfully. Every ```toml block is a scene that `tabor impact` must
//! accept. In README.md and docs/guide/ every fenced block names its language,
//! one of those the tests run (`console`, `toml`; `rust`: doc tests of the facade
//! crate, `src/lib.rs`; `python`: `python/tests/test_guide.py`) or `text` (not run).
//!
//! After a change that moves the printed numbers, regenerate the exact blocks
//! with `TABOR_BLESS_README=1 cargo test -p tabor-cli --test readme` and review
//! the diff (elided blocks are checked, never rewritten).

use std::path::{Path, PathBuf};
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

/// The workspace root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// README.md and every `*.md` under `docs/`, as paths relative to the root.
fn pages(root: &Path) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for path in entries {
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    let mut out = vec![root.join("README.md")];
    walk(&root.join("docs"), &mut out);
    out.iter()
        .map(|p| p.strip_prefix(root).unwrap().to_path_buf())
        .collect()
}

/// The fenced blocks of `text`: (language, first line of the fence, lines inside).
fn fenced_blocks(text: &str) -> Vec<(String, usize, Vec<String>)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut blocks = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        if let Some(lang) = lines[i].trim_start().strip_prefix("```") {
            let end = (i + 1..lines.len())
                .find(|&j| lines[j].trim() == "```")
                .unwrap_or(lines.len());
            let inner = lines[i + 1..end].iter().map(|l| l.to_string()).collect();
            blocks.push((lang.trim().to_string(), i + 1, inner));
            i = end;
        }
        i += 1;
    }
    blocks
}

/// Runs `tabor` with `args` from the root; stdout then stderr (warnings go to
/// stderr after the result; the pages show both).
fn run_tabor(root: &Path, args: &[&str]) -> (std::process::Output, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .current_dir(root)
        .output()
        .unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out, text)
}

/// Checks (or, with `bless`, rewrites) the `$ tabor` blocks of one page; returns
/// how many it ran.
fn check_page(root: &Path, page: &Path, bless: bool) -> usize {
    let original = std::fs::read_to_string(root.join(page)).unwrap();
    let mut lines: Vec<String> = original.lines().map(str::to_string).collect();
    let mut checked = 0;
    // from the last block, so that a rewritten block leaves the earlier ranges
    for block in console_blocks(&original).iter().rev() {
        let Some(args) = block.command.strip_prefix("tabor ") else {
            continue;
        };
        let args: Vec<&str> = args.split_whitespace().collect();
        let (out, text) = run_tabor(root, &args);
        assert!(
            out.status.success(),
            "{}: $ {}: {out:?}",
            page.display(),
            block.command
        );
        let actual: Vec<&str> = text.lines().collect();
        checked += 1;
        // a block that shows only the command: it must run, its output is not shown
        if block.shown.iter().all(|l| l.trim().is_empty()) || matches(&block.shown, &actual) {
            continue;
        }
        let elided = block.shown.iter().any(|l| l.trim() == "...");
        if bless && !elided {
            lines.splice(block.lines.clone(), actual.iter().map(|l| l.to_string()));
            continue;
        }
        panic!(
            "{}: $ {}\n--- shown ---\n{}\n--- printed ---\n{text}\n(regenerate: \
             TABOR_BLESS_README=1 cargo test -p tabor-cli --test readme)",
            page.display(),
            block.command,
            block.shown.join("\n")
        );
    }
    if bless {
        let mut text = lines.join("\n");
        text.push('\n');
        if text != original {
            std::fs::write(root.join(page), text).unwrap();
        }
    }
    checked
}

#[test]
fn console_examples_are_what_tabor_prints() {
    let root = root();
    let bless = std::env::var_os("TABOR_BLESS_README").is_some();
    let mut checked = 0;
    let mut in_guide = 0;
    for page in pages(&root) {
        let n = check_page(&root, &page, bless);
        checked += n;
        if page.starts_with("docs/guide") {
            in_guide += n;
        }
    }
    // README: the scene; the guide: sticking, the combined scene, effective, jkr,
    // maugis-loss (two), the oblique scene, the two exports
    assert!(checked >= 9, "only {checked} `$ tabor` examples found");
    assert!(
        in_guide >= 8,
        "only {in_guide} `$ tabor` examples in docs/guide"
    );
}

#[test]
fn toml_blocks_are_scenes_tabor_accepts() {
    let root = root();
    let dir = std::env::temp_dir().join(format!("tabor-readme-toml-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut checked = 0;
    for page in pages(&root) {
        let text = std::fs::read_to_string(root.join(&page)).unwrap();
        for (lang, line, inner) in fenced_blocks(&text) {
            if lang != "toml" {
                continue;
            }
            let path = dir.join(format!("scene-{checked}.toml"));
            std::fs::write(&path, inner.join("\n") + "\n").unwrap();
            let (out, text) = run_tabor(&root, &["impact", path.to_str().unwrap()]);
            assert!(
                out.status.success(),
                "{}:{line}: the toml block is no scene tabor accepts:\n{text}",
                page.display()
            );
            checked += 1;
        }
    }
    std::fs::remove_dir_all(&dir).ok();
    assert!(checked >= 1, "no toml block found (the README's scene)");
}

#[test]
fn every_fenced_block_in_readme_and_guide_is_run_or_marked_text() {
    let root = root();
    const RUN_OR_TEXT: [&str; 5] = ["console", "toml", "rust", "python", "text"];
    for page in pages(&root) {
        if !(page == Path::new("README.md") || page.starts_with("docs/guide")) {
            continue;
        }
        let text = std::fs::read_to_string(root.join(&page)).unwrap();
        for (lang, line, inner) in fenced_blocks(&text) {
            assert!(
                RUN_OR_TEXT.contains(&lang.as_str()),
                "{}:{line}: fence language `{lang}`: use one the tests run ({:?}) or `text`",
                page.display(),
                &RUN_OR_TEXT[..4]
            );
            if lang == "console" {
                assert!(
                    inner.first().is_some_and(|l| l.starts_with("$ tabor ")),
                    "{}:{line}: a console block runs `$ tabor …`; other commands go in `text`",
                    page.display()
                );
            }
        }
    }
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

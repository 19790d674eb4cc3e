//! The Python package: `cargo xtask wheel` and the `python` step of
//! `cargo xtask test`.
//!
//! `wheel` builds the abi3 manylinux wheel of `python/` with maturin (installed
//! into `target/maturin-venv`) into `target/wheels/` and prints its path.
//!
//! The `python` step builds that wheel, then
//! 1. installs it into `target/python-venv` with the test requirements (numpy 2.x)
//!    and runs pytest;
//! 2. installs it into a fresh `target/python-wheel-venv` with numpy 1.x and runs
//!    pytest again with `PATH` stripped of every directory holding `cargo` or
//!    `rustc` (and `CARGO_HOME`, `RUSTUP_HOME` unset): the wheel works on a machine
//!    without Rust, with either numpy major version.
//!
//! pip's downloads are cached under `target/pip-cache`, the Rust build under
//! `target/python-build`.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The interpreter that creates the venvs (`TABOR_PYTHON`, default `python3`).
fn interpreter() -> String {
    std::env::var("TABOR_PYTHON").unwrap_or_else(|_| "python3".into())
}

fn venv_python(venv: &Path) -> PathBuf {
    let bin = venv.join(if cfg!(windows) { "Scripts" } else { "bin" });
    bin.join(if cfg!(windows) {
        "python.exe"
    } else {
        "python"
    })
}

/// A venv at `venv` (recreated when `fresh`), with pip >= 21.3.
fn venv(venv: &Path, fresh: bool, target: &Path) -> Result<PathBuf, String> {
    if fresh && venv.exists() {
        std::fs::remove_dir_all(venv).map_err(|e| format!("cannot remove {venv:?}: {e}"))?;
    }
    let python = venv_python(venv);
    if !python.exists() {
        crate::checked(Command::new(interpreter()).arg("-m").arg("venv").arg(venv))?;
    }
    pip(&python, target, &["install", "--quiet", "pip>=21.3"])?;
    Ok(python)
}

fn pip(python: &Path, target: &Path, args: &[&str]) -> Result<(), String> {
    crate::checked(
        Command::new(python)
            .args(["-m", "pip", "--disable-pip-version-check"])
            .args(args)
            .arg("--cache-dir")
            .arg(target.join("pip-cache")),
    )
}

/// Builds the wheel into `target/wheels/` and returns its path.
pub fn wheel(root: &Path, target: &Path) -> Result<PathBuf, String> {
    let python = venv(&target.join("maturin-venv"), false, target)?;
    pip(&python, target, &["install", "--quiet", "maturin>=1.7,<2"])?;
    let out = target.join("wheels");
    let version = package_version(root)?;
    // a stale wheel of the same version must not be picked up
    if let Ok(entries) = std::fs::read_dir(&out) {
        for e in entries.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if name.starts_with(&format!("tabor-{version}-")) && name.ends_with(".whl") {
                let _ = std::fs::remove_file(e.path());
            }
        }
    }
    crate::checked(
        Command::new(&python)
            .args(["-m", "maturin", "build", "--release", "--quiet"])
            .arg("--manifest-path")
            .arg(root.join("python").join("Cargo.toml"))
            .arg("--out")
            .arg(&out)
            .env("CARGO_TARGET_DIR", target.join("python-build"))
            .current_dir(root),
    )?;
    let wheel = std::fs::read_dir(&out)
        .map_err(|e| format!("cannot read {out:?}: {e}"))?
        .flatten()
        .map(|e| e.path())
        .find(|p| {
            p.file_name().is_some_and(|n| {
                let n = n.to_string_lossy();
                n.starts_with(&format!("tabor-{version}-")) && n.ends_with(".whl")
            })
        })
        .ok_or_else(|| format!("maturin wrote no tabor-{version} wheel into {out:?}"))?;
    let name = wheel
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    if !(name.contains("-abi3-") && name.contains("manylinux")) {
        return Err(format!("{name}: expected an abi3 manylinux wheel"));
    }
    Ok(wheel)
}

/// The version of `python/Cargo.toml` (the package's one version).
fn package_version(root: &Path) -> Result<String, String> {
    let path = root.join("python").join("Cargo.toml");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("cannot read {path:?}: {e}"))?;
    text.lines()
        .find_map(|l| {
            let l = l.trim();
            l.strip_prefix("version = \"")
                .and_then(|v| v.strip_suffix('"'))
                .map(str::to_string)
        })
        .ok_or_else(|| format!("{path:?} has no version line"))
}

/// `PATH` without the directories that hold `cargo` or `rustc`.
fn path_without_rust() -> OsString {
    let path = std::env::var_os("PATH").unwrap_or_default();
    let kept: Vec<PathBuf> = std::env::split_paths(&path)
        .filter(|d| !(d.join("cargo").exists() || d.join("rustc").exists()))
        .collect();
    std::env::join_paths(kept).unwrap_or_default()
}

fn pytest(
    python: &Path,
    root: &Path,
    cli: &Path,
    args: &[String],
    no_rust: bool,
) -> Result<(), String> {
    let mut cmd = Command::new(python);
    cmd.args(["-m", "pytest", "-p", "no:cacheprovider"])
        .arg(root.join("python").join("tests"))
        .args(args)
        .env("TABOR_CLI", cli)
        .current_dir(root);
    if no_rust {
        cmd.env("PATH", path_without_rust())
            .env_remove("CARGO_HOME")
            .env_remove("RUSTUP_HOME")
            .env_remove("CARGO");
        // proof that this run cannot reach a Rust toolchain
        crate::checked(
            Command::new(python)
                .args([
                    "-c",
                    "import shutil, sys; sys.exit(shutil.which('cargo') is not None or shutil.which('rustc') is not None)",
                ])
                .env("PATH", path_without_rust()),
        )
        .map_err(|_| "cargo or rustc is still on the stripped PATH".to_string())?;
    }
    match crate::status(&mut cmd)? {
        0 => Ok(()),
        5 => Err("pytest collected no tests (exit code 5): that is a failure here".into()),
        c => Err(format!("pytest exited with {c}")),
    }
}

fn test_requirements(python: &Path, target: &Path, requirements: &str) -> Result<(), String> {
    pip(python, target, &["install", "--quiet", "-r", requirements])?;
    // packages whose own dependency tree the tests do not need (see the file)
    pip(
        python,
        target,
        &[
            "install",
            "--quiet",
            "--no-deps",
            "-r",
            "python/tests/requirements-nodeps.txt",
        ],
    )
}

/// The `python` step of `cargo xtask test` (module doc).
pub fn tests(root: &Path, target: &Path, pytest_args: &[String]) -> Result<(), String> {
    let wheel = wheel(root, target)?;
    let wheel_arg = wheel.to_string_lossy().into_owned();
    // the CLI the scene round trip compares against, from the same tree (the
    // release build the LAMMPS steps use too)
    let cli = crate::release_binaries(root, target)?.join(if cfg!(windows) {
        "tabor.exe"
    } else {
        "tabor"
    });
    let fresh = std::env::var("TABOR_FRESH_VENV").is_ok_and(|v| v == "1");
    // 1. the development venv, numpy 2.x
    let python = venv(&target.join("python-venv"), fresh, target)?;
    std::env::set_current_dir(root).map_err(|e| e.to_string())?;
    test_requirements(&python, target, "python/tests/requirements.txt")?;
    pip(
        &python,
        target,
        &[
            "install",
            "--quiet",
            "--force-reinstall",
            "--no-deps",
            &wheel_arg,
        ],
    )?;
    pytest(&python, root, &cli, pytest_args, false)?;
    // 2. a fresh venv, numpy 1.x, no Rust on PATH
    let python = venv(&target.join("python-wheel-venv"), true, target)?;
    test_requirements(&python, target, "python/tests/requirements-numpy1.txt")?;
    pip(
        &python,
        target,
        &["install", "--quiet", "--no-deps", &wheel_arg],
    )?;
    pytest(&python, root, &cli, pytest_args, true)
}

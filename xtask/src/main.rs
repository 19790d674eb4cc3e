//! Project tasks, run as `cargo xtask <task>` (alias in `.cargo/config.toml`).
//!
//! - `lammps-plugin`: builds the LAMMPS pair style `tabor` (see
//!   [`lammps_plugin`]); the last line of standard output is the `.so` path.

mod lammps_plugin;

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("lammps-plugin") => match lammps_plugin::run(&args[1..]) {
            Ok(path) => {
                println!("{}", path.display());
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("cargo xtask lammps-plugin: {e}");
                ExitCode::FAILURE
            }
        },
        _ => {
            eprintln!("usage: cargo xtask lammps-plugin");
            ExitCode::from(2)
        }
    }
}

//! `tabor`: the command line over the tabor library.
//!
//! One module per subcommand in `cmd/`; each parses its own arguments, calls the
//! library and prints either a human-readable table or, with `--json`, one JSON
//! object. Bad input ends with one line on stderr and exit code 2; a reader that
//! closes stdout early (`tabor … | head -1`) ends the program quietly with exit
//! code 0. Output conventions: `output.rs` and the crate README.

mod args;
mod cmd;
mod output;

use clap::{CommandFactory, Parser, Subcommand};
use output::Failure;
use std::process::ExitCode;

/// Adhesive impact of elastic spheres: energy loss, restitution, sticking velocity.
#[derive(Parser)]
#[command(name = "tabor", version = output::VERSION, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Effective modulus, radius and mass of a two-body collision.
    Effective(cmd::effective::Args),
    /// JKR adhesive impact of a sphere: energy loss, sticking velocity, restitution.
    Jkr(cmd::jkr::Args),
    /// Maugis-Dugdale adhesive loss W(Λ) over the Tabor parameter, as a table.
    MaugisLoss(cmd::maugis_loss::Args),
    /// Elasto-plastic impact with and without adhesion: restitution, yield and sticking velocity.
    Plastic(cmd::plastic::Args),
    /// Penalty contact laws: parameters for a nominal restitution, and what they achieve.
    Penalty(cmd::penalty::Args),
    /// Viscoelastic impact: restitution versus the dimensionless parameters.
    Visco(cmd::visco::Args),
    /// The impact of a scene file: restitution, sticking, losses, effects used.
    Impact(cmd::scene::ImpactArgs),
    /// Restitution of a scene over a range of speeds (or another parameter), as CSV.
    Sweep(cmd::sweep::SweepArgs),
    /// The sticking velocity of a scene.
    Sticking(cmd::scene::StickingArgs),
    /// Simulate a scene's impact in the time domain.
    Trajectory(cmd::scene::TrajectoryArgs),
    /// Print a shell completion script (bash, zsh, fish, elvish, powershell).
    Completions(cmd::completions::Args),
    /// Export a scene to a DEM engine (LAMMPS): calibrated input, or --check a line.
    Export(cmd::export::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Effective(args) => cmd::effective::run(&args),
        Command::Jkr(args) => cmd::jkr::run(&args),
        Command::MaugisLoss(args) => cmd::maugis_loss::run(&args),
        Command::Plastic(args) => cmd::plastic::run(&args),
        Command::Penalty(args) => cmd::penalty::run(&args),
        Command::Visco(args) => cmd::visco::run(&args),
        Command::Impact(args) => cmd::scene::impact(&args),
        Command::Sweep(args) => cmd::sweep::sweep(&args),
        Command::Sticking(args) => cmd::scene::sticking(&args),
        Command::Trajectory(args) => cmd::scene::trajectory(&args),
        Command::Completions(args) => cmd::completions::run(&args, &mut Cli::command()),
        Command::Export(args) => cmd::export::run(&args),
    };
    match result {
        Ok(()) | Err(Failure::ClosedPipe) => ExitCode::SUCCESS,
        Err(Failure::Message(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

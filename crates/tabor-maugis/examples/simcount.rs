//! Instruction counts and step anatomy of one simulated impact, for
//! `valgrind --tool=callgrind` (the impacts of `benches/impact.rs`: two silica
//! spheres of radius 1 µm at twice the JKR sticking velocity, default simulation
//! settings, no trajectory kept).
//!
//! ```text
//! cargo build --release -p tabor-maugis --example simcount
//! valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!     target/release/examples/simcount jkr 100     # then with 200
//! target/release/examples/simcount md steps        # the accepted steps, one a line
//! ```
//!
//! `LAW` is `jkr` (fixed grip), `md` (Maugis-Dugdale at Λ = 1) or `md=Λ`; the impact speed is
//! `FACTOR` (default 2) times the JKR sticking velocity. With a count, the
//! program simulates that many impacts (the cost of one is the difference of two
//! counts over the difference of their counts); with `steps`, it simulates one
//! impact with its trajectory and prints every accepted step (normalized time,
//! overlap, overlap rate, step length), then the cost, restitution and energy error.

use std::hint::black_box;
use std::process::ExitCode;
use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_jkr::{JkrForceLaw, JkrImpact, JkrSphere, SeparationRule};
use tabor_maugis::{MaugisContact, MaugisDugdaleForceLaw, MaugisDugdaleImpact};
use tabor_restitution::{impact, sticking_velocity};

const E_STAR: f64 = 2.780_352_177_942_539e10;
const RADIUS: f64 = 0.5e-6;
const WORK_OF_ADHESION: f64 = 0.05;
const MASS: f64 = 5.550_147_021_341_967e-15;

fn simulate(
    law: &str,
    speed: f64,
    settings: &SimulationSettings,
) -> Result<ImpactSimulation, String> {
    let sphere = JkrSphere::new(E_STAR, RADIUS, WORK_OF_ADHESION).map_err(|e| e.to_string())?;
    let mut law: Box<dyn ForceLaw> = match law {
        "jkr" => Box::new(JkrForceLaw::new(sphere, SeparationRule::FixedGrip)),
        md if md.starts_with("md") => {
            let lambda = match md.strip_prefix("md=") {
                Some(l) => l.parse::<f64>().map_err(|_| format!("{md}: md=LAMBDA"))?,
                None => 1.0,
            };
            let md = MaugisDugdaleImpact::new(
                MaugisContact::new(sphere, lambda).map_err(|e| e.to_string())?,
                MASS,
            )
            .map_err(|e| e.to_string())?;
            Box::new(MaugisDugdaleForceLaw::new(&md).map_err(|e| e.to_string())?)
        }
        other => return Err(format!("unknown law {other:?} (jkr or md)")),
    };
    simulate_impact(law.as_mut(), MASS, speed, settings).map_err(|e| e.to_string())
}

/// The closed-form (or quadrature) restitution of the same impact, seed 000
/// eq. (5.37): the JKR fixed-grip loss (5.36), the Maugis-Dugdale loss (5.43)-(5.46).
fn reference(law: &str, speed: f64) -> Result<f64, String> {
    let sphere = JkrSphere::new(E_STAR, RADIUS, WORK_OF_ADHESION).map_err(|e| e.to_string())?;
    let outcome = match law.strip_prefix("md=") {
        Some(l) => {
            let lambda = l.parse::<f64>().map_err(|e| e.to_string())?;
            let md = MaugisDugdaleImpact::new(
                MaugisContact::new(sphere, lambda).map_err(|e| e.to_string())?,
                MASS,
            )
            .map_err(|e| e.to_string())?;
            impact(&md, speed)
        }
        None if law == "md" => {
            let md = MaugisDugdaleImpact::new(
                MaugisContact::new(sphere, 1.0).map_err(|e| e.to_string())?,
                MASS,
            )
            .map_err(|e| e.to_string())?;
            impact(&md, speed)
        }
        None => impact(
            &JkrImpact::new(sphere, MASS).map_err(|e| e.to_string())?,
            speed,
        ),
    };
    outcome.map(|o| o.restitution).map_err(|e| e.to_string())
}

fn run(args: &[String]) -> Result<(), String> {
    let usage = "usage: simcount jkr|md COUNT|steps [FACTOR]";
    let (Some(law), Some(what)) = (args.get(1), args.get(2)) else {
        return Err(usage.into());
    };
    let sphere = JkrSphere::new(E_STAR, RADIUS, WORK_OF_ADHESION).map_err(|e| e.to_string())?;
    let jkr = JkrImpact::new(sphere, MASS).map_err(|e| e.to_string())?;
    let factor = match args.get(3) {
        Some(f) => f
            .parse::<f64>()
            .map_err(|_| format!("{usage}: FACTOR is a number"))?,
        None => 2.0,
    };
    let v0 = factor
        * sticking_velocity(&jkr, 1e-12)
            .map_err(|e| e.to_string())?
            .speed;
    if what == "steps" {
        let settings = SimulationSettings::default();
        let sim = simulate(law, v0, &settings)?;
        let length = sim.max_overlap.abs().max(f64::MIN_POSITIVE);
        let mut last = None;
        for p in &sim.trajectory {
            let h = last.map_or(0.0, |t| p.time - t);
            println!(
                "{:.6e} {:+.6e} {:+.6e} {:.3e}",
                p.time,
                p.overlap / length,
                p.overlap_rate / v0,
                h
            );
            last = Some(p.time);
        }
        println!(
            "steps {} evaluations {} restitution {:.15} (closed form {:.15}) energy error {:.2e} events {}",
            sim.cost.iterations,
            sim.cost.evaluations,
            sim.restitution,
            reference(law, v0)?,
            sim.energy_error,
            sim.events.len()
        );
        return Ok(());
    }
    let count: usize = what
        .parse()
        .map_err(|_| format!("{usage}: COUNT is a number"))?;
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    };
    let mut sum = 0.0;
    for _ in 0..count {
        sum += simulate(law, black_box(v0), &settings)?.restitution;
    }
    // printed so the runs cannot be optimized away
    println!("{sum}");
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}

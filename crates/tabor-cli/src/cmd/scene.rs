//! The scene subcommands: `impact`, `sweep`, `sticking`, `trajectory`. A scene is a
//! TOML or JSON file (format: `examples/scenes/README.md`).

use crate::output::print_json;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use tabor_dynamics::SimulationSettings;
use tabor_scene::{spaced, Scene, SweepParameter};

fn load(path: &Path) -> Result<Scene, String> {
    Scene::from_path(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// Arguments of `tabor impact`.
#[derive(clap::Args)]
pub struct ImpactArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Impact speed (m/s); overrides [impact] speed
    #[arg(long, allow_negative_numbers = true)]
    speed: Option<f64>,
    /// Print one JSON object instead of a report
    #[arg(long)]
    json: bool,
}

/// Runs `tabor impact`.
pub fn impact(args: &ImpactArgs) -> Result<(), String> {
    let scene = load(&args.scene)?;
    let outcome = match args.speed {
        Some(v) => scene.outcome_at(v),
        None => scene.outcome(),
    }
    .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    if args.json {
        return print_json(&outcome);
    }
    let o = &outcome;
    println!("scene             {}", o.scene);
    println!("impact speed      {:.6e} m/s", o.impact_speed);
    println!("restitution       {:.12}", o.restitution);
    println!("sticks            {}", o.sticks);
    match o.sticking_velocity {
        Some(v) => println!("sticking velocity {v:.6e} m/s"),
        None => println!("sticking velocity none (the bodies never stick)"),
    }
    println!(
        "energy loss       {:.6e} J of {:.6e} J",
        o.energy_loss, o.kinetic_energy
    );
    if let Some(l) = o.tabor_parameter {
        println!("Tabor parameter   {l:.6e}");
    }
    println!("model             {}", o.model);
    println!("branch            {}", o.branch);
    println!(
        "combination       {} of {} ({})",
        o.combination.rule.as_str(),
        if o.combination.effects.is_empty() {
            "no dissipative effect".to_string()
        } else {
            o.combination
                .effects
                .iter()
                .map(|e| e.as_str())
                .collect::<Vec<_>>()
                .join(" + ")
        },
        o.combination.source
    );
    println!("effects");
    for e in &o.effects {
        let loss = e
            .energy_loss
            .map_or(String::new(), |l| format!(" [{l:.3e} J]"));
        println!(
            "  {:<16} {:<5} {}{loss}",
            e.name,
            if e.used { "used" } else { "skip" },
            e.reason
        );
    }
    println!(
        "accuracy          {:.1e} (error estimate {:.1e} J, {} evaluations)",
        o.accuracy, o.energy_loss_error, o.cost.evaluations
    );
    for w in &o.warnings {
        println!("warning [{}]: {}", w.code, w.message);
    }
    Ok(())
}

/// Arguments of `tabor sweep`.
#[derive(clap::Args)]
#[command(
    after_help = "Example: tabor sweep examples/scenes/silica.toml --speed 0.01:1:200 --log --out silica.csv"
)]
pub struct SweepArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Speeds as from:to:points (m/s)
    #[arg(long, conflicts_with = "values")]
    speed: Option<String>,
    /// Another parameter to sweep: sphere-radius, work-of-adhesion, tabor-parameter, yield-stress
    #[arg(long, requires = "values")]
    parameter: Option<String>,
    /// Values of --parameter as from:to:points
    #[arg(long)]
    values: Option<String>,
    /// Space the points logarithmically
    #[arg(long)]
    log: bool,
    /// The CSV file to write
    #[arg(long)]
    out: PathBuf,
}

fn range(text: &str, log: bool) -> Result<Vec<f64>, String> {
    let parts: Vec<&str> = text.split(':').collect();
    let bad = || format!("invalid range \"{text}\": expected from:to:points");
    if parts.len() != 3 {
        return Err(bad());
    }
    let from: f64 = parts[0].trim().parse().map_err(|_| bad())?;
    let to: f64 = parts[1].trim().parse().map_err(|_| bad())?;
    let points: usize = parts[2].trim().parse().map_err(|_| bad())?;
    spaced(from, to, points, log).map_err(|e| e.to_string())
}

/// Runs `tabor sweep`.
pub fn sweep(args: &SweepArgs) -> Result<(), String> {
    let scene = load(&args.scene)?;
    let (parameter, values) = match (&args.speed, &args.parameter, &args.values) {
        (Some(s), None, _) => (SweepParameter::Speed, range(s, args.log)?),
        (None, Some(p), Some(v)) => {
            let parameter = SweepParameter::from_name(p).ok_or_else(|| {
                format!("invalid --parameter \"{p}\": expected sphere-radius, work-of-adhesion, tabor-parameter or yield-stress")
            })?;
            (parameter, range(v, args.log)?)
        }
        _ => {
            return Err(
                "give --speed from:to:points, or --parameter NAME --values from:to:points".into(),
            )
        }
    };
    let bar = ProgressBar::new(values.len() as u64);
    if values.len() < 100 {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} points, {eta} left") {
        bar.set_style(style);
    }
    let results = tabor_scene::sweep(&scene, parameter, &values, || bar.inc(1));
    bar.finish_and_clear();
    let file = std::fs::File::create(&args.out)
        .map_err(|e| format!("cannot write {}: {e}", args.out.display()))?;
    let mut csv = std::io::BufWriter::new(file);
    let io = |e: std::io::Error| format!("cannot write {}: {e}", args.out.display());
    writeln!(
        csv,
        "{},restitution,sticks,energy_loss_j,sticking_velocity_m_per_s,model",
        parameter.name().replace('-', "_")
    )
    .map_err(io)?;
    for (value, result) in values.iter().zip(results) {
        let o = result.map_err(|e| format!("{} = {value:e}: {e}", parameter.name()))?;
        writeln!(
            csv,
            "{value:.12e},{:.15e},{},{:.12e},{},\"{}\"",
            o.restitution,
            o.sticks,
            o.energy_loss,
            o.sticking_velocity
                .map_or(String::new(), |v| format!("{v:.12e}")),
            o.model.replace('"', "'")
        )
        .map_err(io)?;
    }
    csv.flush().map_err(io)?;
    eprintln!("wrote {} points to {}", values.len(), args.out.display());
    Ok(())
}

/// Arguments of `tabor sticking`.
#[derive(clap::Args)]
pub struct StickingArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Print one JSON object
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Sticking {
    scene: String,
    sticking_velocity: Option<f64>,
    sticks_ever: bool,
}

/// Runs `tabor sticking`.
pub fn sticking(args: &StickingArgs) -> Result<(), String> {
    let scene = load(&args.scene)?;
    let v = scene
        .sticking_velocity()
        .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    let out = Sticking {
        scene: scene.name.clone(),
        sticking_velocity: v,
        sticks_ever: v.is_some(),
    };
    if args.json {
        return print_json(&out);
    }
    match v {
        Some(v) => println!("sticking velocity {v:.12e} m/s"),
        None => println!("the bodies never stick"),
    }
    Ok(())
}

/// Arguments of `tabor trajectory`.
#[derive(clap::Args)]
pub struct TrajectoryArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Impact speed (m/s); default: the scene's [impact] speed
    #[arg(long, allow_negative_numbers = true)]
    speed: Option<f64>,
    /// Write the trajectory (t, d, ḋ, F, a) as CSV here
    #[arg(long)]
    out: Option<PathBuf>,
    /// Requested relative accuracy of the simulated outcome
    #[arg(long, default_value_t = 1e-9, allow_negative_numbers = true)]
    tolerance: f64,
    /// Print one JSON object
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Trajectory {
    scene: String,
    law: String,
    impact_speed: f64,
    restitution: f64,
    restitution_analytic: f64,
    contact_time: Option<f64>,
    sticks: bool,
    max_overlap: f64,
    max_force: f64,
    energy_loss: f64,
    energy_error: f64,
    points: usize,
}

/// Runs `tabor trajectory`.
pub fn trajectory(args: &TrajectoryArgs) -> Result<(), String> {
    let scene = load(&args.scene)?;
    let speed = args
        .speed
        .or(scene.speed)
        .ok_or_else(|| format!("{}: give --speed or [impact] speed", args.scene.display()))?;
    let mut settings =
        SimulationSettings::with_tolerance(args.tolerance).map_err(|e| e.to_string())?;
    settings.record_trajectory = args.out.is_some();
    let (sim, outcome) = scene
        .simulate(speed, &settings)
        .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    if let Some(path) = &args.out {
        let io = |e: std::io::Error| format!("cannot write {}: {e}", path.display());
        let mut csv = std::io::BufWriter::new(std::fs::File::create(path).map_err(io)?);
        writeln!(
            csv,
            "time_s,overlap_m,overlap_rate_m_per_s,force_n,contact_radius_m"
        )
        .map_err(io)?;
        for p in &sim.trajectory {
            writeln!(
                csv,
                "{:.12e},{:.12e},{:.12e},{:.12e},{:.12e}",
                p.time, p.overlap, p.overlap_rate, p.force, p.contact_radius
            )
            .map_err(io)?;
        }
        csv.flush().map_err(io)?;
    }
    let out = Trajectory {
        scene: scene.name.clone(),
        law: sim.law.clone(),
        impact_speed: speed,
        restitution: sim.restitution,
        restitution_analytic: outcome.restitution,
        contact_time: sim.contact_time,
        sticks: sim.sticks,
        max_overlap: sim.max_overlap,
        max_force: sim.max_force,
        energy_loss: sim.energy_loss,
        energy_error: sim.energy_error,
        points: sim.trajectory.len(),
    };
    if args.json {
        return print_json(&out);
    }
    println!("law                  {}", out.law);
    println!("restitution          {:.12} (simulated)", out.restitution);
    println!("restitution_analytic {:.12}", out.restitution_analytic);
    match out.contact_time {
        Some(t) => println!("contact time         {t:.6e} s"),
        None => println!("contact time         - (the bodies stick)"),
    }
    println!("energy bookkeeping   {:.1e}", out.energy_error);
    Ok(())
}

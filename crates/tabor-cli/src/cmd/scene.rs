//! The scene subcommands: `impact`, `sweep`, `sticking`, `trajectory`. A scene is a
//! TOML or JSON file (format: `examples/scenes/README.md`).

use crate::output::{number, optional, print_json, stdout, Failure, Outcome, VERSION};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use tabor::dynamics::SimulationSettings;
use tabor::scene::{spaced, Scene, SweepParameter};
use tabor::tangential::oblique::ObliqueOutcome;

fn load(path: &Path) -> Result<Scene, String> {
    Scene::from_path(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// Arguments of `tabor impact`.
#[derive(clap::Args)]
pub struct ImpactArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Impact speed (m/s); overrides [impact] speed
    #[arg(long, allow_hyphen_values = true)]
    speed: Option<f64>,
    /// Impact angle (degrees between the relative velocity and the line of centres);
    /// overrides [impact] angle. An oblique impact (an angle, a [friction] section or
    /// a spin) adds normal_restitution, tangential_restitution, rebound_angle,
    /// energy_lost_by_mechanism and after; the central-impact fields are then those
    /// of the normal speed v cos(angle)
    #[arg(long, allow_hyphen_values = true)]
    angle: Option<f64>,
    /// Print one JSON object instead of a report
    #[arg(long)]
    json: bool,
}

/// The scene's oblique impact at `speed` and `angle` (degrees), when it is one:
/// the central outcome at the normal speed and the simulated oblique one.
fn oblique_at(
    scene: &Scene,
    path: &Path,
    speed: f64,
    angle: f64,
) -> Result<Option<(tabor::scene::Outcome, ObliqueOutcome)>, String> {
    if angle == 0.0 && !scene.is_oblique() {
        return Ok(None);
    }
    let fail = |e: tabor::scene::SceneError| format!("{}: {e}", path.display());
    let oblique = scene.oblique(speed, angle).map_err(fail)?;
    let central = scene
        .outcome_at(speed * angle.to_radians().cos())
        .map_err(fail)?;
    Ok(Some((central, oblique)))
}

/// The JSON report of an oblique impact (`Scene::oblique_report`).
fn oblique_json(scene: &Scene, path: &Path, speed: f64, angle: f64) -> Outcome {
    match scene
        .oblique_report(speed, angle)
        .map_err(|e| format!("{}: {e}", path.display()))?
    {
        Some((value, _)) => print_json(&value),
        None => Err("not an oblique impact".into()),
    }
}

/// Runs `tabor impact`.
pub fn impact(args: &ImpactArgs) -> Outcome {
    let scene = load(&args.scene)?;
    let angle = args.angle.or(scene.angle()).unwrap_or(0.0);
    if angle != 0.0 || scene.is_oblique() {
        let speed = args
            .speed
            .or(scene.speed)
            .ok_or_else(|| format!("{}: give --speed or [impact] speed", args.scene.display()))?;
        if args.json {
            return oblique_json(&scene, &args.scene, speed, angle);
        }
        if let Some((central, o)) = oblique_at(&scene, &args.scene, speed, angle)? {
            let mut out = stdout();
            writeln!(out, "scene                  {}", central.scene)?;
            writeln!(
                out,
                "impact speed           {speed:e} m/s at {angle} degrees"
            )?;
            writeln!(out, "normal law             {}", o.law)?;
            writeln!(out, "normal restitution     {}", o.normal_restitution)?;
            match o.tangential_restitution {
                Some(e) => writeln!(out, "tangential restitution {e} (contact point)")?,
                None => writeln!(out, "tangential restitution - (no sliding before impact)")?,
            }
            match o.rebound_angle {
                Some(a) => writeln!(out, "rebound angle          {a} degrees")?,
                None => writeln!(out, "rebound angle          - (the bodies stick)")?,
            }
            writeln!(out, "sticks                 {}", o.sticks)?;
            let s = &o.after.sphere;
            writeln!(
                out,
                "sphere after           v = {:?} m/s, omega = {:?} rad/s (CoM frame)",
                s.velocity, s.angular_velocity
            )?;
            let l = &o.losses;
            writeln!(
                out,
                "energy loss            {:e} J of {:e} J",
                o.energy_loss, o.kinetic_energy
            )?;
            let micro_slip = [("micro-slip", l.micro_slip)];
            // micro-slip only where the model has it (mindlin_deresiewicz)
            let micro_slip = &micro_slip[..usize::from(l.micro_slip != 0.0)];
            for (name, value) in [
                ("normal adhesion", l.normal_adhesion),
                ("normal damping", l.normal_damping),
                ("sliding friction", l.sliding_friction),
            ]
            .into_iter()
            .chain(micro_slip.iter().copied())
            .chain([
                ("tangential damping", l.tangential_damping),
                ("tangential spring", l.tangential_spring),
                ("rolling", l.rolling),
                ("twisting", l.twisting),
                ("torque arm", l.torque_arm),
            ]) {
                writeln!(out, "  {name:<20} {value:e} J")?;
            }
            writeln!(out, "energy bookkeeping     {:.1e}", o.energy_error)?;
            writeln!(
                out,
                "central model          {} (restitution {} at the normal speed)",
                central.model, central.restitution
            )?;
            return out.finish();
        }
    }
    let outcome = match args.speed {
        Some(v) => scene.outcome_at(v),
        None => scene.outcome(),
    }
    .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    if args.json {
        return print_json(&outcome);
    }
    let o = &outcome;
    let mut out = stdout();
    writeln!(out, "scene             {}", o.scene)?;
    writeln!(out, "impact speed      {:e} m/s", o.impact_speed)?;
    writeln!(out, "restitution       {}", o.restitution)?;
    writeln!(out, "sticks            {}", o.sticks)?;
    let sticking_warning = o
        .warnings
        .iter()
        .any(|w| matches!(w.code, "sticks-up-to-limit" | "sticking-velocity-unknown"));
    match o.sticking_velocity {
        Some(v) => writeln!(out, "sticking velocity {v:e} m/s")?,
        None if sticking_warning => writeln!(out, "sticking velocity none (see the warning)")?,
        None => writeln!(out, "sticking velocity none (the bodies never stick)")?,
    }
    writeln!(
        out,
        "energy loss       {:e} J of {:e} J",
        o.energy_loss, o.kinetic_energy
    )?;
    if let Some(l) = o.tabor_parameter {
        writeln!(out, "Tabor parameter   {l:e}")?;
    }
    writeln!(out, "model             {}", o.model)?;
    writeln!(out, "branch            {}", o.branch)?;
    writeln!(
        out,
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
    )?;
    writeln!(out, "effects")?;
    for e in &o.effects {
        let loss = e
            .energy_loss
            .map_or(String::new(), |l| format!(" [{l:e} J]"));
        writeln!(
            out,
            "  {:<16} {:<5} {}{loss}",
            e.name,
            if e.used { "used" } else { "skip" },
            e.reason
        )?;
    }
    writeln!(
        out,
        "accuracy          {:.1e} (error estimate {:.1e} J, {} evaluations)",
        o.accuracy, o.energy_loss_error, o.cost.evaluations
    )?;
    for w in &o.warnings {
        writeln!(out, "warning [{}]: {}", w.code, w.message)?;
    }
    out.finish()
}

/// Arguments of `tabor sweep`.
#[derive(clap::Args)]
#[command(
    after_help = "CSV columns: the swept parameter with its unit (speed_m_per_s, sphere_radius_m, \
work_of_adhesion_j_per_m2, tabor_parameter, yield_stress_pa), restitution, sticks, energy_loss_j, \
sticking_velocity_m_per_s (empty: never sticks), model, tabor_version. Numbers in shortest \
round-trip form.\n\
Example: tabor sweep examples/scenes/silica.toml --speed 0.01:1:200 --log --out silica.csv"
)]
pub struct SweepArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Speeds as from:to:points (m/s)
    #[arg(long, conflicts_with = "values")]
    speed: Option<String>,
    /// Another parameter to sweep: sphere-radius, work-of-adhesion, tabor-parameter, yield-stress,
    /// angle (degrees; an oblique sweep)
    #[arg(long, requires = "values")]
    parameter: Option<String>,
    /// Values of --parameter as from:to:points
    #[arg(long)]
    values: Option<String>,
    /// Space the points logarithmically
    #[arg(long)]
    log: bool,
    /// The CSV file to write; default: stdout
    #[arg(long)]
    out: Option<PathBuf>,
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

/// The CSV column of a swept parameter: its name with its SI unit.
fn column(parameter: SweepParameter) -> String {
    match parameter.name() {
        "speed" => "speed_m_per_s".into(),
        "sphere-radius" => "sphere_radius_m".into(),
        "work-of-adhesion" => "work_of_adhesion_j_per_m2".into(),
        "tabor-parameter" => "tabor_parameter".into(),
        "yield-stress" => "yield_stress_pa".into(),
        "angle" => "angle_deg".into(),
        other => other.replace('-', "_"),
    }
}

/// Where a CSV goes: a file or stdout.
fn csv_target(path: Option<&Path>) -> Result<Box<dyn Write>, String> {
    Ok(match path {
        Some(p) => Box::new(
            std::fs::File::create(p).map_err(|e| format!("cannot write {}: {e}", p.display()))?,
        ),
        None => Box::new(stdout()),
    })
}

/// Turns a CSV write error into the subcommand's failure: a file error names the
/// file; on stdout a closed pipe is the quiet end.
fn csv_failure(path: Option<&Path>) -> impl Fn(csv::Error) -> Failure + '_ {
    move |e| match path {
        Some(p) => format!("cannot write {}: {e}", p.display()).into(),
        None => e.into(),
    }
}

/// Runs `tabor sweep`.
pub fn sweep(args: &SweepArgs) -> Outcome {
    let scene = load(&args.scene)?;
    let (parameter, values) = match (&args.speed, &args.parameter, &args.values) {
        (Some(s), None, _) => (SweepParameter::Speed, range(s, args.log)?),
        (None, Some(p), Some(v)) => {
            let parameter = SweepParameter::from_name(p).ok_or_else(|| {
                format!("invalid --parameter \"{p}\": expected sphere-radius, work-of-adhesion, tabor-parameter, yield-stress or angle")
            })?;
            (parameter, range(v, args.log)?)
        }
        _ => {
            return Err(
                "give --speed from:to:points, or --parameter NAME --values from:to:points".into(),
            )
        }
    };
    scene.check_parameter(parameter).map_err(|e| {
        format!(
            "{}: --parameter {}: {e}",
            args.scene.display(),
            parameter.name()
        )
    })?;
    if parameter == SweepParameter::Angle || scene.is_oblique() {
        return oblique_sweep(&scene, args, parameter, &values);
    }
    let bar = ProgressBar::new(values.len() as u64);
    if values.len() < 100 {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} points, {eta} left") {
        bar.set_style(style);
    }
    let results = tabor::scene::sweep(&scene, parameter, &values, || bar.inc(1));
    bar.finish_and_clear();
    // Every point must succeed before anything is written (as before: no partial file).
    let mut outcomes = Vec::with_capacity(values.len());
    for (value, result) in values.iter().zip(results) {
        outcomes.push(result.map_err(|e| format!("{} = {value:e}: {e}", parameter.name()))?);
    }
    let path = args.out.as_deref();
    let fail = csv_failure(path);
    let mut csv = csv::Writer::from_writer(csv_target(path)?);
    csv.write_record([
        column(parameter).as_str(),
        "restitution",
        "sticks",
        "energy_loss_j",
        "sticking_velocity_m_per_s",
        "model",
        "tabor_version",
    ])
    .map_err(&fail)?;
    for (value, o) in values.iter().zip(&outcomes) {
        csv.write_record([
            number(*value),
            number(o.restitution),
            o.sticks.to_string(),
            number(o.energy_loss),
            optional(o.sticking_velocity),
            o.model.clone(),
            VERSION.to_string(),
        ])
        .map_err(&fail)?;
    }
    csv.flush().map_err(|e| fail(e.into()))?;
    if let Some(p) = path {
        eprintln!("wrote {} points to {}", values.len(), p.display());
    }
    Ok(())
}

/// An oblique sweep (`--parameter angle`, or a scene with an angle, friction or
/// spin): per point the central fields at the normal speed and the oblique ones.
fn oblique_sweep(
    scene: &Scene,
    args: &SweepArgs,
    parameter: SweepParameter,
    values: &[f64],
) -> Outcome {
    let mut rows = Vec::with_capacity(values.len());
    for &value in values {
        let point = scene
            .with_parameter(parameter, value)
            .map_err(|e| format!("{} = {value:e}: {e}", parameter.name()))?;
        let speed = point.speed.ok_or_else(|| {
            format!(
                "{}: an oblique sweep needs [impact] speed",
                args.scene.display()
            )
        })?;
        let angle = point.angle().unwrap_or(0.0);
        let (central, o) = match oblique_at(&point, &args.scene, speed, angle)? {
            Some(pair) => pair,
            None => (
                point.outcome_at(speed).map_err(|e| e.to_string())?,
                point.oblique(speed, 0.0).map_err(|e| e.to_string())?,
            ),
        };
        rows.push((value, central, o));
    }
    let path = args.out.as_deref();
    let fail = csv_failure(path);
    let mut csv = csv::Writer::from_writer(csv_target(path)?);
    csv.write_record([
        column(parameter).as_str(),
        "normal_restitution",
        "tangential_restitution",
        "rebound_angle_deg",
        "sticks",
        "energy_loss_j",
        "sliding_friction_j",
        "sphere_angular_velocity_z_rad_per_s",
        "restitution_central",
        "model",
        "tabor_version",
    ])
    .map_err(&fail)?;
    for (value, central, o) in &rows {
        csv.write_record([
            number(*value),
            number(o.normal_restitution),
            optional(o.tangential_restitution),
            optional(o.rebound_angle),
            o.sticks.to_string(),
            number(o.energy_loss),
            number(o.losses.sliding_friction),
            number(o.after.sphere.angular_velocity[2]),
            number(central.restitution),
            o.law.clone(),
            VERSION.to_string(),
        ])
        .map_err(&fail)?;
    }
    csv.flush().map_err(|e| fail(e.into()))?;
    if let Some(p) = path {
        eprintln!("wrote {} points to {}", values.len(), p.display());
    }
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
    /// When the bodies stick at every speed the model is valid for: its limit
    /// (m/s) and what ends its validity.
    sticks_up_to: Option<f64>,
    limit_reason: Option<&'static str>,
}

/// Runs `tabor sticking`.
pub fn sticking(args: &StickingArgs) -> Outcome {
    let scene = load(&args.scene)?;
    let sticking = scene
        .sticking()
        .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    let (sticks_up_to, limit_reason) = match sticking {
        tabor::scene::Sticking::UpToLimit { limit, reason } => (Some(limit), Some(reason)),
        _ => (None, None),
    };
    let out = Sticking {
        scene: scene.name.clone(),
        sticking_velocity: sticking.velocity(),
        sticks_ever: sticking.sticks_ever(),
        sticks_up_to,
        limit_reason,
    };
    if args.json {
        return print_json(&out);
    }
    let mut stdout = stdout();
    match (out.sticking_velocity, out.sticks_up_to) {
        (Some(v), _) => writeln!(stdout, "sticking velocity {v:e} m/s")?,
        (None, Some(limit)) => writeln!(
            stdout,
            "the bodies stick at every speed up to {limit:e} m/s ({}): no sticking velocity within the model's validity",
            out.limit_reason.unwrap_or("validity limit")
        )?,
        (None, None) => writeln!(stdout, "the bodies never stick")?,
    }
    stdout.finish()
}

/// Arguments of `tabor trajectory`.
#[derive(clap::Args)]
pub struct TrajectoryArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Impact speed (m/s); default: the scene's [impact] speed
    #[arg(long, allow_hyphen_values = true)]
    speed: Option<f64>,
    /// Impact angle (degrees); default: the scene's [impact] angle. An oblique
    /// impact prints the simulated oblique outcome (as `impact --json`; no CSV)
    #[arg(long, allow_hyphen_values = true)]
    angle: Option<f64>,
    /// Write the trajectory as CSV here (columns time_s, overlap_m,
    /// overlap_rate_m_per_s, force_n, contact_radius_m, tabor_version)
    #[arg(long)]
    out: Option<PathBuf>,
    /// Requested relative accuracy of the simulated outcome
    #[arg(long, default_value_t = crate::args::Tolerance(tabor::numerics::tolerance::COSTLY_TOLERANCE), allow_hyphen_values = true)]
    tolerance: crate::args::Tolerance,
    /// Print one JSON object
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Trajectory {
    scene: String,
    law: String,
    /// The rule that answers at this speed (whose outcome is `restitution_analytic`).
    rule: &'static str,
    /// Whether `law` is the rule's own force law; when not, `warnings` says which
    /// model is simulated and by how much its restitution differs.
    law_is_the_rules: bool,
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
    warnings: Vec<tabor::restitution::Warning>,
}

/// Runs `tabor trajectory`.
pub fn trajectory(args: &TrajectoryArgs) -> Outcome {
    let scene = load(&args.scene)?;
    let speed = args
        .speed
        .or(scene.speed)
        .ok_or_else(|| format!("{}: give --speed or [impact] speed", args.scene.display()))?;
    let angle = args.angle.or(scene.angle()).unwrap_or(0.0);
    if angle != 0.0 || scene.is_oblique() {
        if args.out.is_some() {
            return Err("--out: the oblique impact has no trajectory record yet".into());
        }
        return oblique_json(&scene, &args.scene, speed, angle);
    }
    let mut settings =
        SimulationSettings::with_tolerance(args.tolerance.0).map_err(|e| e.to_string())?;
    settings.record_trajectory = args.out.is_some();
    let (sim, outcome) = scene
        .simulate(speed, &settings)
        .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    if let Some(path) = &args.out {
        let fail = csv_failure(Some(path));
        let mut csv = csv::Writer::from_writer(csv_target(Some(path))?);
        csv.write_record([
            "time_s",
            "overlap_m",
            "overlap_rate_m_per_s",
            "force_n",
            "contact_radius_m",
            "tabor_version",
        ])
        .map_err(&fail)?;
        for p in &sim.trajectory {
            csv.write_record([
                number(p.time),
                number(p.overlap),
                number(p.overlap_rate),
                number(p.force),
                number(p.contact_radius),
                VERSION.to_string(),
            ])
            .map_err(&fail)?;
        }
        csv.flush().map_err(|e| fail(e.into()))?;
    }
    let warnings: Vec<_> = outcome
        .warnings
        .iter()
        .filter(|w| w.code == "trajectory-other-model")
        .cloned()
        .collect();
    let out = Trajectory {
        scene: scene.name.clone(),
        law: sim.law.clone(),
        rule: outcome.combination.rule.as_str(),
        law_is_the_rules: warnings.is_empty(),
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
        warnings,
    };
    if args.json {
        return print_json(&out);
    }
    let mut stdout = stdout();
    writeln!(stdout, "law                  {}", out.law)?;
    writeln!(
        stdout,
        "restitution          {} (simulated)",
        out.restitution
    )?;
    writeln!(stdout, "restitution_analytic {}", out.restitution_analytic)?;
    match out.contact_time {
        Some(t) => writeln!(stdout, "contact time         {t:e} s")?,
        None => writeln!(stdout, "contact time         - (the bodies stick)")?,
    }
    writeln!(stdout, "energy bookkeeping   {:.1e}", out.energy_error)?;
    for w in &out.warnings {
        writeln!(stdout, "warning [{}]: {}", w.code, w.message)?;
    }
    stdout.finish()
}

//! The scene subcommands: `impact`, `sweep`, `sticking`, `trajectory`. A scene is a
//! TOML or JSON file (format: `examples/scenes/README.md`).

use crate::output::{number, optional, print_json, stdout, Failure, Outcome, VERSION};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use tabor::dynamics::SimulationSettings;
use tabor::scene::{Scene, Spacing, SweepParameter};
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
    /// Answer beyond the small-strain limit of the pair (refused by default)
    #[arg(long)]
    allow_large_strain: bool,
}

/// Refuses a normal impact speed `speed` beyond the small-strain limit of the
/// scene's pair, where the quasi-static small-strain models do not hold: the Hertz
/// overlap (15 m v²/(16 E* √R))^(2/5) reaches `SMALL_STRAIN_OVERLAP` of R (the
/// export's limit, `tabor::lammps::small_strain_speed`). `allow` lets it through;
/// a graded medium (whose E* is another constant) is not checked.
fn within_small_strain(scene: &Scene, speed: f64, allow: bool, flag: &str) -> Outcome {
    if allow || scene.data().target.gradation.is_some() || !speed.is_finite() {
        return Ok(());
    }
    let limit = tabor::lammps::small_strain_speed(
        scene.effective_modulus,
        scene.effective_radius,
        scene.effective_mass,
    );
    if limit.is_finite() && speed > limit {
        return Err(format!(
            "{flag} = {speed:e} m/s is beyond the small-strain limit {limit:.4e} m/s of this pair \
             (the Hertz overlap would exceed {} times the radius, where the quasi-static models \
             do not hold); pass --allow-large-strain to answer anyway",
            tabor::lammps::SMALL_STRAIN_OVERLAP
        )
        .into());
    }
    Ok(())
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
    let mut central = scene
        .outcome_at(speed * angle.to_radians().cos())
        .map_err(fail)?;
    central.warnings.extend(scene.oblique_accuracy_warning());
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
    if let Some(v) = args.speed.or(scene.speed) {
        // the normal speed sets the overlap
        let normal = v * angle.to_radians().cos().abs();
        within_small_strain(
            &scene,
            normal,
            args.allow_large_strain,
            "the normal impact speed",
        )?;
    }
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
    /// Speeds as from:to:points (m/s; at most 10^7 points)
    #[arg(long, conflicts_with = "values", allow_hyphen_values = true)]
    speed: Option<String>,
    /// Another parameter to sweep: sphere-radius, work-of-adhesion, tabor-parameter, yield-stress,
    /// angle (degrees; an oblique sweep)
    #[arg(long, requires = "values")]
    parameter: Option<String>,
    /// Values of --parameter as from:to:points (at most 10^7 points)
    #[arg(long, allow_hyphen_values = true)]
    values: Option<String>,
    /// Space the points logarithmically
    #[arg(long)]
    log: bool,
    /// Sweep beyond the small-strain limit of the pair (refused by default)
    #[arg(long)]
    allow_large_strain: bool,
    /// The CSV file to write; default: stdout
    #[arg(long)]
    out: Option<PathBuf>,
}

fn range(text: &str, log: bool, flag: &str) -> Result<Spacing, String> {
    let parts: Vec<&str> = text.split(':').collect();
    let bad = || format!("invalid {flag} \"{text}\": expected from:to:points");
    if parts.len() != 3 {
        return Err(bad());
    }
    let from: f64 = parts[0].trim().parse().map_err(|_| bad())?;
    let to: f64 = parts[1].trim().parse().map_err(|_| bad())?;
    // a count beyond usize is beyond the ceiling too
    let points: usize = match parts[2].trim().parse::<u128>() {
        Ok(p) => usize::try_from(p).unwrap_or(usize::MAX),
        Err(_) => return Err(bad()),
    };
    if points > tabor::scene::MAX_SWEEP_POINTS {
        return Err(format!(
            "invalid {flag} \"{text}\": {points} points, at most {} (the ceiling of a sweep)",
            tabor::scene::MAX_SWEEP_POINTS
        ));
    }
    Spacing::new(from, to, points, log).map_err(|e| format!("{flag}: {e}"))
}

/// The error of one sweep point: the scene's message when it names the value
/// already (a bad parameter: "impact.angle: invalid angle = 1e2: …"), else the
/// parameter and value first.
fn point_error(parameter: SweepParameter, value: f64, e: impl std::fmt::Display) -> String {
    let message = e.to_string();
    if message.contains(&format!("= {value:e}")) {
        message
    } else {
        format!("{} = {value:e}: {message}", parameter.name())
    }
}

/// Points computed and written per chunk of a sweep (memory independent of the
/// number of points).
const SWEEP_CHUNK: usize = 4096;

/// A CSV output that appears whole or not at all: `--out FILE` is written to
/// `FILE.partial` and renamed when the sweep succeeds; standard output streams.
struct CsvOut {
    writer: csv::Writer<Box<dyn Write>>,
    path: Option<PathBuf>,
}

impl CsvOut {
    fn new(path: Option<&Path>) -> Result<Self, String> {
        let partial = path.map(|p| {
            let mut name = p.as_os_str().to_owned();
            name.push(".partial");
            PathBuf::from(name)
        });
        Ok(CsvOut {
            writer: csv::Writer::from_writer(csv_target(partial.as_deref())?),
            path: path.map(Path::to_path_buf),
        })
    }

    fn partial(&self) -> Option<PathBuf> {
        self.path.as_ref().map(|p| {
            let mut name = p.as_os_str().to_owned();
            name.push(".partial");
            PathBuf::from(name)
        })
    }

    /// Flushes and moves the file into place.
    fn finish(mut self, points: usize) -> Outcome {
        let fail = csv_failure(self.path.as_deref());
        self.writer.flush().map_err(|e| fail(e.into()))?;
        if let (Some(p), Some(tmp)) = (self.path.clone(), self.partial()) {
            drop(self.writer);
            std::fs::rename(&tmp, &p).map_err(|e| format!("cannot write {}: {e}", p.display()))?;
            eprintln!("wrote {points} points to {}", p.display());
        }
        Ok(())
    }

    /// Removes the partial file of a failed sweep.
    fn abandon(self) {
        if let Some(tmp) = self.partial() {
            drop(self.writer);
            let _ = std::fs::remove_file(tmp);
        }
    }
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

/// Runs `tabor sweep`: the rows are computed and written in chunks, so memory does
/// not grow with the number of points (at most `MAX_SWEEP_POINTS`); a failing
/// point ends the sweep with its error (a chunk is written only when all its
/// points succeeded; `--out` appears only when every point did).
pub fn sweep(args: &SweepArgs) -> Outcome {
    let scene = load(&args.scene)?;
    let (parameter, spacing) = match (&args.speed, &args.parameter, &args.values) {
        (Some(s), None, _) => (SweepParameter::Speed, range(s, args.log, "--speed")?),
        (None, Some(p), Some(v)) => {
            let parameter = SweepParameter::from_name(p).ok_or_else(|| {
                format!("invalid --parameter \"{p}\": expected sphere-radius, work-of-adhesion, tabor-parameter, yield-stress or angle")
            })?;
            (parameter, range(v, args.log, "--values")?)
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
    let fastest = if parameter == SweepParameter::Speed {
        Some(spacing.bounds().1)
    } else {
        scene.speed
    };
    if let Some(v) = fastest {
        within_small_strain(
            &scene,
            v,
            args.allow_large_strain,
            "the highest impact speed",
        )?;
    }
    if parameter == SweepParameter::Angle || scene.is_oblique() {
        return oblique_sweep(&scene, args, parameter, &spacing);
    }
    let bar = ProgressBar::new(spacing.len() as u64);
    if spacing.len() < 100 {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} points, {eta} left") {
        bar.set_style(style);
    }
    let mut out = CsvOut::new(args.out.as_deref())?;
    let fail = csv_failure(args.out.as_deref());
    let header = [
        column(parameter),
        "restitution".into(),
        "sticks".into(),
        "energy_loss_j".into(),
        "sticking_velocity_m_per_s".into(),
        "model".into(),
        "tabor_version".into(),
    ];
    let mut first = true;
    let written = tabor::scene::sweep_streamed(
        &scene,
        parameter,
        &spacing,
        SWEEP_CHUNK,
        || bar.inc(1),
        |values, results| -> Result<(), Failure> {
            let mut rows = Vec::with_capacity(values.len());
            for (value, result) in values.iter().zip(results) {
                rows.push(result.map_err(|e| point_error(parameter, *value, e))?);
            }
            // the header once the first chunk has succeeded: a sweep whose first
            // points fail prints nothing
            if std::mem::take(&mut first) {
                out.writer.write_record(&header).map_err(&fail)?;
            }
            for (value, o) in values.iter().zip(&rows) {
                out.writer
                    .write_record([
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
            Ok(())
        },
    );
    bar.finish_and_clear();
    match written {
        Ok(()) => out.finish(spacing.len()),
        Err(e) => {
            out.abandon();
            Err(e)
        }
    }
}

/// An oblique sweep (`--parameter angle`, or a scene with an angle, friction or
/// spin): per point the central fields at the normal speed and the oblique ones,
/// written point by point.
fn oblique_sweep(
    scene: &Scene,
    args: &SweepArgs,
    parameter: SweepParameter,
    spacing: &Spacing,
) -> Outcome {
    let mut out = CsvOut::new(args.out.as_deref())?;
    let fail = csv_failure(args.out.as_deref());
    let header = [
        column(parameter),
        "normal_restitution".into(),
        "tangential_restitution".into(),
        "rebound_angle_deg".into(),
        "sticks".into(),
        "energy_loss_j".into(),
        "sliding_friction_j".into(),
        "sphere_angular_velocity_z_rad_per_s".into(),
        "restitution_central".into(),
        "model".into(),
        "tabor_version".into(),
    ];
    // rows are written a chunk at a time, once every point of the chunk succeeded
    const OBLIQUE_CHUNK: usize = 256;
    let mut run = || -> Outcome {
        let mut rows: Vec<[String; 11]> = Vec::with_capacity(OBLIQUE_CHUNK);
        for i in 0..spacing.len() {
            let value = spacing.value(i);
            let point = scene
                .with_parameter(parameter, value)
                .map_err(|e| point_error(parameter, value, e))?;
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
            rows.push([
                number(value),
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
            ]);
            if rows.len() == OBLIQUE_CHUNK || i + 1 == spacing.len() {
                if i < OBLIQUE_CHUNK {
                    out.writer.write_record(&header).map_err(&fail)?;
                }
                for row in rows.drain(..) {
                    out.writer.write_record(&row).map_err(&fail)?;
                }
            }
        }
        Ok(())
    };
    match run() {
        Ok(()) => out.finish(spacing.len()),
        Err(e) => {
            out.abandon();
            Err(e)
        }
    }
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
    /// Answer beyond the small-strain limit of the pair (refused by default)
    #[arg(long)]
    allow_large_strain: bool,
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
    let normal = speed * angle.to_radians().cos().abs();
    within_small_strain(
        &scene,
        normal,
        args.allow_large_strain,
        "the normal impact speed",
    )?;
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

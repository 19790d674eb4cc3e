//! `tabor sweep`: the outcome of a scene over a range of one parameter, streamed as
//! CSV in chunks (memory independent of the number of points).

use super::scene::{csv_failure, csv_target, load, oblique_at, within_small_strain};
use crate::output::{number, optional, Failure, Outcome, VERSION};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::Write;
use std::path::{Path, PathBuf};
use tabor::scene::{Scene, Spacing, SweepParameter};

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
    if message.contains(&format!("= {}", number(value))) {
        message
    } else {
        format!("{} = {}: {message}", parameter.name(), number(value))
    }
}

/// Points computed and written per chunk of a sweep (memory independent of the
/// number of points).
const SWEEP_CHUNK: usize = 4096;

/// A CSV output that appears whole or not at all: `--out FILE` is written to
/// `FILE.partial` and renamed when the sweep succeeds; standard output streams.
struct CsvOut {
    writer: csv::Writer<Box<dyn Write>>,
    /// `--out FILE` and `FILE.partial`, the file written until the sweep succeeds.
    files: Option<(PathBuf, PathBuf)>,
}

impl CsvOut {
    fn new(path: Option<&Path>) -> Result<Self, String> {
        let files = path.map(|p| {
            let mut partial = p.as_os_str().to_owned();
            partial.push(".partial");
            (p.to_path_buf(), PathBuf::from(partial))
        });
        Ok(CsvOut {
            writer: csv::Writer::from_writer(csv_target(
                files.as_ref().map(|(_, partial)| partial.as_path()),
            )?),
            files,
        })
    }

    /// Flushes and moves the file into place.
    fn finish(mut self, points: usize) -> Outcome {
        {
            let fail = csv_failure(self.files.as_ref().map(|(p, _)| p.as_path()));
            self.writer.flush().map_err(|e| fail(e.into()))?;
        }
        if let Some((p, partial)) = self.files {
            drop(self.writer);
            std::fs::rename(&partial, &p)
                .map_err(|e| format!("cannot write {}: {e}", p.display()))?;
            eprintln!("wrote {points} points to {}", p.display());
        }
        Ok(())
    }

    /// Removes the partial file of a failed sweep.
    fn abandon(self) {
        if let Some((_, partial)) = self.files {
            drop(self.writer);
            let _ = std::fs::remove_file(partial);
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

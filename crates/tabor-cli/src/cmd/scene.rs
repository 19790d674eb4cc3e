//! The scene subcommands: `impact`, `sweep`, `sticking`, `trajectory`. A scene is a
//! TOML or JSON file (format: `examples/scenes/README.md`).

use crate::output::{human, number, print_json, stdout, Failure, Outcome, Rounding, VERSION};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use tabor::dynamics::SimulationSettings;
use tabor::scene::Scene;
use tabor::tangential::oblique::ObliqueOutcome;

pub(crate) fn load(path: &Path) -> Result<Scene, String> {
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
pub(crate) fn within_small_strain(scene: &Scene, speed: f64, allow: bool, flag: &str) -> Outcome {
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
pub(crate) fn oblique_at(
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
            let r = Rounding::at(central.accuracy);
            let vector = |v: [f64; 3]| v.map(|x| r.value(x, "")).join(", ");
            writeln!(out, "scene                  {}", central.scene)?;
            writeln!(
                out,
                "impact speed           {} at {} degrees",
                r.value(speed, "m/s"),
                r.value(angle, "")
            )?;
            writeln!(out, "normal law             {}", o.law)?;
            writeln!(
                out,
                "normal restitution     {}",
                r.value(o.normal_restitution, "")
            )?;
            match o.tangential_restitution {
                Some(e) => writeln!(
                    out,
                    "tangential restitution {} (contact point)",
                    r.value(e, "")
                )?,
                // `None` for bodies that stick, or a contact point that does
                // not slide before the impact
                None if o.sticks => writeln!(out, "tangential restitution - (the bodies stick)")?,
                None => writeln!(out, "tangential restitution - (no sliding before impact)")?,
            }
            match o.rebound_angle {
                Some(a) => writeln!(out, "rebound angle          {} degrees", r.value(a, ""))?,
                None => writeln!(out, "rebound angle          - (the bodies stick)")?,
            }
            writeln!(out, "sticks                 {}", o.sticks)?;
            let s = &o.after.sphere;
            writeln!(
                out,
                "sphere after           v = [{}] m/s, omega = [{}] rad/s (CoM frame)",
                vector(s.velocity),
                vector(s.angular_velocity)
            )?;
            writeln!(
                out,
                "energy loss            {} of {}",
                r.value(o.energy_loss, "J"),
                r.value(o.kinetic_energy, "J")
            )?;
            // micro-slip only where the model has it (mindlin_deresiewicz)
            for (name, value) in o
                .losses
                .by_mechanism()
                .into_iter()
                .filter(|(name, value)| *name != "micro-slip" || *value != 0.0)
            {
                writeln!(out, "  {name:<20} {}", r.value(value, "J"))?;
            }
            writeln!(out, "energy bookkeeping     {:.1e}", o.energy_error)?;
            writeln!(
                out,
                "central model          {} (restitution {} at the normal speed)",
                central.model,
                r.value(central.restitution, "")
            )?;
            for w in &central.warnings {
                writeln!(out, "warning [{}]: {}", w.code, r.text(&w.message))?;
            }
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
    let r = Rounding::at(o.accuracy);
    writeln!(out, "scene             {}", o.scene)?;
    writeln!(out, "impact speed      {}", r.value(o.impact_speed, "m/s"))?;
    writeln!(out, "restitution       {}", r.value(o.restitution, ""))?;
    writeln!(out, "sticks            {}", o.sticks)?;
    let sticking_warning = o
        .warnings
        .iter()
        .any(|w| matches!(w.code, "sticks-up-to-limit" | "sticking-velocity-unknown"));
    match o.sticking_velocity {
        Some(v) => writeln!(out, "sticking velocity {}", r.value(v, "m/s"))?,
        None if sticking_warning => writeln!(out, "sticking velocity none (see the warning)")?,
        None => writeln!(out, "sticking velocity none (the bodies never stick)")?,
    }
    writeln!(
        out,
        "energy loss       {} of {}",
        r.value(o.energy_loss, "J"),
        r.value(o.kinetic_energy, "J")
    )?;
    if let Some(l) = o.tabor_parameter {
        writeln!(out, "Tabor parameter   {}", r.value(l, ""))?;
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
            .map_or(String::new(), |l| format!(" [{}]", r.value(l, "J")));
        writeln!(
            out,
            "  {:<16} {:<5} {}{loss}",
            e.name,
            if e.used { "used" } else { "skip" },
            r.text(&e.reason)
        )?;
    }
    writeln!(
        out,
        "accuracy          {:.1e} (error estimate {}, {} evaluations)",
        o.accuracy,
        human(o.energy_loss_error, "J", 2),
        o.cost.evaluations
    )?;
    for w in &o.warnings {
        writeln!(out, "warning [{}]: {}", w.code, r.text(&w.message))?;
    }
    out.finish()
}

/// Where a CSV goes: a file or stdout.
pub(crate) fn csv_target(path: Option<&Path>) -> Result<Box<dyn Write>, String> {
    Ok(match path {
        Some(p) => Box::new(
            std::fs::File::create(p).map_err(|e| format!("cannot write {}: {e}", p.display()))?,
        ),
        None => Box::new(stdout()),
    })
}

/// Turns a CSV write error into the subcommand's failure: a file error names the
/// file; on stdout a closed pipe is the quiet end.
pub(crate) fn csv_failure(path: Option<&Path>) -> impl Fn(csv::Error) -> Failure + '_ {
    move |e| match path {
        Some(p) => format!("cannot write {}: {e}", p.display()).into(),
        None => e.into(),
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
    let r = Rounding::at(scene.accuracy);
    match (out.sticking_velocity, out.sticks_up_to) {
        (Some(v), _) => writeln!(stdout, "sticking velocity {}", r.value(v, "m/s"))?,
        (None, Some(limit)) => writeln!(
            stdout,
            "the bodies stick at every speed up to {} ({}): no sticking velocity within the model's validity",
            r.value(limit, "m/s"),
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
    let r = Rounding::at(scene.accuracy);
    writeln!(stdout, "law                  {}", out.law)?;
    writeln!(
        stdout,
        "restitution          {} (simulated)",
        r.value(out.restitution, "")
    )?;
    writeln!(
        stdout,
        "restitution_analytic {}",
        r.value(out.restitution_analytic, "")
    )?;
    match out.contact_time {
        Some(t) => writeln!(stdout, "contact time         {}", r.value(t, "s"))?,
        None => writeln!(stdout, "contact time         - (the bodies stick)")?,
    }
    writeln!(stdout, "energy bookkeeping   {:.1e}", out.energy_error)?;
    for w in &out.warnings {
        writeln!(stdout, "warning [{}]: {}", w.code, r.text(&w.message))?;
    }
    stdout.finish()
}

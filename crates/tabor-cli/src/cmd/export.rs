//! `tabor export lammps`: a scene as a calibrated LAMMPS input fragment, or
//! (`--check`) the restitution a user's LAMMPS granular line really produces.
//! Derivations: `crates/tabor-lammps/README.md`.

use crate::output::{json_text, print_json, stdout, Outcome};
use std::io::Write;
use std::path::PathBuf;
use tabor::lammps::{
    check, check_plugin, export, export_plugin_with, is_plugin_line, Check, PluginCheck,
    PluginOptions,
};
use tabor::scene::Scene;

/// Arguments of `tabor export`.
#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    target: Target,
}

#[derive(clap::Subcommand)]
enum Target {
    /// LAMMPS (pair_style granular / fix wall/gran): calibrated fragment, or --check a line
    Lammps(LammpsArgs),
}

/// Arguments of `tabor export lammps`.
#[derive(clap::Args)]
#[command(
    after_help = "Examples:\n  tabor export lammps examples/scenes/silica.toml --out silica.lmp\n  tabor export lammps examples/scenes/silica_maugis.toml --plugin target/lammps-plugin/taborplugin.so\n  tabor export lammps examples/scenes/silica_maugis.toml --plugin target/lammps-plugin/taborplugin.so --per-contact-lambda\n  tabor export lammps integrations/lammps/scenes/jkr_wall.toml --plugin target/lammps-plugin/taborplugin.so --wall 'zplane NULL 5e-5'\n  tabor export lammps examples/scenes/silica.toml --check 'pair_coeff * * hertz/material 54e9 0.5 0.17 damping tsuji' --speed 0.2"
)]
pub struct LammpsArgs {
    /// The scene file (.toml or .json)
    scene: PathBuf,
    /// Calibration speed (m/s); overrides [impact] speed
    #[arg(long)]
    speed: Option<f64>,
    /// Write the fragment to this file instead of standard output
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print the export (or the check) as one JSON object
    #[arg(long)]
    json: bool,
    /// Predict the restitution LAMMPS produces for this pair_coeff or
    /// "fix ... wall/gran granular ..." line, with the scene's bodies; a
    /// pair_style tabor line (maugis ... [range h | stress s0], jkr/fixed-grip,
    /// jkr/load-controlled, after E* w or the material form "material E nu
    /// gamma") is run through the plugin's own force law
    #[arg(long, value_name = "LINE", conflicts_with = "plugin")]
    check: Option<String>,
    /// Write the fragment for pair_style tabor (the plugin built by
    /// `cargo xtask lammps-plugin`), loaded from this .so (made absolute when it
    /// exists): tabor's own force law
    #[arg(long, value_name = "PATH")]
    plugin: Option<PathBuf>,
    /// With --plugin and a flat target: the wall of `fix wall/tabor`, a wallstyle
    /// and its arguments ("xplane|yplane|zplane lo hi", NULL for no wall on that
    /// side, or "zcylinder radius"); default "zplane 0.0 NULL"
    #[arg(
        long,
        value_name = "STYLE ARGS",
        requires = "plugin",
        allow_hyphen_values = true
    )]
    wall: Option<String>,
    /// With --plugin, a Maugis-Dugdale scene: write `maugis E* w range h` (the
    /// Dugdale range held fixed, each contact's Tabor parameter from its own size,
    /// Lambda = d_n(R*)/h) instead of one Lambda for every size
    #[arg(long, requires = "plugin")]
    per_contact_lambda: bool,
    /// A LAMMPS variable used in the --check line ($x, ${name}), as NAME=VALUE
    /// (repeatable)
    #[arg(long = "var", value_name = "NAME=VALUE", value_parser = parse_var, requires = "check")]
    vars: Vec<(String, String)>,
}

/// `NAME=VALUE` of `--var`.
fn parse_var(s: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((n, v)) if !n.is_empty() => Ok((n.to_string(), v.to_string())),
        _ => Err(format!("--var {s}: expected NAME=VALUE")),
    }
}

/// Writes `text` to stdout; a closed pipe ends the output quietly.
fn emit(text: &str) -> Outcome {
    let mut out = stdout();
    out.write_all(text.as_bytes())?;
    out.finish()
}

fn check_report(c: &Check) -> String {
    let mut s = String::new();
    s.push_str(&format!("line                {}\n", c.line));
    let m = &c.parsed.model;
    s.push_str(&format!(
        "model               {} + damping {}{}\n",
        m.normal.keyword(),
        m.damping.keyword(),
        if m.limit_damping {
            " + limit_damping"
        } else {
            ""
        }
    ));
    if let Some(e) = c.nominal_restitution {
        s.push_str(&format!("nominal restitution {e}\n"));
    }
    s.push_str(&format!(
        "damping coefficient {:.6e}\n",
        c.damping_coefficient
    ));
    s.push_str(&format!(
        "bodies              R* = {:.6e} m, m* = {:.6e} kg\n",
        c.effective_radius, c.effective_mass
    ));
    let p = &c.at_speed;
    s.push_str(&format!(
        "achieved            {:.6} at {:.4e} m/s{} (LAMMPS at timestep <= contact time/5000: +- {:.0e})\n",
        p.lammps,
        p.speed,
        if p.sticks { " (sticks)" } else { "" },
        c.time_step_error
    ));
    decade_table(
        &mut s,
        c.decade.iter().map(|p| (p.speed, p.lammps, p.tabor)),
        &c.notes,
    );
    s
}

fn plugin_check_report(c: &PluginCheck) -> String {
    let mut s = String::new();
    s.push_str(&format!("line                {}\n", c.line));
    s.push_str(&format!(
        "model               pair_style tabor {}{}\n",
        c.model.keyword(),
        c.dugdale_range.map_or(String::new(), |h| format!(
            " at the fixed range h = {h:.6e} m (each contact's Lambda = d_n(R*)/h)"
        ))
    ));
    if let Some(l) = c.tabor_parameter {
        s.push_str(&format!(
            "Lambda              {l:.6e} for the scene's contact\n"
        ));
    }
    s.push_str(&format!(
        "bodies              R* = {:.6e} m, m* = {:.6e} kg\n",
        c.effective_radius, c.effective_mass
    ));
    let p = &c.at_speed;
    s.push_str(&format!(
        "achieved            {:.6} at {:.4e} m/s (LAMMPS at timestep <= contact time/20000: +- {:.0e})\n",
        p.lammps, p.speed, c.time_step_error
    ));
    decade_table(
        &mut s,
        c.decade.iter().map(|p| (p.speed, p.lammps, p.tabor)),
        &c.notes,
    );
    s
}

/// Runs `tabor export`.
pub fn run(args: &Args) -> Outcome {
    let Target::Lammps(a) = &args.target;
    let scene = Scene::from_path(&a.scene).map_err(|e| format!("{}: {e}", a.scene.display()))?;
    if let Some(line) = a.check.as_deref().filter(|l| is_plugin_line(l)) {
        // a pair_style tabor line: the plugin's own law for the scene's bodies
        let c = check_plugin(&scene, line, a.speed, &a.vars)
            .map_err(|e| format!("{}: {e}", a.scene.display()))?;
        if a.json {
            return print_json(&c);
        }
        return emit(&plugin_check_report(&c));
    }
    if let Some(line) = &a.check {
        let c = check(&scene, line, a.speed, &a.vars)
            .map_err(|e| format!("{}: {e}", a.scene.display()))?;
        if a.json {
            return print_json(&c);
        }
        return emit(&check_report(&c));
    }
    if let Some(plugin) = &a.plugin {
        // an existing .so is written as an absolute path, so that the fragment
        // loads it from any working directory
        let plugin = std::fs::canonicalize(plugin).unwrap_or_else(|_| plugin.clone());
        let options = PluginOptions {
            per_contact_lambda: a.per_contact_lambda,
            wall: a.wall.clone(),
        };
        let x = export_plugin_with(&scene, &plugin.to_string_lossy(), a.speed, options)
            .map_err(|e| format!("{}: {e}", a.scene.display()))?;
        // also in the fragment (# WARNING) and the JSON; stderr so it is seen
        for w in &x.warnings {
            eprintln!("warning: {w}");
        }
        return write_out(a, &x, &x.fragment());
    }
    let x = export(&scene, a.speed).map_err(|e| format!("{}: {e}", a.scene.display()))?;
    write_out(a, &x, &x.fragment())
}

/// Prints or writes an export: JSON (`--json`) or the fragment, to `--out` or stdout.
fn write_out(a: &LammpsArgs, x: &impl serde::Serialize, fragment: &str) -> Outcome {
    match (&a.out, a.json) {
        (None, true) => print_json(x),
        // the same object as on stdout
        (Some(path), true) => std::fs::write(path, json_text(x)? + "\n")
            .map_err(|e| format!("cannot write {}: {e}", path.display()).into()),
        (Some(path), false) => std::fs::write(path, fragment)
            .map_err(|e| format!("cannot write {}: {e}", path.display()).into()),
        (None, false) => emit(fragment),
    }
}

/// The decade of speeds of a `--check` report (speed, LAMMPS's restitution,
/// tabor's) and its notes, one line each.
fn decade_table(
    s: &mut String,
    points: impl Iterator<Item = (f64, f64, Option<f64>)>,
    notes: &[String],
) {
    s.push_str("speed (m/s)   LAMMPS     tabor\n");
    for (speed, lammps, tabor) in points {
        s.push_str(&format!(
            "{speed:.4e}    {lammps:.6}   {}\n",
            tabor.map_or("-".into(), |t| format!("{t:.6}"))
        ));
    }
    for n in notes {
        s.push_str(&format!("note: {n}\n"));
    }
}

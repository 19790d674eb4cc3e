//! `tabor jkr`: the JKR adhesive impact of a sphere (seed 000, (5.33)-(5.38)): the
//! adhesive energy loss, the sticking velocity and, for a given impact speed, the
//! maximum contact radius and the coefficient of restitution.

use crate::output::{message, print_json, print_table, stdout, Outcome};
use serde::Serialize;
use std::io::Write;
use tabor::jkr::{AdhesiveContact, JkrImpact, JkrSphere, SeparationRule};
use tabor::restitution::{impact, sticking_velocity};

/// Where contact breaks on the way out.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum Separation {
    /// Displacement-controlled instability dd/da = 0, force −(5/6)πΔγR (the seed's
    /// choice, physical for an impact)
    FixedGrip,
    /// Load-controlled pull-off dF/da = 0, force −(3/2)πΔγR (as some DEM codes do;
    /// about half the loss)
    LoadControlled,
}

/// Arguments of `tabor jkr`. All inputs are effective quantities of the collision.
#[derive(clap::Args)]
#[command(
    after_help = "Inputs are the effective quantities of the collision: E* with \
    1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2, R with 1/R = 1/R1 + 1/R2, and the reduced mass \
    m = m1 m2/(m1 + m2) (see `tabor effective`)."
)]
pub struct Args {
    /// Effective modulus E* (Pa)
    #[arg(long, allow_negative_numbers = true)]
    modulus: f64,
    /// Effective radius R (m)
    #[arg(long, allow_negative_numbers = true)]
    radius: f64,
    /// Work of adhesion Δγ (J/m²)
    #[arg(long, allow_negative_numbers = true)]
    work_of_adhesion: f64,
    /// Effective (reduced) mass m (kg)
    #[arg(long, allow_negative_numbers = true)]
    mass: f64,
    /// Relative impact speed v0 (m/s); adds the maximum contact radius and the restitution
    #[arg(long, allow_negative_numbers = true)]
    speed: Option<f64>,
    /// Where contact breaks
    #[arg(long, value_enum, default_value = "fixed-grip")]
    separation: Separation,
    /// Relative tolerance of quadratures and root searches, in [1e-15, 0.5]
    #[arg(long, allow_negative_numbers = true, default_value = "1e-12")]
    tolerance: f64,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Jkr {
    model: String,
    branch: String,
    separation: &'static str,
    /// |ΔU_kin| (J).
    energy_loss: f64,
    energy_loss_error: f64,
    /// v_c (m/s).
    sticking_velocity: f64,
    /// Force where contact breaks (N, negative: tensile).
    separation_force: f64,
    separation_contact_radius: f64,
    first_touch_contact_radius: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    impact_speed: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    max_contact_radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    restitution: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sticks: Option<bool>,
    /// Function evaluations spent on the loss (0 for the closed form).
    evaluations: u64,
}

/// Runs `tabor jkr`.
pub fn run(args: &Args) -> Outcome {
    let rule = match args.separation {
        Separation::FixedGrip => SeparationRule::FixedGrip,
        Separation::LoadControlled => SeparationRule::LoadControlled,
    };
    let sphere =
        JkrSphere::new(args.modulus, args.radius, args.work_of_adhesion).map_err(message)?;
    let model = JkrImpact::new(sphere, args.mass)
        .map_err(message)?
        .with_separation(rule)
        .with_tolerance(args.tolerance)
        .map_err(message)?;
    let loss = model.adhesive_energy_loss().map_err(message)?;
    let v_c = sticking_velocity(&model, args.tolerance.max(1e-15)).map_err(message)?;
    let separation = sphere.critical_state(rule).map_err(message)?;
    let touch = sphere.first_touch().map_err(message)?;
    let (max_radius, outcome) = match args.speed {
        Some(v) => (
            Some(model.max_contact_radius(v).map_err(message)?),
            Some(impact(&model, v).map_err(message)?),
        ),
        None => (None, None),
    };
    let out = Jkr {
        model: tabor::restitution::ImpactModel::name(&model),
        branch: loss.branch.clone(),
        separation: rule.as_str(),
        energy_loss: loss.joules,
        energy_loss_error: loss.error_estimate,
        sticking_velocity: v_c.speed,
        separation_force: separation.force,
        separation_contact_radius: separation.contact_radius,
        first_touch_contact_radius: touch.contact_radius,
        impact_speed: args.speed,
        max_contact_radius: max_radius.map(|m| m.contact_radius),
        restitution: outcome.as_ref().map(|o| o.restitution),
        sticks: outcome.as_ref().map(|o| o.sticks),
        evaluations: loss.cost.evaluations,
    };
    if args.json {
        return print_json(&out);
    }
    let mut stdout = stdout();
    writeln!(stdout, "model   {}", out.model)?;
    writeln!(stdout, "branch  {}", out.branch)?;
    let mut rows = vec![
        ("energy_loss", out.energy_loss, "J"),
        ("energy_loss_error", out.energy_loss_error, "J"),
        ("sticking_velocity", out.sticking_velocity, "m/s"),
        ("separation_force", out.separation_force, "N"),
        (
            "separation_contact_radius",
            out.separation_contact_radius,
            "m",
        ),
        (
            "first_touch_contact_radius",
            out.first_touch_contact_radius,
            "m",
        ),
    ];
    if let (Some(v), Some(a), Some(e)) = (out.impact_speed, out.max_contact_radius, out.restitution)
    {
        rows.push(("impact_speed", v, "m/s"));
        rows.push(("max_contact_radius", a, "m"));
        rows.push(("restitution", e, ""));
    }
    print_table(&mut stdout, &rows)?;
    stdout.finish()
}

//! `tabor jkr`: the JKR adhesive impact of a sphere (seed 000, (5.33)-(5.38)): the
//! adhesive energy loss, the sticking velocity and, for a given impact speed, the
//! maximum contact radius and the coefficient of restitution.

use crate::args::{self, Tolerance};
use crate::output::{message, print_result, Outcome};
use tabor::jkr::SeparationRule;
use tabor::numerics::tolerance;
use tabor::single::jkr::{jkr, JkrArgs};

/// Arguments of `tabor jkr`. All inputs are effective quantities of the collision.
#[derive(clap::Args)]
#[command(
    after_help = "Inputs are the effective quantities of the collision: E* with \
    1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2, R with 1/R = 1/R1 + 1/R2, and the reduced mass \
    m = m1 m2/(m1 + m2) (see `tabor effective`)."
)]
pub struct Args {
    /// Effective modulus E* (Pa)
    #[arg(long, allow_hyphen_values = true)]
    modulus: f64,
    /// Effective radius R (m)
    #[arg(long, allow_hyphen_values = true)]
    radius: f64,
    /// Work of adhesion Δγ (J/m²)
    #[arg(long, allow_hyphen_values = true)]
    work_of_adhesion: f64,
    /// Effective (reduced) mass m (kg)
    #[arg(long, allow_hyphen_values = true)]
    mass: f64,
    /// Relative impact speed v0 (m/s); adds the maximum contact radius and the restitution
    #[arg(long, allow_hyphen_values = true)]
    speed: Option<f64>,
    /// Where contact breaks
    #[arg(long, value_parser = args::menu(&SeparationRule::ALL, |_| String::new()),
        default_value_t = SeparationRule::FixedGrip)]
    separation: SeparationRule,
    /// Relative tolerance of quadratures and root searches, in [1e-15, 0.5]
    #[arg(long, allow_hyphen_values = true,
        default_value_t = Tolerance(tolerance::DEFAULT_TOLERANCE))]
    tolerance: Tolerance,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

/// Runs `tabor jkr`.
pub fn run(args: &Args) -> Outcome {
    let out = jkr(&JkrArgs {
        modulus: args.modulus,
        radius: args.radius,
        work_of_adhesion: args.work_of_adhesion,
        mass: args.mass,
        speed: args.speed,
        separation: args.separation,
        tolerance: args.tolerance.0,
    })
    .map_err(message)?;
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
    let header = [
        format!("model   {}", out.model),
        format!("branch  {}", out.branch),
    ];
    print_result(args.json, &out, &header, &rows, &[])
}

//! `tabor penalty`: penalty contact laws for multibody codes (crate `tabor-penalty`):
//! the parameters of the seed-002 contact characteristic or of a Hunt-Crossley,
//! Lankarani-Nikravesh or Flores law for a nominal restitution, and the restitution
//! the law actually achieves in a simulated impact.

use crate::args;
use crate::output::{print_result, Outcome};
use tabor::single::penalty::{penalty, PenaltyArgs, PenaltyLaw};
use tabor::single::Naming;

/// Arguments of `tabor penalty`.
#[derive(clap::Args)]
#[command(
    after_help = "The achieved restitution of these laws depends only on the dimensionless \
    damping (chi v0, or v0/V), not on the stiffness, exponent, rounding or mass; those set \
    the contact time and the maximum overlap."
)]
pub struct Args {
    /// The penalty law
    #[arg(long, value_parser = args::menu(&PenaltyLaw::ALL, |_| String::new()))]
    law: PenaltyLaw,
    /// Nominal coefficient of restitution e, in (0, 1]
    #[arg(long, allow_hyphen_values = true)]
    restitution: f64,
    /// Stiffness K (N/m^n; N/m for the characteristic)
    #[arg(long, allow_hyphen_values = true, default_value = "1e7")]
    stiffness: f64,
    /// Force exponent n of K δⁿ (hunt-crossley, lankarani-nikravesh, flores; the
    /// characteristic is linear)
    #[arg(long, allow_hyphen_values = true)]
    exponent: Option<f64>,
    /// Rounding half-width ε of the characteristic (m), ≥ 0
    #[arg(long, allow_hyphen_values = true, default_value = "0")]
    rounding: f64,
    /// Effective (reduced) mass m (kg)
    #[arg(long, allow_hyphen_values = true, default_value = "1")]
    mass: f64,
    /// Impact speed v0 (m/s)
    #[arg(long, allow_hyphen_values = true, default_value = "1")]
    speed: f64,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

/// Runs `tabor penalty`.
pub fn run(args: &Args) -> Outcome {
    let out = penalty(
        &PenaltyArgs {
            law: args.law,
            restitution: args.restitution,
            stiffness: args.stiffness,
            exponent: args.exponent,
            rounding: args.rounding,
            mass: args.mass,
            speed: args.speed,
        },
        Naming::Flags,
    )
    .map_err(|e| e.render(Naming::Flags))?;
    let mut rows = vec![
        ("nominal_restitution", out.nominal_restitution, ""),
        ("achieved_restitution", out.achieved_restitution, ""),
        ("closed_form_restitution", out.closed_form_restitution, ""),
        ("stiffness", out.stiffness, "N/m^n"),
        ("exponent", out.exponent, ""),
    ];
    if let (Some(chi), Some(d), Some(x)) = (
        out.damping_factor,
        out.damping_coefficient,
        out.exact_damping_factor,
    ) {
        rows.push(("damping_factor", chi, "s/m"));
        rows.push(("damping_coefficient", d, "N s/m^(n+1)"));
        rows.push(("exact_damping_factor", x, "s/m"));
    }
    if let Some(v) = out.loss_speed {
        rows.push(("loss_speed", v, "m/s"));
    }
    if let Some(r) = out.rounding {
        rows.push(("rounding", r, "m"));
    }
    rows.push(("max_overlap", out.max_overlap, "m"));
    rows.push(("max_force", out.max_force, "N"));
    if let Some(t) = out.contact_time {
        rows.push(("contact_time", t, "s"));
    }
    print_result(args.json, &out, &[format!("law  {}", out.law)], &rows, &[])
}

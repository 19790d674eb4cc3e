//! `tabor penalty`: penalty contact laws for multibody codes (crate `tabor-penalty`):
//! the parameters of the seed-002 contact characteristic or of a Hunt-Crossley,
//! Lankarani-Nikravesh or Flores law for a nominal restitution, and the restitution
//! the law actually achieves in a simulated impact.

use crate::output::{message, print_json, print_table, stdout, Outcome};
use serde::Serialize;
use std::io::Write;
use tabor::penalty::{
    characteristic_loss_speed, exact_damping_factor, simulate_impact, ContactCharacteristic,
    DampedPowerLaw, DampingModel, ForceLaw, ImpactSimulation, SimulationSettings,
};

/// Which penalty law.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum Law {
    /// Seed 002: F = k κ(h, ε) l(v, V); the loss speed V is calibrated exactly
    Characteristic,
    /// F = K δⁿ (1 + χ δ̇), χ = 3(1 − e)/(2 v0) (Hunt & Crossley 1975)
    HuntCrossley,
    /// χ = 3(1 − e²)/(4 v0) (Lankarani & Nikravesh 1990)
    LankaraniNikravesh,
    /// χ = 8(1 − e)/(5 e v0) (Flores et al. 2011)
    Flores,
}

/// Arguments of `tabor penalty`.
#[derive(clap::Args)]
#[command(
    after_help = "The achieved restitution of these laws depends only on the dimensionless \
    damping (chi v0, or v0/V), not on the stiffness, exponent, rounding or mass; those set \
    the contact time and the maximum overlap."
)]
pub struct Args {
    /// The penalty law
    #[arg(long, value_enum)]
    law: Law,
    /// Nominal coefficient of restitution e, in (0, 1]
    #[arg(long, allow_negative_numbers = true)]
    restitution: f64,
    /// Stiffness K (N/m^n; N/m for the characteristic)
    #[arg(long, allow_negative_numbers = true, default_value = "1e7")]
    stiffness: f64,
    /// Force exponent n of K δⁿ (hunt-crossley, lankarani-nikravesh, flores; the
    /// characteristic is linear)
    #[arg(long, allow_negative_numbers = true)]
    exponent: Option<f64>,
    /// Rounding half-width ε of the characteristic (m), ≥ 0
    #[arg(long, allow_negative_numbers = true, default_value = "0")]
    rounding: f64,
    /// Effective (reduced) mass m (kg)
    #[arg(long, allow_negative_numbers = true, default_value = "1")]
    mass: f64,
    /// Impact speed v0 (m/s)
    #[arg(long, allow_negative_numbers = true, default_value = "1")]
    speed: f64,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Penalty {
    law: &'static str,
    nominal_restitution: f64,
    /// From the simulated impact.
    achieved_restitution: f64,
    /// From the law's exact first integral.
    closed_form_restitution: f64,
    stiffness: f64,
    exponent: f64,
    effective_mass: f64,
    impact_speed: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    damping_factor: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    damping_coefficient: Option<f64>,
    /// The χ that would give the nominal restitution exactly.
    #[serde(skip_serializing_if = "Option::is_none")]
    exact_damping_factor: Option<f64>,
    /// V (m/s); null when infinite (e = 1).
    #[serde(skip_serializing_if = "Option::is_none")]
    loss_speed: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    rounding: Option<f64>,
    max_overlap: f64,
    max_force: f64,
    contact_time: Option<f64>,
    energy_error: f64,
}

fn simulate<L: ForceLaw>(law: &mut L, args: &Args) -> Result<ImpactSimulation, String> {
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    };
    simulate_impact(law, args.mass, args.speed, &settings).map_err(message)
}

/// Runs `tabor penalty`.
pub fn run(args: &Args) -> Outcome {
    let e = args.restitution;
    let out = match args.law {
        Law::Characteristic => {
            if let Some(n) = args.exponent {
                if n != 1.0 {
                    return Err(format!(
                        "invalid --exponent = {n}: the seed-002 characteristic is linear (n = 1)"
                    )
                    .into());
                }
            }
            let big_v = characteristic_loss_speed(e, args.speed).map_err(message)?;
            let mut law = ContactCharacteristic::new(args.stiffness, args.rounding, big_v)
                .map_err(message)?;
            let closed = law.restitution(args.speed).map_err(message)?;
            let sim = simulate(&mut law, args)?;
            Penalty {
                law: "seed-002 contact characteristic",
                nominal_restitution: e,
                achieved_restitution: sim.restitution,
                closed_form_restitution: closed,
                stiffness: args.stiffness,
                exponent: 1.0,
                effective_mass: args.mass,
                impact_speed: args.speed,
                damping_factor: None,
                damping_coefficient: None,
                exact_damping_factor: None,
                loss_speed: big_v.is_finite().then_some(big_v),
                rounding: Some(args.rounding),
                max_overlap: sim.max_overlap,
                max_force: sim.max_force,
                contact_time: sim.contact_time,
                energy_error: sim.energy_error,
            }
        }
        damped => {
            let model = match damped {
                Law::HuntCrossley => DampingModel::HuntCrossley,
                Law::LankaraniNikravesh => DampingModel::LankaraniNikravesh,
                _ => DampingModel::Flores,
            };
            let n = args.exponent.unwrap_or(1.5);
            let mut law = DampedPowerLaw::from_model(model, args.stiffness, n, e, args.speed)
                .map_err(message)?;
            let exact = exact_damping_factor(e, args.speed).map_err(message)?;
            let closed = law.restitution(args.speed).map_err(message)?;
            let sim = simulate(&mut law, args)?;
            Penalty {
                law: model.name(),
                nominal_restitution: e,
                achieved_restitution: sim.restitution,
                closed_form_restitution: closed,
                stiffness: law.stiffness(),
                exponent: law.exponent(),
                effective_mass: args.mass,
                impact_speed: args.speed,
                damping_factor: Some(law.damping_factor()),
                damping_coefficient: Some(law.damping_coefficient()),
                exact_damping_factor: Some(exact),
                loss_speed: None,
                rounding: None,
                max_overlap: sim.max_overlap,
                max_force: sim.max_force,
                contact_time: sim.contact_time,
                energy_error: sim.energy_error,
            }
        }
    };
    if args.json {
        return print_json(&out);
    }
    let mut stdout = stdout();
    writeln!(stdout, "law  {}", out.law)?;
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
    print_table(&mut stdout, &rows)?;
    stdout.finish()
}

//! `tabor plastic`: elasto-plastic impact with and without adhesion (seed 000,
//! sections 5.5-5.6, (5.101)-(5.126); seed 001, eqs. (12), (18), (19)): energy loss,
//! restitution, yield velocity and, for the adhesive models, sticking velocity.

use crate::args;
use crate::output::{print_result, Outcome};
use tabor::single::plastic::{model_inputs, plastic, PlasticArgs, PlasticModel};
use tabor::single::Naming;

/// Arguments of `tabor plastic`. All inputs are effective quantities of the collision.
#[derive(clap::Args)]
#[command(
    after_help = "Inputs are the effective quantities of the collision: E* with \
    1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2, R with 1/R = 1/R1 + 1/R2, the reduced mass m \
    (see `tabor effective`), and the yield stress of the softer (yielding) body.\n\n\
    Which model needs which flag:\n  \
    thornton, interpolation      --modulus --radius --mass --yield-stress --speed\n  \
    jackson-green                + --poisson-ratio (of the yielding body; hardness H/sigma_Y = 2.67)\n  \
    dimensionless-fit            + --density (of the sphere; the dimensionless FEM fit)\n  \
    adhesive-interpolation       + --work-of-adhesion (or --adhesion-parameter to give Phi)\n  \
    superposition                + --work-of-adhesion, --plastic-model (default interpolation)\n\
    With --json the output has model, restitution, energy_loss, yield_velocity, \
    sticking_velocity (adhesive models) and warnings."
)]
pub struct Args {
    /// The model
    #[arg(long, value_parser = args::menu(&PlasticModel::ALL, |m| args::needs(model_inputs(m))))]
    model: PlasticModel,
    /// Effective modulus E* (Pa)
    #[arg(long, allow_hyphen_values = true)]
    modulus: f64,
    /// Effective radius R (m)
    #[arg(long, allow_hyphen_values = true)]
    radius: f64,
    /// Effective (reduced) mass m (kg)
    #[arg(long, allow_hyphen_values = true)]
    mass: f64,
    /// Yield stress sigma_Y of the yielding body (Pa)
    #[arg(long, allow_hyphen_values = true)]
    yield_stress: f64,
    /// Relative impact speed v0 (m/s)
    #[arg(long, allow_hyphen_values = true)]
    speed: f64,
    /// Poisson's ratio of the yielding body (jackson-green)
    #[arg(long, allow_hyphen_values = true)]
    poisson_ratio: Option<f64>,
    /// Density of the sphere (kg/m³) (dimensionless-fit)
    #[arg(long, allow_hyphen_values = true)]
    density: Option<f64>,
    /// Work of adhesion Δγ (J/m²) (adhesive-interpolation, superposition)
    #[arg(long, allow_hyphen_values = true)]
    work_of_adhesion: Option<f64>,
    /// Adhesion parameter Phi, instead of computing it from the material data
    /// (adhesive-interpolation)
    #[arg(long, allow_hyphen_values = true)]
    adhesion_parameter: Option<f64>,
    /// The non-adhesive model of --model superposition
    #[arg(long, value_parser = args::menu(PlasticModel::NON_ADHESIVE, |m| args::needs(model_inputs(m))),
        default_value_t = PlasticModel::Interpolation)]
    plastic_model: PlasticModel,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

/// Runs `tabor plastic`.
pub fn run(args: &Args) -> Outcome {
    let out = plastic(
        &PlasticArgs {
            model: args.model,
            modulus: args.modulus,
            radius: args.radius,
            mass: args.mass,
            yield_stress: args.yield_stress,
            speed: args.speed,
            poisson_ratio: args.poisson_ratio,
            density: args.density,
            work_of_adhesion: args.work_of_adhesion,
            adhesion_parameter: args.adhesion_parameter,
            plastic_model: args.plastic_model,
        },
        Naming::Flags,
    )
    .map_err(|e| e.render(Naming::Flags))?;
    let mut rows = vec![
        ("impact_speed", out.impact_speed, "m/s"),
        ("restitution", out.restitution, ""),
        ("energy_loss", out.energy_loss, "J"),
        ("yield_velocity", out.yield_velocity, "m/s"),
    ];
    if let Some(v) = out.sticking_velocity {
        rows.push(("sticking_velocity", v, "m/s"));
    }
    if let Some(v) = out.elastic_sticking_velocity {
        rows.push(("elastic_sticking_velocity", v, "m/s"));
    }
    if let Some(p) = out.adhesion_parameter {
        rows.push(("adhesion_parameter", p, ""));
    }
    let header = [
        format!("model   {}", out.model),
        format!("branch  {}", out.branch),
    ];
    print_result(args.json, &out, &header, &rows, &out.warnings)
}

//! `tabor visco`: viscoelastic impact without adhesion (seed 000 section 5.4):
//! the coefficient of restitution as a function of each model's dimensionless
//! parameters.

use crate::args::{self, Tolerance};
use crate::output::{print_result, Outcome};
use tabor::numerics::tolerance;
use tabor::single::visco::{model_inputs, visco, ViscoArgs, ViscoModel};
use tabor::single::Naming;

/// Arguments of `tabor visco`. All parameters are dimensionless.
#[derive(clap::Args)]
#[command(
    after_help = "Parameters: D = eta sqrt(2a/(m G)) (5.55); delta = eta (R v0/(m^2 G^3))^(1/5) \
    for spheres (5.68), (5.90), (5.92), delta = eta sqrt(8a/(m G_inf)) for the standard flat \
    punch (5.79); beta = G_inf/G_1; gamma = lambda d0^(b+1)/(m v0) (5.72)."
)]
pub struct Args {
    /// The model
    #[arg(long, value_parser = args::menu(&ViscoModel::ALL, |m| args::needs(model_inputs(m))))]
    model: ViscoModel,
    /// Damping ratio D (flat punch; D1 of the compressible model), > 0
    #[arg(long, allow_hyphen_values = true)]
    damping_ratio: Option<f64>,
    /// Viscous parameter δ, > 0
    #[arg(long, allow_hyphen_values = true)]
    viscous_parameter: Option<f64>,
    /// Modulus ratio β = G∞/G1, in [1e-5, 1e4]
    #[arg(long, allow_hyphen_values = true)]
    modulus_ratio: Option<f64>,
    /// Scaled damping γ of (5.72), in (0, 1e3]
    #[arg(long, allow_hyphen_values = true)]
    damping: Option<f64>,
    /// Damping exponent β of (5.72), in [0, 1.5]
    #[arg(long, allow_hyphen_values = true)]
    damping_exponent: Option<f64>,
    /// Tsuji's α of (5.73), > 0
    #[arg(long, allow_hyphen_values = true)]
    alpha: Option<f64>,
    /// Static Poisson's ratio ν (compressible model), in (-1, 0.5)
    #[arg(long, allow_hyphen_values = true)]
    poisson_ratio: Option<f64>,
    /// Bulk damping ratio D2 (compressible model); default (5.100), equal viscosities
    #[arg(long, allow_hyphen_values = true)]
    bulk_damping_ratio: Option<f64>,
    /// Relative integration tolerance, in [1e-15, 0.5]
    #[arg(long, allow_hyphen_values = true,
        default_value_t = Tolerance(tolerance::ACCURACY))]
    tolerance: Tolerance,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

/// Runs `tabor visco`.
pub fn run(args: &Args) -> Outcome {
    let out = visco(
        &ViscoArgs {
            model: args.model,
            damping_ratio: args.damping_ratio,
            viscous_parameter: args.viscous_parameter,
            modulus_ratio: args.modulus_ratio,
            damping: args.damping,
            damping_exponent: args.damping_exponent,
            alpha: args.alpha,
            poisson_ratio: args.poisson_ratio,
            bulk_damping_ratio: args.bulk_damping_ratio,
            tolerance: args.tolerance.0,
        },
        Naming::Flags,
    )
    .map_err(|e| e.render(Naming::Flags))?;
    let mut rows = vec![("restitution", out.restitution, "")];
    let optional = [
        ("contact_time", out.contact_time),
        ("max_overlap", out.max_overlap),
        ("first_order_restitution", out.first_order_restitution),
        (
            "equivalent_kelvin_voigt_damping_ratio",
            out.equivalent_kelvin_voigt_damping_ratio,
        ),
        (
            "equivalent_kelvin_voigt_restitution",
            out.equivalent_kelvin_voigt_restitution,
        ),
    ];
    for (k, v) in optional {
        if let Some(v) = v {
            rows.push((k, v, "(scaled)"));
        }
    }
    let header = [format!("model   {}", out.model)];
    print_result(args.json, &out, &header, &rows, &[])
}

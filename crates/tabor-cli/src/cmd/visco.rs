//! `tabor visco`: viscoelastic impact without adhesion (seed 000 section 5.4):
//! the coefficient of restitution as a function of each model's dimensionless
//! parameters.

use crate::output::{message, print_json, print_table, stdout, Outcome};
use serde::Serialize;
use std::io::Write;
use tabor::visco::{
    compressible_flat, damping_law, kelvin_maxwell_sphere, kelvin_voigt_flat, kelvin_voigt_sphere,
    standard_flat, standard_sphere, SphereModel,
};

/// The viscoelastic models.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum Model {
    /// Flat punch, Kelvin-Voigt, closed form (5.61)-(5.63); needs --damping-ratio
    KelvinVoigtFlat,
    /// Sphere, Kelvin-Voigt, Kuwabara-Kono (5.66); needs --viscous-parameter
    KuwabaraKono,
    /// Sphere, Kelvin-Voigt, compression and restitution apart (5.64)-(5.67); needs --viscous-parameter
    KelvinVoigtSphere,
    /// Sphere, linear damping β = 0 (5.72); needs --damping
    LeeHerrmann,
    /// Sphere, β = 1/4 with (5.73); needs --alpha
    Tsuji,
    /// Sphere, β = 3/2 (5.72); needs --damping
    HuntCrossley,
    /// Sphere, damping exponent of your choice (5.72); needs --damping-exponent, --damping
    PowerDamping,
    /// Flat punch, standard medium (5.76)-(5.81), with the equivalent Kelvin-Voigt value (5.83); needs --modulus-ratio, --viscous-parameter
    StandardFlat,
    /// Sphere, standard medium, MDR (5.84)-(5.90); needs --modulus-ratio, --viscous-parameter
    StandardSphere,
    /// Sphere, Kelvin-Maxwell medium, MDR (5.91)-(5.92); needs --modulus-ratio, --viscous-parameter
    KelvinMaxwellSphere,
    /// Flat punch, compressible Kelvin-Voigt (5.96)-(5.99); needs --poisson-ratio, --damping-ratio [, --bulk-damping-ratio, default (5.100)]
    CompressibleFlat,
}

/// Arguments of `tabor visco`. All parameters are dimensionless.
#[derive(clap::Args)]
#[command(
    after_help = "Parameters: D = eta sqrt(2a/(m G)) (5.55); delta = eta (R v0/(m^2 G^3))^(1/5) \
    for spheres (5.68), (5.90), (5.92), delta = eta sqrt(8a/(m G_inf)) for the standard flat \
    punch (5.79); beta = G_inf/G_1; gamma = lambda d0^(b+1)/(m v0) (5.72)."
)]
pub struct Args {
    /// The model
    #[arg(long, value_enum)]
    model: Model,
    /// Damping ratio D (flat punch; D1 of the compressible model), > 0
    #[arg(long, allow_negative_numbers = true)]
    damping_ratio: Option<f64>,
    /// Viscous parameter δ, > 0
    #[arg(long, allow_negative_numbers = true)]
    viscous_parameter: Option<f64>,
    /// Modulus ratio β = G∞/G1, in [1e-5, 1e4]
    #[arg(long, allow_negative_numbers = true)]
    modulus_ratio: Option<f64>,
    /// Scaled damping γ of (5.72), in (0, 1e3]
    #[arg(long, allow_negative_numbers = true)]
    damping: Option<f64>,
    /// Damping exponent β of (5.72), in [0, 1.5]
    #[arg(long, allow_negative_numbers = true)]
    damping_exponent: Option<f64>,
    /// Tsuji's α of (5.73), > 0
    #[arg(long, allow_negative_numbers = true)]
    alpha: Option<f64>,
    /// Static Poisson's ratio ν (compressible model), in (-1, 0.5)
    #[arg(long, allow_negative_numbers = true)]
    poisson_ratio: Option<f64>,
    /// Bulk damping ratio D2 (compressible model); default (5.100), equal viscosities
    #[arg(long, allow_negative_numbers = true)]
    bulk_damping_ratio: Option<f64>,
    /// Relative integration tolerance, in [1e-15, 0.5]
    #[arg(long, allow_negative_numbers = true, default_value = "1e-10")]
    tolerance: f64,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Visco {
    model: &'static str,
    restitution: f64,
    /// Scaled contact time (units in the library docs of the model).
    #[serde(skip_serializing_if = "Option::is_none")]
    contact_time: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    max_overlap: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    equivalent_kelvin_voigt_damping_ratio: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    equivalent_kelvin_voigt_restitution: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    first_order_restitution: Option<f64>,
    evaluations: u64,
}

fn need(value: Option<f64>, name: &str, model: &str) -> Result<f64, String> {
    value.ok_or_else(|| format!("missing {name}: the model {model} needs it"))
}

fn model_name(m: Model) -> &'static str {
    match m {
        Model::KelvinVoigtFlat => "kelvin-voigt-flat",
        Model::KuwabaraKono => "kuwabara-kono",
        Model::KelvinVoigtSphere => "kelvin-voigt-sphere",
        Model::LeeHerrmann => "lee-herrmann",
        Model::Tsuji => "tsuji",
        Model::HuntCrossley => "hunt-crossley",
        Model::PowerDamping => "power-damping",
        Model::StandardFlat => "standard-flat",
        Model::StandardSphere => "standard-sphere",
        Model::KelvinMaxwellSphere => "kelvin-maxwell-sphere",
        Model::CompressibleFlat => "compressible-flat",
    }
}

/// Runs `tabor visco`.
pub fn run(args: &Args) -> Outcome {
    let name = model_name(args.model);
    // checked here so that a bad --tolerance names the flag for every model
    let tol =
        tabor::restitution::validate::tolerance("tolerance", args.tolerance).map_err(message)?;
    let mut out = Visco {
        model: name,
        restitution: 0.0,
        contact_time: None,
        max_overlap: None,
        equivalent_kelvin_voigt_damping_ratio: None,
        equivalent_kelvin_voigt_restitution: None,
        first_order_restitution: None,
        evaluations: 0,
    };
    let delta = || need(args.viscous_parameter, "--viscous-parameter", name);
    let beta = || need(args.modulus_ratio, "--modulus-ratio", name);
    let damping = || need(args.damping, "--damping", name);
    let law = |b: f64, g: f64| damping_law::solve(b, g, tol).map_err(message);
    let scaled = match args.model {
        Model::KelvinVoigtFlat => {
            let d = need(args.damping_ratio, "--damping-ratio", name)?;
            out.restitution = kelvin_voigt_flat::restitution(d).map_err(message)?;
            out.contact_time = Some(kelvin_voigt_flat::contact_time(d).map_err(message)?);
            None
        }
        Model::KuwabaraKono | Model::KelvinVoigtSphere => {
            let model = if matches!(args.model, Model::KuwabaraKono) {
                SphereModel::KuwabaraKono
            } else {
                SphereModel::Rigorous
            };
            let d = delta()?;
            out.first_order_restitution =
                Some(kelvin_voigt_sphere::first_order_restitution(d).map_err(message)?);
            Some(kelvin_voigt_sphere::solve(d, model, tol).map_err(message)?)
        }
        Model::LeeHerrmann => Some(law(
            damping_law::DampingLaw::LeeHerrmann.exponent(),
            damping()?,
        )?),
        Model::HuntCrossley => Some(law(
            damping_law::DampingLaw::HuntCrossley.exponent(),
            damping()?,
        )?),
        Model::Tsuji => {
            let alpha = need(args.alpha, "--alpha", name)?;
            let g = damping_law::tsuji_damping(alpha).map_err(message)?;
            Some(law(damping_law::DampingLaw::Tsuji.exponent(), g)?)
        }
        Model::PowerDamping => {
            let b = need(args.damping_exponent, "--damping-exponent", name)?;
            Some(law(b, damping()?)?)
        }
        Model::StandardFlat => {
            let (b, d) = (beta()?, delta()?);
            let s = standard_flat::solve(b, d, tol).map_err(message)?;
            out.equivalent_kelvin_voigt_damping_ratio =
                Some(standard_flat::equivalent_damping_ratio(b, d).map_err(message)?);
            out.equivalent_kelvin_voigt_restitution =
                Some(standard_flat::equivalent_restitution(b, d).map_err(message)?);
            Some(s)
        }
        Model::StandardSphere => {
            Some(standard_sphere::solve(beta()?, delta()?, tol).map_err(message)?)
        }
        Model::KelvinMaxwellSphere => {
            Some(kelvin_maxwell_sphere::solve(beta()?, delta()?, tol).map_err(message)?)
        }
        Model::CompressibleFlat => {
            let nu = need(args.poisson_ratio, "--poisson-ratio", name)?;
            let d1 = need(args.damping_ratio, "--damping-ratio", name)?;
            let d2 = match args.bulk_damping_ratio {
                Some(d2) => d2,
                None => compressible_flat::bulk_damping_ratio_equal_viscosities(nu, d1)
                    .map_err(message)?,
            };
            Some(compressible_flat::solve(nu, d1, d2, tol).map_err(message)?)
        }
    };
    if let Some(s) = scaled {
        out.restitution = s.restitution;
        out.contact_time = Some(s.contact_time);
        out.max_overlap = Some(s.max_overlap);
        out.evaluations = s.cost.evaluations;
    }
    if args.json {
        return print_json(&out);
    }
    let mut stdout = stdout();
    writeln!(stdout, "model   {}", out.model)?;
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
    print_table(&mut stdout, &rows)?;
    stdout.finish()
}

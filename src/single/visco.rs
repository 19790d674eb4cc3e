//! Viscoelastic impact without adhesion (`tabor visco`, `tabor.visco`): the
//! coefficient of restitution as a function of each model's dimensionless
//! parameters.

use super::{Error, Naming};
use crate::restitution::validate;
pub use crate::visco::ViscoModel;
use crate::visco::{
    compressible_flat, damping_law, kelvin_maxwell_sphere, kelvin_voigt_flat, kelvin_voigt_sphere,
    standard_flat, standard_sphere, SphereModel,
};
use serde::Serialize;

/// The inputs `model` needs besides the tolerance (snake_case names of
/// [`ViscoArgs`] fields); `bulk_damping_ratio` is optional.
pub fn model_inputs(model: ViscoModel) -> &'static [&'static str] {
    match model {
        ViscoModel::KelvinVoigtFlat => &["damping_ratio"],
        ViscoModel::KuwabaraKono | ViscoModel::KelvinVoigtSphere => &["viscous_parameter"],
        ViscoModel::LeeHerrmann | ViscoModel::HuntCrossley => &["damping"],
        ViscoModel::Tsuji => &["alpha"],
        ViscoModel::PowerDamping => &["damping_exponent", "damping"],
        ViscoModel::StandardFlat | ViscoModel::StandardSphere | ViscoModel::KelvinMaxwellSphere => {
            &["modulus_ratio", "viscous_parameter"]
        }
        ViscoModel::CompressibleFlat => &["poisson_ratio", "damping_ratio"],
    }
}

/// The inputs of `tabor visco`, named like its flags. All are dimensionless.
#[derive(Clone, Copy, Debug)]
pub struct ViscoArgs {
    /// The model.
    pub model: ViscoModel,
    /// Damping ratio D (flat punch; D1 of the compressible model), > 0.
    pub damping_ratio: Option<f64>,
    /// Viscous parameter δ, > 0.
    pub viscous_parameter: Option<f64>,
    /// Modulus ratio β = G∞/G1, in [1e-5, 1e4].
    pub modulus_ratio: Option<f64>,
    /// Scaled damping γ of (5.72), in (0, 1e3].
    pub damping: Option<f64>,
    /// Damping exponent β of (5.72), in [0, 1.5].
    pub damping_exponent: Option<f64>,
    /// Tsuji's α of (5.73), > 0.
    pub alpha: Option<f64>,
    /// Static Poisson's ratio ν (compressible model), in (-1, 0.5).
    pub poisson_ratio: Option<f64>,
    /// Bulk damping ratio D2 (compressible model); default (5.100), equal
    /// viscosities.
    pub bulk_damping_ratio: Option<f64>,
    /// Relative integration tolerance, in [1e-15, 0.5].
    pub tolerance: f64,
}

/// The result record of `tabor visco` (scaled quantities).
#[derive(Clone, Debug, Serialize)]
pub struct Visco {
    /// The model's name.
    pub model: &'static str,
    /// The coefficient of restitution.
    pub restitution: f64,
    /// Scaled contact time (units in the library docs of the model).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_time: Option<f64>,
    /// Scaled maximum overlap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_overlap: Option<f64>,
    /// The equivalent Kelvin-Voigt damping ratio (5.83) (standard-flat).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub equivalent_kelvin_voigt_damping_ratio: Option<f64>,
    /// The restitution of the equivalent Kelvin-Voigt punch (standard-flat).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub equivalent_kelvin_voigt_restitution: Option<f64>,
    /// The first-order restitution (Kelvin-Voigt spheres).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first_order_restitution: Option<f64>,
    /// Function evaluations (0 for a closed form).
    pub evaluations: u64,
}

/// Validates `a` and computes the record of `tabor visco`; a missing input is
/// named in `naming`.
pub fn visco(a: &ViscoArgs, naming: Naming) -> Result<Visco, Error> {
    let name = a.model.as_str();
    let need = |value: Option<f64>, input: &str| -> Result<f64, Error> {
        value.ok_or_else(|| {
            Error::Input(format!(
                "missing {}: the model {} needs it",
                naming.input(input),
                naming.value(name)
            ))
        })
    };
    // checked first so that a bad tolerance is named for every model
    let tol = validate::tolerance("tolerance", a.tolerance)?;
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
    let delta = || need(a.viscous_parameter, "viscous_parameter");
    let beta = || need(a.modulus_ratio, "modulus_ratio");
    let damping = || need(a.damping, "damping");
    let law = |b: f64, g: f64| damping_law::solve(b, g, tol).map_err(Error::from);
    let scaled = match a.model {
        ViscoModel::KelvinVoigtFlat => {
            let d = need(a.damping_ratio, "damping_ratio")?;
            out.restitution = kelvin_voigt_flat::restitution(d)?;
            out.contact_time = Some(kelvin_voigt_flat::contact_time(d)?);
            None
        }
        ViscoModel::KuwabaraKono | ViscoModel::KelvinVoigtSphere => {
            let model = if a.model == ViscoModel::KuwabaraKono {
                SphereModel::KuwabaraKono
            } else {
                SphereModel::Rigorous
            };
            let d = delta()?;
            out.first_order_restitution = Some(kelvin_voigt_sphere::first_order_restitution(d)?);
            Some(kelvin_voigt_sphere::solve(d, model, tol)?)
        }
        ViscoModel::LeeHerrmann => Some(law(
            damping_law::DampingLaw::LeeHerrmann.exponent(),
            damping()?,
        )?),
        ViscoModel::HuntCrossley => Some(law(
            damping_law::DampingLaw::HuntCrossley.exponent(),
            damping()?,
        )?),
        ViscoModel::Tsuji => {
            let alpha = need(a.alpha, "alpha")?;
            let g = damping_law::tsuji_damping(alpha)?;
            Some(law(damping_law::DampingLaw::Tsuji.exponent(), g)?)
        }
        ViscoModel::PowerDamping => {
            let b = need(a.damping_exponent, "damping_exponent")?;
            Some(law(b, damping()?)?)
        }
        ViscoModel::StandardFlat => {
            let (b, d) = (beta()?, delta()?);
            let s = standard_flat::solve(b, d, tol)?;
            out.equivalent_kelvin_voigt_damping_ratio =
                Some(standard_flat::equivalent_damping_ratio(b, d)?);
            out.equivalent_kelvin_voigt_restitution =
                Some(standard_flat::equivalent_restitution(b, d)?);
            Some(s)
        }
        ViscoModel::StandardSphere => Some(standard_sphere::solve(beta()?, delta()?, tol)?),
        ViscoModel::KelvinMaxwellSphere => {
            Some(kelvin_maxwell_sphere::solve(beta()?, delta()?, tol)?)
        }
        ViscoModel::CompressibleFlat => {
            let nu = need(a.poisson_ratio, "poisson_ratio")?;
            let d1 = need(a.damping_ratio, "damping_ratio")?;
            let d2 = match a.bulk_damping_ratio {
                Some(d2) => d2,
                None => compressible_flat::bulk_damping_ratio_equal_viscosities(nu, d1)?,
            };
            Some(compressible_flat::solve(nu, d1, d2, tol)?)
        }
    };
    if let Some(s) = scaled {
        out.restitution = s.restitution;
        out.contact_time = Some(s.contact_time);
        out.max_overlap = Some(s.max_overlap);
        out.evaluations = s.cost.evaluations;
    }
    Ok(out)
}

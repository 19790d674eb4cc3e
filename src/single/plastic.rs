//! Elasto-plastic impact with and without adhesion (`tabor plastic`,
//! `tabor.plastic`): energy loss, restitution, yield velocity and, for the
//! adhesive models, sticking velocity.

use super::{required, Error, Naming};
use crate::jkr::JkrSphere;
use crate::numerics::tolerance;
pub use crate::plastic::PlasticModel;
use crate::plastic::{
    AdhesiveInterpolationImpact, AdhesivePlasticContact, Clamping, DimensionlessFit, Interpolation,
    JacksonGreen, PlasticContact, PlasticImpact, SimulationSettings, Superposition, Thornton,
};
use crate::restitution::{impact, sticking_velocity, ImpactModel};
use serde::Serialize;

/// The inputs `model` needs besides `modulus`, `radius`, `mass`, `yield_stress`
/// and `speed` (snake_case names of [`PlasticArgs`] fields): under
/// `superposition` also those of the `plastic_model`; `adhesive-interpolation`
/// takes `adhesion_parameter` instead of computing Φ.
pub fn model_inputs(model: PlasticModel) -> &'static [&'static str] {
    match model {
        PlasticModel::Thornton | PlasticModel::Interpolation => &[],
        PlasticModel::JacksonGreen => &["poisson_ratio"],
        PlasticModel::DimensionlessFit => &["density"],
        PlasticModel::AdhesiveInterpolation | PlasticModel::Superposition => &["work_of_adhesion"],
    }
}

/// The inputs of `tabor plastic`, named like its flags. All are effective
/// quantities of the collision.
#[derive(Clone, Copy, Debug)]
pub struct PlasticArgs {
    /// The model.
    pub model: PlasticModel,
    /// Effective modulus E* (Pa).
    pub modulus: f64,
    /// Effective radius R (m).
    pub radius: f64,
    /// Effective (reduced) mass m (kg).
    pub mass: f64,
    /// Yield stress σ_Y of the yielding body (Pa).
    pub yield_stress: f64,
    /// Relative impact speed v0 (m/s).
    pub speed: f64,
    /// Poisson's ratio of the yielding body (jackson-green).
    pub poisson_ratio: Option<f64>,
    /// Density of the sphere (kg/m³) (dimensionless-fit).
    pub density: Option<f64>,
    /// Work of adhesion Δγ (J/m²) (adhesive-interpolation, superposition).
    pub work_of_adhesion: Option<f64>,
    /// Adhesion parameter Φ, instead of computing it from the material data
    /// (adhesive-interpolation).
    pub adhesion_parameter: Option<f64>,
    /// The non-adhesive model under [`PlasticModel::Superposition`] (one of
    /// [`PlasticModel::NON_ADHESIVE`]; any other is taken as interpolation).
    pub plastic_model: PlasticModel,
}

/// The result record of `tabor plastic`.
#[derive(Clone, Debug, Serialize)]
pub struct Plastic {
    /// The model's name.
    pub model: String,
    /// The branch of the loss computation.
    pub branch: String,
    /// The impact speed (m/s).
    pub impact_speed: f64,
    /// ε (5.37) in [0, 1].
    pub restitution: f64,
    /// |ΔU_kin| (J), capped at m v0²/2 when sticking.
    pub energy_loss: f64,
    /// Whether the sphere sticks.
    pub sticks: bool,
    /// Speed where plastic deformation begins (m/s).
    pub yield_velocity: f64,
    /// Sticking velocity (m/s) of the adhesive models.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sticking_velocity: Option<f64>,
    /// Sticking velocity (m/s) of the elastic adhesive part.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub elastic_sticking_velocity: Option<f64>,
    /// Adhesion parameter Φ (adhesive-interpolation).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub adhesion_parameter: Option<f64>,
    /// How the seed 001 fit was clamped (dimensionless-fit).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clamping: Option<Clamping>,
    /// Warnings, worded in the front end's [`Naming`].
    pub warnings: Vec<String>,
}

/// A non-adhesive model boxed, with its yield velocity and any clamping report.
struct NonAdhesive {
    model: Box<dyn ImpactModel>,
    yield_velocity: f64,
    clamping: Option<Clamping>,
}

fn non_adhesive(
    a: &PlasticArgs,
    which: PlasticModel,
    naming: Naming,
) -> Result<NonAdhesive, Error> {
    let contact = PlasticContact::new(a.modulus, a.radius, a.yield_stress)?;
    Ok(match which {
        PlasticModel::Thornton => {
            let m = PlasticImpact::new(contact, Thornton, a.mass)?;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: None,
            }
        }
        PlasticModel::JacksonGreen => {
            let nu = required(a.poisson_ratio, "poisson_ratio", which, naming)?;
            let m = PlasticContact::new(a.modulus, a.radius, a.yield_stress)
                .and_then(|contact| JacksonGreen::new(contact, nu))?
                .impact(a.mass, SimulationSettings::default())?;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: None,
            }
        }
        PlasticModel::DimensionlessFit => {
            let rho = required(a.density, "density", which, naming)?;
            let m = DimensionlessFit::new(a.modulus, a.yield_stress, rho, a.mass)?;
            let clamping = m.restitution(a.speed)?.clamping;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: Some(clamping),
            }
        }
        // interpolation (also the default under superposition)
        _ => {
            let m = PlasticImpact::new(contact, Interpolation::default(), a.mass)?;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: None,
            }
        }
    })
}

/// Validates `a` and computes the record of `tabor plastic`; messages and
/// warnings name the inputs in `naming`.
pub fn plastic(a: &PlasticArgs, naming: Naming) -> Result<Plastic, Error> {
    let which = a.model;
    let mut warnings = Vec::new();
    let mut elastic_sticking = None;
    let mut phi = None;
    let (model, yield_velocity, clamping): (Box<dyn ImpactModel>, f64, Option<Clamping>) =
        match which {
            PlasticModel::Superposition => {
                let dg = required(a.work_of_adhesion, "work_of_adhesion", which, naming)?;
                let n = non_adhesive(a, a.plastic_model, naming)?;
                let sphere = JkrSphere::new(a.modulus, a.radius, dg)?;
                let sup = Superposition::new(n.model, sphere)?;
                elastic_sticking =
                    Some(sticking_velocity(sup.adhesive(), tolerance::DEFAULT_TOLERANCE)?.speed);
                (Box::new(sup), n.yield_velocity, n.clamping)
            }
            PlasticModel::AdhesiveInterpolation => {
                let dg = required(a.work_of_adhesion, "work_of_adhesion", which, naming)?;
                // Validates E*, R, sigma_Y even when Phi is given.
                PlasticContact::new(a.modulus, a.radius, a.yield_stress)?;
                let m = JkrSphere::new(a.modulus, a.radius, dg)
                    .and_then(|sphere| match a.adhesion_parameter {
                        Some(p) => AdhesivePlasticContact::new(sphere, p),
                        None => AdhesivePlasticContact::from_yield_stress(sphere, a.yield_stress),
                    })
                    .and_then(|contact| AdhesiveInterpolationImpact::new(contact, a.mass))?;
                if a.adhesion_parameter.is_some() {
                    warnings.push(format!(
                        "adhesion parameter Phi given directly: {} is checked but \
                         not used (the model depends on v0/v_c and Phi only)",
                        naming.input("yield_stress")
                    ));
                }
                phi = Some(m.model().adhesion_parameter());
                elastic_sticking = Some(m.elastic_sticking_velocity());
                if m.yield_velocity() == 0.0 {
                    warnings.push(
                        "the adhesive yield load (5.111) is reached inside the JKR adhesive \
                         well: every impact deforms plastically (yield_velocity 0)"
                            .to_string(),
                    );
                }
                let v_y = m.yield_velocity();
                (Box::new(m), v_y, None)
            }
            other => {
                let n = non_adhesive(a, other, naming)?;
                (n.model, n.yield_velocity, n.clamping)
            }
        };
    let sticking = if matches!(
        which,
        PlasticModel::Superposition | PlasticModel::AdhesiveInterpolation
    ) {
        Some(sticking_velocity(&*model, tolerance::ACCURACY)?.speed)
    } else {
        None
    };
    let outcome = impact(&*model, a.speed)?;
    match clamping {
        Some(Clamping::ToOne) => warnings.push(
            "the dimensionless FEM fit gave a restitution above 1 (just above its yield velocity): clamped to 1"
                .into(),
        ),
        Some(Clamping::ToZero) => warnings
            .push("the dimensionless FEM fit gave a negative restitution: clamped to 0 (sticking)".into()),
        _ => {}
    }
    if a.speed <= yield_velocity && which != PlasticModel::AdhesiveInterpolation {
        warnings.push("impact speed at or below the yield velocity: elastic impact".into());
    }
    Ok(Plastic {
        model: outcome.model.clone(),
        branch: outcome.branch.clone(),
        impact_speed: a.speed,
        restitution: outcome.restitution,
        energy_loss: outcome.energy_loss,
        sticks: outcome.sticks,
        yield_velocity,
        sticking_velocity: sticking,
        elastic_sticking_velocity: elastic_sticking,
        adhesion_parameter: phi,
        clamping,
        warnings,
    })
}

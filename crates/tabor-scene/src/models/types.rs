//! The models a scene can use, as built once per scene (the types only: building
//! is in `build.rs`, evaluating in `evaluate.rs`).

use crate::combination::{AdhesionKind, EffectKind, EffectSet, PlasticityKind, Rule, ViscoKind};
use crate::error::SceneError;
use crate::inputs::Inputs;
use tabor_elastic::ElasticImpact;
use tabor_jkr::{GradedSphere, JkrImpact, JkrSphere};
use tabor_maugis::MaugisDugdaleImpact;
use tabor_plastic::{
    AdhesiveInterpolationImpact, DimensionlessFit, Interpolation, JacksonGreenImpact,
    PlasticImpact, Thornton, YieldVelocity,
};
use tabor_restitution::{EnergyLoss, Error, ImpactModel};
use tabor_viscoadhesive::ViscoadhesiveImpact;

/// The elastic adhesive models.
#[derive(Clone, Debug)]
pub(crate) enum AdhesiveModel {
    Jkr(JkrImpact<JkrSphere>),
    Graded(JkrImpact<GradedSphere>),
    /// The Maugis-Dugdale impact and the JKR sphere (E*, R, Δγ) it was built on.
    Maugis(MaugisDugdaleImpact, JkrSphere),
}

impl AdhesiveModel {
    pub(crate) fn model(&self) -> &(dyn ImpactModel + Send + Sync) {
        match self {
            AdhesiveModel::Jkr(m) => m,
            AdhesiveModel::Graded(m) => m,
            AdhesiveModel::Maugis(m, _) => m,
        }
    }
}

/// The scene's elastic adhesive model, its kind and why it was chosen.
#[derive(Clone, Debug)]
pub(crate) struct Adhesive {
    pub model: AdhesiveModel,
    pub kind: AdhesionKind,
    pub why: String,
}

/// The non-adhesive plastic models.
#[derive(Clone, Debug)]
pub(crate) enum Plastic {
    Thornton(PlasticImpact<Thornton>),
    Interpolation(PlasticImpact<Interpolation>),
    JacksonGreen(Box<JacksonGreenImpact>),
    Fit(DimensionlessFit),
}

/// A plastic impact model with its yield onset.
pub(crate) trait PlasticModel: ImpactModel + YieldVelocity + Send + Sync {}

impl<T: ImpactModel + YieldVelocity + Send + Sync> PlasticModel for T {}

impl Plastic {
    pub(crate) fn model(&self) -> &dyn PlasticModel {
        match self {
            Plastic::Thornton(m) => m,
            Plastic::Interpolation(m) => m,
            Plastic::JacksonGreen(m) => m.as_ref(),
            Plastic::Fit(m) => m,
        }
    }

    pub(crate) fn kind(&self) -> PlasticityKind {
        match self {
            Plastic::Interpolation(_) => PlasticityKind::Interpolation,
            _ => PlasticityKind::WithoutAdhesiveCounterpart,
        }
    }
}

/// The viscoelastic contact model and its kind.
pub(crate) struct Visco {
    pub kind: ViscoKind,
    pub model: Box<dyn ImpactModel + Send + Sync>,
    /// (E*, η_c) of a Kelvin-Voigt contact E*(s) = E* + η_c s.
    pub kelvin_voigt: Option<(f64, f64)>,
    pub why: String,
}

/// Everything a scene can use, built once.
pub(crate) struct Models {
    pub mass: f64,
    pub accuracy: f64,
    pub elastic: ElasticImpact,
    pub adhesive: Option<Adhesive>,
    pub plastic: Option<Plastic>,
    /// The adhesive interpolation model (5.111)-(5.126), for homogeneous adhesion
    /// with plasticity.
    pub adhesive_interpolation: Option<AdhesiveInterpolationImpact>,
    /// The fixed-grip JKR impact the adhesive interpolation model contains (its
    /// elastic part, for the adhesive-plastic excess).
    pub jkr_fixed_grip: Option<JkrImpact<JkrSphere>>,
    pub visco: Option<Visco>,
    pub viscous_adhesive: Option<ViscoadhesiveImpact>,
    /// The DEM damping law of `[damping]` and the laws it damps.
    pub damped: Option<Damped>,
    /// The scene field each effect's model errors point at.
    pub fields: EffectFields,
    /// The effects whose parameters the scene gives.
    pub candidates: EffectSet,
}

/// The scene field that a model's error points at, per effect.
#[derive(Clone, Copy, Debug)]
pub(crate) struct EffectFields {
    pub adhesion: &'static str,
    pub plasticity: &'static str,
    pub viscoelasticity: &'static str,
}

impl EffectFields {
    pub(crate) fn of(inputs: &Inputs) -> Self {
        EffectFields {
            adhesion: "adhesion.work_of_adhesion",
            plasticity: inputs.yield_stress_field(),
            viscoelasticity: if inputs.target.viscosity.is_some() {
                "target.viscosity"
            } else {
                "sphere.viscosity"
            },
        }
    }

    /// The field of `effect`'s parameter.
    pub fn field(&self, effect: EffectKind) -> &'static str {
        match effect {
            EffectKind::Adhesion => self.adhesion,
            EffectKind::Plasticity => self.plasticity,
            EffectKind::Viscoelasticity => self.viscoelasticity,
            EffectKind::Damping => "damping",
            EffectKind::Elasticity => "sphere.youngs_modulus",
        }
    }

    /// An error of the model of `effect`, pointing at its field.
    pub fn error(&self, effect: EffectKind, e: Error) -> SceneError {
        SceneError::field_model(self.field(effect), e)
    }
}

/// A loss, the model that produced it, and each effect's share of it (`None` when
/// the effects are coupled and the total is not a sum).
pub(crate) struct Evaluation {
    pub loss: EnergyLoss,
    pub model: String,
    pub rule: Rule,
    pub parts: Vec<(EffectKind, Option<f64>)>,
}

impl Models {
    /// The error of a model the scene did not build (an internal inconsistency).
    pub(crate) fn missing(what: &str) -> SceneError {
        SceneError::model(Error::Model {
            model: "scene",
            message: format!("internal: the {what} model was not built"),
        })
    }

    pub(crate) fn adhesive_model(&self) -> Result<&(dyn ImpactModel + Send + Sync), SceneError> {
        self.adhesive
            .as_ref()
            .map(|a| a.model.model())
            .ok_or_else(|| Self::missing("adhesive"))
    }

    pub(crate) fn plastic_model(&self) -> Result<&(dyn ImpactModel + Send + Sync), SceneError> {
        self.plastic
            .as_ref()
            .map(|p| p.model() as &(dyn ImpactModel + Send + Sync))
            .ok_or_else(|| Self::missing("plastic"))
    }

    pub(crate) fn visco_model(&self) -> Result<&(dyn ImpactModel + Send + Sync), SceneError> {
        self.visco
            .as_ref()
            .map(|v| v.model.as_ref())
            .ok_or_else(|| Self::missing("viscoelastic"))
    }
}

/// The scene's DEM damping law and the laws it damps, built once (its building
/// and evaluation: `damped.rs`).
pub(crate) struct Damped {
    pub damping: tabor_viscoadhesive::NormalDamping,
    /// The damped elastic adhesive impact (JKR or Maugis-Dugdale), when the scene
    /// has adhesion on a homogeneous target.
    pub adhesive: Option<ViscoadhesiveImpact>,
    /// The elastic contact (Hertz).
    pub(crate) elastic: tabor_elastic::ElasticContact,
    /// The Jackson-Green law, when the scene's plastic model is Jackson-Green.
    pub(crate) jackson_green: Option<tabor_plastic::JacksonGreenLaw>,
    pub(crate) settings: tabor_dynamics::SimulationSettings,
    pub(crate) accuracy: f64,
}

use crate::Result;
use serde::Serialize;
use tabor_numerics::Cost;

/// The kinetic energy a model says an impact loses, and how it got there.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EnergyLoss {
    /// Kinetic energy lost, |ΔU_kin| (J, ≥ 0). When it exceeds the kinetic energy
    /// before impact the bodies stick.
    pub joules: f64,
    /// Estimated absolute error of `joules` (J); 0 for closed forms.
    pub error_estimate: f64,
    /// Which formula or branch produced it (for example "JKR closed form (5.36)").
    pub branch: String,
    /// What the computation spent.
    pub cost: Cost,
}

impl EnergyLoss {
    /// A loss from a closed form: no error estimate, no cost.
    pub fn closed_form(joules: f64, branch: impl Into<String>) -> Self {
        EnergyLoss {
            joules,
            error_estimate: 0.0,
            branch: branch.into(),
            cost: Cost::ZERO,
        }
    }
}

/// A model of a central impact: one required answer, the energy it loses.
///
/// Everything else (restitution (5.37), sticking velocity (5.38), sweeps) is derived
/// generically in this crate from [`ImpactModel::energy_loss`].
pub trait ImpactModel {
    /// A short human-readable name, for example "JKR (fixed grip)".
    fn name(&self) -> String;

    /// The effective (reduced) mass m of the collision (kg).
    fn effective_mass(&self) -> f64;

    /// The kinetic energy lost by an impact at relative normal speed
    /// `impact_speed` > 0 (m/s). A model whose result would be meaningless (NaN,
    /// outside its domain) returns an error instead.
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss>;

    /// True when the loss does not depend on the impact speed (elastic adhesion): the
    /// sticking velocity is then the closed form (5.38).
    fn loss_is_speed_independent(&self) -> bool {
        false
    }

    /// A typical speed of the model (m/s), where the sticking-velocity search starts.
    fn speed_scale(&self) -> f64 {
        1.0
    }

    /// The highest impact speed at which the model is valid, when it has one (for
    /// example the small-strain limit of a simulated contact): the
    /// sticking-velocity search never evaluates the model above it.
    fn speed_limit(&self) -> Option<SpeedLimit> {
        None
    }
}

/// The highest impact speed at which a model is valid, and why.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SpeedLimit {
    /// The limit (m/s, > 0): the model answers at this speed and errs above it.
    pub speed: f64,
    /// What ends the validity, for example "small-strain limit".
    pub reason: &'static str,
}

macro_rules! forward_impact_model {
    ($($t:ty),*) => {$(
        impl<M: ImpactModel + ?Sized> ImpactModel for $t {
            fn name(&self) -> String {
                (**self).name()
            }
            fn effective_mass(&self) -> f64 {
                (**self).effective_mass()
            }
            fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
                (**self).energy_loss(impact_speed)
            }
            fn loss_is_speed_independent(&self) -> bool {
                (**self).loss_is_speed_independent()
            }
            fn speed_scale(&self) -> f64 {
                (**self).speed_scale()
            }
            fn speed_limit(&self) -> Option<SpeedLimit> {
                (**self).speed_limit()
            }
        }
    )*};
}

// A borrowed, boxed or shared model is a model: `Box<dyn ImpactModel>` works wherever
// a concrete model does.
forward_impact_model!(&M, Box<M>, std::sync::Arc<M>);

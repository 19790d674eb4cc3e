//! # tabor-plastic
//!
//! Elasto-plastic central impact, without and with adhesion (seed 000, sections 5.5
//! and 5.6; seed 001). Every model is a [`tabor_restitution::ImpactModel`], so the
//! restitution (5.37) and the sticking velocity come from `tabor-restitution`.
//!
//! Without adhesion (a rigid sphere on an elastic-perfectly plastic half-space):
//! - [`PlasticContact`]: Thornton's yield onset `d_Y`, `F_Y`, `v_Y` (5.102)-(5.103);
//! - [`PlasticImpact`] with a [`LoadingLaw`]: [`Thornton`] (5.101)-(5.106) or the
//!   [`Interpolation`] model (5.107) (also beyond the fully plastic onset), elastic
//!   unloading with `R_p` and `d_res`; [`PlasticForceLaw`] for the simulator;
//! - [`JacksonGreen`]: the FEM-based law, its impact solved in the time domain
//!   ([`JacksonGreenImpact`]), speed scale (5.108);
//! - [`DimensionlessFit`]: seed 001's fitted restitution (12), (18), (19).
//!
//! With adhesion:
//! - [`Superposition`]: plastic plus JKR losses (5.109)-(5.110);
//! - [`AdhesiveInterpolation`] (normalized) and [`AdhesiveInterpolationImpact`]
//!   (SI): (5.111)-(5.126), JKR relations from `tabor_jkr::normalized`.
//!
//! [`YieldVelocity`]: the impact speed where yield begins, for every model above.
//!
//! [`PlasticModel`] and [`AdhesivePlasticity`] are the menus the front ends name
//! these models by (`ALL`, `as_str`, `FromStr`).
//!
//! [`materials`] holds the comparison cases of seed 000 Table 5.2 and seed 001 Table 3.
//!
//! ```
//! use tabor_plastic::{PlasticContact, PlasticImpact, Thornton};
//! use tabor_restitution::impact;
//!
//! let contact = PlasticContact::new(1e11, 1e-3, 5e8)?;
//! let model = PlasticImpact::new(contact, Thornton, 1e-5)?;
//! let v_y = model.yield_velocity();
//! let e = impact(&model, 2.0 * v_y)?.restitution;
//! assert!((e - 0.9306).abs() < 1e-4);
//! # Ok::<(), tabor_restitution::Error>(())
//! ```

mod adhesive;
mod contact;
mod dimensionless_fit;
mod impact;
mod jackson_green;
mod loading;
pub mod materials;
mod menu;
mod superposition;
mod util;
mod yield_velocity;

pub use adhesive::{
    adhesion_parameter, adhesive_yield_force, AdhesiveForceLaw, AdhesiveInterpolation,
    AdhesiveInterpolationImpact, AdhesivePlasticContact, AdhesiveTurningPoint,
    ADHESION_PARAMETER_FACTOR, ADHESIVE_PLASTIC_ONSET, ADHESIVE_PLASTIC_SLOPE,
    WEAK_ADHESION_YIELD_COEFFICIENT,
};
pub use contact::{PlasticContact, LIMITING_PRESSURE_RATIO};
pub use dimensionless_fit::{Clamping, DimensionlessFit, FittedRestitution};
pub use impact::{PlasticForceLaw, PlasticImpact};
pub use jackson_green::{
    JacksonGreen, JacksonGreenImpact, JacksonGreenLaw, DEFAULT_HARDNESS_RATIO, FIT_ONSET,
};
pub use loading::{
    Interpolation, LoadingLaw, Thornton, TurningPoint, DEFAULT_PLASTIC_ONSET, DEFAULT_PLASTIC_SLOPE,
};
pub use menu::{AdhesivePlasticity, PlasticModel};
pub use superposition::Superposition;
pub use tabor_dynamics::SimulationSettings;
pub use tabor_restitution::{EnergyLoss, Error, Result};
pub use yield_velocity::YieldVelocity;

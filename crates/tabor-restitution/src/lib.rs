//! # tabor-restitution
//!
//! The energy-loss and restitution core. Every tabor model answers one question,
//! *how much kinetic energy does a central impact at speed `v0` lose?*, by
//! implementing [`ImpactModel`]. From that answer this crate derives, once and for
//! all models:
//!
//! - the coefficient of restitution, seed 000 eq. (5.37) ([`restitution_from_loss`],
//!   [`impact`]);
//! - the sticking velocity, closed form (5.38) when the loss does not depend on the
//!   speed, else the root of ε(v) = 0 ([`sticking_velocity`]);
//! - the validity checks of seed 000 section 5.1: quasi-static impact (5.4) and the
//!   elastic limit (5.13), reported as [`Warning`]s, not errors ([`checks`]).
//!
//! It also holds the effective properties of a collision ([`effective`]) and the
//! input validation every model uses ([`validate`]), and the surface every choice
//! menu shares ([`menu`](mod@menu): `ALL`, `as_str`, `FromStr`).

pub mod checks;
pub mod combine;
pub mod effective;
mod error;
pub mod menu;
mod model;
mod outcome;
pub mod validate;

pub use checks::Warning;
pub use combine::LossSum;
pub use effective::ElasticMaterial;
pub use error::Error;
pub use menu::{Menu, UnknownChoice};
pub use model::{EnergyLoss, ImpactModel, SpeedLimit};
pub use outcome::{
    impact, restitution_from_loss, sticking_velocity, ImpactOutcome, StickingMethod,
    StickingVelocity,
};
pub use tabor_numerics::Cost;

/// Result type of tabor's model crates.
pub type Result<T> = std::result::Result<T, Error>;

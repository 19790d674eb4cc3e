//! # tabor-penalty
//!
//! Penalty contact laws for multibody and DEM codes, and the bridge that lets tabor
//! *supply* their parameters.
//!
//! - Seed 002's contact characteristic ([`ContactCharacteristic`]):
//!   `F = k κ(h, ε) l(v, V)` with the piecewise-linear κ(h), its C¹ rounding over
//!   |h| < ε ([`contact_characteristic`]) and the loss factor l(v, V)
//!   ([`loss_factor`]); the hysteresis area of the seed's oscillation cycle
//!   ([`ContactCharacteristic::oscillation_loss`], closed form without rounding,
//!   quadrature with); the impact restitution as a function of V
//!   ([`characteristic_restitution`], an exact first integral) and the V for a
//!   target restitution ([`characteristic_loss_speed`]).
//! - The Hunt-Crossley form `F = K δⁿ (1 + χ δ̇)` ([`DampedPowerLaw`]) with the
//!   Hunt-Crossley (1975), Lankarani-Nikravesh (1990) and Flores et al. (2011)
//!   damping factors ([`DampingModel`]), the restitution such a law really produces
//!   ([`damped_restitution`], exact first integral) and the damping factor that
//!   produces a given restitution exactly ([`exact_damping_factor`]).
//! - The bridge ([`calibrate_damped_law`], [`calibrate_characteristic`]): the
//!   restitution of any `tabor_restitution::ImpactModel` at one speed turned into a
//!   penalty law with a stiffness from the Hertz contact of the same bodies
//!   ([`PenaltyStiffness::hertz`]) or given by the user, checked by a simulated
//!   impact (`tabor_dynamics::simulate_impact`; both laws implement `ForceLaw`).
//!
//! [`PenaltyLaw`] is the menu the front ends name the laws by (`ALL`, `as_str`,
//! `FromStr`).
//!
//! Every public function validates its input and returns
//! `tabor_restitution::Error` naming the parameter and its value.

mod bridge;
mod characteristic;
mod damped;
mod menu;
mod series;
mod valid;

pub use bridge::{calibrate_characteristic, calibrate_damped_law, Calibration, PenaltyStiffness};
pub use characteristic::{
    characteristic_loss_speed, characteristic_restitution, contact_characteristic, loss_factor,
    ContactCharacteristic,
};
pub use damped::{damped_restitution, exact_damping_factor, DampedPowerLaw, DampingModel};
pub use menu::PenaltyLaw;
/// The simulator the laws plug into (re-exported from `tabor-dynamics`, seed 000
/// eq. (5.5) generalized to `m d̈ = −F(d, ḋ)`).
pub use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
pub use tabor_restitution::{Error, Result};

//! # tabor-tangential
//!
//! Friction, rolling and twisting resistance of a contact, on any normal force law,
//! defined as LAMMPS's `pair_style granular` defines them (so that a LAMMPS user
//! gets the same numbers from the same parameters), and the oblique impact of two
//! spheres (or a sphere and a flat) that uses them.
//!
//! - [`Friction`] ([`Tangential`], [`Rolling`], [`Twisting`]) with the menus
//!   [`TangentialModel`], [`RollingModel`], [`TwistingModel`] (`ALL`, `as_str`,
//!   `FromStr`, the LAMMPS keywords);
//! - [`step`]: the per-contact, per-time-step evaluation a DEM engine calls
//!   ([`Friction::step`] with [`ContactKinematics`], [`NormalResponse`],
//!   [`ContactHistory`] → [`ContactForces`]), no allocation;
//! - [`critical_force`]: `F_n0`, the normal force of every Coulomb limit;
//! - [`oblique`]: the oblique impact integrated accurately in continuous time,
//!   with the stick/slip switches located as events and the energy lost to each
//!   mechanism.
//!
//! Sources: the crate README.

mod history;
pub mod micro_slip;
mod model;
pub mod oblique;
pub mod step;

pub use model::{
    critical_force, lammps_number, EffectiveShear, Friction, Rolling, RollingModel, Tangential,
    TangentialModel, Twisting, TwistingModel,
};
pub use step::{ContactForces, ContactHistory, ContactKinematics, NormalResponse};

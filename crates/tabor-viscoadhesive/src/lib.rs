//! # tabor-viscoadhesive
//!
//! Adhesive impact with viscous damping: a coupled model of ours, beyond the seeds.
//! The elastic adhesive force of JKR (seed 000 eqs. (5.33)-(5.36), either separation
//! rule) or Maugis-Dugdale (seed 000 section 5.3.2) plus the viscous force of a
//! Kelvin-Voigt contact modulus `E*(s) = E* + η_c s` in Kuwabara-Kono form (seed 000
//! eq. (5.66)), over the contact radius of the *adhesive* contact:
//!
//! ```text
//! m d̈ = −F_adhesive(d; history) − 2 η_c a(d) ḋ          (README eq. (V1))
//! ```
//!
//! - [`ViscousDamping`]: any `tabor_dynamics::ForceLaw` plus `2 η_c a ḋ`, every hook
//!   and branch delegated to the inner law; or plus a DEM damping law of LAMMPS's
//!   `pair granular` ([`NormalDamping`]: `viscoelastic`, `tsuji`,
//!   `coeff_restitution`, on the adhesive contact radius where LAMMPS refuses);
//! - [`ViscoadhesiveImpact`]: the model (E*, R, m, Δγ, [`Adhesion`], η_c, tolerance)
//!   as a `tabor_restitution::ImpactModel` (loss `(1 − ε²) m v0²/2` from
//!   `simulate_impact`), with the trajectory record and the comparison with the
//!   superposition of the adhesive and the Kuwabara-Kono losses ([`Superposition`]);
//! - [`SpeedTable`] (module [`table`]): the model's loss over a range of speeds,
//!   interpolated from simulations and certified against them, for sweeps
//!   ([`ViscoadhesiveImpact::with_speed_table`]).
//!
//! The derivation, the conventions (contact, separation, sticking) and the limits
//! Δγ → 0 and η_c → 0 are in the crate's README.

mod adhesive;
pub mod damping;
mod law;
mod model;
pub mod table;

pub use adhesive::AdhesiveForceLaw;
pub use damping::{coeff_restitution_alpha, tsuji_alpha, DampingModel, NormalDamping};
pub use law::{SeparationPotential, ViscousDamping};
pub use model::{Adhesion, AdhesiveImpact, Superposition, ViscoadhesiveImpact};
pub use table::SpeedTable;
pub use tabor_jkr::SeparationRule;
pub use tabor_restitution::{Error, Result};

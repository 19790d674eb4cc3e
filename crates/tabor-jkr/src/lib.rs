//! # tabor-jkr
//!
//! JKR-adhesive central impact of elastic bodies (seed 000, section 5.3.1 and 5.3.3):
//!
//! - [`JkrSphere`]: the parabolic contact (a sphere of effective radius R), static
//!   relations (5.33)-(5.34), maximum contact radius from the energy balance (5.35),
//!   adhesive loss (5.36); its dimensionless core is [`normalized`] (the units of the
//!   force-controlled critical state, `a_c`, `F_n`, `d_n`);
//! - [`PowerLawProfile`]: an indenter `f(r) = A rⁿ`, n > 1/2, with the adhesive
//!   relations of the method of dimensionality reduction and the loss (5.39);
//! - [`GradedSphere`]: a sphere on a power-law graded medium (modulus ∝ depth^k,
//!   −1 < k < 1), (5.47)-(5.52);
//! - [`JkrImpact`]: any of these plus an effective mass and a [`SeparationRule`],
//!   implementing [`tabor_restitution::ImpactModel`], so restitution (5.37) and the
//!   sticking velocity (5.38) come from the generic functions of `tabor-restitution`.
//!
//! The loss does not depend on the impact speed: the contact is elastic, and the
//! kinetic energy lost is the work done against adhesion between first touch (d = 0)
//! and separation. Where contact breaks is a modelling choice, made explicit by
//! [`SeparationRule`]: at the displacement-controlled instability (fixed grip, the
//! seed's `d_c^WS`, the default) or at the load-controlled pull-off point (as some DEM
//! codes do), which roughly halves the loss of a sphere. The fixed-grip losses are the
//! seed's closed forms; the load-controlled ones have no closed form in the seed and
//! are computed by quadrature of `∫ F dd` along the same contact relations, with a
//! tolerance, an error estimate and a cost.
//!
//! Sign conventions: the force `F` is positive in compression, the depth `d` is
//! positive for overlap (negative when the bodies are stretched apart by adhesion),
//! losses are reported as magnitudes |ΔU_kin| ≥ 0.
//!
//! ```
//! use tabor_jkr::{JkrImpact, JkrSphere, SeparationRule};
//! use tabor_restitution::{impact, sticking_velocity};
//!
//! // Two silica spheres of radius 1 µm (effective quantities).
//! let sphere = JkrSphere::new(2.78e10, 0.5e-6, 0.05)?;
//! let model = JkrImpact::new(sphere, 5.55e-15)?;
//! let v_c = sticking_velocity(&model, 1e-12)?.speed;
//! assert!((v_c - 0.0866).abs() < 1e-3);
//! let outcome = impact(&model, 0.2)?;
//! assert!(outcome.restitution > 0.0 && outcome.restitution < 1.0);
//! let dem = model.with_separation(SeparationRule::LoadControlled);
//! assert!(sticking_velocity(&dem, 1e-12)?.speed < v_c);
//! # Ok::<(), tabor_restitution::Error>(())
//! ```

mod common;
mod dynamics;
mod graded;
mod impact;
pub mod normalized;
mod power_law;
mod relations;
mod sphere;

pub use common::{JkrContactState, JkrNormalizedLoss, MaxContactRadius, SeparationRule};
pub use dynamics::JkrForceLaw;
pub use graded::GradedSphere;
pub use impact::{AdhesiveContact, JkrImpact, DEFAULT_TOLERANCE};
pub use power_law::PowerLawProfile;
pub use sphere::{JkrScales, JkrSphere};
pub use tabor_restitution::{EnergyLoss, Error, Result};

//! # tabor-elastic
//!
//! The quasi-static central impact of a rigid indenter on an elastic half-space
//! without adhesion, seed 000 section 5.2 (eqs. (5.5)-(5.32)):
//!
//! - [`ElasticContact`]: the static force law F(d), contact radius a(d) and stored
//!   energy U(d) of a Hertzian sphere (5.5), a power-law indenter `f(r) = A rⁿ`
//!   (5.15), a sphere on a power-law graded medium (5.20) and a power-law indenter
//!   on a graded medium (5.28). It is a `tabor_dynamics::ForceLaw` (one conservative
//!   branch), so the time-domain simulator of `tabor-dynamics` integrates it.
//! - [`ElasticImpact`]: the closed-form impact: d_max (5.8)/(5.16)/(5.21)/(5.28),
//!   F_max (5.9), the inverse trajectory t(d) through the incomplete beta function
//!   (5.11)/(5.17)/(5.22)/(5.29), the contact time T_S (5.12)/(5.18)/(5.23)/(5.30),
//!   p_max (5.13)/(5.24), Hunter's sine approximation (5.14); and an
//!   [`tabor_restitution::ImpactModel`] with loss 0 (restitution 1).
//! - [`trajectory`]: the normalized trajectory t̂(d̂) (5.31) that depends only on
//!   ñ = n/(1+k) (5.32), and its harmonic limit (5.19).
//!
//! All inputs are effective quantities (E* or c_N, R or A and n, m); errors name
//! the offending parameter and value.

mod contact;
mod force_law;
mod impact;
pub mod trajectory;

pub use contact::{hertz_force, ContactGeometry, ElasticContact};
pub use impact::ElasticImpact;

//! # tabor
//!
//! Adhesive impact of elastic, plastic and viscoelastic spheres: how much energy a
//! central impact loses, the coefficient of restitution, the sticking velocity.
//!
//! This facade re-exports the workspace crates:
//!
//! - [`numerics`]: root finding, quadrature, special functions, cost accounting;
//! - [`restitution`]: effective properties, the [`ImpactModel`](restitution::ImpactModel)
//!   trait, restitution and sticking velocity from an energy loss.

pub use tabor_numerics as numerics;

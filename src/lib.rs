//! # tabor
//!
//! Adhesive impact of elastic, plastic and viscoelastic spheres: how much energy a
//! central impact loses, the coefficient of restitution, the sticking velocity.
//!
//! This facade re-exports the workspace crates:
//!
//! - [`numerics`]: root finding, quadrature, special functions, Chebyshev
//!   interpolation, cost accounting;
//! - [`restitution`]: effective properties, the [`ImpactModel`](restitution::ImpactModel)
//!   trait, restitution and sticking velocity from an energy loss;
//! - [`maugis`]: Maugis-Dugdale adhesive impact across the Tabor-parameter range.

pub use tabor_maugis as maugis;
pub use tabor_numerics as numerics;
pub use tabor_restitution as restitution;

//! # tabor-maugis
//!
//! Maugis-Dugdale adhesive impact of elastic spheres across the whole range of the
//! Tabor parameter Λ, seed 000 section 5.3.2, eqs. (5.40)-(5.46) and Fig. 5.2, in the
//! normalization of `../shared/spec/maugis-dugdale.md` (scales a_c, F_n, d_n of the
//! JKR force-controlled critical state; `Λ = d_n/h`).
//!
//! - [`branch`]: the contact branch parametrized by θ = arccos(â/b̂) (explicit,
//!   series for small θ) and the no-contact branch (closed form);
//! - [`impact_path`]: the case (1, 2, 3), the jump-in and pull-off states;
//! - [`normalized_loss`]: the loss W(Λ) in units of F_n d_n and over the JKR loss,
//!   direct evaluation to a requested tolerance with cost and error estimate;
//! - [`loss_over_jkr_fast`]: the fast tier (precomputed Chebyshev interpolant,
//!   relative error < 1e-10 for every Λ);
//! - [`units`]: scales and conversions into Λ from σ0, h, Maugis' λ, Tabor's μ;
//! - [`MaugisDugdaleImpact`]: the SI front, an `ImpactModel` (restitution and
//!   sticking velocity through `tabor-restitution`);
//! - [`trace_impact`], [`equilibrium_state`]: the curve F̂(d̂) along the impact.

pub mod branch;
mod dynamics;
mod fast;
mod impact;
mod model;
mod trace;
pub mod units;

pub use dynamics::MaugisDugdaleForceLaw;
pub use fast::{fast_tier_pieces, loss_over_jkr_fast, prepare_fast_tier, FAST_TIER_RELATIVE_ERROR};
pub use impact::{
    impact_path, jkr_normalized_loss, normalized_loss, ImpactPath, MaugisNormalizedLoss, PathState,
    TaborCase, LAMBDA_1, LAMBDA_2, LAMBDA_JKR_LIMIT,
};
pub use model::MaugisDugdaleImpact;
pub use trace::{equilibrium_state, trace_impact, Phase, TracePoint};

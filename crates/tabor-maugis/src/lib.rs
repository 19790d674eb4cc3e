//! # tabor-maugis
//!
//! Maugis-Dugdale adhesive impact of elastic spheres across the whole range of the
//! Tabor parameter Λ, seed 000 section 5.3.2, eqs. (5.40)-(5.46) and Fig. 5.2, in the
//! normalization below (scales a_c, F_n, d_n of the JKR force-controlled critical
//! state; `Λ = d_n/h`).
//!
//! ## Normalization
//!
//! Seed 000 uses the Maugis-Dugdale (MD) contact solution of its chapter 3 (not
//! available); it is given here in exactly the seed's normalization, derived from
//! Maugis (1992) and checked against every closed form the seed quotes
//! (5.40)-(5.46). Symbols: `E` the effective modulus E* (1/E* = (1−ν1²)/E1 +
//! (1−ν2²)/E2), `R` the effective radius, `Δγ` the work of adhesion (J/m²), `σ0`, `h`
//! the Dugdale cohesive stress and range (`σ0 h = Δγ`), `a`, `b` the radii of direct
//! contact and of the cohesive zone (`b ≥ a`), `d` the depth (negative = separated),
//! `F` the force, **positive in compression**.
//!
//! Scales (the JKR force-controlled critical state, [`units::JkrScales`]):
//!
//! ```text
//! a_c = (9 π Δγ R² / (8 E))^(1/3),   F_n = (3/2) π Δγ R,   d_n = a_c² / (3 R),
//! â = a/a_c,  b̂ = b/a_c,  d̂ = d/d_n,  F̂ = F/F_n,
//! energies in F_n d_n = (3·3^(1/3)/8) [R⁴ (πΔγ)⁵ / E²]^(1/3).
//! ```
//!
//! The single MD parameter is `Λ = d_n / h = σ0 a_c² / (3 R Δγ)`. It relates to
//! Maugis' `λ = 2σ0 (R/(π Δγ K²))^(1/3)`, `K = 4E/3`, by `Λ = π (9/4)^(1/3) / 6 · λ
//! ≈ 0.6861 λ`, and to Tabor's `μ = (R Δγ² / (E² z0³))^(1/3)` by the Dugdale
//! equivalence `λ ≈ 1.1570 μ` (Johnson & Greenwood 1997: σ0 = 1.03 σ_th, h = 0.97 z0;
//! so Λ = 4 is μ ≈ 5, as the seed says). [`units`] converts.
//!
//! JKR in these units: `F̂ = â³ − 2 â^(3/2)`, `d̂ = 3 â² − 4 â^(1/2)`; first touch
//! `d̂ = 0`, `â0 = (4/3)^(2/3)`; displacement-controlled pull-off `â = (1/3)^(2/3)`,
//! `d̂ = −3^(2/3)`; the JKR loss (5.36) is about 1.9459 `F_n d_n`.
//!
//! The branch with direct contact (â > 0), with `s = √(b̂² − â²)`,
//! `θ = arccos(â/b̂)` ∈ [0, π/2] ([`branch::contact_state`] parametrizes by θ):
//!
//! ```text
//! gap condition:  (3Λ/π) [â s + (b̂² − 2â²) θ] + (32Λ²/π²) [s θ − b̂ + â] = 1
//! depth:          d̂ = 3 â² − (16Λ/π) s
//! force:          F̂ = â³ − (4Λ/π) [â s + b̂² θ]
//! ```
//!
//! For fixed â the gap condition's left side grows monotonically with b̂ from 0 at
//! b̂ = â, so b̂(â) is unique. The branch without direct contact (â = 0, uniform
//! tension σ0 on a disc of radius b̂, [`branch::no_contact_state`]):
//! `d̂ = (3/2) b̂² − (32Λ/π²) b̂ − 1/Λ`, `F̂ = −2Λ b̂²`, for `b̂ ≤ K b̂_c` with
//! `b̂_c = 32Λ/(3π²)` (the minimum of d̂ on it) and
//! `K = 1 − π/2 + √((1 − π/2)² + 3π⁴/(2⁹ Λ³))`; at `b̂ = K b̂_c` it meets the contact
//! branch at â → 0.
//!
//! The impact: the sphere approaches with F = 0 until the gap at the first point is
//! h, `d̂0 = −1/Λ` (5.40), jumps onto the stable equilibrium state with that depth
//! (without contact `b̂0 = 2b̂_c`, (5.41)), loads and unloads along the equilibrium
//! branch, and snaps off at the displacement-controlled instability (the minimum of
//! d̂ along the branch). The loss is the area under the tensile force between the two
//! depths (5.43), `|ΔU_kin| = F_n d_n · |∫_{−1/Λ}^{d̂_c} F̂ dd̂|`. The three cases
//! ([`TaborCase`]): 1, `Λ ≤ Λ1 = (3π³/1024)^(1/3) ≈ 0.4496`, no contact at either
//! end, closed form `17·2¹⁹Λ⁵/(3⁴π⁸)` (5.44); 2, `Λ1 < Λ ≤ Λ2 ≈ 0.6435` (K = 1),
//! contact at jump-in only, quadrature on the contact branch plus the closed form
//! (5.45)-(5.46); 3, `Λ > Λ2`, contact at both ends, quadrature (5.43). Over the JKR
//! loss the result depends on Λ alone, is below 1 for every finite Λ and tends to 1
//! as Λ → ∞ (Fig. 5.2).
//!
//! - [`branch`]: the contact branch parametrized by θ = arccos(â/b̂) (explicit,
//!   series for small θ) and the no-contact branch (closed form);
//! - [`impact_path`]: the case (1, 2, 3), the jump-in and pull-off states;
//! - [`normalized_loss`]: the loss W(Λ) in units of F_n d_n and over the JKR loss,
//!   direct evaluation to a requested tolerance with cost and error estimate;
//! - [`loss_over_jkr_fast`]: the fast tier (precomputed piecewise Chebyshev table,
//!   relative error < 1e-10 for every Λ);
//! - [`units`]: scales and conversions into Λ from σ0, h, Maugis' λ, Tabor's μ;
//! - [`MaugisDugdaleImpact`]: the SI front, an `ImpactModel` (restitution and
//!   sticking velocity through `tabor-restitution`);
//! - [`trace_impact`], [`equilibrium_state`]: the curve F̂(d̂) along the impact;
//! - [`maugis_curve_point`], [`contact_state_at_radius`]: the equilibrium curve at a
//!   given contact radius (in Maugis' units, as `Adhesion` evaluates it);
//!   [`MaugisDugdaleSphere`] and [`dmt_curve_point`]: the curve and its DMT limit
//!   in SI units ([`CurveModel`]: the menu of these curves and JKR's).

pub mod branch;
mod curve;
mod dynamics;
mod fast;
mod impact;
mod model;
mod trace;
pub mod units;

pub use curve::{
    contact_state_at_radius, dmt_curve_point, maugis_curve_point, CurveModel, MaugisCurvePoint,
    MaugisDugdaleSphere, SphereCurvePoint, MIN_MAUGIS_PARAMETER,
};
pub use dynamics::MaugisDugdaleForceLaw;
pub use fast::{fast_tier_pieces, loss_over_jkr_fast, prepare_fast_tier, FAST_TIER_RELATIVE_ERROR};
pub use impact::{
    impact_path, jkr_normalized_loss, normalized_loss, ImpactPath, MaugisNormalizedLoss, PathState,
    TaborCase, LAMBDA_1, LAMBDA_2, LAMBDA_JKR_LIMIT,
};
pub use model::{MaugisContact, MaugisDugdaleImpact};
pub use trace::{equilibrium_state, trace_impact, Phase, TracePoint};

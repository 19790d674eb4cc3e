//! The fast tier: a precomputed table of `W(Λ)/W_JKR`, piecewise polynomials on
//! equal pieces (`tabor_numerics::chebyshev::UniformChebyshevTable`).
//!
//! - Case 1 (Λ ≤ Λ1) is the closed form (5.44) itself.
//! - Case 2 (Λ1 < Λ ≤ Λ2) is tabulated in `u = √((Λ − Λ1)/(Λ2 − Λ1))`: the loss
//!   has a `(Λ − Λ1)^(5/2)` term at Λ1 (the contact part of the path starts there),
//!   which is smooth in u but would stall a polynomial in Λ.
//! - Case 3 (Λ > Λ2) is tabulated in `t = Λ2/Λ ∈ (0, 1)`: the loss tends to the
//!   JKR value as `1 − c/Λ + O(Λ⁻²)`, analytic in t, so one table covers Λ up to
//!   infinity (t = 0 is the JKR limit, ratio 1). The table holds the shortfall
//!   over t, `(1 − W/W_JKR)/t` (→ 0.4568/Λ2 as t → 0), so the shortfall `t·g(t)`
//!   vanishes at t = 0 by construction and the ratio is 1 to rounding in the JKR
//!   limit (a table of the shortfall itself extrapolated its samples' rounding,
//!   a few 1e-16, to t = 0).
//!
//! Each piece is the interpolant at [`POINTS`] Chebyshev points (degree 7, Estrin's
//! scheme), the piece found by one multiplication: about a quarter of the work of
//! the adaptive 32-point Chebyshev pieces and Clenshaw's recurrence this tier used
//! before (`docs/benchmarks.md`). The table is built from the direct evaluation at
//! tolerance 1e-14 on first use (768 evaluations, a few milliseconds) and kept for
//! the life of the process; its error is certified against the direct evaluation
//! by `tests/maugis.rs` (`fast_tier_agrees_with_direct`).

use crate::impact::{jkr_normalized_loss, normalized_loss, TaborCase, LAMBDA_1, LAMBDA_2};
use std::sync::OnceLock;
use tabor_numerics::chebyshev::UniformChebyshevTable;
use tabor_numerics::Cost;
use tabor_restitution::Result;

/// The error bound the fast tier is built and tested for: relative error of
/// `W/W_JKR` below 1e-10 against the direct evaluation, for every Λ > 0.
pub const FAST_TIER_RELATIVE_ERROR: f64 = 1e-10;

/// Chebyshev points per piece (polynomials of degree 7).
const POINTS: usize = 8;
/// Pieces of case 2 (in u) and case 3 (in t): coefficient tails (the degree-6 and
/// degree-7 coefficients, an overestimate of the error) 1.6e-12 and 7.0e-12, worst
/// error against the direct evaluation 1.1e-14 (`fast_tier_agrees_with_direct`).
/// Case 3 is the harder one next to Λ2, where the pull-off moves onto the contact
/// branch.
const PIECES_CASE_2: usize = 32;
const PIECES_CASE_3: usize = 64;
/// Relative coefficient tail accepted per piece: a build that does not resolve
/// the loss this well fails instead of returning a worse table.
const TAIL: f64 = 1e-11;
/// Direct-evaluation tolerance of the samples.
const SAMPLE_TOLERANCE: f64 = 1e-14;

struct Table {
    case2: UniformChebyshevTable<POINTS>,
    case3: UniformChebyshevTable<POINTS>,
}

static TABLE: OnceLock<Result<Table>> = OnceLock::new();

fn build() -> Result<Table> {
    let sample = |lambda: f64| normalized_loss(lambda, SAMPLE_TOLERANCE).map(|w| w.loss_over_jkr);
    let span = LAMBDA_2 - LAMBDA_1;
    let case2 = UniformChebyshevTable::fit(
        |u| sample(LAMBDA_1 + span * u * u),
        0.0,
        1.0,
        PIECES_CASE_2,
        TAIL,
    )?;
    // case 3 holds the shortfall over t, (1 − W/W_JKR)/t: the shortfall t·g(t) is
    // then 0 at t = 0 whatever the samples' rounding, so the ratio is 1 to the last
    // bit in the JKR limit (the rounding of a sample, a few 1e-16 of the ratio,
    // becomes 1e-12 of g at the smallest t, 1.5e-4, within the tail accepted)
    let case3 = UniformChebyshevTable::fit(
        |t| sample(LAMBDA_2 / t).map(|ratio| (1.0 - ratio) / t),
        0.0,
        1.0,
        PIECES_CASE_3,
        TAIL,
    )?;
    Ok(Table { case2, case3 })
}

fn table() -> Result<&'static Table> {
    TABLE.get_or_init(build).as_ref().map_err(Clone::clone)
}

/// `1/(Λ2 − Λ1)`.
const INVERSE_CASE_2_SPAN: f64 = 1.0 / (LAMBDA_2 - LAMBDA_1);

/// `W(Λ)/W_JKR` from the precomputed table (relative error below
/// [`FAST_TIER_RELATIVE_ERROR`]); the first call builds the table.
///
/// Seed 000 Fig. 5.2. Case 1 uses the closed form (5.44) directly.
pub fn loss_over_jkr_fast(lambda: f64) -> Result<f64> {
    let lambda = crate::impact::check_lambda(lambda)?;
    Ok(match TaborCase::of(lambda) {
        TaborCase::NoContact => {
            let bc = crate::branch::no_contact_pull_off_radius(lambda);
            8.5 * lambda * bc * bc * bc * bc / jkr_normalized_loss()
        }
        TaborCase::ContactThenNoContact => {
            let u = ((lambda - LAMBDA_1) * INVERSE_CASE_2_SPAN).sqrt();
            table()?.case2.eval(u)
        }
        // W/W_JKR < 1: a shortfall rounded below 0 is cut off
        TaborCase::Contact => {
            let t = LAMBDA_2 / lambda;
            (1.0 - t * table()?.case3.eval(t)).min(1.0)
        }
    })
}

/// Builds the fast-tier table now (otherwise the first call does) and reports
/// what it cost: direct evaluations and pieces.
pub fn prepare_fast_tier() -> Result<Cost> {
    let t = table()?;
    Ok(t.case2.cost() + t.case3.cost())
}

/// Number of pieces of (case 2, case 3).
pub fn fast_tier_pieces() -> Result<(usize, usize)> {
    let t = table()?;
    Ok((t.case2.pieces(), t.case3.pieces()))
}

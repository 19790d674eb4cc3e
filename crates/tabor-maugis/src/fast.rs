//! The fast tier: a precomputed piecewise Chebyshev interpolant of `W(Λ)/W_JKR`.
//!
//! - Case 1 (Λ ≤ Λ1) is the closed form (5.44) itself.
//! - Case 2 (Λ1 < Λ ≤ Λ2) is interpolated in `u = √((Λ − Λ1)/(Λ2 − Λ1))`: the loss
//!   has a `(Λ − Λ1)^(5/2)` term at Λ1 (the contact part of the path starts there),
//!   which is smooth in u but would stall a Chebyshev series in Λ.
//! - Case 3 (Λ > Λ2) is interpolated in `t = Λ2/Λ ∈ (0, 1)`: the loss tends to the
//!   JKR value as `1 − c/Λ + O(Λ⁻²)`, analytic in t, so one table covers Λ up to
//!   infinity (t = 0 is the JKR limit, ratio 1).
//!
//! The table is built from the direct evaluation at tolerance 1e-14 on first use
//! (about 1-2 ms) and kept for the life of the process.

use crate::impact::{jkr_normalized_loss, normalized_loss, TaborCase, LAMBDA_1, LAMBDA_2};
use std::sync::OnceLock;
use tabor_numerics::chebyshev::PiecewiseChebyshev;
use tabor_numerics::Cost;
use tabor_restitution::Result;

/// The error bound the fast tier is built and tested for: relative error of
/// `W/W_JKR` below 1e-10 against the direct evaluation, for every Λ > 0.
pub const FAST_TIER_RELATIVE_ERROR: f64 = 1e-10;

/// Chebyshev points per piece.
const POINTS: usize = 32;
/// Relative coefficient tail accepted per piece.
const TAIL: f64 = 1e-14;
/// Direct-evaluation tolerance of the samples.
const SAMPLE_TOLERANCE: f64 = 1e-14;

struct Table {
    case2: PiecewiseChebyshev,
    case3: PiecewiseChebyshev,
}

static TABLE: OnceLock<Result<Table>> = OnceLock::new();

fn build() -> Result<Table> {
    let sample = |lambda: f64| normalized_loss(lambda, SAMPLE_TOLERANCE).map(|w| w.loss_over_jkr);
    let span = LAMBDA_2 - LAMBDA_1;
    let case2 = PiecewiseChebyshev::fit(
        |u| sample(LAMBDA_1 + span * u * u),
        0.0,
        1.0,
        POINTS,
        TAIL,
        64,
    )?;
    let case3 = PiecewiseChebyshev::fit(|t| sample(LAMBDA_2 / t), 0.0, 1.0, POINTS, TAIL, 256)?;
    Ok(Table { case2, case3 })
}

fn table() -> Result<&'static Table> {
    TABLE.get_or_init(build).as_ref().map_err(Clone::clone)
}

/// `W(Λ)/W_JKR` from the precomputed interpolant (relative error below
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
            let u = ((lambda - LAMBDA_1) / (LAMBDA_2 - LAMBDA_1)).sqrt();
            table()?.case2.eval(u)
        }
        // W/W_JKR < 1: the interpolant's rounding above 1 as t → 0 is cut off
        TaborCase::Contact => table()?.case3.eval(LAMBDA_2 / lambda).min(1.0),
    })
}

/// Builds the fast-tier table now (otherwise the first call does) and reports
/// what it cost: direct evaluations and pieces.
pub fn prepare_fast_tier() -> Result<Cost> {
    let t = table()?;
    Ok(t.case2.cost() + t.case3.cost())
}

/// Number of Chebyshev pieces of (case 2, case 3).
pub fn fast_tier_pieces() -> Result<(usize, usize)> {
    let t = table()?;
    Ok((t.case2.pieces().len(), t.case3.pieces().len()))
}

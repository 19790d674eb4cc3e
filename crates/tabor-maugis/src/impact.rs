//! The Maugis-Dugdale impact path and its adhesive energy loss, seed 000 section
//! 5.3.2, eqs. (5.40)-(5.46).

use crate::branch::{
    contact_state, depth_slope_and_curvature, junction_factor, no_contact_pull_off_radius,
    no_contact_state,
};
use serde::Serialize;
use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::OnceLock;
use tabor_numerics::quadrature::{integrate_smooth, GaussLegendrePair, Integral};
use tabor_numerics::root_finding::{brent, newton_safeguarded};
use tabor_numerics::{Cost, NumericsError, QuadTolerance, RootTolerance};
use tabor_restitution::{validate, Error, Result};

/// `Λ1 = (3π³/1024)^(1/3) ≈ 0.4495`: at and below it the impact starts and ends
/// without direct contact (case 1). Seed 000 eq. (5.42).
pub const LAMBDA_1: f64 = 0.449_528_231_858_144;

/// `Λ2 = (3π⁴/(512(π − 1)))^(1/3) ≈ 0.6435` (K = 1): above it the impact also ends
/// with direct contact (case 3). Seed 000 eq. (5.46) and the text after (5.42).
pub const LAMBDA_2: f64 = 0.643_533_715_989_629_8;

/// From this Λ on, [`normalized_loss`] returns the JKR limit: there
/// `1 − W/W_JKR ≈ 0.4568/Λ` (the asymptote tested against the mpmath reference) is
/// below 4.6e-17, less than half the spacing of doubles below 1, so `W_JKR` is the
/// correctly rounded loss, whereas the branch itself loses its last digits to
/// rounding (ratios of 1 + 1e-15) and, beyond Λ ≈ 1e76, θ³ underflows.
pub const LAMBDA_JKR_LIMIT: f64 = 1e16;

/// The JKR loss in units of `F_n d_n`, `4(1 + ∛864)/(15 ∛3) ≈ 1.9459`: seed 000
/// eq. (5.36) from `tabor-jkr` (fixed grip, the displacement-driven separation that
/// the Maugis-Dugdale impact also follows). The prefactor of (5.43) is its inverse.
///
/// Computed once per process (it divides every loss, so the case-1 closed form and
/// the fast tier would otherwise spend most of their time on it); the closed form is
/// written out as the fallback of the (infallible) call.
pub fn jkr_normalized_loss() -> f64 {
    static W_JKR: OnceLock<f64> = OnceLock::new();
    *W_JKR.get_or_init(|| {
        tabor_jkr::normalized::energy_loss(tabor_jkr::SeparationRule::FixedGrip, 0.5)
            .map(|l| l.value)
            .unwrap_or_else(|_| 4.0 * (1.0 + 864f64.cbrt()) / (15.0 * 3f64.cbrt()))
    })
}

/// Which path the impact takes (seed 000 section 5.3.2, the three cases).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TaborCase {
    /// Case 1, Λ ≤ Λ1: starts and ends without direct contact; closed form (5.44).
    NoContact,
    /// Case 2, Λ1 < Λ ≤ Λ2: starts with direct contact, ends without; quadrature on
    /// the contact branch plus the closed form (5.46).
    ContactThenNoContact,
    /// Case 3, Λ > Λ2: starts and ends with direct contact; quadrature (5.43).
    Contact,
}

impl TaborCase {
    /// The case of a Tabor parameter Λ > 0.
    pub fn of(lambda: f64) -> TaborCase {
        if lambda <= LAMBDA_1 {
            TaborCase::NoContact
        } else if lambda <= LAMBDA_2 {
            TaborCase::ContactThenNoContact
        } else {
            TaborCase::Contact
        }
    }

    /// The seed's case number, 1, 2 or 3.
    pub fn number(&self) -> u8 {
        match self {
            TaborCase::NoContact => 1,
            TaborCase::ContactThenNoContact => 2,
            TaborCase::Contact => 3,
        }
    }
}

/// A normalized equilibrium state on the impact path.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PathState {
    /// Contact radius â (0 without direct contact).
    pub contact_radius: f64,
    /// Cohesive-zone radius b̂.
    pub cohesive_radius: f64,
    /// Depth d̂.
    pub depth: f64,
    /// Force F̂, positive in compression.
    pub force: f64,
    /// θ of the contact branch, or `None` on the no-contact branch.
    pub theta: Option<f64>,
}

impl PathState {
    fn from_contact(lambda: f64, theta: f64) -> Self {
        let s = contact_state(lambda, theta);
        PathState {
            contact_radius: s.contact_radius,
            cohesive_radius: s.cohesive_radius,
            depth: s.depth,
            force: s.force,
            theta: Some(theta),
        }
    }
    fn from_no_contact(lambda: f64, b: f64) -> Self {
        let s = no_contact_state(lambda, b);
        PathState {
            contact_radius: 0.0,
            cohesive_radius: b,
            depth: s.depth,
            force: s.force,
            theta: None,
        }
    }
}

/// The characteristic states of a Maugis-Dugdale impact at Tabor parameter Λ.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ImpactPath {
    /// The Tabor parameter Λ.
    pub lambda: f64,
    /// The case (1, 2 or 3).
    pub case: TaborCase,
    /// The state right after jump-in at d̂ = −1/Λ (5.40), (5.41).
    pub jump_in: PathState,
    /// The state at pull-off, the minimum of d̂ along the path (the
    /// displacement-controlled instability).
    pub pull_off: PathState,
    /// Cost of locating the states.
    pub cost: Cost,
}

/// Checks Λ: finite and > 0.
pub(crate) fn check_lambda(lambda: f64) -> Result<f64> {
    let lambda = validate::positive("tabor_parameter", lambda)?;
    // the jump-in depth −1/Λ must be finite (Λ subnormal overflows it)
    if !(1.0 / lambda).is_finite() {
        return Err(Error::invalid(
            "tabor_parameter",
            lambda,
            "is so small that the jump-in depth -1/Lambda overflows",
        ));
    }
    Ok(lambda)
}

const ROOT_TOL: RootTolerance = RootTolerance {
    absolute: 0.0,
    relative: 1e-15,
    max_iterations: 200,
};

/// The impact path at Tabor parameter Λ: case, jump-in and pull-off states.
///
/// Seed 000 eqs. (5.40)-(5.42): jump-in at d̂0 = −1/Λ onto the stable equilibrium
/// state with that depth (b̂0 = 2 b̂_c without contact, (5.41)); pull-off at the
/// minimum of d̂ along the branch.
pub fn impact_path(lambda: f64) -> Result<ImpactPath> {
    let lambda = check_lambda(lambda)?;
    let case = TaborCase::of(lambda);
    let bc = no_contact_pull_off_radius(lambda);
    let mut cost = Cost::ZERO;
    let (jump_in, pull_off) = match case {
        TaborCase::NoContact => (
            PathState::from_no_contact(lambda, 2.0 * bc),
            PathState::from_no_contact(lambda, bc),
        ),
        TaborCase::ContactThenNoContact => {
            let theta_in = jump_in_theta(lambda, FRAC_PI_2, &mut cost)?;
            (
                PathState::from_contact(lambda, theta_in),
                PathState::from_no_contact(lambda, bc),
            )
        }
        TaborCase::Contact => {
            let theta_c = pull_off_theta(lambda, &mut cost)?;
            let theta_in = jump_in_theta(lambda, theta_c, &mut cost)?;
            (
                PathState::from_contact(lambda, theta_in),
                PathState::from_contact(lambda, theta_c),
            )
        }
    };
    Ok(ImpactPath {
        lambda,
        case,
        jump_in,
        pull_off,
        cost,
    })
}

/// Starting guesses of case 3 in `t = Λ2/Λ ∈ (0, 1)`: least-squares quartics
/// `Σ c_k t^k` fitted to `θ_in·Λ` and `θ_c·Λ` at 41 points of `t` (both tend to
/// constants in the JKR limit t → 0, θ ∝ 1/Λ). Worst relative errors 4.9e-4 and
/// 2.6e-3; they only place the bracket of the root finders below, whose sign
/// checks decide (a miss falls back to the search from π/2).
const JUMP_IN_GUESS: [f64; 5] = [0.713_557, 0.090_522, -0.642_692, 0.621_841, -0.188_420];
const PULL_OFF_GUESS: [f64; 5] = [1.133_491, -0.018_933, -0.318_872, 0.041_688, 0.170_891];

/// `θ·Λ` from the guess coefficients `c` at `t = Λ2/Λ`, over Λ.
fn case_3_guess(c: &[f64; 5], lambda: f64) -> f64 {
    let t = LAMBDA_2 / lambda;
    (c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4])))) / lambda
}

/// θ_c of the contact-branch pull-off (dd̂/dθ = 0) in case 3. Where rounding leaves
/// no sign change next to Λ2, the pull-off is the junction θ = π/2.
fn pull_off_theta(lambda: f64, cost: &mut Cost) -> Result<f64> {
    let slope = |t: f64| contact_state(lambda, t).depth_slope;
    let top = FRAC_PI_2;
    // first Newton's method within ±0.4 % of the guess (the slope is < 0 below
    // θ_c, > 0 above)
    let guess = case_3_guess(&PULL_OFF_GUESS, lambda);
    let newton = newton_safeguarded(
        |t| depth_slope_and_curvature(lambda, t),
        guess * 0.996,
        (guess * 1.004).min(top),
        guess,
        ROOT_TOL,
    );
    match newton {
        Ok(root) => {
            *cost += root.cost();
            return Ok(root.value);
        }
        Err(NumericsError::NoBracket { .. }) => *cost += Cost::new(2, 0),
        Err(e) => return Err(e.into()),
    }
    if slope(top) <= 0.0 {
        return Ok(top);
    }
    let mut lo = top;
    let mut evaluations = 1u64;
    loop {
        lo *= 0.5;
        evaluations += 1;
        if slope(lo) < 0.0 {
            break;
        }
        if lo < 1e-300 {
            return Err(Error::Model {
                model: "Maugis-Dugdale",
                message: format!(
                    "no pull-off state found on the contact branch for Lambda = {lambda:e}"
                ),
            });
        }
    }
    let hi = (2.0 * lo).min(top);
    let root = brent(slope, lo, hi, ROOT_TOL)?;
    *cost += root.cost() + Cost::new(evaluations, 0);
    Ok(root.value)
}

/// θ_in of the jump-in state on the contact branch: d̂(θ) = −1/Λ with θ < θ_max
/// (the stable, large-contact side).
fn jump_in_theta(lambda: f64, theta_max: f64, cost: &mut Cost) -> Result<f64> {
    let target = -1.0 / lambda;
    if TaborCase::of(lambda) == TaborCase::Contact {
        // first within ±0.1 % of the guess (d̂ − target is > 0 below θ_in)
        let guess = case_3_guess(&JUMP_IN_GUESS, lambda);
        let g = |t: f64| {
            let s = contact_state(lambda, t);
            (s.depth - target, s.depth_slope)
        };
        let hi = (guess * 1.001).min(theta_max);
        match newton_safeguarded(g, guess * 0.999, hi, guess, ROOT_TOL) {
            Ok(root) => {
                *cost += root.cost();
                return Ok(root.value);
            }
            Err(NumericsError::NoBracket { .. }) => *cost += Cost::new(2, 0),
            Err(e) => return Err(e.into()),
        }
    }
    theta_at_depth(lambda, target, theta_max, cost)
}

/// θ < θ_max on the contact branch where d̂(θ) = `target` (d̂ decreases in θ there).
pub(crate) fn theta_at_depth(
    lambda: f64,
    target: f64,
    theta_max: f64,
    cost: &mut Cost,
) -> Result<f64> {
    let g = |t: f64| {
        let s = contact_state(lambda, t);
        (s.depth - target, s.depth_slope)
    };
    let mut hi = theta_max;
    let mut lo = theta_max;
    let mut evaluations = 0u64;
    loop {
        lo *= 0.5;
        evaluations += 1;
        if g(lo).0 > 0.0 {
            break;
        }
        hi = lo;
        if lo < 1e-300 {
            return Err(Error::Model {
                model: "Maugis-Dugdale",
                message: format!(
                    "no state with depth {target:e} found on the contact branch for Lambda = {lambda:e}"
                ),
            });
        }
    }
    let root = newton_safeguarded(g, lo, hi, 0.5 * (lo + hi), ROOT_TOL)?;
    *cost += root.cost() + Cost::new(evaluations, 0);
    Ok(root.value)
}

/// The adhesive energy loss of a Maugis-Dugdale impact in units of `F_n d_n`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MaugisNormalizedLoss {
    /// The Tabor parameter Λ.
    pub lambda: f64,
    /// The case (1, 2 or 3).
    pub case: TaborCase,
    /// `|ΔU_kin| / (F_n d_n)` (> 0).
    pub loss: f64,
    /// `|ΔU_kin| / |ΔU_kin^JKR|`, the ordinate of seed 000 Fig. 5.2.
    pub loss_over_jkr: f64,
    /// Estimated absolute error of `loss`; 0 for the closed form of case 1.
    pub error_estimate: f64,
    /// Which formula produced it.
    pub method: &'static str,
    /// Work spent.
    pub cost: Cost,
}

/// The adhesive energy loss `|ΔU_kin| / (F_n d_n)` of a Maugis-Dugdale impact at Tabor
/// parameter Λ, to the relative tolerance `tolerance` (direct evaluation).
///
/// Seed 000 eqs. (5.43)-(5.46): case 1 closed form `17·2¹⁹Λ⁵/(3⁴π⁸)` (5.44); case 2
/// quadrature of `∫F̂ dd̂` on the contact branch (in θ, where the integrand is smooth
/// through the pull-off point) plus the closed form (5.46), written as
/// `2¹⁹Λ⁵(K − 1)²(3K² + 2K + 1)/(3⁴π⁸)` so that it stays accurate as K → 1; case 3
/// quadrature (5.43), and for Λ ≥ [`LAMBDA_JKR_LIMIT`] the JKR loss (5.36), which
/// equals it to double precision there.
pub fn normalized_loss(lambda: f64, tolerance: f64) -> Result<MaugisNormalizedLoss> {
    let lambda = check_lambda(lambda)?;
    let tol = validate::tolerance("tolerance", tolerance)?;
    let case = TaborCase::of(lambda);
    let bc = no_contact_pull_off_radius(lambda);
    let bc4 = bc * bc * bc * bc;
    let (loss, error, method, cost) = match case {
        TaborCase::NoContact => (
            8.5 * lambda * bc4,
            0.0,
            "Maugis-Dugdale case 1, closed form (5.44)",
            Cost::ZERO,
        ),
        TaborCase::Contact if lambda >= LAMBDA_JKR_LIMIT => {
            let w_jkr = jkr_normalized_loss();
            (
                w_jkr,
                0.46 / lambda * w_jkr,
                "Maugis-Dugdale case 3, JKR limit (Lambda >= 1e16: 1 - W/W_JKR = 0.4568/Lambda rounds away)",
                Cost::ZERO,
            )
        }
        TaborCase::ContactThenNoContact | TaborCase::Contact => {
            let path = impact_path(lambda)?;
            let theta_in = path.jump_in.theta.unwrap_or(FRAC_PI_2);
            let theta_end = path.pull_off.theta.unwrap_or(FRAC_PI_2);
            let closed = if case == TaborCase::ContactThenNoContact {
                let k = junction_factor(lambda);
                let km1 = junction_factor_minus_one(lambda);
                0.5 * lambda * bc4 * km1 * km1 * (3.0 * k * k + 2.0 * k + 1.0)
            } else {
                0.0
            };
            // Relative tolerance on the total: the closed part is exact.
            let integrand = |t: f64| {
                let s = contact_state(lambda, t);
                s.force * s.depth_slope
            };
            let target = QuadTolerance {
                absolute: 0.25 * tol * closed,
                relative: 0.25 * tol,
            };
            // The integrand is analytic on [θ_in, θ_end]: Gauss-Legendre rules of
            // 12 and 16 points agree to about 5e-15 relative at every Λ, so the
            // pair usually meets the target with its conservative estimate
            // |G16 − G12|; otherwise adaptive Clenshaw-Curtis decides.
            let first = quadrature_pair()?.integrate(integrand, theta_in, theta_end)?;
            let integral = if first.error_estimate
                <= target.absolute.max(target.relative * first.value.abs())
            {
                first
            } else {
                let adaptive = integrate_smooth(integrand, theta_in, theta_end, target)?;
                Integral {
                    evaluations: adaptive.evaluations + first.evaluations,
                    ..adaptive
                }
            };
            let method = if case == TaborCase::Contact {
                "Maugis-Dugdale case 3, quadrature on the contact branch (5.43)"
            } else {
                "Maugis-Dugdale case 2, quadrature on the contact branch + closed form (5.46)"
            };
            (
                integral.value + closed,
                integral.error_estimate,
                method,
                path.cost + integral.cost(),
            )
        }
    };
    Ok(MaugisNormalizedLoss {
        lambda,
        case,
        loss,
        loss_over_jkr: loss / jkr_normalized_loss(),
        error_estimate: error,
        method,
        cost,
    })
}

/// The Gauss-Legendre rules of 12 and 16 points of the loss quadrature, built once.
fn quadrature_pair() -> Result<&'static GaussLegendrePair> {
    static PAIR: OnceLock<std::result::Result<GaussLegendrePair, tabor_numerics::NumericsError>> =
        OnceLock::new();
    PAIR.get_or_init(|| GaussLegendrePair::new(12, 16))
        .as_ref()
        .map_err(|e| Error::from(e.clone()))
}

/// `K − 1` without cancellation: `(x − (π − 1)) / (√((1 − π/2)² + x) + π/2)` with
/// `x = 3π⁴/(512Λ³)`, and `x − (π − 1) = (π − 1)((Λ2/Λ)³ − 1)`.
fn junction_factor_minus_one(lambda: f64) -> f64 {
    let c = 1.0 - FRAC_PI_2;
    let x = 3.0 * PI.powi(4) / (512.0 * lambda * lambda * lambda);
    let r = LAMBDA_2 / lambda;
    (PI - 1.0) * (r * r * r - 1.0) / ((c * c + x).sqrt() + FRAC_PI_2)
}

//! The JKR sphere in the normalized units of the force-controlled critical state
//! (the JKR state with `dF/da = 0`, seed 000 eq. (5.43); `tabor-maugis` uses the same
//! units), for effective modulus `E` = E*, effective radius `R` and work of adhesion
//! `Δγ`, force positive in compression:
//!
//! ```text
//! a_c = (9 π Δγ R² / (8 E))^(1/3),  F_n = (3/2) π Δγ R,  d_n = a_c² / (3 R),
//! â = a/a_c,  F̂ = F/F_n,  d̂ = d/d_n,  energies in units of F_n d_n.
//! ```
//!
//! These are seed 000 eqs. (5.33)-(5.36) without a single dimensional parameter:
//! `F̂ = â³ − 2 â^(3/2)`, `d̂ = 3 â² − 4 â^(1/2)`. The energy unit is
//! `F_n d_n = (3∛3/8) [R⁴ (πΔγ)⁵ / E²]^(1/3)`. Landmarks: first touch `d̂ = 0`,
//! `â0 = (4/3)^(2/3)`, `F̂ = −8/9`; the displacement-controlled pull-off (fixed grip)
//! `dd̂/dâ = 0` at `â = (1/3)^(2/3)`, `d̂ = −3^(2/3)`, `F̂ = −5/9`; the load-controlled
//! pull-off `â = 1`, `d̂ = −1`, `F̂ = −1`; the fixed-grip loss (5.36)
//! `(1/10)(1 + ∛864) [R⁴(πΔγ)⁵/E²]^(1/3)`, about 1.9459 `F_n d_n`.
//! [`crate::JkrSphere`] is the thin physical shell around them.

use crate::common::{
    finite_output, loss_by_quadrature, solve_energy_balance, Balance, JkrContactState,
    JkrNormalizedLoss, MaxContactRadius, SeparationRule,
};
use tabor_numerics::root_finding::newton_safeguarded;
use tabor_numerics::{Cost, RootTolerance};
use tabor_restitution::{validate, Result};

const MODEL: &str = "JKR sphere";

/// Force `F̂(â) = â³ − 2 â^(3/2)` (compression positive) at contact radius `â ≥ 0`.
///
/// Seed 000, eq. (5.33) (the right-hand side, `−m d̈ = F`) divided by `F_n`.
pub fn force(contact_radius: f64) -> Result<f64> {
    let a = validate::non_negative("contact_radius", contact_radius)?;
    finite_output(MODEL, "force", force_hat(a))
}

/// Depth `d̂(â) = 3 â² − 4 â^(1/2)` (negative when adhesion stretches the contact).
///
/// Seed 000, eq. (5.34) divided by `d_n`.
pub fn depth(contact_radius: f64) -> Result<f64> {
    let a = validate::non_negative("contact_radius", contact_radius)?;
    finite_output(MODEL, "depth", depth_hat(a))
}

/// First touch, `d̂ = 0`: the contact jumps to `â0 = (4/3)^(2/3)` with force
/// `F̂ = −8/9` (i.e. −(4/3)πΔγR).
///
/// Seed 000, the lower limit `a_0` of (5.35)-(5.36) (the seed's (3.57)).
pub fn first_touch() -> JkrContactState {
    let a = FIRST_TOUCH_RADIUS;
    JkrContactState {
        contact_radius: a,
        depth: 0.0,
        force: force_hat(a),
    }
}

/// Where contact breaks under `rule`: fixed grip `â = (1/3)^(2/3)`, `d̂ = −3^(2/3)`,
/// `F̂ = −5/9`; load-controlled `â = 1`, `d̂ = −1`, `F̂ = −1`.
///
/// Seed 000, upper limit `a_c^WS` of (5.36) (the seed's (3.60)) for fixed grip; the
/// force-controlled critical state (the normalization point) for load control.
pub fn critical_state(rule: SeparationRule) -> JkrContactState {
    let a = separation_radius(rule);
    JkrContactState {
        contact_radius: a,
        depth: depth_hat(a),
        force: force_hat(a),
    }
}

/// The contact radius `â ≥ (1/3)^(2/3)` on the stable branch at depth `d̂` (finite),
/// clamped to the fixed-grip instability `â = (1/3)^(2/3)` for `d̂ ≤ −3^(2/3)`.
///
/// Seed 000, eq. (5.34) divided by `d_n`, inverted: with `x = √â`, the root
/// `x ≥ 3^(−1/3)` of the quartic `3x⁴ − 4x = d̂` (see [`sqrt_contact_radius_at_depth`]).
pub fn contact_radius_at_depth(depth: f64) -> Result<f64> {
    let x = sqrt_contact_radius_at_depth(depth)?;
    Ok(x * x)
}

/// `x = √â ≥ 3^(−1/3)` on the stable branch at depth `d̂` (finite): the root of the
/// quartic `3x⁴ − 4x = d̂`, by Newton's method safeguarded by bisection in
/// `[3^(−1/3), 3/2 + (d̂⁺/3)^(1/4)]` to a relative 4ε; clamped to `3^(−1/3)` (the
/// fixed-grip instability) for `d̂ ≤ −3^(2/3)`.
///
/// Seed 000, eq. (5.34) divided by `d_n`, inverted. The one quartic inversion of the
/// workspace: [`crate::JkrForceLaw`] and `tabor-plastic`'s JKR unloading use it.
pub fn sqrt_contact_radius_at_depth(depth: f64) -> Result<f64> {
    let d = validate::finite("depth", depth)?;
    if d <= depth_hat(separation_radius(SeparationRule::FixedGrip)) {
        return Ok(SQRT_FIXED_GRIP_RADIUS);
    }
    let upper = 1.5 + (d.max(0.0) / 3.0).powf(0.25);
    let start = (1.0 + d.max(0.0) / 3.0)
        .powf(0.25)
        .clamp(SQRT_FIXED_GRIP_RADIUS, upper);
    let root = newton_safeguarded(
        |x| {
            let x3 = x * x * x;
            (3.0 * x3 * x - 4.0 * x - d, 12.0 * x3 - 4.0)
        },
        SQRT_FIXED_GRIP_RADIUS,
        upper,
        start,
        RootTolerance::relative(4.0 * f64::EPSILON),
    )?;
    Ok(root.value)
}

/// The kinetic energy it takes to reach the maximum contact radius `â_max`, the right
/// side of the energy balance, in units of `F_n d_n`:
/// `(6/5) â⁵ − 4 â^(7/2) + 2 â² + (6/5)(4/3)^(4/3)`.
///
/// Seed 000, eq. (5.35) divided by `F_n d_n`. Meaningful for `â_max` beyond the
/// zero-force radius `4^(1/3)`, where it grows monotonically.
pub fn kinetic_energy_to_reach(max_contact_radius: f64) -> Result<f64> {
    let a = validate::non_negative("max_contact_radius", max_contact_radius)?;
    finite_output(MODEL, "kinetic energy", balance_work(a))
}

/// The maximum contact radius `â_max` reached with kinetic energy `kinetic_energy`
/// (units of `F_n d_n`, > 0), by Brent's method on the energy balance, so that the
/// residual is below `tolerance · (kinetic_energy + ΔÛ_0)` (`tolerance` relative,
/// in [1e-15, 0.5]; below about 1e-13 the residual stops at the rounding error of
/// the work, see [`MaxContactRadius::energy_residual`]).
///
/// Seed 000, eq. (5.35).
pub fn max_contact_radius(kinetic_energy: f64, tolerance: f64) -> Result<MaxContactRadius> {
    let kinetic = validate::positive("kinetic_energy", kinetic_energy)?;
    let tol = validate::tolerance("tolerance", tolerance)?;
    let upper_guess = 1.5 * (kinetic / 1.2).powf(0.2);
    solve_energy_balance(
        Balance {
            work: |a| {
                finite_output(MODEL, "kinetic energy", balance_work(a)).map(|w| (w, Cost::ZERO))
            },
            slope: |a| force_hat(a) * depth_slope_hat(a),
            zero_force_radius: ZERO_FORCE_RADIUS,
            upper_guess,
            offset: LOADING_OFFSET,
        },
        kinetic,
        tol,
    )
}

/// The adhesive energy loss |ΔU_kin| of an impact in units of `F_n d_n`.
///
/// Fixed grip: the closed form of seed 000, eq. (5.36),
/// `(1/10)(1 + ∛864)·8/(3∛3) ≈ 1.9459` (no cost). Load-controlled: no closed form in
/// the seed; the integral `∫ F̂ (dd̂/dâ) dâ` of (5.36) from `â0` to `â = 1`, by
/// adaptive Clenshaw-Curtis to the relative `tolerance` (in [1e-15, 0.5]), with its
/// error estimate and cost (≈ 0.9610).
pub fn energy_loss(rule: SeparationRule, tolerance: f64) -> Result<JkrNormalizedLoss> {
    let tol = validate::tolerance("tolerance", tolerance)?;
    match rule {
        SeparationRule::FixedGrip => Ok(JkrNormalizedLoss {
            value: fixed_grip_loss(),
            error_estimate: 0.0,
            branch: "JKR sphere, fixed grip: closed form (5.36)",
            cost: Cost::ZERO,
        }),
        SeparationRule::LoadControlled => loss_by_quadrature(
            |a| force_hat(a) * depth_slope_hat(a),
            FIRST_TOUCH_RADIUS,
            separation_radius(rule),
            tol,
            "JKR sphere, load-controlled: quadrature of the integral in (5.36) to F' = 0",
        ),
    }
}

/// `(1/10)(1 + ∛864)[R⁴(πΔγ)⁵/E²]^(1/3)` in units of
/// `F_n d_n = (3∛3/8)[R⁴(πΔγ)⁵/E²]^(1/3)`. Seed 000, eq. (5.36).
pub(crate) fn fixed_grip_loss() -> f64 {
    0.1 * (1.0 + 864f64.cbrt()) * 8.0 / (3.0 * 3f64.cbrt())
}

/// `√â` at the fixed-grip instability, `3^(−1/3)`.
const SQRT_FIXED_GRIP_RADIUS: f64 = 0.693_361_274_350_634_8;
/// `â0 = (4/3)^(2/3)`.
const FIRST_TOUCH_RADIUS: f64 = 1.211_413_728_554_759_7;
/// `â` of zero force, `4^(1/3)`.
const ZERO_FORCE_RADIUS: f64 = 1.587_401_051_968_199_4;
/// The constant of (5.35), `(6/5)(4/3)^(4/3)`.
const LOADING_OFFSET: f64 = 1.761_027_866_077_134_1;

pub(crate) fn separation_radius(rule: SeparationRule) -> f64 {
    match rule {
        // (1/3)^(2/3)
        SeparationRule::FixedGrip => 0.480_749_856_769_136_1,
        SeparationRule::LoadControlled => 1.0,
    }
}

pub(crate) fn force_hat(a: f64) -> f64 {
    a * a * a - 2.0 * a * a.sqrt()
}

pub(crate) fn depth_hat(a: f64) -> f64 {
    3.0 * a * a - 4.0 * a.sqrt()
}

fn depth_slope_hat(a: f64) -> f64 {
    6.0 * a - 2.0 / a.sqrt()
}

/// The right side of (5.35) over `F_n d_n`.
fn balance_work(a: f64) -> f64 {
    let a2 = a * a;
    1.2 * a2 * a2 * a - 4.0 * a2 * a * a.sqrt() + 2.0 * a2 + LOADING_OFFSET
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_are_what_their_comments_say() {
        let eps = 4.0 * f64::EPSILON;
        assert!((FIRST_TOUCH_RADIUS - (4.0f64 / 3.0).powf(2.0 / 3.0)).abs() < eps);
        assert!((ZERO_FORCE_RADIUS - 4f64.cbrt()).abs() < eps);
        assert!((LOADING_OFFSET - 1.2 * (4.0f64 / 3.0).powf(4.0 / 3.0)).abs() < eps);
        let fg = separation_radius(SeparationRule::FixedGrip);
        assert!((fg - (1.0f64 / 3.0).powf(2.0 / 3.0)).abs() < eps);
        assert!((SQRT_FIXED_GRIP_RADIUS - 3f64.powf(-1.0 / 3.0)).abs() < eps);
        assert!(depth_hat(FIRST_TOUCH_RADIUS).abs() < 16.0 * eps);
        assert!(force_hat(ZERO_FORCE_RADIUS).abs() < 8.0 * eps);
    }
}

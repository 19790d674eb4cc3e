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
    finite_output, loss_by_quadrature, JkrContactState, JkrNormalizedLoss, MaxContactRadius,
    SeparationRule,
};
use tabor_numerics::Cost;
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
/// quartic `3x⁴ − 4x = d̂`, clamped to `3^(−1/3)` (the fixed-grip instability) for
/// `d̂ ≤ −3^(2/3)`. Ferrari's closed form ([`sqrt_contact_radius_closed_form`]),
/// polished by Newton's method inside the bracket `[3^(−1/3), 3/2 + (d̂⁺/1.8)^(1/4)]`
/// to a step below 2ε x ([`sqrt_contact_radius_at_depth_from`]).
///
/// Seed 000, eq. (5.34) divided by `d_n`, inverted. The one quartic inversion of the
/// workspace: [`crate::JkrForceLaw`] and `tabor-plastic`'s JKR unloading use it,
/// and the laws that solve it at nearby depths over and over (`tabor-viscoadhesive`,
/// `tabor-lammps`) its warm-started variant [`sqrt_contact_radius_at_depth_from`].
pub fn sqrt_contact_radius_at_depth(depth: f64) -> Result<f64> {
    let d = validate::finite("depth", depth)?;
    if d <= FIXED_GRIP_DEPTH {
        return Ok(SQRT_FIXED_GRIP_RADIUS);
    }
    quartic_root_from(d, sqrt_contact_radius_closed_form(d))
}

/// The warm-started [`sqrt_contact_radius_at_depth`]: the same root, by Newton's
/// method from `guess` (typically the root at a nearby depth; a guess that is not
/// finite or not above `3^(−1/3)` starts from `(1 + d̂⁺/3)^(1/4)`), safeguarded by
/// bisection in `[3^(−1/3), 3/2 + (d̂⁺/1.8)^(1/4)]`, to a step below 2ε x, or to a
/// step after which the error left, `f''/(2f') δ²`, is below ε x/4. From the root
/// at a depth 1 % away it takes two or three steps.
///
/// Seed 000, eq. (5.34) divided by `d_n`, inverted.
pub fn sqrt_contact_radius_at_depth_from(depth: f64, guess: f64) -> Result<f64> {
    let d = validate::finite("depth", depth)?;
    if d <= FIXED_GRIP_DEPTH {
        return Ok(SQRT_FIXED_GRIP_RADIUS);
    }
    quartic_root_from(d, guess)
}

/// Ferrari's solution of the depressed quartic `3x⁴ − 4x − d̂ = 0` for its largest
/// real root, for `d̂ ≥ −3^(2/3)`: with `z` the positive root of the resolvent cubic
/// `z³ + (4d̂/3) z − 16/9 = 0` (Cardano, in the cancellation-free form
/// `z = (16/9)/(u² + 4d̂/9 + v²)` for `d̂ ≥ 0`, `u + v` below, `u = ∛(8/9 + √Δ)`,
/// `v = −(4d̂/9)/u`, `Δ = 64/81 + (4d̂/9)³ ≥ 0`) and `r = √z`,
/// `x = (r + √(8/(3r) − r²))/2`. Accurate to a few ulps except within about √ε of
/// the fixed-grip instability, where the root itself is ill-conditioned
/// (`dx/dd̂ → ∞`); [`sqrt_contact_radius_at_depth`] polishes it with Newton's method.
///
/// A second derivation of the inversion of seed 000 eq. (5.34): the tests compare it
/// with the Newton iteration.
pub fn sqrt_contact_radius_closed_form(depth: f64) -> f64 {
    let d = depth.max(FIXED_GRIP_DEPTH);
    let p = 4.0 * d / 9.0;
    let disc = (64.0 / 81.0 + p * p * p).max(0.0);
    let u = (8.0 / 9.0 + disc.sqrt()).cbrt();
    let v = -p / u;
    let z = if d >= 0.0 {
        (16.0 / 9.0) / (u * u + p + v * v)
    } else {
        u + v
    };
    let r = z.sqrt();
    0.5 * (r + (8.0 / (3.0 * r) - r * r).max(0.0).sqrt())
}

/// Newton's method for `3x⁴ − 4x = d` (`d > −3^(2/3)`, finite) from `guess`, kept in
/// a shrinking bracket (bisection when a step leaves it): the function is increasing
/// and convex on the bracket, so from the right the iteration falls monotonically.
fn quartic_root_from(d: f64, guess: f64) -> Result<f64> {
    let mut lo = SQRT_FIXED_GRIP_RADIUS;
    // the upper end of the bracket, `3/2 + (d⁺/1.8)^(1/4)`, is needed only when a
    // step leaves the bracket (rarely): until then it is +∞
    let mut hi = f64::INFINITY;
    let upper = || 1.5 + (d.max(0.0) / 1.8).sqrt().sqrt();
    // from above the root Newton's method falls monotonically (f is convex), so any
    // finite guess above the lower end will do
    let mut x = if guess > lo && guess.is_finite() {
        guess
    } else {
        (1.0 + d.max(0.0) / 3.0).sqrt().sqrt().clamp(lo, upper())
    };
    for _ in 0..QUARTIC_MAX_STEPS {
        let x2 = x * x;
        let x3 = x2 * x;
        let f = 3.0 * x3 * x - 4.0 * x - d;
        if f == 0.0 {
            return Ok(x);
        }
        if f > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        let slope = 12.0 * x3 - 4.0;
        let newton = f / slope;
        // the error left after this step, f''/(2f') δ² (f'' = 36x²): below ε/4 x
        // the step lands on the root
        let left_times_slope = 18.0 * x2 * newton * newton;
        if newton.abs() <= 2.0 * f64::EPSILON * x
            || left_times_slope <= 0.25 * f64::EPSILON * x * slope.abs()
        {
            let next = x - newton;
            if next >= lo && next <= hi {
                return Ok(next);
            }
        }
        x -= newton;
        if !(x > lo && x < hi) {
            if hi.is_infinite() {
                hi = upper();
            }
            x = 0.5 * (lo + hi);
        }
        if hi - lo <= 2.0 * f64::EPSILON * x {
            return Ok(x);
        }
    }
    Err(tabor_restitution::Error::Model {
        model: MODEL,
        message: format!("contact radius: no convergence at normalized depth {d:e}"),
    })
}

/// Bisection halves the bracket to 2ε x in about 60 steps; Newton needs a handful.
const QUARTIC_MAX_STEPS: usize = 200;

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
/// (units of `F_n d_n`, > 0), by Halley's method on the energy balance, so that
/// the residual is below `tolerance · (kinetic_energy + ΔÛ_0)` (`tolerance`
/// relative, in [1e-15, 0.5]; below about 1e-13 the residual stops at the rounding
/// error of the work, see [`MaxContactRadius::energy_residual`]).
///
/// Beyond the zero-force radius `4^(1/3)` the work grows and is convex, and in
/// `s = √â` it is the polynomial `(6/5)s¹⁰ − 4s⁷ + 2s⁴ + ΔÛ_0`, so the iteration
/// runs on `s` with no square root per step and no bracket. From the start (the
/// tangent at the radius where `W = 0` for small energies, `W ≈ (6/5)â⁵ − 4â^(7/2)`
/// for large ones) Halley's cubic convergence leaves 3 or 4 evaluations (Newton's
/// method needed 4 to 8); a step that stops shrinking marks the rounding floor.
/// Written out rather than `tabor_numerics`' safeguarded Newton, which evaluates a
/// bracket first: a batch over speeds pays this per element.
///
/// Seed 000, eq. (5.35).
pub fn max_contact_radius(kinetic_energy: f64, tolerance: f64) -> Result<MaxContactRadius> {
    max_contact_radius_near(kinetic_energy, tolerance, None)
}

/// [`max_contact_radius`] started from `near`, the maximum contact radius of a
/// nearby kinetic energy (a batch over sorted speeds: neighbours differ by parts
/// per million). From there one Halley step lands when the error it leaves (its
/// cubic term, bounded from the derivatives at the start) is below rounding, a
/// second one follows otherwise (3 to 5 from a cold start). A `near` that is not
/// beyond the radius where the work vanishes is ignored. The answer agrees with the
/// cold start's to rounding.
///
/// Seed 000, eq. (5.35).
#[inline]
pub fn max_contact_radius_near(
    kinetic_energy: f64,
    tolerance: f64,
    near: Option<f64>,
) -> Result<MaxContactRadius> {
    let kinetic = validate::positive("kinetic_energy", kinetic_energy)?;
    let tol = validate::tolerance("tolerance", tolerance)?;
    // a step below 0.05·tolerance·â keeps the residual below the tolerance:
    // â W'(â)/(K + ΔÛ_0) stays below 20 beyond the zero-force radius; the
    // iteration runs on s = √â (W a polynomial in s: no square root per step),
    // where the same relative step is half as large (dâ/â = 2 ds/s)
    let width = 0.025 * tol;
    let mut s = match near {
        Some(a) if a.is_finite() && a > ZERO_WORK_RADIUS => a.sqrt(),
        _ => newton_start(kinetic).sqrt(),
    };
    let mut previous = f64::INFINITY;
    for iteration in 1..=NEWTON_MAX_STEPS {
        let (work, slope, curvature) = balance_work_in_sqrt(s);
        let excess = work - kinetic;
        if excess == 0.0 {
            return max_radius(s, kinetic, iteration, iteration);
        }
        // Halley's step (cubic convergence), Newton's where its denominator
        // overflows (energies beyond ~1e250)
        let halley = 2.0 * slope * slope - excess * curvature;
        let halley_used = halley.is_finite() && halley > 0.0;
        let step = if halley_used {
            2.0 * excess * slope / halley
        } else {
            excess / slope
        };
        if !step.is_finite() {
            break;
        }
        // a step that does not shrink is rounding: the root is reached
        if step.abs() >= previous {
            return max_radius(s, kinetic, iteration, iteration);
        }
        // the error Halley's step leaves, |f''²/(4f'²) − f'''/(6f')| |step|³ to
        // leading order (its asymptotic constant; f''' = 12s(72c² − 70c + 4),
        // c = s³), taken twice, below ε/4 of s: the step lands on the root to
        // rounding without another evaluation (from a neighbour's radius in a
        // dense batch over sorted speeds). Only for steps below 1e-3 s, where
        // the leading order is all there is.
        let lands = halley_used && step.abs() <= 1e-3 * s && {
            let c = s * s * s;
            let third = 12.0 * s * ((72.0 * c - 70.0) * c + 4.0);
            // |f''²/4 − f''' f'/6| against f'², without a division
            let constant_times_slope2 =
                (0.25 * curvature * curvature - third * slope * (1.0 / 6.0)).abs();
            2.0 * constant_times_slope2 * step.abs().powi(3)
                <= 0.25 * f64::EPSILON * s * slope * slope
        };
        // every root lies beyond the zero-work radius, where W is convex: a
        // step from a start above the root stays there
        s = (s - step).max(SQRT_ZERO_WORK_RADIUS);
        if lands || step.abs() <= width * s {
            return max_radius(s, kinetic, iteration + 1, iteration);
        }
        previous = step.abs();
    }
    Err(tabor_restitution::Error::Model {
        model: MODEL,
        message: format!(
            "maximum contact radius: Halley's method did not converge at kinetic energy {kinetic:e}"
        ),
    })
}

/// The right side of (5.35) over `F_n d_n` and its first two derivatives, in
/// `s = √â`: `W = (6/5)s¹⁰ − 4s⁷ + 2s⁴ + ΔÛ_0 = s c ((6/5)c² − 4c + 2) + ΔÛ_0`,
/// `dW/ds = 12s⁹ − 28s⁶ + 8s³ = 4c(3c² − 7c + 2)` and
/// `d²W/ds² = 12s²(9c² − 14c + 2)` with `c = s³`. Increasing and convex for
/// `c > 2` (beyond the zero-force radius `â = 4^(1/3)`, where
/// `3c² − 7c + 2 = (3c − 1)(c − 2) > 0` and `9c² − 14c + 2 > 0`).
fn balance_work_in_sqrt(s: f64) -> (f64, f64, f64) {
    let c = s * s * s;
    let work = s * c * ((1.2 * c - 4.0) * c + 2.0) + LOADING_OFFSET;
    let slope = 4.0 * c * ((3.0 * c - 7.0) * c + 2.0);
    let curvature = 12.0 * s * s * ((9.0 * c - 14.0) * c + 2.0);
    (work, slope, curvature)
}

/// Steps of [`max_contact_radius`]: at most 4 needed over kinetic energies from
/// 1e-10 to 1e14.
const NEWTON_MAX_STEPS: u64 = 100;

/// `â` where the work of (5.35) vanishes (beyond the zero-force radius):
/// `W(1.83654…) = 0`.
const ZERO_WORK_RADIUS: f64 = 1.836_544_531_210_768_7;
const _: () = assert!(ZERO_WORK_RADIUS > ZERO_FORCE_RADIUS);
/// `√` of [`ZERO_WORK_RADIUS`].
const SQRT_ZERO_WORK_RADIUS: f64 = 1.355_191_695_374_041_5;

/// A start for the iteration on `W(â) = K`, beyond the zero-force radius: the
/// tangent at [`ZERO_WORK_RADIUS`] (above the root, `W` being convex), or, when
/// smaller, the root of the two leading terms, `g (1 + (2/3) g^(−3/2))` with
/// `g = (K/1.2)^(1/5)`.
fn newton_start(kinetic: f64) -> f64 {
    let tangent = ZERO_WORK_RADIUS
        + kinetic / (force_hat(ZERO_WORK_RADIUS) * depth_slope_hat(ZERO_WORK_RADIUS));
    let g = fifth_root(kinetic / 1.2);
    let leading = if g > 1.0 {
        g * (1.0 + 2.0 / 3.0 / (g * g.sqrt()))
    } else {
        f64::INFINITY
    };
    tangent.min(leading).max(ZERO_WORK_RADIUS)
}

/// `x^(1/5)` for a start (relative error below 1e-6 for normal `x > 0`; a
/// batch pays it per element, where `powf` was a tenth of the cost): the exponent
/// divided by five in the bits (within 15 %), then three Newton steps on
/// `g⁵ = x`.
fn fifth_root(x: f64) -> f64 {
    const ONE_BITS_FOUR_FIFTHS: u64 = (1023u64 << 52) / 5 * 4;
    let mut g = f64::from_bits(x.to_bits() / 5 + ONE_BITS_FOUR_FIFTHS);
    for _ in 0..3 {
        let g2 = g * g;
        g = 0.2 * (4.0 * g + x / (g2 * g2));
    }
    g
}

/// The result at `s = √â_max`, the residual from the work in `s` (no square root).
fn max_radius(s: f64, kinetic: f64, evaluations: u64, iterations: u64) -> Result<MaxContactRadius> {
    let w = finite_output(MODEL, "kinetic energy", balance_work_in_sqrt(s).0)?;
    let a = finite_output(MODEL, "maximum contact radius", s * s)?;
    Ok(MaxContactRadius {
        contact_radius: a,
        energy_residual: (w - kinetic).abs() / (kinetic + LOADING_OFFSET),
        cost: Cost::new(evaluations + 1, iterations),
    })
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
/// `d̂` at the fixed-grip instability, `−3^(2/3)` (`3x⁴ − 4x` at `x = 3^(−1/3)`).
const FIXED_GRIP_DEPTH: f64 = -2.080_083_823_051_904;
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

    /// Newton's root against bisection of the balance (5.35) written out, over 24
    /// decades of kinetic energy, with its cost bounded.
    #[test]
    fn max_contact_radius_by_newton_matches_bisection() {
        let work = |a: f64| 1.2 * a.powi(5) - 4.0 * a.powf(3.5) + 2.0 * a * a + LOADING_OFFSET;
        for k in 0..=96 {
            let kinetic = 10f64.powf(-10.0 + 0.25 * f64::from(k));
            let (mut lo, mut hi) = (4f64.cbrt(), 2.0 + kinetic);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if work(mid) < kinetic {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            for tol in [1e-6, 1e-12, 1e-15] {
                let m = max_contact_radius(kinetic, tol).unwrap();
                let a = m.contact_radius;
                let limit = tol.max(1e-13);
                assert!(m.energy_residual <= limit, "K {kinetic:e} tol {tol}: {m:?}");
                assert!(
                    (a - lo).abs() <= 20.0 * limit * lo,
                    "K {kinetic:e}: {a} vs {lo}"
                );
                assert!(m.cost.evaluations <= 10, "K {kinetic:e}: {m:?}");
            }
        }
        // from a neighbour's radius: the same root to rounding, in 1 or 2 steps;
        // a start outside the convex region is ignored
        for k in 0..=96 {
            let kinetic = 10f64.powf(-10.0 + 0.25 * f64::from(k));
            let cold = max_contact_radius(kinetic, 1e-12).unwrap();
            let near = max_contact_radius(kinetic * (1.0 + 1e-5), 1e-12).unwrap();
            let warm = max_contact_radius_near(kinetic, 1e-12, Some(near.contact_radius)).unwrap();
            assert!(
                (warm.contact_radius / cold.contact_radius - 1.0).abs() < 4.0 * f64::EPSILON,
                "K {kinetic:e}: {warm:?} vs {cold:?}"
            );
            assert!(warm.cost.iterations <= 2, "K {kinetic:e}: {warm:?}");
            for bad in [0.0, 1.0, f64::NAN, f64::INFINITY] {
                let m = max_contact_radius_near(kinetic, 1e-12, Some(bad)).unwrap();
                assert_eq!(m.contact_radius, cold.contact_radius);
            }
        }
        // from a neighbour up to 1e-7 away in energy, one Halley step lands (its
        // error bound is below rounding); farther away a second step is taken;
        // either way the root of the cold start to rounding
        for k in 0..=96 {
            let kinetic = 10f64.powf(-10.0 + 0.25 * f64::from(k));
            let cold = max_contact_radius(kinetic, 1e-12).unwrap();
            for offset in [-1e-3, -1e-5, -1e-7, -1e-9, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1] {
                let near = max_contact_radius(kinetic * (1.0 + offset), 1e-12).unwrap();
                let warm =
                    max_contact_radius_near(kinetic, 1e-12, Some(near.contact_radius)).unwrap();
                assert!(
                    (warm.contact_radius / cold.contact_radius - 1.0).abs() < 4.0 * f64::EPSILON,
                    "K {kinetic:e}, offset {offset:e}: {warm:?} vs {cold:?}"
                );
                assert!(warm.energy_residual <= 1e-12, "K {kinetic:e}: {warm:?}");
                if offset.abs() <= 1e-7 {
                    assert_eq!(
                        warm.cost.iterations, 1,
                        "K {kinetic:e}, {offset:e}: {warm:?}"
                    );
                }
            }
        }
        // no overflow at the largest energies, a clear error beyond
        assert!(max_contact_radius(1e300, 1e-12)
            .unwrap()
            .contact_radius
            .is_finite());
        assert!(max_contact_radius(f64::MAX, 1e-12).is_err());
    }

    #[test]
    fn fifth_root_is_powf_to_1e6() {
        for k in -300..=300 {
            for m in [1.0, 1.7, 3.3, 7.9] {
                let x = m * 10f64.powi(k);
                let exact = x.powf(0.2);
                assert!((fifth_root(x) / exact - 1.0).abs() < 1e-6, "{x:e}");
            }
        }
    }

    #[test]
    fn constants_are_what_their_comments_say() {
        let eps = 4.0 * f64::EPSILON;
        assert!((FIRST_TOUCH_RADIUS - (4.0f64 / 3.0).powf(2.0 / 3.0)).abs() < eps);
        assert!((ZERO_FORCE_RADIUS - 4f64.cbrt()).abs() < eps);
        assert!((LOADING_OFFSET - 1.2 * (4.0f64 / 3.0).powf(4.0 / 3.0)).abs() < eps);
        // W(â) = 0 there, to rounding (|W| ≤ a few ε of its terms, which reach ~20)
        assert!(balance_work(ZERO_WORK_RADIUS).abs() < 1e-14);
        assert!((SQRT_ZERO_WORK_RADIUS - ZERO_WORK_RADIUS.sqrt()).abs() < eps);
        let fg = separation_radius(SeparationRule::FixedGrip);
        assert!((fg - (1.0f64 / 3.0).powf(2.0 / 3.0)).abs() < eps);
        assert!((SQRT_FIXED_GRIP_RADIUS - 3f64.powf(-1.0 / 3.0)).abs() < eps);
        assert!((FIXED_GRIP_DEPTH + 3f64.powf(2.0 / 3.0)).abs() < 4.0 * eps);
        assert_eq!(
            FIXED_GRIP_DEPTH,
            depth_hat(separation_radius(SeparationRule::FixedGrip))
        );
        assert!(depth_hat(FIRST_TOUCH_RADIUS).abs() < 16.0 * eps);
        assert!(force_hat(ZERO_FORCE_RADIUS).abs() < 8.0 * eps);
    }

    /// The residual of the quartic at x, relative to its terms.
    fn quartic_residual(x: f64, d: f64) -> f64 {
        (3.0 * x.powi(4) - 4.0 * x - d).abs() / (3.0 * x.powi(4) + 4.0 * x + d.abs())
    }

    fn depths() -> Vec<f64> {
        let mut out = vec![FIXED_GRIP_DEPTH + 1e-12, FIXED_GRIP_DEPTH + 1e-6, -1.0, 0.0];
        let mut d: f64 = 1e-8;
        while d < 1e12 {
            out.extend([d, -d.min(2.08)]);
            d *= 3.7;
        }
        out
    }

    #[test]
    fn closed_form_and_newton_agree() {
        // Two derivations of the same root: Ferrari's formula and Newton's method
        // from a cold start (1 + d⁺/3)^(1/4), each to a few ulps away from the
        // ill-conditioned fixed-grip end (within 1e-6 of it: 1e-7).
        for d in depths() {
            let cold = quartic_root_from(d, f64::NAN).unwrap();
            let ferrari = sqrt_contact_radius_closed_form(d);
            let tol = if d < FIXED_GRIP_DEPTH + 1e-3 {
                1e-7
            } else {
                1e-14
            };
            assert!(
                (ferrari / cold - 1.0).abs() < tol,
                "d = {d:e}: {ferrari} vs {cold}"
            );
            let x = sqrt_contact_radius_at_depth(d).unwrap();
            assert!(quartic_residual(x, d) < 4.0 * f64::EPSILON, "d = {d:e}");
            assert!(x >= SQRT_FIXED_GRIP_RADIUS);
        }
    }

    #[test]
    fn warm_start_finds_the_same_root_from_any_guess() {
        for d in depths() {
            let x = sqrt_contact_radius_at_depth(d).unwrap();
            // the root's condition number: rounding of the quartic's terms over x f'(x)
            let condition = (3.0 * x.powi(4) + 4.0 * x + d.abs()) / (x * (12.0 * x.powi(3) - 4.0));
            let tol = 8.0 * f64::EPSILON * condition.max(1.0);
            for guess in [
                f64::NAN,
                -1.0,
                0.0,
                0.7,
                1.0,
                2.0,
                1e3,
                x * 1.01,
                x * 0.99,
                x,
            ] {
                let w = sqrt_contact_radius_at_depth_from(d, guess).unwrap();
                assert!((w / x - 1.0).abs() < tol, "d = {d:e}, guess {guess}");
            }
        }
        assert_eq!(
            sqrt_contact_radius_at_depth_from(-5.0, 1.0).unwrap(),
            SQRT_FIXED_GRIP_RADIUS
        );
        assert!(sqrt_contact_radius_at_depth_from(f64::NAN, 1.0).is_err());
        assert!(sqrt_contact_radius_at_depth(f64::INFINITY).is_err());
    }
}

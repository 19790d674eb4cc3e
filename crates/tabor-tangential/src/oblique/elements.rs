//! Small pieces of the friction elements: the turning rate of a slip direction,
//! the cap of a frozen element, the twisting coefficients, error helpers.

use super::limits::RATE_CAP;
use crate::model::Friction;
use crate::model::Twisting;
use crate::model::{Tangential, TangentialModel};
use nalgebra::Vector3;
use std::cell::Cell;
use tabor_restitution::Error;

/// The rate `P⊥(drive)/L` at which a slipping element's force direction `uhat`
/// turns toward the direction of `drive` (1/s), in the tangent plane (normal
/// `n`: the limit surface lies in it, so the part of `drive` along `n`, from
/// the turning of the plane, is dropped; the turning of `uhat` with the plane is
/// added by the caller). Where the limit L vanishes (first
/// touch and separation of a law without adhesion) the rate diverges and the
/// direction follows `drive` at once; there L is replaced by its floor
/// `|drive| time / 10⁴`, so the angle between `uhat` and `drive` relaxes at a rate
/// of at most 10⁴ per time unit `time` (s) of the impact, in proportion to the
/// angle (a capped *magnitude* would make the turning bang-bang about the
/// direction of `drive`, which no step size resolves).
pub(super) fn turn_rate(
    drive: &Vector3<f64>,
    uhat: &Vector3<f64>,
    n: &Vector3<f64>,
    limit: f64,
    time: f64,
) -> Vector3<f64> {
    let drive = drive - n * n.dot(drive);
    let perp = drive - uhat * uhat.dot(&drive);
    let limit = limit.max(drive.norm() * time / RATE_CAP);
    if limit > 0.0 {
        perp / limit
    } else {
        Vector3::zeros()
    }
}

/// The stick force `f` of a frozen element, capped at the limit.
pub(super) fn cap(f: Vector3<f64>, limit: f64, frozen: bool) -> Vector3<f64> {
    let size = f.norm();
    if frozen && size > limit {
        f * (limit / size)
    } else {
        f
    }
}

/// `a/b`, 0 when b is 0.
pub(super) fn ratio(a: f64, b: f64) -> f64 {
    if b != 0.0 {
        a / b
    } else {
        0.0
    }
}

/// The unit vector of `x`, or of `fallback` when `x` is zero (or neither: zero).
pub(super) fn direction(x: &Vector3<f64>, fallback: &Vector3<f64>) -> Vector3<f64> {
    let n = x.norm();
    if n > 0.0 {
        x / n
    } else {
        let m = fallback.norm();
        if m > 0.0 {
            fallback / m
        } else {
            Vector3::zeros()
        }
    }
}

/// Stiffness, damping and limit of the twisting resistance at contact radius `a`
/// with the normal damping coefficient `c_n` (`c a^β`, N s/m) there.
pub(super) fn twist_coefficients(
    tw: &Twisting,
    fr: &Friction,
    a: f64,
    c_n: f64,
    fc: f64,
) -> (f64, f64, f64) {
    match *tw {
        Twisting::Marshall => {
            let t = &fr.tangential;
            (
                0.5 * t.stiffness * a * a,
                0.5 * t.damping_ratio * c_n * a * a,
                2.0 / 3.0 * t.coefficient * a * fc,
            )
        }
        Twisting::Sds {
            stiffness,
            damping,
            coefficient,
        } => (stiffness, damping, coefficient * fc),
    }
}

pub(super) fn model_error(message: String) -> Error {
    Error::Model {
        model: "oblique impact",
        message,
    }
}

pub(super) fn keep_first(slot: &Cell<Option<Error>>, e: Error) {
    let old = slot.take();
    slot.set(Some(old.unwrap_or(e)));
}

/// The rates of a tangential element at contact radius `a` changing at
/// `a_dot` (m/s) with the normal damping coefficient changing at `c_n_dot`:
/// `(k̇, γ̇, ȧ/a)`, the last `mindlin_rescale`'s shrinking of ξ while
/// `unloading` (else 0). ξ ∝ a while it shrinks: the rate ȧ/a diverges where
/// the contact vanishes (Hertz: a ∝ δ^½ at separation), and so do ξ's
/// derivatives; capped at `RATE_CAP` per time unit `time` (s) as the turning of a
/// slip direction ([`turn_rate`]). The cap acts only within ~10⁻⁴ of the end,
/// where the stick force is bounded by a limit ~10⁻⁶ of its largest value.
pub(super) fn spring_rates(
    t: &Tangential,
    (a, a_dot): (f64, f64),
    c_n_dot: f64,
    unloading: bool,
    time: f64,
) -> (f64, f64, f64) {
    let k_dot = match t.model {
        TangentialModel::LinearHistory => 0.0,
        _ => t.stiffness * a_dot,
    };
    let gamma_dot = t.damping_ratio * c_n_dot;
    let rescale = t.model == TangentialModel::MindlinRescale && unloading;
    let rescale_rate = if rescale && a > 0.0 {
        (a_dot / a).max(-RATE_CAP / time)
    } else {
        0.0
    };
    (k_dot, gamma_dot, rescale_rate)
}

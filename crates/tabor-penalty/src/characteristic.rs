//! The contact characteristic of seed 002 ("Kontaktkennlinie"): a heuristic penalty
//! force `F = k κ(h) l(v, V)` with the gap h (negative in contact), the gap rate
//! v = ḣ, the piecewise-linear characteristic κ(h), its C¹ rounding over |h| < ε and
//! the velocity-dependent loss factor l(v, V).

use crate::series::log_remainder;
use crate::valid;
use tabor_dynamics::ForceLaw;
use tabor_numerics::quadrature::integrate_smooth;
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_numerics::{Cost, QuadTolerance};
use tabor_restitution::{validate, EnergyLoss, Error, Result};

/// The contact characteristic κ(h, ε) of seed 002 (dimension of a length).
///
/// Seed 002, "Stückweise linearer Ansatz" and "Ausrunden der Kennlinie": with
/// `rounding` ε = 0 the piecewise-linear law `κ = −h` for h < 0 and 0 otherwise; with
/// ε > 0 the C¹ rounding `κ = ε/4 − h/2 + h²/(4ε)` for −ε ≤ h ≤ ε (the quadratic
/// with p(ε) = 0, p'(−ε) = −1, p'(ε) = 0), `−h` below and 0 above.
///
/// `gap` h (m) finite, any sign (negative: penetration); `rounding` ε (m) finite ≥ 0.
pub fn contact_characteristic(gap: f64, rounding: f64) -> Result<f64> {
    let h = validate::finite("gap", gap)?;
    let eps = validate::non_negative("rounding", rounding)?;
    Ok(characteristic_unchecked(h, eps))
}

fn characteristic_unchecked(h: f64, eps: f64) -> f64 {
    if h >= eps {
        0.0
    } else if h <= -eps {
        -h
    } else {
        // |h| < ε, so ε > 0 here.
        let k = eps / 4.0 - h / 2.0 + h * h / (4.0 * eps);
        if k.is_finite() {
            k
        } else {
            // h² overflows (ε near f64::MAX): |h/ε| < 1 keeps this form finite
            eps / 4.0 - h / 2.0 + (h / eps) * h / 4.0
        }
    }
}

/// The velocity-dependent loss factor l(v, V) of seed 002, "Kontaktkennlinie mit
/// Verlustglied": `l = 1 − v/V` while the gap closes (v < 0) and `l = 1/(1 + v/V)`
/// while it opens (v ≥ 0). Both branches meet with value 1 and slope −1/V at v = 0
/// (the factor is C¹).
///
/// `gap_rate` v = ḣ (m/s) finite; `loss_speed` V (m/s) > 0, where `f64::INFINITY`
/// is the lossless limit l ≡ 1 (NaN, zero and negative values are errors).
pub fn loss_factor(gap_rate: f64, loss_speed: f64) -> Result<f64> {
    let v = validate::finite("gap_rate", gap_rate)?;
    let big_v = valid::loss_speed(loss_speed)?;
    let l = loss_factor_unchecked(v, big_v);
    if !l.is_finite() {
        return Err(Error::invalid(
            "gap_rate",
            v,
            "is so large against the loss speed that the loss factor overflows",
        ));
    }
    Ok(l)
}

fn loss_factor_unchecked(v: f64, big_v: f64) -> f64 {
    let u = v / big_v;
    if u < 0.0 {
        1.0 - u
    } else {
        1.0 / (1.0 + u)
    }
}

/// The coefficient of restitution of an impact at `impact_speed` v0 through the
/// seed-002 law `F = k κ(h) l(v, V)` (any stiffness k, any rounding ε, any mass).
///
/// Derived in this crate from seed 002's law (the seed gives no formula): with
/// r = v0/V, the equation of motion separates in (ḣ, h) on the way in and on the way
/// out, and the two first integrals share `(k/m) ∫κ dh`; hence the rebound
/// ratio e = v1/v0 solves
///
/// `e²/2 + r e³/3 = ψ(r)`, `ψ(r) = (r − ln(1 + r))/r²`,
///
/// independent of k, ε and m. e → 1 as V → ∞ (ψ → 1/2) and e falls monotonically
/// as V decreases (ψ decreases, the left side grows with r), like (3/r²)^(1/3) for
/// r → ∞. The cubic is solved by Brent's method to 1e-15.
pub fn characteristic_restitution(impact_speed: f64, loss_speed: f64) -> Result<f64> {
    let v0 = validate::positive("impact_speed", impact_speed)?;
    let big_v = valid::loss_speed(loss_speed)?;
    let r = v0 / big_v;
    if r == 0.0 {
        return Ok(1.0);
    }
    if !r.is_finite() {
        return Err(Error::invalid(
            "loss_speed",
            big_v,
            "is so small against impact_speed that v0/V overflows",
        ));
    }
    let rhs = log_remainder(r);
    let tol = RootTolerance {
        absolute: f64::MIN_POSITIVE,
        relative: 1e-15,
        max_iterations: 2000,
    };
    let root = brent(|e| e * e * (0.5 + r * e / 3.0) - rhs, 0.0, 1.0, tol)?;
    Ok(root.value.clamp(0.0, 1.0))
}

/// The loss speed V of the seed-002 law that makes an impact at `impact_speed` v0
/// rebound with `restitution` ε ∈ (0, 1]: the inverse of
/// [`characteristic_restitution`] (same relation, solved for r = v0/V by Brent's
/// method on [0, √(3/ε³)], where the left side is provably above ψ). ε = 1 gives
/// `f64::INFINITY` (no loss).
pub fn characteristic_loss_speed(restitution: f64, impact_speed: f64) -> Result<f64> {
    let e = valid::restitution(restitution)?;
    let v0 = validate::positive("impact_speed", impact_speed)?;
    if e == 1.0 {
        return Ok(f64::INFINITY);
    }
    let lhs = |r: f64| e * e * (0.5 + r * e / 3.0) - log_remainder(r);
    let hi = (3.0 / (e * e * e)).sqrt();
    if !hi.is_finite() {
        return Err(Error::invalid(
            "restitution",
            e,
            "is so small that the loss speed underflows",
        ));
    }
    let root = brent(lhs, 0.0, hi, RootTolerance::relative(1e-15))?;
    let big_v = v0 / root.value;
    if big_v.is_finite() && big_v > 0.0 {
        Ok(big_v)
    } else {
        Err(Error::invalid(
            "restitution",
            e,
            "gives a loss speed that is zero or overflows at this impact_speed",
        ))
    }
}

/// The seed-002 penalty law `F = k κ(h, ε) l(v, V)` (seed 002, "Kontaktkennlinie
/// mit Verlustglied"): a linear spring of stiffness k on the rounded characteristic,
/// scaled by the loss factor.
///
/// As a [`ForceLaw`] for the simulator (overlap d = −h, rate ḋ = −v) the motion
/// starts at the gap h = ε, where the rounded characteristic first pushes, and ends
/// when the gap reopens to ε.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ContactCharacteristic {
    stiffness: f64,
    rounding: f64,
    loss_speed: f64,
}

impl ContactCharacteristic {
    /// The law with spring constant `stiffness` k (N/m, > 0), `rounding` ε (m, ≥ 0;
    /// 0 for the piecewise-linear characteristic) and `loss_speed` V (m/s, > 0;
    /// `f64::INFINITY` for the lossless characteristic).
    pub fn new(stiffness: f64, rounding: f64, loss_speed: f64) -> Result<Self> {
        Ok(ContactCharacteristic {
            stiffness: validate::positive("stiffness", stiffness)?,
            rounding: validate::non_negative("rounding", rounding)?,
            loss_speed: valid::loss_speed(loss_speed)?,
        })
    }

    /// The spring constant k (N/m).
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// The rounding half-width ε (m).
    pub fn rounding(&self) -> f64 {
        self.rounding
    }

    /// The loss speed V (m/s).
    pub fn loss_speed(&self) -> f64 {
        self.loss_speed
    }

    /// The contact force `F = k κ(h, ε) l(v, V)` (N, repulsive > 0) at `gap` h (m)
    /// and `gap_rate` v = ḣ (m/s). Seed 002.
    pub fn force(&self, gap: f64, gap_rate: f64) -> Result<f64> {
        let h = validate::finite("gap", gap)?;
        let v = validate::finite("gap_rate", gap_rate)?;
        let f = self.force_unchecked(h, v);
        if !f.is_finite() {
            return Err(Error::invalid(
                "gap",
                h,
                "gives a contact force that overflows",
            ));
        }
        Ok(f)
    }

    fn force_unchecked(&self, h: f64, v: f64) -> f64 {
        self.stiffness
            * characteristic_unchecked(h, self.rounding)
            * loss_factor_unchecked(v, self.loss_speed)
    }

    /// The coefficient of restitution of an impact at `impact_speed` (m/s):
    /// [`characteristic_restitution`] (it does not depend on k, ε or the mass).
    pub fn restitution(&self, impact_speed: f64) -> Result<f64> {
        characteristic_restitution(impact_speed, self.loss_speed)
    }

    /// The energy dissipated in one cycle of the seed's prescribed oscillation
    /// `h = H cos(ω t)` (J): the hatched hysteresis area `∮ F d(−h)` of seed 002's
    /// figure "Kennlinie mit dynamischem Verlustglied" (the seed plots H = 1,
    /// ω = 2π, V = 1).
    ///
    /// Pairing the closing and opening halves at equal h, the loss is
    /// `W = ∫ k κ(h) [l(−|v|) − l(|v|)] |dh|` with `l(−u) − l(u) = u(2 + u)/(1 + u)`
    /// for u = |v|/V, so W ≥ 0 without cancellation.
    ///
    /// - ε = 0: closed form (derived here), with a = Hω/V,
    ///   `W = k H² (1/2 + a/3 − ψ(a))`, `ψ(a) = (a − ln(1 + a))/a²`
    ///   (the closing half does `k H² (1/2 + a/3)`, the opening half returns
    ///   `k H² ψ(a)`); error estimate 0.
    /// - ε > 0: adaptive Clenshaw-Curtis over the phase, split where κ changes
    ///   branch, relative tolerance 1e-12; the error estimate is the quadrature's.
    ///
    /// `amplitude` H (m) > 0, `angular_frequency` ω (rad/s) > 0.
    pub fn oscillation_loss(&self, amplitude: f64, angular_frequency: f64) -> Result<EnergyLoss> {
        let big_h = validate::positive("amplitude", amplitude)?;
        let omega = validate::positive("angular_frequency", angular_frequency)?;
        let k = self.stiffness;
        let speed = big_h * omega;
        let scale = k * big_h * big_h;
        if !(speed.is_finite() && scale.is_finite()) {
            return Err(Error::invalid(
                "amplitude",
                big_h,
                "gives a speed H omega or an energy k H^2 that overflows",
            ));
        }
        let a = speed / self.loss_speed;
        if a == 0.0 {
            return Ok(EnergyLoss::closed_form(0.0, "lossless characteristic"));
        }
        if !a.is_finite() {
            return Err(Error::invalid(
                "loss_speed",
                self.loss_speed,
                "is so small against H omega that the loss overflows",
            ));
        }
        let eps = self.rounding;
        if eps == 0.0 {
            // 1/2 − ψ(a) = a/3 − a²/4 + ... : written as a times a bounded factor.
            let half_minus_psi = if a < 0.05 {
                // a Σ_{j≥0} (−a)^j / (j + 3)
                let mut sum = 0.0;
                for j in (0..16).rev() {
                    sum = sum * (-a) + 1.0 / f64::from(j + 3);
                }
                a * sum
            } else {
                0.5 - log_remainder(a)
            };
            let w = validate::finite("oscillation_loss", scale * (a / 3.0 + half_minus_psi))?;
            return Ok(EnergyLoss::closed_form(
                w,
                "numpedia piecewise-linear contact characteristic: closed-form hysteresis area",
            ));
        }
        // Phase φ ∈ [φ_c, π] of the closing half: h = H cos φ, |v| = H ω sin φ,
        // |dh| = H sin φ dφ. Contact where h < ε.
        let ratio = eps / big_h;
        let phi_contact = ratio.min(1.0).acos();
        let phi_linear = (-ratio).max(-1.0).acos();
        let integrand = |phi: f64| {
            let (s, c) = phi.sin_cos();
            let s = s.max(0.0);
            let kappa = characteristic_unchecked(big_h * c, eps);
            let u = a * s;
            k * kappa * u * (2.0 + u) / (1.0 + u) * big_h * s
        };
        let tol = QuadTolerance {
            absolute: scale * 1e-15,
            relative: tabor_numerics::tolerance::DEFAULT_TOLERANCE,
        };
        let mut joules = 0.0;
        let mut error = 0.0;
        let mut cost = Cost::ZERO;
        let pieces = [
            (phi_contact, phi_linear),
            (phi_linear, std::f64::consts::PI),
        ];
        for (lo, hi) in pieces {
            if hi > lo {
                let part = integrate_smooth(integrand, lo, hi, tol)?;
                joules += part.value;
                error += part.error_estimate;
                cost += part.cost();
            }
        }
        Ok(EnergyLoss {
            joules: joules.max(0.0),
            error_estimate: error,
            branch: "numpedia rounded contact characteristic: hysteresis area by quadrature".into(),
            cost,
        })
    }
}

/// Seed 002's law in the simulator's variables: overlap d = −h, rate ḋ = −ḣ.
impl ForceLaw for ContactCharacteristic {
    fn name(&self) -> String {
        format!(
            "numpedia contact characteristic (k = {:e} N/m, eps = {:e} m, V = {:e} m/s)",
            self.stiffness, self.rounding, self.loss_speed
        )
    }

    /// The linear spring's d_max = v0 √(m/k), plus the rounding ε.
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let m = validate::positive("effective_mass", effective_mass)?;
        let v0 = validate::positive("impact_speed", impact_speed)?;
        validate::positive(
            "overlap_scale",
            v0 * (m / self.stiffness).sqrt() + self.rounding,
        )
    }

    /// The gap h = ε where the rounded characteristic begins to push.
    fn start_overlap(&self) -> f64 {
        -self.rounding
    }

    fn force(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        let f = self.force_unchecked(-overlap, -overlap_rate);
        validate::finite("force", f)
    }

    /// A penalty law has no contact radius: 0.
    fn contact_radius(&self, _overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(0.0)
    }

    /// The gap reopens to ε: `d + ε`.
    fn branch_end(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(overlap + self.rounding)
    }
}

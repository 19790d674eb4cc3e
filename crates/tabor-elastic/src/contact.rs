//! The static contact relations of a rigid power-law indenter on an elastic
//! half-space, homogeneous or power-law graded: the force law F(d), the contact
//! radius a(d) and the stored elastic energy U(d) that the impact solutions rest on.

use serde::Serialize;
use tabor_numerics::special::{graded_power_law_beta, power_law_beta};
use tabor_restitution::effective::{effective_modulus, effective_radius};
use tabor_restitution::{validate, ElasticMaterial, Error, Result};

/// Which body shape and medium a contact describes (for names and the pressure
/// formulas, which exist for spheres only).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContactGeometry {
    /// Hertzian sphere (parabolic profile, n = 2) on a homogeneous half-space.
    HertzSphere {
        /// Effective radius R (m).
        radius: f64,
    },
    /// Power-law profile `f(r) = A rⁿ` on a homogeneous half-space.
    PowerLaw,
    /// Sphere (parabolic profile) on a power-law graded half-space.
    GradedSphere {
        /// Effective radius R (m).
        radius: f64,
    },
    /// Power-law profile on a power-law graded half-space.
    GradedPowerLaw,
}

/// A frictionless, non-adhesive contact of a rigid axisymmetric power-law indenter
/// `f(r) = A rⁿ` with an elastic half-space whose modulus grows with depth as
/// `c_N z^k` (k = 0: homogeneous, `c_N` = E*).
///
/// With `β = β(n, k)` (seed 000 eq. (5.28); β(n) at k = 0) the contact relations are
/// `d = β A aⁿ` and
/// `F(d) = 2 n c_N / ((n + k + 1)(1 + k)) · (β A)^(−(1+k)/n) · d^((n+k+1)/n)`,
/// the derivative of the stored energy of seed 000 eqs. (5.15), (5.20) and the
/// potential behind (5.28). For the Hertzian sphere this is
/// `F = (4/3) E* √(R d³)` (5.5).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ElasticContact {
    geometry: ContactGeometry,
    /// E* (homogeneous) or c_N (graded), Pa·m^(−k).
    modulus_coefficient: f64,
    gradation_exponent: f64,
    profile_prefactor: f64,
    profile_exponent: f64,
    beta: f64,
    /// F = K d^q.
    force_coefficient: f64,
    force_exponent: f64,
}

/// The Hertz force `F = (4/3) E* √R δ^(3/2)` (N) of effective modulus E* (Pa)
/// at overlap δ (m; 0 for δ ≤ 0), given √R (m^(1/2)) so that a caller evaluating
/// many overlaps at one radius takes the root once. Not validated (per-step inner
/// loops): NaN in, NaN out. The same law as [`ElasticContact::hertz`]`.force`.
///
/// Seed 000, eq. (5.5).
#[inline]
pub fn hertz_force(effective_modulus: f64, sqrt_radius: f64, overlap: f64) -> f64 {
    if overlap > 0.0 {
        4.0 / 3.0 * effective_modulus * sqrt_radius * overlap * overlap.sqrt()
    } else if overlap <= 0.0 {
        0.0
    } else {
        f64::NAN
    }
}

impl ElasticContact {
    /// A Hertzian sphere of effective radius `effective_radius` R (m) on a
    /// homogeneous half-space of effective modulus `effective_modulus` E* (Pa):
    /// `F = (4/3) E* √(R d³)`, `a = √(R d)`.
    ///
    /// Seed 000, eq. (5.5).
    pub fn hertz(effective_modulus: f64, effective_radius: f64) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let r = validate::positive("effective_radius", effective_radius)?;
        Self::build(
            ContactGeometry::HertzSphere { radius: r },
            e,
            0.0,
            0.5 / r,
            2.0,
        )
    }

    /// The Hertzian contact of two spheres (or a sphere on a flat when
    /// `target_radius` is `None`) of the two materials: E* and R from
    /// [`tabor_restitution::effective`].
    ///
    /// Seed 000, eq. (5.5) with the effective quantities of chapter 5.
    pub fn hertz_between(
        first: &ElasticMaterial,
        second: &ElasticMaterial,
        radius: f64,
        target_radius: Option<f64>,
    ) -> Result<Self> {
        let e = effective_modulus(first, second)?;
        let r = effective_radius(radius, target_radius)?;
        Self::hertz(e, r)
    }

    /// A rigid power-law indenter `f(r) = A rⁿ` (`profile_prefactor` A > 0 in
    /// m^(1−n), `profile_exponent` n > 0) on a homogeneous half-space of effective
    /// modulus E*: `d = β(n) A aⁿ`, `F = 2E* n/(n+1) β(n) A a^(n+1)`.
    ///
    /// Seed 000, eq. (5.15) (the stored energy) and its contact solution.
    pub fn power_law(
        effective_modulus: f64,
        profile_prefactor: f64,
        profile_exponent: f64,
    ) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let a = validate::positive("profile_prefactor", profile_prefactor)?;
        let n = validate::positive("profile_exponent", profile_exponent)?;
        Self::build(ContactGeometry::PowerLaw, e, 0.0, a, n)
    }

    /// A sphere of effective radius R on a power-law graded half-space with modulus
    /// coefficient `gradation_coefficient` c_N (Pa·m^(−k)) and exponent
    /// `gradation_exponent` −1 < k < 1:
    /// `F = 4 c_N/(3+k) √((1+k)^(k−1) R^(1+k) d^(3+k))`, `a² = (1+k) R d`.
    ///
    /// Seed 000, eq. (5.20) (the stored energy).
    pub fn graded_sphere(
        gradation_coefficient: f64,
        gradation_exponent: f64,
        effective_radius: f64,
    ) -> Result<Self> {
        let c = validate::positive("gradation_coefficient", gradation_coefficient)?;
        let k = gradation("gradation_exponent", gradation_exponent)?;
        let r = validate::positive("effective_radius", effective_radius)?;
        Self::build(
            ContactGeometry::GradedSphere { radius: r },
            c,
            k,
            0.5 / r,
            2.0,
        )
    }

    /// A power-law indenter `f(r) = A rⁿ` on a power-law graded half-space (c_N, k):
    /// `d = β(n, k) A aⁿ`.
    ///
    /// Seed 000, eqs. (5.28)-(5.30) (the contact solution behind them).
    pub fn graded_power_law(
        gradation_coefficient: f64,
        gradation_exponent: f64,
        profile_prefactor: f64,
        profile_exponent: f64,
    ) -> Result<Self> {
        let c = validate::positive("gradation_coefficient", gradation_coefficient)?;
        let k = gradation("gradation_exponent", gradation_exponent)?;
        let a = validate::positive("profile_prefactor", profile_prefactor)?;
        let n = validate::positive("profile_exponent", profile_exponent)?;
        Self::build(ContactGeometry::GradedPowerLaw, c, k, a, n)
    }

    fn build(geometry: ContactGeometry, c: f64, k: f64, a: f64, n: f64) -> Result<Self> {
        let beta = if k == 0.0 {
            power_law_beta(n)?
        } else {
            graded_power_law_beta(n, k)?
        };
        // K = 2 n c / ((n+k+1)(1+k)) (β A)^(−(1+k)/n), in logarithms so that large n
        // or extreme A do not overflow on the way.
        let ln_k =
            (2.0 * n * c / ((n + k + 1.0) * (1.0 + k))).ln() - (1.0 + k) / n * (beta.ln() + a.ln());
        let force_coefficient = ln_k.exp();
        if !(force_coefficient.is_finite() && force_coefficient > 0.0) {
            return Err(Error::invalid(
                "profile_prefactor",
                a,
                "gives a force coefficient that overflows or underflows for this exponent",
            ));
        }
        Ok(ElasticContact {
            geometry,
            modulus_coefficient: c,
            gradation_exponent: k,
            profile_prefactor: a,
            profile_exponent: n,
            beta,
            force_coefficient,
            force_exponent: (n + k + 1.0) / n,
        })
    }

    /// Which geometry this is.
    pub fn geometry(&self) -> ContactGeometry {
        self.geometry
    }

    /// E* (homogeneous) or c_N (graded) (Pa·m^(−k)).
    pub fn modulus_coefficient(&self) -> f64 {
        self.modulus_coefficient
    }

    /// The gradation exponent k (0 for a homogeneous medium).
    pub fn gradation_exponent(&self) -> f64 {
        self.gradation_exponent
    }

    /// The profile prefactor A (m^(1−n)); 1/(2R) for spheres.
    pub fn profile_prefactor(&self) -> f64 {
        self.profile_prefactor
    }

    /// The profile exponent n (2 for spheres).
    pub fn profile_exponent(&self) -> f64 {
        self.profile_exponent
    }

    /// The profile factor β(n) or β(n, k) with `d = β A aⁿ`.
    ///
    /// Seed 000, eqs. (5.15) and (5.28).
    pub fn profile_factor(&self) -> f64 {
        self.beta
    }

    /// The "corrected" profile exponent ñ = n/(1+k): the graded impact follows the
    /// normalized trajectory of the homogeneous impact with this exponent.
    ///
    /// Seed 000, eq. (5.32).
    pub fn equivalent_homogeneous_exponent(&self) -> f64 {
        self.profile_exponent / (1.0 + self.gradation_exponent)
    }

    /// The exponent q of the force law `F = K d^q`, q = (n+k+1)/n (3/2 for Hertz).
    pub fn force_exponent(&self) -> f64 {
        self.force_exponent
    }

    /// The coefficient K of the force law `F = K d^q` (N m^(−q)).
    pub fn force_coefficient(&self) -> f64 {
        self.force_coefficient
    }

    /// The normal force F(d) (N, repulsive positive) at overlap (indentation) `d`
    /// (m); 0 for `d ≤ 0` (no contact). Not validated: NaN in, NaN out (this sits in
    /// the integrator's inner loop).
    ///
    /// Seed 000, eq. (5.5) (Hertz), the derivatives of (5.15), (5.20) and of the
    /// potential behind (5.28).
    pub fn force(&self, overlap: f64) -> f64 {
        if overlap > 0.0 {
            power_term(&[self.force_coefficient], self.force_exponent, overlap)
        } else if overlap <= 0.0 {
            0.0
        } else {
            f64::NAN
        }
    }

    /// The contact stiffness dF/dd (N/m) at overlap `d`; 0 for `d ≤ 0` (for
    /// homogeneous media it equals 2E* a).
    pub fn stiffness(&self, overlap: f64) -> f64 {
        if overlap > 0.0 {
            power_term(
                &[self.force_coefficient, self.force_exponent],
                self.force_exponent - 1.0,
                overlap,
            )
        } else if overlap <= 0.0 {
            0.0
        } else {
            f64::NAN
        }
    }

    /// The contact radius a(d) = (d/(β A))^(1/n) (m); 0 for `d ≤ 0`
    /// (`a = √(R d)` for Hertz, `a = √((1+k) R d)` for a graded sphere).
    ///
    /// Seed 000, the contact solutions behind eqs. (5.15) and (5.28).
    pub fn contact_radius(&self, overlap: f64) -> f64 {
        if overlap > 0.0 {
            let scale = self.beta * self.profile_prefactor;
            let x = overlap / scale;
            if x.is_finite() {
                x.powf(1.0 / self.profile_exponent)
            } else {
                // the quotient overflows (huge radius): take the root of each factor
                overlap.powf(1.0 / self.profile_exponent) / scale.powf(1.0 / self.profile_exponent)
            }
        } else if overlap <= 0.0 {
            0.0
        } else {
            f64::NAN
        }
    }

    /// The elastic energy stored at overlap `d`, `U(d) = ∫₀ᵈ F dd = K d^(q+1)/(q+1)`
    /// (J): the potential terms of seed 000 eqs. (5.7), (5.15) and (5.20).
    pub fn stored_energy(&self, overlap: f64) -> f64 {
        if overlap > 0.0 {
            let q1 = self.force_exponent + 1.0;
            power_term(&[self.force_coefficient, 1.0 / q1], q1, overlap)
        } else if overlap <= 0.0 {
            0.0
        } else {
            f64::NAN
        }
    }

    /// A short name for reports, for example "Hertz sphere".
    pub fn name(&self) -> String {
        match self.geometry {
            ContactGeometry::HertzSphere { .. } => "Hertz sphere".into(),
            ContactGeometry::PowerLaw => {
                format!("power-law indenter (n = {})", self.profile_exponent)
            }
            ContactGeometry::GradedSphere { .. } => {
                format!("sphere on graded medium (k = {})", self.gradation_exponent)
            }
            ContactGeometry::GradedPowerLaw => format!(
                "power-law indenter (n = {}) on graded medium (k = {})",
                self.profile_exponent, self.gradation_exponent
            ),
        }
    }
}

fn gradation(parameter: &'static str, k: f64) -> Result<f64> {
    validate::in_open_interval(
        parameter,
        k,
        -1.0,
        1.0,
        "the gradation exponent must satisfy -1 < k < 1",
    )
}

/// `Π factors · x^p` for positive factors and x > 0, without the NaN of an
/// overflowing factor times an underflowing power (∞ · 0): where the direct
/// product is not a finite non-zero number it is evaluated through logarithms,
/// which rounds to the correct 0 or ∞.
fn power_term(factors: &[f64], p: f64, x: f64) -> f64 {
    let direct = factors.iter().product::<f64>() * x.powf(p);
    if direct.is_finite() && direct != 0.0 {
        direct
    } else {
        (factors.iter().map(|f| f.ln()).sum::<f64>() + p * x.ln()).exp()
    }
}

#[cfg(test)]
mod hertz_force_tests {
    use super::*;

    #[test]
    fn hertz_force_is_the_power_law_of_the_hertz_contact() {
        // the general power law F = K d^q of ElasticContact::hertz (q = 3/2 from the
        // profile (5.15)) against the closed form (5.5)
        let (e, r) = (6.1e10, 3e-6_f64);
        let c = ElasticContact::hertz(e, r).unwrap();
        for d in [1e-12, 3e-10, 2e-8, 1e-6] {
            let f = hertz_force(e, r.sqrt(), d);
            assert!((f / c.force(d) - 1.0).abs() < 1e-13, "{d}");
        }
        assert_eq!(hertz_force(e, r.sqrt(), -1e-9), 0.0);
        assert!(hertz_force(e, r.sqrt(), f64::NAN).is_nan());
    }
}

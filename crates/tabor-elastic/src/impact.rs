//! Closed-form solution of the quasi-static elastic impact without adhesion, seed
//! 000 section 5.2: maximum overlap and force, the inverse trajectory t(d), the
//! contact time, the maximum pressure and Hunter's sine approximation.

use crate::contact::{ContactGeometry, ElasticContact};
use crate::trajectory::{normalized_contact_time, normalized_time};
use serde::Serialize;
use tabor_restitution::{validate, EnergyLoss, Error, ImpactModel, Result};

/// The central impact of a rigid indenter of effective mass m on an elastic
/// half-space through an [`ElasticContact`], starting at first contact d = 0 with
/// speed v0 (seed 000 eq. (5.6)). Without adhesion the impact is conservative:
/// restitution 1, loss 0.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ElasticImpact {
    contact: ElasticContact,
    mass: f64,
}

impl ElasticImpact {
    /// The impact of effective mass `effective_mass` m (kg) through `contact`.
    ///
    /// Seed 000, eq. (5.5) (the equation of motion `m d̈ = −F(d)`) with (5.6).
    pub fn new(contact: ElasticContact, effective_mass: f64) -> Result<Self> {
        Ok(ElasticImpact {
            contact,
            mass: validate::positive("effective_mass", effective_mass)?,
        })
    }

    /// The contact law.
    pub fn contact(&self) -> &ElasticContact {
        &self.contact
    }

    /// The effective mass m (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }

    fn kinetic_energy(&self, impact_speed: f64) -> Result<f64> {
        let v = validate::positive("impact_speed", impact_speed)?;
        let e = 0.5 * self.mass * v * v;
        if e.is_finite() && e > 0.0 {
            Ok(e)
        } else {
            Err(Error::invalid(
                "impact_speed",
                v,
                "gives a kinetic energy m v0^2/2 that is zero or overflows",
            ))
        }
    }

    /// The maximum overlap d_max at impact speed v0 (m/s), from `U(d_max) = m v0²/2`.
    /// For Hertz `d_max = (15 m v0² / (16 E* √R))^(2/5)`.
    ///
    /// Seed 000, eqs. (5.8) (Hertz), (5.16) (power law), (5.21) (graded sphere),
    /// (5.28) (power law on graded medium).
    pub fn max_overlap(&self, impact_speed: f64) -> Result<f64> {
        let w = self.kinetic_energy(impact_speed)?;
        let q1 = self.contact.force_exponent() + 1.0;
        // U(d) = K d^(q+1)/(q+1) = w, in logarithms.
        let ln_d = ((q1 * w).ln() - self.contact.force_coefficient().ln()) / q1;
        finite_positive("max_overlap", ln_d.exp(), impact_speed)
    }

    /// The maximum force F_max = F(d_max) (N); Hertz:
    /// `(125/36 m³ v0⁶ R E*²)^(1/5)`.
    ///
    /// Seed 000, eq. (5.9).
    pub fn max_force(&self, impact_speed: f64) -> Result<f64> {
        let d = self.max_overlap(impact_speed)?;
        finite_positive("max_force", self.contact.force(d), impact_speed)
    }

    /// The largest contact radius a(d_max) (m); for Hertz
    /// `(15 m v0² R² / (16 E*))^(1/5)`.
    ///
    /// Seed 000, eq. (5.26).
    pub fn max_contact_radius(&self, impact_speed: f64) -> Result<f64> {
        let d = self.max_overlap(impact_speed)?;
        finite_positive(
            "max_contact_radius",
            self.contact.contact_radius(d),
            impact_speed,
        )
    }

    /// The time after first contact at which the overlap first reaches `overlap`
    /// d ∈ [0, d_max] (loading half; on unloading the overlap is d again at
    /// `T_S − t(d)`):
    /// `t(d) = p d_max/v0 · B(ξ; p, 1/2)`, `ξ = (d/d_max)^(1/p)`, `p = n/(2n+k+1)`.
    ///
    /// Seed 000, eqs. (5.11) (Hertz, p = 2/5), (5.17) (power law), (5.22) (graded
    /// sphere), (5.29) (power law on graded medium).
    pub fn time_at_overlap(&self, impact_speed: f64, overlap: f64) -> Result<f64> {
        let d_max = self.max_overlap(impact_speed)?;
        let d = validate::non_negative("overlap", overlap)?;
        if d > d_max * (1.0 + 1e-12) {
            return Err(Error::invalid(
                "overlap",
                d,
                "must not exceed the maximum overlap d_max of the impact",
            ));
        }
        let t_hat = normalized_time((d / d_max).min(1.0), self.equivalent_exponent())?;
        finite_non_negative(
            "time_at_overlap",
            t_hat * d_max / impact_speed,
            impact_speed,
        )
    }

    /// The contact time `T_S = 2p d_max/v0 · B(1; p, 1/2)`, `p = n/(2n+k+1)`.
    ///
    /// Seed 000, eqs. (5.12) (Hertz), (5.18) (power law), (5.23) (graded sphere),
    /// (5.30) (power law on graded medium).
    pub fn contact_time(&self, impact_speed: f64) -> Result<f64> {
        let d_max = self.max_overlap(impact_speed)?;
        let t_hat = normalized_contact_time(self.equivalent_exponent())?;
        finite_positive("contact_time", t_hat * d_max / impact_speed, impact_speed)
    }

    /// Hunter's approximation of the trajectory, `d(t) ≈ d_max sin(π t / T_S)` for
    /// 0 ≤ t ≤ T_S (exact for n → ∞, (5.19)).
    ///
    /// Seed 000, eq. (5.14).
    pub fn hunter_overlap(&self, impact_speed: f64, time: f64) -> Result<f64> {
        let t_s = self.contact_time(impact_speed)?;
        let t = validate::non_negative("time", time)?;
        if t > t_s * (1.0 + 1e-12) {
            return Err(Error::invalid(
                "time",
                t,
                "must lie within the contact time T_S",
            ));
        }
        let d_max = self.max_overlap(impact_speed)?;
        Ok(d_max * (std::f64::consts::PI * (t / t_s).min(1.0)).sin().max(0.0))
    }

    /// The maximum contact pressure during the impact (Pa), for spheres only:
    /// Hertz `p_max = (2E*/π) √(d_max/R)` (5.13); sphere on a graded medium
    /// `p_max = (2/π) c_N^(4/(5+k)) R^((k−3)/(5+k)) (1+k)^((k−7)/(5+k))
    /// [m v0² (3+k)(5+k)/16]^((1+k)/(5+k))` (5.24). Other profiles: an error
    /// ([`Error::Model`]); their pressure is singular or off-centre.
    ///
    /// Seed 000, eqs. (5.13) and (5.24).
    pub fn max_pressure(&self, impact_speed: f64) -> Result<f64> {
        let v = validate::positive("impact_speed", impact_speed)?;
        match self.contact.geometry() {
            ContactGeometry::HertzSphere { radius } => {
                let d_max = self.max_overlap(v)?;
                let e = self.contact.modulus_coefficient();
                finite_positive(
                    "max_pressure",
                    2.0 * e / std::f64::consts::PI * (d_max / radius).sqrt(),
                    v,
                )
            }
            ContactGeometry::GradedSphere { radius } => {
                let c = self.contact.modulus_coefficient();
                let k = self.contact.gradation_exponent();
                let s = 5.0 + k;
                let energy = self.mass * v * v * (3.0 + k) * (5.0 + k) / 16.0;
                let ln_p = (2.0 / std::f64::consts::PI).ln()
                    + 4.0 / s * c.ln()
                    + (k - 3.0) / s * radius.ln()
                    + (k - 7.0) / s * (1.0 + k).ln()
                    + (1.0 + k) / s * energy.ln();
                finite_positive("max_pressure", ln_p.exp(), v)
            }
            ContactGeometry::PowerLaw | ContactGeometry::GradedPowerLaw => Err(Error::Model {
                model: "elastic impact",
                message: "the maximum pressure (5.13)/(5.24) is defined for spheres only".into(),
            }),
        }
    }

    /// The exponent ñ = n/(1+k) of the equivalent homogeneous impact.
    ///
    /// Seed 000, eq. (5.32).
    pub fn equivalent_exponent(&self) -> f64 {
        self.contact.equivalent_homogeneous_exponent()
    }
}

fn finite_positive(what: &'static str, value: f64, impact_speed: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::invalid(
            "impact_speed",
            impact_speed,
            match what {
                "max_overlap" => "gives a maximum overlap that overflows or underflows",
                "max_force" => "gives a maximum force that overflows or underflows",
                "contact_time" => "gives a contact time that overflows or underflows",
                "max_pressure" => "gives a maximum pressure that overflows or underflows",
                _ => "gives a result that overflows or underflows",
            },
        ))
    }
}

fn finite_non_negative(what: &'static str, value: f64, impact_speed: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        finite_positive(what, f64::NAN, impact_speed)
    }
}

impl ImpactModel for ElasticImpact {
    fn name(&self) -> String {
        format!("elastic, no adhesion: {}", self.contact.name())
    }

    fn effective_mass(&self) -> f64 {
        self.mass
    }

    /// No loss: the quasi-static elastic impact is conservative, restitution 1
    /// (seed 000 section 5.2.1, after (5.14)).
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        self.kinetic_energy(impact_speed)?;
        Ok(EnergyLoss::closed_form(
            0.0,
            "elastic without adhesion: no loss (Willert 2020, section 5.2)",
        ))
    }

    fn loss_is_speed_independent(&self) -> bool {
        true
    }
}

//! A sphere on a power-law graded elastic medium with JKR adhesion
//! (seed 000, section 5.3.3).

use crate::common::{
    finite_output, loss_by_quadrature, solve_energy_balance, Balance, JkrContactState,
    MaxContactRadius, SeparationRule,
};
use crate::impact::AdhesiveContact;
use crate::relations::{Relations, Scales};
use std::f64::consts::PI;
use tabor_numerics::Cost;
use tabor_restitution::{validate, EnergyLoss, Result};

const MODEL: &str = "JKR graded medium";

/// A parabolic JKR contact (effective radius `R`) on a medium whose modulus grows as
/// a power `k` of depth, −1 < k < 1, parametrized as the seed does by the stiffness
/// coefficient `c_N` (Pa·m^(−k)) and `k` (seed 000, (5.47)-(5.48), from (3.245)-(3.246)):
///
/// ```text
/// F = 4 c_N a^(3+k) / ((1+k)²(3+k) R) − 2/(1+k) √(2π c_N Δγ a^(3+k)),
/// d = a² / ((1+k) R) − √(2π a^(1−k) Δγ / c_N).
/// ```
///
/// `k = 0`, `c_N = E*` is the [`crate::JkrSphere`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GradedSphere {
    coefficient: f64,
    exponent: f64,
    radius: f64,
    work_of_adhesion: f64,
    core: Relations,
    scales: Scales,
}

impl GradedSphere {
    /// A sphere of effective radius `R` (m, > 0) with work of adhesion `Δγ` (J/m², > 0)
    /// on a graded medium with stiffness coefficient `c_N` (Pa·m^(−k), > 0) and
    /// gradation exponent `k` (−1 < k < 1).
    ///
    /// Seed 000, the parameters of (5.47)-(5.52).
    pub fn new(
        modulus_coefficient: f64,
        gradation_exponent: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        let c = validate::positive("modulus_coefficient", modulus_coefficient)?;
        let k = validate::in_open_interval(
            "gradation_exponent",
            gradation_exponent,
            -1.0,
            1.0,
            "must satisfy -1 < k < 1 (Willert 2020, section 5.3.3)",
        )?;
        let r = validate::positive("effective_radius", effective_radius)?;
        let dg = validate::positive("work_of_adhesion", work_of_adhesion)?;
        let core = Relations {
            p: 2.0,
            q: 0.5 * (1.0 - k),
            kappa: 1.0 + k,
        };
        let ln_stiffness = (2.0 * c / (1.0 + k)).ln();
        let ln_p = -((1.0 + k).ln() + r.ln());
        let ln_q = 0.5 * ((2.0 * PI).ln() + dg.ln() - c.ln());
        let scales = core.scales(MODEL, ln_stiffness, ln_p, ln_q)?;
        Ok(GradedSphere {
            coefficient: c,
            exponent: k,
            radius: r,
            work_of_adhesion: dg,
            core,
            scales,
        })
    }

    /// The gradation exponent k.
    pub fn gradation_exponent(&self) -> f64 {
        self.exponent
    }

    /// Force at contact radius `a` (m, ≥ 0), compression positive (N).
    ///
    /// Seed 000, eq. (5.47) (its right-hand side is −F).
    pub fn force(&self, contact_radius: f64) -> Result<f64> {
        let a = validate::non_negative("contact_radius", contact_radius)?;
        let f = self.core.force(a / self.scales.contact_radius) * self.scales.force;
        finite_output(MODEL, "force", f)
    }

    /// Depth at contact radius `a` (m, ≥ 0) (m).
    ///
    /// Seed 000, eq. (5.48).
    pub fn depth(&self, contact_radius: f64) -> Result<f64> {
        let a = validate::non_negative("contact_radius", contact_radius)?;
        let d = self.core.depth(a / self.scales.contact_radius) * self.scales.depth;
        finite_output(MODEL, "depth", d)
    }

    /// `ln ΔU_0`, `ΔU_0 = (3+k)/(5+k) [4 (πΔγ)^(5+k) R⁴ (1+k)⁴ / c_N²]^(1/(3+k))` (J).
    /// Seed 000, eq. (5.50).
    fn ln_delta_u0(&self) -> f64 {
        let k = self.exponent;
        ((3.0 + k) / (5.0 + k)).ln()
            + (4f64.ln()
                + (5.0 + k) * (PI * self.work_of_adhesion).ln()
                + 4.0 * self.radius.ln()
                + 4.0 * (1.0 + k).ln()
                - 2.0 * self.coefficient.ln())
                / (3.0 + k)
    }

    /// The bracket `1 + 2^(−8/(3+k)) (2+k)/((1+k)(3+k)) (1−k)^((7+k)/(3+k))` of
    /// (5.51)-(5.52).
    fn loss_bracket(&self) -> f64 {
        let k = self.exponent;
        1.0 + (2f64.powf(-8.0 / (3.0 + k)) * (2.0 + k) / ((1.0 + k) * (3.0 + k)))
            * (1.0 - k).powf((7.0 + k) / (3.0 + k))
    }

    /// The right side of (5.49) in units of the energy scale, at `x = a/a0`.
    fn kinetic_to_reach_hat(&self, x: f64) -> f64 {
        let k = self.exponent;
        let (c, r, dg) = (self.coefficient, self.radius, self.work_of_adhesion);
        let a = x * self.scales.contact_radius;
        let e = self.scales.energy;
        let t1 = 8.0 * c * a.powf(5.0 + k) / ((1.0 + k).powi(3) * (3.0 + k) * (5.0 + k) * r * r);
        let t2 = 4.0 / ((1.0 + k).powi(2) * (3.0 + k) * r)
            * (2.0 * PI * dg * c * a.powf(7.0 + k)).sqrt();
        let t3 = (1.0 - k) / (1.0 + k) * PI * dg * a * a;
        (t1 - t2 + t3) / e + (self.ln_delta_u0() - e.ln()).exp()
    }

    /// The ratio of the fixed-grip loss to that of a homogeneous sphere (k = 0) of
    /// modulus `E_0` (Pa, > 0) with the same R and Δγ:
    /// `10·2^(2/3)(3+k)(1+k)^(4/(3+k)) / ((5+k)(1+∛864)) · [E_0/(c_N (a_0^(k=0))^k)]^(2/(3+k))
    ///  · [1 + 2^(−8/(3+k)) (2+k)/((1+k)(3+k)) (1−k)^((7+k)/(3+k))]`,
    /// with `a_0^(k=0) = (2πΔγR²/E_0)^(1/3)` the homogeneous first-touch radius.
    ///
    /// Seed 000, eq. (5.52) (and (5.53), its logarithm).
    pub fn loss_ratio_to_homogeneous(&self, homogeneous_modulus: f64) -> Result<f64> {
        let e0 = validate::positive("homogeneous_modulus", homogeneous_modulus)?;
        let k = self.exponent;
        let ln_a00 =
            ((2.0 * PI).ln() + self.work_of_adhesion.ln() + 2.0 * self.radius.ln() - e0.ln()) / 3.0;
        let ln_ratio =
            (10.0 * 2f64.powf(2.0 / 3.0) * (3.0 + k) / ((5.0 + k) * (1.0 + 864f64.cbrt()))).ln()
                + 4.0 / (3.0 + k) * (1.0 + k).ln()
                + 2.0 / (3.0 + k) * (e0.ln() - self.coefficient.ln() - k * ln_a00)
                + self.loss_bracket().ln();
        finite_output(MODEL, "loss ratio", ln_ratio.exp())
    }
}

impl AdhesiveContact for GradedSphere {
    fn description(&self) -> String {
        format!("JKR graded medium (k = {})", self.exponent)
    }

    /// First touch `d = 0`: `a0 = ((1+k)R √(2πΔγ/c_N))^(2/(3+k))`.
    fn first_touch(&self) -> Result<JkrContactState> {
        Ok(self.scales.physical_state(self.core.state(1.0)))
    }

    /// Fixed grip `dd/da = 0`: `a = a0 ((1−k)/4)^(2/(3+k))`; load-controlled
    /// `dF/da = 0`: `a = a0 ((3+k)/4)^(2/(3+k))`.
    fn critical_state(&self, rule: SeparationRule) -> Result<JkrContactState> {
        let x = self.core.separation_radius(rule);
        Ok(self.scales.physical_state(self.core.state(x)))
    }

    fn energy_scale(&self) -> f64 {
        self.scales.energy
    }

    /// Fixed grip: seed 000, eqs. (5.50)-(5.51). Load-controlled: the integral
    /// `∫ F dd` from first touch to `dF/da = 0` by quadrature.
    fn energy_loss(&self, rule: SeparationRule, tolerance: f64) -> Result<EnergyLoss> {
        let tol = validate::tolerance("tolerance", tolerance)?;
        match rule {
            SeparationRule::FixedGrip => {
                let ln_loss = self.ln_delta_u0() + self.loss_bracket().ln();
                Ok(EnergyLoss::closed_form(
                    finite_output(MODEL, "energy loss", ln_loss.exp())?,
                    "JKR graded medium, fixed grip: closed form (5.50)-(5.51)",
                ))
            }
            SeparationRule::LoadControlled => {
                let core = self.core;
                let n = loss_by_quadrature(
                    |x| core.work_integrand(x),
                    1.0,
                    core.separation_radius(rule),
                    tol,
                    "JKR graded medium, load-controlled: quadrature of the integral of (5.51) to F' = 0",
                )?;
                n.in_joules(MODEL, self.scales.energy)
            }
        }
    }

    /// Seed 000, eqs. (5.49)-(5.50), solved for `a_max` by Brent's method.
    fn max_contact_radius(&self, kinetic_energy: f64, tolerance: f64) -> Result<MaxContactRadius> {
        let core = self.core;
        let offset = (self.ln_delta_u0() - self.scales.energy.ln()).exp();
        self.scales
            .max_contact_radius(MODEL, kinetic_energy, tolerance, |k_hat, tol| {
                solve_energy_balance(
                    Balance {
                        work: |x| {
                            finite_output(MODEL, "kinetic energy", self.kinetic_to_reach_hat(x))
                                .map(|w| (w, Cost::ZERO))
                        },
                        slope: |x| core.work_integrand(x),
                        zero_force_radius: core.zero_force_radius(),
                        upper_guess: core.upper_guess(k_hat),
                        offset,
                    },
                    k_hat,
                    tol,
                )
            })
    }
}

//! An axisymmetric power-law indenter `f(r) = A rⁿ` with JKR adhesion.

use crate::common::{
    finite_output, loss_by_quadrature, solve_energy_balance, work_by_quadrature, Balance,
    JkrContactState, MaxContactRadius, SeparationRule,
};
use crate::impact::AdhesiveContact;
use crate::relations::{Relations, Scales};
use std::f64::consts::PI;
use tabor_numerics::special::power_law_beta;
use tabor_restitution::{validate, EnergyLoss, Error, Result};

const MODEL: &str = "JKR power-law profile";

/// A JKR contact of a power-law profile `f(r) = A rⁿ` (n > 1/2) on an elastic
/// half-space of effective modulus `E*`, work of adhesion `Δγ`, with the adhesive
/// relations of the method of dimensionality reduction (seed 000 eqs. (3.65)-(3.66),
/// quoted for (5.39)):
///
/// ```text
/// d = β(n) A aⁿ − √(2π a Δγ / E*),
/// F = 2E* [n/(n+1) β(n) A a^(n+1) − √(2π a³ Δγ / E*)],
/// β(n) = √π Γ(n/2 + 1) / Γ(n/2 + 1/2).
/// ```
///
/// `n = 2`, `A = 1/(2R)` is the [`crate::JkrSphere`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowerLawProfile {
    modulus: f64,
    exponent: f64,
    coefficient: f64,
    work_of_adhesion: f64,
    beta: f64,
    core: Relations,
    scales: Scales,
}

impl PowerLawProfile {
    /// A power-law profile with effective modulus `E*` (Pa), profile exponent `n`
    /// (> 1/2: for n ≤ 1/2 the adhesive term dominates at every size and the loss
    /// (5.39) does not exist), profile coefficient `A` (m^(1−n), > 0) and work of
    /// adhesion `Δγ` (J/m², > 0).
    ///
    /// Seed 000, eq. (5.39) and its condition n > 1/2.
    pub fn new(
        effective_modulus: f64,
        profile_exponent: f64,
        profile_coefficient: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let n = validate::in_open_interval(
            "profile_exponent",
            profile_exponent,
            0.5,
            f64::INFINITY,
            "must be finite and > 1/2 for an adhesive power-law contact (Willert 2020, (5.39))",
        )?;
        let a = validate::positive("profile_coefficient", profile_coefficient)?;
        let dg = validate::positive("work_of_adhesion", work_of_adhesion)?;
        let beta = power_law_beta(n)?;
        let core = Relations {
            p: n,
            q: 0.5,
            kappa: 1.0,
        };
        let ln_q = 0.5 * ((2.0 * PI).ln() + dg.ln() - e.ln());
        let scales = core.scales(MODEL, (2.0 * e).ln(), beta.ln() + a.ln(), ln_q)?;
        Ok(PowerLawProfile {
            modulus: e,
            exponent: n,
            coefficient: a,
            work_of_adhesion: dg,
            beta,
            core,
            scales,
        })
    }

    /// The profile exponent n.
    pub fn profile_exponent(&self) -> f64 {
        self.exponent
    }

    /// The profile factor `β(n)`, `d = β(n) A aⁿ` without adhesion
    /// (seed 000, (5.15)-(5.16), (5.39)).
    pub fn profile_factor(&self) -> f64 {
        self.beta
    }

    /// Force at contact radius `a` (m, ≥ 0):
    /// `F = 2E*[n/(n+1) β A a^(n+1) − √(2π a³ Δγ / E*)]` (N, compression positive).
    ///
    /// Seed 000, (3.66) as used for (5.39).
    pub fn force(&self, contact_radius: f64) -> Result<f64> {
        let a = validate::non_negative("contact_radius", contact_radius)?;
        let f = self.core.force(a / self.scales.contact_radius) * self.scales.force;
        finite_output(MODEL, "force", f)
    }

    /// Depth at contact radius `a` (m, ≥ 0): `d = β A aⁿ − √(2π a Δγ / E*)` (m).
    ///
    /// Seed 000, (3.65) as used for (5.39).
    pub fn depth(&self, contact_radius: f64) -> Result<f64> {
        let a = validate::non_negative("contact_radius", contact_radius)?;
        let d = self.core.depth(a / self.scales.contact_radius) * self.scales.depth;
        finite_output(MODEL, "depth", d)
    }

    /// The closed form (5.39), evaluated in logarithms:
    /// `|ΔU| = (4n−2)/(2n²+3n+1) [n + (n+1)(2n)^(4/(2n−1))] (πΔγ/2)^((2n+1)/(2n−1))
    ///  (1/(E* n² β² A²))^(2/(2n−1))`.
    fn fixed_grip_loss(&self) -> Result<f64> {
        let n = self.exponent;
        let m = 2.0 * n - 1.0;
        let t = 4.0 / m * (2.0 * n).ln();
        // ln(n + (n+1) e^t) without overflow of e^t.
        let ln_bracket = t + ((n + 1.0) + n * (-t).exp()).ln();
        let ln_loss = (2.0 * m / (2.0 * n * n + 3.0 * n + 1.0)).ln()
            + ln_bracket
            + (2.0 * n + 1.0) / m * (0.5 * PI * self.work_of_adhesion).ln()
            - 2.0 / m
                * (self.modulus.ln()
                    + 2.0 * n.ln()
                    + 2.0 * self.beta.ln()
                    + 2.0 * self.coefficient.ln());
        finite_output(MODEL, "energy loss", ln_loss.exp())
    }
}

impl AdhesiveContact for PowerLawProfile {
    fn description(&self) -> String {
        format!("JKR power-law profile (n = {})", self.exponent)
    }

    /// First touch `d = 0`: `a0 = (√(2πΔγ/E*)/(βA))^(1/(n−1/2))`.
    fn first_touch(&self) -> Result<JkrContactState> {
        Ok(self.scales.physical_state(self.core.state(1.0)))
    }

    /// Fixed grip: `dd/da = 0`, `a = a0 (1/(2n))^(2/(2n−1))`. Load-controlled:
    /// `dF/da = 0`, `a = a0 (3/(2n))^(2/(2n−1))`, which lies below first touch only
    /// for n > 3/2 (else an error naming `profile_exponent`).
    fn critical_state(&self, rule: SeparationRule) -> Result<JkrContactState> {
        let x = self.separation_radius(rule)?;
        Ok(self.scales.physical_state(self.core.state(x)))
    }

    fn energy_scale(&self) -> f64 {
        self.scales.energy
    }

    /// Fixed grip: seed 000, eq. (5.39). Load-controlled: the integral `∫ F dd` from
    /// first touch to `dF/da = 0` by quadrature (n > 3/2 required).
    fn energy_loss(&self, rule: SeparationRule, tolerance: f64) -> Result<EnergyLoss> {
        let tol = validate::tolerance("tolerance", tolerance)?;
        match rule {
            SeparationRule::FixedGrip => Ok(EnergyLoss::closed_form(
                self.fixed_grip_loss()?,
                "JKR power-law profile, fixed grip: closed form (5.39)",
            )),
            SeparationRule::LoadControlled => {
                let end = self.separation_radius(rule)?;
                let core = self.core;
                let n = loss_by_quadrature(
                    |x| core.work_integrand(x),
                    1.0,
                    end,
                    tol,
                    "JKR power-law profile, load-controlled: quadrature of the integral in (5.39) to F' = 0",
                )?;
                n.in_joules(MODEL, self.scales.energy)
            }
        }
    }

    /// The energy balance `m v0²/2 = ∫_{a0}^{a_max} F dd` as for (5.35); the seed
    /// gives no closed form for the power law, so the work is a quadrature. The
    /// residual is relative to `m v0²/2` plus the depth of the adhesive well (the work
    /// from first touch to zero force).
    fn max_contact_radius(&self, kinetic_energy: f64, tolerance: f64) -> Result<MaxContactRadius> {
        let core = self.core;
        self.scales
            .max_contact_radius(MODEL, kinetic_energy, tolerance, |k_hat, tol| {
                let integrand = |y: f64| core.work_integrand(y);
                // The depth of the adhesive well, from first touch to zero force: the
                // energy the residual is measured against (with the kinetic energy),
                // since the work passes through it on the way to a_max.
                let zero_force = core.zero_force_radius();
                let (well, mut cost) =
                    work_by_quadrature(integrand, 1.0, zero_force, 0.0, 0.1 * tol)?;
                let offset = (-well).max(f64::MIN_POSITIVE);
                let scale = k_hat + offset;
                let mut m = solve_energy_balance(
                    Balance {
                        work: |x| work_by_quadrature(integrand, 1.0, x, scale, 0.1 * tol),
                        slope: integrand,
                        zero_force_radius: zero_force,
                        upper_guess: core.upper_guess(k_hat),
                        offset,
                    },
                    k_hat,
                    tol,
                )?;
                cost += m.cost;
                m.cost = cost;
                Ok(m)
            })
    }
}

impl PowerLawProfile {
    fn separation_radius(&self, rule: SeparationRule) -> Result<f64> {
        if rule == SeparationRule::LoadControlled && self.exponent <= 1.5 {
            return Err(Error::invalid(
                "profile_exponent",
                self.exponent,
                "must be > 3/2 for load-controlled separation: for n <= 3/2 the force minimum \
                 lies at or beyond first touch",
            ));
        }
        Ok(self.core.separation_radius(rule))
    }
}

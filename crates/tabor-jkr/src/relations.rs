//! The normalized core shared by the power-law profile and the graded medium.
//!
//! Both (and the sphere) are JKR contacts of the method of dimensionality reduction
//! with contact stiffness `K a^κ`, non-adhesive depth `P a^p` and adhesive depth
//! `Q a^q`:
//!
//! ```text
//! d(a) = P a^p − Q a^q,     F(a) = K P p/(p+κ) a^(p+κ) − K Q a^(κ+q)
//! ```
//!
//! (sphere: K = 2E, κ = 1, p = 2, P = 1/R, q = 1/2; power law: p = n, P = β(n) A;
//! graded: K = 2c_N/(1+k), κ = 1+k, P = 1/((1+k)R), q = (1−k)/2). In units of the
//! first-touch radius `a0 = (Q/P)^(1/(p−q))`, the depth `D = P a0^p` and the force
//! `F* = K a0^κ D`, with `x = a/a0`:
//!
//! ```text
//! d̂(x) = x^p − x^q,          F̂(x) = c x^(p+κ) − x^(κ+q),   c = p/(p+κ)
//! ```
//!
//! First touch is x = 1; the fixed-grip point `dd̂/dx = 0` is `x^(p−q) = q/p`; the
//! load-controlled point `dF̂/dx = 0` is `x^(p−q) = (κ+q)/p`; zero force is
//! `x^(p−q) = 1/c`. Energies are in units of `F* D`.

use crate::common::{
    finite_output, positive_output, JkrContactState, MaxContactRadius, SeparationRule,
};
use tabor_restitution::{validate, Error, Result};

/// Exponents of the normalized relations (p > q required).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Relations {
    pub p: f64,
    pub q: f64,
    pub kappa: f64,
}

/// Physical scales of the normalized relations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Scales {
    /// First-touch contact radius a0 (m).
    pub contact_radius: f64,
    /// Depth scale D = P a0^p (m).
    pub depth: f64,
    /// Force scale F* = K a0^κ D (N).
    pub force: f64,
    /// Energy scale F* D (J).
    pub energy: f64,
}

impl Relations {
    /// The scales from ln K, ln P, ln Q (in logarithms, so that no intermediate power
    /// overflows).
    pub fn scales(
        &self,
        model: &'static str,
        ln_stiffness: f64,
        ln_p: f64,
        ln_q: f64,
    ) -> Result<Scales> {
        let ln_a0 = (ln_q - ln_p) / (self.p - self.q);
        let ln_d = ln_p + self.p * ln_a0;
        let ln_f = ln_stiffness + self.kappa * ln_a0 + ln_d;
        Ok(Scales {
            contact_radius: positive_output(model, "first-touch contact radius", ln_a0.exp())?,
            depth: positive_output(model, "depth scale", ln_d.exp())?,
            force: positive_output(model, "force scale", ln_f.exp())?,
            energy: positive_output(model, "energy scale", (ln_f + ln_d).exp())?,
        })
    }

    fn c(&self) -> f64 {
        self.p / (self.p + self.kappa)
    }

    pub fn depth(&self, x: f64) -> f64 {
        x.powf(self.p) - x.powf(self.q)
    }

    pub fn depth_slope(&self, x: f64) -> f64 {
        self.p * x.powf(self.p - 1.0) - self.q * x.powf(self.q - 1.0)
    }

    pub fn force(&self, x: f64) -> f64 {
        self.c() * x.powf(self.p + self.kappa) - x.powf(self.kappa + self.q)
    }

    /// `F̂ dd̂/dx`, the integrand of the work.
    pub fn work_integrand(&self, x: f64) -> f64 {
        self.force(x) * self.depth_slope(x)
    }

    /// Contact radius where the contact breaks under `rule` (x < 1 when the rule is
    /// meaningful; the caller checks).
    pub fn separation_radius(&self, rule: SeparationRule) -> f64 {
        let ratio = match rule {
            SeparationRule::FixedGrip => self.q / self.p,
            SeparationRule::LoadControlled => (self.kappa + self.q) / self.p,
        };
        ratio.powf(1.0 / (self.p - self.q))
    }

    /// Contact radius of zero force, `(1/c)^(1/(p−q))` (> 1).
    pub fn zero_force_radius(&self) -> f64 {
        (1.0 / self.c()).powf(1.0 / (self.p - self.q))
    }

    /// A first guess of the contact radius reached with normalized kinetic energy
    /// `kinetic`, from the leading term `c p x^(2p+κ)/(2p+κ)` of the work.
    pub fn upper_guess(&self, kinetic: f64) -> f64 {
        let e = 2.0 * self.p + self.kappa;
        1.2 * ((kinetic + 1.0) * e / (self.c() * self.p)).powf(1.0 / e)
    }

    /// The normalized state at `x`.
    pub fn state(&self, x: f64) -> JkrContactState {
        JkrContactState {
            contact_radius: x,
            depth: self.depth(x),
            force: self.force(x),
        }
    }
}

impl Scales {
    /// A normalized state in physical units.
    pub fn physical_state(&self, s: JkrContactState) -> JkrContactState {
        JkrContactState {
            contact_radius: s.contact_radius * self.contact_radius,
            depth: s.depth * self.depth,
            force: s.force * self.force,
        }
    }

    /// The maximum contact radius (m) reached with `kinetic_energy` (J, > 0): checks
    /// the inputs, hands the normalized kinetic energy `K̂ = K/(F* D)` and the
    /// relative `tolerance` (in [1e-15, 0.5]) to `solve`, which solves the normalized
    /// energy balance, and turns its `x_max` into meters (`a_max = x_max a0`).
    ///
    /// Seed 000, eqs. (5.35), (5.49): the prologue and epilogue every MDR contact
    /// shares; `model` names the contact in errors.
    pub fn max_contact_radius<S>(
        &self,
        model: &'static str,
        kinetic_energy: f64,
        tolerance: f64,
        solve: S,
    ) -> Result<MaxContactRadius>
    where
        S: FnOnce(f64, f64) -> Result<MaxContactRadius>,
    {
        let k = validate::positive("kinetic_energy", kinetic_energy)?;
        let tol = validate::tolerance("tolerance", tolerance)?;
        let k_hat = k / self.energy;
        if !(k_hat.is_finite() && k_hat > 0.0) {
            return Err(Error::invalid(
                "kinetic_energy",
                k,
                "is not representable in the contact's energy units",
            ));
        }
        let mut m = solve(k_hat, tol)?;
        m.contact_radius = finite_output(
            model,
            "maximum contact radius",
            m.contact_radius * self.contact_radius,
        )?;
        Ok(m)
    }
}

//! The JKR sphere in physical units: a thin shell over [`crate::normalized`].

use crate::common::{
    finite_output, positive_output, JkrContactState, MaxContactRadius, SeparationRule,
};
use crate::impact::AdhesiveContact;
use crate::normalized;
use serde::Serialize;
use std::f64::consts::PI;
use tabor_restitution::{validate, EnergyLoss, Result};

const MODEL: &str = "JKR sphere";

/// The scales of the JKR sphere: its force-controlled critical state.
///
/// Seed 000 eq. (5.43) (the normalization of [`crate::normalized`]; `tabor-maugis`
/// uses the same scales).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct JkrScales {
    /// `a_c = (9πΔγR²/(8E))^(1/3)` (m).
    pub contact_radius: f64,
    /// `F_n = (3/2)πΔγR` (N), the load-controlled pull-off force.
    pub force: f64,
    /// `d_n = a_c²/(3R)` (m).
    pub depth: f64,
    /// `F_n d_n = (3∛3/8)[R⁴(πΔγ)⁵/E²]^(1/3)` (J).
    pub energy: f64,
}

impl JkrScales {
    /// The scales for effective modulus `E*` (Pa), effective radius `R` (m) and work
    /// of adhesion `Δγ` (J/m²), all finite and > 0: `a_c = (9πΔγR²/(8E*))^(1/3)`,
    /// `F_n = (3/2)πΔγR`, `d_n = a_c²/(3R)`, `F_n d_n`.
    ///
    /// Seed 000, eq. (5.43) (the units of the force-controlled critical state of
    /// (5.33)-(5.34)). Fails when a scale under- or overflows. The JKR sphere and the
    /// Maugis-Dugdale model (`tabor-maugis`) share these scales.
    pub fn new(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        Self::for_model(
            "JKR scales",
            effective_modulus,
            effective_radius,
            work_of_adhesion,
        )
    }

    /// [`JkrScales::new`], naming `model` in the error when a scale is not
    /// representable.
    fn for_model(
        model: &'static str,
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let r = validate::positive("effective_radius", effective_radius)?;
        let dg = validate::positive("work_of_adhesion", work_of_adhesion)?;
        // a_c = (9π/8 · Δγ/E)^(1/3) R^(2/3), ordered to avoid intermediate overflow:
        // only the ratio Δγ/E and cube roots are formed, never Δγ·R/E.
        let rc = r.cbrt();
        let a_c = positive_output(
            model,
            "contact radius scale a_c",
            (9.0 * PI / 8.0 * (dg / e)).cbrt() * rc * rc,
        )?;
        let f_n = positive_output(model, "force scale F_n", 1.5 * PI * dg * r)?;
        let d_n = positive_output(model, "depth scale d_n", a_c * (a_c / (3.0 * r)))?;
        let energy = positive_output(model, "energy scale F_n d_n", f_n * d_n)?;
        Ok(JkrScales {
            contact_radius: a_c,
            force: f_n,
            depth: d_n,
            energy,
        })
    }
}

/// A parabolic JKR contact: a sphere of effective radius `R` on a half-space, effective
/// modulus `E*`, work of adhesion `Δγ`. Seed 000, eqs. (5.33)-(5.38).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JkrSphere {
    modulus: f64,
    radius: f64,
    work_of_adhesion: f64,
    scales: JkrScales,
}

impl JkrSphere {
    /// A sphere with effective modulus `E*` (Pa, `1/E* = (1−ν1²)/E1 + (1−ν2²)/E2`),
    /// effective radius `R` (m) and work of adhesion `Δγ` (J/m²), all finite and > 0.
    ///
    /// Seed 000, the parameters `Ẽ`, `R̃`, `Δγ` of (5.33)-(5.38). Fails when the
    /// scales `a_c`, `F_n`, `d_n` are not representable.
    pub fn new(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        let scales =
            JkrScales::for_model(MODEL, effective_modulus, effective_radius, work_of_adhesion)?;
        Ok(JkrSphere {
            modulus: effective_modulus,
            radius: effective_radius,
            work_of_adhesion,
            scales,
        })
    }

    /// The effective modulus `E*` (Pa).
    pub fn effective_modulus(&self) -> f64 {
        self.modulus
    }

    /// The effective radius `R` (m).
    pub fn effective_radius(&self) -> f64 {
        self.radius
    }

    /// The work of adhesion `Δγ` (J/m²).
    pub fn work_of_adhesion(&self) -> f64 {
        self.work_of_adhesion
    }

    /// The normalization scales `a_c`, `F_n`, `d_n`, `F_n d_n`.
    pub fn scales(&self) -> JkrScales {
        self.scales
    }

    /// Force at contact radius `a` (m, ≥ 0):
    /// `F = 4E*a³/(3R) − √(8πa³E*Δγ)` (N, compression positive).
    ///
    /// Seed 000, eq. (5.33).
    pub fn force(&self, contact_radius: f64) -> Result<f64> {
        let a = validate::non_negative("contact_radius", contact_radius)?;
        let f = normalized::force_hat(a / self.scales.contact_radius) * self.scales.force;
        finite_output(MODEL, "force", f)
    }

    /// Depth at contact radius `a` (m, ≥ 0): `d = a²/R − √(2πaΔγ/E*)` (m).
    ///
    /// Seed 000, eq. (5.34).
    pub fn depth(&self, contact_radius: f64) -> Result<f64> {
        let a = validate::non_negative("contact_radius", contact_radius)?;
        let d = normalized::depth_hat(a / self.scales.contact_radius) * self.scales.depth;
        finite_output(MODEL, "depth", d)
    }

    fn physical_state(&self, s: JkrContactState) -> JkrContactState {
        JkrContactState {
            contact_radius: s.contact_radius * self.scales.contact_radius,
            depth: s.depth * self.scales.depth,
            force: s.force * self.scales.force,
        }
    }
}

impl AdhesiveContact for JkrSphere {
    fn description(&self) -> String {
        "JKR sphere".into()
    }

    /// First touch: `d = 0`, `a0 = (2πΔγR²/E*)^(1/3)`, `F = −(4/3)πΔγR`.
    /// Seed 000, lower limit of (5.35)-(5.36).
    fn first_touch(&self) -> Result<JkrContactState> {
        Ok(self.physical_state(normalized::first_touch()))
    }

    /// Separation: fixed grip `F = −(5/6)πΔγR`, `d = −3^(2/3) d_n`; load-controlled
    /// `F = −(3/2)πΔγR`, `a = a_c`, `d = −d_n`. Seed 000, (5.36) and its `d_c^WS`.
    fn critical_state(&self, rule: SeparationRule) -> Result<JkrContactState> {
        Ok(self.physical_state(normalized::critical_state(rule)))
    }

    /// `F_n d_n` (J).
    fn energy_scale(&self) -> f64 {
        self.scales.energy
    }

    /// Seed 000, eq. (5.36) (fixed grip), or its integral to the load-controlled
    /// pull-off point by quadrature; [`normalized::energy_loss`] times `F_n d_n`.
    fn energy_loss(&self, rule: SeparationRule, tolerance: f64) -> Result<EnergyLoss> {
        normalized::energy_loss(rule, tolerance)?.in_joules(MODEL, self.scales.energy)
    }

    /// Seed 000, eq. (5.35); [`normalized::max_contact_radius`] in physical units.
    fn max_contact_radius(&self, kinetic_energy: f64, tolerance: f64) -> Result<MaxContactRadius> {
        self.max_contact_radius_near(kinetic_energy, tolerance, None)
    }

    /// [`normalized::max_contact_radius_near`] in physical units.
    #[inline]
    fn max_contact_radius_near(
        &self,
        kinetic_energy: f64,
        tolerance: f64,
        near: Option<f64>,
    ) -> Result<MaxContactRadius> {
        let k = validate::positive("kinetic_energy", kinetic_energy)?;
        let k_hat = positive_output(MODEL, "normalized kinetic energy", k / self.scales.energy)?;
        let near = near.map(|a| a / self.scales.contact_radius);
        let mut m = normalized::max_contact_radius_near(k_hat, tolerance, near)?;
        m.contact_radius = finite_output(
            MODEL,
            "maximum contact radius",
            m.contact_radius * self.scales.contact_radius,
        )?;
        Ok(m)
    }
}

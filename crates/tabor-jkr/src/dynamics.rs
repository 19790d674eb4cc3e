//! The JKR sphere as a time-domain force law for `tabor-dynamics`.

use crate::common::SeparationRule;
use crate::normalized;
use crate::sphere::JkrSphere;
use tabor_dynamics::{BranchChange, ForceLaw};
use tabor_restitution::{validate, Result};

/// The JKR sphere (seed 000 eqs. (5.33)-(5.34)) as a force law `F(d)` for the
/// time-domain simulator: the motion starts at first touch d = 0 already on the
/// adhesive branch (the jump-in to `a0`), loads and unloads along the stable
/// branch, and the bodies separate where the [`SeparationRule`] says (fixed grip:
/// `d = −3^(2/3) d_n`; load-controlled: `d = −d_n`, where `F = −(3/2)πΔγR`).
///
/// The contact radius at depth d is the root `x = √â ≥ 3^(−1/3)` of
/// `3x⁴ − 4x = d̂` (the stable branch), [`normalized::sqrt_contact_radius_at_depth`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JkrForceLaw {
    sphere: JkrSphere,
    rule: SeparationRule,
    separation_depth: f64,
}

impl JkrForceLaw {
    /// The force law of `sphere` with separation rule `rule`.
    pub fn new(sphere: JkrSphere, rule: SeparationRule) -> Self {
        let s = normalized::critical_state(rule);
        JkrForceLaw {
            sphere,
            rule,
            separation_depth: s.depth * sphere.scales().depth,
        }
    }

    /// The separation rule.
    pub fn separation(&self) -> SeparationRule {
        self.rule
    }

    /// The depth where the bodies separate (m, negative).
    pub fn separation_depth(&self) -> f64 {
        self.separation_depth
    }
}

impl ForceLaw for JkrForceLaw {
    fn name(&self) -> String {
        format!("JKR sphere ({})", self.rule.as_str())
    }

    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let m = validate::positive("effective_mass", effective_mass)?;
        let v = validate::positive("impact_speed", impact_speed)?;
        let e = self.sphere.effective_modulus();
        let r = self.sphere.effective_radius();
        // the larger of the adhesive depth scale and the Hertz d_max (5.8)
        let hertz = (15.0 * m * v * v / (16.0 * e * r.sqrt())).powf(0.4);
        let scale = hertz.max(self.sphere.scales().depth);
        validate::positive("overlap_scale", scale)
    }

    fn force(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        let s = self.sphere.scales();
        let x = normalized::sqrt_contact_radius_at_depth(overlap / s.depth)?;
        let a = x * x;
        Ok((a * a * a - 2.0 * a * x) * s.force)
    }

    fn contact_radius(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        let s = self.sphere.scales();
        let x = normalized::sqrt_contact_radius_at_depth(overlap / s.depth)?;
        Ok(x * x * s.contact_radius)
    }

    fn branch_end(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(overlap - self.separation_depth)
    }

    fn on_branch_end(&mut self, _overlap: f64, _overlap_rate: f64) -> Result<BranchChange> {
        Ok(BranchChange::Separate)
    }
}

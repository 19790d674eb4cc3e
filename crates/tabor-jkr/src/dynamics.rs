//! The JKR sphere as a time-domain force law for `tabor-dynamics`.

use crate::common::SeparationRule;
use crate::normalized;
use crate::sphere::JkrSphere;
use std::sync::atomic::{AtomicU64, Ordering};
use tabor_dynamics::{BranchChange, BranchCurve, CurvePoint, ForceLaw, SeparationBarrier};
use tabor_restitution::{validate, Result};

/// The JKR sphere (seed 000 eqs. (5.33)-(5.34)) as a force law `F(d)` for the
/// time-domain simulator: the motion starts at first touch d = 0 already on the
/// adhesive branch (the jump-in to `a0`), loads and unloads along the stable
/// branch, and the bodies separate where the [`SeparationRule`] says (fixed grip:
/// `d = −3^(2/3) d_n`; load-controlled: `d = −d_n`, where `F = −(3/2)πΔγR`).
///
/// The contact radius at depth d is the root `x = √â ≥ 3^(−1/3)` of
/// `3x⁴ − 4x = d̂` (the stable branch), solved by
/// [`normalized::sqrt_contact_radius_at_depth_from`] warm-started from the last
/// root the law solved (the tangent there predicts the new one), which the law keeps
/// as a hint: it changes where Newton's method starts, not its result (to the
/// solve's tolerance), and the law stays `Sync`.
#[derive(Debug)]
pub struct JkrForceLaw {
    sphere: JkrSphere,
    rule: SeparationRule,
    separation_depth: f64,
    /// `x = √â` where the bodies separate.
    separation_root: f64,
    /// The last (d̂, x) solved, as bits of `f64`s (NaN: none).
    hint: [AtomicU64; 2],
}

impl Clone for JkrForceLaw {
    fn clone(&self) -> Self {
        let mut law = JkrForceLaw::new(self.sphere, self.rule);
        law.hint = [
            AtomicU64::new(self.hint[0].load(Ordering::Relaxed)),
            AtomicU64::new(self.hint[1].load(Ordering::Relaxed)),
        ];
        law
    }
}

impl PartialEq for JkrForceLaw {
    /// The same sphere and separation rule (the hint does not count).
    fn eq(&self, other: &Self) -> bool {
        self.sphere == other.sphere && self.rule == other.rule
    }
}

impl JkrForceLaw {
    /// The force law of `sphere` with separation rule `rule`.
    pub fn new(sphere: JkrSphere, rule: SeparationRule) -> Self {
        let s = normalized::critical_state(rule);
        let nan = f64::NAN.to_bits();
        JkrForceLaw {
            sphere,
            rule,
            separation_depth: s.depth * sphere.scales().depth,
            separation_root: s.contact_radius.sqrt(),
            hint: [AtomicU64::new(nan), AtomicU64::new(nan)],
        }
    }

    /// `x = √â` at overlap `overlap` (m), warm-started from the hint: Newton's
    /// method from the tangent prediction `x + (d̂ − d̂_h)/(12x³ − 4)` of the last
    /// root.
    fn root(&self, overlap: f64) -> Result<f64> {
        let d = overlap / self.sphere.scales().depth;
        let d_last = f64::from_bits(self.hint[0].load(Ordering::Relaxed));
        let x_last = f64::from_bits(self.hint[1].load(Ordering::Relaxed));
        let guess = x_last + (d - d_last) / (12.0 * x_last * x_last * x_last - 4.0);
        let x = normalized::sqrt_contact_radius_at_depth_from(d, guess)?;
        self.hint[0].store(d.to_bits(), Ordering::Relaxed);
        self.hint[1].store(x.to_bits(), Ordering::Relaxed);
        Ok(x)
    }

    /// The separation rule.
    pub fn separation(&self) -> SeparationRule {
        self.rule
    }

    /// The depth where the bodies separate (m, negative).
    pub fn separation_depth(&self) -> f64 {
        self.separation_depth
    }

    /// Seed 000 eqs. (5.33)-(5.34): `∫ F̂ dd̂ = ∫ (x⁶ − 2x³)(12x³ − 4) dx
    /// = 1.2x¹⁰ − 4x⁷ + 2x⁴` from x = 0, in units of force times depth (J).
    fn branch_work(&self, x: f64) -> f64 {
        let x3 = x * x * x;
        let scales = self.sphere.scales();
        (1.2 * x3 * x3 - 4.0 * x3 + 2.0) * x3 * x * scales.force * scales.depth
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
        let x = self.root(overlap)?;
        let a = x * x;
        Ok((a * a * a - 2.0 * a * x) * self.sphere.scales().force)
    }

    fn contact_radius(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        let x = self.root(overlap)?;
        Ok(x * x * self.sphere.scales().contact_radius)
    }

    fn branch_end(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(overlap - self.separation_depth)
    }

    fn on_branch_end(&mut self, _overlap: f64, _overlap_rate: f64) -> Result<BranchChange> {
        Ok(BranchChange::Separate)
    }

    fn curve(&self) -> Option<&dyn BranchCurve> {
        Some(self)
    }

    /// Seed 000 eqs. (5.33)-(5.35): `W(x) − W(x_sep)` of [`BranchCurve::work`]
    /// (the stable branch is conservative), at the rule's separation depth.
    fn separation_barrier(&self, overlap: f64) -> Result<Option<SeparationBarrier>> {
        let x = self.root(overlap)?;
        Ok(Some(SeparationBarrier {
            potential: self.branch_work(x) - self.branch_work(self.separation_root),
            separation_overlap: self.separation_depth,
        }))
    }
}

impl BranchCurve for JkrForceLaw {
    /// `x = √â` at the overlap (the warm-started quartic inversion).
    fn coordinate(&self, overlap: f64) -> Result<f64> {
        self.root(overlap)
    }

    /// Seed 000 eqs. (5.33)-(5.34) in `x = √â`: `d̂ = 3x⁴ − 4x`,
    /// `dd̂/dx = 12x³ − 4`, `F̂ = x⁶ − 2x³`, `â = x²`, and the slopes
    /// `dF̂/dx = 6x⁵ − 6x²`, `dâ/dx = 2x` (polynomials, so they continue smoothly
    /// beyond the snap-off).
    fn point(&self, coordinate: f64, _overlap_rate: f64) -> Result<CurvePoint> {
        let x = coordinate;
        let x2 = x * x;
        let x3 = x2 * x;
        let scales = self.sphere.scales();
        Ok(CurvePoint {
            overlap: (3.0 * x3 - 4.0) * x * scales.depth,
            overlap_slope: (12.0 * x3 - 4.0) * scales.depth,
            force: (x3 - 2.0) * x3 * scales.force,
            contact_radius: x2 * scales.contact_radius,
            slopes: Some((
                6.0 * (x3 - 1.0) * x2 * scales.force,
                2.0 * x * scales.contact_radius,
            )),
        })
    }

    /// `x − x_sep`: falls to 0 at the separation state of the rule (for fixed
    /// grip the fold `x = 3^(−1/3)`, where `d − d_sep` would touch 0 without a
    /// sign change).
    fn end(&self, coordinate: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(coordinate - self.separation_root)
    }

    /// dd/dx at first touch, `x³ = 4/3`: `(12x³ − 4) d_n = 12 d_n`.
    fn slope_scale(&self) -> f64 {
        12.0 * self.sphere.scales().depth
    }

    /// `dd̂/dx = 12x³ − 4` grows with x from its separation value: fold-free when
    /// that is at least 3 of the 12 at first touch (load-controlled: x = 1, 8;
    /// fixed grip ends at the fold x³ = 1/3, 0).
    fn fold_free(&self) -> bool {
        12.0 * self.separation_root.powi(3) - 4.0 >= 3.0
    }

    /// Seed 000 eqs. (5.33)-(5.34): `∫ F̂ dd̂ = ∫ (x⁶ − 2x³)(12x³ − 4) dx
    /// = 1.2x¹⁰ − 4x⁷ + 2x⁴` from x = 0, in units of force times depth.
    fn work(&self, coordinate: f64) -> Option<f64> {
        Some(self.branch_work(coordinate))
    }
}

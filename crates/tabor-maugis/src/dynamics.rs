//! The Maugis-Dugdale impact as a time-domain force law for `tabor-dynamics`.

use crate::branch::contact_state;
use crate::impact::TaborCase;
use crate::impact::{impact_path, ImpactPath};
use crate::model::MaugisDugdaleImpact;
use crate::trace::{equilibrium_state_near, BranchPoint};
use crate::units::JkrScales;
use std::sync::atomic::{AtomicU64, Ordering};
use tabor_dynamics::{BranchChange, BranchCurve, CurvePoint, ForceLaw};
use tabor_numerics::Cost;
use tabor_restitution::{validate, Result};

/// The Maugis-Dugdale contact as a force law `F(d)` following the traced branch
/// (seed 000 section 5.3.2): the sphere approaches with `F = 0` from
/// `d = −(3/2)h` until the gap at the first point equals the range h
/// (`d̂ = −1/Λ`, (5.40)), jumps onto the stable equilibrium state with that depth
/// (no contact, b̂0 = 2b̂_c (5.41), in case 1), loads and unloads along the
/// equilibrium branch, and snaps off at its minimum depth (the
/// displacement-controlled instability) with the speed it has there.
///
/// The state at a depth is solved from the last one solved (Newton's method on the
/// branch from its tangent, module `trace`), which the law keeps as a hint; the
/// hint changes the start of the solve, not its result (to the solve's tolerance,
/// 1e-15 in θ), and the law stays `Sync`.
///
/// In case 3 (Λ > Λ2, contact from jump-in to snap-off) the simulator integrates
/// the contact branch in θ itself ([`BranchCurve`]): depth and force are explicit
/// there (`branch::contact_state`), so no θ is solved per force evaluation, and the
/// snap-off, the fold dd̂/dθ = 0 where F(d) has a square-root singularity, is a
/// regular point. In cases 1 and 2 the path joins the no-contact branch with a kink
/// and the law is integrated in time.
#[derive(Clone, Debug)]
pub struct MaugisDugdaleForceLaw {
    scales: JkrScales,
    path: ImpactPath,
    approaching: bool,
    hint: Hint,
}

impl PartialEq for MaugisDugdaleForceLaw {
    /// Equal laws: the same scales, path and branch (the hint does not count).
    fn eq(&self, other: &Self) -> bool {
        self.scales == other.scales
            && self.path == other.path
            && self.approaching == other.approaching
    }
}

/// The last solved contact-branch state (depth, θ, dd̂/dθ) as bits of `f64`s, NaN
/// when there is none: atomics, so that the law is `Sync`; a torn or stale value
/// only gives the solve a worse start.
#[derive(Debug)]
struct Hint([AtomicU64; 3]);

impl Hint {
    fn empty() -> Self {
        let nan = f64::NAN.to_bits();
        Hint([
            AtomicU64::new(nan),
            AtomicU64::new(nan),
            AtomicU64::new(nan),
        ])
    }

    fn get(&self) -> Option<BranchPoint> {
        let [d, t, s] = &self.0;
        let p = BranchPoint {
            depth: f64::from_bits(d.load(Ordering::Relaxed)),
            theta: f64::from_bits(t.load(Ordering::Relaxed)),
            depth_slope: f64::from_bits(s.load(Ordering::Relaxed)),
        };
        (p.depth.is_finite() && p.theta.is_finite() && p.depth_slope.is_finite()).then_some(p)
    }

    fn set(&self, p: BranchPoint) {
        let [d, t, s] = &self.0;
        d.store(p.depth.to_bits(), Ordering::Relaxed);
        t.store(p.theta.to_bits(), Ordering::Relaxed);
        s.store(p.depth_slope.to_bits(), Ordering::Relaxed);
    }
}

impl Clone for Hint {
    fn clone(&self) -> Self {
        let h = Hint::empty();
        if let Some(p) = self.get() {
            h.set(p);
        }
        h
    }
}

impl MaugisDugdaleForceLaw {
    /// The force law of a Maugis-Dugdale impact.
    pub fn new(model: &MaugisDugdaleImpact) -> Result<Self> {
        Ok(MaugisDugdaleForceLaw {
            scales: model.scales(),
            path: impact_path(model.tabor_parameter())?,
            approaching: true,
            hint: Hint::empty(),
        })
    }

    /// The range of adhesion h = d_n/Λ (m).
    pub fn range(&self) -> f64 {
        self.scales.depth / self.path.lambda
    }

    /// The depth of jump-in −h and of snap-off (m).
    pub fn jump_in_and_pull_off_depths(&self) -> (f64, f64) {
        (
            self.path.jump_in.depth * self.scales.depth,
            self.path.pull_off.depth * self.scales.depth,
        )
    }

    /// The pull-off force of the impact (N, a magnitude): the most tensile force
    /// on the equilibrium branch the impact unloads along, from the snap-off depth
    /// inwards (Maugis 1992, J. Colloid Interface Sci. 150, 243: `(3/2)π w R` as
    /// Λ → ∞ (JKR), `2π w R` as Λ → 0 (DMT)). The branch is searched over
    /// `d̂ = d̂_off + L x²`, `0 ≤ x ≤ 8` (`L = max(1/Λ, 1)`, the depth the adhesive
    /// features span), on a grid of 4096 cells refined by golden-section search
    /// to 10⁻¹⁴ in x (`tabor_numerics::minimize::grid_then_golden`; the branch
    /// has a kink where the no-contact branch meets the contact branch). Used as
    /// `F_pulloff` of the friction models' Coulomb limit by the scene's oblique
    /// impact and by the LAMMPS plugin alike.
    pub fn pull_off_force(&self) -> Result<f64> {
        let (_, pull_off) = self.jump_in_and_pull_off_depths();
        let step = (1.0 / self.path.lambda).max(1.0) * self.scales.depth;
        let force = |x: f64| -> Result<f64> {
            let d = pull_off + x * x * step;
            // exactly at the junction, rounding can leave the contact-branch root
            // unbracketed: the state a hair shallower is the same
            self.state(d)
                .or_else(|_| self.state(d - 1e-12 * step))
                .map(|s| s.force * self.scales.force)
        };
        let min = tabor_numerics::minimize::grid_then_golden(force, 0.0, 8.0, 4096, 1e-14)?;
        Ok(-min.value)
    }

    fn state(&self, overlap: f64) -> Result<crate::impact::PathState> {
        // clamp trial points beyond the snap-off to the snap-off state
        let d = (overlap / self.scales.depth).max(self.path.pull_off.depth);
        let mut cost = Cost::ZERO;
        let (state, next) = equilibrium_state_near(&self.path, d, self.hint.get(), &mut cost)?;
        if let Some(p) = next {
            self.hint.set(p);
        }
        Ok(state)
    }
}

impl ForceLaw for MaugisDugdaleForceLaw {
    fn name(&self) -> String {
        format!("Maugis-Dugdale (Lambda = {:.6e})", self.path.lambda)
    }

    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let m = validate::positive("effective_mass", effective_mass)?;
        let v = validate::positive("impact_speed", impact_speed)?;
        // R and E* from the scales: d_n = a_c²/(3R), F_n = 1.5πΔγR; the Hertz
        // d_max (5.8) needs E*√R = (9π/8)Δγ R²/a_c³ · √R
        let s = self.scales;
        let r_times_dg = s.force / (1.5 * std::f64::consts::PI);
        let r = s.contact_radius * s.contact_radius / (3.0 * s.depth);
        let dg = r_times_dg / r;
        let e = 9.0 * std::f64::consts::PI * dg * r * r / (8.0 * s.contact_radius.powi(3));
        let hertz = (15.0 * m * v * v / (16.0 * e * r.sqrt())).powf(0.4);
        let scale = hertz.max(s.depth).max(self.range());
        validate::positive("overlap_scale", scale)
    }

    fn begin_impact(&mut self, _effective_mass: f64, _impact_speed: f64) -> Result<()> {
        self.approaching = true;
        Ok(())
    }

    fn start_overlap(&self) -> f64 {
        -1.5 * self.range()
    }

    fn in_contact(&self) -> bool {
        !self.approaching
    }

    fn force(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        if self.approaching {
            return Ok(0.0);
        }
        Ok(self.state(overlap)?.force * self.scales.force)
    }

    fn contact_radius(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        if self.approaching {
            return Ok(0.0);
        }
        Ok(self.state(overlap)?.contact_radius * self.scales.contact_radius)
    }

    fn branch_end(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        let (jump_in, pull_off) = self.jump_in_and_pull_off_depths();
        Ok(if self.approaching {
            jump_in - overlap
        } else {
            overlap - pull_off
        })
    }

    fn on_branch_end(&mut self, _overlap: f64, _overlap_rate: f64) -> Result<BranchChange> {
        if self.approaching {
            self.approaching = false;
            Ok(BranchChange::Continue)
        } else {
            Ok(BranchChange::Separate)
        }
    }

    fn curve(&self) -> Option<&dyn BranchCurve> {
        (!self.approaching && self.path.case == TaborCase::Contact).then_some(self as _)
    }
}

impl BranchCurve for MaugisDugdaleForceLaw {
    /// θ of the contact-branch state at the overlap (the warm-started solve).
    fn coordinate(&self, overlap: f64) -> Result<f64> {
        let state = self.state(overlap)?;
        state.theta.ok_or_else(|| {
            tabor_restitution::Error::invalid(
                "overlap",
                overlap,
                "is not on the contact branch of the Maugis-Dugdale impact path",
            )
        })
    }

    /// The contact-branch state at θ (seed 000 section 5.3.2; `branch::contact_state`,
    /// depth, force and dd̂/dθ in closed form), in SI units.
    fn point(&self, coordinate: f64, _overlap_rate: f64) -> Result<CurvePoint> {
        let s = contact_state(self.path.lambda, coordinate);
        Ok(CurvePoint {
            overlap: s.depth * self.scales.depth,
            overlap_slope: s.depth_slope * self.scales.depth,
            force: s.force * self.scales.force,
            contact_radius: s.contact_radius * self.scales.contact_radius,
        })
    }

    /// `θ_c − θ`: θ grows as the depth falls, to the snap-off θ_c (the fold of
    /// d̂(θ), where `d − d_off` would touch 0 without a sign change).
    fn end(&self, coordinate: f64) -> f64 {
        self.path
            .pull_off
            .theta
            .unwrap_or(std::f64::consts::FRAC_PI_2)
            - coordinate
    }
}

//! The elastic adhesive laws inside the model's viscous wrapper: `tabor-jkr`'s
//! [`JkrForceLaw`] and `tabor-maugis`' [`MaugisDugdaleForceLaw`], each with its
//! potential relative to separation ([`SeparationPotential`]), and the JKR
//! contact radius solved once per overlap (force and radius share it) with a warm
//! start.

use crate::law::SeparationPotential;
use std::cell::Cell;
use std::sync::Arc;
use tabor_dynamics::{BranchChange, BranchCurve, ForceLaw, SeparationBarrier};
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};
use tabor_maugis::MaugisDugdaleForceLaw;
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_restitution::{Error, Result};

/// `x_c = 3^(−1/3)`: the fixed-grip instability in `x = √â` (`dd̂/dx = 0`).
const X_MIN: f64 = 0.693_361_274_350_634_8;

/// The JKR sphere on its stable branch: every hook is `tabor-jkr`'s
/// [`JkrForceLaw`]; force and contact radius come from the root `x = √â ≥ 3^(−1/3)`
/// of `3x⁴ − 4x = d̂` (seed 000 eq. (5.34) normalized), solved once per overlap
/// and warm-started from the previous root (`F̂ = x⁶ − 2x³`, (5.33)).
#[derive(Clone, Debug)]
struct JkrBranch {
    law: JkrForceLaw,
    contact_radius_unit: f64,
    force_unit: f64,
    depth_unit: f64,
    energy_unit: f64,
    /// P(â_sep) of [`jkr_potential`].
    separation_potential: f64,
    /// (d̂, x) of the last solve.
    last: Cell<(f64, f64)>,
}

impl PartialEq for JkrBranch {
    fn eq(&self, other: &Self) -> bool {
        self.law == other.law
    }
}

/// `P(â) = (6/5)â⁵ − 4â^(7/2) + 2â²`: `dP/dâ = F̂ dd̂/dâ`, so `F_n d_n [P(â) − P(â')]`
/// is `∫ F dd` along the stable branch. Seed 000 eq. (5.35) without its constant.
fn jkr_potential(x: f64) -> f64 {
    let a = x * x;
    let a2 = a * a;
    1.2 * a2 * a2 * a - 4.0 * a2 * a * x + 2.0 * a2
}

impl JkrBranch {
    fn new(sphere: &JkrSphere, rule: SeparationRule) -> Self {
        let s = sphere.scales();
        let x_sep = match rule {
            SeparationRule::FixedGrip => X_MIN,
            SeparationRule::LoadControlled => 1.0,
        };
        JkrBranch {
            law: JkrForceLaw::new(*sphere, rule),
            contact_radius_unit: s.contact_radius,
            force_unit: s.force,
            depth_unit: s.depth,
            energy_unit: s.energy,
            separation_potential: jkr_potential(x_sep),
            last: Cell::new((f64::NAN, f64::NAN)),
        }
    }

    /// `x = √â` at overlap d (clamped to the fixed-grip instability below it).
    fn root(&self, overlap: f64) -> Result<f64> {
        let d = overlap / self.depth_unit;
        let (d_last, x_last) = self.last.get();
        if d == d_last {
            return Ok(x_last);
        }
        let x = tabor_jkr::normalized::sqrt_contact_radius_at_depth_from(d, x_last)?;
        self.last.set((d, x));
        Ok(x)
    }
}

/// A table of the Maugis-Dugdale potential `U(d) − U(d_pull-off)` along the
/// equilibrium branch, from the snap-off depth to beyond the depth where it is 0
/// again, by Gauss-Legendre panels in `s = √((d − d_po)/span)` (the force has a
/// square-root singularity at the snap-off, smooth in s) and cubic Hermite
/// interpolation (dU/ds = F dd/ds).
#[derive(Debug, PartialEq)]
pub(crate) struct PotentialTable {
    pull_off: f64,
    span: f64,
    /// U at the nodes s_i = i/n (J).
    values: Vec<f64>,
    /// dU/ds at the nodes (J).
    slopes: Vec<f64>,
    /// F at the table's upper end (N, > 0).
    end_force: f64,
}

const TABLE_PANELS: usize = 512;

impl PotentialTable {
    fn build(law: &MaugisDugdaleForceLaw, depth_unit: f64) -> Result<Self> {
        // the law on its contact branch (after jump-in)
        let mut on_branch = law.clone();
        on_branch.begin_impact(1.0, 1.0)?;
        let (jump_in, pull_off) = law.jump_in_and_pull_off_depths();
        if on_branch.on_branch_end(jump_in, 1.0)? != BranchChange::Continue {
            return Err(Error::Model {
                model: "Maugis-Dugdale potential",
                message: "the law does not continue after jump-in".into(),
            });
        }
        let force = |d: f64| on_branch.force(d, 0.0);
        let mut span = 4.0 * (jump_in - pull_off).max(depth_unit);
        for _ in 0..60 {
            let n = TABLE_PANELS;
            let h = 1.0 / n as f64;
            let slope =
                |s: f64| -> Result<f64> { Ok(force(pull_off + span * s * s)? * 2.0 * span * s) };
            let mut values = Vec::with_capacity(n + 1);
            let mut slopes = Vec::with_capacity(n + 1);
            values.push(0.0);
            slopes.push(slope(0.0)?);
            // 3-point Gauss-Legendre per panel
            let g = (0.6f64).sqrt() * 0.5;
            for i in 0..n {
                let s0 = i as f64 * h;
                let mid = s0 + 0.5 * h;
                let panel = h / 18.0
                    * (5.0 * slope(mid - g * h)? + 8.0 * slope(mid)? + 5.0 * slope(mid + g * h)?);
                let last = values[i];
                values.push(last + panel);
                slopes.push(slope(s0 + h)?);
            }
            let end_force = force(pull_off + span)?;
            if values[n] > 0.0 && end_force > 0.0 {
                return Ok(PotentialTable {
                    pull_off,
                    span,
                    values,
                    slopes,
                    end_force,
                });
            }
            span *= 2.0;
        }
        Err(Error::Model {
            model: "Maugis-Dugdale potential",
            message: "the potential does not return to 0 along the branch".into(),
        })
    }

    /// `U(d) − U(d_po)` (J); beyond the table the lower bound
    /// `U_end + F_end (d − d_end)` (> 0; F grows along the branch), which is all
    /// the sticking criterion needs there.
    fn eval(&self, overlap: f64) -> f64 {
        let n = TABLE_PANELS;
        let rel = (overlap - self.pull_off) / self.span;
        if rel.is_nan() || rel <= 0.0 {
            return 0.0;
        }
        if rel >= 1.0 {
            return self.values[n] + self.end_force * (overlap - self.pull_off - self.span);
        }
        let s = rel.sqrt() * n as f64;
        let i = (s.floor() as usize).min(n - 1);
        let t = s - i as f64;
        let h = 1.0 / n as f64;
        let (t2, t3) = (t * t, t * t * t);
        (2.0 * t3 - 3.0 * t2 + 1.0) * self.values[i]
            + (t3 - 2.0 * t2 + t) * h * self.slopes[i]
            + (-2.0 * t3 + 3.0 * t2) * self.values[i + 1]
            + (t3 - t2) * h * self.slopes[i + 1]
    }
}

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    Jkr(JkrBranch),
    MaugisDugdale(MaugisDugdaleForceLaw, Arc<PotentialTable>),
}

/// The elastic adhesive force law inside the model's [`crate::ViscousDamping`]:
/// the JKR sphere (seed 000 eqs. (5.33)-(5.34), every hook from `tabor-jkr`'s
/// [`JkrForceLaw`]) or the Maugis-Dugdale sphere (`tabor-maugis`'
/// [`MaugisDugdaleForceLaw`], seed 000 section 5.3.2), with its potential relative
/// to separation ([`SeparationPotential`], README eq. (V4)).
#[derive(Clone, Debug, PartialEq)]
pub struct AdhesiveForceLaw {
    kind: Kind,
}

impl AdhesiveForceLaw {
    /// The JKR law of `sphere` with separation rule `rule`.
    pub fn jkr(sphere: &JkrSphere, rule: SeparationRule) -> Self {
        LawSpec::Jkr(*sphere, rule).build()
    }

    /// The Maugis-Dugdale law `law` whose depth scale is `d_n` (m); tabulates its
    /// potential along the equilibrium branch (about 500 force evaluations).
    pub fn maugis_dugdale(law: MaugisDugdaleForceLaw, depth_unit: f64) -> Result<Self> {
        Ok(LawSpec::maugis_dugdale(law, depth_unit)?.build())
    }
}

/// What an [`AdhesiveForceLaw`] is built from, without its per-simulation cache
/// (so that a model holding it is `Sync`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum LawSpec {
    Jkr(JkrSphere, SeparationRule),
    MaugisDugdale(MaugisDugdaleForceLaw, Arc<PotentialTable>),
}

impl LawSpec {
    pub(crate) fn maugis_dugdale(law: MaugisDugdaleForceLaw, depth_unit: f64) -> Result<Self> {
        let table = PotentialTable::build(&law, depth_unit)?;
        Ok(LawSpec::MaugisDugdale(law, Arc::new(table)))
    }

    pub(crate) fn build(&self) -> AdhesiveForceLaw {
        AdhesiveForceLaw {
            kind: match self {
                LawSpec::Jkr(sphere, rule) => Kind::Jkr(JkrBranch::new(sphere, *rule)),
                LawSpec::MaugisDugdale(l, t) => Kind::MaugisDugdale(l.clone(), Arc::clone(t)),
            },
        }
    }
}

macro_rules! delegate {
    ($self:ident, $l:ident => $e:expr) => {
        match &$self.kind {
            Kind::Jkr(j) => {
                let $l = &j.law;
                $e
            }
            Kind::MaugisDugdale($l, _) => $e,
        }
    };
}

macro_rules! delegate_mut {
    ($self:ident, $l:ident => $e:expr) => {
        match &mut $self.kind {
            Kind::Jkr(j) => {
                let $l = &mut j.law;
                $e
            }
            Kind::MaugisDugdale($l, _) => $e,
        }
    };
}

impl ForceLaw for AdhesiveForceLaw {
    fn name(&self) -> String {
        delegate!(self, l => l.name())
    }
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        delegate!(self, l => l.overlap_scale(effective_mass, impact_speed))
    }
    fn begin_impact(&mut self, effective_mass: f64, impact_speed: f64) -> Result<()> {
        delegate_mut!(self, l => l.begin_impact(effective_mass, impact_speed))
    }
    fn start_overlap(&self) -> f64 {
        delegate!(self, l => l.start_overlap())
    }
    fn in_contact(&self) -> bool {
        delegate!(self, l => l.in_contact())
    }
    /// JKR: `F = F_n (x⁶ − 2x³)`, seed 000 eq. (5.33); Maugis-Dugdale: the law's.
    fn force(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        match &self.kind {
            Kind::Jkr(j) => {
                let x = j.root(overlap)?;
                let x3 = x * x * x;
                Ok((x3 * x3 - 2.0 * x3) * j.force_unit)
            }
            Kind::MaugisDugdale(l, _) => l.force(overlap, overlap_rate),
        }
    }
    /// JKR: `a = a_c x²`, seed 000 eq. (5.34); Maugis-Dugdale: the law's.
    fn contact_radius(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        match &self.kind {
            Kind::Jkr(j) => {
                let x = j.root(overlap)?;
                Ok(x * x * j.contact_radius_unit)
            }
            Kind::MaugisDugdale(l, _) => l.contact_radius(overlap, overlap_rate),
        }
    }
    /// JKR: `F_n d_n [P(â) − P(â_sep)]` (seed 000 eq. (5.35)) with the rule's
    /// separation depth; Maugis-Dugdale: the tabulated `∫_{d_po}^{d} F dd'` with
    /// the pull-off depth d_po; `None` before the Maugis-Dugdale jump-in.
    fn separation_barrier(&self, overlap: f64) -> Result<Option<SeparationBarrier>> {
        match &self.kind {
            Kind::Jkr(j) => {
                let x = j.root(overlap)?;
                Ok(Some(SeparationBarrier {
                    potential: (jkr_potential(x) - j.separation_potential) * j.energy_unit,
                    separation_overlap: j.law.separation_depth(),
                }))
            }
            Kind::MaugisDugdale(l, table) => Ok(l.in_contact().then(|| SeparationBarrier {
                potential: table.eval(overlap),
                separation_overlap: table.pull_off,
            })),
        }
    }
    fn branch_end(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        delegate!(self, l => l.branch_end(overlap, overlap_rate))
    }
    fn on_branch_end(&mut self, overlap: f64, overlap_rate: f64) -> Result<BranchChange> {
        delegate_mut!(self, l => l.on_branch_end(overlap, overlap_rate))
    }
    fn on_max_compression(&mut self, overlap: f64) -> Result<BranchChange> {
        delegate_mut!(self, l => l.on_max_compression(overlap))
    }
    fn on_min_compression(&mut self, overlap: f64) -> Result<BranchChange> {
        delegate_mut!(self, l => l.on_min_compression(overlap))
    }
    fn on_curve_end(
        &mut self,
        coordinate: f64,
        overlap: f64,
        overlap_rate: f64,
    ) -> Result<BranchChange> {
        delegate_mut!(self, l => l.on_curve_end(coordinate, overlap, overlap_rate))
    }
    /// The inner law's: JKR in `x = √â`, Maugis-Dugdale in θ (contact) and b̂
    /// (no contact).
    fn curve(&self) -> Option<&dyn BranchCurve> {
        delegate!(self, l => l.curve())
    }
}

impl SeparationPotential for AdhesiveForceLaw {
    /// JKR: `F_n d_n [P(â_sep) − P(4^(1/3))]` (the zero-force radius);
    /// Maugis-Dugdale: `−min U` of the table.
    fn well_depth(&self) -> Option<f64> {
        Some(match &self.kind {
            Kind::Jkr(j) => {
                let x_eq = 4f64.cbrt().sqrt();
                (j.separation_potential - jkr_potential(x_eq)) * j.energy_unit
            }
            Kind::MaugisDugdale(_, table) => -table.values.iter().copied().fold(0.0, f64::min),
        })
    }

    /// JKR: `d_eq = 2^(4/3) d_n` (F̂ = x⁶ − 2x³ = 0 at x³ = 2, d̂ = 3x⁴ − 4x, seed 000
    /// eqs. (5.33), (5.34)); Maugis-Dugdale: the root of F on the contact branch
    /// between the pull-off depth (tensile) and `upper` (compressive), by Brent.
    fn equilibrium_overlap(&self, upper: f64) -> Result<Option<f64>> {
        match &self.kind {
            Kind::Jkr(j) => Ok(Some(2f64.powf(4.0 / 3.0) * j.depth_unit)),
            Kind::MaugisDugdale(l, table) => {
                let compressive = l.force(upper, 0.0)? > 0.0;
                if !l.in_contact() || !compressive || upper <= table.pull_off {
                    return Ok(None);
                }
                let mut failure = None;
                let f = |d: f64| match l.force(d, 0.0) {
                    Ok(f) => f,
                    Err(e) => {
                        failure.get_or_insert(e);
                        f64::NAN
                    }
                };
                let root = brent(
                    f,
                    table.pull_off,
                    upper,
                    RootTolerance::absolute(1e-12 * upper.abs().max(table.span)),
                );
                if let Some(e) = failure {
                    return Err(e);
                }
                Ok(Some(root?.value))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use tabor_maugis::{MaugisContact, MaugisDugdaleImpact};
    use tabor_restitution::ImpactModel;

    const E: f64 = 2.78e10;
    const R: f64 = 0.5e-6;
    const DG: f64 = 0.05;

    #[test]
    fn the_cached_jkr_branch_equals_tabor_jkr_force_law() {
        let sphere = JkrSphere::new(E, R, DG).unwrap();
        for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
            let ours = AdhesiveForceLaw::jkr(&sphere, rule);
            let theirs = JkrForceLaw::new(sphere, rule);
            let d_n = sphere.scales().depth;
            // a warm-started sequence up and down the branch, and cold jumps
            let mut depths: Vec<f64> = (0..200).map(|i| d_n * (-2.2 + 0.05 * i as f64)).collect();
            depths.extend([1e4 * d_n, -d_n, 1e-3 * d_n, -2.0800838 * d_n, 1e8 * d_n]);
            for d in depths {
                let (f1, f2) = (ours.force(d, 0.0).unwrap(), theirs.force(d, 0.0).unwrap());
                let (a1, a2) = (
                    ours.contact_radius(d, 0.0).unwrap(),
                    theirs.contact_radius(d, 0.0).unwrap(),
                );
                let fs = sphere.scales().force;
                assert!(
                    (f1 - f2).abs() <= 1e-12 * fs.max(f2.abs()),
                    "F at {d:e}: {f1} vs {f2}"
                );
                assert!((a1 - a2).abs() <= 1e-12 * a2, "a at {d:e}: {a1} vs {a2}");
            }
        }
    }

    #[test]
    fn the_jkr_potential_at_first_touch_is_minus_the_adhesive_loss() {
        // U(0) − U(d_sep) = −|ΔU| of (5.36) (fixed grip) / its quadrature (load control)
        let sphere = JkrSphere::new(E, R, DG).unwrap();
        for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
            let law = AdhesiveForceLaw::jkr(&sphere, rule);
            let u = law.separation_barrier(0.0).unwrap().unwrap().potential;
            let loss = tabor_jkr::JkrImpact::new(sphere, 1e-15)
                .unwrap()
                .with_separation(rule)
                .energy_loss(1.0)
                .unwrap()
                .joules;
            assert!((u + loss).abs() <= 1e-12 * loss, "{rule}: {u} vs {loss}");
        }
    }

    #[test]
    fn the_maugis_dugdale_table_gives_minus_the_adhesive_loss_at_jump_in() {
        for lambda in [0.2, 0.3, 0.5, 0.6, 1.0, 3.0] {
            let md = MaugisDugdaleImpact::new(
                MaugisContact::new(JkrSphere::new(E, R, DG).unwrap(), lambda).unwrap(),
                1e-15,
            )
            .unwrap();
            let law = MaugisDugdaleForceLaw::new(&md).unwrap();
            let (jump_in, _) = law.jump_in_and_pull_off_depths();
            let table = PotentialTable::build(&law, md.scales().depth).unwrap();
            let loss = md.energy_loss_joules().unwrap();
            let u = table.eval(jump_in);
            println!("Lambda {lambda}: {:e}", (u + loss) / loss);
            assert!(
                (u + loss).abs() <= 1e-7 * loss,
                "Lambda {lambda}: {u} vs {loss}"
            );
        }
    }

    #[test]
    fn equilibrium_overlaps_are_where_the_force_vanishes() {
        // JKR: the closed form 2^(4/3) d_n against (5.33)/(5.34) in SI,
        // a_eq³ = 9πΔγR²/(2E*), d_eq = a²/R − √(2πΔγ a/E*); Maugis-Dugdale: the
        // law's force is 0 there, and the potential table is at its minimum.
        let sphere = JkrSphere::new(E, R, DG).unwrap();
        let law = AdhesiveForceLaw::jkr(&sphere, SeparationRule::FixedGrip);
        let d_eq = law.equilibrium_overlap(1.0).unwrap().unwrap();
        let a = (9.0 * std::f64::consts::PI * DG * R * R / (2.0 * E)).cbrt();
        let reference = a * a / R - (2.0 * std::f64::consts::PI * DG * a / E).sqrt();
        assert!(
            (d_eq / reference - 1.0).abs() < 1e-12,
            "{d_eq} vs {reference}"
        );
        assert!(law.force(d_eq, 0.0).unwrap().abs() < 1e-12 * sphere.scales().force);
        for lambda in [0.3, 1.0, 3.0] {
            let md = MaugisDugdaleImpact::new(
                MaugisContact::new(JkrSphere::new(E, R, DG).unwrap(), lambda).unwrap(),
                1e-12,
            )
            .unwrap();
            let f = MaugisDugdaleForceLaw::new(&md).unwrap();
            let mut law = AdhesiveForceLaw::maugis_dugdale(f.clone(), md.scales().depth).unwrap();
            let d_n = md.scales().depth;
            // on the contact branch after jump-in
            law.begin_impact(1.0, 1.0).unwrap();
            let (jump_in, _) = f.jump_in_and_pull_off_depths();
            assert_eq!(
                law.on_branch_end(jump_in, 1.0).unwrap(),
                BranchChange::Continue
            );
            let d_eq = law.equilibrium_overlap(10.0 * d_n).unwrap().unwrap();
            let force = law.force(d_eq, 0.0).unwrap();
            println!("Lambda {lambda}: d_eq {:.6} d_n, F {force:e}", d_eq / d_n);
            assert!(
                force.abs() < 1e-9 * md.scales().force,
                "Lambda {lambda}: {force}"
            );
        }
    }
}

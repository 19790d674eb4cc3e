#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Toy laws that exercise what the adhesive and plastic laws will need: history
//! (a branch chosen at the turning point), an approach phase, jump-in, snap-off at
//! a negative overlap, and sticking. Each has an exact solution (piecewise
//! harmonic motion) to compare with.

use std::f64::consts::PI;
use tabor_dynamics::{
    simulate_impact, BranchChange, BranchCurve, CurvePoint, EventKind, ForceLaw, SimulatedImpact,
    SimulationSettings,
};
use tabor_restitution::{impact, Error, Result};

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Stiff linear loading `F = k_load d`, then (chosen at the turning point) softer...
/// here *stiffer* elastic unloading `F = k_unload (d − d_res)` with the residual
/// depth d_res that keeps F continuous, separation where F = 0: a plastic-like law.
/// Exact: ε² = k_load/k_unload, T = (π/2)(√(m/k_load) + √(m/k_unload)).
#[derive(Clone, Debug)]
struct Hysteretic {
    k_load: f64,
    k_unload: f64,
    residual_depth: Option<f64>,
}

impl ForceLaw for Hysteretic {
    fn name(&self) -> String {
        "toy hysteretic".into()
    }
    fn overlap_scale(&self, m: f64, v0: f64) -> Result<f64> {
        Ok(v0 * (m / self.k_load).sqrt())
    }
    fn begin_impact(&mut self, _m: f64, _v0: f64) -> Result<()> {
        self.residual_depth = None;
        Ok(())
    }
    fn force(&self, d: f64, _r: f64) -> Result<f64> {
        Ok(match self.residual_depth {
            None => self.k_load * d.max(0.0),
            // Extended linearly beyond F = 0 (trial points may go there).
            Some(d_res) => self.k_unload * (d - d_res),
        })
    }
    fn contact_radius(&self, _d: f64, _r: f64) -> Result<f64> {
        Ok(0.0)
    }
    fn branch_end(&self, d: f64, r: f64) -> Result<f64> {
        // Loading: separation at d = 0 (not reached); unloading: F = 0.
        match self.residual_depth {
            None => Ok(d),
            Some(_) => self.force(d, r),
        }
    }
    fn on_max_compression(&mut self, d: f64) -> Result<BranchChange> {
        self.residual_depth = Some(d * (1.0 - self.k_load / self.k_unload));
        Ok(BranchChange::Continue)
    }
}

#[test]
fn hysteretic_law_uses_history_and_matches_the_exact_solution() {
    // Tolerances: restitution, contact time and residual depth 1e-9 relative;
    // energy bookkeeping 1e-9.
    for &(k_load, k_unload, m, v0) in &[(1e4, 4e4, 1e-3, 1.0), (3e7, 3.1e7, 2e-9, 1e-2)] {
        let mut law = Hysteretic {
            k_load,
            k_unload,
            residual_depth: None,
        };
        let sim = simulate_impact(&mut law, m, v0, &SimulationSettings::default()).unwrap();
        let eps = (k_load / k_unload).sqrt();
        assert!(
            rel(sim.restitution, eps) < 1e-9,
            "{} vs {eps}",
            sim.restitution
        );
        let t = 0.5 * PI * ((m / k_load).sqrt() + (m / k_unload).sqrt());
        assert!(rel(sim.contact_time.unwrap(), t) < 1e-9);
        let d_max = v0 * (m / k_load).sqrt();
        assert!(rel(sim.max_overlap, d_max) < 1e-9);
        assert!(
            rel(
                law.residual_depth.unwrap(),
                d_max * (1.0 - k_load / k_unload)
            ) < 1e-9
        );
        assert!(rel(sim.energy_loss, 0.5 * m * v0 * v0 * (1.0 - eps * eps)) < 1e-9);
        assert!(sim.energy_error < 1e-9, "{}", sim.energy_error);
        let kinds: Vec<_> = sim.events.iter().map(|e| e.kind).collect();
        assert_eq!(kinds, [EventKind::MaxCompression, EventKind::BranchEnd]);
        assert_eq!(sim.events[1].decision, BranchChange::Separate);
        // Running again resets the history (begin_impact).
        let again = simulate_impact(&mut law, m, v0, &SimulationSettings::default()).unwrap();
        assert_eq!(again.restitution, sim.restitution);
        // The same law as an ImpactModel gives (5.37) the same restitution.
        let model = SimulatedImpact::new(law.clone(), m, SimulationSettings::default()).unwrap();
        let out = impact(&model, v0).unwrap();
        assert!(rel(out.restitution, eps) < 1e-9);
    }
}

/// A Maugis-Dugdale-like toy: free approach from `start` (< −h) with F = 0; at
/// d = −h the body jumps onto the contact branch `F = k (d + h) − F_a` (an
/// attractive jump); snap-off at `d_off` < −h. With x = d + h and s = d_off + h:
/// ε² = 1 − (k s² + 2 F_a |s|)/(m v0²); the body sticks when the rebound turns
/// inward before reaching s.
#[derive(Clone, Debug)]
struct JumpInSnapOff {
    stiffness: f64,
    range: f64,
    adhesive_force: f64,
    snap_off: f64,
    start: f64,
    touching: bool,
}

impl ForceLaw for JumpInSnapOff {
    fn name(&self) -> String {
        "toy jump-in/snap-off".into()
    }
    fn overlap_scale(&self, m: f64, v0: f64) -> Result<f64> {
        Ok(self.range.max(v0 * (m / self.stiffness).sqrt()))
    }
    fn begin_impact(&mut self, _m: f64, _v0: f64) -> Result<()> {
        self.touching = false;
        Ok(())
    }
    fn start_overlap(&self) -> f64 {
        self.start
    }
    fn in_contact(&self) -> bool {
        self.touching
    }
    fn force(&self, d: f64, _r: f64) -> Result<f64> {
        if !d.is_finite() {
            return Err(Error::invalid("overlap", d, "must be finite"));
        }
        Ok(if self.touching {
            self.stiffness * (d + self.range) - self.adhesive_force
        } else {
            0.0
        })
    }
    fn contact_radius(&self, _d: f64, _r: f64) -> Result<f64> {
        Ok(0.0)
    }
    fn branch_end(&self, d: f64, _r: f64) -> Result<f64> {
        Ok(if self.touching {
            d - self.snap_off
        } else {
            -self.range - d
        })
    }
    fn on_branch_end(&mut self, _d: f64, _r: f64) -> Result<BranchChange> {
        if self.touching {
            Ok(BranchChange::Separate)
        } else {
            self.touching = true;
            Ok(BranchChange::Continue)
        }
    }
}

/// Exact time from jump-in to snap-off, or `None` when the body sticks.
fn exact_contact_time(law: &JumpInSnapOff, m: f64, v0: f64) -> Option<f64> {
    let omega = (law.stiffness / m).sqrt();
    let x_e = law.adhesive_force / law.stiffness;
    let s = law.snap_off + law.range;
    let amp = (x_e * x_e + (v0 / omega).powi(2)).sqrt();
    if x_e - amp > s {
        return None;
    }
    let alpha = x_e.atan2(v0 / omega);
    Some((alpha + PI - ((s - x_e) / amp).asin()) / omega)
}

#[test]
fn approach_jump_in_and_snap_off() {
    // Tolerances: restitution, contact time and onset 1e-9 relative.
    let (m, k) = (1e-12, 50.0);
    let mut law = JumpInSnapOff {
        stiffness: k,
        range: 1e-9,
        adhesive_force: 2e-8,
        snap_off: -1.5e-9,
        start: -3e-9,
        touching: false,
    };
    let s: f64 = law.snap_off + law.range;
    let loss = k * s * s + 2.0 * law.adhesive_force * s.abs();
    let v_c = (loss / m).sqrt();
    for &v0 in &[3.0 * v_c, 1.2 * v_c, 1.01 * v_c] {
        let sim = simulate_impact(&mut law, m, v0, &SimulationSettings::default()).unwrap();
        let eps = (1.0 - loss / (m * v0 * v0)).sqrt();
        assert!(!sim.sticks);
        assert!(
            rel(sim.restitution, eps) < 1e-9,
            "{v0}: {} vs {eps}",
            sim.restitution
        );
        let onset = (-law.range - law.start) / v0;
        assert!(rel(sim.contact_onset_time, onset) < 1e-9);
        let t = exact_contact_time(&law, m, v0).unwrap();
        assert!(rel(sim.contact_time.unwrap(), t) < 1e-9, "{v0}");
        let kinds: Vec<_> = sim.events.iter().map(|e| e.kind).collect();
        assert_eq!(
            kinds,
            [
                EventKind::BranchEnd,
                EventKind::MaxCompression,
                EventKind::BranchEnd
            ]
        );
        assert!(sim.energy_error < 1e-9);
        // The force jumps at jump-in: the record holds −F_a right after it.
        let jump = sim
            .trajectory
            .iter()
            .find(|p| p.time >= sim.contact_onset_time && p.force != 0.0)
            .unwrap();
        assert!(rel(jump.force, -law.adhesive_force) < 1e-6);
    }
    // Below the sticking velocity the body turns inward again before snap-off:
    // the default on_min_compression says Stick.
    for &v0 in &[0.99 * v_c, 0.1 * v_c] {
        assert!(exact_contact_time(&law, m, v0).is_none());
        let sim = simulate_impact(&mut law, m, v0, &SimulationSettings::default()).unwrap();
        assert!(sim.sticks);
        assert_eq!(sim.restitution, 0.0);
        assert_eq!(sim.contact_time, None);
        assert_eq!(sim.events.last().unwrap().kind, EventKind::MinCompression);
        assert_eq!(sim.energy_loss, sim.kinetic_energy);
    }
}

/// A toy law of one branch, the force `force(d)` (N), that misbehaves: its
/// `on_branch_end` answers `at_branch_end` (the default `Separate`, or
/// `Continue` without leaving the branch).
#[derive(Clone, Debug)]
struct Toy {
    name: &'static str,
    force: fn(f64) -> Result<f64>,
    at_branch_end: BranchChange,
}

impl ForceLaw for Toy {
    fn name(&self) -> String {
        self.name.into()
    }
    fn overlap_scale(&self, _m: f64, _v0: f64) -> Result<f64> {
        Ok(1.0)
    }
    fn force(&self, d: f64, _r: f64) -> Result<f64> {
        (self.force)(d)
    }
    fn contact_radius(&self, _d: f64, _r: f64) -> Result<f64> {
        Ok(0.0)
    }
    fn on_branch_end(&mut self, _d: f64, _r: f64) -> Result<BranchChange> {
        Ok(self.at_branch_end)
    }
}

/// A law whose `on_branch_end` says Continue without leaving the branch is
/// reported, not looped on.
const STUCK: Toy = Toy {
    name: "stuck",
    force: |d| Ok(d.max(0.0)),
    at_branch_end: BranchChange::Continue,
};

/// A law whose force fails: the error comes back unchanged.
const FAILING: Toy = Toy {
    name: "failing",
    force: |d| {
        if d > 0.5 {
            Err(Error::invalid("overlap", d, "beyond the toy's range"))
        } else {
            Ok(d.max(0.0))
        }
    },
    at_branch_end: BranchChange::Separate,
};

#[test]
fn misbehaving_laws_give_errors() {
    let s = SimulationSettings::default();
    let (mut stuck, mut failing) = (STUCK, FAILING);
    let err = simulate_impact(&mut stuck, 1.0, 1.0, &s).unwrap_err();
    assert!(matches!(err, Error::Model { .. }), "{err:?}");
    let err = simulate_impact(&mut failing, 1.0, 1.0, &s).unwrap_err();
    assert!(
        matches!(
            err,
            Error::InvalidParameter {
                parameter: "overlap",
                ..
            }
        ),
        "{err:?}"
    );
}

/// A branch with a fold at its end: `d = d_c + q²` (q ≥ 0), `F = k q`, so that
/// `F(d) = k √(d − d_c)` has a square-root singularity where the bodies separate
/// (q = 0, d = d_c < 0), as JKR's fixed-grip snap-off has. With `curve` the law
/// offers its coordinate q ([`BranchCurve`]); without, it is integrated in time
/// with the same `F(d)`. Exact (conservative): the speed at the fold from
/// `v² = v0² + (4k/3m) q0³` with `q0 = √(−d_c)`, the turning point from
/// `(2k/3)(q_max³ − q0³) = m v0²/2`.
#[derive(Clone, Debug)]
struct Folded {
    fold_depth: f64,
    stiffness: f64,
    curve: bool,
}

impl ForceLaw for Folded {
    fn name(&self) -> String {
        "toy fold".into()
    }
    fn overlap_scale(&self, _m: f64, _v0: f64) -> Result<f64> {
        Ok(-self.fold_depth)
    }
    fn force(&self, d: f64, _r: f64) -> Result<f64> {
        Ok(self.stiffness * (d - self.fold_depth).max(0.0).sqrt())
    }
    fn contact_radius(&self, d: f64, _r: f64) -> Result<f64> {
        Ok((d - self.fold_depth).max(0.0).sqrt())
    }
    fn branch_end(&self, d: f64, _r: f64) -> Result<f64> {
        Ok(d - self.fold_depth)
    }
    fn curve(&self) -> Option<&dyn BranchCurve> {
        self.curve.then_some(self as _)
    }
}

impl BranchCurve for Folded {
    fn coordinate(&self, overlap: f64) -> Result<f64> {
        Ok((overlap - self.fold_depth).max(0.0).sqrt())
    }
    fn point(&self, q: f64, _rate: f64) -> Result<CurvePoint> {
        Ok(CurvePoint {
            overlap: self.fold_depth + q * q,
            overlap_slope: 2.0 * q,
            force: self.stiffness * q,
            contact_radius: q,
            slopes: None,
        })
    }
    fn end(&self, q: f64, _rate: f64) -> Result<f64> {
        Ok(q)
    }
    fn slope_scale(&self) -> f64 {
        2.0 * (-self.fold_depth).sqrt()
    }
}

#[test]
fn a_fold_at_the_branch_end_is_integrated_in_the_branch_coordinate() {
    let (m, v0, k, d_c): (f64, f64, f64, f64) = (2.0, 1.5, 3.0, -0.5);
    let q0 = (-d_c).sqrt();
    let exact_restitution = (v0 * v0 + 4.0 * k / (3.0 * m) * q0 * q0 * q0).sqrt() / v0;
    let q_max = (q0 * q0 * q0 + 0.75 * m * v0 * v0 / k).cbrt();
    let exact_max_overlap = d_c + q_max * q_max;
    let settings = SimulationSettings::default();
    let mut sims = Vec::new();
    for curve in [true, false] {
        let mut law = Folded {
            fold_depth: d_c,
            stiffness: k,
            curve,
        };
        let sim = simulate_impact(&mut law, m, v0, &settings).unwrap();
        assert!(!sim.sticks);
        assert_eq!(
            sim.events.len(),
            2,
            "turning point and fold: {:?}",
            sim.events
        );
        assert!(
            rel(sim.restitution, exact_restitution) < 1e-10,
            "curve {curve}: {} vs {exact_restitution}",
            sim.restitution
        );
        assert!(
            rel(sim.max_overlap, exact_max_overlap) < 1e-10,
            "curve {curve}: {} vs {exact_max_overlap}",
            sim.max_overlap
        );
        assert!(
            sim.energy_error < 1e-10,
            "curve {curve}: {}",
            sim.energy_error
        );
        assert!((sim.events[1].overlap - d_c).abs() < 1e-12);
        sims.push(sim);
    }
    // the two integrations (in q, in time) agree on the contact time
    let (on_curve, in_time) = (&sims[0], &sims[1]);
    let (t1, t2) = (
        on_curve.contact_time.unwrap(),
        in_time.contact_time.unwrap(),
    );
    assert!(rel(t1, t2) < 1e-9, "{t1} vs {t2}");
    // the point of the coordinate: the square-root singularity costs the time
    // integration its short steps near the fold
    assert!(
        on_curve.cost.evaluations < in_time.cost.evaluations,
        "{:?} vs {:?}",
        on_curve.cost,
        in_time.cost
    );
}

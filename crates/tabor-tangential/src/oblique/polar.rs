//! The planar contact in polar coordinates on the law's branch curve: where a
//! planar segment is in contact on a [`BranchCurve`] without a fold
//! ([`BranchCurve::fold_free`]: JKR load-controlled), the contact is undamped
//! (a damped one that is captured creeps toward its equilibrium with ḋ → 0
//! and no turning point, which only the rounding of the Cartesian `ḋ = −n·u`
//! reaches) and the tangential element is a single spring (not the spring
//! bed), the segment integrates the branch
//! coordinate q itself (`q̇ = ḋ/(dd/dq)`, as the central simulated impact does:
//! no solve for q at an evaluation), the overlap rate ḋ, the velocity w of the
//! centres across the line of centres, the spins, the angle Δθ through which the
//! line of centres has turned (on a flat: the deviation along y), and the
//! tangential and rolling displacements as their components along the tangent
//! `t̂ = ẑ × n` (they stay in the turning tangent line: `ξ = s t̂`).
//!
//! The equations are those of [`super::plane`] in the rotating frame (n, t̂),
//! with `r = R_i + R_j − d(q)`, `ṅ = θ̇ t̂`, `θ̇ = w/r`:
//!
//! - `d̈ = −w²/r − F_n/m`, `ẇ = w ḋ/r + F_t/m` (the relative motion in polar
//!   coordinates, `m` the reduced mass);
//! - stick: `ṡ = v_t` (`v_t = w − ω_i R_i − ω_j R_j`, plus `mindlin_rescale`'s
//!   `(ȧ/a) s`), rolling `ψ̇ = (ω_i − ω_j) R*`; slip: `ṡ = 0` (in one dimension
//!   a slip direction cannot turn);
//! - the torques, the slip rates and every power as in [`super::plane`], each
//!   vector along t̂ as its component; the normal elastic-adhesive work from the
//!   curve's closed form ([`BranchCurve::work`]) where it gives one.
//!
//! A second derivation of the same motion: `polar_segments_match_the_cartesian_ones`
//! checks it against the Cartesian planar state. The segment's start and end
//! are converted from and to the Cartesian state, where the driver decides the
//! modes, so the segment's event values are those of [`Setup::planar_event_values`]
//! at the same point.

use super::elements::{keep_first, ratio, spring_rates};
use super::limits::EVENTS;
use super::normal::CURVE_MISMATCH;
use super::planar::with_state;
use super::plane::Trials;
use super::segment::sliding_work_to_event;
use super::state::*;
use nalgebra::Vector2;
use std::cell::Cell;
use tabor_dynamics::{BranchCurve, CurvePoint, ForceLaw};
use tabor_numerics::ode::{
    drive_events, DormandPrince853, EventDirection, EventsIntegration, OdeTolerance,
};
use tabor_restitution::{Error, Result};

/// An in-plane vector (x, y).
type V2 = Vector2<f64>;

/// The branch coordinate q.
const Q: usize = 0;
/// The overlap rate ḋ (m/s).
const RATE: usize = 1;
/// The relative velocity of the centres along t̂ (m/s).
const W: usize = 2;
/// ω_i about z.
const SPIN_I: usize = 3;
/// ω_j about z.
const SPIN_J: usize = 4;
/// The angle Δθ the line of centres has turned since the segment's start (rad;
/// on a flat: the deviation along y, m).
const TURN: usize = 5;
/// The tangential displacement along t̂.
const SPRING_T: usize = 6;
/// The rolling displacement along t̂.
const SPRING_R: usize = 7;
/// The 8 energies, in the order of the full state's.
const ENERGY: usize = 8;
/// The components of the polar state.
const PN: usize = 16;
/// Its motion (the error control's, and the step control's in the tensile end:
/// the bodies' motion alone, `[Q, SPRING_T)`).
const MOTION: usize = 8;

#[cfg(test)]
thread_local! {
    /// Tests: integrate every planar segment on the Cartesian state.
    pub(super) static CARTESIAN: Cell<bool> = const { Cell::new(false) };
    /// Tests: the number of segments integrated in polar coordinates.
    pub(super) static POLAR_SEGMENTS: Cell<usize> = const { Cell::new(0) };
}

/// The sign of the scalar `x` along t̂, or of `fallback` when `x` is 0 (or 0):
/// [`super::elements::direction`] on the tangent line.
fn direction1(x: f64, fallback: f64) -> f64 {
    if x != 0.0 {
        x.signum()
    } else if fallback != 0.0 {
        fallback.signum()
    } else {
        0.0
    }
}

/// [`super::elements::cap`] on the tangent line.
fn cap1(f: f64, limit: f64, frozen: bool) -> f64 {
    if frozen && f.abs() > limit {
        limit.copysign(f)
    } else {
        f
    }
}

/// `ẑ × n`: the tangent of the impact plane at the normal `n`.
fn tangent(n: &V2) -> V2 {
    V2::new(-n.y, n.x)
}

/// One polar segment: the curve, the frame at the segment's start, the units.
struct Polar<'s, 'a> {
    setup: &'s Setup<'a>,
    law: &'s dyn ForceLaw,
    curve: &'s dyn BranchCurve,
    modes: &'s Modes,
    /// The normal and the tangent at the segment's start (pair of spheres).
    n0: V2,
    t0: V2,
    /// SI value of one normalized unit of each component.
    scale: [f64; PN],
    /// 1/m of the reduced mass.
    inv_m: f64,
    /// The curve's work ([`BranchCurve::work`]) at the segment's start, where
    /// it gives one: the normal work is then booked from it, not integrated.
    work: Option<f64>,
}

impl<'a> Setup<'a> {
    /// The planar segment from the normalized full state `yn` at `ends.0` in
    /// polar coordinates, where it applies (in contact past the warm-up, the law
    /// on a fold-free curve with closed-form slopes that reproduces the
    /// overlap, no spring bed); `None` elsewhere. Arguments and result as
    /// [`Setup::planar_segment`].
    #[allow(clippy::too_many_arguments)]
    pub(super) fn polar_segment(
        &self,
        law: &dyn ForceLaw,
        modes: &Modes,
        combine: &dyn Fn([f64; EVENTS]) -> f64,
        failures: (&Cell<Option<Error>>, &Cell<Option<Error>>),
        ends: (f64, f64),
        yn: &[f64; N],
        tolerance: OdeTolerance,
        quadratures: bool,
    ) -> Option<tabor_numerics::Result<EventsIntegration<N>>> {
        #[cfg(test)]
        if CARTESIAN.with(Cell::get) {
            return None;
        }
        if !modes.in_contact || modes.warmup || self.bed.is_some() || self.imp.normal.damping != 0.0
        {
            return None;
        }
        let curve = law.curve().filter(|c| c.fold_free())?;
        let t = ends.0 * self.time;
        let y = self.to_si(yn);
        let (n, overlap, rate, _) = self.planar_geometry(t, &Setup::planar_of(&y));
        let q = curve.coordinate(overlap).ok()?;
        let p = curve.point(q, rate).ok()?;
        let work = curve.work(q);
        let on_curve = (p.overlap - overlap).abs() <= CURVE_MISMATCH * self.length
            && p.overlap_slope.is_finite()
            && p.overlap_slope != 0.0
            && p.slopes.is_some();
        if !on_curve {
            return None;
        }
        #[cfg(test)]
        POLAR_SEGMENTS.with(|c| c.set(c.get() + 1));
        let tn = tangent(&n);
        let u = V2::new(y[U], y[U + 1]);
        let mut z = [0.0; PN];
        z[Q] = q;
        z[RATE] = rate;
        z[W] = tn.dot(&u);
        z[SPIN_I] = y[WI + 2];
        z[SPIN_J] = y[WJ + 2];
        z[TURN] = if self.flat { y[E + 1] } else { 0.0 };
        z[SPRING_T] = tn.dot(&V2::new(y[XT], y[XT + 1]));
        z[SPRING_R] = tn.dot(&V2::new(y[XR], y[XR + 1]));
        z[ENERGY..].copy_from_slice(&y[EN..]);
        let mut scale = [1.0; PN];
        scale[Q] = self.length / curve.slope_scale();
        scale[RATE] = self.scale[U];
        scale[W] = self.scale[U + 1];
        scale[SPIN_I] = self.scale[WI + 2];
        scale[SPIN_J] = self.scale[WJ + 2];
        scale[TURN] = if self.flat {
            self.scale[E + 1]
        } else {
            self.scale[E] / self.r_sum
        };
        scale[SPRING_T] = self.scale[XT];
        scale[SPRING_R] = self.scale[XR];
        scale[ENERGY..].copy_from_slice(&self.scale[EN..]);
        let polar = Polar {
            setup: self,
            law,
            curve,
            modes,
            n0: n,
            t0: tn,
            scale,
            inv_m: 1.0 / self.m_eff,
            work,
        };
        let zn: [f64; PN] = std::array::from_fn(|k| z[k] / scale[k]);
        let controlled = if modes.tensile { SPRING_T } else { MOTION };
        let tolerance = self.dop853_tolerance(tolerance, quadratures, controlled);
        let all: [usize; PN] = std::array::from_fn(|k| k);
        if !quadratures {
            return Some(polar.dop853(all, failures, combine, ends, &zn, yn, tolerance));
        }
        // the normal elastic-adhesive work in closed form where the curve gives it
        let mut active = self.active_energies(modes);
        active[0] &= work.is_none();
        let (slots, m) = Setup::energy_slots::<PN>(active, MOTION, ENERGY);
        macro_rules! dispatch {
            ($($size:literal)*) => {
                match m {
                    $($size => polar.dop853::<$size>(std::array::from_fn(|j| slots[j]),
                        failures, combine, ends, &zn, yn, tolerance),)*
                    _ => polar.dop853(all, failures, combine, ends, &zn, yn, tolerance),
                }
            };
        }
        Some(dispatch!(8 9 10 11 12 13 14 15))
    }
}

impl Polar<'_, '_> {
    /// The polar SI state of the integrated components `x` (the motion first,
    /// in its order; the energies 0: no rate or event value reads them).
    fn si<const M: usize>(&self, x: &[f64; M]) -> [f64; PN] {
        let mut z = [0.0; PN];
        for k in 0..MOTION {
            z[k] = x[k] * self.scale[k];
        }
        z
    }

    /// The SI rates of the polar SI state `z` into `dz` (zeros on entry), and the
    /// tangential and rolling slip rates (∞ where an element sticks):
    /// [`Setup::planar_rates`] in the rotating frame, for the undamped normal
    /// contact a polar segment has (no normal or tangential dashpot: their
    /// terms are exact zeros there and left out).
    fn rates(&self, z: &[f64; PN], dz: &mut [f64; PN]) -> Result<(f64, f64)> {
        let p = self.curve.point(z[Q], z[RATE])?;
        self.rates_at(z, &p, dz)
    }

    /// [`Polar::rates`] with the curve's point `p` at `z` already evaluated.
    fn rates_at(&self, z: &[f64; PN], p: &CurvePoint, dz: &mut [f64; PN]) -> Result<(f64, f64)> {
        let s = self.setup;
        let modes = self.modes;
        let (rate, w) = (z[RATE], z[W]);
        let (wi, wj) = (z[SPIN_I], if s.flat { 0.0 } else { z[SPIN_J] });
        let (df_dq, da_dq) = p.slopes.unwrap_or((0.0, 0.0));
        let overlap = p.overlap;
        let q_dot = rate / p.overlap_slope;
        dz[Q] = q_dot;
        let theta_dot = if s.flat { 0.0 } else { w / (s.r_sum - overlap) };
        // on a flat t̂ = −ŷ: the deviation along y moves at −w − u0_y
        dz[TURN] = if s.flat { -w - s.u0.y } else { theta_dot };
        let (f_n, a) = (p.force, p.contact_radius.max(0.0));
        let pull_off = s.imp.normal.pull_off_force;
        let fc = crate::critical_force(f_n, f_n, pull_off);
        let (arm_i, arm_j, r_i, r_j) = s.planar_radii(overlap);
        let v_tr = w - (wi * r_i + wj * r_j);
        let v_rl = (wi - wj) * s.r_eff;
        let mut out = (f64::INFINITY, f64::INFINITY);
        dz[ENERGY] = f_n * rate;
        let Some(fr) = s.imp.friction.as_ref() else {
            dz[RATE] = -w * theta_dot - f_n * self.inv_m;
            dz[W] = theta_dot * rate;
            return Ok(out);
        };

        // forces: the spring (no dashpot) and the rolling resistance
        let t = &fr.tangential;
        let k = t.spring(a);
        let limit = t.coefficient * fc;
        let xi = z[SPRING_T];
        let f_t = match modes.tangential {
            Mode::Stick => cap1(-(xi * k), limit, modes.frozen[0]),
            Mode::Slip => -direction1(xi, v_tr) * limit,
        };
        let f_r = match &fr.rolling {
            Some(r) => {
                let psi = z[SPRING_R];
                let limit_r = r.coefficient * fc;
                match modes.rolling {
                    Mode::Stick => cap1(
                        -(psi * r.stiffness + v_rl * r.damping),
                        limit_r,
                        modes.frozen[1],
                    ),
                    Mode::Slip => -direction1(psi, v_rl) * limit_r,
                }
            }
            None => 0.0,
        };

        // accelerations (the twisting torque is 0)
        let torque_roll = f_r * s.r_eff;
        let wi_dot = (-f_t * arm_i + torque_roll) * s.inv_i_i;
        let wj_dot = if s.flat {
            0.0
        } else {
            (-f_t * arm_j - torque_roll) * s.inv_i_j
        };
        let w_dot = theta_dot * rate + f_t * self.inv_m;
        dz[RATE] = -w * theta_dot - f_n * self.inv_m;
        dz[W] = w_dot;
        dz[SPIN_I] = wi_dot;
        dz[SPIN_J] = wj_dot;

        // energies (power removed from the bodies; twisting's is 0)
        dz[ENERGY + 4] = -f_t * v_tr;
        dz[ENERGY + 5] = -f_r * v_rl;
        dz[ENERGY + 7] = -f_t * (wi * (r_i - arm_i) + wj * (r_j - arm_j));

        let a_dot = da_dq * q_dot;
        let (k_dot, _, rescale_rate) = spring_rates(t, (a, a_dot), 0.0, !modes.loading, s.time);
        // the rate of the critical force where an element slips
        let fc_dot = || {
            let d = df_dq * q_dot;
            let raw = if pull_off > 0.0 {
                f_n + 2.0 * pull_off
            } else {
                f_n
            };
            let tensile = if pull_off > 0.0 {
                raw < 0.0
            } else {
                modes.tensile
            };
            if tensile {
                -d
            } else {
                d
            }
        };
        match modes.tangential {
            Mode::Stick => dz[SPRING_T] = v_tr + xi * rescale_rate,
            Mode::Slip => {
                let uv = direction1(xi, v_tr) * v_tr;
                let g =
                    (ratio(k_dot, k) + rescale_rate) * limit + k * uv - t.coefficient * fc_dot();
                out.0 = g;
                let slip_rate = if modes.frozen[0] { g.max(0.0) } else { g };
                // the direction does not turn: û̇·v = 0
                let (power, _) = slip_power(
                    (t.model, modes.frozen[0]),
                    (limit, slip_rate, k),
                    (uv, 0.0, 0.0),
                );
                dz[ENERGY + 2] = power;
            }
        }
        if let Some(r) = &fr.rolling {
            match modes.rolling {
                Mode::Stick => dz[SPRING_R] = v_rl,
                Mode::Slip => {
                    let sign = direction1(z[SPRING_R], v_rl);
                    let v_rl_dot = (wi_dot - wj_dot) * s.r_eff;
                    out.1 = sign * (v_rl * r.stiffness + v_rl_dot * r.damping)
                        - r.coefficient * fc_dot();
                }
            }
        }
        Ok(out)
    }

    /// [`Setup::planar_event_values`] of the polar SI state `z` at SI time `t`
    /// (undamped: no dashpot in a trial force, no zero of a damped normal force).
    fn event_values(&self, t: f64, z: &[f64; PN]) -> Result<[f64; EVENTS]> {
        let s = self.setup;
        let modes = self.modes;
        let (q, rate) = (z[Q], z[RATE]);
        let p = self.curve.point(q, rate)?;
        let mut g = [f64::INFINITY; EVENTS];
        g[0] = self.law.branch_end(p.overlap, rate)? / s.length;
        g[1] = if modes.loading { rate } else { -rate } / s.v_n;
        let Some(fr) = s.imp.friction.as_ref() else {
            return Ok(g);
        };
        if modes.frozen_for_good() {
            return Ok(g);
        }
        modes.thaw_events(&mut g, t, s.time);
        let slip_rates = if modes.tangential == Mode::Slip || modes.rolling == Mode::Slip {
            self.rates_at(z, &p, &mut [0.0; PN])?
        } else {
            (f64::INFINITY, f64::INFINITY)
        };
        // the trial forces along the tangent (no dashpot in the tangential one)
        let contact = || -> Result<Trials> {
            let a = p.contact_radius.max(0.0);
            let (wi, wj) = (z[SPIN_I], if s.flat { 0.0 } else { z[SPIN_J] });
            let v_rl = (wi - wj) * s.r_eff;
            let rolling = fr.rolling.as_ref().map_or(0.0, |r| {
                (z[SPRING_R] * r.stiffness + v_rl * r.damping).abs()
            });
            Ok(Trials {
                radius: a,
                damping: 0.0,
                critical_force: crate::critical_force(
                    p.force,
                    p.force,
                    s.imp.normal.pull_off_force,
                ),
                tangential: (z[SPRING_T] * fr.tangential.spring(a)).abs(),
                rolling,
            })
        };
        s.element_events(&mut g, (fr, modes, true), contact, slip_rates)?;
        Ok(g)
    }

    /// The full normalized state of the polar normalized components `x`
    /// (`slots`) at normalized time `sn`, the rest as in the full `yn`.
    fn full<const M: usize>(
        &self,
        slots: &[usize; M],
        sn: f64,
        x: &[f64; M],
        yn: &[f64; N],
    ) -> Result<[f64; N]> {
        let s = self.setup;
        let z = self.si(x);
        let p = self.curve.point(z[Q], z[RATE])?;
        let t = sn * s.time;
        let (n, e) = if s.flat {
            let n = V2::new(-1.0, -0.0);
            (n, V2::new(p.overlap - s.v_n * t, z[TURN]))
        } else {
            let (sin, cos) = z[TURN].sin_cos();
            let n = self.n0 * cos + self.t0 * sin;
            let r = s.r_sum - p.overlap;
            (n, n * r - (s.d_touch.xy() + s.u0.xy() * t))
        };
        let tn = tangent(&n);
        let u = -n * z[RATE] + tn * z[W];
        let xi = tn * z[SPRING_T];
        let psi = tn * z[SPRING_R];
        let mut y = *yn;
        let mut set = |i: usize, v: f64| y[i] = v / s.scale[i];
        set(E, e.x);
        set(E + 1, e.y);
        set(U, u.x);
        set(U + 1, u.y);
        set(WI + 2, z[SPIN_I]);
        if !s.flat {
            set(WJ + 2, z[SPIN_J]);
        }
        set(XT, xi.x);
        set(XT + 1, xi.y);
        set(XR, psi.x);
        set(XR + 1, psi.y);
        for (&k, &v) in slots.iter().zip(x.iter()).skip(MOTION) {
            // energies: normalized alike in both states
            y[EN + k - ENERGY] = v;
        }
        if let (Some(w0), false) = (self.work, slots.contains(&ENERGY)) {
            let w1 = self.curve.work(z[Q]).unwrap_or(w0);
            y[EN] = yn[EN] + (w1 - w0) / s.scale[EN];
        }
        Ok(y)
    }

    /// DOP853 on the polar components `slots` (the motion first) from the
    /// normalized polar state `zn`; the result in the full normalized state.
    #[allow(clippy::too_many_arguments)]
    fn dop853<const M: usize>(
        &self,
        slots: [usize; M],
        (failure, g_failure): (&Cell<Option<Error>>, &Cell<Option<Error>>),
        combine: &dyn Fn([f64; EVENTS]) -> f64,
        (s0, s_end): (f64, f64),
        zn: &[f64; PN],
        yn: &[f64; N],
        tolerance: OdeTolerance,
    ) -> tabor_numerics::Result<EventsIntegration<N>> {
        let time = self.setup.time;
        let units: [f64; M] = std::array::from_fn(|j| time / self.scale[slots[j]]);
        let mut f = |_: f64, x: &[f64; M]| -> [f64; M] {
            let mut dz = [0.0; PN];
            match self.rates(&self.si(x), &mut dz) {
                Ok(_) => {
                    // the motion in its order, then the energies integrated
                    let mut out = [0.0; M];
                    for j in 0..MOTION {
                        out[j] = dz[j] * units[j];
                    }
                    for j in MOTION..M {
                        out[j] = dz[slots[j]] * units[j];
                    }
                    out
                }
                Err(e) => {
                    keep_first(failure, e);
                    [f64::NAN; M]
                }
            }
        };
        let mut g = |sn: f64, x: &[f64; M]| -> [f64; 1] {
            [match self.event_values(sn * time, &self.si(x)) {
                Ok(v) => combine(v),
                Err(e) => {
                    keep_first(g_failure, e);
                    f64::NAN
                }
            }]
        };
        let x0 = std::array::from_fn(|j| zn[slots[j]]);
        let mut stepper = DormandPrince853::new(&mut f, s0, x0, s_end, tolerance)?;
        let falling = [EventDirection::Falling];
        let mut observer = |_: f64, _: &[f64; M]| {};
        let mut run = drive_events(&mut stepper, &mut f, &mut g, falling, s_end, &mut observer)?;
        self.setup.step_hint.set(Some(stepper.proposed_step()));
        let sliding = slots.iter().position(|&k| k == ENERGY + 2);
        if let Some(k) = sliding.filter(|_| self.setup.singular_sliding_power(self.modes)) {
            sliding_work_to_event(&stepper, &mut f, k, &mut run);
        }
        let sol = &run.solution;
        let y = match self.full(&slots, sol.t, &sol.y, yn) {
            Ok(y) => y,
            Err(e) => {
                keep_first(failure, e);
                [f64::NAN; N]
            }
        };
        Ok(with_state(run, y))
    }
}

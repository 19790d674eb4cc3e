//! An adaptive explicit Runge-Kutta integrator for small ODE systems
//! `y' = f(t, y)`, `y ∈ ℝᴺ`: Dormand-Prince 5(4) with PI step-size control, the
//! standard 4th-order continuous extension (dense output) and event location.
//!
//! The method and its constants are those of Hairer, Nørsett & Wanner, *Solving
//! Ordinary Differential Equations I* (2nd ed., 1993), section II.5 and II.6 (code
//! `DOPRI5`): fifth-order solution, embedded fourth-order error estimate, first
//! same as last (FSAL), PI controller with β = 0.04, safety factor 0.9, step ratio
//! limited to [0.2, 10]. Events (sign changes of a user function `g(t, y)`) are
//! located on the dense output with Brent's method ([`crate::root_finding::brent`]),
//! so locating them costs no evaluations of `f`.
//!
//! Two layers:
//!
//! - [`DormandPrince`], a stepper: one accepted step at a time, dense output on the
//!   last step, event search on the last step, restart after a discontinuity. Use it
//!   when the right-hand side changes at events (branch changes of a contact law).
//! - [`solve`] and [`solve_until_event`], drivers that integrate to a final time or
//!   to the first event.
//!
//! The state is a fixed-size array `[f64; N]` (no allocation per step).

#![allow(clippy::needless_range_loop)] // component loops over small fixed arrays

use crate::root_finding::{brent, RootTolerance};
use crate::{Cost, NumericsError, Result};

/// Fifth-order Dormand-Prince coefficients (Hairer et al., Table II.5.2).
mod tableau {
    pub const C2: f64 = 1.0 / 5.0;
    pub const C3: f64 = 3.0 / 10.0;
    pub const C4: f64 = 4.0 / 5.0;
    pub const C5: f64 = 8.0 / 9.0;
    pub const A21: f64 = 1.0 / 5.0;
    pub const A31: f64 = 3.0 / 40.0;
    pub const A32: f64 = 9.0 / 40.0;
    pub const A41: f64 = 44.0 / 45.0;
    pub const A42: f64 = -56.0 / 15.0;
    pub const A43: f64 = 32.0 / 9.0;
    pub const A51: f64 = 19372.0 / 6561.0;
    pub const A52: f64 = -25360.0 / 2187.0;
    pub const A53: f64 = 64448.0 / 6561.0;
    pub const A54: f64 = -212.0 / 729.0;
    pub const A61: f64 = 9017.0 / 3168.0;
    pub const A62: f64 = -355.0 / 33.0;
    pub const A63: f64 = 46732.0 / 5247.0;
    pub const A64: f64 = 49.0 / 176.0;
    pub const A65: f64 = -5103.0 / 18656.0;
    pub const A71: f64 = 35.0 / 384.0;
    pub const A73: f64 = 500.0 / 1113.0;
    pub const A74: f64 = 125.0 / 192.0;
    pub const A75: f64 = -2187.0 / 6784.0;
    pub const A76: f64 = 11.0 / 84.0;
    /// Error coefficients: fifth- minus fourth-order weights.
    pub const E1: f64 = 71.0 / 57600.0;
    pub const E3: f64 = -71.0 / 16695.0;
    pub const E4: f64 = 71.0 / 1920.0;
    pub const E5: f64 = -17253.0 / 339200.0;
    pub const E6: f64 = 22.0 / 525.0;
    pub const E7: f64 = -1.0 / 40.0;
    /// Dense-output coefficients (Hairer's `CONTD5`).
    pub const D1: f64 = -12715105075.0 / 11282082432.0;
    pub const D3: f64 = 87487479700.0 / 32700410799.0;
    pub const D4: f64 = -10690763975.0 / 1880347072.0;
    pub const D5: f64 = 701980252875.0 / 199316789632.0;
    pub const D6: f64 = -1453857185.0 / 822651844.0;
    pub const D7: f64 = 69997945.0 / 29380423.0;
}

/// Accuracy and limits of an integration. A step is accepted when the embedded
/// error estimate satisfies `|err_i| ≤ absolute + relative · max(|y_i|, |y_i,new|)`
/// in the root-mean-square norm over the components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdeTolerance {
    /// Relative tolerance (≥ 1e-15 after raising; must be finite and ≥ 0).
    pub relative: f64,
    /// Absolute tolerance (finite, ≥ 0; relative and absolute may not both be 0).
    pub absolute: f64,
    /// Limit on the number of steps (accepted plus rejected).
    pub max_steps: u64,
    /// Largest step allowed (> 0, may be infinite).
    pub max_step: f64,
    /// First trial step; `None` chooses it automatically (Hairer's `HINIT`).
    pub initial_step: Option<f64>,
}

impl OdeTolerance {
    /// Relative tolerance `relative`, absolute tolerance `absolute`, at most one
    /// million steps, no step limit, automatic first step.
    pub fn new(relative: f64, absolute: f64) -> Self {
        OdeTolerance {
            relative,
            absolute,
            max_steps: 1_000_000,
            max_step: f64::INFINITY,
            initial_step: None,
        }
    }

    /// The same tolerance with a largest step `max_step`.
    pub fn with_max_step(mut self, max_step: f64) -> Self {
        self.max_step = max_step;
        self
    }

    /// The same tolerance with at most `max_steps` steps.
    pub fn with_max_steps(mut self, max_steps: u64) -> Self {
        self.max_steps = max_steps;
        self
    }

    pub(crate) fn validate(&self) -> Result<()> {
        let check = |name: &'static str, v: f64| {
            if v.is_finite() && v >= 0.0 {
                Ok(())
            } else {
                Err(NumericsError::InvalidArgument {
                    name,
                    value: v,
                    requirement: "must be finite and >= 0",
                })
            }
        };
        check("relative tolerance", self.relative)?;
        check("absolute tolerance", self.absolute)?;
        if self.relative == 0.0 && self.absolute == 0.0 {
            return Err(NumericsError::InvalidArgument {
                name: "absolute tolerance",
                value: 0.0,
                requirement: "relative and absolute tolerance may not both be 0",
            });
        }
        if self.max_step.is_nan() || self.max_step <= 0.0 {
            return Err(NumericsError::InvalidArgument {
                name: "max_step",
                value: self.max_step,
                requirement: "must be > 0",
            });
        }
        if self.max_steps == 0 {
            return Err(NumericsError::InvalidArgument {
                name: "max_steps",
                value: 0.0,
                requirement: "must be at least 1",
            });
        }
        if let Some(h) = self.initial_step {
            if !(h.is_finite() && h > 0.0) {
                return Err(NumericsError::InvalidArgument {
                    name: "initial_step",
                    value: h,
                    requirement: "must be finite and > 0",
                });
            }
        }
        Ok(())
    }

    /// The error scale of a component that was `a` before and `b` after a step.
    pub(crate) fn error_scale(&self, a: f64, b: f64) -> f64 {
        self.absolute + self.relative_effective() * a.abs().max(b.abs())
    }

    pub(crate) fn relative_effective(&self) -> f64 {
        self.relative.max(1e-15)
    }
}

impl Default for OdeTolerance {
    /// `relative = 1e-10`, `absolute = 1e-12`.
    fn default() -> Self {
        OdeTolerance::new(1e-10, 1e-12)
    }
}

/// Which sign changes of an event function count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventDirection {
    /// From `g > 0` to `g ≤ 0`.
    Falling,
    /// From `g < 0` to `g ≥ 0`.
    Rising,
    /// Either of the two.
    Either,
}

impl EventDirection {
    /// True when going from `before` to `after` is a crossing in this direction.
    /// A value that starts at exactly 0 never triggers, so an integration restarted
    /// at an event does not find the same event again.
    pub fn is_crossing(self, before: f64, after: f64) -> bool {
        let falling = before > 0.0 && after <= 0.0;
        let rising = before < 0.0 && after >= 0.0;
        match self {
            EventDirection::Falling => falling,
            EventDirection::Rising => rising,
            EventDirection::Either => falling || rising,
        }
    }
}

/// A located event: where the event function changed sign.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventPoint<const N: usize> {
    /// Time of the sign change.
    pub t: f64,
    /// State there (from the dense output).
    pub y: [f64; N],
}

/// The result of a driver ([`solve`], [`solve_until_event`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdeSolution<const N: usize> {
    /// Where the integration stopped: the final time, or the event time.
    pub t: f64,
    /// State at `t`.
    pub y: [f64; N],
    /// True when an event stopped the integration.
    pub event_found: bool,
    /// Accepted steps.
    pub accepted_steps: u64,
    /// Rejected steps.
    pub rejected_steps: u64,
    /// Right-hand-side evaluations (`evaluations`) and steps (`iterations`).
    pub cost: Cost,
}

/// The Dormand-Prince 5(4) stepper: integrates `y' = f(t, y)` one accepted step at
/// a time, forwards in time.
///
/// Keep the same right-hand side between [`DormandPrince::new`] /
/// [`DormandPrince::restart`] and the following steps; after a discontinuity of `f`
/// (an event changes a branch), call [`DormandPrince::restart`].
#[derive(Clone, Debug)]
pub struct DormandPrince<const N: usize> {
    tol: OdeTolerance,
    t: f64,
    y: [f64; N],
    /// f(t, y) (first same as last).
    dy: [f64; N],
    /// Start of the last accepted step.
    t_old: f64,
    /// Proposed next step size.
    h: f64,
    /// Length of the last accepted step (0 before the first).
    h_last: f64,
    /// Dense-output coefficients of the last accepted step.
    cont: [[f64; N]; 5],
    err_old: f64,
    last_rejected: bool,
    accepted: u64,
    rejected: u64,
    evaluations: u64,
}

fn axpy<const N: usize>(y: &[f64; N], h: f64, terms: &[(f64, &[f64; N])]) -> [f64; N] {
    let mut out = *y;
    for (i, o) in out.iter_mut().enumerate() {
        let mut s = 0.0;
        for (c, k) in terms {
            s += c * k[i];
        }
        *o += h * s;
    }
    out
}

pub(crate) fn first_non_finite<const N: usize>(v: &[f64; N]) -> Option<f64> {
    v.iter().copied().find(|x| !x.is_finite())
}

impl<const N: usize> DormandPrince<N> {
    /// Starts at `(t0, y0)`. Evaluates `f(t0, y0)` (an error if it is not finite)
    /// and chooses the first step. `t_hint` > `t0` is the time the integration aims
    /// at; it only bounds the automatic first step.
    pub fn new<F>(f: &mut F, t0: f64, y0: [f64; N], t_hint: f64, tol: OdeTolerance) -> Result<Self>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        tol.validate()?;
        finite("t0", t0)?;
        for &v in &y0 {
            finite("y0", v)?;
        }
        let mut s = DormandPrince {
            tol,
            t: t0,
            y: y0,
            dy: [0.0; N],
            t_old: t0,
            h: 0.0,
            h_last: 0.0,
            cont: [[0.0; N]; 5],
            err_old: 1e-4,
            last_rejected: false,
            accepted: 0,
            rejected: 0,
            evaluations: 0,
        };
        s.restart(f, t0, y0, t_hint)?;
        Ok(s)
    }

    /// Restarts at `(t, y)` after a discontinuity of the right-hand side (or with a
    /// new one): re-evaluates `f(t, y)` and chooses a new first step. Counters are
    /// kept; the dense output of the previous step is discarded.
    pub fn restart<F>(&mut self, f: &mut F, t: f64, y: [f64; N], t_hint: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let span = restart_span(t, &y, t_hint)?;
        self.t = t;
        self.t_old = t;
        self.y = y;
        self.h_last = 0.0;
        self.cont = [y, [0.0; N], [0.0; N], [0.0; N], [0.0; N]];
        self.err_old = 1e-4;
        self.last_rejected = false;
        self.dy = self.eval(f, t, &y)?;
        if let Some(bad) = first_non_finite(&self.dy) {
            return Err(NumericsError::NonFinite { at: t, value: bad });
        }
        let h_max = self.tol.max_step.min(span);
        self.h = match self.tol.initial_step {
            Some(h) => h.min(h_max),
            None => self.initial_step(f, h_max)?,
        };
        Ok(())
    }

    fn eval<F>(&mut self, f: &mut F, t: f64, y: &[f64; N]) -> Result<[f64; N]>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.evaluations += 1;
        Ok(f(t, y))
    }

    fn scale(&self, a: f64, b: f64) -> f64 {
        self.tol.error_scale(a, b)
    }

    /// Hairer's `HINIT`: a first step from the sizes of y, f and an estimate of y''.
    fn initial_step<F>(&mut self, f: &mut F, h_max: f64) -> Result<f64>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let n = N.max(1) as f64;
        let mut dnf = 0.0;
        let mut dny = 0.0;
        for i in 0..N {
            let sk = self.scale(self.y[i], self.y[i]);
            dnf += (self.dy[i] / sk).powi(2);
            dny += (self.y[i] / sk).powi(2);
        }
        let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
            1e-6
        } else {
            (dny / dnf).sqrt() * 0.01
        };
        h = h.min(h_max);
        let y1 = axpy(&self.y, h, &[(1.0, &self.dy)]);
        let f1 = self.eval(f, self.t + h, &y1)?;
        let mut der2 = 0.0;
        for i in 0..N {
            let sk = self.scale(self.y[i], self.y[i]);
            der2 += ((f1[i] - self.dy[i]) / sk).powi(2);
        }
        let der2 = (der2 / n).sqrt() / h;
        let der12 = der2.max((dnf / n).sqrt());
        let h1 = if der12 <= 1e-15 || !der12.is_finite() {
            (h * 1e-3).max(1e-6)
        } else {
            (0.01 / der12).powf(0.2)
        };
        let h = (100.0 * h).min(h1).min(h_max);
        if h.is_finite() && h > 0.0 {
            Ok(h)
        } else {
            Ok(h_max.min(1e-6))
        }
    }

    /// Current time (end of the last accepted step).
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn y(&self) -> [f64; N] {
        self.y
    }

    /// `f(t, y)` at the current point.
    pub fn derivative(&self) -> [f64; N] {
        self.dy
    }

    /// Start of the last accepted step (equal to [`DormandPrince::t`] right after a
    /// (re)start).
    pub fn previous_t(&self) -> f64 {
        self.t_old
    }

    /// Accepted and rejected steps so far.
    pub fn steps(&self) -> (u64, u64) {
        (self.accepted, self.rejected)
    }

    /// Right-hand-side evaluations (`evaluations`) and steps, accepted plus rejected
    /// (`iterations`), so far.
    pub fn cost(&self) -> Cost {
        Cost::new(self.evaluations, self.accepted + self.rejected)
    }

    /// Takes one accepted step, not beyond `t_limit` (> current time). Rejected trial
    /// steps are retried with a smaller step.
    ///
    /// Errors: [`NumericsError::NonFinite`] when `f` is not finite at an accepted
    /// point, or stays non-finite while the step shrinks to underflow;
    /// [`NumericsError::NoConvergence`] when the step size underflows (`h` below
    /// 16 ε |t|) or the step limit is reached.
    pub fn step<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        use tableau::*;
        if !(t_limit.is_finite() && t_limit > self.t) {
            return Err(NumericsError::InvalidArgument {
                name: "t_limit",
                value: t_limit,
                requirement: "must be finite and later than the current time",
            });
        }
        const BETA: f64 = 0.04;
        const EXPO1: f64 = 0.2 - BETA * 0.75;
        const SAFE: f64 = 0.9;
        const FAC_MIN: f64 = 0.2; // largest shrink 1/5
        const FAC_MAX: f64 = 10.0; // largest growth
        let mut non_finite: Option<(f64, f64)> = None;
        loop {
            if self.accepted + self.rejected >= self.tol.max_steps {
                return Err(NumericsError::NoConvergence {
                    method: "Dormand-Prince 5(4): step limit reached",
                    iterations: self.accepted + self.rejected,
                    estimate: self.t,
                    error: self.h,
                });
            }
            let remaining = t_limit - self.t;
            let mut h = self.h.min(self.tol.max_step);
            let last = h >= remaining * (1.0 - 4.0 * f64::EPSILON);
            if last {
                h = remaining;
            }
            let h_min = 16.0 * f64::EPSILON * self.t.abs().max(f64::MIN_POSITIVE);
            if h <= h_min && !last {
                return Err(match non_finite {
                    Some((at, value)) => NumericsError::NonFinite { at, value },
                    None => NumericsError::NoConvergence {
                        method: "Dormand-Prince 5(4): step size underflow",
                        iterations: self.accepted + self.rejected,
                        estimate: self.t,
                        error: h,
                    },
                });
            }
            let t = self.t;
            let y = self.y;
            let k1 = self.dy;
            let y2 = axpy(&y, h, &[(A21, &k1)]);
            let k2 = self.eval(f, t + C2 * h, &y2)?;
            let y3 = axpy(&y, h, &[(A31, &k1), (A32, &k2)]);
            let k3 = self.eval(f, t + C3 * h, &y3)?;
            let y4 = axpy(&y, h, &[(A41, &k1), (A42, &k2), (A43, &k3)]);
            let k4 = self.eval(f, t + C4 * h, &y4)?;
            let y5 = axpy(&y, h, &[(A51, &k1), (A52, &k2), (A53, &k3), (A54, &k4)]);
            let k5 = self.eval(f, t + C5 * h, &y5)?;
            let y6 = axpy(
                &y,
                h,
                &[(A61, &k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)],
            );
            let t_new = if last { t_limit } else { t + h };
            let k6 = self.eval(f, t_new, &y6)?;
            let y_new = axpy(
                &y,
                h,
                &[(A71, &k1), (A73, &k3), (A74, &k4), (A75, &k5), (A76, &k6)],
            );
            let k7 = self.eval(f, t_new, &y_new)?;
            let stage_bad = [&k2, &k3, &k4, &k5, &k6, &k7, &y_new]
                .iter()
                .find_map(|k| first_non_finite(k));
            if let Some(bad) = stage_bad {
                // A trial step into a region where f is not finite: shrink and retry.
                non_finite.get_or_insert((t + h, bad));
                self.rejected += 1;
                self.h = 0.1 * h;
                self.last_rejected = true;
                continue;
            }
            let mut err = 0.0;
            for i in 0..N {
                let e = h
                    * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
                let sk = self.scale(y[i], y_new[i]);
                err += (e / sk).powi(2);
            }
            let err = (err / N.max(1) as f64).sqrt();
            if !err.is_finite() {
                self.rejected += 1;
                self.h = 0.1 * h;
                self.last_rejected = true;
                continue;
            }
            let fac11 = err.powf(EXPO1);
            if err <= 1.0 {
                // Accept: PI control (Gustafsson) as in DOPRI5.
                let fac = fac11 / self.err_old.powf(BETA);
                let fac = (fac / SAFE).clamp(1.0 / FAC_MAX, 1.0 / FAC_MIN);
                let mut h_new = h / fac;
                if self.last_rejected {
                    h_new = h_new.min(h);
                }
                self.err_old = err.max(1e-4);
                // Dense output coefficients.
                let mut cont = [[0.0; N]; 5];
                for i in 0..N {
                    let ydiff = y_new[i] - y[i];
                    let bspl = h * k1[i] - ydiff;
                    cont[0][i] = y[i];
                    cont[1][i] = ydiff;
                    cont[2][i] = bspl;
                    cont[3][i] = ydiff - h * k7[i] - bspl;
                    cont[4][i] = h
                        * (D1 * k1[i]
                            + D3 * k3[i]
                            + D4 * k4[i]
                            + D5 * k5[i]
                            + D6 * k6[i]
                            + D7 * k7[i]);
                }
                self.cont = cont;
                self.t_old = t;
                self.h_last = t_new - t;
                self.t = t_new;
                self.y = y_new;
                self.dy = k7;
                self.h = h_new.min(self.tol.max_step);
                self.accepted += 1;
                self.last_rejected = false;
                return Ok(());
            }
            self.h = h / (1.0 / FAC_MIN).min(fac11 / SAFE);
            self.rejected += 1;
            self.last_rejected = true;
        }
    }

    /// The dense output (4th-order continuous extension) of the last accepted step at
    /// time `t`, which should lie in `[previous_t, t]` (outside it the polynomial is
    /// extrapolated). Right after a (re)start it returns the current state.
    pub fn dense_output(&self, t: f64) -> [f64; N] {
        if self.h_last <= 0.0 {
            return self.y;
        }
        let theta = (t - self.t_old) / self.h_last;
        let theta1 = 1.0 - theta;
        let c = &self.cont;
        let mut out = [0.0; N];
        for (i, o) in out.iter_mut().enumerate() {
            *o = c[0][i]
                + theta * (c[1][i] + theta1 * (c[2][i] + theta * (c[3][i] + theta1 * c[4][i])));
        }
        out
    }

    /// Searches the last accepted step for a crossing of the event function `g` in
    /// `direction`, given its values `g_before` at the start and `g_after` at the end
    /// of the step. Returns the crossing located by Brent's method on the dense
    /// output to `time_tolerance` (absolute, in t), with the evaluations of `g`
    /// spent, or `None` when the step has no such crossing.
    pub fn locate_event<G>(
        &self,
        mut g: G,
        direction: EventDirection,
        g_before: f64,
        g_after: f64,
        time_tolerance: f64,
    ) -> Result<Option<(EventPoint<N>, Cost)>>
    where
        G: FnMut(f64, &[f64; N]) -> f64,
    {
        locate_event_in_step(self, &mut g, direction, g_before, g_after, time_tolerance)
    }
}

pub(crate) fn finite(name: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(NumericsError::InvalidArgument {
            name,
            value: v,
            requirement: "must be finite",
        })
    }
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` to `t_end` > `t0`.
pub fn solve<F, const N: usize>(
    mut f: F,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    tol: OdeTolerance,
) -> Result<OdeSolution<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
{
    solve_until_event(
        &mut f,
        |_: f64, _: &[f64; N]| 1.0,
        EventDirection::Falling,
        t0,
        y0,
        t_end,
        tol,
    )
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` until the event function `g(t, y)`
/// crosses zero in `direction` (located on the dense output to a few ulps of t), or
/// until `t_end` when it does not. The cost counts evaluations of `f` only; locating
/// the event evaluates `g` on the dense output.
pub fn solve_until_event<F, G, const N: usize>(
    mut f: F,
    mut g: G,
    direction: EventDirection,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    tol: OdeTolerance,
) -> Result<OdeSolution<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    finite("t_end", t_end)?;
    let stepper = DormandPrince::new(&mut f, t0, y0, t_end, tol)?;
    drive_until_event(stepper, &mut f, &mut g, direction, t0, y0, t_end)
}

/// Checks a (re)start at `(t, y)` aiming at `t_hint`; returns `t_hint − t`.
pub(crate) fn restart_span<const N: usize>(t: f64, y: &[f64; N], t_hint: f64) -> Result<f64> {
    finite("t", t)?;
    for &v in y {
        finite("y", v)?;
    }
    let span = t_hint - t;
    if !(span.is_finite() && span > 0.0) {
        return Err(NumericsError::InvalidArgument {
            name: "t_hint",
            value: t_hint,
            requirement: "must be finite and later than the current time",
        });
    }
    Ok(span)
}

/// A one-step integrator with a dense output on its last accepted step
/// ([`DormandPrince`], [`crate::rosenbrock::Rosenbrock`]): what event location
/// ([`locate_event_in_step`]) and phase drivers built on either method need.
pub trait DenseStepper<const N: usize> {
    /// Current time and state.
    fn current(&self) -> (f64, [f64; N]);
    /// Start of the last accepted step.
    fn step_start(&self) -> f64;
    /// The dense output on the last accepted step.
    fn dense(&self, t: f64) -> [f64; N];
    /// One accepted step, not beyond `t_limit`.
    fn advance<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N];
    /// Accepted and rejected steps.
    fn step_counts(&self) -> (u64, u64);
    /// Evaluations of f and steps so far.
    fn spent(&self) -> Cost;
}

impl<const N: usize> DenseStepper<N> for DormandPrince<N> {
    fn current(&self) -> (f64, [f64; N]) {
        (self.t, self.y)
    }
    fn step_start(&self) -> f64 {
        self.t_old
    }
    fn dense(&self, t: f64) -> [f64; N] {
        self.dense_output(t)
    }
    fn advance<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.step(f, t_limit)
    }
    fn step_counts(&self) -> (u64, u64) {
        self.steps()
    }
    fn spent(&self) -> Cost {
        self.cost()
    }
}

/// The crossing of `g` in `direction` on the last accepted step of `stepper`,
/// located by Brent's method on the dense output to `time_tolerance` (absolute,
/// in t), with the evaluations of `g` spent; `None` when the step has none.
pub fn locate_event_in_step<S, G, const N: usize>(
    stepper: &S,
    g: &mut G,
    direction: EventDirection,
    g_before: f64,
    g_after: f64,
    time_tolerance: f64,
) -> Result<Option<(EventPoint<N>, Cost)>>
where
    S: DenseStepper<N>,
    G: FnMut(f64, &[f64; N]) -> f64,
{
    if !direction.is_crossing(g_before, g_after) {
        return Ok(None);
    }
    let (b, y_b) = stepper.current();
    if g_after == 0.0 {
        return Ok(Some((EventPoint { t: b, y: y_b }, Cost::ZERO)));
    }
    let a = stepper.step_start();
    let tol = RootTolerance {
        absolute: time_tolerance.max(0.0),
        relative: 4.0 * f64::EPSILON,
        max_iterations: 200,
    };
    let root = brent(
        |s| {
            if s <= a {
                g_before
            } else if s >= b {
                g_after
            } else {
                g(s, &stepper.dense(s))
            }
        },
        a,
        b,
        tol,
    )?;
    let t = root.value;
    Ok(Some((
        EventPoint {
            t,
            y: stepper.dense(t),
        },
        root.cost(),
    )))
}

/// Steps `stepper` (started at `(t0, y0)`) until `g` crosses zero in `direction`
/// or `t_end` is reached: the body of both `solve_until_event` functions.
pub(crate) fn drive_until_event<S, F, G, const N: usize>(
    mut stepper: S,
    f: &mut F,
    g: &mut G,
    direction: EventDirection,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
) -> Result<OdeSolution<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    let mut g_prev = g(t0, &y0);
    let solution = |stepper: &S, t: f64, y: [f64; N], event_found: bool| {
        let (accepted, rejected) = stepper.step_counts();
        OdeSolution {
            t,
            y,
            event_found,
            accepted_steps: accepted,
            rejected_steps: rejected,
            cost: stepper.spent(),
        }
    };
    while stepper.current().0 < t_end {
        stepper.advance(f, t_end)?;
        let (t, y) = stepper.current();
        let g_new = g(t, &y);
        if let Some((hit, _)) = locate_event_in_step(&stepper, g, direction, g_prev, g_new, 0.0)? {
            return Ok(solution(&stepper, hit.t, hit.y, true));
        }
        g_prev = g_new;
    }
    let (t, y) = stepper.current();
    Ok(solution(&stepper, t, y, false))
}

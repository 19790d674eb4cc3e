//! DOP853: the explicit Runge-Kutta method of order 8 by Dormand and Prince with
//! Hairer's error estimate of order 5 (corrected by one of order 3) and a
//! continuous extension of order 7, as in the code `DOP853` of Hairer, Nørsett &
//! Wanner, *Solving Ordinary Differential Equations I* (2nd ed., 1993), section
//! II.10: twelve evaluations of f per step (the thirteenth, at the step's end, is
//! the next step's first), step-size control `h_new = h / clamp(err^(1/8)/0.9, 1/6,
//! 3)`. At tight tolerances (1e-9 and below) it takes several times fewer steps
//! than Dormand-Prince 5(4) on smooth problems.
//!
//! The dense output needs three more evaluations of f. They are done only when
//! asked ([`DenseStepper::prepare_dense`], which [`drive`](super::drive) calls on
//! every step it shows its observer and [`drive_events`](super::drive_events) only
//! on the step that contains an event), so an integration that locates a few events
//! pays for a few dense outputs only.

#![allow(clippy::needless_range_loop)] // stage loops over small fixed arrays

mod tableau;

use super::{
    finite, first_non_finite, locate_event_in_step, one_step_method, DenseStepper, EventDirection,
    EventPoint, FailureNames, OdeTolerance, StepperCore,
};
use crate::{Cost, NumericsError, Result};
use tableau::{A, B, BHH, C, D, E5, STAGES};

/// Step-size control of `DOP853`: safety factor and the bounds of `h / h_new`.
const SAFE: f64 = 0.9;
const FAC_MIN: f64 = 1.0 / 6.0; // largest growth 6
const FAC_MAX: f64 = 1.0 / 0.333; // largest shrink 0.333

const NAMES: FailureNames = FailureNames {
    step_limit: "DOP853: step limit reached",
    underflow: "DOP853: step size underflow",
};

/// The sixteen stages of a step: 0-11 of the step, 12 = `f(t + h, y_new)`, 13-15
/// for the dense output.
type Stages<const N: usize> = [[f64; N]; 16];

/// The DOP853 stepper: integrates `y' = f(t, y)` one accepted step at a time,
/// forwards in time, with the interface of [`DormandPrince`](super::DormandPrince)
/// (restart after a discontinuity of f; keep the same f in between).
#[derive(Clone, Debug)]
pub struct DormandPrince853<const N: usize> {
    core: StepperCore<N>,
    /// The stages of the last accepted step (stage 0 of the next is `k[12]`).
    k: Stages<N>,
    /// The state at the start of the last accepted step.
    y_old: [f64; N],
    /// Coefficients of the continuous extension of the last accepted step, once
    /// [`DormandPrince853::prepare_dense_output`] has computed them.
    cont: Option<[[f64; N]; 8]>,
}

/// `y + h Σ_j a[j] k[j]` over the first `stages` stages (the zero coefficients
/// skipped). The sums run stage by stage over all components (vectorized), in
/// the order of j for every component.
fn stage_input<const N: usize>(
    y: &[f64; N],
    h: f64,
    a: &[f64; 15],
    k: &Stages<N>,
    stages: usize,
) -> [f64; N] {
    let mut sum = [0.0; N];
    for (&aj, kj) in a.iter().zip(k.iter()).take(stages) {
        if aj != 0.0 {
            for (s, &kji) in sum.iter_mut().zip(kj.iter()) {
                *s += aj * kji;
            }
        }
    }
    let mut out = *y;
    for (o, s) in out.iter_mut().zip(sum.iter()) {
        *o += h * s;
    }
    out
}

impl<const N: usize> DormandPrince853<N> {
    /// Starts at `(t0, y0)`. Evaluates `f(t0, y0)` (an error if it is not finite)
    /// and chooses the first step. `t_hint` > `t0` is the time the integration aims
    /// at; it only bounds the automatic first step.
    pub fn new<F>(f: &mut F, t0: f64, y0: [f64; N], t_hint: f64, tol: OdeTolerance) -> Result<Self>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        finite("t0", t0)?;
        for &v in &y0 {
            finite("y0", v)?;
        }
        let mut s = DormandPrince853 {
            core: StepperCore::new(tol, t0, y0)?,
            k: [[0.0; N]; 16],
            y_old: y0,
            cont: None,
        };
        s.restart(f, t0, y0, t_hint)?;
        Ok(s)
    }

    /// Restarts at `(t, y)` after a discontinuity of the right-hand side (or with a
    /// new one): re-evaluates `f(t, y)` and chooses a new first step (Hairer's
    /// `HINIT` for order 8). Counters are kept; the last step is forgotten.
    pub fn restart<F>(&mut self, f: &mut F, t: f64, y: [f64; N], t_hint: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.k[12] = self.core.restart_at(f, t, y, t_hint, Some(8))?;
        self.y_old = y;
        self.cont = None;
        Ok(())
    }

    /// Takes one accepted step, not beyond `t_limit` (> current time). Rejected trial
    /// steps are retried with a smaller step.
    ///
    /// Errors: [`NumericsError::NonFinite`] when f is not finite at an accepted
    /// point, or stays non-finite while the step shrinks to underflow;
    /// [`NumericsError::NoConvergence`] when the step size underflows (`h` below
    /// 16 ε |t|) or the step limit is reached.
    pub fn step<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.core.check_limit(t_limit)?;
        let mut non_finite: Option<(f64, f64)> = None;
        // the stages are written in place: the last step's dense output is not
        // needed once a new step is tried (stage 0 is its stage 12, kept at 12
        // until this step is accepted)
        self.k[0] = self.k[12];
        self.cont = None;
        let k = &mut self.k;
        loop {
            let (h, last) = self.core.trial_step(t_limit, non_finite, &NAMES)?;
            let t = self.core.t;
            let t_new = if last { t_limit } else { t + h };
            let y = self.core.y;
            let mut bad = None;
            for s in 1..STAGES {
                let ys = stage_input(&y, h, &A[s], k, s);
                let ts = if s == STAGES - 1 { t_new } else { t + C[s] * h };
                k[s] = self.core.eval(f, ts, &ys);
                if let Some(v) = first_non_finite(&k[s]) {
                    bad = Some(v);
                    break;
                }
            }
            let y_new = stage_input(&y, h, &B_ROW, k, STAGES);
            if let Some(v) = bad.or_else(|| first_non_finite(&y_new)) {
                // A trial step into a region where f is not finite: shrink and retry.
                non_finite.get_or_insert((t + h, v));
                self.core.reject(0.1 * h);
                continue;
            }
            let err = error_norm(&self.core, h, k, &y_new);
            if !err.is_finite() {
                self.core.reject(0.1 * h);
                continue;
            }
            let fac11 = err.powf(1.0 / 8.0);
            let fac = (fac11 / SAFE).clamp(FAC_MIN, FAC_MAX);
            if err <= 1.0 {
                let last_stage = self.core.eval(f, t_new, &y_new);
                if let Some(v) = first_non_finite(&last_stage) {
                    // f is not finite at the new point: shrink and retry.
                    non_finite.get_or_insert((t_new, v));
                    self.core.reject(0.1 * h);
                    continue;
                }
                k[12] = last_stage;
                self.y_old = y;
                self.core.accept(h, t_new, y_new, h / fac);
                return Ok(());
            }
            self.core.reject(h / fac);
        }
    }

    /// Computes the continuous extension of the last accepted step (three more
    /// evaluations of f, once per step); [`DormandPrince853::dense_output`] needs
    /// it. Nothing to do right after a (re)start.
    pub fn prepare_dense_output<F>(&mut self, f: &mut F) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        if self.cont.is_some() || self.core.h_last <= 0.0 {
            return Ok(());
        }
        let h = self.core.h_last;
        let (t, y) = (self.core.t_old, self.y_old);
        for s in 13..16 {
            let ys = stage_input(&y, h, &A[s], &self.k, s);
            self.k[s] = self.core.eval(f, t + C[s] * h, &ys);
            if let Some(v) = first_non_finite(&self.k[s]) {
                return Err(NumericsError::NonFinite {
                    at: t + C[s] * h,
                    value: v,
                });
            }
        }
        let k = &self.k;
        let y_new = self.core.y;
        let mut cont = [[0.0; N]; 8];
        for i in 0..N {
            let ydiff = y_new[i] - y[i];
            let bspl = h * k[0][i] - ydiff;
            cont[0][i] = y[i];
            cont[1][i] = ydiff;
            cont[2][i] = bspl;
            cont[3][i] = ydiff - h * k[12][i] - bspl;
            for r in 0..4 {
                let mut s = 0.0;
                for j in 0..16 {
                    s += D[r][j] * k[j][i];
                }
                cont[4 + r][i] = h * s;
            }
        }
        self.cont = Some(cont);
        Ok(())
    }

    /// The dense output (continuous extension of order 7) of the last accepted step
    /// at time `t`, which should lie in `[previous_t, t]`. Right after a (re)start
    /// it returns the current state; before [`DormandPrince853::prepare_dense_output`]
    /// on a step, the cubic Hermite interpolant of the step's ends (order 3), so call
    /// that first (the drivers of this module do).
    pub fn dense_output(&self, t: f64) -> [f64; N] {
        let Some(s) = self.core.theta(t) else {
            return self.core.y;
        };
        let s1 = 1.0 - s;
        let mut out = [0.0; N];
        match &self.cont {
            Some(c) => {
                for (i, o) in out.iter_mut().enumerate() {
                    *o = c[0][i]
                        + s * (c[1][i]
                            + s1 * (c[2][i]
                                + s * (c[3][i]
                                    + s1 * (c[4][i]
                                        + s * (c[5][i] + s1 * (c[6][i] + s * c[7][i]))))));
                }
            }
            None => {
                let h = self.core.h_last;
                let (y0, y1) = (&self.y_old, &self.core.y);
                for (i, o) in out.iter_mut().enumerate() {
                    let ydiff = y1[i] - y0[i];
                    let bspl = h * self.k[0][i] - ydiff;
                    *o = y0[i] + s * (ydiff + s1 * (bspl + s * (ydiff - h * self.k[12][i] - bspl)));
                }
            }
        }
        out
    }
}

/// Hairer's error norm of `DOP853`: the fifth-order estimate `err5`, corrected
/// by the third-order one `err3` as `err5² / √(err5² + 0.01 err3²)`, both in
/// the root-mean-square norm over the error scales (of the controlled
/// components, [`OdeTolerance::error_components`]), times `|h|`.
fn error_norm<const N: usize>(
    core: &StepperCore<N>,
    h: f64,
    k: &Stages<N>,
    y_new: &[f64; N],
) -> f64 {
    let y = &core.y;
    // Σ_j E5[j] k[j] and Σ_j B[j] k[j] stage by stage over all components
    let (mut e5, mut high) = ([0.0; N], [0.0; N]);
    for j in 0..STAGES {
        let (ej, bj, kj) = (E5[j], B[j], &k[j]);
        for i in 0..N {
            e5[i] += ej * kj[i];
            high[i] += bj * kj[i];
        }
    }
    let m = core.controlled();
    let (mut err5, mut err3) = (0.0, 0.0);
    for i in 0..m {
        let sk = core.scale(y[i], y_new[i]);
        let e3 = high[i] - BHH[0] * k[0][i] - BHH[1] * k[8][i] - BHH[2] * k[11][i];
        err5 += (e5[i] / sk).powi(2);
        err3 += (e3 / sk).powi(2);
    }
    let mut deno = err5 + 0.01 * err3;
    if deno <= 0.0 {
        deno = 1.0;
    }
    h.abs() * err5 * (1.0 / (m.max(1) as f64 * deno)).sqrt()
}

/// The weights `B` as a row of the coupling matrix.
const B_ROW: [f64; 15] = pad(&B);

const fn pad(b: &[f64; 12]) -> [f64; 15] {
    let mut out = [0.0; 15];
    let mut i = 0;
    while i < 12 {
        out[i] = b[i];
        i += 1;
    }
    out
}

one_step_method!(DormandPrince853, prepare = prepare_dense_output);

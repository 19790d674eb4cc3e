//! [`StepperCore`]: the state and step control every one-step method shares (the
//! current point, the last step, the proposed step size, the counters, Hairer's
//! `HINIT`).

#![allow(clippy::needless_range_loop)] // component loops over small fixed arrays

use super::OdeTolerance;
use crate::{Cost, NumericsError, Result};

/// The names a method gives its step failures ([`StepperCore::trial_step`]).
pub(crate) struct FailureNames {
    pub(crate) step_limit: &'static str,
    pub(crate) underflow: &'static str,
}

/// The state every one-step method keeps: the current point, the start and length
/// of the last accepted step, the proposed step size and the counters. The methods
/// add their own controller memory and dense-output coefficients.
#[derive(Clone, Debug)]
pub(crate) struct StepperCore<const N: usize> {
    pub(crate) tol: OdeTolerance,
    /// Current time and state (end of the last accepted step).
    pub(crate) t: f64,
    pub(crate) y: [f64; N],
    /// Start of the last accepted step.
    pub(crate) t_old: f64,
    /// Proposed next step size.
    pub(crate) h: f64,
    /// Length of the last accepted step (0 before the first).
    pub(crate) h_last: f64,
    pub(crate) last_rejected: bool,
    pub(crate) accepted: u64,
    pub(crate) rejected: u64,
    pub(crate) evaluations: u64,
}

impl<const N: usize> StepperCore<N> {
    /// Validates `tol` and starts at `(t0, y0)` (the method then restarts there).
    pub(crate) fn new(tol: OdeTolerance, t0: f64, y0: [f64; N]) -> Result<Self> {
        tol.validate()?;
        Ok(StepperCore {
            tol,
            t: t0,
            y: y0,
            t_old: t0,
            h: 0.0,
            h_last: 0.0,
            last_rejected: false,
            accepted: 0,
            rejected: 0,
            evaluations: 0,
        })
    }

    /// Checks a (re)start at `(t, y)` aiming at `t_hint`, moves there and forgets
    /// the last step; returns the span `t_hint − t`.
    pub(crate) fn restart(&mut self, t: f64, y: [f64; N], t_hint: f64) -> Result<f64> {
        finite("t", t)?;
        for &v in &y {
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
        self.t = t;
        self.t_old = t;
        self.y = y;
        self.h_last = 0.0;
        self.last_rejected = false;
        Ok(span)
    }

    /// `f(t, y)`, counted.
    pub(crate) fn eval<F>(&mut self, f: &mut F, t: f64, y: &[f64; N]) -> [f64; N]
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.evaluations += 1;
        f(t, y)
    }

    /// `f(t, y)` at the current point, counted; an error if it is not finite.
    pub(crate) fn eval_current<F>(&mut self, f: &mut F) -> Result<[f64; N]>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let (t, y) = (self.t, self.y);
        let dy = self.eval(f, t, &y);
        match first_non_finite(&dy) {
            Some(bad) => Err(NumericsError::NonFinite { at: t, value: bad }),
            None => Ok(dy),
        }
    }

    /// The error scale of a component that was `a` before and `b` after a step.
    pub(crate) fn scale(&self, a: f64, b: f64) -> f64 {
        self.tol.error_scale(a, b)
    }

    /// The number of leading components the error norm covers
    /// ([`OdeTolerance::error_components`]).
    pub(crate) fn controlled(&self) -> usize {
        self.tol.controlled(N)
    }

    /// The largest first step after a restart spanning `span`.
    pub(crate) fn first_step_limit(&self, span: f64) -> f64 {
        self.tol.max_step.min(span)
    }

    /// The first guess of Hairer's `HINIT` from the sizes of y and `dy = f(t, y)`:
    /// `0.01 ‖y‖/‖f‖`, or 1e-6 when either is tiny; with `‖f‖²·N` (`dnf`) for the
    /// second stage of `HINIT`.
    pub(crate) fn first_guess(&self, dy: &[f64; N]) -> (f64, f64) {
        let mut dnf = 0.0;
        let mut dny = 0.0;
        for i in 0..self.controlled() {
            let sk = self.scale(self.y[i], self.y[i]);
            dnf += (dy[i] / sk).powi(2);
            dny += (self.y[i] / sk).powi(2);
        }
        let h = if dnf <= 1e-10 || dny <= 1e-10 {
            1e-6
        } else {
            (dny / dnf).sqrt() * 0.01
        };
        (h, dnf)
    }

    /// The restart every stepper shares: checks and moves to `(t, y)` (forgetting the
    /// last step), evaluates `f(t, y)` (returned) and sets the first step `h`: the
    /// tolerance's `initial_step` if given (at most the span to `t_hint` and
    /// `max_step`), else Hairer's `HINIT` for a method of order `order`, or only its
    /// first guess (`order = None`, for the Rosenbrock methods).
    pub(crate) fn restart_at<F>(
        &mut self,
        f: &mut F,
        t: f64,
        y: [f64; N],
        t_hint: f64,
        order: Option<u32>,
    ) -> Result<[f64; N]>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let span = self.restart(t, y, t_hint)?;
        let dy = self.eval_current(f)?;
        let h_max = self.first_step_limit(span);
        self.h = match (self.tol.initial_step, order) {
            (Some(h), _) => h.min(h_max),
            (None, Some(order)) => self.hinit(f, &dy, h_max, order),
            (None, None) => {
                let (h, _) = self.first_guess(&dy);
                if h.is_finite() && h > 0.0 {
                    h.min(h_max)
                } else {
                    h_max.min(1e-6)
                }
            }
        };
        Ok(dy)
    }

    /// Hairer's `HINIT` for a method of order `order`: a first step from the sizes
    /// of y, `dy = f(t, y)` and an estimate of y'' (one more evaluation), at most
    /// `h_max`; 1e-6 (or `h_max`) when that is not informative.
    fn hinit<F>(&mut self, f: &mut F, dy: &[f64; N], h_max: f64, order: u32) -> f64
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let m = self.controlled();
        let n = m.max(1) as f64;
        let (h, dnf) = self.first_guess(dy);
        let h = h.min(h_max);
        let (t, y) = (self.t, self.y);
        let mut y1 = y;
        for i in 0..N {
            y1[i] += h * dy[i];
        }
        let f1 = self.eval(f, t + h, &y1);
        let mut der2 = 0.0;
        for i in 0..m {
            let sk = self.scale(y[i], y[i]);
            der2 += ((f1[i] - dy[i]) / sk).powi(2);
        }
        let der2 = (der2 / n).sqrt() / h;
        let der12 = der2.max((dnf / n).sqrt());
        let h1 = if der12 <= 1e-15 || !der12.is_finite() {
            (h * 1e-3).max(1e-6)
        } else {
            (0.01 / der12).powf(1.0 / f64::from(order))
        };
        let h = (100.0 * h).min(h1).min(h_max);
        if h.is_finite() && h > 0.0 {
            h
        } else {
            h_max.min(1e-6)
        }
    }

    /// Checks the target of a step.
    pub(crate) fn check_limit(&self, t_limit: f64) -> Result<()> {
        if t_limit.is_finite() && t_limit > self.t {
            Ok(())
        } else {
            Err(NumericsError::InvalidArgument {
                name: "t_limit",
                value: t_limit,
                requirement: "must be finite and later than the current time",
            })
        }
    }

    /// The size of the next trial step towards `t_limit` and whether it is the last
    /// one (it then reaches `t_limit` exactly). Errors when the step limit is
    /// reached, or when the step underflows (`h` below 16 ε |t`|; then the first
    /// non-finite value met, if any, is reported).
    pub(crate) fn trial_step(
        &self,
        t_limit: f64,
        non_finite: Option<(f64, f64)>,
        names: &FailureNames,
    ) -> Result<(f64, bool)> {
        if self.accepted + self.rejected >= self.tol.max_steps {
            return Err(NumericsError::NoConvergence {
                method: names.step_limit,
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
                    method: names.underflow,
                    iterations: self.accepted + self.rejected,
                    estimate: self.t,
                    error: h,
                },
            });
        }
        Ok((h, last))
    }

    /// Counts a rejected trial step and proposes `h_next`.
    pub(crate) fn reject(&mut self, h_next: f64) {
        self.rejected += 1;
        self.h = h_next;
        self.last_rejected = true;
    }

    /// Accepts a step of size `h` to `(t_new, y_new)` and proposes `h_proposed` for
    /// the next one (not larger than `h` right after a rejection).
    pub(crate) fn accept(&mut self, h: f64, t_new: f64, y_new: [f64; N], h_proposed: f64) {
        let h_new = if self.last_rejected {
            h_proposed.min(h)
        } else {
            h_proposed
        };
        self.t_old = self.t;
        self.h_last = t_new - self.t;
        self.t = t_new;
        self.y = y_new;
        self.h = h_new.min(self.tol.max_step);
        self.accepted += 1;
        self.last_rejected = false;
    }

    /// The position `θ ∈ [0, 1]` of `t` in the last accepted step, or `None` before
    /// the first step (the dense output is then the current state).
    pub(crate) fn theta(&self, t: f64) -> Option<f64> {
        (self.h_last > 0.0).then(|| (t - self.t_old) / self.h_last)
    }

    pub(crate) fn steps(&self) -> (u64, u64) {
        (self.accepted, self.rejected)
    }

    pub(crate) fn cost(&self) -> Cost {
        Cost::new(self.evaluations, self.accepted + self.rejected)
    }
}

pub(crate) fn first_non_finite<const N: usize>(v: &[f64; N]) -> Option<f64> {
    v.iter().copied().find(|x| !x.is_finite())
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

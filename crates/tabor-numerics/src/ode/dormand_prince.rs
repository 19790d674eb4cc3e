//! Dormand-Prince 5(4): an adaptive explicit Runge-Kutta method with PI step-size
//! control and the standard 4th-order continuous extension (dense output).
//!
//! The method and its constants are those of Hairer, Nørsett & Wanner, *Solving
//! Ordinary Differential Equations I* (2nd ed., 1993), sections II.5 and II.6 (code
//! `DOPRI5`): fifth-order solution, embedded fourth-order error estimate, first
//! same as last (FSAL), PI controller with β = 0.04, safety factor 0.9, step ratio
//! limited to [0.2, 10].
//!
//! Two layers:
//!
//! - [`DormandPrince`], a stepper: one accepted step at a time, dense output on the
//!   last step, event search on the last step, restart after a discontinuity. Use it
//!   when the right-hand side changes at events (branch changes of a contact law).
//! - [`solve`] and [`solve_until_event`]: the driver [`drive`](super::drive) with this stepper,
//!   to a final time or to the first event.

#![allow(clippy::needless_range_loop)] // component loops over small fixed arrays

use super::{
    drive_unobserved, finite, first_non_finite, locate_event_in_step, no_event, one_step_method,
    DenseStepper, EventDirection, EventPoint, FailureNames, OdeSolution, OdeTolerance, StepperCore,
};
use crate::{Cost, Result};

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

/// PI controller (Gustafsson) of `DOPRI5`.
const BETA: f64 = 0.04;
const EXPO1: f64 = 0.2 - BETA * 0.75;
const SAFE: f64 = 0.9;
const FAC_MIN: f64 = 0.2; // largest shrink 1/5
const FAC_MAX: f64 = 10.0; // largest growth

const NAMES: FailureNames = FailureNames {
    step_limit: "Dormand-Prince 5(4): step limit reached",
    underflow: "Dormand-Prince 5(4): step size underflow",
};

/// The Dormand-Prince 5(4) stepper: integrates `y' = f(t, y)` one accepted step at
/// a time, forwards in time.
///
/// Keep the same right-hand side between [`DormandPrince::new`] /
/// [`DormandPrince::restart`] and the following steps; after a discontinuity of `f`
/// (an event changes a branch), call [`DormandPrince::restart`].
#[derive(Clone, Debug)]
pub struct DormandPrince<const N: usize> {
    core: StepperCore<N>,
    /// f(t, y) (first same as last).
    dy: [f64; N],
    /// Dense-output coefficients of the last accepted step.
    cont: [[f64; N]; 5],
    /// Error of the last accepted step (PI controller), at least 1e-4.
    err_old: f64,
}

/// The seven stages of a trial step: `k[0] = f(t, y)`, …, `k[6] = f(t + h, y_new)`.
type Stages<const N: usize> = [[f64; N]; 7];

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

impl<const N: usize> DormandPrince<N> {
    /// Starts at `(t0, y0)`. Evaluates `f(t0, y0)` (an error if it is not finite)
    /// and chooses the first step. `t_hint` > `t0` is the time the integration aims
    /// at; it only bounds the automatic first step.
    pub fn new<F>(f: &mut F, t0: f64, y0: [f64; N], t_hint: f64, tol: OdeTolerance) -> Result<Self>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let core = StepperCore::new(tol, t0, y0)?;
        finite("t0", t0)?;
        for &v in &y0 {
            finite("y0", v)?;
        }
        let mut s = DormandPrince {
            core,
            dy: [0.0; N],
            cont: [[0.0; N]; 5],
            err_old: 1e-4,
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
        self.dy = self.core.restart_at(f, t, y, t_hint, Some(5))?;
        self.cont = [y, [0.0; N], [0.0; N], [0.0; N], [0.0; N]];
        self.err_old = 1e-4;
        Ok(())
    }

    /// Takes one accepted step, not beyond `t_limit` (> current time). Rejected trial
    /// steps are retried with a smaller step.
    ///
    /// Errors: [`NumericsError::NonFinite`](crate::NumericsError::NonFinite) when `f`
    /// is not finite at an accepted point, or stays non-finite while the step
    /// shrinks to underflow;
    /// [`NumericsError::NoConvergence`](crate::NumericsError::NoConvergence) when
    /// the step size underflows (`h` below 16 ε |t|) or the step limit is reached.
    pub fn step<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.core.check_limit(t_limit)?;
        let mut non_finite: Option<(f64, f64)> = None;
        loop {
            let (h, last) = self.core.trial_step(t_limit, non_finite, &NAMES)?;
            let t = self.core.t;
            let t_new = if last { t_limit } else { t + h };
            let (k, y_new) = self.stages(f, h, t_new);
            let stage_bad = k[1..].iter().chain([&y_new]).find_map(first_non_finite);
            if let Some(bad) = stage_bad {
                // A trial step into a region where f is not finite: shrink and retry.
                non_finite.get_or_insert((t + h, bad));
                self.core.reject(0.1 * h);
                continue;
            }
            let err = self.error_norm(h, &k, &y_new);
            if !err.is_finite() {
                self.core.reject(0.1 * h);
                continue;
            }
            let fac11 = err.powf(EXPO1);
            if err <= 1.0 {
                // Accept: PI control (Gustafsson) as in DOPRI5.
                let fac = fac11 / self.err_old.powf(BETA);
                let fac = (fac / SAFE).clamp(1.0 / FAC_MAX, 1.0 / FAC_MIN);
                self.err_old = err.max(1e-4);
                self.cont = dense_coefficients(h, &self.core.y, &k, &y_new);
                self.dy = k[6];
                self.core.accept(h, t_new, y_new, h / fac);
                return Ok(());
            }
            self.core.reject(h / (1.0 / FAC_MIN).min(fac11 / SAFE));
        }
    }

    /// The stages of a trial step of size `h` from the current point (ending at
    /// `t_new`) and the fifth-order solution there.
    fn stages<F>(&mut self, f: &mut F, h: f64, t_new: f64) -> (Stages<N>, [f64; N])
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        use tableau::*;
        let (t, y) = (self.core.t, self.core.y);
        let k1 = self.dy;
        let y2 = axpy(&y, h, &[(A21, &k1)]);
        let k2 = self.core.eval(f, t + C2 * h, &y2);
        let y3 = axpy(&y, h, &[(A31, &k1), (A32, &k2)]);
        let k3 = self.core.eval(f, t + C3 * h, &y3);
        let y4 = axpy(&y, h, &[(A41, &k1), (A42, &k2), (A43, &k3)]);
        let k4 = self.core.eval(f, t + C4 * h, &y4);
        let y5 = axpy(&y, h, &[(A51, &k1), (A52, &k2), (A53, &k3), (A54, &k4)]);
        let k5 = self.core.eval(f, t + C5 * h, &y5);
        let y6 = axpy(
            &y,
            h,
            &[(A61, &k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)],
        );
        let k6 = self.core.eval(f, t_new, &y6);
        let y_new = axpy(
            &y,
            h,
            &[(A71, &k1), (A73, &k3), (A74, &k4), (A75, &k5), (A76, &k6)],
        );
        let k7 = self.core.eval(f, t_new, &y_new);
        ([k1, k2, k3, k4, k5, k6, k7], y_new)
    }

    /// The root-mean-square of the embedded error estimate over the error scales.
    fn error_norm(&self, h: f64, k: &Stages<N>, y_new: &[f64; N]) -> f64 {
        use tableau::*;
        let y = &self.core.y;
        let m = self.core.controlled();
        let mut err = 0.0;
        for i in 0..m {
            let e = h
                * (E1 * k[0][i]
                    + E3 * k[2][i]
                    + E4 * k[3][i]
                    + E5 * k[4][i]
                    + E6 * k[5][i]
                    + E7 * k[6][i]);
            let sk = self.core.scale(y[i], y_new[i]);
            err += (e / sk).powi(2);
        }
        (err / m.max(1) as f64).sqrt()
    }

    /// The dense output (4th-order continuous extension) of the last accepted step at
    /// time `t`, which should lie in `[previous_t, t]` (outside it the polynomial is
    /// extrapolated). Right after a (re)start it returns the current state.
    pub fn dense_output(&self, t: f64) -> [f64; N] {
        let Some(theta) = self.core.theta(t) else {
            return self.core.y;
        };
        let theta1 = 1.0 - theta;
        let c = &self.cont;
        let mut out = [0.0; N];
        for (i, o) in out.iter_mut().enumerate() {
            *o = c[0][i]
                + theta * (c[1][i] + theta1 * (c[2][i] + theta * (c[3][i] + theta1 * c[4][i])));
        }
        out
    }
}

one_step_method!(DormandPrince);

/// The coefficients of the continuous extension of an accepted step of size `h`
/// from `y` to `y_new` with stages `k` (Hairer's `CONTD5`).
fn dense_coefficients<const N: usize>(
    h: f64,
    y: &[f64; N],
    k: &Stages<N>,
    y_new: &[f64; N],
) -> [[f64; N]; 5] {
    use tableau::*;
    let mut cont = [[0.0; N]; 5];
    for i in 0..N {
        let ydiff = y_new[i] - y[i];
        let bspl = h * k[0][i] - ydiff;
        cont[0][i] = y[i];
        cont[1][i] = ydiff;
        cont[2][i] = bspl;
        cont[3][i] = ydiff - h * k[6][i] - bspl;
        cont[4][i] = h
            * (D1 * k[0][i]
                + D3 * k[2][i]
                + D4 * k[3][i]
                + D5 * k[4][i]
                + D6 * k[5][i]
                + D7 * k[6][i]);
    }
    cont
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` to `t_end` > `t0`.
pub fn solve<F, const N: usize>(
    f: F,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    tol: OdeTolerance,
) -> Result<OdeSolution<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
{
    solve_until_event(f, no_event, EventDirection::Falling, t0, y0, t_end, tol)
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
    let mut stepper = DormandPrince::new(&mut f, t0, y0, t_end, tol)?;
    drive_unobserved(&mut stepper, &mut f, &mut g, direction, t_end)
}

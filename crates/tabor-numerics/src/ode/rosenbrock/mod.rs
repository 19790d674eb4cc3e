//! Adaptive L-stable integrators for small stiff ODE systems `y' = f(t, y)`,
//! `y ∈ ℝᴺ`: Rosenbrock methods with an embedded error estimate, a continuous
//! extension (dense output) and event location. Two schemes ([`Scheme`]):
//!
//! - [`Scheme::Rodas5P`] (default): Steinebach, *Construction of Rosenbrock–Wanner
//!   method Rodas5P and numerical benchmarks within the Julia Differential
//!   Equations package*, BIT Numer. Math. 63:27 (2023). Eight stages, order 5 with
//!   an embedded order-4 estimate, stiffly accurate, L-stable, a dense output of
//!   order 4, and the additional conditions that keep the order on the
//!   Prothero-Robinson problem `y' = λ (y − φ(t)) + φ'(t)` for all `hλ` (classical
//!   Rosenbrock methods have stage order 1 and lose order there when `hλ` is
//!   moderately large, which makes them take tiny steps at tight tolerances on
//!   mildly stiff relaxations). Coefficients in the W-transformed form of the
//!   Julia `OrdinaryDiffEq` tableau `Rodas5PTableau`.
//! - [`Scheme::Rodas4`]: Hairer & Wanner, *Solving Ordinary Differential Equations
//!   II* (2nd ed., 1996), section IV.7, code `RODAS` (`METH = 1`): six stages, order
//!   4(3), stiffly accurate, L-stable, dense output of order 3.
//!
//! L-stability means that the stability function vanishes at infinity: a stiff
//! transient is damped within a step, not carried along as by an explicit method
//! at its stability limit. Each step solves the stage equations with the matrix
//! `I/(γh) − J` (one LU decomposition with partial pivoting; N is small), J the
//! Jacobian `∂f/∂y` at the start of the step, computed by forward differences
//! ([`Jacobian`]; N evaluations of f, plus one for `∂f/∂t` unless the system is
//! autonomous) or supplied by the caller ([`Rosenbrock::step_with_jacobian`]). Step
//! sizes: `h_new = h / clamp(err^{1/q}/0.9, 1/6, 5)` (q the order of the scheme)
//! with the predictive (Gustafsson) correction after accepted steps, as in
//! `RODAS`. The error norm and tolerances ([`OdeTolerance`]), the events
//! ([`EventDirection`], located on the dense output with Brent's method) and the
//! results ([`OdeSolution`]) are those of [`crate::ode`], and the stepper has the
//! interface of [`DormandPrince`](crate::ode::DormandPrince).
//!
//! Use it where an explicit method is limited by stability rather than accuracy
//! (relaxation rates far above the inverse time scale of the solution). A
//! Jacobian by differences is accurate to about √ε relative; Rosenbrock methods
//! need a good Jacobian for their order, which matters only near the tightest
//! tolerances.

//!
//! Layout: the coefficients are in `tableau`, the small LU decomposition in `lu`;
//! this module holds the stepper, whose step is split into the stage solves
//! ([`Rosenbrock::step_with_jacobian`] calls `stages`), the error norm and the
//! step-size controller.

#![allow(clippy::needless_range_loop)] // component loops over small fixed arrays

mod lu;
mod tableau;

pub use lu::Matrix;

use super::{
    drive_unobserved, finite, first_non_finite, locate_event_in_step, no_event, one_step_method,
    DenseStepper, EventDirection, EventPoint, FailureNames, OdeSolution, OdeTolerance, StepperCore,
};
use crate::{Cost, Result};
use lu::Lu;
use tableau::{Tableau, RODAS4, RODAS5P};

/// Which Rosenbrock method a [`Rosenbrock`] stepper uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Scheme {
    /// Rodas5P: order 5(4), dense output of order 4, no order reduction on
    /// Prothero-Robinson problems.
    #[default]
    Rodas5P,
    /// RODAS4: order 4(3), dense output of order 3.
    Rodas4,
}

impl Scheme {
    fn tableau(self) -> &'static Tableau {
        match self {
            Scheme::Rodas5P => &RODAS5P,
            Scheme::Rodas4 => &RODAS4,
        }
    }
}

/// How [`Rosenbrock::step`] obtains the Jacobian `∂f/∂y` (and `∂f/∂t`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Jacobian {
    /// Forward differences in y (N evaluations of f per step); f does not depend
    /// on t, so `∂f/∂t = 0`.
    Autonomous,
    /// Forward differences in y and t (N + 1 evaluations of f per step).
    NonAutonomous,
}

/// The Jacobian `∂f/∂y` at `(t, y)` by forward differences, given `fy = f(t, y)`,
/// with the increments of Hairer's codes, `√(ε · max(1e-5, |y_j|))`.
pub fn finite_difference_jacobian<F, const N: usize>(
    f: &mut F,
    t: f64,
    y: &[f64; N],
    fy: &[f64; N],
) -> Matrix<N>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
{
    let mut jac = [[0.0; N]; N];
    for j in 0..N {
        let mut yj = *y;
        let delta = (f64::EPSILON * y[j].abs().max(1e-5)).sqrt();
        yj[j] += delta;
        let dj = yj[j] - y[j];
        let fj = f(t, &yj);
        for i in 0..N {
            jac[i][j] = (fj[i] - fy[i]) / dj;
        }
    }
    jac
}

/// `∂f/∂t` at `(t, y)` by a forward difference, given `fy = f(t, y)`.
fn finite_difference_time_derivative<F, const N: usize>(
    f: &mut F,
    t: f64,
    y: &[f64; N],
    fy: &[f64; N],
) -> [f64; N]
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
{
    let mut ft = [0.0; N];
    let dt = (f64::EPSILON * t.abs().max(1e-5)).sqrt();
    let t1 = t + dt;
    let f1 = f(t1, y);
    for i in 0..N {
        ft[i] = (f1[i] - fy[i]) / (t1 - t);
    }
    ft
}

/// The iteration matrix `W = I/(γh) − J`.
fn iteration_matrix<const N: usize>(jacobian: &Matrix<N>, gamma: f64, h: f64) -> Matrix<N> {
    let mut w = *jacobian;
    for i in 0..N {
        for j in 0..N {
            w[i][j] = -w[i][j];
        }
        w[i][i] += 1.0 / (gamma * h);
    }
    w
}

/// Step-size control of `RODAS`: safety factor and the bounds of `h / h_new`.
const SAFE: f64 = 0.9;
const FAC_MIN: f64 = 1.0 / 6.0; // largest growth 6
const FAC_MAX: f64 = 5.0; // largest shrink 1/5

const NAMES: FailureNames = FailureNames {
    step_limit: "Rosenbrock: step limit reached",
    underflow: "Rosenbrock: step size underflow",
};

/// The stage increments `k_1 … k_s` of a trial step (s ≤ 8).
type Stages<const N: usize> = [[f64; N]; 8];

/// What every trial step from the same point shares: the state, `f` there, the
/// Jacobian `∂f/∂y` and `∂f/∂t`.
struct StepStart<const N: usize> {
    t: f64,
    y: [f64; N],
    dy: [f64; N],
    jacobian: Matrix<N>,
    ft: [f64; N],
}

/// A Rosenbrock stepper ([`Scheme`]): integrates `y' = f(t, y)` one accepted step
/// at a time, forwards in time.
///
/// As for [`DormandPrince`](crate::ode::DormandPrince): keep the same right-hand
/// side between [`Rosenbrock::new`] / [`Rosenbrock::restart`] and the following
/// steps, and restart after a discontinuity of f.
#[derive(Clone, Debug)]
pub struct Rosenbrock<const N: usize> {
    core: StepperCore<N>,
    scheme: Scheme,
    jacobian: Jacobian,
    /// f(t, y), if evaluated since the last accepted step.
    dy: Option<[f64; N]>,
    /// The state at the start of the last accepted step.
    y_old: [f64; N],
    /// Dense-output coefficients K_1, K_2, K_3 of the last accepted step.
    cont: [[f64; N]; 3],
    /// Size and error of the last accepted step (predictive controller).
    h_accepted: f64,
    err_accepted: f64,
}

impl<const N: usize> Rosenbrock<N> {
    /// Starts at `(t0, y0)` with the method `scheme` and the Jacobian strategy
    /// `jacobian`. Evaluates `f(t0, y0)` (an error if it is not finite) and chooses
    /// the first step (or takes `tol.initial_step`). `t_hint` > `t0` is the time the
    /// integration aims at; it only bounds the first step.
    pub fn new<F>(
        f: &mut F,
        t0: f64,
        y0: [f64; N],
        t_hint: f64,
        tol: OdeTolerance,
        jacobian: Jacobian,
        scheme: Scheme,
    ) -> Result<Self>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let mut s = Rosenbrock {
            core: StepperCore::new(tol, t0, y0)?,
            scheme,
            jacobian,
            dy: None,
            y_old: y0,
            cont: [[0.0; N]; 3],
            h_accepted: 0.0,
            err_accepted: 1e-2,
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
        self.dy = Some(self.core.restart_at(f, t, y, t_hint, None)?);
        self.y_old = y;
        self.cont = [[0.0; N]; 3];
        self.h_accepted = 0.0;
        self.err_accepted = 1e-2;
        Ok(())
    }

    /// The method.
    pub fn scheme(&self) -> Scheme {
        self.scheme
    }

    /// Takes one accepted step, not beyond `t_limit` (> current time), with the
    /// Jacobian by forward differences ([`Jacobian`]). Rejected trial steps are
    /// retried with a smaller step.
    ///
    /// Errors: [`NumericsError::NonFinite`](crate::NumericsError::NonFinite) when f
    /// is not finite at an accepted point, or stays non-finite while the step
    /// shrinks to underflow;
    /// [`NumericsError::NoConvergence`](crate::NumericsError::NoConvergence) when
    /// the step size underflows or the step limit is reached.
    pub fn step<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let autonomous = self.jacobian == Jacobian::Autonomous;
        let mut evaluations = 0u64;
        let result = self.step_with_jacobian(
            f,
            &mut |f: &mut F, t: f64, y: &[f64; N], fy: &[f64; N]| {
                evaluations += N as u64;
                let jac = finite_difference_jacobian(f, t, y, fy);
                let ft = if autonomous {
                    [0.0; N]
                } else {
                    evaluations += 1;
                    finite_difference_time_derivative(f, t, y, fy)
                };
                (jac, ft)
            },
            t_limit,
        );
        self.core.evaluations += evaluations;
        result
    }

    /// [`Rosenbrock::step`] with the Jacobian from `jac(f, t, y, f(t, y))`, which
    /// returns `(∂f/∂y, ∂f/∂t)` at `(t, y)` (it may evaluate f; those evaluations are
    /// not counted).
    ///
    /// Each trial step decomposes `W = I/(γh) − J` (a singular W shrinks the step
    /// fourfold), solves the stages, and is accepted when the error norm is at most
    /// 1; a non-finite stage shrinks the step tenfold.
    pub fn step_with_jacobian<F, J>(&mut self, f: &mut F, jac: &mut J, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
        J: FnMut(&mut F, f64, &[f64; N], &[f64; N]) -> (Matrix<N>, [f64; N]),
    {
        self.core.check_limit(t_limit)?;
        let tab = self.scheme.tableau();
        let start = self.step_start_data(f, jac)?;
        let t = start.t;
        let mut non_finite: Option<(f64, f64)> = None;
        loop {
            let (h, last) = self.core.trial_step(t_limit, non_finite, &NAMES)?;
            let Some(w) = Lu::decompose(iteration_matrix(&start.jacobian, tab.gamma, h)) else {
                non_finite.get_or_insert((t + h, f64::NAN));
                self.core.reject(0.25 * h);
                continue;
            };
            let t_new = if last { t_limit } else { t + h };
            let (k, y_new) = match self.stages(f, tab, &start, &w, h, t_new) {
                Ok(trial) => trial,
                Err(bad) => {
                    // A trial step into a region where f is not finite: shrink and
                    // retry.
                    non_finite.get_or_insert((t + h, bad));
                    self.core.reject(0.1 * h);
                    continue;
                }
            };
            let err = self.error_norm(&k[tab.stages - 1], &y_new);
            if !err.is_finite() {
                self.core.reject(0.1 * h);
                continue;
            }
            let exponent = 1.0 / f64::from(tab.order);
            let fac = (err.powf(exponent) / SAFE).clamp(FAC_MIN, FAC_MAX);
            if err <= 1.0 {
                self.accept(tab, h, err, fac, &k, t_new, y_new);
                return Ok(());
            }
            let h_next = if self.core.accepted == 0 && self.core.last_rejected {
                0.1 * h
            } else {
                h / fac
            };
            self.core.reject(h_next);
        }
    }

    /// The current point, f there (evaluated once per accepted step) and the
    /// Jacobians from `jac`.
    fn step_start_data<F, J>(&mut self, f: &mut F, jac: &mut J) -> Result<StepStart<N>>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
        J: FnMut(&mut F, f64, &[f64; N], &[f64; N]) -> (Matrix<N>, [f64; N]),
    {
        let (t, y) = (self.core.t, self.core.y);
        let dy = match self.dy {
            Some(d) => d,
            None => {
                let d = self.core.eval_current(f)?;
                self.dy = Some(d);
                d
            }
        };
        let (jacobian, ft) = jac(f, t, &y, &dy);
        Ok(StepStart {
            t,
            y,
            dy,
            jacobian,
            ft,
        })
    }

    /// The stage increments of a trial step of size `h` ending at `t_new`, with
    /// the decomposed iteration matrix `w`, and the new state `y_new = u_s + k_s`;
    /// `Err` with the first non-finite value of f or of `y_new`.
    fn stages<F>(
        &mut self,
        f: &mut F,
        tab: &Tableau,
        start: &StepStart<N>,
        w: &Lu<N>,
        h: f64,
        t_new: f64,
    ) -> std::result::Result<(Stages<N>, [f64; N]), f64>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        let (t, y) = (start.t, start.y);
        let mut k = [[0.0; N]; 8];
        let mut u = y;
        for i in 0..tab.stages {
            // Stage input u_i and f there.
            let fi = if i == 0 {
                start.dy
            } else {
                if i < tab.explicit {
                    u = y;
                    for j in 0..i {
                        for n in 0..N {
                            u[n] += tab.a[i][j] * k[j][n];
                        }
                    }
                } else {
                    for n in 0..N {
                        u[n] += k[i - 1][n];
                    }
                }
                let ti = if tab.c[i] == 1.0 {
                    t_new
                } else {
                    t + tab.c[i] * h
                };
                self.core.eval(f, ti, &u)
            };
            if let Some(bad) = first_non_finite(&fi) {
                return Err(bad);
            }
            // Right-hand side f_i + h d_i ∂f/∂t + Σ_{j<i} (C_ij/h) k_j.
            let mut b = fi;
            for n in 0..N {
                b[n] += h * tab.d[i] * start.ft[n];
                for j in 0..i {
                    b[n] += tab.c_mat[i][j] / h * k[j][n];
                }
            }
            k[i] = w.solve(&b);
        }
        let mut y_new = u;
        for n in 0..N {
            y_new[n] += k[tab.stages - 1][n];
        }
        match first_non_finite(&y_new) {
            Some(bad) => Err(bad),
            None => Ok((k, y_new)),
        }
    }

    /// The root-mean-square of the error estimate `k_s` over the error scales.
    fn error_norm(&self, estimate: &[f64; N], y_new: &[f64; N]) -> f64 {
        let y = &self.core.y;
        let m = self.core.controlled();
        let mut err = 0.0;
        for n in 0..m {
            err += (estimate[n] / self.core.scale(y[n], y_new[n])).powi(2);
        }
        (err / m.max(1) as f64).sqrt()
    }

    /// Accepts a step of size `h` with error `err` and controller factor `fac`
    /// (`h / h_new`, raised by the predictive (Gustafsson) controller as in
    /// `RODAS`); stores the dense-output coefficients.
    #[allow(clippy::too_many_arguments)]
    fn accept(
        &mut self,
        tab: &Tableau,
        h: f64,
        err: f64,
        mut fac: f64,
        k: &Stages<N>,
        t_new: f64,
        y_new: [f64; N],
    ) {
        if self.core.accepted > 0 && self.h_accepted > 0.0 {
            let exponent = 1.0 / f64::from(tab.order);
            let gus = (self.h_accepted / h) * (err * err / self.err_accepted).powf(exponent) / SAFE;
            fac = fac.max(gus.clamp(FAC_MIN, FAC_MAX));
        }
        self.h_accepted = h;
        self.err_accepted = err.max(1e-2);
        for r in 0..3 {
            for n in 0..N {
                self.cont[r][n] = (0..tab.stages).map(|j| tab.h[r][j] * k[j][n]).sum();
            }
        }
        self.y_old = self.core.y;
        self.dy = None;
        self.core.accept(h, t_new, y_new, h / fac);
    }

    /// The dense output (continuous extension of order 4 for Rodas5P, 3 for
    /// RODAS4) of the last accepted step at time `t`, which should lie in
    /// `[previous_t, t]` (outside it the polynomial is extrapolated). Right after a
    /// (re)start it returns the current state.
    pub fn dense_output(&self, t: f64) -> [f64; N] {
        let Some(s) = self.core.theta(t) else {
            return self.core.y;
        };
        let s1 = 1.0 - s;
        let (k, y) = (&self.cont, &self.core.y);
        let mut out = [0.0; N];
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.y_old[i] * s1 + s * (y[i] + s1 * (k[0][i] + s * (k[1][i] + s * k[2][i])));
        }
        out
    }
}

one_step_method!(Rosenbrock);

/// Integrates `y' = f(t, y)` from `(t0, y0)` with Rodas5P (Jacobian strategy
/// `jacobian`) until the event function `g(t, y)` crosses zero in `direction`, or
/// until `t_end` when it does not: the driver [`drive`](crate::ode::drive) with this stepper, as
/// [`crate::ode::solve_until_event`] with Dormand-Prince.
#[allow(clippy::too_many_arguments)]
pub fn solve_until_event<F, G, const N: usize>(
    mut f: F,
    mut g: G,
    direction: EventDirection,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    tol: OdeTolerance,
    jacobian: Jacobian,
) -> Result<OdeSolution<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> f64,
{
    finite("t_end", t_end)?;
    let mut stepper = Rosenbrock::new(&mut f, t0, y0, t_end, tol, jacobian, Scheme::Rodas5P)?;
    drive_unobserved(&mut stepper, &mut f, &mut g, direction, t_end)
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` to `t_end` > `t0` with Rodas5P.
pub fn solve<F, const N: usize>(
    f: F,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    tol: OdeTolerance,
    jacobian: Jacobian,
) -> Result<OdeSolution<N>>
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
{
    solve_until_event(
        f,
        no_event,
        EventDirection::Falling,
        t0,
        y0,
        t_end,
        tol,
        jacobian,
    )
}

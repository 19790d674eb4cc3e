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

#![allow(clippy::needless_range_loop)] // component loops over small fixed arrays

use crate::ode::{
    drive_until_event, finite, first_non_finite, locate_event_in_step, restart_span, DenseStepper,
    EventDirection, EventPoint, OdeSolution, OdeTolerance,
};
use crate::{Cost, NumericsError, Result};

/// A Rosenbrock method in the W-transformed form used by `RODAS` and Julia's
/// `OrdinaryDiffEq`: with `W = I/(γh) − J`, stage i solves
/// `W k_i = f(t + c_i h, u_i) + h d_i ∂f/∂t + Σ_{j<i} (C_ij/h) k_j`, where
/// `u_i = y + Σ_{j<i} a_ij k_j` for `i ≤ explicit` and `u_i = u_{i−1} + k_{i−1}`
/// beyond; `y_new = u_s + k_s`, and `k_s` is the error estimate. Dense output:
/// `y(θ) = (1−θ) y + θ (y_new + (1−θ) (K_1 + θ (K_2 + θ K_3)))`, `K_r = Σ_j H_rj k_j`.
struct Tableau {
    stages: usize,
    /// Stages whose input is given by `a` (the later ones chain `u + k`).
    explicit: usize,
    gamma: f64,
    /// `a[i][j]`, i < explicit (row 0 unused).
    a: [[f64; 8]; 8],
    /// `C[i][j]`, j < i.
    c_mat: [[f64; 8]; 8],
    /// Stage times (fractions of h).
    c: [f64; 8],
    /// Coefficients of `h ∂f/∂t`.
    d: [f64; 8],
    /// Dense-output weights.
    h: [[f64; 8]; 3],
    /// Order of the scheme (the error estimate is of order `order − 1`).
    order: i32,
}

/// RODAS4 (Hairer & Wanner, `RODCOE`, `METH = 1`).
const RODAS4: Tableau = Tableau {
    stages: 6,
    explicit: 5,
    gamma: 0.25,
    a: [
        [0.0; 8],
        [0.154_4e1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [
            0.946_678_528_081_582_6,
            0.255_701_169_898_328_4,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            0.331_482_518_706_852_1e1,
            0.289_612_401_597_220_1e1,
            0.998_641_913_997_781_7,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            0.122_122_450_922_664_1e1,
            0.601_913_448_128_862_9e1,
            0.125_370_833_293_208_7e2,
            -0.687_886_036_105_895,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [0.0; 8],
        [0.0; 8],
        [0.0; 8],
    ],
    c_mat: [
        [0.0; 8],
        [-0.566_88e1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [
            -0.243_009_335_683_387_5e1,
            -0.206_359_915_709_191_5,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            -0.107_352_905_815_137_5,
            -0.959_456_225_102_335_5e1,
            -0.204_702_861_480_961_6e2,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            0.749_644_331_396_764_7e1,
            -0.102_468_043_146_435_2e2,
            -0.339_999_035_281_990_5e2,
            0.117_089_089_320_616e2,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            0.808_324_679_592_152_2e1,
            -0.798_113_298_806_489_3e1,
            -0.315_215_943_287_437_1e2,
            0.163_193_054_312_313_6e2,
            -0.605_881_823_883_405_4e1,
            0.0,
            0.0,
            0.0,
        ],
        [0.0; 8],
        [0.0; 8],
    ],
    c: [0.0, 0.386, 0.21, 0.63, 1.0, 1.0, 0.0, 0.0],
    d: [
        0.25,
        -0.1043,
        0.1035,
        -0.362_000_000_000_002_3e-1,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    h: [
        [
            0.101_262_350_834_458_6e2,
            -0.748_799_587_761_016_7e1,
            -0.348_009_186_155_574_7e2,
            -0.799_277_170_756_882_3e1,
            0.102_513_772_329_566_2e1,
            0.0,
            0.0,
            0.0,
        ],
        [
            -0.676_280_339_280_125_3,
            0.608_771_465_168_001_5e1,
            0.164_308_432_089_247_8e2,
            0.247_672_251_141_838_6e2,
            -0.659_438_912_571_687_2e1,
            0.0,
            0.0,
            0.0,
        ],
        [0.0; 8],
    ],
    order: 4,
};

/// Rodas5P (Steinebach 2023; Julia `OrdinaryDiffEq`, `Rodas5PTableau`).
const RODAS5P: Tableau = Tableau {
    stages: 8,
    explicit: 6,
    gamma: 0.211_937_563_194_290_14,
    a: [
        [0.0; 8],
        [3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [
            2.849_394_379_747_939,
            0.458_422_422_044_639_23,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            -6.954_028_509_809_101,
            2.489_845_061_869_568,
            -10.358_996_098_473_584,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            2.802_998_627_562_896_4,
            0.507_246_473_622_820_6,
            -0.398_831_254_177_052_4,
            -0.047_211_872_304_046_41,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            -7.502_846_399_306_121,
            2.561_846_144_803_919,
            -11.627_539_656_261_098,
            -0.182_687_676_599_422_56,
            0.030_198_172_008_377_946,
            0.0,
            0.0,
            0.0,
        ],
        [0.0; 8],
        [0.0; 8],
    ],
    c_mat: [
        [0.0; 8],
        [-14.155_112_264_123_755, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [
            -17.972_960_358_859_52,
            -2.859_693_295_451_294,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            147.121_502_757_117_16,
            -1.412_214_027_182_13,
            71.689_402_513_023_58,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            165.435_170_248_716_76,
            -0.459_282_345_649_112_6,
            42.909_383_369_586_03,
            -5.961_986_721_573_306,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            24.854_864_614_690_072,
            -3.000_922_700_283_218_6,
            47.493_111_002_076_8,
            5.581_419_782_155_812_5,
            -0.661_069_182_524_947_1,
            0.0,
            0.0,
            0.0,
        ],
        [
            30.912_732_140_285_99,
            -3.120_824_334_993_797_4,
            77.799_546_460_708_92,
            34.286_460_282_947_83,
            -19.097_331_116_725_623,
            -28.087_943_162_872_662,
            0.0,
            0.0,
        ],
        [
            37.802_771_233_905_63,
            -3.257_196_902_907_227_6,
            112.269_188_494_963_27,
            66.934_723_124_404_7,
            -40.066_189_370_910_02,
            -54.667_802_628_779_68,
            -9.488_616_523_096_27,
            0.0,
        ],
    ],
    c: [
        0.0,
        0.635_812_689_582_870_4,
        0.409_579_839_339_753_5,
        0.976_930_672_506_071_6,
        0.428_840_360_955_866_4,
        1.0,
        1.0,
        1.0,
    ],
    d: [
        0.211_937_563_194_290_14,
        -0.423_875_126_388_580_27,
        -0.338_462_712_623_592_4,
        1.804_645_287_288_273_4,
        2.325_825_639_765_069,
        0.0,
        0.0,
        0.0,
    ],
    h: [
        [
            25.948_786_856_663_858,
            -2.557_972_484_584_623_5,
            10.433_815_404_888_879,
            -2.367_925_102_268_520_4,
            0.524_948_541_321_073,
            1.124_108_831_045_040_4,
            0.427_287_619_443_187_4,
            -0.172_022_210_701_554_93,
        ],
        [
            -9.915_688_506_951_71,
            -0.968_994_459_411_515_4,
            3.043_803_724_297_845_3,
            -24.495_224_566_215_796,
            20.176_138_334_709_044,
            15.980_663_614_246_51,
            -6.789_040_303_419_874,
            -6.710_236_069_923_372,
        ],
        [
            11.419_903_575_922_262,
            2.887_964_514_613_699_4,
            72.921_379_959_960_29,
            80.125_118_346_226_43,
            -52.072_871_366_152_654,
            -59.789_936_252_667_29,
            -0.155_826_842_827_519_13,
            4.883_087_185_713_722,
        ],
    ],
    order: 5,
};

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

/// A square matrix `m[row][column]`.
pub type Matrix<const N: usize> = [[f64; N]; N];

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

/// LU decomposition with partial pivoting of a small matrix, in place; `None` if
/// it is singular (or not finite).
fn lu_decompose<const N: usize>(a: &mut Matrix<N>) -> Option<[usize; N]> {
    let mut perm = [0usize; N];
    for (i, p) in perm.iter_mut().enumerate() {
        *p = i;
    }
    for k in 0..N {
        let mut pivot = k;
        for i in k + 1..N {
            if a[i][k].abs() > a[pivot][k].abs() {
                pivot = i;
            }
        }
        if !(a[pivot][k].is_finite() && a[pivot][k] != 0.0) {
            return None;
        }
        a.swap(k, pivot);
        perm.swap(k, pivot);
        for i in k + 1..N {
            let m = a[i][k] / a[k][k];
            a[i][k] = m;
            for j in k + 1..N {
                a[i][j] -= m * a[k][j];
            }
        }
    }
    Some(perm)
}

/// Solves `LU x = P b` for the decomposition of [`lu_decompose`].
fn lu_solve<const N: usize>(lu: &Matrix<N>, perm: &[usize; N], b: &[f64; N]) -> [f64; N] {
    let mut x = [0.0; N];
    for i in 0..N {
        x[i] = b[perm[i]];
    }
    for i in 0..N {
        for j in 0..i {
            x[i] -= lu[i][j] * x[j];
        }
    }
    for i in (0..N).rev() {
        for j in i + 1..N {
            x[i] -= lu[i][j] * x[j];
        }
        x[i] /= lu[i][i];
    }
    x
}

/// A Rosenbrock stepper ([`Scheme`]): integrates `y' = f(t, y)` one accepted step
/// at a time, forwards in time.
///
/// As for [`DormandPrince`](crate::ode::DormandPrince): keep the same right-hand
/// side between [`Rosenbrock::new`] / [`Rosenbrock::restart`] and the following
/// steps, and restart after a discontinuity of f.
#[derive(Clone, Debug)]
pub struct Rosenbrock<const N: usize> {
    scheme: Scheme,
    tol: OdeTolerance,
    jacobian: Jacobian,
    t: f64,
    y: [f64; N],
    /// f(t, y), if evaluated since the last accepted step.
    dy: Option<[f64; N]>,
    /// Start of the last accepted step and the state there.
    t_old: f64,
    y_old: [f64; N],
    /// Proposed next step size.
    h: f64,
    /// Length of the last accepted step (0 before the first).
    h_last: f64,
    /// Dense-output coefficients K_1, K_2, K_3 of the last accepted step.
    cont: [[f64; N]; 3],
    /// Size and error of the last accepted step (predictive controller).
    h_accepted: f64,
    err_accepted: f64,
    last_rejected: bool,
    accepted: u64,
    rejected: u64,
    evaluations: u64,
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
        tol.validate()?;
        let mut s = Rosenbrock {
            scheme,
            tol,
            jacobian,
            t: t0,
            y: y0,
            dy: None,
            t_old: t0,
            y_old: y0,
            h: 0.0,
            h_last: 0.0,
            cont: [[0.0; N]; 3],
            h_accepted: 0.0,
            err_accepted: 1e-2,
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
        self.y_old = y;
        self.h_last = 0.0;
        self.cont = [[0.0; N]; 3];
        self.h_accepted = 0.0;
        self.err_accepted = 1e-2;
        self.last_rejected = false;
        let dy = self.eval(f, t, &y);
        if let Some(bad) = first_non_finite(&dy) {
            return Err(NumericsError::NonFinite { at: t, value: bad });
        }
        self.dy = Some(dy);
        let h_max = self.tol.max_step.min(span);
        self.h = match self.tol.initial_step {
            Some(h) => h.min(h_max),
            None => self.initial_step(&dy, h_max),
        };
        Ok(())
    }

    fn eval<F>(&mut self, f: &mut F, t: f64, y: &[f64; N]) -> [f64; N]
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        self.evaluations += 1;
        f(t, y)
    }

    fn scale(&self, a: f64, b: f64) -> f64 {
        self.tol.error_scale(a, b)
    }

    /// A first step from the sizes of y and f (the first guess of Hairer's `HINIT`),
    /// at most `h_max`; 1e-6 (or `h_max`) when that is not informative.
    fn initial_step(&self, dy: &[f64; N], h_max: f64) -> f64 {
        let (mut dnf, mut dny) = (0.0, 0.0);
        for i in 0..N {
            let sk = self.scale(self.y[i], self.y[i]);
            dnf += (dy[i] / sk).powi(2);
            dny += (self.y[i] / sk).powi(2);
        }
        let h = if dnf <= 1e-10 || dny <= 1e-10 {
            1e-6
        } else {
            0.01 * (dny / dnf).sqrt()
        };
        if h.is_finite() && h > 0.0 {
            h.min(h_max)
        } else {
            h_max.min(1e-6)
        }
    }

    /// The method.
    pub fn scheme(&self) -> Scheme {
        self.scheme
    }

    /// Current time (end of the last accepted step).
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn y(&self) -> [f64; N] {
        self.y
    }

    /// Start of the last accepted step (equal to [`Rosenbrock::t`] right after a
    /// (re)start).
    pub fn previous_t(&self) -> f64 {
        self.t_old
    }

    /// Accepted and rejected steps so far.
    pub fn steps(&self) -> (u64, u64) {
        (self.accepted, self.rejected)
    }

    /// Right-hand-side evaluations (`evaluations`, including those of the Jacobian
    /// by differences) and steps, accepted plus rejected (`iterations`), so far.
    pub fn cost(&self) -> Cost {
        Cost::new(self.evaluations, self.accepted + self.rejected)
    }

    /// Takes one accepted step, not beyond `t_limit` (> current time), with the
    /// Jacobian by forward differences ([`Jacobian`]). Rejected trial steps are
    /// retried with a smaller step.
    ///
    /// Errors: [`NumericsError::NonFinite`] when f is not finite at an accepted
    /// point, or stays non-finite while the step shrinks to underflow;
    /// [`NumericsError::NoConvergence`] when the step size underflows or the step
    /// limit is reached.
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
                let mut ft = [0.0; N];
                if !autonomous {
                    evaluations += 1;
                    let dt = (f64::EPSILON * t.abs().max(1e-5)).sqrt();
                    let t1 = t + dt;
                    let f1 = f(t1, y);
                    for i in 0..N {
                        ft[i] = (f1[i] - fy[i]) / (t1 - t);
                    }
                }
                (jac, ft)
            },
            t_limit,
        );
        self.evaluations += evaluations;
        result
    }

    /// [`Rosenbrock::step`] with the Jacobian from `jac(f, t, y, f(t, y))`, which
    /// returns `(∂f/∂y, ∂f/∂t)` at `(t, y)` (it may evaluate f; those evaluations are
    /// not counted).
    pub fn step_with_jacobian<F, J>(&mut self, f: &mut F, jac: &mut J, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
        J: FnMut(&mut F, f64, &[f64; N], &[f64; N]) -> (Matrix<N>, [f64; N]),
    {
        if !(t_limit.is_finite() && t_limit > self.t) {
            return Err(NumericsError::InvalidArgument {
                name: "t_limit",
                value: t_limit,
                requirement: "must be finite and later than the current time",
            });
        }
        const SAFE: f64 = 0.9;
        const FAC_MIN: f64 = 1.0 / 6.0; // largest growth 6
        const FAC_MAX: f64 = 5.0; // largest shrink 1/5
        let tab = self.scheme.tableau();
        let exponent = 1.0 / f64::from(tab.order);
        let (t, y) = (self.t, self.y);
        let dy = match self.dy {
            Some(d) => d,
            None => {
                let d = self.eval(f, t, &y);
                if let Some(bad) = first_non_finite(&d) {
                    return Err(NumericsError::NonFinite { at: t, value: bad });
                }
                self.dy = Some(d);
                d
            }
        };
        let (jacobian, ft) = jac(f, t, &y, &dy);
        let mut non_finite: Option<(f64, f64)> = None;
        loop {
            if self.accepted + self.rejected >= self.tol.max_steps {
                return Err(NumericsError::NoConvergence {
                    method: "Rosenbrock: step limit reached",
                    iterations: self.accepted + self.rejected,
                    estimate: self.t,
                    error: self.h,
                });
            }
            let remaining = t_limit - t;
            let mut h = self.h.min(self.tol.max_step);
            let last = h >= remaining * (1.0 - 4.0 * f64::EPSILON);
            if last {
                h = remaining;
            }
            let h_min = 16.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE);
            if h <= h_min && !last {
                return Err(match non_finite {
                    Some((at, value)) => NumericsError::NonFinite { at, value },
                    None => NumericsError::NoConvergence {
                        method: "Rosenbrock: step size underflow",
                        iterations: self.accepted + self.rejected,
                        estimate: t,
                        error: h,
                    },
                });
            }
            // W = I/(γh) − J.
            let mut w = jacobian;
            for i in 0..N {
                for j in 0..N {
                    w[i][j] = -w[i][j];
                }
                w[i][i] += 1.0 / (tab.gamma * h);
            }
            let Some(perm) = lu_decompose(&mut w) else {
                non_finite.get_or_insert((t + h, f64::NAN));
                self.rejected += 1;
                self.h = 0.25 * h;
                self.last_rejected = true;
                continue;
            };
            let t_new = if last { t_limit } else { t + h };
            let mut k = [[0.0; N]; 8];
            let mut u = y;
            let mut bad = None;
            for i in 0..tab.stages {
                // Stage input u_i and f there.
                let fi = if i == 0 {
                    dy
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
                    self.eval(f, ti, &u)
                };
                if let Some(v) = first_non_finite(&fi) {
                    bad = Some(v);
                    break;
                }
                let mut b = fi;
                for n in 0..N {
                    b[n] += h * tab.d[i] * ft[n];
                    for j in 0..i {
                        b[n] += tab.c_mat[i][j] / h * k[j][n];
                    }
                }
                k[i] = lu_solve(&w, &perm, &b);
            }
            let last_stage = tab.stages - 1;
            let mut y_new = u;
            for n in 0..N {
                y_new[n] += k[last_stage][n];
            }
            if bad.is_none() {
                bad = first_non_finite(&y_new);
            }
            if let Some(bad) = bad {
                // A trial step into a region where f is not finite: shrink and retry.
                non_finite.get_or_insert((t + h, bad));
                self.rejected += 1;
                self.h = 0.1 * h;
                self.last_rejected = true;
                continue;
            }
            let mut err = 0.0;
            for n in 0..N {
                err += (k[last_stage][n] / self.scale(y[n], y_new[n])).powi(2);
            }
            let err = (err / N.max(1) as f64).sqrt();
            if !err.is_finite() {
                self.rejected += 1;
                self.h = 0.1 * h;
                self.last_rejected = true;
                continue;
            }
            let mut fac = (err.powf(exponent) / SAFE).clamp(FAC_MIN, FAC_MAX);
            if err <= 1.0 {
                if self.accepted > 0 && self.h_accepted > 0.0 {
                    // Predictive controller (Gustafsson), as in RODAS.
                    let gus = (self.h_accepted / h)
                        * (err * err / self.err_accepted).powf(exponent)
                        / SAFE;
                    fac = fac.max(gus.clamp(FAC_MIN, FAC_MAX));
                }
                let mut h_new = h / fac;
                if self.last_rejected {
                    h_new = h_new.min(h);
                }
                self.h_accepted = h;
                self.err_accepted = err.max(1e-2);
                for r in 0..3 {
                    for n in 0..N {
                        self.cont[r][n] = (0..tab.stages).map(|j| tab.h[r][j] * k[j][n]).sum();
                    }
                }
                self.y_old = y;
                self.t_old = t;
                self.h_last = t_new - t;
                self.t = t_new;
                self.y = y_new;
                self.dy = None;
                self.h = h_new.min(self.tol.max_step);
                self.accepted += 1;
                self.last_rejected = false;
                return Ok(());
            }
            self.rejected += 1;
            self.h = if self.accepted == 0 && self.last_rejected {
                0.1 * h
            } else {
                h / fac
            };
            self.last_rejected = true;
        }
    }

    /// The dense output (continuous extension of order 4 for Rodas5P, 3 for
    /// RODAS4) of the last accepted step at time `t`, which should lie in
    /// `[previous_t, t]` (outside it the polynomial is extrapolated). Right after a
    /// (re)start it returns the current state.
    pub fn dense_output(&self, t: f64) -> [f64; N] {
        if self.h_last <= 0.0 {
            return self.y;
        }
        let s = (t - self.t_old) / self.h_last;
        let s1 = 1.0 - s;
        let k = &self.cont;
        let mut out = [0.0; N];
        for (i, o) in out.iter_mut().enumerate() {
            *o =
                self.y_old[i] * s1 + s * (self.y[i] + s1 * (k[0][i] + s * (k[1][i] + s * k[2][i])));
        }
        out
    }

    /// Searches the last accepted step for a crossing of the event function `g` in
    /// `direction`, given its values `g_before` at the start and `g_after` at the end
    /// of the step; as [`DormandPrince::locate_event`](crate::ode::DormandPrince::locate_event).
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

/// Integrates `y' = f(t, y)` from `(t0, y0)` with Rodas5P (Jacobian strategy
/// `jacobian`) until the event function `g(t, y)` crosses zero in `direction`, or
/// until `t_end` when it does not; as [`crate::ode::solve_until_event`].
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
    let stepper = Rosenbrock::new(&mut f, t0, y0, t_end, tol, jacobian, Scheme::Rodas5P)?;
    drive_until_event(stepper, &mut f, &mut g, direction, t0, y0, t_end)
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
        |_: f64, _: &[f64; N]| 1.0,
        EventDirection::Falling,
        t0,
        y0,
        t_end,
        tol,
        jacobian,
    )
}

impl<const N: usize> DenseStepper<N> for Rosenbrock<N> {
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

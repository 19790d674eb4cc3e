//! Quadrature: adaptive Clenshaw-Curtis for smooth integrands, tanh-sinh for
//! integrands with endpoint singularities, fixed Gauss-Legendre rules for hot loops.
//!
//! Clenshaw-Curtis is the `quadrature` crate's `clenshaw_curtis::integrate`, made
//! adaptive by interval bisection (the crate stops at 257 points). For endpoint
//! singularities the crate's double-exponential rule is not used: its abscissas are
//! stored as `x ∈ [-1, 1]` and mapped by `c x + d`, which rounds the points next to
//! the endpoints, so `∫₀¹ x^(-1/2) dx` comes out 2.6e-7 low with an error estimate of
//! 3e-8 (see the test `crate_de_rule_is_not_enough_for_singular_endpoints`). The
//! tanh-sinh rule here computes the distance of each node to its endpoint directly.

use crate::error::require_finite;
use crate::{Cost, NumericsError, Result};
use std::cell::Cell;

/// When an integral is accurate enough: error estimate ≤ `max(absolute, relative·|I|)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadTolerance {
    /// Absolute tolerance (≥ 0).
    pub absolute: f64,
    /// Relative tolerance (≥ 0).
    pub relative: f64,
}

impl QuadTolerance {
    /// A purely relative tolerance.
    pub fn relative(relative: f64) -> Self {
        QuadTolerance {
            absolute: 0.0,
            relative,
        }
    }
    /// A purely absolute tolerance.
    pub fn absolute(absolute: f64) -> Self {
        QuadTolerance {
            absolute,
            relative: 0.0,
        }
    }
    fn validate(&self) -> Result<()> {
        crate::error::require_tolerances(self.absolute, self.relative)?;
        if self.absolute == 0.0 && self.relative == 0.0 {
            return Err(NumericsError::InvalidArgument {
                name: "tolerance",
                value: 0.0,
                requirement: "absolute or relative tolerance must be > 0",
            });
        }
        Ok(())
    }
    fn target(&self, integral: f64) -> f64 {
        self.absolute
            .max(self.relative * integral.abs())
            .max(f64::MIN_POSITIVE)
    }
}

impl Default for QuadTolerance {
    /// Relative [`DEFAULT_TOLERANCE`](crate::tolerance::DEFAULT_TOLERANCE) (1e-12).
    fn default() -> Self {
        QuadTolerance::relative(crate::tolerance::DEFAULT_TOLERANCE)
    }
}

/// An integral with its error estimate and what it cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integral {
    /// The value of the integral.
    pub value: f64,
    /// An estimate of the absolute error.
    pub error_estimate: f64,
    /// Integrand evaluations spent.
    pub evaluations: u64,
    /// Subintervals (Clenshaw-Curtis) or refinement levels (tanh-sinh) used.
    pub iterations: u64,
}

impl Integral {
    /// The cost of this integral as a [`Cost`].
    pub fn cost(&self) -> Cost {
        Cost::new(self.evaluations, self.iterations)
    }
}

fn check_interval(a: f64, b: f64) -> Result<()> {
    require_finite("lower integration limit", a)?;
    require_finite("upper integration limit", b)?;
    Ok(())
}

/// Wraps an integrand so that evaluations are counted and the first non-finite
/// value is remembered (the `quadrature` crate silently replaces them by 0).
struct Watched<F> {
    f: F,
    evaluations: Cell<u64>,
    non_finite: Cell<Option<(f64, f64)>>,
}

impl<F: Fn(f64) -> f64> Watched<F> {
    fn new(f: F) -> Self {
        Watched {
            f,
            evaluations: Cell::new(0),
            non_finite: Cell::new(None),
        }
    }
    fn eval(&self, x: f64) -> f64 {
        self.evaluations.set(self.evaluations.get() + 1);
        let y = (self.f)(x);
        if !y.is_finite() && self.non_finite.get().is_none() {
            self.non_finite.set(Some((x, y)));
        }
        y
    }
    fn check(&self) -> Result<()> {
        match self.non_finite.get() {
            Some((at, value)) => Err(NumericsError::NonFinite { at, value }),
            None => Ok(()),
        }
    }
}

/// Maximum number of subintervals for adaptive Clenshaw-Curtis.
const MAX_SUBINTERVALS: usize = 2000;

/// Integrates a smooth function over `[a, b]` with adaptive Clenshaw-Curtis.
///
/// The whole interval is tried first with the crate's nested rule (up to 257
/// points); where its error estimate misses the target the interval is bisected,
/// each half receiving its share of the tolerance. A reversed interval gives the
/// negated integral.
pub fn integrate_smooth<F>(f: F, a: f64, b: f64, tol: QuadTolerance) -> Result<Integral>
where
    F: Fn(f64) -> f64,
{
    tol.validate()?;
    check_interval(a, b)?;
    if a > b {
        return integrate_smooth(f, b, a, tol).map(|i| Integral {
            value: -i.value,
            ..i
        });
    }
    if a == b {
        return Ok(Integral {
            value: 0.0,
            error_estimate: 0.0,
            evaluations: 0,
            iterations: 0,
        });
    }
    let w = Watched::new(f);
    let rule = |lo: f64, hi: f64, target: f64| {
        quadrature::clenshaw_curtis::integrate(|x| w.eval(x), lo, hi, target)
    };
    // A coarse first pass sets the scale for the relative tolerance.
    let coarse = rule(a, b, f64::MAX);
    w.check()?;
    let mut target = tol.target(coarse.integral);
    let first = rule(a, b, target);
    w.check()?;
    target = tol.target(first.integral);
    // Stack of (lo, hi, estimate, error).
    let mut done_value = 0.0;
    let mut done_error = 0.0;
    let mut pending = vec![(a, b, first.integral, first.error_estimate)];
    let mut intervals = 1usize;
    let width = (b - a).abs();
    while let Some((lo, hi, value, error)) = pending.pop() {
        let share = target * ((hi - lo).abs() / width);
        if error <= share || intervals >= MAX_SUBINTERVALS {
            done_value += value;
            done_error += error;
            continue;
        }
        let mid = 0.5 * (lo + hi);
        if mid == lo || mid == hi {
            done_value += value;
            done_error += error;
            continue;
        }
        let left = rule(lo, mid, 0.5 * share);
        let right = rule(mid, hi, 0.5 * share);
        w.check()?;
        intervals += 1;
        pending.push((lo, mid, left.integral, left.error_estimate));
        pending.push((mid, hi, right.integral, right.error_estimate));
    }
    let result = Integral {
        value: done_value,
        error_estimate: done_error,
        evaluations: w.evaluations.get(),
        iterations: intervals as u64,
    };
    // An integral that overflows (huge interval or integrand) is no result either.
    if !done_value.is_finite() || !done_error.is_finite() || done_error > tol.target(done_value) {
        return Err(NumericsError::NoConvergence {
            method: "adaptive Clenshaw-Curtis",
            iterations: intervals as u64,
            estimate: done_value,
            error: done_error,
        });
    }
    Ok(result)
}

/// Largest parameter of the tanh-sinh transformation: at t = 6.1 the node next to an
/// endpoint lies at a distance of about 1e-300 of the half-width, so even
/// `x^(-0.9)` loses no visible mass near the singular end.
const T_MAX: f64 = 6.1;
/// Step of the coarsest tanh-sinh level.
const H0: f64 = 0.5;
/// Refinement levels of tanh-sinh (step `H0 · 2^-level`).
const MAX_LEVEL: u32 = 10;
/// Terms below this fraction of the coarse sum end the tail of the node sequence.
const TAIL: f64 = 1e-20;

/// Integrates `f` over `[a, b]` with the tanh-sinh (double-exponential) rule,
/// suited to integrable singularities at one or both endpoints.
///
/// The nodes next to an endpoint are placed at `a + c·δ` and `b − c·δ` with the
/// distance `δ` computed without cancellation, so a singularity located exactly at
/// a representable endpoint where the integrand is written in `x` (such as
/// `x^(-1/2)` at 0) is resolved to full accuracy. For a singularity at an endpoint
/// `b ≠ 0`, `1 − x` computed from `x` has lost its digits: use
/// [`integrate_singular_by_distance`], which hands the integrand the distances.
/// The step is halved until two successive levels agree within the tolerance; the
/// reported error estimate is that difference (the true error is typically far
/// smaller, since the rule converges quadratically).
pub fn integrate_singular<F>(f: F, a: f64, b: f64, tol: QuadTolerance) -> Result<Integral>
where
    F: Fn(f64) -> f64,
{
    // Nodes that round onto an endpoint carry a weight below 1e-60 of the total;
    // skip them instead of evaluating a possibly singular f there.
    integrate_singular_by_distance(
        |x, _, _| if x == a || x == b { 0.0 } else { f(x) },
        a,
        b,
        tol,
    )
}

/// Tanh-sinh quadrature of `f(x, x − a, b − x)` over `[a, b]`: the integrand receives
/// each node together with its distances to both endpoints, computed without
/// cancellation, so singularities such as `1/√((x − a)(b − x))` are resolved to full
/// accuracy at both ends. Otherwise as [`integrate_singular`].
pub fn integrate_singular_by_distance<F>(
    f: F,
    a: f64,
    b: f64,
    tol: QuadTolerance,
) -> Result<Integral>
where
    F: Fn(f64, f64, f64) -> f64,
{
    tol.validate()?;
    check_interval(a, b)?;
    if a > b {
        return tanh_sinh(|x, da, db| f(x, db, da), b, a, tol).map(|i| Integral {
            value: -i.value,
            ..i
        });
    }
    tanh_sinh(f, a, b, tol)
}

/// Tanh-sinh on `[a, b]` with `a <= b`.
fn tanh_sinh<F>(f: F, a: f64, b: f64, tol: QuadTolerance) -> Result<Integral>
where
    F: Fn(f64, f64, f64) -> f64,
{
    if a == b {
        return Ok(Integral {
            value: 0.0,
            error_estimate: 0.0,
            evaluations: 0,
            iterations: 0,
        });
    }
    let evaluations = Cell::new(0u64);
    let non_finite: Cell<Option<(f64, f64)>> = Cell::new(None);
    let c = 0.5 * (b - a);
    let mid = 0.5 * (a + b);
    let eval = |x: f64, da: f64, db: f64| -> f64 {
        evaluations.set(evaluations.get() + 1);
        let y = f(x, da, db);
        if !y.is_finite() && non_finite.get().is_none() {
            non_finite.set(Some((x, y)));
        }
        y
    };
    let check = || match non_finite.get() {
        Some((at, value)) => Err(NumericsError::NonFinite { at, value }),
        None => Ok(()),
    };
    // Weighted contributions of the two nodes at parameter t > 0: (left, right).
    let pair = |t: f64, want_left: bool, want_right: bool| -> (f64, f64) {
        let u = std::f64::consts::FRAC_PI_2 * t.sinh();
        let e = (-2.0 * u).exp();
        // 1 − tanh(u) = 2e/(1+e); weight = (π/2) cosh(t) sech²(u)
        let delta = c * (2.0 * e / (1.0 + e));
        let weight = std::f64::consts::FRAC_PI_2 * t.cosh() * 4.0 * e / ((1.0 + e) * (1.0 + e));
        if delta <= 0.0 || weight == 0.0 {
            return (0.0, 0.0);
        }
        let xl = a + delta;
        let xr = b - delta;
        let left = if want_left {
            weight * eval(xl, delta, 2.0 * c - delta)
        } else {
            0.0
        };
        let right = if want_right {
            weight * eval(xr, 2.0 * c - delta, delta)
        } else {
            0.0
        };
        (left, right)
    };
    // Coarse level: all nodes up to T_MAX, then cut each tail where its terms
    // become negligible.
    let n0 = (T_MAX / H0).ceil() as usize;
    let centre = std::f64::consts::FRAC_PI_2 * eval(mid, c, c);
    let mut terms = Vec::with_capacity(n0);
    for j in 1..=n0 {
        terms.push(pair(j as f64 * H0, true, true));
    }
    check()?;
    let mut sum = centre + terms.iter().map(|(l, r)| l + r).sum::<f64>();
    let scale = centre.abs() + terms.iter().map(|(l, r)| l.abs() + r.abs()).sum::<f64>();
    let cut = |side: fn(&(f64, f64)) -> f64| -> f64 {
        let last = terms
            .iter()
            .rposition(|t| side(t).abs() > TAIL * scale)
            .map_or(1, |p| p + 2);
        (last as f64 * H0).min(T_MAX)
    };
    let t_left = cut(|t| t.0);
    let t_right = cut(|t| t.1);
    // Sum only up to the tails found above.
    sum -= terms
        .iter()
        .enumerate()
        .map(|(j, (l, r))| {
            let t = (j + 1) as f64 * H0;
            (if t > t_left { *l } else { 0.0 }) + (if t > t_right { *r } else { 0.0 })
        })
        .sum::<f64>();
    let t_max = t_left.max(t_right);
    let mut h = H0;
    let mut value = c * h * sum;
    let mut error = f64::INFINITY;
    for level in 1..=MAX_LEVEL {
        h *= 0.5;
        let mut i = 0u64;
        loop {
            let t = (2 * i + 1) as f64 * h;
            if t > t_max {
                break;
            }
            let (l, r) = pair(t, t <= t_left, t <= t_right);
            sum += l + r;
            i += 1;
        }
        check()?;
        let new_value = c * h * sum;
        error = (new_value - value).abs();
        value = new_value;
        if level >= 2 && error <= tol.target(value) {
            return Ok(Integral {
                value,
                error_estimate: error,
                evaluations: evaluations.get(),
                iterations: u64::from(level),
            });
        }
    }
    Err(NumericsError::NoConvergence {
        method: "tanh-sinh",
        iterations: u64::from(MAX_LEVEL),
        estimate: value,
        error,
    })
}

/// A fixed n-point Gauss-Legendre rule, exact for polynomials of degree 2n − 1.
///
/// For hot loops whose integrand is smooth by construction (the caller has removed
/// singularities by a change of variables). Nodes and weights are computed once by
/// Newton's iteration on the Legendre polynomial, to full double precision.
#[derive(Clone, Debug, PartialEq)]
pub struct GaussLegendre {
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl GaussLegendre {
    /// The rule with `n` points (1 ≤ n ≤ 1000).
    pub fn new(n: usize) -> Result<Self> {
        if n == 0 || n > 1000 {
            return Err(NumericsError::InvalidArgument {
                name: "number of Gauss-Legendre points",
                value: n as f64,
                requirement: "must be between 1 and 1000",
            });
        }
        let mut nodes = vec![0.0; n];
        let mut weights = vec![0.0; n];
        let m = n.div_ceil(2);
        let nf = n as f64;
        for i in 0..m {
            // Tricomi's initial guess, then Newton on P_n.
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (p, d) = legendre_with_derivative(n, x);
                dp = d;
                let dx = p / d;
                x -= dx;
                if dx.abs() <= 1e-16 * x.abs().max(1e-300) {
                    break;
                }
            }
            let (_, d) = legendre_with_derivative(n, x);
            if d.is_finite() {
                dp = d;
            }
            let wgt = 2.0 / ((1.0 - x * x) * dp * dp);
            nodes[i] = -x;
            nodes[n - 1 - i] = x;
            weights[i] = wgt;
            weights[n - 1 - i] = wgt;
        }
        if n % 2 == 1 {
            nodes[n / 2] = 0.0;
        }
        Ok(GaussLegendre { nodes, weights })
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Always false: a rule has at least one point.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Nodes on [−1, 1], ascending.
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// Weights matching [`GaussLegendre::nodes`].
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// Applies the rule to `f` on `[a, b]` (no error estimate; `len()` evaluations).
    pub fn integrate<F: FnMut(f64) -> f64>(&self, mut f: F, a: f64, b: f64) -> f64 {
        let c = 0.5 * (b - a);
        let d = 0.5 * (a + b);
        let mut sum = 0.0;
        for (x, w) in self.nodes.iter().zip(&self.weights) {
            sum += w * f(c * x + d);
        }
        c * sum
    }
}

/// P_n(x) and P_n'(x) by the three-term recurrence.
fn legendre_with_derivative(n: usize, x: f64) -> (f64, f64) {
    let mut p0 = 1.0;
    let mut p1 = x;
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 2..=n {
        let kf = k as f64;
        let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
        p0 = p1;
        p1 = p2;
    }
    let nf = n as f64;
    let dp = nf * (x * p1 - p0) / (x * x - 1.0);
    (p1, dp)
}

/// Two Gauss-Legendre rules of different orders applied to one integrand: the
/// higher rule's value, with its distance to the lower rule's value as the error
/// estimate (conservative: for an integrand analytic on the interval the error of
/// an n-point rule falls geometrically in 2n, so the higher rule is far more
/// accurate than the distance says). `low + high` evaluations, no adaptivity: a
/// first try on smooth integrands before [`integrate_smooth`] (the Maugis-Dugdale
/// loss uses 12 and 16 points).
#[derive(Clone, Debug, PartialEq)]
pub struct GaussLegendrePair {
    low: GaussLegendre,
    high: GaussLegendre,
}

impl GaussLegendrePair {
    /// The rules with `low` and `high` points (1 ≤ low < high ≤ 1000).
    pub fn new(low: usize, high: usize) -> Result<Self> {
        if low >= high {
            return Err(NumericsError::InvalidArgument {
                name: "points of the lower Gauss-Legendre rule",
                value: low as f64,
                requirement: "must be fewer than the points of the higher rule",
            });
        }
        Ok(GaussLegendrePair {
            low: GaussLegendre::new(low)?,
            high: GaussLegendre::new(high)?,
        })
    }

    /// Both rules applied to `f` on `[a, b]`: the value of the higher one and the
    /// estimate `|high − low|`. A non-finite value of `f` is an error naming where.
    pub fn integrate<F: FnMut(f64) -> f64>(&self, mut f: F, a: f64, b: f64) -> Result<Integral> {
        check_interval(a, b)?;
        let mut non_finite = None;
        let mut watched = |x: f64| {
            let y = f(x);
            if !y.is_finite() && non_finite.is_none() {
                non_finite = Some((x, y));
            }
            y
        };
        let low = self.low.integrate(&mut watched, a, b);
        let high = self.high.integrate(&mut watched, a, b);
        if let Some((at, value)) = non_finite {
            return Err(NumericsError::NonFinite { at, value });
        }
        Ok(Integral {
            value: high,
            error_estimate: (high - low).abs(),
            evaluations: (self.low.len() + self.high.len()) as u64,
            iterations: 1,
        })
    }
}

//! Chebyshev interpolation: the precomputed fast tier of expensive smooth functions.
//!
//! [`ChebyshevSeries::fit`] samples a function at the Chebyshev points of the first
//! kind on `[a, b]` and computes the coefficients of the interpolating polynomial by
//! the discrete cosine sums; [`PiecewiseChebyshev::fit`] bisects the interval until
//! the tail of every piece's coefficients is below a tolerance. Evaluation is
//! Clenshaw's recurrence: a handful of multiply-adds, no allocation.

use crate::{Cost, NumericsError};

/// A Chebyshev series `Σ c_k T_k(x̃)` on `[a, b]`, `x̃ = (2x − a − b)/(b − a)`.
#[derive(Clone, Debug, PartialEq)]
pub struct ChebyshevSeries {
    lower: f64,
    upper: f64,
    coefficients: Vec<f64>,
}

impl ChebyshevSeries {
    /// Interpolates `f` at the `n` Chebyshev points of the first kind on
    /// `[lower, upper]` (n ≥ 2). `f` is never evaluated at the endpoints.
    /// A non-finite or failed sample is returned as an error.
    pub fn fit<F, E>(mut f: F, lower: f64, upper: f64, n: usize) -> std::result::Result<Self, E>
    where
        F: FnMut(f64) -> std::result::Result<f64, E>,
        E: From<NumericsError>,
    {
        if !(lower.is_finite() && upper.is_finite() && lower < upper) {
            return Err(E::from(NumericsError::InvalidArgument {
                name: "interval",
                value: upper - lower,
                requirement: "lower < upper, both finite",
            }));
        }
        if !(2..=4096).contains(&n) {
            return Err(E::from(NumericsError::InvalidArgument {
                name: "number of Chebyshev points",
                value: n as f64,
                requirement: "must be between 2 and 4096",
            }));
        }
        let nf = n as f64;
        let half = 0.5 * (upper - lower);
        let mid = 0.5 * (upper + lower);
        let mut values = Vec::with_capacity(n);
        for j in 0..n {
            let x = (std::f64::consts::PI * (j as f64 + 0.5) / nf).cos();
            let y = f(mid + half * x)?;
            if !y.is_finite() {
                return Err(E::from(NumericsError::NonFinite {
                    at: mid + half * x,
                    value: y,
                }));
            }
            values.push(y);
        }
        let mut coefficients = Vec::with_capacity(n);
        for k in 0..n {
            let mut sum = 0.0;
            for (j, y) in values.iter().enumerate() {
                sum += y * (std::f64::consts::PI * k as f64 * (j as f64 + 0.5) / nf).cos();
            }
            let scale = if k == 0 { 1.0 / nf } else { 2.0 / nf };
            coefficients.push(scale * sum);
        }
        Ok(ChebyshevSeries {
            lower,
            upper,
            coefficients,
        })
    }

    /// The interval `[lower, upper]`.
    pub fn interval(&self) -> (f64, f64) {
        (self.lower, self.upper)
    }

    /// The coefficients c_0, c_1, ….
    pub fn coefficients(&self) -> &[f64] {
        &self.coefficients
    }

    /// The magnitude of the last quarter of the coefficients (at least the last
    /// two), relative to the largest: an estimate of the interpolation error.
    pub fn tail(&self) -> f64 {
        let n = self.coefficients.len();
        let start = n - (n / 4).max(2).min(n);
        let tail = self.coefficients[start..]
            .iter()
            .fold(0.0f64, |m, c| m.max(c.abs()));
        let head = self.coefficients.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        if head == 0.0 {
            0.0
        } else {
            tail / head
        }
    }

    /// Evaluates the series at `x` (Clenshaw's recurrence). Outside `[a, b]` the
    /// polynomial is extrapolated; callers keep `x` inside.
    #[inline]
    pub fn eval(&self, x: f64) -> f64 {
        let t = (2.0 * x - self.lower - self.upper) / (self.upper - self.lower);
        let t2 = 2.0 * t;
        let mut b1 = 0.0;
        let mut b2 = 0.0;
        for &c in self.coefficients[1..].iter().rev() {
            let b0 = c + t2 * b1 - b2;
            b2 = b1;
            b1 = b0;
        }
        self.coefficients[0] + t * b1 - b2
    }
}

/// Chebyshev series on consecutive pieces of an interval, each accurate to a
/// relative coefficient tail below the tolerance it was built with.
#[derive(Clone, Debug, PartialEq)]
pub struct PiecewiseChebyshev {
    breaks: Vec<f64>,
    pieces: Vec<ChebyshevSeries>,
    cost: Cost,
}

impl PiecewiseChebyshev {
    /// Fits `f` on `[lower, upper]` with `n` points per piece, bisecting a piece
    /// while its coefficient tail exceeds `tolerance`, up to `max_pieces` pieces.
    pub fn fit<F, E>(
        mut f: F,
        lower: f64,
        upper: f64,
        n: usize,
        tolerance: f64,
        max_pieces: usize,
    ) -> std::result::Result<Self, E>
    where
        F: FnMut(f64) -> std::result::Result<f64, E>,
        E: From<NumericsError>,
    {
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(E::from(NumericsError::InvalidArgument {
                name: "tolerance",
                value: tolerance,
                requirement: "must be finite and > 0",
            }));
        }
        let mut evaluations = 0u64;
        let mut counted = |x: f64| {
            evaluations += 1;
            f(x)
        };
        let mut done: Vec<ChebyshevSeries> = Vec::new();
        let mut todo = vec![(lower, upper)];
        while let Some((a, b)) = todo.pop() {
            let series = ChebyshevSeries::fit(&mut counted, a, b, n)?;
            if series.tail() <= tolerance {
                done.push(series);
            } else if done.len() + todo.len() + 2 > max_pieces {
                return Err(E::from(NumericsError::NoConvergence {
                    method: "piecewise Chebyshev",
                    iterations: max_pieces as u64,
                    estimate: series.coefficients[0],
                    error: series.tail(),
                }));
            } else {
                let m = 0.5 * (a + b);
                // push the right half first so the left half is processed next
                todo.push((m, b));
                todo.push((a, m));
            }
        }
        done.sort_by(|p, q| p.lower.total_cmp(&q.lower));
        let mut breaks: Vec<f64> = done.iter().map(|p| p.lower).collect();
        breaks.push(upper);
        let pieces = done.len() as u64;
        Ok(PiecewiseChebyshev {
            breaks,
            pieces: done,
            cost: Cost::new(evaluations, pieces),
        })
    }

    /// The piece boundaries, ascending (one more than the pieces).
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// The pieces.
    pub fn pieces(&self) -> &[ChebyshevSeries] {
        &self.pieces
    }

    /// What building the interpolant cost (evaluations of `f`, pieces).
    pub fn cost(&self) -> Cost {
        self.cost
    }

    /// Evaluates at `x`; `x` outside the interval is clamped to it.
    #[inline]
    pub fn eval(&self, x: f64) -> f64 {
        let inner = &self.breaks[1..self.breaks.len() - 1];
        let i = inner.partition_point(|&b| b <= x);
        let piece = &self.pieces[i];
        let (a, b) = piece.interval();
        piece.eval(x.clamp(a, b))
    }
}

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

/// A function tabulated on `pieces` equal pieces of `[lower, upper]`: on each, the
/// interpolant at `N` Chebyshev points of the first kind ([`ChebyshevSeries::fit`]),
/// converted to a polynomial of degree `N − 1` in the piece's local coordinate
/// `s ∈ [−1, 1]` and evaluated by Estrin's scheme.
///
/// This is the form for hot loops: the piece is found by one multiplication and a
/// truncation (no search), and Estrin's scheme evaluates the polynomial in about
/// log₂ N dependent multiply-adds instead of the N of Clenshaw's recurrence. The
/// conversion to monomials is well conditioned for the low degrees it is meant for
/// (`N ≤ 16`: the monomial coefficients of `T_k` on `[−1, 1]` sum to at most
/// `(1 + √2)^k`, and the Chebyshev coefficients of a resolved piece decay faster).
/// Trefethen, *Approximation Theory and Approximation Practice*, SIAM 2013 (the
/// interpolant); Knuth, *The Art of Computer Programming* vol. 2, 3rd ed. 1997,
/// section 4.6.4 (Estrin's scheme).
#[derive(Clone, Debug, PartialEq)]
pub struct UniformChebyshevTable<const N: usize> {
    lower: f64,
    upper: f64,
    pieces_per_unit: f64,
    coefficients: Vec<[f64; N]>,
    tail: f64,
    cost: Cost,
}

impl<const N: usize> UniformChebyshevTable<N> {
    /// Fits `f` on `pieces` equal pieces of `[lower, upper]` (1 ≤ pieces ≤ 2²⁰,
    /// 2 ≤ N ≤ 16). Fails when a sample fails or is not finite, and when a piece's
    /// relative coefficient tail ([`ChebyshevSeries::tail`]) exceeds `tolerance`.
    pub fn fit<F, E>(
        mut f: F,
        lower: f64,
        upper: f64,
        pieces: usize,
        tolerance: f64,
    ) -> std::result::Result<Self, E>
    where
        F: FnMut(f64) -> std::result::Result<f64, E>,
        E: From<NumericsError>,
    {
        if !(2..=16).contains(&N) {
            return Err(E::from(NumericsError::InvalidArgument {
                name: "points per piece",
                value: N as f64,
                requirement: "must be between 2 and 16",
            }));
        }
        if !(1..=1 << 20).contains(&pieces) {
            return Err(E::from(NumericsError::InvalidArgument {
                name: "pieces",
                value: pieces as f64,
                requirement: "must be between 1 and 2^20",
            }));
        }
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(E::from(NumericsError::InvalidArgument {
                name: "tolerance",
                value: tolerance,
                requirement: "must be finite and > 0",
            }));
        }
        let width = (upper - lower) / pieces as f64;
        let mut coefficients = Vec::with_capacity(pieces);
        let mut tail: f64 = 0.0;
        for i in 0..pieces {
            let a = lower + width * i as f64;
            let b = if i + 1 == pieces { upper } else { a + width };
            let series = ChebyshevSeries::fit(&mut f, a, b, N)?;
            let piece_tail = series.tail();
            if piece_tail > tolerance {
                return Err(E::from(NumericsError::NoConvergence {
                    method: "uniform Chebyshev table",
                    iterations: i as u64,
                    estimate: series.coefficients[0],
                    error: piece_tail,
                }));
            }
            tail = tail.max(piece_tail);
            coefficients.push(chebyshev_to_monomial(series.coefficients()));
        }
        Ok(UniformChebyshevTable {
            lower,
            upper,
            pieces_per_unit: pieces as f64 / (upper - lower),
            coefficients,
            tail,
            cost: Cost::new((pieces * N) as u64, pieces as u64),
        })
    }

    /// The number of pieces.
    pub fn pieces(&self) -> usize {
        self.coefficients.len()
    }

    /// The interval `[lower, upper]`.
    pub fn interval(&self) -> (f64, f64) {
        (self.lower, self.upper)
    }

    /// The largest relative coefficient tail of the pieces (an estimate of the
    /// interpolation error relative to the function's size on a piece).
    pub fn tail(&self) -> f64 {
        self.tail
    }

    /// What building the table cost (evaluations of `f`, pieces).
    pub fn cost(&self) -> Cost {
        self.cost
    }

    /// Evaluates at `x`; `x` outside the interval (or NaN) is clamped to it.
    #[inline]
    pub fn eval(&self, x: f64) -> f64 {
        let x = x.clamp(self.lower, self.upper);
        let position = (x - self.lower) * self.pieces_per_unit;
        // `as` saturates; the last piece also holds `upper` itself
        let i = (position as usize).min(self.coefficients.len() - 1);
        let s = 2.0 * (position - i as f64) - 1.0;
        estrin(&self.coefficients[i], s)
    }
}

/// The monomial coefficients in `s` of `Σ c_k T_k(s)`.
fn chebyshev_to_monomial<const N: usize>(c: &[f64]) -> [f64; N] {
    let mut out = [0.0; N];
    // T_{k−1}, T_k as monomial coefficients
    let mut previous = [0.0; N];
    let mut current = [0.0; N];
    previous[0] = 1.0;
    if N > 1 {
        current[1] = 1.0;
    }
    for (k, &ck) in c.iter().enumerate().take(N) {
        let t = if k == 0 { &previous } else { &current };
        for (o, ti) in out.iter_mut().zip(t) {
            *o += ck * ti;
        }
        if k >= 1 {
            // T_{k+1} = 2 s T_k − T_{k−1}
            let mut next = [0.0; N];
            for j in 0..N {
                let shifted = if j > 0 { 2.0 * current[j - 1] } else { 0.0 };
                next[j] = shifted - previous[j];
            }
            previous = current;
            current = next;
        }
    }
    out
}

/// `Σ c_i s^i` by Estrin's scheme: pairs `c_2i + c_2i+1 s`, then pairs of those
/// with `s²`, and so on (the loops unroll for a constant N).
#[inline]
fn estrin<const N: usize>(c: &[f64; N], s: f64) -> f64 {
    let mut level = *c;
    let mut len = N;
    let mut power = s;
    while len > 1 {
        let half = len / 2;
        for i in 0..half {
            level[i] = level[2 * i] + power * level[2 * i + 1];
        }
        if len % 2 == 1 {
            level[half] = level[len - 1];
        }
        len = half + len % 2;
        power *= power;
    }
    level[0]
}

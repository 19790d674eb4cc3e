//! Root finding: Brent's method with bracket validation and expansion, and a
//! safeguarded Newton iteration.
//!
//! Brent's method is the `roots` crate's `find_root_brent`, driven by a convergence
//! test that combines an absolute and a relative tolerance on the bracket width and
//! counts iterations. The wrapper validates the bracket first, catches non-finite
//! function values, and returns the best evaluated point.

use crate::error::require_finite;
use crate::{Cost, NumericsError, Result};

/// When a root search may stop: the bracket is narrower than
/// `absolute + relative · |x|`, or the iteration limit is reached (an error).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RootTolerance {
    /// Absolute tolerance on the root (≥ 0).
    pub absolute: f64,
    /// Relative tolerance on the root (≥ 0; values below 2 ε are raised to 2 ε).
    pub relative: f64,
    /// Iteration limit.
    pub max_iterations: u32,
}

impl RootTolerance {
    /// A purely relative tolerance with a generous iteration limit (200).
    pub fn relative(relative: f64) -> Self {
        RootTolerance {
            absolute: 0.0,
            relative,
            max_iterations: 200,
        }
    }

    /// A purely absolute tolerance with a generous iteration limit (200).
    pub fn absolute(absolute: f64) -> Self {
        RootTolerance {
            absolute,
            relative: 0.0,
            max_iterations: 200,
        }
    }

    fn validate(&self) -> Result<()> {
        crate::error::require_tolerances(self.absolute, self.relative)?;
        if self.max_iterations == 0 {
            return Err(NumericsError::InvalidArgument {
                name: "max_iterations",
                value: 0.0,
                requirement: "must be at least 1",
            });
        }
        Ok(())
    }

    fn width(&self, x1: f64, x2: f64) -> f64 {
        let rel = self.relative.max(2.0 * f64::EPSILON);
        self.absolute + rel * x1.abs().max(x2.abs())
    }
}

impl Default for RootTolerance {
    fn default() -> Self {
        RootTolerance::relative(1e-14)
    }
}

/// A root with what it cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Root {
    /// The abscissa where the function changes sign (or vanishes).
    pub value: f64,
    /// Iterations spent.
    pub iterations: u64,
    /// Function evaluations spent.
    pub evaluations: u64,
}

impl Root {
    /// The cost of this search as a [`Cost`].
    pub fn cost(&self) -> Cost {
        Cost::new(self.evaluations, self.iterations)
    }
}

/// The convergence test handed to the `roots` crate.
struct Convergence {
    tol: RootTolerance,
    iterations: usize,
}

impl roots::Convergency<f64> for Convergence {
    fn is_root_found(&mut self, y: f64) -> bool {
        y == 0.0
    }
    fn is_converged(&mut self, x1: f64, x2: f64) -> bool {
        (x1 - x2).abs() <= self.tol.width(x1, x2)
    }
    fn is_iteration_limit_reached(&mut self, iter: usize) -> bool {
        self.iterations = iter;
        iter >= self.tol.max_iterations as usize
    }
}

/// Records every evaluation: the count, the first non-finite value, and the
/// tightest sign-change bracket seen.
struct Recorder {
    evaluations: u64,
    non_finite: Option<(f64, f64)>,
    best: (f64, f64),
}

impl Recorder {
    fn new() -> Self {
        Recorder {
            evaluations: 0,
            non_finite: None,
            best: (f64::NAN, f64::INFINITY),
        }
    }
    fn record(&mut self, x: f64, y: f64) {
        self.evaluations += 1;
        if !y.is_finite() {
            if self.non_finite.is_none() {
                self.non_finite = Some((x, y));
            }
        } else if y.abs() < self.best.1.abs() || self.best.0.is_nan() {
            self.best = (x, y);
        }
    }
}

/// Finds a root of `f` in `[lower, upper]` with Brent's method.
///
/// The bracket is validated first: both ends finite, `f` finite at both ends, and a
/// sign change (or an exact zero) between them; otherwise a typed error.
pub fn brent<F>(mut f: F, lower: f64, upper: f64, tol: RootTolerance) -> Result<Root>
where
    F: FnMut(f64) -> f64,
{
    tol.validate()?;
    require_finite("lower end of bracket", lower)?;
    require_finite("upper end of bracket", upper)?;
    let (lo, hi) = if lower <= upper {
        (lower, upper)
    } else {
        (upper, lower)
    };
    let f_lo = f(lo);
    let f_hi = f(hi);
    for (x, y) in [(lo, f_lo), (hi, f_hi)] {
        if !y.is_finite() {
            return Err(NumericsError::NonFinite { at: x, value: y });
        }
    }
    if f_lo == 0.0 {
        return Ok(Root {
            value: lo,
            iterations: 0,
            evaluations: 2,
        });
    }
    if f_hi == 0.0 {
        return Ok(Root {
            value: hi,
            iterations: 0,
            evaluations: 2,
        });
    }
    if f_lo.signum() == f_hi.signum() {
        return Err(NumericsError::NoBracket {
            lower: lo,
            upper: hi,
            f_lower: f_lo,
            f_upper: f_hi,
        });
    }
    let mut rec = Recorder::new();
    rec.record(lo, f_lo);
    rec.record(hi, f_hi);
    let mut conv = Convergence { tol, iterations: 0 };
    // The crate's iteration evaluates f again at the ends of the bracket it
    // already knows (`arrange(a, f(a), s, f(s))`): the last points used are
    // answered from memory (the least recently used forgotten), so f is
    // evaluated once per new point.
    let mut known = [
        (lo, f_lo, 0u64),
        (hi, f_hi, 1),
        (f64::NAN, f64::NAN, 0),
        (f64::NAN, f64::NAN, 0),
    ];
    let mut clock = 2u64;
    let outcome = roots::find_root_brent(
        lo,
        hi,
        |x| {
            clock += 1;
            let y = match known.iter_mut().find(|(k, ..)| k.to_bits() == x.to_bits()) {
                Some(entry) => {
                    entry.2 = clock;
                    entry.1
                }
                None => {
                    let y = f(x);
                    rec.record(x, y);
                    if let Some(oldest) = known.iter_mut().min_by_key(|e| e.2) {
                        *oldest = (x, y, clock);
                    }
                    y
                }
            };
            if y.is_finite() {
                y
            } else {
                f64::NAN
            }
        },
        &mut conv,
    );
    if let Some((at, value)) = rec.non_finite {
        return Err(NumericsError::NonFinite { at, value });
    }
    match outcome {
        Ok(x) => {
            // The crate may return the previous iterate; prefer the best evaluated
            // point when it is at least as good.
            let (bx, by) = rec.best;
            let value = if by == 0.0 || (bx - x).abs() <= tol.width(bx, x) {
                bx
            } else {
                x
            };
            Ok(Root {
                value,
                iterations: conv.iterations as u64,
                evaluations: rec.evaluations,
            })
        }
        Err(_) => Err(NumericsError::NoConvergence {
            method: "Brent",
            iterations: conv.iterations as u64,
            estimate: rec.best.0,
            error: rec.best.1.abs(),
        }),
    }
}

/// How a bracket may grow until it contains a sign change.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BracketExpansion {
    /// Move the end with the smaller |f| outwards by `factor` times the current width
    /// (Numerical Recipes' `zbrac`), within `[min, max]`.
    Linear {
        /// Growth factor of the width per step (> 0).
        factor: f64,
        /// Lowest abscissa allowed.
        min: f64,
        /// Highest abscissa allowed.
        max: f64,
        /// Number of expansion steps allowed.
        max_steps: u32,
    },
    /// For positive variables (speeds, radii): divide the lower end and multiply the
    /// upper end by `factor`, one end per step, choosing the end with smaller |f|.
    Geometric {
        /// Factor per step (> 1).
        factor: f64,
        /// Number of expansion steps allowed.
        max_steps: u32,
    },
}

impl Default for BracketExpansion {
    fn default() -> Self {
        BracketExpansion::Geometric {
            factor: 4.0,
            max_steps: 200,
        }
    }
}

/// Grows `[lower, upper]` until `f` changes sign across it.
///
/// Returns the bracket and the evaluations spent, or [`NumericsError::NoBracket`] with
/// the last interval tried.
pub fn expand_bracket<F>(
    mut f: F,
    lower: f64,
    upper: f64,
    expansion: BracketExpansion,
) -> Result<(f64, f64, Cost)>
where
    F: FnMut(f64) -> f64,
{
    require_finite("lower end of bracket", lower)?;
    require_finite("upper end of bracket", upper)?;
    let (mut lo, mut hi) = if lower <= upper {
        (lower, upper)
    } else {
        (upper, lower)
    };
    let mut eval = |x: f64, n: &mut u64| -> Result<f64> {
        *n += 1;
        let y = f(x);
        if y.is_finite() {
            Ok(y)
        } else {
            Err(NumericsError::NonFinite { at: x, value: y })
        }
    };
    let mut n = 0u64;
    let mut f_lo = eval(lo, &mut n)?;
    let mut f_hi = eval(hi, &mut n)?;
    let (steps, geometric, factor, min, max) = match expansion {
        BracketExpansion::Linear {
            factor,
            min,
            max,
            max_steps,
        } => (max_steps, false, factor, min, max),
        BracketExpansion::Geometric { factor, max_steps } => {
            if lo <= 0.0 {
                return Err(NumericsError::InvalidArgument {
                    name: "lower end of bracket",
                    value: lo,
                    requirement: "must be > 0 for geometric expansion",
                });
            }
            (max_steps, true, factor, 0.0, f64::MAX)
        }
    };
    if !(factor > 0.0 && factor.is_finite()) || (geometric && factor <= 1.0) {
        return Err(NumericsError::InvalidArgument {
            name: "expansion factor",
            value: factor,
            requirement: "must be finite, > 0 (linear) or > 1 (geometric)",
        });
    }
    for step in 0..=steps {
        if f_lo.signum() != f_hi.signum() || f_lo == 0.0 || f_hi == 0.0 {
            return Ok((lo, hi, Cost::new(n, step as u64)));
        }
        if step == steps {
            break;
        }
        let grow_low = f_lo.abs() < f_hi.abs();
        if geometric {
            if grow_low {
                lo /= factor;
                f_lo = eval(lo, &mut n)?;
            } else {
                hi *= factor;
                if !hi.is_finite() {
                    break;
                }
                f_hi = eval(hi, &mut n)?;
            }
        } else {
            let width = hi - lo;
            let can_low = lo > min;
            let can_high = hi < max;
            if (grow_low && can_low) || !can_high {
                if !can_low {
                    break;
                }
                lo = (lo - factor * width).max(min);
                f_lo = eval(lo, &mut n)?;
            } else {
                hi = (hi + factor * width).min(max);
                f_hi = eval(hi, &mut n)?;
            }
        }
    }
    Err(NumericsError::NoBracket {
        lower: lo,
        upper: hi,
        f_lower: f_lo,
        f_upper: f_hi,
    })
}

/// Expands `[lower, upper]` as [`expand_bracket`] does, then runs [`brent`].
/// The returned cost includes the expansion.
pub fn brent_expanding<F>(
    mut f: F,
    lower: f64,
    upper: f64,
    expansion: BracketExpansion,
    tol: RootTolerance,
) -> Result<Root>
where
    F: FnMut(f64) -> f64,
{
    let (lo, hi, cost) = expand_bracket(&mut f, lower, upper, expansion)?;
    let mut root = brent(&mut f, lo, hi, tol)?;
    root.evaluations += cost.evaluations;
    root.iterations += cost.iterations;
    Ok(root)
}

/// Newton's method safeguarded by bisection inside the bracket `[lower, upper]`.
///
/// `f_df(x)` returns `(f(x), f'(x))`. A Newton step that leaves the current bracket,
/// or does not at least halve |f| every other step, is replaced by bisection, so the
/// method converges whenever the bracket is valid (Numerical Recipes' `rtsafe`).
pub fn newton_safeguarded<F>(
    mut f_df: F,
    lower: f64,
    upper: f64,
    start: f64,
    tol: RootTolerance,
) -> Result<Root>
where
    F: FnMut(f64) -> (f64, f64),
{
    tol.validate()?;
    require_finite("lower end of bracket", lower)?;
    require_finite("upper end of bracket", upper)?;
    require_finite("start", start)?;
    let (mut lo, mut hi) = if lower <= upper {
        (lower, upper)
    } else {
        (upper, lower)
    };
    let mut n = 0u64;
    let mut eval = |x: f64, n: &mut u64| -> Result<(f64, f64)> {
        *n += 1;
        let (y, dy) = f_df(x);
        if !y.is_finite() {
            return Err(NumericsError::NonFinite { at: x, value: y });
        }
        if dy.is_nan() {
            return Err(NumericsError::NonFinite { at: x, value: dy });
        }
        Ok((y, dy))
    };
    let (f_lo, _) = eval(lo, &mut n)?;
    let (f_hi, _) = eval(hi, &mut n)?;
    if f_lo == 0.0 {
        return Ok(Root {
            value: lo,
            iterations: 0,
            evaluations: n,
        });
    }
    if f_hi == 0.0 {
        return Ok(Root {
            value: hi,
            iterations: 0,
            evaluations: n,
        });
    }
    if f_lo.signum() == f_hi.signum() {
        return Err(NumericsError::NoBracket {
            lower: lo,
            upper: hi,
            f_lower: f_lo,
            f_upper: f_hi,
        });
    }
    // Orient so that f(lo) < 0 < f(hi).
    let increasing = f_lo < 0.0;
    let mut x = if start > lo && start < hi {
        start
    } else {
        0.5 * (lo + hi)
    };
    let mut dx_old = hi - lo;
    let mut dx = dx_old;
    let (mut y, mut dy) = eval(x, &mut n)?;
    for iter in 1..=u64::from(tol.max_iterations) {
        if y == 0.0 {
            return Ok(Root {
                value: x,
                iterations: iter,
                evaluations: n,
            });
        }
        // Update the bracket with the current point.
        if (y < 0.0) == increasing {
            lo = x;
        } else {
            hi = x;
        }
        if dy != 0.0 && dy.is_finite() && (y / dy).abs() <= tol.width(x, x) {
            // The Newton correction is below the tolerance: done.
            return Ok(Root {
                value: x - y / dy,
                iterations: iter,
                evaluations: n,
            });
        }
        let newton_ok = dy != 0.0 && dy.is_finite() && {
            let xn = x - y / dy;
            xn > lo && xn < hi && (2.0 * y).abs() <= (dx_old * dy).abs()
        };
        dx_old = dx;
        let x_new = if newton_ok {
            dx = y / dy;
            x - dx
        } else {
            dx = 0.5 * (hi - lo);
            lo + dx
        };
        let converged = (x_new - x).abs() <= tol.width(x_new, x) || (hi - lo) <= tol.width(lo, hi);
        x = x_new;
        if converged {
            return Ok(Root {
                value: x,
                iterations: iter,
                evaluations: n,
            });
        }
        (y, dy) = eval(x, &mut n)?;
    }
    Err(NumericsError::NoConvergence {
        method: "safeguarded Newton",
        iterations: u64::from(tol.max_iterations),
        estimate: x,
        error: hi - lo,
    })
}

//! One-dimensional minimization of a continuous function on an interval: a
//! uniform grid to find the cell of the global minimum (the function may have
//! several local minima or a kink), then golden-section search inside it.
//!
//! Golden-section search (Kiefer 1953) shrinks a bracket by 1/φ per evaluation and
//! needs only continuity and one minimum in the bracket; it is robust where
//! derivatives are unreliable (a branch read from a table, a kink). Hand-written
//! (a dozen lines) rather than taken from a crate: the `roots` crate has no
//! minimizer, and the callers' functions are fallible (`Result`), which the
//! closures of optimization crates do not carry.

use crate::Cost;

/// A minimum found by [`grid_then_golden`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Minimum {
    /// Where (the abscissa of the smallest value seen).
    pub x: f64,
    /// The smallest value seen.
    pub value: f64,
    /// Function evaluations spent.
    pub cost: Cost,
}

/// The minimum of `f` over `[lo, hi]`: the best of `grid` + 1 equally spaced
/// points, refined by golden-section search in the two grid cells around it until
/// the bracket is below `x_tolerance` (absolute, in x; at most 200 steps). Errors
/// from `f` are passed on. `lo < hi` and `grid ≥ 2` are the caller's to ensure
/// (a debug assertion).
pub fn grid_then_golden<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    lo: f64,
    hi: f64,
    grid: usize,
    x_tolerance: f64,
) -> Result<Minimum, E> {
    debug_assert!(lo < hi && grid >= 2);
    let h = (hi - lo) / grid as f64;
    let at = |i: usize| if i == grid { hi } else { lo + h * i as f64 };
    let mut evaluations = 0u64;
    let mut best = (0usize, f(lo)?);
    evaluations += 1;
    for i in 1..=grid {
        let v = f(at(i))?;
        evaluations += 1;
        if v < best.1 {
            best = (i, v);
        }
    }
    let (mut a, mut b) = (at(best.0.saturating_sub(1)), at((best.0 + 1).min(grid)));
    let mut min = (at(best.0), best.1);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = b - g * (b - a);
    let mut x2 = a + g * (b - a);
    let (mut f1, mut f2) = (f(x1)?, f(x2)?);
    evaluations += 2;
    let mut iterations = 0u64;
    while b - a > x_tolerance && iterations < 200 {
        iterations += 1;
        if f1 < f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1)?;
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2)?;
        }
        evaluations += 1;
    }
    for (x, v) in [(x1, f1), (x2, f2)] {
        if v < min.1 {
            min = (x, v);
        }
    }
    Ok(Minimum {
        x: min.0,
        value: min.1,
        cost: Cost::new(evaluations, iterations),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_global_minimum_of_a_function_with_two_minima_and_a_kink() {
        // f = (x − 0.7)² + 0.3|x − 0.2| − 5·exp(−((x − 2.3)/0.05)²): a local minimum
        // at 0.55 (value 0.1275) and the global one near 2.3 (value ≈ 2.56 + 0.63 − 5)
        let f = |x: f64| -> Result<f64, ()> {
            Ok((x - 0.7).powi(2) + 0.3 * (x - 0.2).abs()
                - 5.0 * (-((x - 2.3) / 0.05).powi(2)).exp())
        };
        let m = grid_then_golden(f, 0.0, 3.0, 300, 1e-12).unwrap();
        // near 2.3 the Gaussian dominates: the minimum is where the derivative of the
        // smooth part, 2(x − 0.7) + 0.3, balances the Gaussian's slope
        assert!((m.x - 2.3).abs() < 3e-3 && m.value < -1.8, "{m:?}");
        let g = |x: f64| f(x).unwrap();
        assert!(m.value <= g(m.x - 1e-6) && m.value <= g(m.x + 1e-6));
        // a parabola: the vertex to the tolerance
        let p = grid_then_golden(
            |x: f64| Ok::<_, ()>((x - 0.123456789).powi(2)),
            -1.0,
            1.0,
            8,
            1e-10,
        )
        .unwrap();
        assert!((p.x - 0.123456789).abs() < 1e-9, "{p:?}");
        // the minimum at an end of the interval
        let e = grid_then_golden(|x: f64| Ok::<_, ()>(x), 0.0, 1.0, 4, 1e-12).unwrap();
        assert_eq!(e.x, 0.0);
        // errors pass through
        assert!(grid_then_golden(|_| Err::<f64, _>("boom"), 0.0, 1.0, 4, 1e-3).is_err());
    }
}

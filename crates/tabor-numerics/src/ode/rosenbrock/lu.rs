//! LU decomposition with partial pivoting of a small fixed-size matrix: the one
//! linear solve a Rosenbrock step needs (Golub & Van Loan, *Matrix Computations*,
//! 4th ed. 2013, algorithms 3.4.1 and 3.1.1-3.1.2). The matrix lives on the stack
//! (`[[f64; N]; N]`), so a step allocates nothing. Kept instead of `nalgebra`'s
//! const-size LU: that takes 3.6× the instructions for N = 3 and needs a
//! `DimMin` bound on every caller generic over N (the crate README, "Why not
//! `nalgebra`").

#![allow(clippy::needless_range_loop)] // index loops over small fixed arrays

/// A square matrix `m[row][column]`.
pub type Matrix<const N: usize> = [[f64; N]; N];

/// The factors `P A = L U` of a matrix: `L` (unit diagonal) below and `U` on and
/// above the diagonal of `lu`, the row permutation in `perm`.
pub(super) struct Lu<const N: usize> {
    lu: Matrix<N>,
    perm: [usize; N],
}

impl<const N: usize> Lu<N> {
    /// Decomposes `a`; `None` if it is singular (or not finite).
    pub(super) fn decompose(mut a: Matrix<N>) -> Option<Self> {
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
        Some(Lu { lu: a, perm })
    }

    /// Solves `A x = b`: forward substitution with L on `P b`, then back
    /// substitution with U.
    pub(super) fn solve(&self, b: &[f64; N]) -> [f64; N] {
        let (lu, perm) = (&self.lu, &self.perm);
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
}

//! The precomputed force–overlap relation of an adhesive branch in normalized
//! variables, interpolated by piecewise cubic Hermite polynomials: the fast tier of
//! the per-step force (the same idea as the fast tier of the Maugis-Dugdale loss,
//! `tabor_maugis::loss_over_jkr_fast`).
//!
//! The stable branch that an adhesive impact follows ends at a minimum of the depth
//! (the fixed-grip snap-off of JKR, seed 000 (5.36)'s lower limit; the pull-off of
//! the Maugis-Dugdale path, section 5.3.2), where dd̂/d(branch parameter) = 0: there
//! F̂(d̂) has a square-root singularity, F̂ ≈ F̂₀ + c√(d̂ − d̂₀). In the coordinate
//! `s = √(d̂ − d̂₀)` both F̂ and â are smooth, so the table is uniform in s:
//!
//! - the fine segment `0 ≤ s ≤ S_FINE` ((d̂ − d̂₀)/L ≤ 64, every adhesive feature;
//!   the law chooses the length L, max(1, 1/Λ) for Maugis-Dugdale) with
//!   [`FINE_INTERVALS`] intervals, tabulating F̂ and â, split at a kink of the
//!   branch if it has one (the junction of the Maugis-Dugdale branches);
//! - the Hertzian segment `S_FINE ≤ s ≤ S_MAX` (d̂ − d̂₀ ≤ 1e6), uniform in ln s,
//!   tabulating F̂/s³ and â/s (both tend to constants, Hertz (5.5));
//! - beyond `S_MAX` (an overlap a million times the adhesive depth scale) the exact
//!   law is evaluated (slow, but never met in practice).
//!
//! Node derivatives are central differences of the exact law (one-sided at s = 0).
//! The interpolation error is *measured* when the table is built, against the exact
//! law at the midpoint and the quarter points of every interval (the extrema of the
//! cubic Hermite error kernel t²(1−t)²); [`Table::error`] reports it.

/// Fine segment end in s = √(d̂ − d̂₀).
pub const S_FINE: f64 = 8.0;
/// Hertzian segment end in s (d̂ − d̂₀ = 1e6).
pub const S_MAX: f64 = 1000.0;
/// Intervals of the fine segment.
pub const FINE_INTERVALS: usize = 2048;
/// Intervals of the Hertzian segment (uniform in ln s).
pub const HERTZ_INTERVALS: usize = 512;

/// Measured interpolation errors of a [`Table`].
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct TableError {
    /// Largest |F̂_table − F̂_exact| on the fine segment, in units of F_n.
    pub fine_force_abs: f64,
    /// Largest |F̂_table/F̂_exact − 1| on the Hertzian segment.
    pub hertz_force_rel: f64,
    /// Largest |â_table − â_exact| on the fine segment, in units of a_c.
    pub fine_radius_abs: f64,
}

/// Cubic Hermite coefficients of (F̂, â) on one interval, in the local coordinate
/// t ∈ [0, 1]: value = c0 + t(c1 + t(c2 + t c3)).
type Cubic2 = [[f64; 4]; 2];

/// The tabulated branch: F̂(s) and â(s) (see the module docs).
#[derive(Clone, Debug)]
pub struct Table {
    fine: Vec<Cubic2>,
    fine_inv_h: f64,
    /// The fine segment is split at `s_break` (a kink of the branch: the junction of
    /// the Maugis-Dugdale no-contact and contact branches); above it `upper` holds
    /// the intervals, uniform in r = √(s − s_break) up to S_FINE.
    s_break: f64,
    upper: Vec<Cubic2>,
    upper_inv_h: f64,
    hertz: Vec<Cubic2>,
    ln_s_fine: f64,
    hertz_inv_h: f64,
    error: TableError,
}

fn hermite(v0: f64, d0: f64, v1: f64, d1: f64, h: f64) -> [f64; 4] {
    // p(t) on [0,1] with p(0)=v0, p'(0)=h d0, p(1)=v1, p'(1)=h d1
    let m0 = h * d0;
    let m1 = h * d1;
    [
        v0,
        m0,
        3.0 * (v1 - v0) - 2.0 * m0 - m1,
        2.0 * (v0 - v1) + m0 + m1,
    ]
}

#[inline(always)]
fn horner(c: &[f64; 4], t: f64) -> f64 {
    c[0] + t * (c[1] + t * (c[2] + t * c[3]))
}

/// Builds the piecewise cubic Hermite table of `f(x) = (F̂, â)` over `n`
/// uniform intervals of [x0, x1] (derivatives by central differences of `f`,
/// one-sided at a left end where f is not defined further left).
fn segment<E>(
    f: &dyn Fn(f64) -> Result<(f64, f64), E>,
    x0: f64,
    x1: f64,
    n: usize,
    one_sided: (bool, bool),
) -> Result<Vec<Cubic2>, E> {
    let h = (x1 - x0) / n as f64;
    let eps = 1e-3 * h;
    let mut values = Vec::with_capacity(n + 1);
    let mut slopes = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let x = x0 + h * i as f64;
        let v = f(x)?;
        let d = if (i == 0 && one_sided.0) || (i == n && one_sided.1) {
            // second-order one-sided difference, into the segment
            let e = if i == 0 { eps } else { -eps };
            let a = f(x + e)?;
            let b = f(x + 2.0 * e)?;
            (
                (-3.0 * v.0 + 4.0 * a.0 - b.0) / (2.0 * e),
                (-3.0 * v.1 + 4.0 * a.1 - b.1) / (2.0 * e),
            )
        } else {
            // fourth-order central difference
            let p1 = f(x + eps)?;
            let m1 = f(x - eps)?;
            let p2 = f(x + 2.0 * eps)?;
            let m2 = f(x - 2.0 * eps)?;
            (
                (8.0 * (p1.0 - m1.0) - (p2.0 - m2.0)) / (12.0 * eps),
                (8.0 * (p1.1 - m1.1) - (p2.1 - m2.1)) / (12.0 * eps),
            )
        };
        values.push(v);
        slopes.push(d);
    }
    Ok((0..n)
        .map(|i| {
            [
                hermite(
                    values[i].0,
                    slopes[i].0,
                    values[i + 1].0,
                    slopes[i + 1].0,
                    h,
                ),
                hermite(
                    values[i].1,
                    slopes[i].1,
                    values[i + 1].1,
                    slopes[i + 1].1,
                    h,
                ),
            ]
        })
        .collect())
}

impl Table {
    /// Tabulates `exact(s) = (F̂, â)` (normalized force and contact radius at
    /// `s = √(d̂ − d̂₀)`), and measures the interpolation error against it.
    ///
    /// `kink`: a value of s in (0, S_FINE) where the branch has a kink (derivatives
    /// are then one-sided there and the fine segment is split), or `None`.
    pub fn build<E>(
        exact: &dyn Fn(f64) -> Result<(f64, f64), E>,
        kink: Option<f64>,
    ) -> Result<Table, E> {
        let s_break = kink
            .filter(|k| *k > 1e-3 * S_FINE && *k < 0.999 * S_FINE)
            .unwrap_or(S_FINE);
        let n_lower = ((FINE_INTERVALS as f64 * s_break / S_FINE).round() as usize).max(16);
        let n_upper = FINE_INTERVALS.saturating_sub(n_lower).max(16);
        let split = s_break < S_FINE;
        let fine = segment(exact, 0.0, s_break, n_lower, (true, split))?;
        // above a kink the contact radius grows like √(s − s_break) (seed 000
        // section 5.3.2: â = 0 at the junction): tabulate in r = √(s − s_break)
        let r_max = (S_FINE - s_break).sqrt();
        let above = |r: f64| exact(s_break + r * r);
        let upper = if split {
            segment(&above, 0.0, r_max, n_upper, (true, false))?
        } else {
            Vec::new()
        };
        let ln0 = S_FINE.ln();
        let ln1 = S_MAX.ln();
        let scaled = |t: f64| -> Result<(f64, f64), E> {
            let s = t.exp();
            let (f, a) = exact(s)?;
            Ok((f / (s * s * s), a / s))
        };
        let hertz = segment(&scaled, ln0, ln1, HERTZ_INTERVALS, (false, false))?;
        let mut table = Table {
            fine_inv_h: fine.len() as f64 / s_break,
            fine,
            s_break,
            upper_inv_h: upper.len() as f64 / r_max,
            upper,
            hertz,
            ln_s_fine: ln0,
            hertz_inv_h: HERTZ_INTERVALS as f64 / (ln1 - ln0),
            error: TableError::default(),
        };
        let mut err = TableError::default();
        let checks = (0..table.fine.len())
            .map(|i| (i as f64, false, table.fine_inv_h))
            .chain((0..table.upper.len()).map(|i| (i as f64, true, table.upper_inv_h)))
            .collect::<Vec<_>>();
        for (i, upper, inv_h) in checks {
            for q in [0.25, 0.5, 0.75] {
                let x = (i + q) / inv_h;
                let s = if upper { s_break + x * x } else { x };
                let (f, a) = exact(s)?;
                if let Some((ft, at)) = table.eval(s) {
                    err.fine_force_abs = err.fine_force_abs.max((ft - f).abs());
                    err.fine_radius_abs = err.fine_radius_abs.max((at - a).abs());
                }
            }
        }
        for i in 0..HERTZ_INTERVALS {
            for q in [0.25, 0.5, 0.75] {
                let s = (ln0 + (i as f64 + q) / table.hertz_inv_h).exp();
                let (f, _) = exact(s)?;
                if let Some((ft, _)) = table.eval(s) {
                    err.hertz_force_rel = err.hertz_force_rel.max((ft / f - 1.0).abs());
                }
            }
        }
        table.error = err;
        Ok(table)
    }

    /// The bytes the table's coefficients take (64 per interval).
    pub fn memory_bytes(&self) -> usize {
        (self.fine.len() + self.upper.len() + self.hertz.len()) * std::mem::size_of::<Cubic2>()
    }

    /// The measured interpolation errors.
    pub fn error(&self) -> TableError {
        self.error
    }

    /// (F̂, â) at s ≥ 0 from the table, or `None` beyond [`S_MAX`] (or for s < 0
    /// or NaN).
    #[inline]
    pub fn eval(&self, s: f64) -> Option<(f64, f64)> {
        if s < self.s_break {
            if s.is_nan() || s < 0.0 {
                return None;
            }
            let u = s * self.fine_inv_h;
            let i = (u as usize).min(self.fine.len() - 1);
            let t = u - i as f64;
            let c = &self.fine[i];
            Some((horner(&c[0], t), horner(&c[1], t)))
        } else if s < S_FINE {
            let u = (s - self.s_break).sqrt() * self.upper_inv_h;
            let i = (u as usize).min(self.upper.len() - 1);
            let t = u - i as f64;
            let c = &self.upper[i];
            Some((horner(&c[0], t), horner(&c[1], t)))
        } else if s <= S_MAX {
            let u = (s.ln() - self.ln_s_fine) * self.hertz_inv_h;
            let i = (u as usize).min(HERTZ_INTERVALS - 1);
            let t = u - i as f64;
            let c = &self.hertz[i];
            Some((horner(&c[0], t) * s * s * s, horner(&c[1], t) * s))
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_a_cubic_exactly_and_a_hertz_law_closely() {
        // a cubic in s is reproduced by cubic Hermite (up to the differences)
        let t = Table::build(
            &|s: f64| Ok::<_, ()>((s * s * s - 2.0 * s + 1.0, 0.5 * s)),
            None,
        )
        .expect("builds");
        assert!(t.error().fine_force_abs < 1e-9, "{:?}", t.error());
        let (f, a) = t.eval(3.3).expect("in range");
        assert!((f - (3.3f64.powi(3) - 6.6 + 1.0)).abs() < 1e-9);
        assert!((a - 1.65).abs() < 1e-12);
        assert!(t.eval(-1.0).is_none());
        assert!(t.eval(f64::NAN).is_none());
        assert!(t.eval(2e3).is_none());
    }
}

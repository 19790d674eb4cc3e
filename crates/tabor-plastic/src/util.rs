//! Output checks and small helpers shared by the models.

pub(crate) use tabor_restitution::validate::{finite_output, positive_output};

/// A cubic Hermite segment on `[0, L]`: `p(t) = y0 + m0 t + c2 t² + c3 t³` with
/// `p(0) = y0`, `p'(0) = m0`, `p(L) = y1`, `p'(L) = m1`.
///
/// The construction of seed 000 eqs. (5.115)-(5.120) (and, in the variable
/// `x = d/d_Y`, of the chapter-3 interpolation (3.285) behind (5.107)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Hermite {
    pub y0: f64,
    pub m0: f64,
    pub c2: f64,
    pub c3: f64,
    pub length: f64,
}

impl Hermite {
    pub(crate) fn new(y0: f64, m0: f64, y1: f64, m1: f64, length: f64) -> Self {
        let l = length;
        Hermite {
            y0,
            m0,
            c2: (3.0 * (y1 - y0) - (2.0 * m0 + m1) * l) / (l * l),
            c3: (2.0 * (y0 - y1) + (m0 + m1) * l) / (l * l * l),
            length: l,
        }
    }
    pub(crate) fn value(&self, t: f64) -> f64 {
        self.y0 + t * (self.m0 + t * (self.c2 + t * self.c3))
    }
    pub(crate) fn slope(&self, t: f64) -> f64 {
        self.m0 + t * (2.0 * self.c2 + 3.0 * t * self.c3)
    }
    /// `∫_0^t p`.
    pub(crate) fn integral(&self, t: f64) -> f64 {
        t * (self.y0 + t * (0.5 * self.m0 + t * (self.c2 / 3.0 + 0.25 * t * self.c3)))
    }
    /// The smallest slope on `[lo, L]` (the slope is a quadratic in t).
    pub(crate) fn min_slope(&self, lo: f64) -> f64 {
        let mut m = self.slope(lo).min(self.slope(self.length));
        if self.c3 > 0.0 {
            let t = -self.c2 / (3.0 * self.c3);
            if t > lo && t < self.length {
                m = m.min(self.slope(t));
            }
        }
        m
    }
}

/// `a > b`, false when either is NaN.
pub(crate) fn exceeds(a: f64, b: f64) -> bool {
    a > b
}

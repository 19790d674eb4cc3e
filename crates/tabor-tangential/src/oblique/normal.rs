//! The normal law at one overlap, as the oblique integration needs it: the
//! elastic-adhesive force, the contact radius and their slopes in the overlap.
//!
//! Where the law gives its branch as a curve in a coordinate of its own
//! ([`BranchCurve`]: the JKR root `x = √â`, the Maugis-Dugdale angle θ), as the
//! central simulated impact integrates it, one solve for the coordinate gives the
//! force and the radius, and the slopes are central differences along the curve
//! (explicit, no further solve), or the curve's closed form where it gives one
//! (JKR). Elsewhere (Hertz, the plastic laws) the law is
//! evaluated at the overlap and the slopes are central differences of it. The last
//! point is kept: the rates, the event values and the mode switches ask for the
//! same overlap several times (it is forgotten whenever a hook of the law may have
//! changed its branch, [`Setup::forget_normal`]).

use super::state::{derivative, Modes, NormalPoint, Setup, N};
use tabor_dynamics::{BranchCurve, ForceLaw};
use tabor_restitution::Result;

/// The largest mismatch (relative to the overlap scale) between the overlap and
/// the curve's overlap at the coordinate solved for it: beyond it the curve does
/// not describe the law there (a clamped coordinate) and the law is evaluated.
pub(super) const CURVE_MISMATCH: f64 = 1e-9;

impl<'a> Setup<'a> {
    /// The normal law at `overlap` (m) and `rate` (m/s), with the slopes when
    /// `slopes` (their steps: [`Setup::difference_step`]).
    pub(super) fn normal(
        &self,
        law: &dyn ForceLaw,
        overlap: f64,
        rate: f64,
        slopes: bool,
    ) -> Result<NormalPoint> {
        let key = [overlap.to_bits(), rate.to_bits()];
        if let Some((k, p)) = self.normal_cache.get() {
            if k == key && (p.slopes.is_some() || !slopes) {
                return Ok(p);
            }
        }
        let p = match law.curve() {
            Some(curve) => match self.on_curve(law, curve, overlap, rate, slopes)? {
                Some(p) => p,
                None => self.evaluated(law, overlap, rate, slopes)?,
            },
            None => self.evaluated(law, overlap, rate, slopes)?,
        };
        self.normal_cache.set(Some((key, p)));
        Ok(p)
    }

    /// True when the segment from SI (t, y) in `modes` is in contact on a law
    /// whose slopes are exact ([`NormalPoint::exact`]).
    pub(super) fn exact_slopes(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        modes: &Modes,
    ) -> Result<bool> {
        if !modes.in_contact || law.curve().is_none() {
            return Ok(false);
        }
        let (_, overlap, rate, _) = self.geometry(t, y);
        Ok(self.normal(law, overlap, rate, false)?.exact)
    }

    /// Forgets the last point (after a hook of the law).
    pub(super) fn forget_normal(&self) {
        self.normal_cache.set(None);
    }

    /// On the law's curve; `None` where the curve does not reproduce the overlap.
    fn on_curve(
        &self,
        law: &dyn ForceLaw,
        curve: &dyn BranchCurve,
        overlap: f64,
        rate: f64,
        slopes: bool,
    ) -> Result<Option<NormalPoint>> {
        let q = curve.coordinate(overlap)?;
        let p = curve.point(q, rate)?;
        let slope = p.overlap_slope;
        if !((p.overlap - overlap).abs() <= CURVE_MISMATCH * self.length
            && slope.is_finite()
            && slope != 0.0)
        {
            return Ok(None);
        }
        let slopes = match (slopes, p.slopes) {
            (false, _) => None,
            (true, Some((df, da))) => Some((da / slope, df / slope)),
            (true, None) => {
                let h = self.difference_step(law, overlap, rate)? / slope.abs();
                let up = curve.point(q + h, rate)?;
                let down = curve.point(q - h, rate)?;
                let dd = up.overlap - down.overlap;
                Some((
                    (up.contact_radius - down.contact_radius) / dd,
                    (up.force - down.force) / dd,
                ))
            }
        };
        Ok(Some(NormalPoint {
            force: p.force,
            radius: p.contact_radius.max(0.0),
            slopes,
            exact: p.slopes.is_some(),
        }))
    }

    /// The law evaluated at the overlap, the slopes by central differences of it
    /// (one-sided forward where the law errs below).
    fn evaluated(
        &self,
        law: &dyn ForceLaw,
        overlap: f64,
        rate: f64,
        slopes: bool,
    ) -> Result<NormalPoint> {
        let force = law.force(overlap, rate)?;
        if !slopes {
            return Ok(NormalPoint {
                force,
                radius: law.contact_radius(overlap, rate)?.max(0.0),
                slopes: None,
                exact: false,
            });
        }
        let h = self.difference_step(law, overlap, rate)?;
        let (a, a_prime) = derivative(&|d: f64| law.contact_radius(d, rate), overlap, h)?;
        let (_, f_prime) = derivative(&|d: f64| law.force(d, rate), overlap, h)?;
        Ok(NormalPoint {
            force,
            radius: a.max(0.0),
            slopes: Some((a_prime, f_prime)),
            exact: false,
        })
    }
}

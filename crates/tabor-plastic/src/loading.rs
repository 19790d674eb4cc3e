//! Normalized loading laws of the non-adhesive elasto-plastic contact (seed 000,
//! section 5.5.1): Thornton's law and the interpolation model, in `x = d/d_Y`,
//! `F/F_Y`, `a/a_Y`, work in `F_Y d_Y`, speed in `v_Y`. Unloading is Hertzian with
//! the radius `R_p` and the residual depth of (3.273)-(3.274), so the restitution is
//! (5.105) for both.

use crate::util::{exceeds, finite_output, Hermite};
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_restitution::{validate, Error, Result};

pub(crate) mod sealed {
    /// The raw, unvalidated curves (x ≥ 0 finite is guaranteed by callers).
    pub trait RawLoading {
        fn f(&self, x: f64) -> f64;
        fn alpha(&self, x: f64) -> f64;
        fn work(&self, x: f64) -> f64;
        fn x_max(&self, speed_ratio: f64) -> tabor_restitution::Result<f64>;
    }
}

/// A loading law `F/F_Y = f(d/d_Y)`, `a/a_Y = α(d/d_Y)` of a rigid sphere on an
/// elastic-perfectly plastic half-space, Hertzian below yield (`f = x^(3/2)`,
/// `α = √x` for `x ≤ 1`), with elastic (Hertzian) unloading from the turning point
/// with radius `R_p = 4E* a_max³/(3F_max)` and residual depth
/// `d_res = d_max − a_max²/R_p` (the chapter-3 relations (3.273)-(3.274)).
///
/// Implemented by [`Thornton`] and [`Interpolation`] (sealed). Seed 000, section 5.5.1.
pub trait LoadingLaw: sealed::RawLoading + Clone + std::fmt::Debug {
    /// A short name for reports.
    fn name(&self) -> String;

    /// `F/F_Y` at `x = d/d_Y` (finite, ≥ 0).
    ///
    /// Seed 000, the loading laws behind (5.101) and (5.107).
    fn force_ratio(&self, depth_ratio: f64) -> Result<f64> {
        let x = validate::non_negative("depth_ratio", depth_ratio)?;
        finite_output("loading law", "force", self.f(x))
    }

    /// `a/a_Y` at `x = d/d_Y` (finite, ≥ 0).
    ///
    /// Seed 000, the contact radius of the loading laws behind (5.105), (5.107).
    fn contact_radius_ratio(&self, depth_ratio: f64) -> Result<f64> {
        let x = validate::non_negative("depth_ratio", depth_ratio)?;
        finite_output("loading law", "contact radius", self.alpha(x))
    }

    /// The loading work `∫_0^d F dd` in units of `F_Y d_Y`, at `x = d/d_Y` ≥ 0.
    ///
    /// Seed 000, eq. (5.101) (Thornton) and (5.107) (interpolation) times `2/5`.
    fn loading_work_ratio(&self, depth_ratio: f64) -> Result<f64> {
        let x = validate::non_negative("depth_ratio", depth_ratio)?;
        finite_output("loading law", "loading work", self.work(x))
    }

    /// The maximum depth `d_max/d_Y` of an impact at `v0/v_Y` (finite, > 0): the root
    /// of `(5/2) W(x)/(F_Y d_Y) = (v0/v_Y)²`.
    ///
    /// Seed 000, eq. (5.104) (Thornton), (5.107) (interpolation).
    fn max_depth_ratio(&self, speed_ratio: f64) -> Result<f64> {
        let s = validate::positive("speed_ratio", speed_ratio)?;
        finite_output("loading law", "maximum depth", self.x_max(s)?)
    }

    /// The turning point and the elastic unloading it sets up, for `v0/v_Y` > 0.
    ///
    /// Seed 000, eqs. (5.104)/(5.107) with (3.273)-(3.274).
    fn turning_point(&self, speed_ratio: f64) -> Result<TurningPoint> {
        let x = self.max_depth_ratio(speed_ratio)?;
        let f = self.f(x);
        let alpha = self.alpha(x);
        if !(f > 0.0 && alpha > 0.0) {
            return Err(Error::Model {
                model: "loading law",
                message: format!("turning point at x = {x:e} has no positive force"),
            });
        }
        Ok(TurningPoint {
            max_depth_ratio: x,
            max_force_ratio: f,
            max_contact_radius_ratio: alpha,
            unloading_radius_ratio: alpha * alpha * alpha / f,
            residual_depth_ratio: (x - f / alpha).max(0.0),
        })
    }

    /// The coefficient of restitution at `v0/v_Y` > 0:
    /// `ε = (v_Y/v0)[(R_p/R)((d_max − d_res)/d_Y)⁵]^(1/4) = (v_Y/v0) f/√α`, and
    /// `ε = 1` for `v0 ≤ v_Y`.
    ///
    /// Seed 000, eq. (5.105).
    fn restitution(&self, speed_ratio: f64) -> Result<f64> {
        let s = validate::positive("speed_ratio", speed_ratio)?;
        if s <= 1.0 {
            return Ok(1.0);
        }
        let t = self.turning_point(s)?;
        let e = (t.unloading_radius_ratio * (t.max_depth_ratio - t.residual_depth_ratio).powi(5))
            .powf(0.25)
            / s;
        finite_output("loading law", "restitution", e.min(1.0))
    }

    /// The elastic unloading work `(2/5) F_max (d_max − d_res)` in units of `F_Y d_Y`
    /// at `v0/v_Y` > 0 (the rebound kinetic energy).
    ///
    /// Seed 000, eq. (5.105) before normalization (Hertz work with radius `R_p`).
    fn rebound_work_ratio(&self, speed_ratio: f64) -> Result<f64> {
        let t = self.turning_point(speed_ratio)?;
        Ok(0.4 * t.max_force_ratio * (t.max_depth_ratio - t.residual_depth_ratio))
    }
}

/// The state at maximum compression, normalized by the yield onset.
///
/// Seed 000, eqs. (5.104)-(5.105), chapter 3 (3.273)-(3.274).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct TurningPoint {
    /// `d_max/d_Y`, seed 000 eq. (5.104)/(5.107).
    pub max_depth_ratio: f64,
    /// `F_max/F_Y`.
    pub max_force_ratio: f64,
    /// `a_max/a_Y`.
    pub max_contact_radius_ratio: f64,
    /// `R_p/R = (a_max/a_Y)³/(F_max/F_Y)` (chapter 3, (3.273)).
    pub unloading_radius_ratio: f64,
    /// `d_res/d_Y = x − f/α` (chapter 3, (3.274)); 0 below yield.
    pub residual_depth_ratio: f64,
}

/// Thornton's loading law: Hertz to `d_Y`, then `F = F_Y[1 + (3/2)(d/d_Y − 1)]`
/// (mean pressure capped at the limiting pressure), `a² = R d`.
///
/// Seed 000, eqs. (5.101)-(5.106).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Thornton;

impl sealed::RawLoading for Thornton {
    fn f(&self, x: f64) -> f64 {
        if x <= 1.0 {
            x * x.sqrt()
        } else {
            1.0 + 1.5 * (x - 1.0)
        }
    }
    fn alpha(&self, x: f64) -> f64 {
        x.sqrt()
    }
    fn work(&self, x: f64) -> f64 {
        if x <= 1.0 {
            0.4 * x * x * x.sqrt()
        } else {
            // (5.101): 2/5 + (3x² − 2x − 1)/4
            0.4 + 0.25 * (3.0 * x * x - 2.0 * x - 1.0)
        }
    }
    fn x_max(&self, s: f64) -> Result<f64> {
        Ok(if s <= 1.0 {
            s.powf(0.8)
        } else {
            // (5.104)
            1.0 / 3.0 + 2.0 / 15.0 * (30.0 * s * s - 5.0).sqrt()
        })
    }
}

impl LoadingLaw for Thornton {
    fn name(&self) -> String {
        "Thornton".into()
    }
}

impl Thornton {
    /// The high-speed asymptote of the restitution, `ε ≈ 1.185 (v0/v_Y)^(−1/4)`
    /// (the constant is `(3/2)(2√30/15)^(3/4)`), for `v0/v_Y` > 0.
    ///
    /// Seed 000, eq. (5.106).
    pub fn high_speed_restitution(speed_ratio: f64) -> Result<f64> {
        let s = validate::positive("speed_ratio", speed_ratio)?;
        let c = 1.5 * (2.0 * 30f64.sqrt() / 15.0).powf(0.75);
        finite_output("Thornton", "restitution", c * s.powf(-0.25))
    }
}

/// Default `Q` of the interpolation model: fully plastic `F/F_Y = Q d/d_Y` (mean
/// pressure `Q p_Y/3 ≈ 2.67 σ_Y`). Seed 000, text after (5.108) (chapter 3, (3.282)).
pub const DEFAULT_PLASTIC_SLOPE: f64 = 5.0;
/// Default `D` of the interpolation model: fully plastic from `d = D d_Y`.
/// Seed 000, text after (5.108) (chapter 3, (3.282)).
pub const DEFAULT_PLASTIC_ONSET: f64 = 80.0;

/// The interpolation model: Hertz for `x = d/d_Y ≤ 1`; fully plastic `F/F_Y = Q x`
/// with `a² = 2 R d` for `x ≥ D`; in between the cubics in `(x − 1)` that make force
/// and contact radius C¹ at both ends. Unloading as in Thornton's model.
///
/// Seed 000, eq. (5.107) (constants of chapter 3, (3.282)-(3.288), not available;
/// reconstructed as described in the crate README, "The interpolation model (5.107)"),
/// extended to loading beyond `x = D`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interpolation {
    plastic_slope: f64,
    plastic_onset: f64,
    force: Hermite,
    radius: Hermite,
    work_at_onset: f64,
}

impl Default for Interpolation {
    fn default() -> Self {
        // Q = 5, D = 80 satisfy every condition `new` checks (tested).
        Interpolation::build(DEFAULT_PLASTIC_SLOPE, DEFAULT_PLASTIC_ONSET)
    }
}

impl Interpolation {
    /// The model with fully plastic slope `Q` (> 0) and onset `D` (> 1), both finite;
    /// fails unless both interpolating cubics increase monotonically on `[1, D]`.
    ///
    /// Seed 000, eq. (5.107) with `C_2`, `C_3` of (3.285) (the Hermite construction of
    /// (5.116)-(5.117) in `x`).
    pub fn new(plastic_slope: f64, plastic_onset: f64) -> Result<Self> {
        let q = validate::positive("plastic_slope", plastic_slope)?;
        let d = validate::positive("plastic_onset", plastic_onset)?;
        if !(d > 1.0 && d < 1e12) {
            return Err(Error::invalid(
                "plastic_onset",
                d,
                "must lie in (1, 1e12): fully plastic beyond first yield",
            ));
        }
        if q > 1e12 {
            return Err(Error::invalid("plastic_slope", q, "must be <= 1e12"));
        }
        let model = Interpolation::build(q, d);
        if !exceeds(model.force.min_slope(0.0), 0.0) {
            return Err(Error::invalid(
                "plastic_slope",
                q,
                "gives a force cubic that is not increasing on [1, D]",
            ));
        }
        if !exceeds(model.radius.min_slope(0.0), 0.0) {
            return Err(Error::invalid(
                "plastic_onset",
                d,
                "gives a contact-radius cubic that is not increasing on [1, D]",
            ));
        }
        Ok(model)
    }

    fn build(q: f64, d: f64) -> Self {
        let l = d - 1.0;
        let force = Hermite::new(1.0, 1.5, q * d, q, l);
        let r0 = (2.0 * d).sqrt();
        let radius = Hermite::new(1.0, 0.5, r0, 1.0 / r0, l);
        Interpolation {
            plastic_slope: q,
            plastic_onset: d,
            force,
            radius,
            work_at_onset: 0.4 + force.integral(l),
        }
    }

    /// `Q`: fully plastic `F/F_Y = Q d/d_Y`.
    ///
    /// Seed 000, text after (5.108) (chapter 3, (3.282)).
    pub fn plastic_slope(&self) -> f64 {
        self.plastic_slope
    }

    /// `D`: the fully plastic range starts at `d = D d_Y`.
    ///
    /// Seed 000, text after (5.108) (chapter 3, (3.282)).
    pub fn plastic_onset(&self) -> f64 {
        self.plastic_onset
    }

    /// The cubic coefficients `C_2`, `C_3` of the force,
    /// `F/F_Y = 1 + (3/2)(x−1) + C_2 (x−1)² + C_3 (x−1)³`.
    ///
    /// Seed 000, eq. (5.107) (chapter 3, (3.285)).
    pub fn force_coefficients(&self) -> (f64, f64) {
        (self.force.c2, self.force.c3)
    }
}

impl sealed::RawLoading for Interpolation {
    fn f(&self, x: f64) -> f64 {
        if x <= 1.0 {
            x * x.sqrt()
        } else if x < self.plastic_onset {
            self.force.value(x - 1.0)
        } else {
            self.plastic_slope * x
        }
    }
    fn alpha(&self, x: f64) -> f64 {
        if x <= 1.0 {
            x.sqrt()
        } else if x < self.plastic_onset {
            self.radius.value(x - 1.0)
        } else {
            (2.0 * x).sqrt()
        }
    }
    fn work(&self, x: f64) -> f64 {
        if x <= 1.0 {
            0.4 * x * x * x.sqrt()
        } else if x < self.plastic_onset {
            0.4 + self.force.integral(x - 1.0)
        } else {
            let d = self.plastic_onset;
            self.work_at_onset + 0.5 * self.plastic_slope * (x - d) * (x + d)
        }
    }
    fn x_max(&self, s: f64) -> Result<f64> {
        if s <= 1.0 {
            return Ok(s.powf(0.8));
        }
        let target = 0.4 * s * s;
        if target >= self.work_at_onset {
            let d = self.plastic_onset;
            return Ok((d * d + 2.0 * (target - self.work_at_onset) / self.plastic_slope).sqrt());
        }
        // (5.107): (5/2) W(x) = s², a quartic in x − 1 on [1, D].
        let root = brent(
            |x| self.work(x) - target,
            1.0,
            self.plastic_onset,
            RootTolerance::relative(4.0 * f64::EPSILON),
        )?;
        Ok(root.value)
    }
}

impl LoadingLaw for Interpolation {
    fn name(&self) -> String {
        format!(
            "interpolation (Q = {}, D = {})",
            self.plastic_slope, self.plastic_onset
        )
    }
}

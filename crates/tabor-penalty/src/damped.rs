//! Penalty laws of the Hunt-Crossley form `F = K δⁿ (1 + χ δ̇)` and the three
//! published choices of the hysteresis damping factor χ from a restitution
//! coefficient (named in seed 001's introduction, refs. [8]-[10]).

use crate::series::{exp_ratio, exp_remainder, log_remainder};
use crate::valid;
use tabor_dynamics::ForceLaw;
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_restitution::{validate, Error, Result};

/// How a published model turns a restitution coefficient ε and an impact speed v0
/// into the hysteresis damping factor χ (s/m) of `F = K δⁿ (1 + χ δ̇)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum DampingModel {
    /// Hunt, K. H. & Crossley, F. R. E. (1975), "Coefficient of restitution
    /// interpreted as damping in vibroimpact", J. Appl. Mech. 42, 440-445:
    /// `χ = 3(1 − ε)/(2 v0)`.
    HuntCrossley,
    /// Lankarani, H. M. & Nikravesh, P. E. (1990), "A contact force model with
    /// hysteresis damping for impact analysis of multibody systems", J. Mech. Des.
    /// 112, 369-376: `χ = 3(1 − ε²)/(4 v0)`.
    LankaraniNikravesh,
    /// Flores, P., Machado, M., Silva, M. T. & Martins, J. M. (2011), "On the
    /// continuous contact force models for soft materials in multibody dynamics",
    /// Multibody Syst. Dyn. 25, 357-375: `χ = 8(1 − ε)/(5 ε v0)`.
    Flores,
}

impl DampingModel {
    /// The model's name, as in the literature.
    pub fn name(self) -> &'static str {
        match self {
            DampingModel::HuntCrossley => "Hunt-Crossley",
            DampingModel::LankaraniNikravesh => "Lankarani-Nikravesh",
            DampingModel::Flores => "Flores",
        }
    }

    /// The nominal hysteresis damping factor χ (s/m) for `restitution` ε ∈ (0, 1]
    /// at `impact_speed` v0 > 0 (m/s); see the variants for the formulas and papers.
    pub fn damping_factor(self, restitution: f64, impact_speed: f64) -> Result<f64> {
        let e = valid::restitution(restitution)?;
        let v0 = validate::positive("impact_speed", impact_speed)?;
        let x = match self {
            DampingModel::HuntCrossley => 1.5 * (1.0 - e),
            DampingModel::LankaraniNikravesh => 0.75 * (1.0 - e) * (1.0 + e),
            DampingModel::Flores => 1.6 * (1.0 - e) / e,
        };
        finite_damping(x / v0, e)
    }
}

fn finite_damping(chi: f64, e: f64) -> Result<f64> {
    if chi.is_finite() {
        Ok(chi)
    } else {
        Err(Error::invalid(
            "restitution",
            e,
            "gives a damping factor that overflows at this impact_speed",
        ))
    }
}

/// The coefficient of restitution that the law `F = K δⁿ (1 + χ δ̇)` actually
/// produces in an impact at `impact_speed` v0, for `damping_factor` χ ≥ 0 (s/m).
///
/// Exact first integral (derived in this crate): `m δ̈ = −K δⁿ (1 + χ δ̇)` gives
/// `δ̇ dδ̇/(1 + χ δ̇) = −(K/m) δⁿ dδ`, whose right side integrates to zero over the
/// closed path δ: 0 → δ_max → 0. So x = χ v0 and y = χ v1 satisfy
///
/// `x − ln(1 + x) = −y − ln(1 − y)`, 0 ≤ y < 1,
///
/// for every K, n and m; ε = y/x. (The force never turns tensile: δ̇ cannot pass
/// −1/χ, where the acceleration vanishes.) Solved by Brent's method for z = −ln(1 − y)
/// scaled by x, to 1e-15.
pub fn damped_restitution(damping_factor: f64, impact_speed: f64) -> Result<f64> {
    let chi = validate::non_negative("damping_factor", damping_factor)?;
    let v0 = validate::positive("impact_speed", impact_speed)?;
    let x = chi * v0;
    if x == 0.0 {
        return Ok(1.0);
    }
    if !x.is_finite() {
        return Err(Error::invalid(
            "damping_factor",
            chi,
            "times impact_speed overflows",
        ));
    }
    // z = t x with z²ω(z) = x²ψ(x); z ≤ x (since 1 − e^(−x) ≤ ln(1 + x)), t ∈ [0, 1].
    let target = log_remainder(x);
    let tol = RootTolerance {
        absolute: 1e-17,
        relative: 1e-15,
        max_iterations: 500,
    };
    let root = brent(|t| t * t * exp_remainder(t * x) - target, 0.0, 1.0, tol)?;
    let t = root.value;
    Ok((t * exp_ratio(t * x)).clamp(0.0, 1.0))
}

/// The damping factor χ (s/m) with which `F = K δⁿ (1 + χ δ̇)` rebounds with
/// exactly `restitution` ε ∈ (0, 1] from an impact at `impact_speed` v0: the inverse
/// of [`damped_restitution`] (same first integral), for any K, n and mass.
///
/// Solved by Brent's method for z = −ln(1 − ε x) ∈ (0, 1 + 1/ε) (z ≤ x < 1/ε),
/// relative tolerance 1e-15. To first order in 1 − ε, χ v0 = 3(1 − ε)/2: the
/// Hunt-Crossley factor.
pub fn exact_damping_factor(restitution: f64, impact_speed: f64) -> Result<f64> {
    let e = valid::restitution(restitution)?;
    let v0 = validate::positive("impact_speed", impact_speed)?;
    if e == 1.0 {
        return Ok(0.0);
    }
    let hi = 1.0 + 1.0 / e;
    if !hi.is_finite() {
        return Err(Error::invalid(
            "restitution",
            e,
            "is so small that the damping factor overflows",
        ));
    }
    // ω(z) = (q(z)/ε)² ψ(q(z) z/ε): the first integral divided by z².
    let balance = |z: f64| {
        let q = exp_ratio(z);
        let ratio = q / e;
        exp_remainder(z) - ratio * ratio * log_remainder(ratio * z)
    };
    let tol = RootTolerance {
        absolute: 0.0,
        relative: 1e-15,
        max_iterations: 500,
    };
    let root = brent(balance, 0.0, hi, tol)?;
    let z = root.value;
    let x = exp_ratio(z) * z / e;
    finite_damping(x / v0, e)
}

/// The penalty law `F = K δⁿ (1 + χ δ̇)` (Hunt & Crossley 1975, eq. for the
/// "hysteresis damping" force; Lankarani & Nikravesh 1990 and Flores et al. 2011
/// use the same form with other χ), δ the overlap, zero force for δ ≤ 0.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct DampedPowerLaw {
    stiffness: f64,
    exponent: f64,
    damping_factor: f64,
}

impl DampedPowerLaw {
    /// The law with `stiffness` K > 0 (N/mⁿ), `exponent` n ∈ (0, 10] (3/2 for Hertz,
    /// 1 for a linear spring) and `damping_factor` χ ≥ 0 (s/m).
    pub fn new(stiffness: f64, exponent: f64, damping_factor: f64) -> Result<Self> {
        let law = DampedPowerLaw {
            stiffness: validate::positive("stiffness", stiffness)?,
            exponent: valid::exponent(exponent)?,
            damping_factor: validate::non_negative("damping_factor", damping_factor)?,
        };
        // the damping coefficient χ K must be finite too
        if !law.damping_coefficient().is_finite() {
            return Err(Error::invalid(
                "damping_factor",
                damping_factor,
                "times the stiffness overflows",
            ));
        }
        Ok(law)
    }

    /// The law whose damping factor is `model`'s nominal χ for `restitution` ε at
    /// `impact_speed` v0 ([`DampingModel::damping_factor`]).
    pub fn from_model(
        model: DampingModel,
        stiffness: f64,
        exponent: f64,
        restitution: f64,
        impact_speed: f64,
    ) -> Result<Self> {
        let chi = model.damping_factor(restitution, impact_speed)?;
        DampedPowerLaw::new(stiffness, exponent, chi)
    }

    /// The stiffness K (N/mⁿ).
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// The exponent n.
    pub fn exponent(&self) -> f64 {
        self.exponent
    }

    /// The hysteresis damping factor χ (s/m).
    pub fn damping_factor(&self) -> f64 {
        self.damping_factor
    }

    /// The damping coefficient `D = χ K` of the force `K δⁿ + D δⁿ δ̇` (N s/m^(n+1)).
    pub fn damping_coefficient(&self) -> f64 {
        self.damping_factor * self.stiffness
    }

    /// The force `K δⁿ (1 + χ δ̇)` (N, repulsive > 0) at `overlap` δ (m; 0 for
    /// δ ≤ 0) and `overlap_rate` δ̇ (m/s). Hunt & Crossley (1975).
    pub fn force(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        let d = validate::finite("overlap", overlap)?;
        let r = validate::finite("overlap_rate", overlap_rate)?;
        validate::finite("force", self.force_unchecked(d, r))
    }

    fn force_unchecked(&self, d: f64, r: f64) -> f64 {
        if d <= 0.0 {
            0.0
        } else {
            self.stiffness * d.powf(self.exponent) * (1.0 + self.damping_factor * r)
        }
    }

    /// The restitution this law produces at `impact_speed` (m/s):
    /// [`damped_restitution`] (exact, independent of K, n and the mass).
    pub fn restitution(&self, impact_speed: f64) -> Result<f64> {
        damped_restitution(self.damping_factor, impact_speed)
    }
}

impl ForceLaw for DampedPowerLaw {
    fn name(&self) -> String {
        format!(
            "damped power law K d^n (1 + chi d') (K = {:e}, n = {}, chi = {:e} s/m)",
            self.stiffness, self.exponent, self.damping_factor
        )
    }

    /// d_max of the undamped law, `((n + 1) m v0² / (2K))^(1/(n+1))`.
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let m = validate::positive("effective_mass", effective_mass)?;
        let v0 = validate::positive("impact_speed", impact_speed)?;
        let n = self.exponent;
        let energy = (n + 1.0) * m * v0 * v0 / (2.0 * self.stiffness);
        validate::positive("overlap_scale", energy.powf(1.0 / (n + 1.0)))
    }

    fn force(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        validate::finite("force", self.force_unchecked(overlap, overlap_rate))
    }

    /// A penalty law has no contact radius: 0.
    fn contact_radius(&self, _overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(0.0)
    }
}

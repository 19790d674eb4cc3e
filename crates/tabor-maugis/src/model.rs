//! The physical-unit front: a Maugis-Dugdale impact as a [`tabor_restitution::ImpactModel`].

use crate::impact::{normalized_loss, MaugisNormalizedLoss};
use crate::units::{tabor_parameter_from_cohesive_stress, tabor_parameter_from_range, JkrScales};
use tabor_jkr::JkrSphere;
use tabor_restitution::{validate, EnergyLoss, ImpactModel, Result};

/// A Maugis-Dugdale contact: the JKR sphere (effective modulus E*, effective radius
/// R, work of adhesion Δγ) with a finite range of adhesion, given by the seed's Tabor
/// parameter Λ (Λ → ∞ is the JKR limit, Λ → 0 the DMT limit).
///
/// Seed 000 section 5.3.2, eqs. (5.40)-(5.46): the Dugdale cohesive zone on the
/// parabolic contact of (5.33)-(5.34), normalized by the JKR scales `a_c`, `F_n`, `d_n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaugisContact {
    sphere: JkrSphere,
    tabor_parameter: f64,
}

impl MaugisContact {
    /// The contact of `sphere` with Tabor parameter Λ = `tabor_parameter` (> 0).
    ///
    /// Seed 000 section 5.3.2, eqs. (5.40)-(5.46) (Λ as defined in the crate docs,
    /// "Normalization").
    pub fn new(sphere: JkrSphere, tabor_parameter: f64) -> Result<Self> {
        Ok(MaugisContact {
            sphere,
            tabor_parameter: validate::positive("tabor_parameter", tabor_parameter)?,
        })
    }

    /// The contact of `sphere` with the Dugdale cohesive stress σ0 (Pa) instead of Λ:
    /// `Λ = σ0 a_c² / (3 R Δγ)`.
    ///
    /// Seed 000 section 5.3.2, eqs. (5.40)-(5.46); the conversion of the crate docs,
    /// "Normalization"
    /// ([`tabor_parameter_from_cohesive_stress`]).
    pub fn from_cohesive_stress(sphere: JkrSphere, cohesive_stress: f64) -> Result<Self> {
        let l = tabor_parameter_from_cohesive_stress(
            cohesive_stress,
            sphere.work_of_adhesion(),
            sphere.effective_modulus(),
            sphere.effective_radius(),
        )?;
        Self::new(sphere, l)
    }

    /// The contact of `sphere` with the range of adhesion h = Δγ/σ0 (m) instead of Λ.
    ///
    /// Seed 000 section 5.3.2, eqs. (5.40)-(5.46); the conversion of the crate docs,
    /// "Normalization"
    /// ([`tabor_parameter_from_range`]).
    pub fn from_range(sphere: JkrSphere, range: f64) -> Result<Self> {
        let l = tabor_parameter_from_range(
            range,
            sphere.work_of_adhesion(),
            sphere.effective_modulus(),
            sphere.effective_radius(),
        )?;
        Self::new(sphere, l)
    }

    /// The JKR sphere (E*, R, Δγ and the scales `a_c`, `F_n`, `d_n`).
    ///
    /// Seed 000 eqs. (5.33)-(5.34).
    pub fn sphere(&self) -> JkrSphere {
        self.sphere
    }

    /// The Tabor parameter Λ.
    ///
    /// Seed 000 eq. (5.43) (`W(Λ)`).
    pub fn tabor_parameter(&self) -> f64 {
        self.tabor_parameter
    }
}

/// A Maugis-Dugdale adhesive impact in SI units: a [`MaugisContact`] (E*, R, Δγ, Λ),
/// the effective mass m, and the relative tolerance of the direct evaluation (default
/// 1e-12).
///
/// Seed 000 eq. (5.43): `|ΔU_kin| = F_n d_n · W(Λ)`; the loss does not depend on the
/// impact speed, so the sticking velocity is the closed form (5.38).
#[derive(Clone, Debug, PartialEq)]
pub struct MaugisDugdaleImpact {
    scales: JkrScales,
    tabor_parameter: f64,
    effective_mass: f64,
    tolerance: f64,
}

impl MaugisDugdaleImpact {
    /// The impact of the contact `contact` with effective mass m (kg, > 0).
    ///
    /// Seed 000 eq. (5.43).
    pub fn new(contact: MaugisContact, effective_mass: f64) -> Result<Self> {
        Ok(MaugisDugdaleImpact {
            scales: contact.sphere.scales(),
            tabor_parameter: contact.tabor_parameter,
            effective_mass: validate::positive("effective_mass", effective_mass)?,
            tolerance: tabor_numerics::tolerance::DEFAULT_TOLERANCE,
        })
    }

    /// The same impact evaluated to relative tolerance `tolerance` ∈ [1e-15, 0.5].
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        self.tolerance = validate::tolerance("tolerance", tolerance)?;
        Ok(self)
    }

    /// The Tabor parameter Λ.
    pub fn tabor_parameter(&self) -> f64 {
        self.tabor_parameter
    }

    /// The scales a_c, F_n, d_n, F_n d_n.
    pub fn scales(&self) -> JkrScales {
        self.scales
    }

    /// The normalized loss W(Λ) with its case, error estimate and cost.
    pub fn normalized_loss(&self) -> Result<MaugisNormalizedLoss> {
        normalized_loss(self.tabor_parameter, self.tolerance)
    }

    /// The adhesive loss |ΔU_kin| in joules, seed 000 eq. (5.43).
    pub fn energy_loss_joules(&self) -> Result<f64> {
        // F_n d_n is finite, but W · F_n d_n may overflow: an error, not ∞
        validate::finite_output(
            MODEL,
            "energy loss",
            self.normalized_loss()?.loss * self.scales.energy,
        )
    }
}

/// The model name in output errors.
const MODEL: &str = "Maugis-Dugdale impact";

impl ImpactModel for MaugisDugdaleImpact {
    fn name(&self) -> String {
        format!("Maugis-Dugdale (Lambda = {:.6e})", self.tabor_parameter)
    }
    fn effective_mass(&self) -> f64 {
        self.effective_mass
    }
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        validate::positive("impact_speed", impact_speed)?;
        let w = self.normalized_loss()?;
        Ok(EnergyLoss {
            joules: validate::finite_output(MODEL, "energy loss", w.loss * self.scales.energy)?,
            error_estimate: validate::finite_output(
                MODEL,
                "error estimate",
                w.error_estimate * self.scales.energy,
            )?,
            branch: w.method.to_string(),
            cost: w.cost,
        })
    }
    fn loss_is_speed_independent(&self) -> bool {
        true
    }
    fn speed_scale(&self) -> f64 {
        (2.0 * self.scales.energy / self.effective_mass).sqrt()
    }
}

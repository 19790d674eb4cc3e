//! The physical-unit front: a Maugis-Dugdale impact as a [`tabor_restitution::ImpactModel`].

use crate::impact::{normalized_loss, MaugisNormalizedLoss};
use crate::units::{tabor_parameter_from_cohesive_stress, tabor_parameter_from_range, JkrScales};
use tabor_restitution::{validate, EnergyLoss, ImpactModel, Result};

/// A Maugis-Dugdale adhesive impact in SI units: effective modulus E*, effective
/// radius R, work of adhesion Δγ, Tabor parameter Λ, effective mass m, and the
/// relative tolerance of the direct evaluation (default 1e-12).
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
    /// From E* (Pa), R (m), Δγ (J/m²), Λ and m (kg).
    pub fn new(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        tabor_parameter: f64,
        effective_mass: f64,
    ) -> Result<Self> {
        Ok(MaugisDugdaleImpact {
            scales: JkrScales::new(effective_modulus, effective_radius, work_of_adhesion)?,
            tabor_parameter: validate::positive("tabor_parameter", tabor_parameter)?,
            effective_mass: validate::positive("effective_mass", effective_mass)?,
            tolerance: 1e-12,
        })
    }

    /// From the cohesive stress σ0 (Pa) instead of Λ.
    pub fn from_cohesive_stress(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        cohesive_stress: f64,
        effective_mass: f64,
    ) -> Result<Self> {
        let l = tabor_parameter_from_cohesive_stress(
            cohesive_stress,
            work_of_adhesion,
            effective_modulus,
            effective_radius,
        )?;
        Self::new(
            effective_modulus,
            effective_radius,
            work_of_adhesion,
            l,
            effective_mass,
        )
    }

    /// From the range of adhesion h = Δγ/σ0 (m) instead of Λ.
    pub fn from_range(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        range: f64,
        effective_mass: f64,
    ) -> Result<Self> {
        let l = tabor_parameter_from_range(
            range,
            work_of_adhesion,
            effective_modulus,
            effective_radius,
        )?;
        Self::new(
            effective_modulus,
            effective_radius,
            work_of_adhesion,
            l,
            effective_mass,
        )
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

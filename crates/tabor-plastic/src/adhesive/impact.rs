//! The adhesive interpolation model in SI units: the shell around the normalized
//! core, an [`ImpactModel`]. Seed 000, eqs. (5.111)-(5.126).

use super::normalized::{adhesion_parameter, AdhesiveInterpolation};
use super::{AdhesiveForceLaw, MODEL};
use crate::util::{finite_output, positive_output};
use tabor_jkr::{JkrImpact, JkrSphere};
use tabor_restitution::{sticking_velocity, validate, EnergyLoss, ImpactModel, Result};

/// An adhesive elastic-plastic contact: the JKR sphere (effective modulus `E*`,
/// effective radius `R`, work of adhesion `Δγ`) whose softer body yields, the onset of
/// yield given by the adhesion parameter Φ.
///
/// Seed 000, eqs. (5.111)-(5.126) (Φ as in [`adhesion_parameter`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdhesivePlasticContact {
    sphere: JkrSphere,
    model: AdhesiveInterpolation,
}

impl AdhesivePlasticContact {
    /// The contact of `sphere` with the adhesion parameter Φ = `adhesion_parameter`
    /// given directly.
    ///
    /// Seed 000, eqs. (5.111)-(5.125).
    pub fn new(sphere: JkrSphere, adhesion_parameter: f64) -> Result<Self> {
        Ok(AdhesivePlasticContact {
            sphere,
            model: AdhesiveInterpolation::new(adhesion_parameter)?,
        })
    }

    /// The contact of `sphere` whose softer body has yield stress `σ_Y` (Pa); Φ by
    /// [`adhesion_parameter`] from `E*`, `R`, `σ_Y` and `Δγ` of the sphere.
    ///
    /// Seed 000, eqs. (5.111)-(5.126).
    pub fn from_yield_stress(sphere: JkrSphere, yield_stress: f64) -> Result<Self> {
        let phi = adhesion_parameter(
            sphere.effective_modulus(),
            sphere.effective_radius(),
            yield_stress,
            sphere.work_of_adhesion(),
        )?;
        Self::new(sphere, phi)
    }

    /// The JKR sphere (scales `a_c`, `F_n`, `d_n`).
    ///
    /// Seed 000, eqs. (5.33)-(5.34).
    pub fn sphere(&self) -> &JkrSphere {
        &self.sphere
    }

    /// The adhesion parameter Φ.
    ///
    /// Seed 000, eq. (5.111).
    pub fn adhesion_parameter(&self) -> f64 {
        self.model.adhesion_parameter()
    }
}

/// The adhesive interpolation model in SI units: an [`ImpactModel`].
///
/// As Δγ → 0 its restitution tends to that of `PlasticImpact<Interpolation::default()>`
/// (the derived `Q̃`, `D̃`, `κ`). It is not monotone in Δγ: for Φ below about 3 the
/// JKR unloading (5.121)-(5.125) returns more energy than Hertz unloading, and ε lies
/// above the non-adhesive value (by up to about 0.08; README).
///
/// Seed 000, eqs. (5.111)-(5.126).
#[derive(Clone, Debug)]
pub struct AdhesiveInterpolationImpact {
    model: AdhesiveInterpolation,
    sphere: JkrSphere,
    mass: f64,
    elastic_sticking_velocity: f64,
    yield_velocity: f64,
}

impl AdhesiveInterpolationImpact {
    /// The impact of the contact `contact` with effective mass `m` (kg).
    ///
    /// Seed 000, eqs. (5.111)-(5.125).
    pub fn new(contact: AdhesivePlasticContact, effective_mass: f64) -> Result<Self> {
        let AdhesivePlasticContact { sphere, model } = contact;
        let elastic = JkrImpact::new(sphere, effective_mass)?;
        let v_c = sticking_velocity(&elastic, tabor_numerics::tolerance::DEFAULT_TOLERANCE)?.speed;
        let v_c = positive_output(MODEL, "elastic sticking velocity", v_c)?;
        let energy = sphere.scales().energy;
        let yield_velocity = finite_output(
            MODEL,
            "yield velocity",
            (2.0 * model.yield_kinetic_energy().max(0.0) * energy / effective_mass).sqrt(),
        )?;
        Ok(AdhesiveInterpolationImpact {
            model,
            sphere,
            mass: effective_mass,
            elastic_sticking_velocity: v_c,
            yield_velocity,
        })
    }

    /// The normalized model.
    ///
    /// Seed 000, eqs. (5.111)-(5.125).
    pub fn model(&self) -> &AdhesiveInterpolation {
        &self.model
    }

    /// The JKR sphere (scales `a_c`, `F_n`, `d_n`).
    ///
    /// Seed 000, eqs. (5.33)-(5.34) (the JKR relations used for loading and unloading).
    pub fn sphere(&self) -> &JkrSphere {
        &self.sphere
    }

    /// The elastic JKR sticking velocity `v_c` (m/s), seed 000 eq. (5.38).
    pub fn elastic_sticking_velocity(&self) -> f64 {
        self.elastic_sticking_velocity
    }

    /// The impact speed (m/s) at which the contact reaches the adhesive yield onset
    /// (5.111) (0 when it yields at first touch or inside the adhesive well).
    ///
    /// Seed 000, eqs. (5.35), (5.111)-(5.113).
    pub fn yield_velocity(&self) -> f64 {
        self.yield_velocity
    }

    /// The time-domain force law of this model for `tabor_dynamics::simulate_impact`:
    /// jump-in at first touch, loading (JKR, cubic, plastic), turning point, JKR
    /// unloading with `R_p` and `d_res`, snap-off at (5.125).
    ///
    /// Seed 000, eqs. (5.111)-(5.125).
    pub fn force_law(&self) -> AdhesiveForceLaw {
        AdhesiveForceLaw::new(self.model, self.sphere.scales())
    }

    /// Kinetic energy of an impact at `v0`, in units of `F_n d_n`.
    fn kinetic(&self, impact_speed: f64) -> Result<f64> {
        let v = validate::positive("impact_speed", impact_speed)?;
        positive_output(
            MODEL,
            "kinetic energy",
            0.5 * self.mass * v * v / self.sphere.scales().energy,
        )
    }
}

impl ImpactModel for AdhesiveInterpolationImpact {
    fn name(&self) -> String {
        format!(
            "adhesive interpolation (Phi = {:.4})",
            self.model.adhesion_parameter()
        )
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    /// Seed 000, eqs. (5.111)-(5.125), in units of `F_n d_n`.
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let k = self.kinetic(impact_speed)?;
        let loss = self.model.energy_loss(k)? * self.sphere.scales().energy;
        Ok(EnergyLoss::closed_form(
            finite_output(MODEL, "energy loss", loss)?,
            "adhesive interpolation (5.111)-(5.125)",
        ))
    }
    fn speed_scale(&self) -> f64 {
        self.elastic_sticking_velocity
    }
}

//! Physical-unit (SI) fronts: the dimensionless cores as
//! [`tabor_restitution::ImpactModel`]s. Each converts its inputs into the model's
//! dimensionless parameters, asks the core for ε and returns the loss
//! `|ΔU| = (1 − ε²) m v0²/2` (the inverse of seed 000 eq. (5.37)).

use crate::kelvin_voigt_sphere::SphereModel;
use crate::scaled::ScaledImpact;
use crate::{kelvin_maxwell_sphere, kelvin_voigt_flat, kelvin_voigt_sphere, standard_sphere};
use tabor_restitution::{validate, EnergyLoss, ImpactModel, Result};

/// Relative tolerance of the integrations behind the physical models (1e-9).
const TOLERANCE: f64 = tabor_numerics::tolerance::COSTLY_TOLERANCE;

fn loss_from(scaled: &ScaledImpact, mass: f64, speed: f64, branch: &str) -> Result<EnergyLoss> {
    let kinetic = 0.5 * mass * speed * speed;
    let e = scaled.restitution;
    Ok(EnergyLoss {
        joules: validate::non_negative("energy_loss", (1.0 - e * e) * kinetic)?,
        error_estimate: 2.0 * e * TOLERANCE * kinetic,
        branch: branch.to_string(),
        cost: scaled.cost,
    })
}

/// A rigid flat punch of radius a and mass m on an incompressible Kelvin-Voigt
/// half-space (G, η). ε does not depend on the impact speed.
///
/// Seed 000, eqs. (5.54)-(5.63).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KelvinVoigtFlatPunch {
    damping_ratio: f64,
    mass: f64,
}

impl KelvinVoigtFlatPunch {
    /// From the shear modulus G (Pa), the shear viscosity η (Pa s), the punch radius
    /// a (m) and the mass m (kg).
    ///
    /// Seed 000, eq. (5.55).
    pub fn new(shear_modulus: f64, viscosity: f64, punch_radius: f64, mass: f64) -> Result<Self> {
        Ok(KelvinVoigtFlatPunch {
            damping_ratio: kelvin_voigt_flat::damping_ratio(
                shear_modulus,
                viscosity,
                punch_radius,
                mass,
            )?,
            mass,
        })
    }

    /// The damping ratio D.
    ///
    /// Seed 000, eq. (5.55).
    pub fn damping_ratio(&self) -> f64 {
        self.damping_ratio
    }
}

impl ImpactModel for KelvinVoigtFlatPunch {
    fn name(&self) -> String {
        "Kelvin-Voigt flat punch".into()
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let v = validate::positive("impact_speed", impact_speed)?;
        let e = kelvin_voigt_flat::restitution(self.damping_ratio)?;
        let kinetic = 0.5 * self.mass * v * v;
        Ok(EnergyLoss::closed_form(
            validate::non_negative("energy_loss", (1.0 - e * e) * kinetic)?,
            "Kelvin-Voigt flat punch closed form (5.61)-(5.63)",
        ))
    }
}

/// A rigid sphere (radius R, mass m) on an incompressible Kelvin-Voigt half-space
/// (G, η), Kuwabara-Kono or rigorous.
///
/// Seed 000, eqs. (5.64)-(5.68).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KelvinVoigtSphere {
    shear_modulus: f64,
    viscosity: f64,
    radius: f64,
    mass: f64,
    model: SphereModel,
    tolerance: f64,
}

impl KelvinVoigtSphere {
    /// From G (Pa), η (Pa s), the radius R (m), the mass m (kg) and the model.
    ///
    /// Seed 000, eqs. (5.64)-(5.68).
    pub fn new(
        shear_modulus: f64,
        viscosity: f64,
        radius: f64,
        mass: f64,
        model: SphereModel,
    ) -> Result<Self> {
        Ok(KelvinVoigtSphere {
            shear_modulus: validate::positive("shear_modulus", shear_modulus)?,
            viscosity: validate::positive("viscosity", viscosity)?,
            radius: validate::positive("radius", radius)?,
            mass: validate::positive("mass", mass)?,
            model,
            tolerance: TOLERANCE,
        })
    }

    /// The same sphere integrated at relative tolerance `tolerance` (default
    /// 1e-9; [`kelvin_voigt_sphere::solve`] accepts [1e-15, 0.5]).
    pub fn with_tolerance(self, tolerance: f64) -> Result<Self> {
        Ok(KelvinVoigtSphere {
            tolerance: validate::tolerance("tolerance", tolerance)?,
            ..self
        })
    }

    /// δ at the impact speed v0 (m/s).
    ///
    /// Seed 000, eq. (5.68).
    pub fn viscous_parameter(&self, impact_speed: f64) -> Result<f64> {
        kelvin_voigt_sphere::viscous_parameter(
            self.viscosity,
            self.radius,
            impact_speed,
            self.mass,
            self.shear_modulus,
        )
    }
}

impl ImpactModel for KelvinVoigtSphere {
    fn name(&self) -> String {
        format!("Kelvin-Voigt sphere ({})", self.model.as_str())
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let delta = self.viscous_parameter(impact_speed)?;
        // 1 − ε from the dissipated energy, accurate relative to itself: a tiny
        // loss (δ → 0, two stiff bodies) is a number, not the rounding of 1 − ε².
        let o = kelvin_voigt_sphere::solve_with_loss(delta, self.model, self.tolerance, None)?;
        let kinetic = 0.5 * self.mass * impact_speed * impact_speed;
        let e = o.impact.restitution;
        let joules = o.loss * (1.0 + e) * kinetic;
        Ok(EnergyLoss {
            joules: validate::non_negative("energy_loss", joules)?,
            error_estimate: 2.0 * self.tolerance.min(1e-3) * joules.max(e * kinetic),
            branch: "Kelvin-Voigt sphere (5.64)-(5.68)".to_string(),
            cost: o.impact.cost,
        })
    }
    fn speed_scale(&self) -> f64 {
        1.0
    }
}

/// A rigid sphere on a standard medium (G∞, G1, η) or a Kelvin-Maxwell medium
/// (G∞, G1 with relaxation time (5.12), dashpot η0), by the MDR.
///
/// Seed 000, eqs. (5.84)-(5.92).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaxwellBranchSphere {
    relaxed_modulus: f64,
    branch_modulus: f64,
    viscosity: f64,
    radius: f64,
    mass: f64,
    kelvin_maxwell: bool,
}

impl MaxwellBranchSphere {
    /// Standard medium: relaxed modulus G∞, branch modulus G1 (Pa), branch
    /// viscosity η (Pa s), radius R (m), mass m (kg).
    ///
    /// Seed 000, eqs. (5.75), (5.84)-(5.90).
    pub fn standard(
        relaxed_modulus: f64,
        branch_modulus: f64,
        viscosity: f64,
        radius: f64,
        mass: f64,
    ) -> Result<Self> {
        Self::checked(
            relaxed_modulus,
            branch_modulus,
            viscosity,
            radius,
            mass,
            false,
        )
    }

    /// Kelvin-Maxwell medium: G∞, G1 (Pa), parallel dashpot η0 (Pa s), radius R (m),
    /// mass m (kg); the branch relaxes over the elastic contact time (5.12).
    ///
    /// Seed 000, eqs. (5.91), (5.92).
    pub fn kelvin_maxwell(
        relaxed_modulus: f64,
        branch_modulus: f64,
        dashpot_viscosity: f64,
        radius: f64,
        mass: f64,
    ) -> Result<Self> {
        Self::checked(
            relaxed_modulus,
            branch_modulus,
            dashpot_viscosity,
            radius,
            mass,
            true,
        )
    }

    fn checked(g: f64, g1: f64, eta: f64, r: f64, m: f64, km: bool) -> Result<Self> {
        Ok(MaxwellBranchSphere {
            relaxed_modulus: validate::positive("relaxed_modulus", g)?,
            branch_modulus: validate::positive("branch_modulus", g1)?,
            viscosity: validate::positive("viscosity", eta)?,
            radius: validate::positive("radius", r)?,
            mass: validate::positive("mass", m)?,
            kelvin_maxwell: km,
        })
    }

    /// (β, δ) at the impact speed v0 (m/s).
    ///
    /// Seed 000, eqs. (5.90), (5.92).
    pub fn parameters(&self, impact_speed: f64) -> Result<(f64, f64)> {
        standard_sphere::parameters(
            self.relaxed_modulus,
            self.branch_modulus,
            self.viscosity,
            self.radius,
            impact_speed,
            self.mass,
        )
    }
}

impl ImpactModel for MaxwellBranchSphere {
    fn name(&self) -> String {
        if self.kelvin_maxwell {
            "Kelvin-Maxwell sphere (MDR)".into()
        } else {
            "standard-medium sphere (MDR)".into()
        }
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let (b, d) = self.parameters(impact_speed)?;
        let s = if self.kelvin_maxwell {
            kelvin_maxwell_sphere::solve(b, d, TOLERANCE)?
        } else {
            standard_sphere::solve(b, d, TOLERANCE)?
        };
        loss_from(&s, self.mass, impact_speed, "MDR (5.84)-(5.92)")
    }
}

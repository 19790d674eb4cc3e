//! [`SimulatedImpact`]: the simulation as an [`ImpactModel`] (restitution and
//! sticking velocity from `tabor-restitution`).

use super::{simulate_impact, ImpactSimulation, SimulationSettings};
use crate::law::ForceLaw;
use tabor_restitution::{validate, EnergyLoss, ImpactModel, Result};

/// An [`ImpactModel`] whose energy loss comes from [`simulate_impact`]: any
/// [`ForceLaw`] gets restitution (5.37) and sticking velocity (5.38) from
/// `tabor-restitution` for free.
#[derive(Clone, Debug)]
pub struct SimulatedImpact<L> {
    law: L,
    mass: f64,
    settings: SimulationSettings,
}

impl<L: ForceLaw + Clone> SimulatedImpact<L> {
    /// The model of `law` with effective mass `effective_mass` (kg).
    pub fn new(law: L, effective_mass: f64, settings: SimulationSettings) -> Result<Self> {
        Ok(SimulatedImpact {
            law,
            mass: validate::positive("effective_mass", effective_mass)?,
            settings: SimulationSettings {
                record_trajectory: false,
                ..settings
            },
        })
    }

    /// Simulates one impact at `impact_speed` on a copy of the law.
    pub fn simulate(&self, impact_speed: f64) -> Result<ImpactSimulation> {
        let mut law = self.law.clone();
        simulate_impact(&mut law, self.mass, impact_speed, &self.settings)
    }
}

impl<L: ForceLaw + Clone> ImpactModel for SimulatedImpact<L> {
    fn name(&self) -> String {
        format!("{} (time-domain simulation)", self.law.name())
    }

    fn effective_mass(&self) -> f64 {
        self.mass
    }

    /// The kinetic energy lost in the simulated impact, seed 000 eq. (5.37) read
    /// backwards; tiny negative values from the integration error are clipped to 0
    /// and the error estimate is the energy bookkeeping error.
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let sim = self.simulate(impact_speed)?;
        let error_estimate = sim.energy_error * sim.kinetic_energy;
        Ok(EnergyLoss {
            joules: sim.energy_loss.max(0.0),
            error_estimate: error_estimate + (-sim.energy_loss).max(0.0),
            branch: format!("time-domain simulation of {}", sim.law),
            cost: sim.cost,
        })
    }
}

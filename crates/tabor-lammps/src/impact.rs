//! A LAMMPS granular model between two given bodies as a
//! `tabor_restitution::ImpactModel`: its restitution at a speed and its sticking
//! velocity through `tabor_restitution::sticking_velocity`.

use crate::law::{GranularModel, LammpsLaw};
use tabor_dynamics::{EventKind, ImpactSimulation, SimulatedImpact, SimulationSettings};
use tabor_numerics::quadrature::integrate_smooth;
use tabor_numerics::QuadTolerance;
use tabor_restitution::{sticking_velocity, EnergyLoss, ImpactModel, Result, StickingMethod};

/// The relative tolerance of the sticking velocities of LAMMPS models: the
/// workspace's default for sticking-velocity searches
/// (`tabor_numerics::tolerance::ACCURACY`, 1e-10).
pub const STICKING_TOLERANCE: f64 = tabor_numerics::tolerance::ACCURACY;

/// The excess, as a fraction of m v²/2, that a sticking impact reports beyond its
/// escape energy, so that g(v) = 1 − 2W/(m v²) is negative wherever the bodies
/// stick (the search needs a sign change); far below the resolution of g near the
/// root, where g ∝ (v − v_c)/v_c.
const STICK_EXCESS: f64 = 1e-14;

impl GranularModel {
    /// Simulates a central impact at relative normal speed `speed` (m/s) with this
    /// model: the restitution LAMMPS produces in the limit of a small time step
    /// ([`LammpsImpact::simulate`]).
    pub fn impact(
        &self,
        effective_radius: f64,
        effective_mass: f64,
        speed: f64,
    ) -> Result<ImpactSimulation> {
        LammpsImpact::new(*self, effective_radius, effective_mass)?.simulate(speed)
    }
}

/// A [`GranularModel`] between bodies of effective radius R and reduced mass m.
#[derive(Clone, Debug)]
pub struct LammpsImpact {
    model: GranularModel,
    law: LammpsLaw,
    simulated: SimulatedImpact<LammpsLaw>,
    speed_scale: f64,
}

impl LammpsImpact {
    /// The impacts of `model` for effective radius `effective_radius` (m) and
    /// reduced mass `effective_mass` (kg), integrated by tabor's simulator at its
    /// default tolerance (`tabor_numerics::tolerance::ODE_TOLERANCE`, relative
    /// 1e-11): what LAMMPS produces in the limit of a
    /// small time step. The sticking-velocity search starts at 1 m/s (see
    /// [`LammpsImpact::with_speed_scale`]).
    pub fn new(model: GranularModel, effective_radius: f64, effective_mass: f64) -> Result<Self> {
        let law = model.law(effective_radius, effective_mass)?;
        let settings = SimulationSettings {
            record_trajectory: false,
            ..SimulationSettings::default()
        };
        Ok(LammpsImpact {
            model,
            law: law.clone(),
            simulated: SimulatedImpact::new(law, effective_mass, settings)?,
            speed_scale: 1.0,
        })
    }

    /// The same, with the sticking-velocity search starting at `speed` (m/s; a
    /// guess of the sticking velocity, finite and > 0, else ignored).
    pub fn with_speed_scale(mut self, speed: f64) -> Self {
        if speed.is_finite() && speed > 0.0 {
            self.speed_scale = speed;
        }
        self
    }

    /// The model.
    pub fn model(&self) -> &GranularModel {
        &self.model
    }

    /// One impact at relative normal speed `speed` (m/s).
    ///
    /// Where the simulator reports sticking at a turning point *beyond* the
    /// separation overlap (the body crossed the separation point and turned back
    /// within one integrator step, so the branch end was not seen at the step's
    /// ends: `tabor_dynamics` locates an event only between step ends of opposite
    /// sign), the impact is corrected to the separation it was: the body crossed
    /// δ_s with the speed u that carried it from δ_s to the turn δ_t against the
    /// elastic-adhesive force, ½ m u² = ∫ −F_e dδ over [δ_t, δ_s] (exact without
    /// damping; with damping the excursion is short and its damping work is of
    /// second order).
    pub fn simulate(&self, speed: f64) -> Result<ImpactSimulation> {
        let mut sim = self.simulated.simulate(speed)?;
        if let Some(turn) = self.turn_beyond_separation(&sim) {
            let separation = self.law.separation_overlap();
            let work = self.work_against_force(turn, separation)?;
            let u = (2.0 * work / self.simulated.effective_mass()).sqrt();
            sim.sticks = false;
            sim.rebound_speed = u;
            sim.restitution = u / sim.impact_speed;
            sim.energy_loss = sim.kinetic_energy - work;
            sim.contact_time = Some(sim.end_time - sim.contact_onset_time);
        }
        Ok(sim)
    }

    /// The restitution at `speed` (m/s), 0 when the bodies stick.
    pub fn restitution(&self, speed: f64) -> Result<f64> {
        let s = self.simulate(speed)?;
        Ok(if s.sticks { 0.0 } else { s.restitution })
    }

    /// The sticking velocity (m/s) to relative tolerance `tolerance`, by
    /// `tabor_restitution::sticking_velocity`; `None` when the model never sticks.
    pub fn sticking_velocity(&self, tolerance: f64) -> Result<Option<f64>> {
        let s = sticking_velocity(self, tolerance)?;
        Ok(match s.method {
            StickingMethod::NeverSticks => None,
            _ => Some(s.speed),
        })
    }
}

impl LammpsImpact {
    /// The energy a body that turned inward at overlap δ_t (the last event of a
    /// sticking impact) lacks to reach the separation overlap δ_s against the
    /// elastic-adhesive force: ∫ −F_e dδ from δ_s to δ_t (J, ≥ 0; 0 without such
    /// a turn).
    fn escape_energy(&self, sim: &ImpactSimulation) -> Result<f64> {
        match last_turn(sim) {
            Some(turn) if turn > self.law.separation_overlap() => {
                self.work_against_force(self.law.separation_overlap(), turn)
            }
            _ => Ok(0.0),
        }
    }

    /// The overlap of the final inward turn of a sticking impact when it lies
    /// beyond the separation overlap (see [`LammpsImpact::simulate`]).
    fn turn_beyond_separation(&self, sim: &ImpactSimulation) -> Option<f64> {
        let turn = last_turn(sim)?;
        (sim.sticks && turn < self.law.separation_overlap()).then_some(turn)
    }

    /// ∫ −F_e dδ over [`from`, `to`] (J, ≥ 0 where the force is attractive).
    fn work_against_force(&self, from: f64, to: f64) -> Result<f64> {
        let work = integrate_smooth(
            |d| -self.law.elastic_force(d),
            from,
            to,
            QuadTolerance::relative(1e-10),
        )
        .map_err(|e| tabor_restitution::Error::Model {
            model: "LAMMPS granular",
            message: format!("work of the adhesive force near separation: {e}"),
        })?;
        Ok(work.value.max(0.0))
    }
}

/// The overlap of the last event when it is an inward turn (ḋ: − → +).
fn last_turn(sim: &ImpactSimulation) -> Option<f64> {
    sim.events
        .last()
        .filter(|e| e.kind == EventKind::MinCompression)
        .map(|e| e.overlap)
}

impl ImpactModel for LammpsImpact {
    fn name(&self) -> String {
        self.simulated.name()
    }

    fn effective_mass(&self) -> f64 {
        self.simulated.effective_mass()
    }

    /// The simulated loss (seed 000 (5.37) read backwards); a sticking impact
    /// reports m v²/2 plus the energy it lacks to escape the well (see
    /// `escape_energy`), so that g(v) = 1 − 2W/(m v²) continues smoothly below
    /// the sticking velocity (for a speed-independent loss W it is exactly
    /// 1 − v_c²/v² on both sides) and `sticking_velocity` converges fast.
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let sim = self.simulate(impact_speed)?;
        let joules = if sim.sticks {
            sim.kinetic_energy * (1.0 + STICK_EXCESS) + self.escape_energy(&sim)?
        } else {
            sim.energy_loss.max(0.0)
        };
        Ok(EnergyLoss {
            joules,
            error_estimate: sim.energy_error * sim.kinetic_energy + (-sim.energy_loss).max(0.0),
            branch: format!("time-domain simulation of {}", sim.law),
            cost: sim.cost,
        })
    }

    fn speed_scale(&self) -> f64 {
        self.speed_scale
    }
}

//! The time-domain simulation of one central impact.
//!
//! - `settings`: [`SimulationSettings`], how accurately and how long;
//! - `outcome`: what a run returns ([`ImpactSimulation`], [`ContactEvent`],
//!   [`EventKind`], [`TrajectoryPoint`]);
//! - this file: [`simulate_impact`] and the normalized units of a run;
//! - `run`: the state between segments and what happens at an event;
//! - `segments`: the integration of one smooth segment to its first event;
//! - `model`: [`SimulatedImpact`], the simulation as an `ImpactModel`.

mod model;
mod outcome;
mod run;
mod segments;
mod settings;

pub use model::SimulatedImpact;
pub use outcome::{ContactEvent, EventKind, ImpactSimulation, TrajectoryPoint};
pub use settings::SimulationSettings;

use crate::law::ForceLaw;
use run::Run;
use tabor_restitution::{validate, Error, Result};

/// Simulates the central impact of effective mass `effective_mass` (kg) at
/// `impact_speed` v0 > 0 (m/s) through `law`: integrates `m d̈ = −F(d, ḋ)` from
/// d = [`ForceLaw::start_overlap`] (0: first contact), ḋ = v0 (seed 000 eq. (5.6)),
/// with the contact work `W = −∫ F ḋ dt` as a third state, until the law separates
/// or sticks. The law is left in its final state.
///
/// The run is a sequence of smooth segments: each is integrated to its first event
/// (`Run::integrate_to_event`), where the law's hook decides how the motion goes on
/// (`Run::handle_event`); the outcome is assembled from the last event
/// (`Run::outcome`).
///
/// Seed 000, eq. (5.5) (and (5.15), (5.20) for the other elastic laws).
pub fn simulate_impact<L: ForceLaw + ?Sized>(
    law: &mut L,
    effective_mass: f64,
    impact_speed: f64,
    settings: &SimulationSettings,
) -> Result<ImpactSimulation> {
    let m = validate::positive("effective_mass", effective_mass)?;
    let v0 = validate::positive("impact_speed", impact_speed)?;
    let kinetic = 0.5 * m * v0 * v0;
    if !(kinetic.is_finite() && kinetic > 0.0) {
        return Err(Error::invalid(
            "impact_speed",
            v0,
            "gives a kinetic energy m v0^2/2 that is zero or overflows",
        ));
    }
    validate::positive("max_duration", settings.max_duration)?;
    law.begin_impact(m, v0)?;
    let scale = validate::positive("overlap_scale", law.overlap_scale(m, v0)?)?;
    let start = validate::finite("start_overlap", law.start_overlap())?;
    let mut run = Run::new(law, Units::new(m, v0, scale), start, settings)?;
    let decision = loop {
        let (kind, hit, coordinate) = run.integrate_to_event(law)?;
        if let Some(decision) = run.handle_event(law, kind, hit, coordinate)? {
            break decision;
        }
    };
    Ok(run.outcome(law, decision, kinetic))
}

/// The normalized units of one simulation: `x = d/L`, `s = t v0/L`, `u = ḋ/v0`,
/// `w = W/(m v0²)`, with L the law's overlap scale.
#[derive(Clone, Copy, Debug)]
struct Units {
    /// Effective mass m (kg).
    mass: f64,
    /// Impact speed v0 (m/s).
    speed: f64,
    /// Overlap scale L (m).
    length: f64,
    /// L/v0 (s).
    time: f64,
    /// m v0²/L (N).
    force: f64,
}

impl Units {
    fn new(mass: f64, speed: f64, length: f64) -> Self {
        Units {
            mass,
            speed,
            length,
            time: length / speed,
            force: mass * speed * speed / length,
        }
    }

    /// Overlap d (m) of the normalized state.
    fn overlap(&self, y: &[f64; 3]) -> f64 {
        y[0] * self.length
    }

    /// Overlap rate ḋ (m/s) of the normalized state.
    fn rate(&self, y: &[f64; 3]) -> f64 {
        y[1] * self.speed
    }
}

//! [`SimulationSettings`]: how accurately and how long to simulate.

use tabor_numerics::ode::OdeTolerance;
use tabor_numerics::tolerance;
use tabor_restitution::{validate, Result};

/// How accurately and how long to simulate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimulationSettings {
    /// Integrator tolerance, applied to the normalized state (d/L, ḋ/v0 and the
    /// contact work over m v0², with L the law's overlap scale), so an absolute
    /// tolerance of 1e-13 means 1e-13 L. `max_step` is in units of L/v0.
    pub tolerance: OdeTolerance,
    /// Keep a [`TrajectoryPoint`](super::TrajectoryPoint) at every accepted step and event.
    pub record_trajectory: bool,
    /// Give up (an error) after this time, in units of L/v0.
    pub max_duration: f64,
    /// Give up (an error) after this many events.
    pub max_events: usize,
}

impl Default for SimulationSettings {
    /// `OdeTolerance::default()` (relative 1e-11, absolute 1e-13: one line in
    /// `tabor_numerics::tolerance`), at most 0.1 L/v0 per step (so that no
    /// turning point is stepped over), trajectory recorded, 10⁶ L/v0, 1000 events.
    fn default() -> Self {
        SimulationSettings {
            tolerance: OdeTolerance::default().with_max_step(0.1),
            record_trajectory: true,
            max_duration: 1e6,
            max_events: 1000,
        }
    }
}

impl SimulationSettings {
    /// Default settings for a requested relative accuracy `relative` of the
    /// impact's outcome (restitution, contact time). The integrator's per-step
    /// tolerance is `relative / 100` (at least 1e-15), absolute a further factor 100
    /// below, in normalized units: local errors add up over the few hundred steps of
    /// an impact, and a per-step tolerance equal to the requested accuracy was
    /// measured to miss it by up to 11× (`examples/accuracy_vs_time.rs`).
    pub fn with_tolerance(relative: f64) -> Result<Self> {
        let rel = validate::tolerance("tolerance", relative)?;
        let mut s = SimulationSettings::default();
        let per_step = (rel * 1e-2).max(tolerance::FINEST_TOLERANCE);
        s.tolerance.relative = per_step;
        s.tolerance.absolute = per_step * 1e-2;
        Ok(s)
    }
}

//! What a simulated impact returns: [`ImpactSimulation`], with its
//! [`ContactEvent`]s ([`EventKind`]) and [`TrajectoryPoint`]s.

use crate::law::BranchChange;
use serde::Serialize;
use tabor_numerics::Cost;

/// One recorded state of the impact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TrajectoryPoint {
    /// Time since the start of the simulation (s).
    pub time: f64,
    /// Overlap d (m), positive in contact.
    pub overlap: f64,
    /// Overlap rate ḋ (m/s).
    pub overlap_rate: f64,
    /// Contact force F (N), repulsive > 0.
    pub force: f64,
    /// Contact radius (m).
    pub contact_radius: f64,
    /// Work done on the body by the contact force so far, `−∫ F ḋ dt` (J); equals
    /// the change of kinetic energy.
    pub contact_work: f64,
}

/// What kind of event the simulation met.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EventKind {
    /// ḋ: + → − (maximum compression).
    MaxCompression,
    /// ḋ: − → + (turned inward again).
    MinCompression,
    /// The law's current branch ended.
    BranchEnd,
}

/// A located event and what the law decided there.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ContactEvent {
    /// Time (s).
    pub time: f64,
    /// Overlap (m).
    pub overlap: f64,
    /// Overlap rate (m/s).
    pub overlap_rate: f64,
    /// What happened.
    pub kind: EventKind,
    /// What the law decided.
    pub decision: BranchChange,
}

/// The result of one simulated impact.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ImpactSimulation {
    /// The law's name.
    pub law: String,
    /// Impact speed v0 (m/s).
    pub impact_speed: f64,
    /// Rebound speed −ḋ at separation (m/s); 0 when the bodies stick.
    pub rebound_speed: f64,
    /// Coefficient of restitution, rebound speed / v0. Not clamped: for a lossless
    /// (elastic) impact it may exceed 1 by the integration error, which
    /// is of the order of [`ImpactSimulation::energy_error`].
    pub restitution: f64,
    /// True when the bodies stay together.
    pub sticks: bool,
    /// Time from contact onset to separation (s); `None` when the bodies stick.
    pub contact_time: Option<f64>,
    /// Time at which contact began (s; 0 for laws that start in contact).
    pub contact_onset_time: f64,
    /// Time at which the simulation ended (separation or sticking) (s).
    pub end_time: f64,
    /// Largest overlap (m), located at the turning point.
    pub max_overlap: f64,
    /// Largest force over the accepted steps and events (N); exact when it occurs
    /// at an event (the turning point of monotone laws).
    pub max_force: f64,
    /// Kinetic energy before the impact, m v0²/2 (J).
    pub kinetic_energy: f64,
    /// Kinetic energy lost, m (v0² − v_rebound²)/2 (J); all of it when sticking.
    pub energy_loss: f64,
    /// Energy bookkeeping error: |ΔE_kin − W_contact| / (m v0²/2), with the contact
    /// work integrated alongside the motion.
    pub energy_error: f64,
    /// The events met, in order.
    pub events: Vec<ContactEvent>,
    /// The recorded trajectory (empty unless requested).
    pub trajectory: Vec<TrajectoryPoint>,
    /// Right-hand-side evaluations and integrator steps.
    pub cost: Cost,
}

//! # tabor-dynamics
//!
//! The time-domain simulation of one central impact, seed 000 eq. (5.5) and its
//! generalizations: `m d̈ = −F(d, ḋ, history)` with the overlap d (positive in
//! contact), starting at first contact (or an approach distance) with ḋ = v0 (5.6),
//! ending at separation or sticking.
//!
//! - [`ForceLaw`]: the contact law, as branches with hooks at located events
//!   (turning points, branch ends) where history may change, so that adhesive
//!   (JKR, Maugis-Dugdale) and plastic laws plug in; every model implements it in its
//!   own crate (`tabor-elastic`, `tabor-jkr`, `tabor-maugis`, `tabor-plastic`, ...), so
//!   this crate stands on `tabor-restitution` and `tabor-numerics` only, below every
//!   model.
//! - [`simulate_impact`]: DOP853 (order 8) run segment by segment by
//!   `tabor_numerics::ode::drive_events` (branch ends and turning points located on
//!   the dense output), energy bookkeeping (the contact work integrated with the
//!   motion), a trajectory record and an [`ImpactSimulation`] outcome.
//! - [`SimulatedImpact`]: any law as a `tabor_restitution::ImpactModel`.

mod law;
mod simulate;

pub use law::{BranchChange, BranchCurve, CurvePoint, ForceLaw, SeparationBarrier};
pub use simulate::{
    simulate_impact, ContactEvent, EventKind, ImpactSimulation, SimulatedImpact,
    SimulationSettings, TrajectoryPoint,
};

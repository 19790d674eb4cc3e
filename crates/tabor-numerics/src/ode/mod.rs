//! Adaptive integrators for small ODE systems `y' = f(t, y)`, `y ∈ ℝᴺ`, with dense
//! output and event location. This module holds what every method shares; the
//! methods live in their own modules:
//!
//! - [`DormandPrince`] (module `dormand_prince`): explicit Runge-Kutta 5(4) with a
//!   4th-order dense output, for non-stiff systems; [`solve`] and
//!   [`solve_until_event`] integrate with it;
//! - [`DormandPrince853`] (module `dop853`): explicit Runge-Kutta of order 8 with a
//!   7th-order dense output prepared on demand, for tight tolerances (the impact
//!   simulator of `tabor-dynamics`);
//! - [`rosenbrock`]: the L-stable Rosenbrock methods Rodas5P (default) and RODAS4,
//!   for stiff systems.
//!
//! Shared here, one file each (re-exported from this module):
//!
//! - [`OdeTolerance`]: the error norm, tolerances and step limits of every method;
//! - [`EventDirection`], [`EventPoint`] and [`locate_event_in_step`]: the sign
//!   changes of a user function `g(t, y)`, located on the dense output of the last
//!   step with Brent's method ([`crate::root_finding::brent`]), so locating them
//!   costs no evaluations of `f`;
//! - [`DenseStepper`]: the interface of a one-step integrator with dense output;
//! - [`drive`] and [`drive_events`]: the one step-and-locate-event loop (one event
//!   function, or several of which the earliest crossing wins), with an observer
//!   called after every accepted step (to record a trajectory or watch the state);
//!   every solver, phase integration and the impact simulator of the workspace is
//!   built on it;
//! - [`OdeSolution`], [`Integration`]: what a driver returns.
//!
//! The state is a fixed-size array `[f64; N]` (no allocation per step).

#![allow(clippy::needless_range_loop)] // component loops over small fixed arrays

mod dop853;
mod dormand_prince;
mod drive;
mod events;
pub mod rosenbrock;
mod solution;
mod stepper;
mod stepper_core;
mod tolerance;

pub use dop853::DormandPrince853;
pub use dormand_prince::{solve, solve_until_event, DormandPrince};

pub use drive::{drive, drive_events};
pub use events::{locate_event_in_step, EventDirection, EventPoint};
pub use solution::{EventsIntegration, Integration, OdeSolution};
pub use stepper::DenseStepper;
pub use tolerance::OdeTolerance;

pub(crate) use drive::drive_unobserved;
pub(crate) use events::no_event;
pub(crate) use stepper::one_step_method;
pub(crate) use stepper_core::{finite, first_non_finite, FailureNames, StepperCore};

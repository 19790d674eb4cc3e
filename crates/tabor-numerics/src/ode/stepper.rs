//! [`DenseStepper`], the interface of a one-step integrator with dense output, and
//! `one_step_method!`, its implementation shared by every method of the module.

use crate::{Cost, Result};

/// A one-step integrator with a dense output on its last accepted step
/// ([`DormandPrince`](super::DormandPrince), [`rosenbrock::Rosenbrock`](super::rosenbrock::Rosenbrock)): what event location
/// ([`locate_event_in_step`](super::locate_event_in_step)) and the driver ([`drive`](super::drive)) need.
pub trait DenseStepper<const N: usize> {
    /// Current time and state.
    fn current(&self) -> (f64, [f64; N]);
    /// Start of the last accepted step.
    fn step_start(&self) -> f64;
    /// The dense output on the last accepted step.
    fn dense(&self, t: f64) -> [f64; N];
    /// One accepted step, not beyond `t_limit`.
    fn advance<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N];
    /// Accepted and rejected steps.
    fn step_counts(&self) -> (u64, u64);
    /// Evaluations of f and steps so far.
    fn spent(&self) -> Cost;
    /// Makes [`DenseStepper::dense`] available on the last accepted step. Methods
    /// whose continuous extension needs extra evaluations of f
    /// ([`DormandPrince853`](super::DormandPrince853)) do them here, once per step, only when asked; for the
    /// others it does nothing. [`drive`](super::drive) calls it before it locates an event or
    /// hands a step to its observer, [`drive_events`](super::drive_events) only on the step that
    /// contains an event.
    fn prepare_dense<F>(&mut self, _f: &mut F) -> Result<()>
    where
        F: FnMut(f64, &[f64; N]) -> [f64; N],
    {
        Ok(())
    }
}

/// The accessors, the event search on the last step and the [`DenseStepper`]
/// implementation that every one-step method of this module shares, written once:
/// the method provides `core: StepperCore<N>`, `dense_output(&self, t)` and
/// `step(&mut self, f, t_limit)` (and, for a lazily prepared dense output,
/// `prepare_dense_output(&mut self, f)`).
macro_rules! one_step_method {
    ($method:ident $(, prepare = $prepare:ident)?) => {
        impl<const N: usize> $method<N> {
            /// Current time (end of the last accepted step).
            pub fn t(&self) -> f64 {
                self.core.t
            }

            /// Current state.
            pub fn y(&self) -> [f64; N] {
                self.core.y
            }

            /// Start of the last accepted step (equal to the current time right after
            /// a (re)start).
            pub fn previous_t(&self) -> f64 {
                self.core.t_old
            }

            /// The size of the next trial step the step-size control proposes
            /// (after a (re)start, the first step it chose): a first step for a
            /// restart of the same motion with a new right-hand side
            /// ([`OdeTolerance::initial_step`](crate::ode::OdeTolerance::initial_step)).
            pub fn proposed_step(&self) -> f64 {
                self.core.h
            }

            /// Accepted and rejected steps so far.
            pub fn steps(&self) -> (u64, u64) {
                self.core.steps()
            }

            /// Right-hand-side evaluations (`evaluations`, including those of a
            /// Jacobian by differences) and steps, accepted plus rejected
            /// (`iterations`), so far.
            pub fn cost(&self) -> Cost {
                self.core.cost()
            }

            /// Searches the last accepted step for a crossing of the event function
            /// `g` in `direction`, given its values `g_before` at the start and
            /// `g_after` at the end of the step. Returns the crossing located by
            /// Brent's method on the dense output to `time_tolerance` (absolute, in
            /// t), with the evaluations of `g` spent, or `None` when the step has no
            /// such crossing ([`locate_event_in_step`](super::locate_event_in_step)).
            pub fn locate_event<G>(
                &self,
                mut g: G,
                direction: EventDirection,
                g_before: f64,
                g_after: f64,
                time_tolerance: f64,
            ) -> Result<Option<(EventPoint<N>, Cost)>>
            where
                G: FnMut(f64, &[f64; N]) -> f64,
            {
                locate_event_in_step(self, &mut g, direction, g_before, g_after, time_tolerance)
            }
        }

        impl<const N: usize> DenseStepper<N> for $method<N> {
            fn current(&self) -> (f64, [f64; N]) {
                (self.core.t, self.core.y)
            }
            fn step_start(&self) -> f64 {
                self.core.t_old
            }
            fn dense(&self, t: f64) -> [f64; N] {
                self.dense_output(t)
            }
            fn advance<F>(&mut self, f: &mut F, t_limit: f64) -> Result<()>
            where
                F: FnMut(f64, &[f64; N]) -> [f64; N],
            {
                self.step(f, t_limit)
            }
            fn step_counts(&self) -> (u64, u64) {
                self.core.steps()
            }
            fn spent(&self) -> Cost {
                self.core.cost()
            }
            $(
            fn prepare_dense<F>(&mut self, f: &mut F) -> Result<()>
            where
                F: FnMut(f64, &[f64; N]) -> [f64; N],
            {
                self.$prepare(f)
            }
            )?
        }
    };
}
pub(crate) use one_step_method;

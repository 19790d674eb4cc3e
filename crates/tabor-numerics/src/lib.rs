//! # tabor-numerics
//!
//! The one numerical layer every tabor model stands on. It holds no physics:
//!
//! - [`roots`](crate::root_finding): Brent's method (from the `roots` crate) with
//!   bracket validation and automatic bracket expansion, and a safeguarded Newton
//!   iteration for smooth problems;
//! - [`quadrature`] — Clenshaw-Curtis (from the `quadrature` crate)
//!   for smooth integrands, tanh-sinh for integrands with endpoint singularities, and
//!   fixed Gauss-Legendre rules for hot loops;
//! - [`special`]: Gamma and Beta functions (from `statrs`), the incomplete beta
//!   function `B(x; a, b)` of seed 000 eqs. (5.11), (5.17) and the Gamma-function
//!   ratios `β(n)`, `β(n, k)` of the power-law contact solutions;
//! - [`ode`]: adaptive integrators for small ODE systems with dense output and
//!   event location, explicit (Dormand-Prince 5(4), DOP853) and, in [`rosenbrock`] (also
//!   reachable as `ode::rosenbrock`), L-stable for stiff systems (Rodas5P by
//!   default, RODAS4 on request), all run by one loop ([`ode::drive`],
//!   [`ode::drive_events`]);
//! - [`search`]: the edge of a yes/no property of a positive argument, by bisection
//!   in its logarithm (where two models stop agreeing within a bound);
//! - [`chebyshev`]: Chebyshev interpolation (single, piecewise, and on equal pieces
//!   for hot loops) for precomputed fast tiers of expensive smooth functions;
//! - [`minimize`]: the global minimum of a function on an interval (grid, then
//!   golden-section search);
//! - [`Cost`]: evaluations and iterations that callers accumulate, so the library can
//!   show what accuracy costs;
//! - [`NumericsError`]: typed failures (no bracket, no convergence, non-finite value,
//!   invalid argument) instead of NaN or panics.
//!
//! Every routine takes a tolerance and returns the value with what it spent; every
//! default tolerance of the workspace comes from [`tolerance`] (one constant,
//! [`tolerance::DEFAULT_TOLERANCE`]).

pub mod chebyshev;
mod cost;
mod error;
pub mod minimize;
pub mod ode;
pub mod quadrature;
pub mod readable;
pub mod root_finding;
pub mod search;
pub mod special;
pub mod tolerance;

pub use ode::rosenbrock;

pub use cost::Cost;
pub use error::NumericsError;
pub use quadrature::{GaussLegendre, GaussLegendrePair, Integral, QuadTolerance};
pub use root_finding::{BracketExpansion, Root, RootTolerance};

/// Result type of this crate.
pub type Result<T> = std::result::Result<T, NumericsError>;

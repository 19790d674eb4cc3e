//! # tabor-visco
//!
//! The central impact of a rigid indenter on a linear viscoelastic half-space
//! without adhesion, seed 000 section 5.4 (eqs. (5.54)-(5.100)). Every model has a
//! dimensionless core (restitution as a function of its governing parameters);
//! [`models`] wraps the main ones as [`tabor_restitution::ImpactModel`]s in SI
//! units.
//!
//! | module | medium, indenter | parameters | method |
//! |---|---|---|---|
//! | [`kelvin_voigt_flat`] | Kelvin-Voigt, flat punch (5.54)-(5.63) | D | closed form, stable through D = 1 |
//! | [`kelvin_voigt_sphere`] | Kelvin-Voigt, sphere (5.64)-(5.71) | δ | Kuwabara-Kono and rigorous (MDR), first order (5.71), inverse δ(ε) |
//! | [`damping_law`] | generalized damping (5.72)-(5.73) | β, γ | Lee-Herrmann, Tsuji, Hunt-Crossley; overdamped limit |
//! | [`standard_flat`] | standard medium, flat punch (5.76)-(5.83) | β, δ | exact ODE; equivalent Kelvin-Voigt (5.83) |
//! | [`standard_sphere`] | standard medium, sphere (5.84)-(5.90) | β, δ | MDR with internal variables (5.88)-(5.89), continuum limit |
//! | [`kelvin_maxwell_sphere`] | Kelvin-Maxwell, sphere (5.91)-(5.92) | β, δ | MDR, continuum limit |
//! | [`compressible_flat`] | compressible Kelvin-Voigt, flat punch (5.93)-(5.100) | ν, D1, D2 | ODE |
//! | [`contact`] | two bodies, either or both Kelvin-Voigt, by the correspondence principle: elastic, standard medium (5.75)/(5.84), Kelvin-Voigt (5.64) | M, η of each body | classification; standard-medium sphere over the whole range (Kelvin-Voigt limit, MDR, weak-branch first order) |
//!
//! Integrations use `tabor_numerics::ode` (Dormand-Prince 5(4)) and, where internal
//! variables relax far faster than the motion (standard medium at small relaxation
//! times), `tabor_numerics::rosenbrock` (the L-stable Rodas5P); events are located
//! on the dense output. Heavily damped spheres (power-law dashpot, Kelvin-Voigt)
//! are integrated in a form whose end of contact is a state crossing zero (module
//! `hertz_damped`, README). Every impact ends where the normal force vanishes (seed
//! footnote 6). All inputs are validated; errors name the parameter and value;
//! restitution is always in [0, 1].
//!
//! [`ViscoModel`] is the menu the front ends name these models by (`ALL`,
//! `as_str`, `FromStr`).

pub mod compressible_flat;
pub mod contact;
pub mod damping_law;
mod hertz_damped;
pub mod kelvin_maxwell_sphere;
pub mod kelvin_voigt_flat;
pub mod kelvin_voigt_sphere;
pub mod kuwabara_kono;
mod mdr;
mod menu;
pub mod models;
mod scaled;
pub mod standard_flat;
pub mod standard_sphere;

pub use kelvin_voigt_sphere::SphereModel;
pub use menu::ViscoModel;
pub use scaled::{ScaledImpact, ScaledPoint};

//! # tabor
//!
//! Adhesive impact of elastic, plastic and viscoelastic spheres: how much energy a
//! central impact loses, the coefficient of restitution, the sticking velocity.
//!
//! This facade re-exports the workspace's library crates but `tabor-ffi` (the C ABI
//! of the LAMMPS plugin, built on the model crates directly; the `tabor` binary of
//! `tabor-cli` stands on this facade):
//!
//! - [`numerics`]: root finding, quadrature, ODE integrators, special functions,
//!   Chebyshev interpolation, cost accounting, the default tolerances;
//! - [`restitution`]: effective properties, the [`ImpactModel`](restitution::ImpactModel)
//!   trait, restitution and sticking velocity from an energy loss;
//! - [`elastic`]: non-adhesive elastic impact (Hertz, power-law, graded media);
//! - [`jkr`]: JKR adhesive impact (spheres, power-law profiles, graded media);
//! - [`maugis`]: Maugis-Dugdale adhesive impact across the Tabor-parameter range;
//! - [`dynamics`]: the time-domain simulator and its force-law interface;
//! - [`lammps`]: the DEM bridge to LAMMPS — a scene exported as a calibrated
//!   `pair_style granular` fragment (or for the `pair_style tabor` plugin), and
//!   `--check`, the restitution a LAMMPS line really produces;
//! - [`penalty`]: penalty contact laws for DEM codes (damped power laws, contact
//!   characteristics) calibrated against the impact models;
//! - [`plastic`]: elasto-plastic impact with and without adhesion;
//! - [`scene`]: scenes — describe a collision once, compute only the effects it
//!   calls for (the main entry point);
//! - [`tangential`]: friction, rolling and twisting as LAMMPS's `pair granular`
//!   defines them, and the oblique impact of two spheres;
//! - [`visco`]: viscoelastic impact (Kelvin-Voigt, standard, Kelvin-Maxwell media);
//! - [`viscoadhesive`]: adhesion (JKR or Maugis-Dugdale) with Kuwabara-Kono viscous
//!   damping.
//!
//! [`single`] holds the single-model computations shared by the command line
//! (`tabor jkr`, …) and the Python package: plain inputs named like the flags, one
//! result record per model.
//!
//! [`VERSION`] is the version of this package, which every workspace crate shares.

pub use tabor_dynamics as dynamics;
pub use tabor_elastic as elastic;
pub use tabor_jkr as jkr;
pub use tabor_lammps as lammps;
pub use tabor_maugis as maugis;
pub use tabor_numerics as numerics;
pub use tabor_penalty as penalty;
pub use tabor_plastic as plastic;
pub use tabor_restitution as restitution;
pub use tabor_scene as scene;
pub use tabor_tangential as tangential;
pub use tabor_visco as visco;
pub use tabor_viscoadhesive as viscoadhesive;

pub mod single;

/// The tabor version (every workspace crate has this version).
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The guide's Rust examples (`docs/guide/*.md`) as doc tests: `cargo test --doc -p
/// tabor` compiles and runs every ```rust block of them, so the guide cannot drift
/// from the library. Only collected for doc tests, never part of the API.
#[cfg(doctest)]
mod guide {
    #[doc = include_str!("../docs/guide/README.md")]
    struct Index;
    #[doc = include_str!("../docs/guide/researcher.md")]
    struct Researcher;
    #[doc = include_str!("../docs/guide/dem.md")]
    struct Dem;
    #[doc = include_str!("../docs/guide/cli.md")]
    struct Cli;
    #[doc = include_str!("../docs/guide/models.md")]
    struct Models;
    #[doc = include_str!("../docs/guide/validation.md")]
    struct Validation;
    #[doc = include_str!("../docs/guide/accuracy-and-speed.md")]
    struct AccuracyAndSpeed;
}

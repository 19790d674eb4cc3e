//! # tabor-scene
//!
//! The main entry point of tabor for users: describe a collision once — the bodies,
//! the interface, the requested accuracy — and get its restitution, whether the
//! bodies stick, the sticking velocity and the energy lost, computed by only the
//! effects the scene calls for, each with the reason it was used or skipped.
//!
//! - [`Scene`]: a validated scene, from TOML or JSON ([`Scene::from_path`],
//!   [`Scene::from_str`]) or built in code ([`SceneBuilder`]); file format in
//!   `examples/scenes/README.md`;
//! - [`Scene::outcome`], [`Scene::outcome_at`]: restitution (5.37), sticking,
//!   sticking velocity, total and per-effect losses, effects used and skipped,
//!   model, branch, accuracy, cost and warnings ([`Outcome`]);
//! - [`Scene::sticking_velocity`], [`Scene::simulate`] (time domain);
//! - [`Scene::oblique`]: the oblique impact (`[friction]`, `[impact] angle`),
//!   with translation and rotation (`tabor-tangential`);
//! - [`sweep`]: outcomes over a range of speeds or another parameter, in parallel.
//!
//! Effect selection (seed 000 chapter 5 and the issue that specified it):
//! adhesion is used when a work of adhesion is given and its loss is at least the
//! requested accuracy times the kinetic energy; the JKR closed form (fixed grip, the
//! Λ → ∞ limit of Maugis-Dugdale, whatever the scene's separation rule) is used when
//! the Maugis-Dugdale loss differs from it by less than the accuracy, the case-1 closed
//! form when Λ ≤ Λ1, the numerical Maugis-Dugdale solution otherwise. Plasticity is
//! used when a yield stress is given and the impact exceeds the yield onset
//! (adhesive or not); with adhesion it is the adhesive interpolation model
//! (superposition on request). Viscoelasticity is used when a viscosity is given
//! and its loss matters: the contact of both bodies by the correspondence
//! principle (a viscous body on an elastic one is a standard medium, two viscous
//! bodies with equal relaxation times a Kelvin-Voigt contact, different ones are
//! refused). With adhesion on a Kelvin-Voigt contact it is coupled to it in the
//! time domain (the viscous-adhesive rule, `tabor-viscoadhesive`); otherwise its
//! loss is added to the others' on the kinetic energy they leave (superposition,
//! with a warning). A DEM damping law (`[damping]`: LAMMPS `pair granular`'s
//! `viscoelastic`, `tsuji`, `coeff_restitution`, [`NormalDamping`]) damps the force
//! law of the other effects, simulated (the `dem-damping` rule; with adhesion the
//! Tsuji form uses the adhesive contact radius, `k_n = (4/3) E* a`). The one rule
//! per combination of effects: [`rule`] and the crate README.

mod builder;
mod combination;
mod error;
pub mod file;
mod floors;
mod friction;
mod inputs;
mod models;
mod oblique;
mod outcome;
mod parameter;
mod scene;
mod select;
mod simulate;
mod sweep;

pub use builder::{ElasticSphere, SceneBuilder};
pub use combination::{
    rule, AdhesionKind, Combination, EffectKind, EffectSet, PlasticityKind, Refusal, Rule,
    ViscoKind,
};
pub use error::{SceneError, SceneErrorKind};
pub use file::{DampingFile, Format, FrictionFile, ParseError, SceneFile, SdsFile, TwistingFile};
pub use inputs::{
    Adhesion, AdhesionRange, AdhesivePlasticity, Body, PlasticModel, DEFAULT_ACCURACY,
};
pub use outcome::{Effect, Outcome};
pub use parameter::SweepParameter;
pub use scene::{Scene, SpeedBatch, MAX_SCENE_BYTES};
pub use select::Sticking;
pub use sweep::{spaced, sweep, sweep_streamed, Spacing, MAX_SWEEP_POINTS};
pub use tabor_viscoadhesive::{DampingModel, NormalDamping};

//! # tabor-lammps
//!
//! The DEM bridge to LAMMPS (`pair_style granular`, `fix wall/gran granular`):
//!
//! - [`export()`]: a scene turned into a LAMMPS input fragment whose parameters are
//!   calibrated so that LAMMPS reproduces tabor's restitution — an effective
//!   surface energy for `jkr` (LAMMPS breaks contacts at the load-controlled
//!   point), a `damping viscoelastic` coefficient for viscoelastic and plastic
//!   losses — with the claims (which speeds, which error) and what is not
//!   reproduced ([`Export::fragment`]);
//! - [`export_plugin()`]: the fragment for `pair_style tabor` (the plugin of
//!   `integrations/lammps/plugin`, tabor's own force laws through `tabor-ffi`):
//!   `plugin load`, `pair_coeff * * maugis|jkr/…|hertz …`, the neighbor skin, and
//!   what it reproduces ([`PluginExport::fragment`]);
//! - [`check()`]: the restitution LAMMPS will really produce for a user's
//!   `pair_coeff` or `wall/gran` line (nominal versus achieved);
//! - [`GranularModel`]: LAMMPS's normal force and damping laws as a
//!   `tabor_dynamics::ForceLaw`, the predictor behind both.
//!
//! Derivations and sources: `crates/tabor-lammps/README.md`; the claims are
//! verified by running LAMMPS in `integrations/lammps`.

mod check;
mod export;
mod law;
mod parse;
mod plugin;

pub use check::{check, Check, CheckPoint};
pub use export::{
    effective_work_of_adhesion, export, load_controlled_loss, model_keywords, time_step_error,
    Bodies, Claim, Export, ExportError, Geometry, Parameter, Scope, SpeedComparison,
    LOSS_STEP_ERROR, REPRODUCES, TIME_STEP_ERROR, TIME_STEP_FRACTION,
};
pub use law::{
    coeff_restitution_alpha, jkr_pulloff_distance, tsuji_alpha, DampingModel, GranularModel,
    LammpsLaw, NormalModel,
};
pub use parse::{parse_line, LineError, LineKind, ParsedLine};
pub use plugin::{
    export_plugin, plugin_load_command, PluginExport, PluginModel, PluginSpeed,
    PLUGIN_RESTITUTION_ERROR, PLUGIN_TIME_STEP_FRACTION,
};

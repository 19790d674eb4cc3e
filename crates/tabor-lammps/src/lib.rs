//! # tabor-lammps
//!
//! The DEM bridge to LAMMPS (`pair_style granular`, `fix wall/gran granular`):
//!
//! - [`export()`]: a scene turned into a LAMMPS input fragment whose parameters are
//!   calibrated so that LAMMPS reproduces tabor's restitution — an effective
//!   surface energy for `jkr` (LAMMPS breaks contacts at the load-controlled
//!   point), a `damping viscoelastic` coefficient for viscoelastic and plastic
//!   losses — with the claim (over which speeds, within which error) and what is
//!   left out effect by effect ([`Export::fragment`]);
//! - [`export_plugin()`]: the fragment for `pair_style tabor` (the plugin of
//!   `integrations/lammps/plugin`, tabor's own force laws through `tabor-ffi`):
//!   `plugin load`, `pair_coeff * * maugis|jkr/…|hertz …`, the neighbor skin, and
//!   what it reproduces ([`PluginExport::fragment`]); for a flat target the wall
//!   fix `fix tabor_wall all wall/tabor … zplane 0.0 NULL` ([`export_plugin_wall()`]
//!   takes another wall);
//! - [`check()`]: the restitution LAMMPS will really produce for a user's
//!   `pair_coeff` or `wall/gran` line (nominal versus achieved);
//! - [`GranularModel`]: LAMMPS's normal force and damping laws as a
//!   `tabor_dynamics::ForceLaw`, and [`LammpsImpact`] the same between two given
//!   bodies as a `tabor_restitution::ImpactModel` (restitution, sticking velocity),
//!   the predictor behind all three.
//!
//! Layout: `report` (types), `calibrate`, `verify`, `fragment` (text), `export`
//! (the pipeline); `law`, `impact`; `parse`, `check`; `plugin`.
//! Derivations and sources: `crates/tabor-lammps/README.md`; the claims are
//! verified by running LAMMPS in `integrations/lammps`.
//!
//! - [`check_plugin()`]: `--check` of a `pair_style tabor` line (`maugis … range h`
//!   too): the restitution the plugin's own law gives the scene's bodies.

mod calibrate;
mod check;
mod export;
mod fragment;
mod friction;
mod impact;
mod law;
mod parse;
mod plugin;
mod plugin_check;
mod report;
mod verify;
mod wall;

pub use calibrate::{effective_work_of_adhesion, load_controlled_loss, small_strain_speed};
pub use check::{check, Check, CheckPoint};
pub use export::export;
pub use fragment::model_keywords;
pub use friction::FRICTIONLESS;
pub use impact::{LammpsImpact, STICKING_TOLERANCE};
pub use law::{
    coeff_restitution_alpha, jkr_pulloff_distance, tsuji_alpha, DampingModel, GranularModel,
    LammpsLaw, NormalModel,
};
pub use parse::{parse_line, substitute_variables, LineError, LineKind, ParsedLine};
pub use plugin::{
    export_plugin, export_plugin_wall, export_plugin_with, plugin_load_command, PluginExport,
    PluginModel, PluginOptions, PluginSpeed, DEFAULT_WALL, PLUGIN_RESTITUTION_ERROR,
    PLUGIN_TIME_STEP_FRACTION,
};
pub use plugin_check::{check_plugin, is_plugin_line, PluginCheck, PluginCheckPoint};
pub use report::{
    time_step_error, Bodies, Claim, Export, ExportError, Geometry, Limit, Parameter, RangeEnd,
    Scope, SpeedComparison, CALIBRATED_RELATIVE_ERROR, LOSS_STEP_ERROR, REPRODUCES,
    SMALL_STRAIN_OVERLAP, TIME_STEP_ERROR, TIME_STEP_FRACTION,
};

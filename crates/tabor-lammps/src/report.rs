//! What an export reports: the error type, the constants of its claims, and the
//! value types of an [`Export`] (parameters, claim, limits, comparison).

use crate::law::GranularModel;
use serde::Serialize;
use std::fmt;
use tabor_numerics::NumericsError;

/// The time step, as a fraction of the contact time, at which the claims of an
/// export are verified by running LAMMPS (`integrations/lammps`).
pub const TIME_STEP_FRACTION: f64 = 1.0 / 5000.0;

/// The error LAMMPS's velocity-Verlet integration adds to the restitution at a time
/// step of [`TIME_STEP_FRACTION`] of the contact time (measured in
/// `integrations/lammps`: at most a few 1e-4 away from the sticking velocity).
pub const TIME_STEP_ERROR: f64 = 1e-3;

/// The relative error of the adhesive (`jkr`) loss per impact that LAMMPS's time
/// stepping adds at a time step of [`TIME_STEP_FRACTION`] of the contact time
/// (measured 1.0e-3 for pairs, 1.3e-3 for walls in `integrations/lammps`; it
/// falls as the time step). Through e² = 1 − 2W/(m v²) it becomes an error of
/// e of (1 − e²)/(2e) times this, which grows without bound at the sticking
/// velocity.
pub const LOSS_STEP_ERROR: f64 = 2e-3;

/// The error of a LAMMPS restitution `e` (> 0) at a time step of
/// [`TIME_STEP_FRACTION`] of the contact time: [`TIME_STEP_ERROR`], or for an
/// adhesive contact the larger [`LOSS_STEP_ERROR`] (1 − e²)/(2e) near the sticking
/// velocity (infinite at e = 0, where sticking or not is decided by the step).
pub fn time_step_error(restitution: f64, adhesive: bool) -> f64 {
    if !adhesive {
        return TIME_STEP_ERROR;
    }
    if restitution <= 0.0 {
        return f64::INFINITY;
    }
    let e = restitution.min(1.0);
    TIME_STEP_ERROR.max(LOSS_STEP_ERROR * (1.0 - e * e) / (2.0 * e))
}

/// The calibration error up to which an export with a speed-independent loss claims
/// to reproduce tabor's restitution (small against [`TIME_STEP_ERROR`]).
pub const REPRODUCES: f64 = 1e-4;

/// The relative error (of tabor's restitution) up to which an export calibrated at
/// one speed claims to hold around it.
pub const CALIBRATED_RELATIVE_ERROR: f64 = 0.01;

/// The largest elastic overlap, as a fraction of the effective radius, at which the
/// export compares LAMMPS with tabor: the small-strain limit d_max ≤ R of tabor's
/// models (`tabor-viscoadhesive` refuses speeds beyond it), with d_max the Hertz
/// overlap of seed 000 (5.8).
pub const SMALL_STRAIN_OVERLAP: f64 = 1.0;

/// Why a scene cannot be exported.
#[derive(Clone, Debug, PartialEq)]
pub enum ExportError {
    /// An effect of the scene that LAMMPS's granular models cannot represent, or a
    /// calibration that cannot be made (for example a speed at which the bodies
    /// stick).
    Unrepresentable {
        /// The effect (for example "graded medium").
        effect: String,
        /// Why (one line).
        reason: String,
    },
    /// The scene or a model computation failed.
    Model(String),
}

impl fmt::Display for ExportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExportError::Unrepresentable { effect, reason } => {
                write!(f, "LAMMPS cannot represent {effect}: {reason}")
            }
            ExportError::Model(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for ExportError {}

impl From<NumericsError> for ExportError {
    fn from(e: NumericsError) -> Self {
        ExportError::Model(e.to_string())
    }
}

pub(crate) fn model_err(e: impl fmt::Display) -> ExportError {
    ExportError::Model(e.to_string())
}

pub(crate) fn unrepresentable(effect: &str, reason: String) -> ExportError {
    ExportError::Unrepresentable {
        effect: effect.into(),
        reason,
    }
}

/// Sphere–sphere (`pair_coeff`) or sphere–wall (`fix wall/gran`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Geometry {
    /// Two spheres: `pair_style granular` + `pair_coeff * *`.
    Pair,
    /// A sphere on a flat target: `fix … wall/gran granular … zplane`.
    Wall,
}

/// One calibrated or derived number of an export.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Parameter {
    /// Its name in the LAMMPS line (or a derived quantity).
    pub name: String,
    /// Value (SI).
    pub value: f64,
    /// Unit.
    pub unit: String,
    /// How it was obtained (one line).
    pub derivation: String,
}

/// How an export matches tabor's restitution over speeds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scope {
    /// The loss LAMMPS carries does not depend on the speed (elastic adhesion):
    /// e(v) and the sticking velocity agree to [`REPRODUCES`] over the claimed
    /// range.
    SpeedIndependent,
    /// A speed-dependent loss calibrated at one speed: within
    /// [`CALIBRATED_RELATIVE_ERROR`] of tabor over the claimed range.
    CalibrationSpeed,
}

/// Why a claimed speed range ends where it does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RangeEnd {
    /// The comparison grid ends there (two decades from the reference speed).
    Grid,
    /// Small strain: beyond it tabor's models do not apply
    /// ([`SMALL_STRAIN_OVERLAP`]).
    SmallStrain,
    /// An effect LAMMPS leaves out sets in there (see [`Limit::from_speed`]).
    EffectOnset,
    /// LAMMPS's restitution leaves the error bound there.
    ErrorBound,
    /// tabor's scene gives no outcome at the next grid speed (the error is in
    /// [`Export::does_not_reproduce`]).
    NoAnswer,
}

/// What an export claims: the speeds over which LAMMPS's restitution stays within
/// a stated error of tabor's.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Claim {
    /// Speed-independent or calibrated at one speed.
    pub scope: Scope,
    /// The reference (calibration) speed (m/s).
    pub speed: f64,
    /// The speeds (m/s) over which the claim holds: a contiguous range around the
    /// reference speed, inside small strain and below the onset of any effect the
    /// export leaves out.
    pub range: [f64; 2],
    /// Why the range ends at each side.
    pub range_ends: [RangeEnd; 2],
    /// The bound the range is drawn with: [`REPRODUCES`], or
    /// [`CALIBRATED_RELATIVE_ERROR`] of tabor's restitution.
    pub bound: f64,
    /// The largest |e_LAMMPS − e_tabor| of the LAMMPS force law (no time step)
    /// found over the range: the stated error, to which a LAMMPS run adds
    /// [`time_step_error`].
    pub error: f64,
    /// Largest |e_LAMMPS − e_tabor| over a decade of speeds around the reference
    /// (v/√10 … v√10, inside small strain), whether claimed or not.
    pub decade_error: f64,
    /// The sentence the fragment prints.
    pub statement: String,
}

/// One effect (or property) of the scene that the LAMMPS model leaves out.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Limit {
    /// The effect: "plasticity", "viscoelasticity", "adhesion range", "pull-off
    /// force", "friction", "materials".
    pub effect: String,
    /// The speed (m/s) above which tabor's scene uses the effect and LAMMPS leaves
    /// it out (plasticity: its onset), when that is what limits it.
    pub from_speed: Option<f64>,
    /// What is left out (one line).
    pub note: String,
}

/// tabor's and the LAMMPS model's restitution at one speed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SpeedComparison {
    /// Impact speed (m/s).
    pub speed: f64,
    /// tabor's restitution (`Scene::restitution_with_error`; 0 when the bodies
    /// stick).
    pub tabor: f64,
    /// The restitution of the exported LAMMPS model, integrated in the time domain
    /// without time-step error ([`GranularModel::impact`]).
    pub lammps: f64,
    /// lammps − tabor.
    pub difference: f64,
    /// The error the export states for a LAMMPS run at this speed with a time step
    /// of at most [`TIME_STEP_FRACTION`] of the contact time:
    /// |difference| + [`time_step_error`] (infinite where LAMMPS's model sticks
    /// only marginally: at e = 0 both stick, up to the step's resolution of v_c).
    pub tolerance: f64,
    /// Whether this speed lies in the claimed range.
    pub claimed: bool,
}

/// The masses and radii LAMMPS needs for the bodies (`set atom … diameter … density`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bodies {
    /// Sphere radius (m).
    pub sphere_radius: f64,
    /// Sphere density (kg/m³).
    pub sphere_density: f64,
    /// Target radius (m), `None` for a wall.
    pub target_radius: Option<f64>,
    /// Target density (kg/m³), `None` for a wall.
    pub target_density: Option<f64>,
}

/// A scene exported to LAMMPS.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Export {
    /// The scene's name.
    pub scene: String,
    /// Pair or wall.
    pub geometry: Geometry,
    /// The LAMMPS normal contact.
    pub model: GranularModel,
    /// The model keywords (after `pair_coeff * *` or `wall/gran granular`).
    pub model_keywords: String,
    /// The tangential, rolling and twisting keywords from the scene's `[friction]`
    /// (part of `model_keywords`), `None` without friction.
    pub friction: Option<String>,
    /// The LAMMPS commands of the fragment.
    pub commands: Vec<String>,
    /// Every calibrated number and how it was obtained.
    pub parameters: Vec<Parameter>,
    /// What LAMMPS reproduces, over which speeds, within which error.
    pub reproduces: Claim,
    /// What it leaves out, effect by effect.
    pub does_not_reproduce: Vec<Limit>,
    /// The bodies.
    pub bodies: Bodies,
    /// Effective modulus E* (Pa) of the exported contact.
    pub effective_modulus: f64,
    /// Effective radius (m).
    pub effective_radius: f64,
    /// Reduced mass (kg).
    pub effective_mass: f64,
    /// The highest speed (m/s) inside small strain (Hertz d_max = R), where the
    /// comparison stops.
    pub small_strain_speed: f64,
    /// tabor's sticking velocity (m/s), when the bodies can stick.
    pub sticking_velocity: Option<f64>,
    /// The LAMMPS model's sticking velocity (m/s), when it can stick.
    pub lammps_sticking_velocity: Option<f64>,
    /// Contact time of the LAMMPS model at the reference speed (s).
    pub contact_time: f64,
    /// The time step at which the claims are verified, `TIME_STEP_FRACTION` × contact time (s).
    pub time_step: f64,
    /// tabor versus the LAMMPS model over speeds around the reference.
    pub comparison: Vec<SpeedComparison>,
}

//! A validated scene: the scene data, its validated inputs and speed, and every
//! question a scene answers (the one `impl Scene`).

use crate::combination::Combination;
use crate::error::{impact_speed, in_field, located, SceneError, Source};
use crate::file::{parse, AdhesionFile, Format, ImpactFile, SceneFile};
use crate::inputs::{Adhesion, AdhesivePlasticity, Body, Inputs, PlasticModel};
use crate::outcome::Outcome;
use crate::parameter::SweepParameter;
use crate::select::{Cache, Prepared, Sticking};
use rayon::prelude::*;
use std::path::Path;
use tabor_dynamics::{ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_restitution::validate;
use tabor_viscoadhesive::NormalDamping;

/// A validated scene. Its fields are read-only views of the validated inputs: a
/// scene with other inputs is made by [`Scene::with_parameter`],
/// [`Scene::with_speed`] or [`Scene::from_data`] (a scene whose fields were changed
/// in place still answers for its fields, building its models anew).
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub(crate) data: SceneFile,
    /// The text the scene was read from, to locate errors found later.
    source: Option<Source>,
    /// Its models, built on first use (shared with its copies at other speeds).
    cache: Cache,
    /// The scene's name (file stem or `name`).
    pub name: String,
    /// The impacting sphere.
    pub sphere: Body,
    /// The target.
    pub target: Body,
    /// Adhesion, when given.
    pub adhesion: Option<Adhesion>,
    /// The plasticity model: one of [`PlasticModel::NON_ADHESIVE`], or `None`
    /// (`auto`: the interpolation model (5.107)).
    pub plasticity: Option<PlasticModel>,
    /// How adhesion and plasticity combine.
    pub adhesive_plasticity: AdhesivePlasticity,
    /// The impact speed, when given (m/s).
    pub speed: Option<f64>,
    /// The requested relative accuracy.
    pub accuracy: f64,
    /// Effective modulus E* (Pa).
    pub effective_modulus: f64,
    /// Effective radius R (m).
    pub effective_radius: f64,
    /// Effective (reduced) mass m (kg).
    pub effective_mass: f64,
    /// The DEM normal damping law of `[damping]`, when given (LAMMPS
    /// `pair granular` `damping`; `tabor_viscoadhesive::NormalDamping`).
    pub damping: Option<NormalDamping>,
}

impl Scene {
    /// Validates scene data (from a file or the [`SceneBuilder`](crate::SceneBuilder)).
    pub fn from_data(data: SceneFile) -> Result<Scene, SceneError> {
        let inputs = Inputs::validate(&data)?;
        crate::friction::validate_data(&data)?;
        let speed = match data.impact.as_ref().and_then(|i| i.speed) {
            None => None,
            Some(v) => Some(validate::positive("speed", v).map_err(in_field("impact", "speed"))?),
        };
        let name = data.name.clone().unwrap_or_else(|| "scene".into());
        Ok(Scene {
            data,
            source: None,
            cache: Cache::default(),
            name,
            sphere: inputs.sphere,
            target: inputs.target,
            adhesion: inputs.adhesion,
            plasticity: inputs.plasticity,
            adhesive_plasticity: inputs.adhesive_plasticity,
            speed,
            accuracy: inputs.accuracy,
            effective_modulus: inputs.effective_modulus,
            effective_radius: inputs.effective_radius,
            effective_mass: inputs.effective_mass,
            damping: inputs.damping,
        })
    }

    /// Parses and validates a scene text. Validation errors are located in the text
    /// (line of the offending key) where possible.
    pub fn from_str(text: &str, format: Format) -> Result<Scene, SceneError> {
        let data = parse(text, format)?;
        let source = Source::new((text.to_string(), format));
        let mut scene = Scene::from_data(data).map_err(|e| located(Some(&source), e))?;
        scene.source = Some(source);
        Ok(scene)
    }

    /// `e` with the line of its field in the scene text, when the scene was read
    /// from a text and the error has a field but no line yet.
    fn locate(&self, e: SceneError) -> SceneError {
        located(self.source.as_ref(), e)
    }

    /// Reads and validates a scene file (`.json` is JSON, anything else TOML);
    /// the path `-` reads standard input (JSON when it starts with `{`, else
    /// TOML). A file larger than [`MAX_SCENE_BYTES`] is refused before it is read
    /// whole.
    pub fn from_path(path: &Path) -> Result<Scene, SceneError> {
        let stdin = path.as_os_str() == "-";
        let text = if stdin {
            bounded_read(std::io::stdin().lock(), "standard input")?
        } else {
            let file = std::fs::File::open(path)
                .map_err(|e| SceneError::input(format!("cannot read {}: {e}", path.display())))?;
            bounded_read(file, &path.display().to_string())?
        };
        let format = if stdin {
            if text.trim_start().starts_with('{') {
                Format::Json
            } else {
                Format::Toml
            }
        } else {
            Format::of_path(path)
        };
        let mut scene = Scene::from_str(&text, format)?;
        if scene.data.name.is_none() && !stdin {
            if let Some(stem) = path.file_stem().and_then(|s| s.to_str()) {
                scene.name = stem.to_string();
            }
        }
        Ok(scene)
    }

    /// The scene data as written (for re-serialization or edits).
    pub fn data(&self) -> &SceneFile {
        &self.data
    }

    /// The same scene at another impact speed.
    pub fn with_speed(&self, speed: f64) -> Result<Scene, SceneError> {
        let mut data = self.data.clone();
        data.impact.get_or_insert_with(ImpactFile::default).speed = Some(speed);
        let mut s = Scene::from_data(data).map_err(|e| self.locate(e))?;
        s.name = self.name.clone();
        s.source = self.source.clone();
        // the models do not depend on the speed
        s.cache = self.cache.clone();
        Ok(s)
    }

    /// The Tabor parameter Λ, when the interface has a range.
    pub fn tabor_parameter(&self) -> Option<f64> {
        self.inputs().tabor_parameter()
    }

    /// The yield stress of the softer plastic body (the smaller one given).
    pub fn yield_stress(&self) -> Option<f64> {
        self.inputs().yield_stress()
    }

    /// The field of the yield stress that [`Scene::yield_stress`] uses.
    pub fn yield_stress_field(&self) -> &'static str {
        self.inputs().yield_stress_field()
    }

    /// The Poisson's ratio of the plastic body (the target if it has a yield
    /// stress, else the sphere).
    pub fn plastic_poisson_ratio(&self) -> f64 {
        self.inputs().plastic_poisson_ratio()
    }

    /// The slowest elastic wave speed √(E/ρ) of the bodies whose density is known,
    /// as (E, ρ).
    pub fn wave_speed_body(&self) -> Option<(f64, f64)> {
        self.inputs().wave_speed_body()
    }

    /// Whether the scene has `parameter` to vary: an error names the parameter and
    /// the section that would give it (a sweep never adds an effect the scene does
    /// not call for). The work of adhesion and the Tabor parameter need an
    /// `[adhesion]` section, the yield stress a `yield_stress` on a body.
    pub fn check_parameter(&self, parameter: SweepParameter) -> Result<(), SceneError> {
        let missing =
            |field: &str, message: String| Err(self.locate(SceneError::field(field, message)));
        match parameter {
            SweepParameter::Speed | SweepParameter::SphereRadius => Ok(()),
            SweepParameter::WorkOfAdhesion | SweepParameter::TaborParameter
                if self.data.adhesion.is_none() =>
            {
                missing(
                    "adhesion",
                    format!(
                        "the scene has no {}: add an [adhesion] section (work_of_adhesion, and a range or tabor_parameter) to sweep it",
                        parameter.name()
                    ),
                )
            }
            SweepParameter::YieldStress
                if self.data.sphere.yield_stress.is_none()
                    && self.data.target.yield_stress.is_none() =>
            {
                missing(
                    "target.yield_stress",
                    "the scene has no yield-stress: give the target (or the sphere) a yield_stress (Pa) to sweep it".into(),
                )
            }
            _ => Ok(()),
        }
    }

    /// The same scene with `parameter` set to `value`, validated again; an error
    /// when the scene lacks the parameter ([`Scene::check_parameter`]). The yield
    /// stress set is the target's when it has one, else the sphere's.
    pub fn with_parameter(
        &self,
        parameter: SweepParameter,
        value: f64,
    ) -> Result<Scene, SceneError> {
        self.check_parameter(parameter)?;
        let mut data = self.data.clone();
        match parameter {
            SweepParameter::Speed => return self.with_speed(value),
            SweepParameter::SphereRadius => data.sphere.radius = Some(value),
            SweepParameter::WorkOfAdhesion => {
                data.adhesion
                    .get_or_insert_with(AdhesionFile::default)
                    .work_of_adhesion = value
            }
            SweepParameter::TaborParameter => {
                let a = data.adhesion.get_or_insert_with(AdhesionFile::default);
                a.range = None;
                a.cohesive_stress = None;
                a.maugis_parameter = None;
                a.tabor_mu = None;
                a.tabor_parameter = Some(value);
            }
            SweepParameter::YieldStress => {
                if data.target.yield_stress.is_some() {
                    data.target.yield_stress = Some(value)
                } else {
                    data.sphere.yield_stress = Some(value)
                }
            }
            SweepParameter::Angle => {
                data.impact.get_or_insert_with(ImpactFile::default).angle = Some(value)
            }
        }
        let mut s = Scene::from_data(data).map_err(|e| self.locate(e))?;
        s.name = self.name.clone();
        Ok(s)
    }

    /// The validated inputs, as the fields say.
    fn inputs(&self) -> Inputs {
        Inputs {
            sphere: self.sphere.clone(),
            target: self.target.clone(),
            adhesion: self.adhesion.clone(),
            plasticity: self.plasticity,
            adhesive_plasticity: self.adhesive_plasticity,
            accuracy: self.accuracy,
            effective_modulus: self.effective_modulus,
            effective_radius: self.effective_radius,
            effective_mass: self.effective_mass,
            damping: self.damping,
        }
    }

    /// The scene with its models (built on first use, then shared).
    pub(crate) fn prepared(&self) -> Result<Prepared<'_>, SceneError> {
        Prepared::new(&self.name, self.source.as_ref(), &self.cache, self.inputs())
    }

    /// The outcome at the scene's impact speed (an error names `impact.speed` when
    /// the scene has none).
    pub fn outcome(&self) -> Result<Outcome, SceneError> {
        let v = self
            .speed
            .ok_or_else(|| SceneError::field("impact.speed", "is required for an impact (m/s)"))?;
        self.prepared()?.outcome_at(v)
    }

    /// The outcome at impact speed `speed` (m/s).
    pub fn outcome_at(&self, speed: f64) -> Result<Outcome, SceneError> {
        let v = impact_speed(speed)?;
        self.prepared()?.outcome_at(v)
    }

    /// The coefficient of restitution at `speed` (m/s) with the estimated error of
    /// the loss as a fraction of the kinetic energy (the error of 1 − ε²), without
    /// the outcome's sticking velocity and reports.
    pub fn restitution_with_error(&self, speed: f64) -> Result<(f64, f64), SceneError> {
        let v = impact_speed(speed)?;
        self.prepared()?.restitution_with_error(v)
    }

    /// The combination (rule and effects used) that answers at impact speed `speed`
    /// (m/s), without computing the outcome's sticking velocity.
    pub fn combination_at(&self, speed: f64) -> Result<Combination, SceneError> {
        let v = impact_speed(speed)?;
        Ok(self.prepared()?.select(v)?.combination())
    }

    /// The sticking velocity (m/s) of the scene's model (the root of ε(v) = 0 of the
    /// model that answers at each speed), or `None` when the bodies never stick or
    /// stick at every speed the model is valid for ([`Scene::sticking`] tells which).
    pub fn sticking_velocity(&self) -> Result<Option<f64>, SceneError> {
        Ok(self.sticking()?.velocity())
    }

    /// Where the bodies stick, as far as the scene's model is valid: below a
    /// sticking velocity, never, or at every speed up to the model's validity
    /// limit (the small-strain limit of the simulated viscous-adhesive model).
    pub fn sticking(&self) -> Result<Sticking, SceneError> {
        Ok(self.prepared()?.sticking()?.0)
    }

    /// Simulates the impact at `speed` in the time domain with the force law of the
    /// model the scene selects at that speed, and returns the simulation with the
    /// analytic outcome of the same model.
    pub fn simulate(
        &self,
        speed: f64,
        settings: &SimulationSettings,
    ) -> Result<(ImpactSimulation, Outcome), SceneError> {
        let v = impact_speed(speed)?;
        self.prepared()?.simulate(v, settings)
    }

    /// The force law F(d) of the rule that answers at `speed` (m/s), the one the
    /// time-domain simulation integrates there, begun for that impact (its first
    /// branch: loading, or the approach), so that `force(d, ḋ)` gives F (N,
    /// repulsive > 0) at overlap d (m). An error names why a rule has no force law
    /// of its own (a loss-level combination, a model solved without one): never a
    /// substitute. For front ends that evaluate the law itself (Python's
    /// `Scene.force`).
    pub fn force_law(&self, speed: f64) -> Result<Box<dyn ForceLaw>, SceneError> {
        let v = impact_speed(speed)?;
        let prepared = self.prepared()?;
        let mut law = prepared.force_law(&prepared.outcome_at(v)?)?;
        law.begin_impact(self.effective_mass, v)
            .map_err(SceneError::model)?;
        Ok(law)
    }

    /// The scene prepared for many impact speeds within the range of `speeds` (m/s;
    /// only their count and the range of the finite, positive ones count): its
    /// models and sticking velocity built once and, for at least 500 speeds of a
    /// coupled viscous-adhesive scene, a speed table of that model certified
    /// against its simulation (`tabor_viscoadhesive::table`) over the range.
    /// What [`crate::sweep`] over speeds uses; front ends that evaluate in chunks
    /// (Python) prepare the whole array once with it.
    pub fn speed_batch(&self, speeds: &[f64]) -> Result<SpeedBatch<'_>, SceneError> {
        let valid = speeds.iter().copied().filter(|v| v.is_finite() && *v > 0.0);
        let upper = valid.clone().fold(0.0, f64::max);
        let lower = valid.fold(f64::INFINITY, f64::min);
        self.speed_batch_over(lower, upper, speeds.len())
    }

    /// [`Scene::speed_batch`] for `count` speeds from `lower` to `upper` (m/s).
    pub fn speed_batch_over(
        &self,
        lower: f64,
        upper: f64,
        count: usize,
    ) -> Result<SpeedBatch<'_>, SceneError> {
        Ok(SpeedBatch {
            prepared: self.prepared()?.with_speed_table(lower, upper, count),
        })
    }

    /// The coefficient of restitution (5.37) at each of `speeds` (m/s), computed in
    /// parallel on rayon's pool, by the same model and combination rule as
    /// [`Scene::outcome_at`] at that speed (the models are built once). The first
    /// invalid speed or failing point is returned with its index.
    ///
    /// When the scene's loss does not depend on the speed (elastic adhesion alone),
    /// the loss is computed once and each point is the closed form (5.37) with the
    /// same negligible-effect rule as the outcome (bit-identical to it).
    pub fn restitutions(&self, speeds: &[f64]) -> Result<Vec<f64>, (usize, SceneError)> {
        let prepared = self.prepared().map_err(|e| (0, e))?;
        restitutions(&prepared, speeds)
    }
}

/// A scene prepared for many impact speeds ([`Scene::speed_batch`]).
pub struct SpeedBatch<'a> {
    prepared: Prepared<'a>,
}

impl SpeedBatch<'_> {
    /// The outcome at impact speed `speed` (m/s), as [`Scene::outcome_at`] (from
    /// the speed table where the batch has one, within its certified error).
    pub fn outcome_at(&self, speed: f64) -> Result<Outcome, SceneError> {
        let v = impact_speed(speed)?;
        self.prepared.outcome_at(v)
    }

    /// The restitution at each of `speeds` (m/s), as [`Scene::restitutions`] (from
    /// the speed table where the batch has one, within its certified error).
    pub fn restitutions(&self, speeds: &[f64]) -> Result<Vec<f64>, (usize, SceneError)> {
        restitutions(&self.prepared, speeds)
    }
}

/// [`Scene::restitutions`] on a prepared scene.
fn restitutions(prepared: &Prepared<'_>, speeds: &[f64]) -> Result<Vec<f64>, (usize, SceneError)> {
    match prepared.constant_loss().map_err(|e| (0, e))? {
        Some(loss) => speeds
            .par_iter()
            .enumerate()
            .map(|(i, &v)| {
                impact_speed(v)
                    .and_then(|v| prepared.restitution_with_constant_loss(loss, v))
                    .map_err(|e| (i, e))
            })
            .collect(),
        None => speeds
            .par_iter()
            .enumerate()
            .map(|(i, &v)| {
                impact_speed(v)
                    .and_then(|v| prepared.restitution_with_error(v))
                    .map(|(e, _)| e)
                    .map_err(|e| (i, e))
            })
            .collect(),
    }
}

/// The largest scene file read (1 MiB; the bundled scenes are below 2 kB): a
/// larger file, or a device that never ends (`/dev/zero`), is refused after
/// reading one byte more than this.
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// Reads at most [`MAX_SCENE_BYTES`] of UTF-8 text from `reader` (`what` names it
/// in errors).
fn bounded_read(reader: impl std::io::Read, what: &str) -> Result<String, SceneError> {
    use std::io::Read;
    let mut bytes = Vec::new();
    reader
        .take(MAX_SCENE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| SceneError::input(format!("cannot read {what}: {e}")))?;
    if bytes.len() as u64 > MAX_SCENE_BYTES {
        return Err(SceneError::input(format!(
            "the scene is larger than {MAX_SCENE_BYTES} bytes (1 MiB), the ceiling of a scene file"
        )));
    }
    String::from_utf8(bytes)
        .map_err(|e| SceneError::input(format!("cannot read {what}: not UTF-8 text ({e})")))
}

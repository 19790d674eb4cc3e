//! A validated scene: bodies, interface, requested accuracy, and the effective
//! quantities every model needs.

use crate::file::{
    locate, locate_section, parse, AdhesionFile, BodyFile, Format, GradationFile, ImpactFile,
    ParseError, PlasticityFile, SceneFile,
};
use serde::Serialize;
use std::fmt;
use std::path::Path;
use tabor_jkr::SeparationRule;
use tabor_maugis::units::{
    tabor_parameter_from_cohesive_stress, tabor_parameter_from_maugis, tabor_parameter_from_range,
    tabor_parameter_from_tabor_mu,
};
use tabor_restitution::effective::{
    effective_modulus, effective_radius, reduced_mass, sphere_mass,
};
use tabor_restitution::{validate, ElasticMaterial, Error};

/// Why a scene is not valid: the field, its value, the rule, and where in the file.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    /// 1-based line in the scene file, when known.
    pub line: Option<usize>,
    /// 1-based column, when known.
    pub column: Option<usize>,
    /// The field path (`sphere.radius`), when the error concerns one field.
    pub field: Option<String>,
    /// What is wrong (one line).
    pub message: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let e = ParseError {
            line: self.line,
            column: self.column,
            field: self.field.clone(),
            message: self.message.clone(),
        };
        write!(f, "{e}")
    }
}

impl std::error::Error for SceneError {}

impl From<ParseError> for SceneError {
    fn from(e: ParseError) -> Self {
        SceneError {
            line: e.line,
            column: e.column,
            field: e.field,
            message: e.message,
        }
    }
}

impl SceneError {
    /// An error about field `field`.
    pub fn field(field: impl Into<String>, message: impl Into<String>) -> Self {
        SceneError {
            line: None,
            column: None,
            field: Some(field.into()),
            message: message.into(),
        }
    }

    /// An error of a model computation (no field).
    pub fn model(e: Error) -> Self {
        SceneError {
            line: None,
            column: None,
            field: None,
            message: e.to_string(),
        }
    }
}

/// Prefixes a parameter error with its field path (`sphere.` + parameter).
fn in_field<'a>(section: &'a str, key: &'static str) -> impl Fn(Error) -> SceneError + 'a {
    move |e| {
        let message = match &e {
            Error::InvalidParameter {
                value, requirement, ..
            } => format!("= {value:e}: {requirement}"),
            other => other.to_string(),
        };
        SceneError::field(format!("{section}.{key}"), message)
    }
}

/// A body of the scene, validated.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Body {
    /// Radius (m); `None` for a flat half-space target.
    pub radius: Option<f64>,
    /// Mass (kg); `None` for an immovable half-space target.
    pub mass: Option<f64>,
    /// Density (kg/m³), when given or derivable from mass and radius.
    pub density: Option<f64>,
    /// Elastic constants.
    pub material: ElasticMaterial,
    /// Yield stress (Pa), when plastic.
    pub yield_stress: Option<f64>,
    /// Shear viscosity (Pa·s), when viscoelastic.
    pub viscosity: Option<f64>,
    /// Gradation `(k, c_N)`, when graded.
    pub gradation: Option<(f64, f64)>,
}

/// How the adhesive stress is specified.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind", content = "value")]
pub enum AdhesionRange {
    /// No range given: the JKR limit.
    Jkr,
    /// The seed's Tabor parameter Λ (derived or given).
    TaborParameter(f64),
}

/// The adhesive interface, validated.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Adhesion {
    /// Work of adhesion Δγ (J/m²), ≥ 0.
    pub work_of_adhesion: f64,
    /// The Tabor parameter, when a range, cohesive stress, Λ, λ or μ was given.
    pub range: AdhesionRange,
    /// The JKR separation rule.
    pub separation: SeparationRule,
}

/// The non-adhesive plasticity model a scene asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PlasticityModel {
    /// The interpolation model (5.107) (the most complete: beyond the fully plastic
    /// onset too).
    Auto,
    /// Thornton (5.104)-(5.106).
    Thornton,
    /// The interpolation model (5.107).
    Interpolation,
    /// The Jackson-Green type law (5.108), solved in the time domain.
    JacksonGreen,
    /// Seed 001's dimensionless fit.
    DimensionlessFit,
}

/// How adhesion and plasticity combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum AdhesivePlasticity {
    /// The adhesive interpolation model (5.111)-(5.125).
    Interpolation,
    /// Superposition of the plastic and the JKR losses (5.109)-(5.110).
    Superposition,
}

/// A validated scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub(crate) data: SceneFile,
    /// The text the scene was read from, to locate errors found later.
    source: Option<std::sync::Arc<(String, Format)>>,
    /// The scene's name (file stem or `name`).
    pub name: String,
    /// The impacting sphere.
    pub sphere: Body,
    /// The target.
    pub target: Body,
    /// Adhesion, when given.
    pub adhesion: Option<Adhesion>,
    /// The plasticity model.
    pub plasticity: PlasticityModel,
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
}

/// The default requested relative accuracy (1e-10, from
/// `tabor_numerics::tolerance`).
pub const DEFAULT_ACCURACY: f64 = tabor_numerics::tolerance::ACCURACY;

fn body(section: &str, b: &BodyFile, is_target: bool) -> Result<Body, SceneError> {
    let material =
        ElasticMaterial::new(b.youngs_modulus, b.poisson_ratio).map_err(|e| match e {
            Error::InvalidParameter { parameter, .. } => in_field(section, parameter)(e),
            other => SceneError::model(other),
        })?;
    let radius = match b.radius {
        Some(r) => Some(validate::positive("radius", r).map_err(in_field(section, "radius"))?),
        None if is_target => None,
        None => {
            return Err(SceneError::field(
                format!("{section}.radius"),
                "is required (m)",
            ))
        }
    };
    if b.mass.is_some() && b.density.is_some() {
        return Err(SceneError::field(
            format!("{section}.mass"),
            "give either mass or density, not both",
        ));
    }
    let density = b
        .density
        .map(|d| validate::positive("density", d).map_err(in_field(section, "density")))
        .transpose()?;
    let mass = match (b.mass, density, radius) {
        (Some(m), _, _) => Some(validate::positive("mass", m).map_err(in_field(section, "mass"))?),
        (None, Some(rho), Some(r)) => Some(sphere_mass(r, rho).map_err(|_| {
            SceneError::field(
                format!("{section}.radius"),
                format!("= {r:e} with density {rho:e} kg/m^3: the mass (4/3) pi R^3 rho = {:e} kg is not representable", 4.0 / 3.0 * std::f64::consts::PI * r * r * r * rho),
            )
        })?),
        (None, _, None) => None,
        (None, None, Some(_)) => {
            return Err(SceneError::field(
                format!("{section}.density"),
                "is required (kg/m^3), or give mass (kg)",
            ))
        }
    };
    let density = density.or(match (mass, radius) {
        (Some(m), Some(r)) => Some(m / (4.0 / 3.0 * std::f64::consts::PI * r * r * r)),
        _ => None,
    });
    let yield_stress = b
        .yield_stress
        .map(|s| validate::positive("yield_stress", s).map_err(in_field(section, "yield_stress")))
        .transpose()?;
    let viscosity = b
        .viscosity
        .map(|s| validate::positive("viscosity", s).map_err(in_field(section, "viscosity")))
        .transpose()?;
    let gradation = match &b.gradation {
        None => None,
        Some(GradationFile {
            exponent,
            modulus_factor,
        }) => {
            if !is_target {
                return Err(SceneError::field(
                    format!("{section}.gradation"),
                    "only the target (a half-space) can be graded",
                ));
            }
            let k = validate::in_open_interval(
                "exponent",
                *exponent,
                -1.0,
                1.0,
                "must satisfy -1 < k < 1",
            )
            .map_err(in_field(section, "gradation.exponent"))?;
            let c = validate::positive("modulus_factor", *modulus_factor)
                .map_err(in_field(section, "gradation.modulus_factor"))?;
            Some((k, c))
        }
    };
    Ok(Body {
        radius,
        mass,
        density,
        material,
        yield_stress,
        viscosity,
        gradation,
    })
}

impl Scene {
    /// Validates scene data (from a file or the [`SceneBuilder`]).
    pub fn from_data(data: SceneFile) -> Result<Scene, SceneError> {
        let accuracy = match data.accuracy {
            None => DEFAULT_ACCURACY,
            Some(a) => validate::tolerance("accuracy", a)
                .map_err(|e| SceneError::field("accuracy", in_field("", "accuracy")(e).message))?,
        };
        let sphere = body("sphere", &data.sphere, false)?;
        let target = body("target", &data.target, true)?;
        if target.radius.is_some() && target.mass.is_none() {
            return Err(SceneError::field(
                "target.density",
                "a spherical target needs density or mass",
            ));
        }
        if target.gradation.is_some() && target.radius.is_some() {
            return Err(SceneError::field(
                "target.gradation",
                "a graded target must be a half-space (no radius)",
            ));
        }
        let e = effective_modulus(&sphere.material, &target.material)
            .map_err(in_field("sphere", "youngs_modulus"))?;
        let r_sphere = sphere.radius.unwrap_or(f64::NAN);
        let r = effective_radius(r_sphere, target.radius).map_err(in_field("sphere", "radius"))?;
        let m = reduced_mass(sphere.mass.unwrap_or(f64::NAN), target.mass)
            .map_err(in_field("sphere", "mass"))?;
        let adhesion = match &data.adhesion {
            None => None,
            Some(a) => Some(adhesion(a, e, r)?),
        };
        let (plasticity, adhesive_plasticity) = plasticity(data.plasticity.as_ref())?;
        if data.plasticity.is_some()
            && sphere.yield_stress.is_none()
            && target.yield_stress.is_none()
        {
            return Err(SceneError::field(
                "plasticity",
                "a [plasticity] section needs a yield_stress on the sphere or the target (Pa)",
            ));
        }
        if let Some(a) = &adhesion {
            if a.separation == SeparationRule::LoadControlled
                && matches!(a.range, AdhesionRange::TaborParameter(_))
            {
                return Err(SceneError::field(
                    "adhesion.separation",
                    "\"load-controlled\" applies to JKR only (no range): a Maugis-Dugdale contact separates at its own instability; remove separation or the range",
                ));
            }
        }
        let speed = match data.impact.as_ref().and_then(|i| i.speed) {
            None => None,
            Some(v) => Some(validate::positive("speed", v).map_err(in_field("impact", "speed"))?),
        };
        let name = data.name.clone().unwrap_or_else(|| "scene".into());
        Ok(Scene {
            data,
            source: None,
            name,
            sphere,
            target,
            adhesion,
            plasticity,
            adhesive_plasticity,
            speed,
            accuracy,
            effective_modulus: e,
            effective_radius: r,
            effective_mass: m,
        })
    }

    /// Parses and validates a scene text. Validation errors are located in the text
    /// (line of the offending key) where possible.
    pub fn from_str(text: &str, format: Format) -> Result<Scene, SceneError> {
        let data = parse(text, format)?;
        let source = std::sync::Arc::new((text.to_string(), format));
        let mut scene = Scene::from_data(data).map_err(|e| located(&source, e))?;
        scene.source = Some(source);
        Ok(scene)
    }

    /// `e` with the line of its field in the scene text, when the scene was read
    /// from a text and the error has a field but no line yet.
    pub(crate) fn locate(&self, e: SceneError) -> SceneError {
        match &self.source {
            Some(source) => located(source, e),
            None => e,
        }
    }

    /// Reads and validates a scene file (`.json` is JSON, anything else TOML).
    pub fn from_path(path: &Path) -> Result<Scene, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|e| SceneError {
            line: None,
            column: None,
            field: None,
            message: format!("cannot read {}: {e}", path.display()),
        })?;
        let mut scene = Scene::from_str(&text, Format::of_path(path))?;
        if scene.data.name.is_none() {
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
        Ok(s)
    }

    /// The Tabor parameter Λ, when the interface has a range.
    pub fn tabor_parameter(&self) -> Option<f64> {
        match self.adhesion.as_ref()?.range {
            AdhesionRange::Jkr => None,
            AdhesionRange::TaborParameter(l) => Some(l),
        }
    }

    /// The yield stress of the softer plastic body (the smaller one given).
    pub fn yield_stress(&self) -> Option<f64> {
        match (self.sphere.yield_stress, self.target.yield_stress) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// The field of the yield stress that [`Scene::yield_stress`] uses.
    pub fn yield_stress_field(&self) -> &'static str {
        match (self.sphere.yield_stress, self.target.yield_stress) {
            (Some(a), Some(b)) if a < b => "sphere.yield_stress",
            (Some(_), None) => "sphere.yield_stress",
            _ => "target.yield_stress",
        }
    }

    /// The Poisson's ratio of the plastic body (the target if it has a yield
    /// stress, else the sphere).
    pub fn plastic_poisson_ratio(&self) -> f64 {
        if self.target.yield_stress.is_some() {
            self.target.material.poisson_ratio()
        } else {
            self.sphere.material.poisson_ratio()
        }
    }

    /// The slowest elastic wave speed √(E/ρ) of the bodies whose density is known.
    pub fn wave_speed_body(&self) -> Option<(f64, f64)> {
        [&self.sphere, &self.target]
            .iter()
            .filter_map(|b| b.density.map(|rho| (b.material.youngs_modulus(), rho)))
            .min_by(|a, b| (a.0 / a.1).total_cmp(&(b.0 / b.1)))
    }
}

/// `e` with the line of its field (or section) in `source`, when it has none.
fn located(source: &(String, Format), mut e: SceneError) -> SceneError {
    let (text, format) = (source.0.as_str(), source.1);
    if e.line.is_none() {
        if let Some(field) = &e.field {
            let (section, key) = match field.split_once('.') {
                Some((s, k)) if !s.is_empty() => (Some(s), k),
                _ => (None, field.trim_start_matches('.')),
            };
            let key = key.rsplit('.').next().unwrap_or(key);
            e.line =
                locate(text, format, section, key).or_else(|| locate_section(text, format, field));
        }
    }
    e
}

fn adhesion(a: &AdhesionFile, e: f64, r: f64) -> Result<Adhesion, SceneError> {
    let w = validate::non_negative("work_of_adhesion", a.work_of_adhesion)
        .map_err(in_field("adhesion", "work_of_adhesion"))?;
    let given = [
        a.range.is_some(),
        a.cohesive_stress.is_some(),
        a.tabor_parameter.is_some(),
        a.maugis_parameter.is_some(),
        a.tabor_mu.is_some(),
    ]
    .iter()
    .filter(|x| **x)
    .count();
    if given > 1 {
        return Err(SceneError::field(
            "adhesion",
            "give at most one of range, cohesive_stress, tabor_parameter, maugis_parameter, tabor_mu",
        ));
    }
    let range = if w == 0.0 || given == 0 {
        AdhesionRange::Jkr
    } else if let Some(h) = a.range {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_range(h, w, e, r).map_err(in_field("adhesion", "range"))?,
        )
    } else if let Some(s) = a.cohesive_stress {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_cohesive_stress(s, w, e, r)
                .map_err(in_field("adhesion", "cohesive_stress"))?,
        )
    } else if let Some(l) = a.tabor_parameter {
        AdhesionRange::TaborParameter(
            validate::positive("tabor_parameter", l)
                .map_err(in_field("adhesion", "tabor_parameter"))?,
        )
    } else if let Some(l) = a.maugis_parameter {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_maugis(l).map_err(in_field("adhesion", "maugis_parameter"))?,
        )
    } else if let Some(mu) = a.tabor_mu {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_tabor_mu(mu).map_err(in_field("adhesion", "tabor_mu"))?,
        )
    } else {
        AdhesionRange::Jkr
    };
    let separation = match a.separation.as_deref() {
        None | Some("fixed-grip") => SeparationRule::FixedGrip,
        Some("load-controlled") => SeparationRule::LoadControlled,
        Some(other) => {
            return Err(SceneError::field(
                "adhesion.separation",
                format!("unknown rule \"{other}\": expected \"fixed-grip\" or \"load-controlled\""),
            ))
        }
    };
    Ok(Adhesion {
        work_of_adhesion: w,
        range,
        separation,
    })
}

fn plasticity(
    p: Option<&PlasticityFile>,
) -> Result<(PlasticityModel, AdhesivePlasticity), SceneError> {
    let model = match p.and_then(|p| p.model.as_deref()) {
        None | Some("auto") => PlasticityModel::Auto,
        Some("thornton") => PlasticityModel::Thornton,
        Some("interpolation") => PlasticityModel::Interpolation,
        Some("jackson-green") => PlasticityModel::JacksonGreen,
        Some("dimensionless-fit") => PlasticityModel::DimensionlessFit,
        Some(other) => {
            return Err(SceneError::field(
                "plasticity.model",
                format!(
                    "unknown model \"{other}\": expected auto, thornton, interpolation, jackson-green or dimensionless-fit"
                ),
            ))
        }
    };
    let adhesive = match p.and_then(|p| p.adhesive_model.as_deref()) {
        None | Some("interpolation") => AdhesivePlasticity::Interpolation,
        Some("superposition") => AdhesivePlasticity::Superposition,
        Some(other) => {
            return Err(SceneError::field(
                "plasticity.adhesive_model",
                format!("unknown model \"{other}\": expected interpolation or superposition"),
            ))
        }
    };
    Ok((model, adhesive))
}

/// An elastic sphere for [`SceneBuilder::sphere`] and [`SceneBuilder::target_sphere`]:
/// radius (m), density (kg/m³) and elastic material (Young's modulus, Poisson's
/// ratio). The radius and density are checked by [`SceneBuilder::build`], as in a file.
///
/// Seed 000, introduction of chapter 5 (a sphere of radius `R_i`, mass
/// `m_i = (4/3)π R_i³ ρ_i`, modulus `E_i` and Poisson's ratio `ν_i`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticSphere {
    /// Radius (m).
    pub radius: f64,
    /// Density (kg/m³).
    pub density: f64,
    /// Young's modulus and Poisson's ratio.
    pub material: ElasticMaterial,
}

impl ElasticSphere {
    /// The scene-file section of this sphere.
    fn body_file(&self) -> BodyFile {
        BodyFile {
            radius: Some(self.radius),
            density: Some(self.density),
            youngs_modulus: self.material.youngs_modulus(),
            poisson_ratio: self.material.poisson_ratio(),
            ..BodyFile::default()
        }
    }
}

/// Builds a scene in code; [`SceneBuilder::build`] validates it exactly as a file.
#[derive(Clone, Debug, Default)]
pub struct SceneBuilder {
    data: SceneFile,
}

impl SceneBuilder {
    /// A new builder: the sphere and the target need at least their elastic
    /// constants (and the sphere a radius and density or mass).
    pub fn new() -> Self {
        SceneBuilder::default()
    }
    /// The sphere (radius, density, elastic material).
    ///
    /// Seed 000, introduction of chapter 5 (the impacting sphere of radius `R1`, mass
    /// `m1` and material `E1`, `ν1`).
    pub fn sphere(mut self, sphere: ElasticSphere) -> Self {
        self.data.sphere = sphere.body_file();
        self
    }
    /// A spherical target (radius, density, elastic material).
    ///
    /// Seed 000, introduction of chapter 5 (`1/R = 1/R1 + 1/R2`, `1/m = 1/m1 + 1/m2`).
    pub fn target_sphere(mut self, target: ElasticSphere) -> Self {
        self.data.target = target.body_file();
        self
    }
    /// A flat half-space target of elastic material `material`; its density (kg/m³)
    /// optional (for the quasi-static check).
    ///
    /// Seed 000, introduction of chapter 5 (`R2 → ∞`: `R = R1`).
    pub fn target_half_space(mut self, material: ElasticMaterial, density: Option<f64>) -> Self {
        self.data.target = BodyFile {
            density,
            youngs_modulus: material.youngs_modulus(),
            poisson_ratio: material.poisson_ratio(),
            ..BodyFile::default()
        };
        self
    }
    /// The target's yield stress (Pa).
    pub fn target_yield_stress(mut self, yield_stress: f64) -> Self {
        self.data.target.yield_stress = Some(yield_stress);
        self
    }
    /// JKR adhesion with work of adhesion Δγ (J/m²).
    pub fn adhesion(mut self, work_of_adhesion: f64) -> Self {
        self.data.adhesion = Some(AdhesionFile {
            work_of_adhesion,
            ..AdhesionFile::default()
        });
        self
    }
    /// The range of adhesion h (m): Maugis-Dugdale adhesion.
    pub fn adhesion_range(mut self, range: f64) -> Self {
        self.data
            .adhesion
            .get_or_insert_with(AdhesionFile::default)
            .range = Some(range);
        self
    }
    /// The Tabor parameter Λ directly.
    pub fn tabor_parameter(mut self, lambda: f64) -> Self {
        self.data
            .adhesion
            .get_or_insert_with(AdhesionFile::default)
            .tabor_parameter = Some(lambda);
        self
    }
    /// The JKR separation rule ("fixed-grip" or "load-controlled").
    pub fn separation(mut self, rule: SeparationRule) -> Self {
        self.data
            .adhesion
            .get_or_insert_with(AdhesionFile::default)
            .separation = Some(rule.as_str().to_string());
        self
    }
    /// The plasticity model name.
    pub fn plasticity_model(mut self, model: &str) -> Self {
        self.data
            .plasticity
            .get_or_insert_with(PlasticityFile::default)
            .model = Some(model.into());
        self
    }
    /// The impact speed (m/s).
    pub fn speed(mut self, speed: f64) -> Self {
        self.data
            .impact
            .get_or_insert_with(ImpactFile::default)
            .speed = Some(speed);
        self
    }
    /// The requested relative accuracy.
    pub fn accuracy(mut self, accuracy: f64) -> Self {
        self.data.accuracy = Some(accuracy);
        self
    }
    /// Validates and builds the scene.
    pub fn build(self) -> Result<Scene, SceneError> {
        Scene::from_data(self.data)
    }
}

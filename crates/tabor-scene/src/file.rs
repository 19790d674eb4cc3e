//! The scene file format (TOML or JSON) and its one-line parse errors.
//!
//! Every table rejects unknown keys; every value is a plain number in SI units (or a
//! string for the choices). A parse error names the file position (line:column),
//! the field path (`sphere.radius`) and what was wrong, on one line.

use serde::{Deserialize, Serialize};
use std::fmt;

/// The contents of a scene file, as written (before validation).
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Optional requested relative accuracy (default 1e-10).
    pub accuracy: Option<f64>,
    /// Optional name of the scene.
    pub name: Option<String>,
    /// Optional one-line description.
    pub description: Option<String>,
    /// The impacting sphere.
    pub sphere: BodyFile,
    /// The target: a second sphere if it has a radius, else a flat half-space.
    pub target: BodyFile,
    /// Adhesion at the interface (optional).
    pub adhesion: Option<AdhesionFile>,
    /// The plasticity model (optional; plasticity needs a yield stress).
    pub plasticity: Option<PlasticityFile>,
    /// The impact (optional: speed).
    pub impact: Option<ImpactFile>,
    /// Friction, rolling and twisting resistance (optional; LAMMPS `pair granular`
    /// sub-models), for the oblique impact.
    pub friction: Option<FrictionFile>,
    /// A DEM normal damping law (optional; LAMMPS `pair granular` `damping`).
    pub damping: Option<DampingFile>,
}

/// The `[damping]` section: a DEM normal damping law of LAMMPS's `pair granular`
/// (documentation `pair_granular`, "Damping"), applied to the scene's normal force
/// law (`tabor_viscoadhesive::NormalDamping`).
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DampingFile {
    /// "viscoelastic", "tsuji" or "coeff_restitution" (LAMMPS `pair_granular`,
    /// "Damping").
    pub model: String,
    /// `viscoelastic`: η_n0 (1/(m s)), `F = η_n0 m* a v_n`; `tsuji`: the damping
    /// value (read as a restitution by Tsuji's polynomial), in (0, 1].
    pub coefficient: Option<f64>,
    /// `coeff_restitution`: the restitution e, in (0, 1] (LAMMPS reads it the
    /// same way).
    pub restitution: Option<f64>,
}

/// The `[friction]` section: LAMMPS `pair granular`'s tangential, rolling and
/// twisting sub-models.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionFile {
    /// The sliding friction coefficient μ.
    pub coefficient: f64,
    /// "mindlin" (default), "mindlin_rescale" or "linear_history".
    pub tangential: Option<String>,
    /// k_t: for the Mindlin models the coefficient of the contact radius (Pa;
    /// default 8 G* from the materials, LAMMPS `mindlin NULL`), for
    /// `linear_history` the spring (N/m, required).
    pub tangential_stiffness: Option<f64>,
    /// x_γ,t: the tangential damping as a multiple of the normal damping
    /// coefficient (default 0).
    pub tangential_damping: Option<f64>,
    /// Rolling resistance `sds`.
    pub rolling: Option<SdsFile>,
    /// Twisting resistance: "marshall", or `{ stiffness, damping, coefficient }`
    /// for `sds`.
    pub twisting: Option<TwistingFile>,
}

/// A spring-dashpot-slider (`sds`) as written: stiffness, damping, coefficient.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SdsFile {
    /// Stiffness (rolling: N/m; twisting: N m/rad).
    pub stiffness: f64,
    /// Damping (rolling: N s/m; twisting: N m s/rad); default 0.
    pub damping: Option<f64>,
    /// Coefficient of the limit μ F_n0 (twisting: m).
    pub coefficient: f64,
}

/// The twisting model as written: a name or an `sds` table.
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(untagged)]
pub enum TwistingFile {
    /// "marshall".
    Name(String),
    /// `{ stiffness, damping, coefficient }`: `sds`.
    Sds(SdsFile),
}

/// A body as written in a scene file.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BodyFile {
    /// Radius (m); for the target: absent = flat half-space.
    pub radius: Option<f64>,
    /// Density (kg/m³); or `mass`.
    pub density: Option<f64>,
    /// Mass (kg); or `density`.
    pub mass: Option<f64>,
    /// Young's modulus (Pa).
    pub youngs_modulus: f64,
    /// Poisson's ratio.
    pub poisson_ratio: f64,
    /// Yield stress (Pa), optional: makes the body elastic-perfectly plastic.
    pub yield_stress: Option<f64>,
    /// Shear viscosity (Pa·s) of an incompressible Kelvin-Voigt body, optional.
    pub viscosity: Option<f64>,
    /// Power-law gradation of the modulus with depth (target only), optional.
    pub gradation: Option<GradationFile>,
}

/// A power-law graded medium, modulus ∝ depth^k (seed 000 eq. (5.20)).
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct GradationFile {
    /// The exponent k, −1 < k < 1.
    pub exponent: f64,
    /// The modulus factor c_N (Pa·m^(−k)).
    pub modulus_factor: f64,
}

/// The adhesive interface as written.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct AdhesionFile {
    /// Work of adhesion Δγ (J/m²).
    pub work_of_adhesion: f64,
    /// Range of the adhesive stress h (m).
    pub range: Option<f64>,
    /// Dugdale cohesive stress σ0 (Pa).
    pub cohesive_stress: Option<f64>,
    /// The seed's Tabor parameter Λ = d_n/h.
    pub tabor_parameter: Option<f64>,
    /// Maugis' λ.
    pub maugis_parameter: Option<f64>,
    /// Tabor's μ = (R Δγ²/(E*² z0³))^(1/3), converted to Λ through the Dugdale
    /// equivalence λ ≈ 1.1570 μ (an approximation).
    pub tabor_mu: Option<f64>,
    /// JKR separation rule: "fixed-grip" (default) or "load-controlled".
    pub separation: Option<String>,
}

/// The plasticity section as written.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PlasticityFile {
    /// "auto" (default), "thornton", "interpolation", "jackson-green",
    /// "dimensionless-fit".
    pub model: Option<String>,
    /// With adhesion: "interpolation" (the adhesive interpolation model, default) or
    /// "superposition".
    pub adhesive_model: Option<String>,
}

/// The impact section as written.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ImpactFile {
    /// Relative impact speed (m/s).
    pub speed: Option<f64>,
    /// Degrees between the relative velocity and the line of centres at first
    /// touch (default 0: central impact).
    pub angle: Option<f64>,
    /// Initial angular velocity of the sphere (rad/s, [x, y, z] in the impact frame).
    pub sphere_spin: Option<[f64; 3]>,
    /// Initial angular velocity of the target (rad/s).
    pub target_spin: Option<[f64; 3]>,
}

/// The format of a scene text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// TOML.
    Toml,
    /// JSON.
    Json,
}

impl Format {
    /// The format of a path by its extension (`.json` is JSON, anything else TOML).
    pub fn of_path(path: &std::path::Path) -> Format {
        match path.extension().and_then(|e| e.to_str()) {
            Some(e) if e.eq_ignore_ascii_case("json") => Format::Json,
            _ => Format::Toml,
        }
    }
}

/// A scene that could not be read: where, which field, and why — one line.
#[derive(Clone, Debug, PartialEq)]
pub struct ParseError {
    /// 1-based line, when known.
    pub line: Option<usize>,
    /// 1-based column, when known.
    pub column: Option<usize>,
    /// The field path (`sphere.radius`), when known.
    pub field: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.column) {
            (Some(l), Some(c)) => write!(f, "line {l}, column {c}: ")?,
            (Some(l), None) => write!(f, "line {l}: ")?,
            _ => {}
        }
        if let Some(field) = &self.field {
            write!(f, "{field}: ")?;
        }
        // one line, whatever the parser said
        let message = self
            .message
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        write!(f, "{message}")
    }
}

impl std::error::Error for ParseError {}

/// 1-based (line, column) of byte offset `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let column = before.rfind('\n').map_or(offset, |p| offset - p - 1) + 1;
    (line, column)
}

fn path_string(path: &serde_path_to_error::Path) -> Option<String> {
    let s = path.to_string();
    (s != "." && !s.is_empty()).then_some(s)
}

/// Parses a scene text in the given format (no validation of the values yet).
pub fn parse(text: &str, format: Format) -> Result<SceneFile, ParseError> {
    match format {
        Format::Toml => {
            let de = toml::Deserializer::parse(text).map_err(|e| {
                let (line, column) = e
                    .span()
                    .map(|s| line_column(text, s.start))
                    .map_or((None, None), |(l, c)| (Some(l), Some(c)));
                ParseError {
                    line,
                    column,
                    field: None,
                    message: plain(e.message()),
                }
            })?;
            serde_path_to_error::deserialize(de).map_err(|e| {
                let field = path_string(e.path());
                let inner = e.inner();
                let (line, column) = inner
                    .span()
                    .map(|s| line_column(text, s.start))
                    .map_or((None, None), |(l, c)| (Some(l), Some(c)));
                ParseError {
                    line,
                    column,
                    field,
                    message: plain(inner.message()),
                }
            })
        }
        Format::Json => {
            let mut de = serde_json::Deserializer::from_str(text);
            serde_path_to_error::deserialize(&mut de).map_err(|e| {
                let field = path_string(e.path());
                let inner = e.inner();
                // serde_json appends " at line L column C" to its message
                let message = inner.to_string();
                let message = match message.rfind(" at line ") {
                    Some(p) => message[..p].to_string(),
                    None => message,
                };
                ParseError {
                    line: (inner.line() > 0).then_some(inner.line()),
                    column: (inner.column() > 0).then_some(inner.column()),
                    field,
                    message: plain(&message),
                }
            })
        }
    }
}

/// A deserializer's message in the words of the scene file: serde names the Rust
/// type it expected ("expected struct SdsFile"), which a user never wrote.
fn plain(message: &str) -> String {
    const TABLES: [(&str, &str); 10] = [
        (
            "data did not match any variant of untagged enum TwistingFile",
            "expected \"marshall\" or a table { stiffness, damping, coefficient }",
        ),
        ("struct SceneFile", "a scene table"),
        ("struct FrictionFile", "a [friction] table"),
        (
            "struct SdsFile",
            "a table { stiffness, damping, coefficient }",
        ),
        (
            "enum TwistingFile",
            "\"marshall\" or a table { stiffness, damping, coefficient }",
        ),
        ("struct BodyFile", "a body table"),
        ("struct GradationFile", "a [gradation] table"),
        ("struct AdhesionFile", "an [adhesion] table"),
        ("struct PlasticityFile", "a [plasticity] table"),
        ("struct ImpactFile", "an [impact] table"),
    ];
    let mut out = message.to_string();
    for (rust, words) in TABLES {
        out = out.replace(rust, words);
    }
    out
}

/// The 1-based line where `key` is set inside table `[section]` of a TOML text (or
/// after `"section"` in JSON): used to point validation errors at the file.
pub fn locate(text: &str, format: Format, section: Option<&str>, key: &str) -> Option<usize> {
    let mut in_section = section.is_none();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        match format {
            Format::Toml => {
                if line.starts_with('[') {
                    let name = line.trim_matches(|c| c == '[' || c == ']').trim();
                    in_section = Some(name) == section;
                    continue;
                }
                if in_section {
                    if let Some((k, _)) = line.split_once('=') {
                        if k.trim() == key {
                            return Some(i + 1);
                        }
                    }
                }
            }
            Format::Json => {
                if let Some(s) = section {
                    if line.contains(&format!("\"{s}\"")) {
                        in_section = true;
                    }
                }
                if in_section && line.contains(&format!("\"{key}\"")) {
                    return Some(i + 1);
                }
            }
        }
    }
    None
}

/// The 1-based line of the table `[section]` (TOML) or of the key `"section"`
/// (JSON), for errors that concern a whole section.
pub fn locate_section(text: &str, format: Format, section: &str) -> Option<usize> {
    text.lines()
        .position(|raw| {
            let line = raw.trim();
            match format {
                Format::Toml => {
                    line.starts_with('[')
                        && line.trim_matches(|c| c == '[' || c == ']').trim() == section
                }
                Format::Json => line.contains(&format!("\"{section}\"")),
            }
        })
        .map(|i| i + 1)
}

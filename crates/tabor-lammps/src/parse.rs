//! Reading a user's LAMMPS line: `pair_coeff I J <normal model> … damping <model>
//! [limit_damping]` or `fix ID group wall/gran granular <same keywords> <wall>`,
//! as documented for `pair_style granular` and `fix wall/gran` in the LAMMPS
//! manual.

use crate::law::{DampingModel, GranularModel, NormalModel};
use serde::Serialize;
use std::fmt;

/// What kind of LAMMPS line was read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum LineKind {
    /// `pair_coeff …` of `pair_style granular`: a sphere–sphere contact.
    PairCoeff,
    /// `fix … wall/gran granular …`: a sphere–wall contact.
    WallGran,
}

/// A LAMMPS line that could not be read: the token and why (one line).
#[derive(Clone, Debug, PartialEq)]
pub struct LineError(pub String);

impl fmt::Display for LineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for LineError {}

/// A parsed line: its kind, the normal contact, and the keywords read but without
/// effect on a central impact (tangential, rolling, twisting).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ParsedLine {
    /// `pair_coeff` or `wall/gran`.
    pub kind: LineKind,
    /// The normal contact.
    pub model: GranularModel,
    /// Sub-models read and ignored (no effect on a frictionless central impact).
    pub ignored: Vec<String>,
}

fn number(tokens: &[&str], i: usize, what: &str) -> Result<f64, LineError> {
    let t = tokens
        .get(i)
        .ok_or_else(|| LineError(format!("missing {what} (coefficient {})", i)))?;
    t.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| LineError(format!("{what} = \"{t}\" is not a finite number")))
}

const SUB_MODELS: [&str; 5] = ["tangential", "rolling", "twisting", "heat", "damping"];

/// Parses a `pair_coeff` or `fix wall/gran granular` line.
pub fn parse_line(line: &str) -> Result<ParsedLine, LineError> {
    let tokens: Vec<&str> = line
        .split('#')
        .next()
        .unwrap_or("")
        .split_whitespace()
        .collect();
    let (kind, start) = match tokens.first() {
        Some(&"pair_coeff") => {
            if tokens.len() < 4 {
                return Err(LineError(
                    "pair_coeff needs two atom types and a normal model".into(),
                ));
            }
            (LineKind::PairCoeff, 3)
        }
        Some(&"fix") => {
            let g = tokens
                .iter()
                .position(|t| *t == "granular")
                .ok_or_else(|| {
                    LineError("a fix line must be \"fix ID group wall/gran granular …\"".into())
                })?;
            if !tokens.iter().take(g).any(|t| *t == "wall/gran") {
                return Err(LineError(
                    "a fix line must be \"fix ID group wall/gran granular …\"".into(),
                ));
            }
            (LineKind::WallGran, g + 1)
        }
        Some(other) => {
            return Err(LineError(format!(
            "expected a line starting with pair_coeff or fix (wall/gran granular), got \"{other}\""
        )))
        }
        None => return Err(LineError("empty line".into())),
    };
    let name = *tokens
        .get(start)
        .ok_or_else(|| LineError("missing the normal model".into()))?;
    let c = |k: usize, what: &str| number(&tokens, start + k, what);
    let (normal, damp, used) = match name {
        "hooke" => (
            NormalModel::Hooke {
                stiffness: c(1, "hooke k")?,
            },
            c(2, "hooke damp")?,
            3,
        ),
        "hertz" => (
            NormalModel::Hertz {
                stiffness: c(1, "hertz k")?,
            },
            c(2, "hertz damp")?,
            3,
        ),
        "hertz/material" => (
            NormalModel::HertzMaterial {
                youngs_modulus: c(1, "hertz/material E")?,
                poisson_ratio: c(3, "hertz/material nu")?,
            },
            c(2, "hertz/material damp")?,
            4,
        ),
        "dmt" => (
            NormalModel::Dmt {
                youngs_modulus: c(1, "dmt E")?,
                poisson_ratio: c(3, "dmt nu")?,
                surface_energy: c(4, "dmt gamma")?,
            },
            c(2, "dmt damp")?,
            5,
        ),
        "jkr" => (
            NormalModel::Jkr {
                youngs_modulus: c(1, "jkr E")?,
                poisson_ratio: c(3, "jkr nu")?,
                surface_energy: c(4, "jkr gamma")?,
            },
            c(2, "jkr damp")?,
            5,
        ),
        "mdr" => {
            return Err(LineError(
                "normal model mdr: not predicted by --check (its plastic and bulk response has no tabor counterpart here)".into(),
            ))
        }
        other => {
            return Err(LineError(format!(
                "unknown normal model \"{other}\": expected hooke, hertz, hertz/material, dmt or jkr"
            )))
        }
    };
    let mut damping = DampingModel::Viscoelastic; // LAMMPS's default
    let mut limit_damping = false;
    let mut ignored = Vec::new();
    let mut i = start + used;
    while i < tokens.len() {
        match tokens[i] {
            "damping" => {
                let d = *tokens
                    .get(i + 1)
                    .ok_or_else(|| LineError("damping needs a model name".into()))?;
                damping = match d {
                    "none" => {
                        return Err(LineError(
                            "damping none: LAMMPS 22 Jul 2025 refuses it (\"Must specify damping granular model\"); write damping viscoelastic with a damping coefficient of 0".into(),
                        ))
                    }
                    "velocity" => DampingModel::Velocity,
                    "mass_velocity" => DampingModel::MassVelocity,
                    "viscoelastic" => DampingModel::Viscoelastic,
                    "tsuji" => DampingModel::Tsuji,
                    "coeff_restitution" => DampingModel::CoeffRestitution,
                    other => {
                        return Err(LineError(format!(
                            "unknown damping model \"{other}\": expected none, velocity, mass_velocity, viscoelastic, tsuji or coeff_restitution"
                        )))
                    }
                };
                i += 2;
            }
            "limit_damping" => {
                limit_damping = true;
                i += 1;
            }
            t if SUB_MODELS.contains(&t) => {
                // tangential/rolling/twisting/heat and their coefficients: up to the
                // next keyword
                let mut j = i + 1;
                while j < tokens.len()
                    && !SUB_MODELS.contains(&tokens[j])
                    && tokens[j] != "limit_damping"
                    && !is_wall_style(tokens[j])
                {
                    j += 1;
                }
                ignored.push(tokens[i..j].join(" "));
                i = j;
            }
            t if kind == LineKind::WallGran && is_wall_style(t) => {
                // the wall geometry and its keywords end the model
                break;
            }
            other => {
                return Err(LineError(format!(
                    "unexpected \"{other}\" after the {name} coefficients"
                )))
            }
        }
    }
    let model = GranularModel {
        normal,
        damp,
        damping,
        limit_damping,
    };
    model.validate().map_err(|e| LineError(e.to_string()))?;
    Ok(ParsedLine {
        kind,
        model,
        ignored,
    })
}

fn is_wall_style(t: &str) -> bool {
    matches!(t, "xplane" | "yplane" | "zplane" | "zcylinder" | "region")
}

//! Reading a user's LAMMPS line: `pair_coeff I J <normal model> … damping <model>
//! [limit_damping]` or `fix ID group wall/gran granular <same keywords> <wall>`,
//! as documented for `pair_style granular` and `fix wall/gran` in the LAMMPS
//! manual; the legacy styles `pair_style gran/hooke|gran/hooke/history|
//! gran/hertz/history Kn Kt γn γt xmu dampflag [limit_damping]` and their
//! `fix wall/gran hooke|hooke/history|hertz/history …` walls (LAMMPS's
//! `pair_gran` page); and LAMMPS's variable substitution `$x`, `${name}`
//! ([`substitute_variables`]).

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
    /// `pair_coeff` or `wall/gran` (a legacy `pair_style gran/…` line is a pair).
    pub kind: LineKind,
    /// The style: `granular`, or a legacy `gran/hooke`, `gran/hooke/history`,
    /// `gran/hertz/history` (`hooke`, `hooke/history`, `hertz/history` for walls).
    pub style: String,
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

/// LAMMPS's variable substitution in an input line (its `Input::substitute`
/// rules): `${name}` and `$x` (one-character names) are replaced by their values
/// from `variables`; a variable not given is an error naming it, and so is an
/// immediate expression `$(…)` (it is evaluated by LAMMPS's expression parser, not
/// here: give its value instead). Text after `#` is a comment and left alone.
pub fn substitute_variables(
    line: &str,
    variables: &[(String, String)],
) -> Result<String, LineError> {
    let value = |name: &str| -> Result<String, LineError> {
        variables
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.clone())
            .ok_or_else(|| {
                LineError(format!(
                    "the line uses the LAMMPS variable \"{name}\", which is not given: pass its value (--var {name}=VALUE)"
                ))
            })
    };
    let code = line.split('#').next().unwrap_or("");
    let mut out = String::with_capacity(line.len());
    let mut chars = code.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '$' {
            out.push(c);
            continue;
        }
        match chars.next() {
            Some('{') => {
                let mut name = String::new();
                loop {
                    match chars.next() {
                        Some('}') => break,
                        Some(ch) => name.push(ch),
                        None => {
                            return Err(LineError(format!(
                                "unterminated variable \"${{{name}\" (no closing brace)"
                            )))
                        }
                    }
                }
                if name.is_empty() {
                    return Err(LineError("empty variable name \"${}\"".into()));
                }
                out.push_str(&value(&name)?);
            }
            Some('(') => {
                return Err(LineError(
                    "the line uses an immediate expression $(...), which only LAMMPS evaluates: replace it by its value".into(),
                ))
            }
            Some(ch) if !ch.is_whitespace() => out.push_str(&value(&ch.to_string())?),
            _ => return Err(LineError("a lone \"$\" (no variable name after it)".into())),
        }
    }
    out.push_str(&line[code.len()..]);
    Ok(out)
}

/// The legacy granular styles (LAMMPS `pair_gran`): `pair_style gran/… Kn Kt γn γt
/// xmu dampflag [limit_damping]` for pairs, `fix ID group wall/gran hooke|…` with
/// the same coefficients then the wall for walls. F_hooke = Kn δ + m* γn δ̇;
/// F_hertz = √(R* δ) (Kn δ + m* γn δ̇): `hooke Kn γn` with `damping
/// mass_velocity`, and `hertz Kn γn` with `damping viscoelastic`.
fn legacy(
    kind: LineKind,
    style: &str,
    tokens: &[&str],
    start: usize,
) -> Result<ParsedLine, LineError> {
    let hertz = style.ends_with("hertz/history");
    let c = |k: usize, what: &str| number(tokens, start + k, what);
    let kn = c(0, "Kn")?;
    let gamma_n = c(2, "gamma_n")?;
    let mut ignored = Vec::new();
    for (k, what) in [(1, "Kt"), (3, "gamma_t")] {
        match tokens.get(start + k) {
            Some(&"NULL") => {}
            Some(_) => {
                c(k, what)?;
            }
            None => return Err(LineError(format!("missing {what} (coefficient {})", k + 1))),
        }
    }
    c(4, "xmu")?;
    let dampflag = c(5, "dampflag")?;
    if dampflag != 0.0 && dampflag != 1.0 {
        return Err(LineError(format!("dampflag = {dampflag}: must be 0 or 1")));
    }
    ignored.push(format!(
        "Kt {} gamma_t {} xmu {} dampflag {} (tangential)",
        tokens[start + 1],
        tokens[start + 3],
        tokens[start + 4],
        tokens[start + 5]
    ));
    let mut limit_damping = false;
    for t in &tokens[start + 6..] {
        match *t {
            "limit_damping" => limit_damping = true,
            // the wall geometry and its arguments
            _ if kind == LineKind::WallGran => {}
            other => {
                return Err(LineError(format!(
                    "unexpected \"{other}\" after the {style} coefficients (expected limit_damping)"
                )))
            }
        }
    }
    let model = GranularModel {
        normal: if hertz {
            NormalModel::Hertz { stiffness: kn }
        } else {
            NormalModel::Hooke { stiffness: kn }
        },
        damp: gamma_n,
        damping: if hertz {
            DampingModel::Viscoelastic
        } else {
            DampingModel::MassVelocity
        },
        limit_damping,
    };
    model.validate().map_err(|e| LineError(e.to_string()))?;
    Ok(ParsedLine {
        kind,
        style: style.to_string(),
        model,
        ignored,
    })
}

const LEGACY_PAIR: [&str; 3] = ["gran/hooke", "gran/hooke/history", "gran/hertz/history"];
const LEGACY_WALL: [&str; 3] = ["hooke", "hooke/history", "hertz/history"];

/// Parses a `pair_coeff` or `fix wall/gran granular` line, or a legacy
/// `pair_style gran/…` or `fix wall/gran hooke|hooke/history|hertz/history` line
/// (variables substituted first: [`substitute_variables`]).
pub fn parse_line(line: &str) -> Result<ParsedLine, LineError> {
    let tokens: Vec<&str> = line
        .split('#')
        .next()
        .unwrap_or("")
        .split_whitespace()
        .collect();
    let (kind, start) = match tokens.first() {
        Some(&"pair_style") => {
            let style = *tokens
                .get(1)
                .ok_or_else(|| LineError("pair_style needs a style".into()))?;
            if LEGACY_PAIR.contains(&style) {
                return legacy(LineKind::PairCoeff, style, &tokens, 2);
            }
            return Err(LineError(format!(
                "pair_style {style}: --check reads the legacy gran/hooke, gran/hooke/history and gran/hertz/history lines, or a pair_coeff line of pair_style granular (which carries the model)"
            )));
        }
        Some(&"pair_coeff") => {
            if tokens.len() < 4 {
                return Err(LineError(
                    "pair_coeff needs two atom types and a normal model".into(),
                ));
            }
            (LineKind::PairCoeff, 3)
        }
        Some(&"fix") => {
            if matches!(
                tokens.get(3),
                Some(&"wall/tabor") | Some(&"wall/tabor/region")
            ) {
                return Err(LineError(
                    "fix wall/tabor is the plugin's wall with tabor's own force law: it reproduces `tabor impact` on a flat (tabor export lammps SCENE --plugin PATH writes it); --check predicts LAMMPS's own granular models (pair_coeff of pair_style granular, fix wall/gran)".into(),
                ));
            }
            if tokens.get(3) != Some(&"wall/gran") {
                return Err(LineError(
                    "a fix line must be \"fix ID group wall/gran granular …\" (or a legacy hooke, hooke/history, hertz/history wall)".into(),
                ));
            }
            let style = tokens.get(4).copied().unwrap_or("");
            if LEGACY_WALL.contains(&style) {
                return legacy(LineKind::WallGran, style, &tokens, 5);
            }
            if style != "granular" {
                return Err(LineError(format!(
                    "fix wall/gran style \"{style}\": expected granular (followed by the model keywords) or a legacy hooke, hooke/history, hertz/history wall"
                )));
            }
            let g = 4;
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
        style: "granular".into(),
        model,
        ignored,
    })
}

fn is_wall_style(t: &str) -> bool {
    matches!(t, "xplane" | "yplane" | "zplane" | "zcylinder" | "region")
}

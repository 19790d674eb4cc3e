//! Why a scene is not valid or cannot be answered: the field, its value, the rule,
//! and where in the file.

use crate::file::{locate, locate_section, Format, ParseError};
use std::fmt;
use std::sync::Arc;
use tabor_restitution::Error;

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
pub(crate) fn in_field<'a>(
    section: &'a str,
    key: &'static str,
) -> impl Fn(Error) -> SceneError + 'a {
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

/// The text a scene was read from, to locate errors found later.
pub(crate) type Source = Arc<(String, Format)>;

/// `e` with the line of its field (or section) in `source`, when it has none.
pub(crate) fn located(source: Option<&Source>, mut e: SceneError) -> SceneError {
    let Some(source) = source else {
        return e;
    };
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

/// The impact speed `speed` (m/s), validated (finite, > 0): the one check of a
/// speed per call.
pub(crate) fn impact_speed(speed: f64) -> Result<f64, SceneError> {
    tabor_restitution::validate::positive("speed", speed)
        .map_err(|e| SceneError::field("impact.speed", e.to_string()))
}

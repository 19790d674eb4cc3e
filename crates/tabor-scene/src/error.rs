//! Why a scene is not valid or cannot be answered: the field, its value, the rule,
//! and where in the file.

use crate::file::{locate, locate_section, Format, ParseError};
use std::fmt;
use std::sync::Arc;
use tabor_restitution::Error;

/// What kind of failure a [`SceneError`] is, for front ends that map errors to
/// exception classes or exit codes (the message alone does not say).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneErrorKind {
    /// Bad input: a field, its value, the file.
    Input,
    /// Valid input outside a model's validity (or a model that cannot answer).
    Validity,
    /// A numerical method did not converge.
    Convergence,
}

impl SceneErrorKind {
    /// The kind of a model error: a bad parameter is input, a numerical failure
    /// (but an invalid argument) non-convergence, anything else validity.
    pub fn of(e: &Error) -> Self {
        match e {
            Error::InvalidParameter { .. } => SceneErrorKind::Input,
            Error::Numerics(tabor_numerics::NumericsError::InvalidArgument { .. }) => {
                SceneErrorKind::Input
            }
            Error::Numerics(_) => SceneErrorKind::Convergence,
            Error::Model { .. } => SceneErrorKind::Validity,
        }
    }
}

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
    /// What kind of failure ([`SceneError::kind`]).
    kind: SceneErrorKind,
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
            kind: SceneErrorKind::Input,
        }
    }
}

impl SceneError {
    /// A bad-input error about field `field`.
    pub fn field(field: impl Into<String>, message: impl Into<String>) -> Self {
        SceneError {
            line: None,
            column: None,
            field: Some(field.into()),
            message: message.into(),
            kind: SceneErrorKind::Input,
        }
    }

    /// An error of a model computation (no field), of the model error's kind.
    pub fn model(e: Error) -> Self {
        SceneError {
            line: None,
            column: None,
            field: None,
            kind: SceneErrorKind::of(&e),
            message: e.to_string(),
        }
    }

    /// A model error pointing at field `field`, of the model error's kind.
    pub fn field_model(field: impl Into<String>, e: Error) -> Self {
        SceneError {
            field: Some(field.into()),
            ..SceneError::model(e)
        }
    }

    /// A bad-input error without a field (a file that cannot be read).
    pub fn input(message: impl Into<String>) -> Self {
        SceneError {
            line: None,
            column: None,
            field: None,
            message: message.into(),
            kind: SceneErrorKind::Input,
        }
    }

    /// Bad input, a model's validity, or non-convergence.
    pub fn kind(&self) -> SceneErrorKind {
        self.kind
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
            } => format!(
                "= {}: {requirement}",
                tabor_numerics::readable::plain(*value)
            ),
            other => other.to_string(),
        };
        SceneError {
            kind: SceneErrorKind::of(&e),
            ..SceneError::field(format!("{section}.{key}"), message)
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use tabor_numerics::NumericsError;

    #[test]
    fn each_error_has_its_kind() {
        let bad = Error::invalid("radius", -1.0, "must be > 0");
        let validity = Error::Model {
            model: "JKR sphere",
            message: "outside".into(),
        };
        let stuck = Error::Numerics(NumericsError::NoConvergence {
            method: "brent",
            iterations: 100,
            estimate: 1.0,
            error: 1e-3,
        });
        assert_eq!(SceneError::model(bad.clone()).kind(), SceneErrorKind::Input);
        assert_eq!(
            SceneError::model(validity.clone()).kind(),
            SceneErrorKind::Validity
        );
        assert_eq!(
            SceneError::model(stuck.clone()).kind(),
            SceneErrorKind::Convergence
        );
        // a model error pointing at a field keeps its kind and names the field
        let e = SceneError::field_model("target.yield_stress", validity);
        assert_eq!(e.kind(), SceneErrorKind::Validity);
        assert_eq!(e.field.as_deref(), Some("target.yield_stress"));
        assert_eq!(
            SceneError::field_model("x", stuck).kind(),
            SceneErrorKind::Convergence
        );
        assert_eq!(
            SceneError::field("sphere.radius", "bad").kind(),
            SceneErrorKind::Input
        );
        assert_eq!(
            in_field("sphere", "radius")(bad).kind(),
            SceneErrorKind::Input
        );
        assert_eq!(
            SceneError::input("cannot read").kind(),
            SceneErrorKind::Input
        );
    }
}

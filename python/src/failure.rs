//! Why an element failed, and the Python exception each kind becomes
//! (`tabor.InputError`, `tabor.ModelValidityError`, `tabor.ConvergenceError`,
//! defined in `tabor/_errors.py`; a panic is a `RuntimeError`).

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::PyType;
use tabor::numerics::NumericsError;
use tabor::restitution::Error;

/// The kind of a failure, which picks the exception class.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Bad input: `tabor.InputError` (a `ValueError`).
    Input,
    /// Valid input outside the model's validity: `tabor.ModelValidityError`.
    Validity,
    /// A numerical method did not converge: `tabor.ConvergenceError`.
    Convergence,
    /// A panic in the library (a bug): `RuntimeError`.
    Internal,
}

/// One failed element: its kind and the message (naming the parameter and value).
#[derive(Clone, Debug)]
pub struct Failure {
    /// Which exception.
    pub kind: Kind,
    /// One line.
    pub message: String,
}

impl Failure {
    /// A bad-input failure.
    pub fn input(message: impl Into<String>) -> Self {
        Failure {
            kind: Kind::Input,
            message: message.into(),
        }
    }

    /// A library error, classified by its variant; `message` renders it (so that a
    /// front end can rename the parameter).
    pub fn library(e: &Error, message: String) -> Self {
        let kind = match e {
            Error::InvalidParameter { .. } => Kind::Input,
            Error::Numerics(n) => numerics_kind(n),
            Error::Model { .. } => Kind::Validity,
        };
        Failure { kind, message }
    }

    /// A scene error, of the kind the scene gives it (`SceneError::kind`).
    pub fn scene(e: &tabor::scene::SceneError) -> Self {
        use tabor::scene::SceneErrorKind;
        let kind = match e.kind() {
            SceneErrorKind::Input => Kind::Input,
            SceneErrorKind::Validity => Kind::Validity,
            SceneErrorKind::Convergence => Kind::Convergence,
        };
        Failure {
            kind,
            message: e.to_string(),
        }
    }

    /// The Python exception, with ` (at index …)` appended when `index` is given.
    pub fn into_pyerr(self, py: Python<'_>, index: Option<String>) -> PyErr {
        let message = match index {
            Some(i) => format!("{} (at index {i})", self.message),
            None => self.message,
        };
        let name = match self.kind {
            Kind::Input => "InputError",
            Kind::Validity => "ModelValidityError",
            Kind::Convergence => "ConvergenceError",
            Kind::Internal => {
                return PyRuntimeError::new_err(format!(
                    "internal error in tabor (please report): {message}"
                ))
            }
        };
        match exception_class(py, name) {
            Ok(class) => PyErr::from_type(class, message),
            Err(e) => e,
        }
    }
}

fn numerics_kind(e: &NumericsError) -> Kind {
    match e {
        NumericsError::InvalidArgument { .. } => Kind::Input,
        _ => Kind::Convergence,
    }
}

static ERRORS: PyOnceLock<Py<PyModule>> = PyOnceLock::new();

/// `tabor._errors.<name>`.
pub fn exception_class<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyType>> {
    let module = ERRORS.get_or_try_init(py, || py.import("tabor._errors").map(|m| m.unbind()))?;
    Ok(module.bind(py).getattr(name)?.cast_into::<PyType>()?)
}

/// `tabor._errors.<name>` (a function of the warnings helper).
pub fn errors_module(py: Python<'_>) -> PyResult<Bound<'_, PyModule>> {
    let module = ERRORS.get_or_try_init(py, || py.import("tabor._errors").map(|m| m.unbind()))?;
    Ok(module.bind(py).clone())
}

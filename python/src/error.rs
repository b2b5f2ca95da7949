//! `cagd.CagdError`: the one exception of the package, a `ValueError` carrying the kind of the
//! library's error and the argument it names.
//!
//! Every error of the core ([`cagd::Error`]) keeps its own one-line text; `kind` is the name of
//! its variant (`"ShapeMismatch"`, `"NonFinite"`, `"TooLarge"`, …, as in docs/ERRORS.md) and
//! `argument` the argument the library names (`"B-spline knots"`), or `None`. The only errors
//! made here are the conversions of Python values that the core never sees (a complex or text
//! array, a value that is no number): kind `"Conversion"`.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

pyo3::create_exception!(
    cagd,
    CagdError,
    PyValueError,
    "An input cagd cannot use: `kind` names the library's error (as in docs/ERRORS.md), `argument` the argument it concerns (or None)."
);

/// The name of the variant of `e` (the first word of its derived `Debug` form).
fn kind_of(e: &cagd::Error) -> String {
    let debug = format!("{e:?}");
    debug
        .split(|c: char| !c.is_alphanumeric() && c != '_')
        .next()
        .unwrap_or("Error")
        .to_string()
}

/// The argument `e` names, where it names one.
fn argument_of(e: &cagd::Error) -> Option<&'static str> {
    use cagd::Error as E;
    match e {
        E::TooFewPoints { what, .. }
        | E::ShapeMismatch { what, .. }
        | E::NonFinite { what, .. }
        | E::EmptyGrid { what, .. }
        | E::EmptyInterval { what, .. }
        | E::DecreasingKnots { what, .. }
        | E::TooFewControlPoints { what, .. }
        | E::KnotCount { what, .. }
        | E::NonPositiveWeight { what, .. }
        | E::ParameterOutOfRange { what, .. }
        | E::UnusableDomain { what, .. }
        | E::Singular { what, .. }
        | E::InvalidArgument { what, .. }
        | E::DuplicateNodes { what, .. }
        | E::UnsortedNodes { what, .. }
        | E::TooFewCurves { what, .. }
        | E::TooLarge { what, .. } => Some(what),
        E::BlendingCondition { function, .. } => Some(function),
        _ => None,
    }
}

/// The exception for `message`, with its `kind` and `argument` attributes set.
pub fn cagd_error(kind: &str, argument: Option<&str>, message: String) -> PyErr {
    let err = CagdError::new_err(message);
    Python::attach(|py| {
        let value = err.value(py);
        // Setting attributes on a fresh exception instance cannot fail short of memory.
        let _ = value.setattr("kind", kind);
        let _ = value.setattr("argument", argument);
    });
    err
}

/// The library's error as `cagd.CagdError`.
pub fn to_py(e: cagd::Error) -> PyErr {
    cagd_error(&kind_of(&e), argument_of(&e), e.to_string())
}

/// A Python value that cannot be converted to what `argument` needs.
pub fn conversion(argument: &str, message: impl Into<String>) -> PyErr {
    let message = message.into();
    cagd_error(
        "Conversion",
        Some(argument),
        format!("{argument}: {message}"),
    )
}

/// `Result<T, cagd::Error>` → `PyResult<T>`.
pub trait IntoPy<T> {
    /// The error as `cagd.CagdError`.
    fn py(self) -> PyResult<T>;
}

impl<T> IntoPy<T> for cagd::Result<T> {
    fn py(self) -> PyResult<T> {
        self.map_err(to_py)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_are_variant_names() {
        let e = cagd::Error::EmptyInterval {
            what: "x",
            a: 1.0,
            b: 0.0,
        };
        assert_eq!(kind_of(&e), "EmptyInterval");
        assert_eq!(argument_of(&e), Some("x"));
    }
}

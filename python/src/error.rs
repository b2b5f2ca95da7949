//! `cagd.CagdError`: the one exception of the package, a `ValueError` carrying the kind of the
//! error and the argument it names.
//!
//! Errors come from the operation layer ([`cagd_ops::OpError`], [`op_error`]): the message is
//! `NAME: PROBLEM; expected FORM`, the operation's words after the Python name of the argument
//! (`knots`, `points`, `weights`), the same words as the command line's, the Octave package's
//! and the page's; `argument` is that name. `kind` is the name of the library error underneath
//! (`"KnotCount"`, `"NonPositiveWeight"`, `"TooLarge"`, … as in docs/ERRORS.md), or, for a rule
//! the operation layer states itself, the name of its [`Kind`] (`"NonFinite"`, `"Shape"`,
//! `"Knots"`, …). The few calls that still reach the core directly (evaluations, the thesis
//! functions) raise its error with its own text ([`to_py`]). The only errors made here are the
//! conversions of Python values that no layer below sees (a complex or text array, a value
//! that is no number): kind `"Conversion"`.

use cagd_ops::{Kind, OpError, Role};

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

pyo3::create_exception!(
    cagd,
    CagdError,
    PyValueError,
    "An input cagd cannot use, in the operation layer's words: `kind` names the library's error underneath or the operation layer's kind (as in docs/ERRORS.md), `argument` the Python name of the argument it concerns (or None).\n\n>>> try:\n...     cagd.BezierCurve([[0, 0], [float('nan'), 1]])\n... except cagd.CagdError as e:\n...     print(e.kind, e.argument, isinstance(e, ValueError))\nNonFinite points True\n"
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

/// How a class or function names the roles of its operation: `(role, Python name)`; a role
/// not listed is named by its key ([`Role::key`]).
pub type Names = &'static [(Role, &'static str)];

/// The Python name of `role`.
pub fn name_of(names: Names, role: Role) -> &'static str {
    names
        .iter()
        .find(|(r, _)| *r == role)
        .map_or_else(|| role.key(), |(_, n)| *n)
}

/// The kind a `CagdError` carries for `e`: the variant of the library's error underneath, or
/// the operation layer's kind.
fn op_kind(e: &OpError) -> String {
    match &e.source {
        Some(source) => kind_of(source),
        None => format!("{:?}", e.kind),
    }
}

/// An operation's error as `cagd.CagdError`: `NAME: PROBLEM; expected FORM`, the argument
/// named as `names` say; a limit says how to raise it (`cagd.set_limit`).
pub fn op_error(names: Names, e: OpError) -> PyErr {
    let name = name_of(names, e.role);
    let mut problem = e.problem.clone();
    if let Some(limit) = e.limit {
        problem = format!(
            "{problem} (raise it with cagd.set_limit(\"{}\", VALUE))",
            limit.field()
        );
    }
    if e.kind == Kind::Interrupted {
        let message = format!("{name}: {problem}; expected {}", e.expected);
        return pyo3::exceptions::PyKeyboardInterrupt::new_err(message);
    }
    worded(&op_kind(&e), name, &problem, &e.expected)
}

/// The exception `NAME: PROBLEM; expected FORM` of the operation layer's words about the
/// argument `name`.
pub fn worded(kind: &str, name: &str, problem: &str, expected: &str) -> PyErr {
    cagd_error(
        kind,
        Some(name),
        format!("{name}: {problem}; expected {expected}"),
    )
}

/// `Result<T, OpError>` → `PyResult<T>`, the roles named as `names` say.
pub trait OpIntoPy<T> {
    /// The error as `cagd.CagdError`.
    fn named(self, names: Names) -> PyResult<T>;
}

impl<T> OpIntoPy<T> for cagd_ops::Result<T> {
    fn named(self, names: Names) -> PyResult<T> {
        self.map_err(|e| op_error(names, e))
    }
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

    #[test]
    fn operation_errors_keep_the_library_kind_or_name_their_own() {
        let lib = OpError::library(
            Role::Knots,
            cagd::Error::KnotCount {
                what: "knot vector",
                expected: 7,
                found: 6,
            },
            "n + p + 1 knots",
        );
        assert_eq!(op_kind(&lib), "KnotCount");
        let own = OpError::new(
            Role::Weights,
            Kind::NonFinite,
            "value 2 is not finite (NaN)",
            "x",
        );
        assert_eq!(op_kind(&own), "NonFinite");
        const NAMES: Names = &[(Role::Control, "points")];
        assert_eq!(name_of(NAMES, Role::Control), "points");
        assert_eq!(name_of(NAMES, Role::Knots), "knots");
    }
}

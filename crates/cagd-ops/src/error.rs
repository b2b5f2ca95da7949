//! The one error of the operation layer: which role, what kind, what was wrong and what was
//! expected, worded once for every front end.

use cagd::limits::Limit;

use crate::Role;

/// The kind of an error: the part after `cagd:` in an Octave identifier, the class of a
/// command-line refusal; a Python `CagdError.kind` is the variant of the library's error
/// underneath ([`OpError::source`]), or this kind by its type name (`NonFinite`, `Shape`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Kind {
    /// A size or count that does not fit: too few points, mismatched shapes, an empty list.
    Shape,
    /// NaN or ±Inf in an argument.
    NonFinite,
    /// A value that is not allowed: an unknown option word, a derivative order above the
    /// degree, a condition the construction states.
    Value,
    /// A parameter outside the domain of a curve or surface.
    Domain,
    /// A knot vector that decreases or has the wrong length.
    Knots,
    /// A NURBS weight that is zero or negative.
    Weights,
    /// Interpolation nodes that repeat or do not increase.
    Nodes,
    /// Boundary curves that do not meet at the corners (or tangents that disagree there).
    Corners,
    /// A Gordon network whose curves do not cross where they should.
    Network,
    /// A singular linear system.
    Singular,
    /// Work or a size above a resource limit ([`OpError::limit`] says which).
    Limit,
    /// A result whose value overflows the range of doubles.
    Overflow,
    /// Arguments that do not fit together (an option that has no effect, a conflict).
    Usage,
    /// The computation was interrupted by the user.
    Interrupted,
    /// A fault of the program itself.
    Internal,
}

impl Kind {
    /// Every kind.
    pub const ALL: [Kind; 15] = [
        Kind::Shape,
        Kind::NonFinite,
        Kind::Value,
        Kind::Domain,
        Kind::Knots,
        Kind::Weights,
        Kind::Nodes,
        Kind::Corners,
        Kind::Network,
        Kind::Singular,
        Kind::Limit,
        Kind::Overflow,
        Kind::Usage,
        Kind::Interrupted,
        Kind::Internal,
    ];

    /// The kind's name (`"knots"`): Octave's `cagd:knots`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Shape => "shape",
            Kind::NonFinite => "nonfinite",
            Kind::Value => "value",
            Kind::Domain => "domain",
            Kind::Knots => "knots",
            Kind::Weights => "weights",
            Kind::Nodes => "nodes",
            Kind::Corners => "corners",
            Kind::Network => "network",
            Kind::Singular => "singular",
            Kind::Limit => "limit",
            Kind::Overflow => "overflow",
            Kind::Usage => "usage",
            Kind::Interrupted => "interrupted",
            Kind::Internal => "internal",
        }
    }

    /// The kind of a library error.
    pub fn of(error: &cagd::Error) -> Kind {
        use cagd::Error as E;
        match error {
            E::TooFewPoints { .. }
            | E::ShapeMismatch { .. }
            | E::EmptyGrid { .. }
            | E::TooFewControlPoints { .. }
            | E::TooFewCurves { .. } => Kind::Shape,
            E::NonFinite { .. } => Kind::NonFinite,
            E::Overflow { .. } => Kind::Overflow,
            E::ParameterOutOfRange { .. } => Kind::Domain,
            E::DecreasingKnots { .. } | E::KnotCount { .. } => Kind::Knots,
            E::NonPositiveWeight { .. } => Kind::Weights,
            E::DuplicateNodes { .. } | E::UnsortedNodes { .. } => Kind::Nodes,
            E::CornerMismatch { .. } => Kind::Corners,
            E::NetworkMismatch { .. } => Kind::Network,
            E::Singular { .. } | E::SingularMask { .. } => Kind::Singular,
            E::TooLarge { .. } => Kind::Limit,
            _ => Kind::Value,
        }
    }
}

/// An error of a construction: `problem; expected form`, about the argument in `role`.
///
/// A front end prints it after its own name of the role: the command line
/// `cagd: error: --knots: PROBLEM; expected FORM`, Octave `cagd_bspline: U: PROBLEM; expected
/// FORM` with the identifier `cagd:<kind>`, the page beside the field. The words after the
/// name are the same everywhere. For a [`Kind::Limit`] error [`limit`](Self::limit) names the
/// limit, which each front end tells how to raise in its own terms.
///
/// ```
/// use cagd_ops::{Kind, OpError, Role};
/// let e = OpError::new(Role::Samples, Kind::Shape, "N = 1 is too small", "an integer N ≥ 2");
/// assert_eq!(e.to_string(), "N = 1 is too small; expected an integer N ≥ 2");
/// ```
#[derive(Debug, Clone, thiserror::Error)]
#[error("{problem}; expected {expected}")]
pub struct OpError {
    /// The role of the argument the error is about.
    pub role: Role,
    /// The kind.
    pub kind: Kind,
    /// What was wrong, one line.
    pub problem: String,
    /// The form that would have been accepted, one line.
    pub expected: String,
    /// The resource limit a [`Kind::Limit`] error is about.
    pub limit: Option<Limit>,
    /// The library error underneath, if any.
    pub source: Option<Box<cagd::Error>>,
    /// A front end's own error underneath (an expression that did not evaluate), which the
    /// front end may recognise again; opaque here.
    pub cause: Option<std::sync::Arc<dyn std::error::Error + Send + Sync>>,
}

impl PartialEq for OpError {
    /// Equal roles, kinds, words, limits and library errors (a front end's cause is compared
    /// by its text).
    fn eq(&self, other: &Self) -> bool {
        let cause = |e: &OpError| e.cause.as_ref().map(|c| c.to_string());
        self.role == other.role
            && self.kind == other.kind
            && self.problem == other.problem
            && self.expected == other.expected
            && self.limit == other.limit
            && self.source == other.source
            && cause(self) == cause(other)
    }
}

impl OpError {
    /// An error about `role`.
    pub fn new(
        role: Role,
        kind: Kind,
        problem: impl Into<String>,
        expected: impl Into<String>,
    ) -> Self {
        OpError {
            role,
            kind,
            problem: one_line(&problem.into()),
            expected: one_line(&expected.into()),
            limit: None,
            source: None,
            cause: None,
        }
    }

    /// The same error with a front end's own error as its cause.
    pub fn caused_by(self, cause: impl std::error::Error + Send + Sync + 'static) -> Self {
        OpError {
            cause: Some(std::sync::Arc::new(cause)),
            ..self
        }
    }

    /// A library error about `role`, with the form that would have been accepted. A limit
    /// error keeps its [`Limit`]; its problem reads `WHAT: REQUESTED exceeds the limit of
    /// LIMIT`. A knot, a value, a weight and a node are counted from 1 in these words, as the
    /// notes and Octave count them (the library's index counts from 0).
    ///
    /// ```
    /// use cagd_ops::{OpError, Role};
    /// let e = cagd::Error::DecreasingKnots { what: "knot vector", index: 2, previous: 1.0, next: 0.5 };
    /// assert_eq!(OpError::library(Role::Knots, e, "").problem,
    ///     "knot vector: knot 3 (0.5) is below the knot before it (1); knots must be non-decreasing");
    /// let e = cagd::Error::NonPositiveWeight { what: "NURBS weights", index: 1, value: -1.0 };
    /// assert_eq!(OpError::library(Role::Weights, e, "").problem,
    ///     "NURBS weights: weight 2 is -1; weights must be positive");
    /// let e = cagd::Error::NonFinite { what: "points", index: 0, value: f64::NAN };
    /// assert_eq!(OpError::library(Role::Control, e, "").problem, "points: value 1 is not finite (NaN)");
    /// let e = cagd::Error::DuplicateNodes { what: "nodes", first: 0, second: 1, value: 1.0 };
    /// assert_eq!(OpError::library(Role::Nodes, e, "").problem, "nodes: nodes 1 and 2 are equal (1)");
    /// ```
    pub fn library(role: Role, error: cagd::Error, expected: &str) -> Self {
        let (problem, limit) = match &error {
            cagd::Error::DecreasingKnots {
                what,
                index,
                previous,
                next,
            } => (
                format!(
                    "{what}: knot {} ({next}) is below the knot before it ({previous}); knots must be non-decreasing",
                    index + 1
                ),
                None,
            ),
            cagd::Error::TooLarge {
                what,
                requested,
                limit,
                which,
            } => (
                format!("{what}: {requested} exceeds the limit of {limit}"),
                Some(*which),
            ),
            other => (counted_from_one(other), None),
        };
        OpError {
            limit,
            source: Some(Box::new(error.clone())),
            ..OpError::new(role, Kind::of(&error), problem, expected)
        }
    }

    /// The same error about another role.
    pub fn about(self, role: Role) -> Self {
        OpError { role, ..self }
    }
}

/// The words of a library error whose index counts from 0, counted from 1 as every index in
/// these words is (a value, a weight, a node, a knot): the library's own `Display` otherwise.
/// The Octave package words the errors of its thesis functions with it too.
///
/// ```
/// let e = cagd::Error::Overflow { what: "T", index: 0, value: f64::INFINITY };
/// assert!(cagd_ops::error::counted_from_one(&e).starts_with("T: value 1 is not a finite double (inf)"));
/// ```
pub fn counted_from_one(error: &cagd::Error) -> String {
    match error {
        cagd::Error::NonFinite { what, index, value } => {
            format!("{what}: value {} is not finite ({value})", index + 1)
        }
        cagd::Error::Overflow { what, index, value } => format!(
            "{what}: value {} is not a finite double ({value}): the input's magnitudes are too large (or too close together) for double precision",
            index + 1
        ),
        cagd::Error::DecreasingKnots {
            what,
            index,
            previous,
            next,
        } => format!(
            "{what}: knot {} ({next}) is below the knot before it ({previous}); knots must be non-decreasing",
            index + 1
        ),
        cagd::Error::NonPositiveWeight { what, index, value } => format!(
            "{what}: weight {} is {value}; weights must be positive",
            index + 1
        ),
        cagd::Error::DuplicateNodes {
            what,
            first,
            second,
            value,
        } => format!(
            "{what}: nodes {} and {} are equal ({value})",
            first + 1,
            second + 1
        ),
        cagd::Error::UnsortedNodes {
            what,
            index,
            value,
            next,
        } => format!(
            "{what}: nodes must increase, but node {} ({value}) is above node {} ({next})",
            index + 1,
            index + 2
        ),
        other => other.to_string(),
    }
}

/// `|e| OpError::library(role, e, expected)`, for `map_err`.
pub fn lib(role: Role, expected: &str) -> impl Fn(cagd::Error) -> OpError + '_ {
    move |e| OpError::library(role, e, expected)
}

/// One line: runs of white space (line breaks among them) become one space, and control
/// characters are shown escaped (`\u{1b}`), so that quoted input cannot break a message or
/// send a terminal escape.
///
/// ```
/// assert_eq!(cagd_ops::error::one_line("a\n  b\u{7}"), "a b\\u{7}");
/// ```
pub fn one_line(s: &str) -> String {
    s.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .chars()
        .flat_map(|c| {
            if c.is_control() {
                c.escape_unicode().collect::<Vec<_>>()
            } else {
                vec![c]
            }
        })
        .collect()
}

/// The operation layer's result type.
pub type Result<T, E = OpError> = std::result::Result<T, E>;

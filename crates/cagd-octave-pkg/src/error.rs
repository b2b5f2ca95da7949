//! The package's errors: an Octave identifier `cagd:<kind>` and a one-line message.
//!
//! A library error ([`cagd::Error`]) keeps its own text with indices counted from 1
//! ([`cagd_ops::error::counted_from_one`]), which is the text the command line prints after the
//! argument name (`cagd: error: ARG: PROBLEM; expected FORM`); in Octave it
//! reads `FUNCTION: PROBLEM`. Errors found by the package itself (a wrong class, an empty
//! array, a size) read `FUNCTION: ARGUMENT: PROBLEM; expected FORM`, the command line's form.

use cagd::limits::Limit;

/// The kind of an error: the part after `cagd:` in its Octave identifier.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// Wrong number of arguments (`cagd:nargin`).
    Nargin,
    /// An argument of a class the function does not take: integer, logical, single, complex,
    /// sparse, cell, struct, function handle… (`cagd:class`).
    Class,
    /// An empty array where data is needed (`cagd:empty`).
    Empty,
    /// A size or a count that does not fit (`cagd:shape`): library errors `ShapeMismatch`,
    /// `TooFewPoints`, `TooFewControlPoints`, `TooFewCurves`, `EmptyGrid`.
    Shape,
    /// NaN or ±Inf (`cagd:nonfinite`).
    NonFinite,
    /// A value that is not allowed: a count that is not a non-negative integer, an index out of
    /// range, an unknown option, a derivative order above the degree… (`cagd:value`).
    Value,
    /// A parameter outside the domain of a curve or surface (`cagd:domain`).
    Domain,
    /// A knot vector that decreases or has the wrong length (`cagd:knots`).
    Knots,
    /// A NURBS weight that is zero or negative (`cagd:weights`).
    Weights,
    /// Interpolation nodes that repeat or do not increase (`cagd:nodes`).
    Nodes,
    /// Coons boundary curves that do not meet at the corners (`cagd:corners`).
    Corners,
    /// A Gordon network whose curves do not cross where they should (`cagd:network`).
    Network,
    /// A singular linear system (`cagd:singular`).
    Singular,
    /// A struct without the fields the function needs, or not a NURBS (`cagd:struct`).
    Struct,
    /// A size over a resource limit (`cagd:limit`; see `cagd_limits`).
    Limit,
    /// A result that overflows the range of doubles although the arguments are finite
    /// (`cagd:overflow`): library error `Overflow`, the operation layer's check of every answer,
    /// the thesis functions' check of their results.
    Overflow,
    /// The computation was interrupted (`cagd:interrupted`): in Octave, Ctrl-C stops the
    /// function with Octave's own interrupt instead (the gateway rethrows it), so this
    /// identifier is seen only by a caller of [`call_interruptible`](crate::call_interruptible)
    /// whose interrupt answered `true`.
    Interrupted,
    /// An output that could not be allocated (`cagd:memory`).
    Memory,
    /// A fault of the package itself, such as a caught Rust panic (`cagd:internal`).
    Internal,
}

impl Kind {
    /// Every kind.
    pub const ALL: [Kind; 19] = [
        Kind::Nargin,
        Kind::Class,
        Kind::Empty,
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
        Kind::Struct,
        Kind::Limit,
        Kind::Overflow,
        Kind::Interrupted,
        Kind::Memory,
        Kind::Internal,
    ];

    /// The name after `cagd:`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Nargin => "nargin",
            Kind::Class => "class",
            Kind::Empty => "empty",
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
            Kind::Struct => "struct",
            Kind::Limit => "limit",
            Kind::Overflow => "overflow",
            Kind::Interrupted => "interrupted",
            Kind::Memory => "memory",
            Kind::Internal => "internal",
        }
    }

    /// The kind of a library error: the operation layer's ([`cagd_ops::Kind::of`]).
    pub fn of(error: &cagd::Error) -> Kind {
        Kind::from(cagd_ops::Kind::of(error))
    }
}

/// An error of a package function.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct PkgError {
    /// The kind (`cagd:<kind>`).
    pub kind: Kind,
    /// The message, one line.
    pub message: String,
}

impl PkgError {
    /// An error of `kind` with `message`.
    pub fn new(kind: Kind, message: impl Into<String>) -> Self {
        let message: String = message.into();
        PkgError {
            kind,
            message: message.split_whitespace().collect::<Vec<_>>().join(" "),
        }
    }

    /// `ARGUMENT: PROBLEM; expected FORM`, the command line's form.
    pub fn arg(kind: Kind, argument: &str, problem: impl AsRef<str>, form: &str) -> Self {
        Self::new(
            kind,
            format!("{argument}: {}; expected {form}", problem.as_ref()),
        )
    }

    /// The Octave identifier, `cagd:<kind>`.
    pub fn identifier(&self) -> String {
        format!("cagd:{}", self.kind.name())
    }

    /// The same error with `prefix: ` before its message.
    pub fn prefixed(mut self, prefix: &str) -> Self {
        self.message = format!("{prefix}: {}", self.message);
        self
    }
}

impl From<cagd::Error> for PkgError {
    /// The library's own text; a resource limit also says how to raise it in Octave.
    fn from(error: cagd::Error) -> Self {
        let kind = Kind::of(&error);
        let message = match &error {
            cagd::Error::TooLarge {
                what,
                requested,
                limit,
                which,
            } => format!(
                "{what}: {requested} exceeds the limit of {limit} (raise it with cagd_limits (\"{}\", VALUE))",
                which.field()
            ),
            // Indices counted from 1, as Octave counts and as the operations word them.
            other => cagd_ops::error::counted_from_one(other),
        };
        PkgError::new(kind, message)
    }
}

/// The package's result type.
pub type Result<T, E = PkgError> = std::result::Result<T, E>;

/// A [`Limit`] by its field name (`"max_grid_points"`), as `cagd_limits` takes it.
pub fn limit_by_name(name: &str) -> Option<Limit> {
    Limit::ALL.into_iter().find(|l| l.field() == name)
}

/// The kind of an operation's error in the package's identifiers.
impl From<cagd_ops::Kind> for Kind {
    fn from(kind: cagd_ops::Kind) -> Kind {
        use cagd_ops::Kind as K;
        match kind {
            K::Shape => Kind::Shape,
            K::NonFinite => Kind::NonFinite,
            K::Overflow => Kind::Overflow,
            K::Interrupted => Kind::Interrupted,
            K::Domain => Kind::Domain,
            K::Knots => Kind::Knots,
            K::Weights => Kind::Weights,
            K::Nodes => Kind::Nodes,
            K::Corners => Kind::Corners,
            K::Network => Kind::Network,
            K::Singular => Kind::Singular,
            K::Limit => Kind::Limit,
            K::Internal => Kind::Internal,
            _ => Kind::Value,
        }
    }
}

/// An operation's error as the package raises it: `ARGUMENT: PROBLEM; expected FORM`, the
/// argument named as the function's usage names it, a limit with the call that raises it.
pub fn op_error(names: &[(cagd_ops::Role, &str)], e: cagd_ops::OpError) -> PkgError {
    if e.kind == cagd_ops::Kind::Interrupted {
        // Octave's own interrupt in the session; the same words as every other function.
        return PkgError::new(Kind::Interrupted, "interrupted");
    }
    let name = names
        .iter()
        .find(|(r, _)| *r == e.role)
        .map_or_else(|| e.role.key(), |(_, n)| *n);
    let mut problem = e.problem;
    if let Some(limit) = e.limit {
        problem = format!(
            "{problem} (raise it with cagd_limits (\"{}\", VALUE))",
            limit.field()
        );
    }
    PkgError::arg(Kind::from(e.kind), name, problem, &e.expected)
}

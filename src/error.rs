//! The crate's one error type.
//!
//! Every fallible entry point returns [`Result<T>`]; each variant carries the offending data so
//! that a caller (and the command line) can say exactly what was wrong. Algorithms never panic
//! on user input.

use thiserror::Error;

use crate::scalar::Scalar;

/// Result alias used throughout the crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can be wrong with the input of a construction.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    /// A curve or patch was given no control points (or a net with an empty direction).
    #[error("{what}: expected at least {min} control point(s), got {found}")]
    TooFewPoints {
        /// Which argument.
        what: &'static str,
        /// The least number accepted.
        min: usize,
        /// The number given.
        found: usize,
    },
    /// Points, rows or columns of different sizes were mixed.
    #[error("{what}: expected {expected}, found {found}")]
    ShapeMismatch {
        /// Which argument.
        what: &'static str,
        /// The expected size or shape, in words.
        expected: String,
        /// The size or shape found.
        found: String,
    },
    /// A coordinate or parameter is NaN or infinite. The crate rejects non-finite input at every
    /// entry point instead of propagating NaN silently.
    #[error("{what}: value at index {index} is not finite ({value})")]
    NonFinite {
        /// Which argument.
        what: &'static str,
        /// Flat index (column-major, as Octave counts) of the first offending value.
        index: usize,
        /// The value itself.
        value: f64,
    },
    /// A derivative of order higher than the degree was asked for.
    #[error("derivative order {order} exceeds the degree {degree}")]
    DerivativeOrder {
        /// The order asked for.
        order: usize,
        /// The degree of the curve or patch direction.
        degree: usize,
    },
    /// A parameter list or sample grid is empty.
    #[error("{what}: expected at least {min} parameter value(s), got {found}")]
    EmptyGrid {
        /// Which argument.
        what: &'static str,
        /// The least number accepted.
        min: usize,
        /// The number given.
        found: usize,
    },
    /// An interval `[a, b]` with `a >= b`.
    #[error("{what}: interval [{a}, {b}] is empty (expected a < b)")]
    EmptyInterval {
        /// Which argument.
        what: &'static str,
        /// Left end.
        a: f64,
        /// Right end.
        b: f64,
    },
    /// A knot vector that decreases somewhere (knots must be non-decreasing).
    #[error("{what}: knot {index} ({next}) is below the knot before it ({previous}); knots must be non-decreasing")]
    DecreasingKnots {
        /// Which argument.
        what: &'static str,
        /// Index of the first knot smaller than its predecessor (so `index ≥ 1`).
        index: usize,
        /// The knot before it.
        previous: f64,
        /// The offending knot.
        next: f64,
    },
    /// A B-spline or NURBS of degree `p` needs at least `p + 1` control points (and exactly
    /// `n + p + 1` knots for `n` control points).
    #[error("{what}: degree {degree} needs at least {min} control point(s), got {found}")]
    TooFewControlPoints {
        /// Which argument.
        what: &'static str,
        /// The degree asked for.
        degree: usize,
        /// The least number of control points for that degree (`degree + 1`).
        min: usize,
        /// The number given.
        found: usize,
    },
    /// The knot vector has the wrong length for the degree and the number of control points.
    #[error("{what}: expected {expected} knots (control points + degree + 1), got {found}")]
    KnotCount {
        /// Which argument.
        what: &'static str,
        /// `n + p + 1`.
        expected: usize,
        /// The number given.
        found: usize,
    },
    /// A NURBS weight that is zero or negative (weights must be positive so that the curve
    /// stays in the convex hull of its control points and is defined everywhere).
    #[error("{what}: weight {index} is {value}; weights must be positive")]
    NonPositiveWeight {
        /// Which argument.
        what: &'static str,
        /// Index of the first offending weight (column-major for surfaces).
        index: usize,
        /// The weight.
        value: f64,
    },
    /// A parameter outside the domain `[min, max]` of a curve or surface (for a B-spline,
    /// `[u_p, u_{n+1}]` of its knot vector).
    #[error("{what}: parameter {value} is outside the domain [{min}, {max}]")]
    ParameterOutOfRange {
        /// Which argument.
        what: &'static str,
        /// The parameter.
        value: f64,
        /// Start of the domain.
        min: f64,
        /// End of the domain.
        max: f64,
    },
    /// A square system that has no unique solution (repeated interpolation parameters, a
    /// singular matrix to invert).
    #[error("{what}: the system is singular ({reason})")]
    Singular {
        /// Which argument.
        what: &'static str,
        /// Why, in words.
        reason: String,
    },
    /// Other invalid argument, with a sentence saying what was expected.
    #[error("{what}: {message}")]
    InvalidArgument {
        /// Which argument.
        what: &'static str,
        /// What was wrong and what was expected.
        message: String,
    },
}

/// Checks that every value is finite; reports the first one that is not.
pub(crate) fn check_finite<'a, T: Scalar>(
    what: &'static str,
    values: impl IntoIterator<Item = &'a T>,
) -> Result<()> {
    for (index, value) in values.into_iter().enumerate() {
        if !value.is_finite_value() {
            return Err(Error::NonFinite {
                what,
                index,
                value: value.to_f64(),
            });
        }
    }
    Ok(())
}

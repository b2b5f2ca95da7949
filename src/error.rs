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
    /// `[u_p, u_n]` of its knot vector): what every `try_eval` answers to a finite parameter
    /// outside the domain (see [`crate::param`]).
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
    /// A curve whose domain a construction cannot reparametrise onto `[0, 1]` (an infinite end,
    /// or a start not below the end): Coons, Gordon and ruled surfaces map each curve's domain
    /// `[a, b]` affinely onto `[0, 1]` (see [`crate::param`]).
    #[error("{what}: its domain [{start}, {end}] cannot be mapped onto [0, 1] (expected finite ends, start below end, a width within the range of doubles)")]
    UnusableDomain {
        /// Which curve.
        what: &'static str,
        /// Start of its domain.
        start: f64,
        /// End of its domain.
        end: f64,
    },
    /// A square system that has no unique solution (a singular matrix to invert, a zero
    /// pivot of a spline system). Repeated interpolation nodes are [`Error::DuplicateNodes`].
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
    /// The four boundary curves of a Coons patch (or their cross-boundary derivatives) do not
    /// meet at the corners: every corner whose two values differ by more than the tolerance is
    /// listed, with the gap.
    #[error("boundary curves do not meet at the corners ({tolerance}): {}", format_corner_gaps(.gaps))]
    CornerMismatch {
        /// One entry per disagreeing corner.
        gaps: Vec<crate::tolerance::CornerGap>,
        /// The tolerance the gaps were checked against.
        tolerance: crate::tolerance::Tolerance,
    },
    /// A Gordon curve network is not compatible: the curve `g(u_i, v)` at `v = v_j` is not the
    /// curve `g(u, v_j)` at `u = u_i`. The worst pair is reported, with the number of pairs
    /// over the tolerance.
    #[error(
        "curve network is not compatible ({tolerance}): g(u_{u_curve}, v) at v = {v} and g(u, v_{v_curve}) at u = {u} are {gap:e} apart (allowed {allowed:e}; {count} pair(s) over)"
    )]
    NetworkMismatch {
        /// Index `i` of the curve `g(u_i, v)`.
        u_curve: usize,
        /// Index `j` of the curve `g(u, v_j)`.
        v_curve: usize,
        /// The node `u_i`.
        u: f64,
        /// The node `v_j`.
        v: f64,
        /// The gap (largest coordinate difference).
        gap: f64,
        /// The largest gap the tolerance allows at this pair.
        allowed: f64,
        /// The tolerance the gaps were checked against.
        tolerance: crate::tolerance::Tolerance,
        /// How many pairs are over the tolerance.
        count: usize,
    },
    /// Two interpolation nodes coincide (Lagrange blending needs distinct nodes).
    #[error("{what}: nodes {first} and {second} are equal ({value})")]
    DuplicateNodes {
        /// Which node vector.
        what: &'static str,
        /// Index of the first of the two.
        first: usize,
        /// Index of the second.
        second: usize,
        /// The common value.
        value: f64,
    },
    /// Interpolation nodes are not in increasing order.
    #[error("{what}: nodes must increase, but node {index} ({value}) is above node {} ({next})", .index + 1)]
    UnsortedNodes {
        /// Which node vector.
        what: &'static str,
        /// Index `k` with `nodes[k] > nodes[k+1]`.
        index: usize,
        /// `nodes[k]`.
        value: f64,
        /// `nodes[k+1]`.
        next: f64,
    },
    /// A construction was given fewer curves than it needs.
    #[error("{what}: expected at least {min} curve(s), got {found}")]
    TooFewCurves {
        /// Which family of curves.
        what: &'static str,
        /// The least number accepted.
        min: usize,
        /// The number given.
        found: usize,
    },
    /// A blending function of a generalized Coons patch breaks one of its conditions
    /// (`f1 + f2 = 1`, `f1(0) = 1`, `f1(1) = 0`, likewise for `g1`, `g2`).
    #[error(
        "blending function {function}: {condition} fails at t = {t}: value {value}, expected {expected} (tolerance {tolerance:e})"
    )]
    BlendingCondition {
        /// The function or combination checked, e.g. `"f1 + f2"`.
        function: &'static str,
        /// The condition, e.g. `"partition of unity"`.
        condition: &'static str,
        /// The parameter where it fails.
        t: f64,
        /// The value found.
        value: f64,
        /// The value required.
        expected: f64,
        /// The tolerance used.
        tolerance: f64,
    },
    /// A discrete Coons mask `(α, β)` that is not affinely invariant: the weights of the eight
    /// neighbours must sum to one, `4α + 4β = 1`.
    #[error("mask (alpha = {alpha}, beta = {beta}): 4*alpha + 4*beta = {sum}, expected 1")]
    MaskNotAffine {
        /// The corner weight α.
        alpha: f64,
        /// The edge weight β.
        beta: f64,
        /// The value of `4α + 4β`.
        sum: f64,
    },
    /// The linear system of a discrete Coons mask is singular (or numerically singular) on the
    /// given net: some eigenvalue `1 − 2β(cos θ_p + cos φ_q) − 4α cos θ_p cos φ_q`,
    /// `θ_p = pπ/m`, `φ_q = qπ/n`, vanishes.
    #[error(
        "mask (alpha = {alpha}, beta = {beta}) is singular on a net of degree ({m}, {n}): eigenvalue {eigenvalue:e} for mode (p, q) = ({p}, {q})"
    )]
    SingularMask {
        /// The corner weight α.
        alpha: f64,
        /// The edge weight β.
        beta: f64,
        /// Degree of the net in the first direction (rows `0..=m`).
        m: usize,
        /// Degree of the net in the second direction (columns `0..=n`).
        n: usize,
        /// The mode `p` (1 ≤ p < m) of the smallest eigenvalue.
        p: usize,
        /// The mode `q` (1 ≤ q < n) of the smallest eigenvalue.
        q: usize,
        /// The smallest eigenvalue in absolute value (0 for an exactly singular system).
        eigenvalue: f64,
    },
    /// A value computed from finite input is not a finite double: a product or sum overflowed
    /// to ±∞, or a quotient by a difference that rounded to zero gave ±∞ or NaN (control points
    /// near ±1.7·10³⁰⁸, an interval `[−10³⁰⁸, 10³⁰⁸]` whose width overflows, knots or nodes
    /// 5·10⁻³²⁴ apart, weights all 10³⁰⁸). Every `Result`-returning function checks what it
    /// computes ([`check_overflow`]) instead of returning a non-finite value; exact values are
    /// converted to doubles the same way ([`crate::exact::to_finite_f64`]). `what` names the
    /// quantity, `index` its first non-finite entry (column-major, as Octave counts).
    #[error(
        "{what}: value at index {index} is not a finite double ({value}): the input's magnitudes are too large (or too close together) for double precision"
    )]
    Overflow {
        /// Which computed quantity.
        what: &'static str,
        /// Flat index of the first offending value.
        index: usize,
        /// The value computed (±∞ or NaN).
        value: f64,
    },
    /// A size that would need more memory or time than the [`crate::limits::Limits`] passed
    /// allow (a grid, a degree, a linear system, an input): refused before anything is
    /// allocated.
    #[error("{what}: {requested} exceeds the limit of {limit} ({which})")]
    TooLarge {
        /// Which argument.
        what: &'static str,
        /// The size asked for (grid points, degree, entries, bytes).
        requested: u128,
        /// The limit in force.
        limit: u128,
        /// Which limit: the command line names its flag and environment variable.
        which: Limit,
    },
}

/// One of the resource limits, as [`Error::TooLarge`] names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Limit {
    /// [`crate::limits::Limits::max_input_bytes`].
    InputBytes,
    /// [`crate::limits::Limits::max_expression_bytes`].
    ExpressionBytes,
    /// [`crate::limits::Limits::max_depth`].
    Depth,
    /// [`crate::limits::Limits::max_elements`].
    Elements,
    /// [`crate::limits::Limits::max_iterations`].
    Iterations,
    /// [`crate::limits::Limits::max_samples`].
    Samples,
    /// [`crate::limits::Limits::max_grid_points`].
    GridPoints,
    /// [`crate::limits::Limits::max_degree`].
    Degree,
    /// [`crate::limits::Limits::max_system_entries`].
    SystemEntries,
    /// [`crate::limits::Limits::max_work`].
    Work,
}

impl Limit {
    /// Every limit, in the field order of [`crate::limits::Limits`].
    pub const ALL: [Limit; 10] = [
        Limit::InputBytes,
        Limit::ExpressionBytes,
        Limit::Depth,
        Limit::Elements,
        Limit::Iterations,
        Limit::Samples,
        Limit::GridPoints,
        Limit::Degree,
        Limit::SystemEntries,
        Limit::Work,
    ];

    /// The name of the field of [`crate::limits::Limits`] that holds it, e.g. `max_grid_points`.
    pub fn field(self) -> &'static str {
        match self {
            Limit::InputBytes => "max_input_bytes",
            Limit::ExpressionBytes => "max_expression_bytes",
            Limit::Depth => "max_depth",
            Limit::Elements => "max_elements",
            Limit::Iterations => "max_iterations",
            Limit::Samples => "max_samples",
            Limit::GridPoints => "max_grid_points",
            Limit::Degree => "max_degree",
            Limit::SystemEntries => "max_system_entries",
            Limit::Work => "max_work",
        }
    }
}

impl std::fmt::Display for Limit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Limits::{}", self.field())
    }
}

/// One line per corner gap, for the message of [`Error::CornerMismatch`].
fn format_corner_gaps(gaps: &[crate::tolerance::CornerGap]) -> String {
    gaps.iter()
        .map(|g| g.to_string())
        .collect::<Vec<_>>()
        .join("; ")
}

/// Rejects a negative or non-finite tolerance.
///
/// # Errors
/// [`Error::InvalidArgument`] naming the tolerance.
///
/// ```
/// use cagd::Tolerance;
/// assert!(cagd::error::check_tolerance(&Tolerance::Relative(1e-10)).is_ok());
/// assert!(cagd::error::check_tolerance(&Tolerance::Absolute(-1.0)).is_err());
/// ```
pub fn check_tolerance(tolerance: &crate::tolerance::Tolerance) -> Result<()> {
    match tolerance {
        crate::tolerance::Tolerance::Relative(t) | crate::tolerance::Tolerance::Absolute(t)
            if !tolerance.is_valid() =>
        {
            Err(Error::InvalidArgument {
                what: "tolerance",
                message: format!("expected a finite value >= 0, got {t}"),
            })
        }
        _ => Ok(()),
    }
}

/// Checks that every value is finite; reports the first one that is not.
///
/// # Errors
/// [`Error::NonFinite`] naming `what`, the index and the value of the first non-finite value.
///
/// ```
/// use cagd::error::{check_finite, Error};
/// assert!(check_finite("points", &[1.0, 2.0]).is_ok());
/// let err = check_finite("points", &[1.0, f64::NAN]).unwrap_err();
/// assert!(matches!(err, Error::NonFinite { what: "points", index: 1, .. }));
/// ```
pub fn check_finite<'a, T: Scalar>(
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

/// [`check_finite`] for a slice, the same error; a list of parameters of a batch is checked a
/// block of values at a time ([`Scalar::first_non_finite`]).
///
/// # Errors
/// [`Error::NonFinite`] naming `what` and the first NaN or infinite value.
pub fn check_finite_slice<T: Scalar>(what: &'static str, values: &[T]) -> Result<()> {
    if T::first_non_finite(values).is_none() {
        return Ok(());
    }
    // The error as check_finite words it (the scan again, only on the way out).
    check_finite(what, values)
}

/// Checks that every value a computation produced is finite; reports the first one that is not.
///
/// The one check behind the crate's promise "finite in, finite out": a value computed in `f64`
/// from finite input can still overflow (`1.7e308 + 1.7e308`), or divide by a difference that
/// rounded to zero (`0/0`), and every `Result`-returning function runs its results through
/// this before it returns `Ok` (for exact rationals every value is finite and the check costs
/// one comparison per value).
///
/// # Errors
/// [`Error::Overflow`] naming `what`, the index and the value of the first non-finite value.
///
/// ```
/// use cagd::error::{check_overflow, Error};
/// assert!(check_overflow("sum", &[1.0, 2.0]).is_ok());
/// let big = f64::MAX;
/// let err = check_overflow("sum", &[1.0, big + big]).unwrap_err();
/// assert!(matches!(err, Error::Overflow { what: "sum", index: 1, .. }));
/// ```
pub fn check_overflow<'a, T: Scalar>(
    what: &'static str,
    values: impl IntoIterator<Item = &'a T>,
) -> Result<()> {
    if T::EXACT {
        return Ok(());
    }
    for (index, value) in values.into_iter().enumerate() {
        if !value.is_finite_value() {
            return Err(Error::Overflow {
                what,
                index,
                value: value.to_f64(),
            });
        }
    }
    Ok(())
}

/// `value` if all its entries are finite ([`check_overflow`]): the last step of the evaluations
/// that return a point.
///
/// # Errors
/// [`Error::Overflow`] naming `what`.
pub(crate) fn finite<T: Scalar, V>(what: &'static str, value: V) -> Result<V>
where
    for<'a> &'a V: IntoIterator<Item = &'a T>,
{
    check_overflow(what, &value)?;
    Ok(value)
}

/// Checks increasing values that a construction divides differences of (knots, nodes, the
/// parameters of a spline or a sampled curve): the whole range `last − first` must be a finite
/// double, and every gap between two different values must have a finite reciprocal (a gap of
/// 5·10⁻³²⁴ has none). Values out of order are left to the caller's own check.
///
/// # Errors
/// [`Error::Overflow`] naming `what`: at the last index for a range that overflows (values
/// from −10³⁰⁸ to 10³⁰⁸), at the upper value of a gap whose reciprocal overflows.
///
/// ```
/// use cagd::error::{check_spacing, Error};
/// assert!(check_spacing("knots", &[0.0, 0.0, 0.5, 1.0]).is_ok());
/// let err = check_spacing("knots", &[0.0, 0.0, 5e-324, 1.0]).unwrap_err();
/// assert!(matches!(err, Error::Overflow { what: "knots", index: 2, .. }));
/// assert!(check_spacing("knots", &[-1e308, 0.0, 1e308]).is_err());
/// ```
pub fn check_spacing<T: Scalar>(what: &'static str, values: &[T]) -> Result<()> {
    if T::EXACT || values.len() < 2 {
        return Ok(());
    }
    let last = values.len() - 1;
    let range = values[last].clone() - values[0].clone();
    if !range.is_finite_value() {
        return Err(Error::Overflow {
            what,
            index: last,
            value: range.to_f64(),
        });
    }
    for (k, w) in values.windows(2).enumerate() {
        let gap = w[1].clone() - w[0].clone();
        if !gap.is_zero() {
            let reciprocal = T::one() / gap;
            if !reciprocal.is_finite_value() {
                return Err(Error::Overflow {
                    what,
                    index: k + 1,
                    value: reciprocal.to_f64(),
                });
            }
        }
    }
    Ok(())
}

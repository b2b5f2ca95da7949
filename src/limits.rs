//! Resource limits: sizes that would need more memory (or time) than a machine has are refused
//! up front with [`Error::TooLarge`], never left to an out-of-memory kill.
//!
//! | [`Limit`] | field | default | guards |
//! |---|---|---|---|
//! | `InputBytes` | [`max_input_bytes`](Limits::max_input_bytes) | 64 MiB | an input file or standard input |
//! | `ExpressionBytes` | [`max_expression_bytes`](Limits::max_expression_bytes) | 1 MiB | a literal, expression or data script |
//! | `Depth` | [`max_depth`](Limits::max_depth) | 64 | nesting of brackets, calls, unary operators, loops |
//! | `Elements` | [`max_elements`](Limits::max_elements) | 4 000 000 | elements of a matrix or range built by a literal or script; every length of an array read from a `save -text` file |
//! | `Iterations` | [`max_iterations`](Limits::max_iterations) | 1 000 000 | loop iterations of a data script |
//! | `Samples` | [`max_samples`](Limits::max_samples) | 1 000 000 | parameter values along one axis |
//! | `GridPoints` | [`max_grid_points`](Limits::max_grid_points) | 10 000 000 | points of a surface grid (`nu · nv`) |
//! | `Degree` | [`max_degree`](Limits::max_degree) | 1 000 | degree of a Bernstein basis, Bézier curve or patch direction, B-spline, Lagrange basis (nodes − 1), curves of a Gordon network |
//! | `SystemEntries` | [`max_system_entries`](Limits::max_system_entries) | 100 000 000 | stored entries of a linear system (the banded system of a discrete Coons mask) |
//! | `Work` | [`max_work`](Limits::max_work) | 2 000 000 000 | arithmetic operations of one computation, estimated before it starts (points × cost per point: `(n+1)²` for de Casteljau, the band solve of a mask, and for a user expression its size in nodes at every sample); in exact arithmetic each operation weighs [`exact_op_cost`] of the size its numbers reach |
//!
//! **Values, not globals.** A [`Limits`] is a plain value passed to the functions that need
//! it (the discrete Coons mask, the Octave layer's parsers and readers, the command line); no
//! library code reads a process-wide setting, so a result never depends on what other code in
//! the process did. [`Error::TooLarge`] names the [`Limit`] it hit; the command line maps it to
//! its flag and environment variable.
//!
//! Why these numbers (a machine with 24 GiB shared by other work): a grid point of a 3-D
//! surface costs 24 bytes in `f64`, and a command keeps up to about eight copies of it (the
//! grid, the three Coons or Gordon terms for `--steps`, the copy in doubles for pictures and
//! meshes, and the formatted text at up to 25 bytes per number), about 200 bytes per point:
//! 10⁷ points stay near 2 GB. Exact rationals cost several times more per number and are
//! also far slower, so an exact grid of 10⁷ points is allowed but slow. A de Casteljau scheme
//! of degree `n` holds `(n+1)(n+2)/2` points per parameter, and evaluation costs `O(n²)` per
//! point: degree 1000 keeps both at about half a million. 10⁸ system entries are 800 MB in
//! `f64`.
//!
//! A user expression (a curve or surface written as in the thesis, `[u; 0; u-u^2]`, or one
//! computed by a data script) is evaluated once per sample, and one evaluation does about
//! one operation per node of its tree (the Octave layer's `ParamExpr::node_count`): the
//! estimate charges samples × nodes before any sample is taken, so a long expression at many
//! samples (100 KB of text at 10⁶ samples is 5·10¹⁰ node evaluations) is refused at once.
//!
//! Two budgets derive from `max_elements`: one evaluation of an expression may do at most
//! 64 × `max_elements` element operations (results of every operation and matrix-product
//! terms; in exact arithmetic an operation on numbers of `a` and `b` 64-bit words counts as
//! `32 (a + b)²`, the cost of the gcd behind it), and a data script may assign elements and do
//! element operations at most 25 × `max_elements` in all, every evaluation counting; so a
//! short text (`A*A*A*…`, a loop rebuilding a large matrix) stops with an error instead of
//! running for minutes.
//!
//! **Exact arithmetic.** An operation on rationals costs far more than on doubles, and the
//! numbers grow as a construction proceeds: a Bernstein value of degree `n` at `t = p/q` has a
//! denominator `qⁿ`, the tridiagonal solve of an interpolating spline through `N` points
//! builds continuants of about `4N` bits. So with `--exact` the command line weighs every
//! operation of its estimate by [`exact_op_cost`] of the size (in bits, numerator and
//! denominator together) the numbers reach: the inputs' sizes, and the growth of the
//! construction (`n · bits(t)` for degree `n` at `t`, `4N` for a spline through `N` points,
//! and for a user expression the size of its value and the work of one evaluation at the
//! largest parameter, measured before sampling). Found by fuzzing: an exact spline through
//! 2 223 points (2 s, and 6 s through 1 000 points of random digits) and exact Bernstein
//! values of degree 95 passed the operation count alone; degree 1 000 would have run for
//! minutes.
//!
//! **Bounded work in the library itself.** Every function of the crate that can fail checks,
//! before it starts, whatever would make its work or memory grow faster than the data it was
//! given — one rule, applied against the `Limits` value the function takes (as
//! [`solve_mask`](crate::coons::solve_mask) does) or, for every function without one, against
//! the documented defaults [`Limits::DEFAULT`]:
//!
//! - **a count, degree or exponent given as a number** — the `r` of
//!   [`BSplineCurve::elevate`](crate::BSplineCurve::elevate), the `n` of
//!   [`bezier_to_monomial_matrix`](crate::conversion::bezier_to_monomial_matrix) and
//!   [`bernstein::elevate`](crate::bernstein::elevate), the exponent of
//!   [`rational_from_decimal`](crate::exact::rational_from_decimal), the samples of
//!   [`Lagrange::lebesgue_constant`](crate::lagrange::Lagrange::lebesgue_constant) — against
//!   `max_degree`, `max_samples` or `max_expression_bytes`, and memory sized by such a number
//!   is reserved with `try_reserve` ([`Error::TooLarge`] if it cannot be);
//! - **the work of one result** — one point of a curve or surface (de Casteljau's `d (n+1)²`,
//!   a B-spline's `(p+1)²`), one basis, one inverse (`n³`), one set of Lagrange weights
//!   (`(m+1)²`), the Cox–de Boor recursion's `2^(p+1)` calls, a degree elevation — estimated by
//!   the construction's own `*_cost` function ([`crate::cost`]), weighed by the size of the
//!   numbers in exact arithmetic ([`Cost::weigh`](crate::cost::Cost::weigh)), against
//!   `max_work`: `try_eval` of a degree-100 000 Bézier curve (10¹⁰ operations per point) is
//!   refused at once, a cubic's is not looked at twice.
//!
//! The total of a batch — many points, a large grid, an exact spline through many points — is
//! linear in what the caller asks for: the command line, the Octave package and the page
//! estimate it with the same `*_cost` functions against their own `Limits` (raised with
//! `--max-work` and friends) before they call the library. Functions that cannot fail
//! (`eval`, `linspace`, the Bernstein bases) cannot refuse: each documents in `# Panics` what
//! it cannot hold (it panics naming the size, never aborts: its memory is reserved with
//! `try_reserve`) and has a fallible twin (`try_linspace`,
//! [`PointGrid::try_from_elem`](crate::grid::PointGrid::try_from_elem),
//! [`try_cox_de_boor_triangle`](crate::bspline::try_cox_de_boor_triangle)) where a front end
//! passes a user's number.
//!
//! ```
//! use cagd::limits::Limits;
//! let limits = Limits { max_grid_points: 100, ..Limits::default() };
//! let err = limits.check_grid("--u/--v", 20, 20).unwrap_err();
//! assert!(matches!(
//!     err,
//!     cagd::Error::TooLarge { requested: 400, limit: 100, which: cagd::limits::Limit::GridPoints, .. }
//! ));
//! assert!(limits.check_grid("--u/--v", 10, 10).is_ok());
//! ```

pub use crate::error::Limit;
use crate::error::{Error, Result};

/// The resource limits (see the [module documentation](self) for the defaults and why).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Largest input file (or standard input) read, in bytes.
    pub max_input_bytes: u64,
    /// Longest literal, expression or data script parsed, in bytes.
    pub max_expression_bytes: usize,
    /// Deepest nesting of parentheses, brackets, call arguments, unary operators and loops.
    pub max_depth: usize,
    /// Most elements of any matrix or range built while evaluating a literal or script.
    pub max_elements: usize,
    /// Most loop iterations a data script may run, all loops together.
    pub max_iterations: usize,
    /// Most parameter values along one axis.
    pub max_samples: usize,
    /// Most points of a surface grid.
    pub max_grid_points: usize,
    /// Highest degree of a basis, curve or patch direction; most curves of a network − 1.
    pub max_degree: usize,
    /// Most stored entries of a linear system.
    pub max_system_entries: usize,
    /// Most arithmetic operations of one command, estimated up front (about 2–20 seconds in
    /// `f64`; exact rationals are slower).
    pub max_work: u64,
}

impl Default for Limits {
    /// [`Limits::DEFAULT`].
    fn default() -> Self {
        Limits::DEFAULT
    }
}

fn to_usize(x: u64) -> usize {
    usize::try_from(x).unwrap_or(usize::MAX)
}

impl Limits {
    /// The defaults (see the [module documentation](self) for why these numbers): what
    /// `Limits::default()` gives, and what every function of the crate that takes no `Limits`
    /// argument checks against.
    pub const DEFAULT: Limits = Limits {
        max_input_bytes: 64 << 20,
        max_expression_bytes: 1 << 20,
        max_depth: 64,
        max_elements: 4_000_000,
        max_iterations: 1_000_000,
        max_samples: 1_000_000,
        max_grid_points: 10_000_000,
        max_degree: 1000,
        max_system_entries: 100_000_000,
        max_work: 2_000_000_000,
    };

    /// The value of one limit.
    ///
    /// ```
    /// use cagd::limits::{Limit, Limits};
    /// assert_eq!(Limits::default().get(Limit::Degree), 1000);
    /// ```
    pub fn get(&self, limit: Limit) -> u64 {
        match limit {
            Limit::InputBytes => self.max_input_bytes,
            Limit::ExpressionBytes => self.max_expression_bytes as u64,
            Limit::Depth => self.max_depth as u64,
            Limit::Elements => self.max_elements as u64,
            Limit::Iterations => self.max_iterations as u64,
            Limit::Samples => self.max_samples as u64,
            Limit::GridPoints => self.max_grid_points as u64,
            Limit::Degree => self.max_degree as u64,
            Limit::SystemEntries => self.max_system_entries as u64,
            Limit::Work => self.max_work,
        }
    }

    /// Sets one limit (values above `usize::MAX` saturate).
    ///
    /// ```
    /// use cagd::limits::{Limit, Limits};
    /// let mut limits = Limits::default();
    /// limits.set(Limit::GridPoints, 100);
    /// assert_eq!(limits.max_grid_points, 100);
    /// ```
    pub fn set(&mut self, limit: Limit, value: u64) {
        match limit {
            Limit::InputBytes => self.max_input_bytes = value,
            Limit::ExpressionBytes => self.max_expression_bytes = to_usize(value),
            Limit::Depth => self.max_depth = to_usize(value),
            Limit::Elements => self.max_elements = to_usize(value),
            Limit::Iterations => self.max_iterations = to_usize(value),
            Limit::Samples => self.max_samples = to_usize(value),
            Limit::GridPoints => self.max_grid_points = to_usize(value),
            Limit::Degree => self.max_degree = to_usize(value),
            Limit::SystemEntries => self.max_system_entries = to_usize(value),
            Limit::Work => self.max_work = value,
        }
    }

    /// `count` parameter values along one axis.
    ///
    /// # Errors
    /// [`Error::TooLarge`] above [`Limits::max_samples`].
    pub fn check_samples(&self, what: &'static str, count: usize) -> Result<()> {
        too_large(what, Limit::Samples, count as u128, self.max_samples)
    }

    /// A grid of `nu × nv` points.
    ///
    /// # Errors
    /// [`Error::TooLarge`] above [`Limits::max_grid_points`].
    pub fn check_grid(&self, what: &'static str, nu: usize, nv: usize) -> Result<()> {
        too_large(
            what,
            Limit::GridPoints,
            nu as u128 * nv as u128,
            self.max_grid_points,
        )
    }

    /// A basis, curve or patch direction of degree `degree`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] above [`Limits::max_degree`].
    pub fn check_degree(&self, what: &'static str, degree: usize) -> Result<()> {
        too_large(what, Limit::Degree, degree as u128, self.max_degree)
    }

    /// A computation of about `operations` arithmetic operations.
    ///
    /// # Errors
    /// [`Error::TooLarge`] above [`Limits::max_work`].
    pub fn check_work(&self, what: &'static str, operations: u128) -> Result<()> {
        too_large(
            what,
            Limit::Work,
            operations,
            usize::try_from(self.max_work).unwrap_or(usize::MAX),
        )
    }

    /// A linear system storing `entries` numbers.
    ///
    /// # Errors
    /// [`Error::TooLarge`] above [`Limits::max_system_entries`].
    pub fn check_system(&self, what: &'static str, entries: u128) -> Result<()> {
        too_large(what, Limit::SystemEntries, entries, self.max_system_entries)
    }
}

/// What one exact rational operation on numbers of about `bits` bits (numerator and
/// denominator together) is charged against [`Limits::max_work`], in units of one `f64`
/// operation (about a nanosecond): `1000·w + 16·w²` with `w = ⌈bits/64⌉ ≥ 1` words.
///
/// Measured in a release build (num-rational, x86-64), sums and products of reduced
/// fractions whose numerators and denominators are products of random factors: 1.2–1.9 µs at
/// one word, 13–18 µs at 8 words, 29–34 µs at 16, 129–159 µs at 64 and 330–410 µs at 128
/// words — the gcd that keeps every result reduced grows about linearly in the length here and
/// faster beyond. Numbers with small prime factors only (powers of `1/100`, continuants) and
/// the zeros, ones and integers of typical data are several times cheaper. Checked against
/// whole commands (`bench/exact_work.sh`, table in docs/PERFORMANCE.md): the estimates lie
/// between about 0.6 and 10 times the run time in nanoseconds (70 times for a spline through
/// collinear integers), so an allowed command runs for seconds, not minutes.
///
/// ```
/// use cagd::limits::exact_op_cost;
/// assert_eq!(exact_op_cost(0), 1016);
/// assert_eq!(exact_op_cost(64), 1016);
/// assert_eq!(exact_op_cost(65), 2064);
/// assert_eq!(exact_op_cost(64 * 64), 1000 * 64 + 16 * 64 * 64);
/// ```
pub fn exact_op_cost(bits: u128) -> u128 {
    let w = bits.div_ceil(64).max(1);
    w.saturating_mul(1000)
        .saturating_add(w.saturating_mul(w).saturating_mul(16))
}

fn too_large(what: &'static str, which: Limit, requested: u128, limit: usize) -> Result<()> {
    if requested > limit as u128 {
        return Err(Error::TooLarge {
            what,
            requested,
            limit: limit as u128,
            which,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn get_and_set_every_limit() {
        let mut l = Limits::default();
        for (k, limit) in Limit::ALL.into_iter().enumerate() {
            l.set(limit, 5 + k as u64);
        }
        for (k, limit) in Limit::ALL.into_iter().enumerate() {
            assert_eq!(l.get(limit), 5 + k as u64, "{limit}");
        }
        assert_eq!((l.max_grid_points, l.max_degree, l.max_depth), (11, 12, 7));
    }

    #[test]
    fn grid_product_does_not_overflow() {
        let err = Limits::default()
            .check_grid("g", usize::MAX, usize::MAX)
            .unwrap_err();
        assert!(matches!(
            err,
            Error::TooLarge {
                limit: 10_000_000,
                ..
            }
        ));
    }
}

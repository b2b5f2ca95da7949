//! Likely slips of the hand, answered with a warning instead of a silent wrong answer.
//!
//! Each check knows a way the course's notation and the command line's can differ, and says
//! how the input was read and which flag changes the reading:
//! - [`point_matrix`]: points typed as rows (as the matrix-form and lecture notes write them)
//!   but read as columns, or the other way round — a matrix with more rows than columns, or
//!   points of dimension above 3;
//! - [`decimal_commas`]: `--t "[0,2 0,4]"` is t = 0, 2, 0, 4 (a comma separates elements), not
//!   the decimals 0,2 and 0,4 the sources write (and `--t 0,5` is 0 and 5);
//! - [`outside`]: parameters outside the domain of a construction (the curve is extrapolated
//!   there).
//!
//! Warnings are collected while a command runs ([`warn`]) and handed out with its result
//! ([`take`]), each distinct warning once.

use std::cell::RefCell;

use cagd_octave::literal::{LiteralScalar, Position, Warning};
use nalgebra::DMatrix;

thread_local! {
    static PENDING: RefCell<Vec<(String, Warning)>> = const { RefCell::new(Vec::new()) };
}

/// Records a warning about `argument` (printed as `cagd: warning: ARGUMENT: MESSAGE`).
pub fn warn(argument: impl Into<String>, message: impl Into<String>) {
    let warning = Warning {
        at: Position::default(),
        message: message.into(),
    };
    PENDING.with(|p| p.borrow_mut().push((argument.into(), warning)));
}

/// The warnings recorded since the last call, in order, each distinct one once.
pub fn take() -> Vec<(String, Warning)> {
    PENDING.with(|p| dedup(std::mem::take(&mut *p.borrow_mut())))
}

/// `warnings` without repeats (the first of equal ones stays, in order).
pub fn dedup(warnings: Vec<(String, Warning)>) -> Vec<(String, Warning)> {
    let mut out: Vec<(String, Warning)> = Vec::with_capacity(warnings.len());
    for w in warnings {
        if !out.contains(&w) {
            out.push(w);
        }
    }
    out
}

/// Warns when a matrix of points, as typed, is implausible in the orientation it is read in:
/// read as columns (`rows` false), a matrix with more rows than columns (but more than one
/// column) or more than 3 rows; read as rows, the same of its transpose. The warning says how it was read and names
/// `--rows`.
///
/// ```
/// use nalgebra::DMatrix;
/// cagd_cli::slips::take();
/// cagd_cli::slips::point_matrix("CONTROL", &DMatrix::<f64>::zeros(4, 2), false);
/// let w = cagd_cli::slips::take();
/// assert!(w[0].1.message.contains("--rows"), "{}", w[0].1.message);
/// cagd_cli::slips::point_matrix("CONTROL", &DMatrix::<f64>::zeros(2, 4), false);
/// assert!(cagd_cli::slips::take().is_empty());
/// ```
pub fn point_matrix<T: LiteralScalar>(argument: &str, typed: &DMatrix<T>, rows: bool) {
    let (r, c) = typed.shape();
    let (dim, count) = if rows { (c, r) } else { (r, c) };
    // One point written as a column (or, with --rows, as a row) is the natural way to write
    // it; only its dimension can be implausible.
    if dim <= 3 && (dim <= count || count == 1) {
        return;
    }
    let why = if dim > 3 {
        format!("points of dimension {dim}")
    } else {
        format!("fewer points ({count}) than coordinates ({dim})")
    };
    let message = if rows {
        format!(
            "read as {count} point(s) in {dim} dimensions, one per row (--rows): {why}; if the points are the columns, leave out --rows"
        )
    } else {
        format!(
            "read as {count} point(s) in {dim} dimensions, one per column: {why}; if the points are the rows (as the notes write them), add --rows"
        )
    };
    warn(argument, message);
}

/// Warns when a list looks as if written with decimal commas, as the sources write decimals:
/// a comma with a digit right before and right after it, which Octave — and so the command
/// line — reads as two elements, in a list whose elements are otherwise separated by spaces
/// or semicolons (`[0,2 0,4]`), or a lone `0,5`. A list separated by commas only
/// (`[0,0,0,1,1,1]`) is read as written, silently. The warning says what was read and how to
/// write a decimal.
///
/// ```
/// cagd_cli::slips::take();
/// cagd_cli::slips::decimal_commas("--t", "[0,2 0,4]");
/// let w = cagd_cli::slips::take();
/// assert!(w[0].1.message.contains("0.2"), "{}", w[0].1.message);
/// cagd_cli::slips::decimal_commas("--t", "0,5");
/// assert_eq!(cagd_cli::slips::take().len(), 1);
/// for fine in ["[0, 0.5, 1]", "0:0.2:1", "[0,0,0,1,1,1]", "[0.2 0.4]"] {
///     cagd_cli::slips::decimal_commas("--knots", fine);
/// }
/// assert!(cagd_cli::slips::take().is_empty());
/// ```
pub fn decimal_commas(argument: &str, text: &str) {
    let trimmed = text.trim();
    let inner = trimmed.trim_start_matches('[').trim_end_matches(']');
    let elements = inner
        .split(|c: char| c.is_whitespace() || c == ';')
        .filter(|t| !t.is_empty())
        .count();
    let lone = !trimmed.starts_with('[') && elements == 1 && inner.matches(',').count() == 1;
    if elements < 2 && !lone {
        return;
    }
    let chars: Vec<char> = text.chars().collect();
    let Some(k) = (1..chars.len().saturating_sub(1)).find(|&k| {
        chars[k] == ',' && chars[k - 1].is_ascii_digit() && chars[k + 1].is_ascii_digit()
    }) else {
        return;
    };
    let start = chars[..k]
        .iter()
        .rposition(|c| !(c.is_ascii_digit() || *c == '.'))
        .map_or(0, |p| p + 1);
    let end = chars[k + 1..]
        .iter()
        .position(|c| !c.is_ascii_digit())
        .map_or(chars.len(), |p| k + 1 + p);
    let (before, after): (String, String) = (
        chars[start..k].iter().collect(),
        chars[k + 1..end].iter().collect(),
    );
    warn(
        argument,
        format!(
            "`{before},{after}` is read as two values, {before} and {after} (a comma separates values); for the decimal number write {before}.{after}"
        ),
    );
}

/// Warns when some of `values` lie outside `[lo, hi]`, the domain of the construction;
/// `consequence` says what happens there ("the curve is extrapolated").
///
/// ```
/// cagd_cli::slips::take();
/// cagd_cli::slips::outside("--t", &[0.0, 2.0], &0.0, &1.0, "the curve is extrapolated");
/// let w = cagd_cli::slips::take();
/// assert_eq!(w[0].1.message, "t = 2 lies outside [0, 1]; the curve is extrapolated");
/// ```
pub fn outside<T: LiteralScalar>(argument: &str, values: &[T], lo: &T, hi: &T, consequence: &str) {
    let out: Vec<&T> = values.iter().filter(|x| *x < lo || *x > hi).collect();
    let Some(first) = out.first() else {
        return;
    };
    let name = argument.trim_start_matches('-');
    let what = if out.len() == 1 {
        format!("{name} = {} lies", crate::number_text(*first))
    } else {
        format!(
            "{} values lie (the first {name} = {})",
            out.len(),
            crate::number_text(*first)
        )
    };
    warn(
        argument,
        format!(
            "{what} outside [{}, {}]; {consequence}",
            crate::number_text(lo),
            crate::number_text(hi)
        ),
    );
}

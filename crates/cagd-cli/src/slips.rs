//! Likely slips of the hand, answered with a warning instead of a silent wrong answer.
//!
//! Each check knows a way the course's notation and the command line's can differ, and says
//! how the input was read and which flag changes the reading:
//! - [`point_matrix`]: points typed as rows (as the notes write them) but read as columns, or
//!   the other way round — a note whenever both readings are plausible, a warning when the
//!   reading gives points of dimension above 3;
//! - [`decimal_commas`]: `--t "[0,2 0,4]"` is t = 0, 2, 0, 4 (a comma separates elements), not
//!   the decimals 0,2 and 0,4 the sources write (and `0,5` is 0 and 5), in every list, matrix
//!   and numeric file;
//! - [`outside`]: parameters outside the domain of a construction (the curve is extrapolated
//!   there).
//!
//! Warnings are collected while a command runs ([`warn`]) and handed out with its result
//! ([`take`]), each distinct warning once; an error of the command adds how its points and
//! numbers were read ([`explain`]).

use std::cell::RefCell;

use cagd_octave::literal::{LiteralScalar, Position, Warning};
use nalgebra::DMatrix;

/// What one command noticed while reading its input.
#[derive(Default)]
struct Pending {
    /// The warnings, with their argument.
    warnings: Vec<(String, Warning)>,
    /// Whether the orientation of points was stated (`--rows` or `--columns`).
    stated: bool,
    /// How each matrix of points was read, by argument.
    readings: Vec<(String, Reading)>,
    /// The decimal-comma warnings, by argument.
    commas: Vec<(String, String)>,
}

thread_local! {
    static PENDING: RefCell<Pending> = RefCell::new(Pending::default());
}

/// Starts a command: forgets what the last one noticed; `stated` says whether the
/// orientation of points was stated (`--rows` or `--columns`), which silences the note of
/// [`point_matrix`].
pub fn begin(stated: bool) {
    PENDING.with(|p| {
        *p.borrow_mut() = Pending {
            stated,
            ..Pending::default()
        }
    });
}

/// Records a warning about `argument` (printed as `cagd: warning: ARGUMENT: MESSAGE`).
pub fn warn(argument: impl Into<String>, message: impl Into<String>) {
    let warning = Warning {
        at: Position::default(),
        message: message.into(),
    };
    PENDING.with(|p| p.borrow_mut().warnings.push((argument.into(), warning)));
}

/// The warnings recorded since the last call, in order, each distinct one once.
pub fn take() -> Vec<(String, Warning)> {
    PENDING.with(|p| dedup(std::mem::take(&mut p.borrow_mut().warnings)))
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

/// How a matrix of points was read: `count` points in `dim`-D, one per column or (with
/// `--rows`) one per row, with the flag that flips the reading.
///
/// ```
/// let r = cagd_cli::slips::Reading { count: 3, dim: 2, rows: false };
/// assert_eq!(r.to_string(), "read as 3 points in 2-D, one per column; --rows if each row is a point");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Reading {
    /// The number of points.
    pub count: usize,
    /// Their dimension.
    pub dim: usize,
    /// Whether each row is a point (`--rows`).
    pub rows: bool,
}

impl std::fmt::Display for Reading {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (count, dim) = (self.count, self.dim);
        let points = if count == 1 { "point" } else { "points" };
        if self.rows {
            write!(
                f,
                "read as {count} {points} in {dim}-D, one per row (--rows); leave out --rows if each column is a point"
            )
        } else {
            write!(
                f,
                "read as {count} {points} in {dim}-D, one per column; --rows if each row is a point"
            )
        }
    }
}

/// Notes how a matrix of points was read, unless only one reading of its shape is plausible
/// or the orientation was stated (`--rows` or `--columns`, see [`begin`]): points are of
/// dimension 1 to 3, so a matrix with both sizes at most 3 (and neither 1) reads either way
/// and gets the note; a matrix whose reading gives points of dimension above 3 gets it as a
/// warning, also with `--rows`. A literal transposed as a whole states the reading too
/// ([`point_matrix_text`]). One point written as a column (or a row with `--rows`) and a
/// row of numbers (points in 1-D) read as typed, silently. The reading is remembered for
/// the errors about these points ([`explain`]).
///
/// ```
/// use nalgebra::DMatrix;
/// cagd_cli::slips::begin(false);
/// cagd_cli::slips::point_matrix("CONTROL", &DMatrix::<f64>::zeros(4, 2), false);
/// let w = cagd_cli::slips::take();
/// assert!(w[0].1.message.contains("--rows"), "{}", w[0].1.message);
/// cagd_cli::slips::point_matrix("CONTROL", &DMatrix::<f64>::zeros(3, 3), false);
/// assert_eq!(cagd_cli::slips::take()[0].1.message, "read as 3 points in 3-D, one per column; --rows if each row is a point");
/// cagd_cli::slips::point_matrix("CONTROL", &DMatrix::<f64>::zeros(2, 4), false);
/// assert!(cagd_cli::slips::take().is_empty());
/// cagd_cli::slips::begin(true); // --columns or --rows
/// cagd_cli::slips::point_matrix("CONTROL", &DMatrix::<f64>::zeros(3, 3), false);
/// assert!(cagd_cli::slips::take().is_empty());
/// ```
pub fn point_matrix<T: LiteralScalar>(argument: &str, typed: &DMatrix<T>, rows: bool) {
    point_matrix_typed(argument, typed, rows, false);
}

/// [`point_matrix`] of a matrix typed as `text`: a literal transposed as a whole
/// (`"[0 0; 1 2; 3 0]'"`, the thesis's way of writing points as rows) states that its
/// columns are the points, as `--columns` does.
pub fn point_matrix_text<T: LiteralScalar>(
    argument: &str,
    text: &str,
    typed: &DMatrix<T>,
    rows: bool,
) {
    let t = text.trim();
    let transposed = t.starts_with('[') && t.ends_with("]'");
    point_matrix_typed(argument, typed, rows, transposed);
}

fn point_matrix_typed<T: LiteralScalar>(
    argument: &str,
    typed: &DMatrix<T>,
    rows: bool,
    transposed: bool,
) {
    let (r, c) = typed.shape();
    let (dim, count) = if rows { (c, r) } else { (r, c) };
    let reading = Reading { count, dim, rows };
    PENDING.with(|p| {
        p.borrow_mut()
            .readings
            .push((argument.to_string(), reading))
    });
    let stated = transposed || PENDING.with(|p| p.borrow().stated);
    let implausible = dim > 3;
    let ambiguous = r > 1 && c > 1 && r <= 3 && c <= 3;
    if implausible || (ambiguous && !stated) {
        warn(argument, reading.to_string());
    }
}

/// What an error about `argument` should add, given how the input was read: the reading of
/// its points (or, for an error of another argument about points, of the points read unless
/// the orientation was stated), and any decimal comma read in it. Empty when there is nothing
/// to add.
pub fn explain(argument: &str, problem: &str) -> String {
    PENDING.with(|p| {
        let p = p.borrow();
        let mut parts = Vec::new();
        let own = p.readings.iter().find(|(a, _)| a == argument);
        if let Some((_, reading)) = own {
            parts.push(reading.to_string());
        } else if problem.contains("point") && !p.stated {
            if let Some((a, reading)) = p.readings.first() {
                parts.push(format!("{a} {reading}"));
            }
        }
        if let Some((_, message)) = p.commas.iter().find(|(a, _)| a == argument) {
            parts.push(message.clone());
        }
        parts.join("; ")
    })
}

/// The decimal comma in `text`, if it looks written with them, as the sources write
/// decimals: Octave — and so the command line — reads `0,5` as two numbers. Looks so: a
/// piece `d,d` (digits, one comma, digits) among pieces separated by white space (`[0,2
/// 0,4]`, `[1 0,5 1]`, a file's line `0,5 1,5`), or the whole list one such piece (`0,5`,
/// `[2,5]`). A list separated by commas only (`[0,0,0,1,1,1]`, `[1,2;3,4]`) or with spaces
/// after its commas (`[0, 0.5, 1]`) reads as written. `lone` says whether a single piece
/// counts (not on a file's line, where `x,y` is a CSV row).
///
/// ```
/// use cagd_cli::slips::decimal_comma;
/// assert_eq!(decimal_comma("[0,2 0,4]", true), Some(("0".into(), "2".into())));
/// assert_eq!(decimal_comma("[2,5]", true), Some(("2".into(), "5".into())));
/// for fine in ["[0, 0.5, 1]", "0:0.2:1", "[0,0,0,1,1,1]", "[0.2 0.4]", "[1,2;3,4]"] {
///     assert_eq!(decimal_comma(fine, true), None, "{fine}");
/// }
/// assert_eq!(decimal_comma("0,5", false), None);
/// ```
pub fn decimal_comma(text: &str, lone: bool) -> Option<(String, String)> {
    let inner = text.trim().trim_start_matches('[');
    let inner = inner.trim_end_matches('\'').trim_end_matches(']');
    let pieces: Vec<&str> = inner
        .split(|c: char| c.is_whitespace() || c == ';')
        .filter(|t| !t.is_empty())
        .collect();
    let spaced = inner.trim().contains(char::is_whitespace);
    if !(spaced || (lone && pieces.len() == 1)) {
        return None;
    }
    pieces.iter().find_map(|piece| {
        let piece = piece.trim_matches(|c: char| "[]()'".contains(c));
        let (before, after) = piece.split_once(',')?;
        let number = |s: &str, lead: bool| {
            let s = if lead {
                s.trim_start_matches(['-', '+'])
            } else {
                s
            };
            !s.is_empty()
                && s.chars().all(|c| c.is_ascii_digit())
                && s.starts_with(|c: char| c.is_ascii_digit())
        };
        (number(before, true) && number(after, false)).then(|| (before.into(), after.into()))
    })
}

/// The warning for a decimal comma `before,after`.
fn comma_message(before: &str, after: &str) -> String {
    format!("`{before},{after}` read as two numbers {before} and {after}; a decimal point is `{before}.{after}`")
}

/// Warns when a list or matrix typed as `argument` looks written with decimal commas (see
/// [`decimal_comma`]), saying how it was read and how to write a decimal; an error about
/// `argument` then says so too ([`explain`]).
///
/// ```
/// cagd_cli::slips::begin(false);
/// cagd_cli::slips::decimal_commas("--t", "[0,2 0,4]");
/// let w = cagd_cli::slips::take();
/// assert_eq!(w[0].1.message, "`0,2` read as two numbers 0 and 2; a decimal point is `0.2`");
/// cagd_cli::slips::decimal_commas("--t", "0,5");
/// assert_eq!(cagd_cli::slips::take().len(), 1);
/// for fine in ["[0, 0.5, 1]", "0:0.2:1", "[0,0,0,1,1,1]", "[0.2 0.4]"] {
///     cagd_cli::slips::decimal_commas("--knots", fine);
/// }
/// assert!(cagd_cli::slips::take().is_empty());
/// ```
pub fn decimal_commas(argument: &str, text: &str) {
    if let Some((before, after)) = decimal_comma(text, true) {
        comma(argument, comma_message(&before, &after));
    }
}

/// [`decimal_commas`] for the lines of a numeric text file (a line `x,y` alone is a CSV row).
pub fn decimal_commas_in_file(argument: &str, text: &str) {
    let found = text
        .lines()
        .map(|l| l.split(['#', '%']).next().unwrap_or(""))
        .find_map(|l| decimal_comma(l, false));
    if let Some((before, after)) = found {
        comma(argument, comma_message(&before, &after));
    }
}

fn comma(argument: &str, message: String) {
    PENDING.with(|p| {
        p.borrow_mut()
            .commas
            .push((argument.to_string(), message.clone()))
    });
    warn(argument, message);
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

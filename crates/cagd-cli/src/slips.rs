//! Likely slips of the hand, answered with a warning instead of a silent wrong answer.
//!
//! Each check knows a way the course's notation and the command line's can differ, and says
//! how the input was read and which flag changes the reading:
//! - [`point_matrix`]: points typed as rows (as the notes write them) but read as columns, or
//!   the other way round — a note whenever both readings are plausible, a warning when the
//!   reading gives points of dimension above 3;
//! - [`decimal_commas`]: `--t "[0,2 0,4]"` is t = 0, 2, 0, 4 (a comma separates elements), not
//!   the decimals 0,2 and 0,4 the sources write (and `0,5` is 0 and 5, `[0,5;1,5]` a 2×2
//!   matrix), in every list, matrix and numeric file;
//!
//! Warnings are collected in the command's context while it runs ([`warn`]) and handed out
//! with its result ([`take`]), each distinct warning once; an error of the command adds how
//! its points and numbers were read ([`explain`]).

use cagd_octave::literal::{LiteralScalar, Position, Warning};
use nalgebra::DMatrix;

use crate::cx::Cx;
pub use crate::noticed::Reading;

/// Records a warning about `argument` (printed as `cagd: warning: ARGUMENT: MESSAGE`).
pub fn warn(cx: &Cx, argument: impl Into<String>, message: impl Into<String>) {
    let warning = Warning {
        at: Position::default(),
        message: message.into(),
    };
    cx.noticed().warnings.push((argument.into(), warning));
}

/// The warnings recorded since the last call, in order, each distinct one once.
pub fn take(cx: &Cx) -> Vec<(String, Warning)> {
    dedup(std::mem::take(&mut cx.noticed().warnings))
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

/// Notes how a matrix of points was read, unless only one reading of its shape is plausible
/// or the orientation was stated (`--rows` or `--columns`, see [`Cx::stating_orientation`]): points are of
/// dimension 1 to 3, so a matrix with both sizes at most 3 (and neither 1) reads either way
/// and gets the note; a matrix whose reading gives points of dimension above 3 gets it as a
/// warning, also with `--rows`. A literal transposed as a whole states the reading too
/// ([`point_matrix_text`]). One point written as a column (or a row with `--rows`) and a
/// row of numbers (points in 1-D) read as typed, silently. The reading is remembered for
/// the errors about these points ([`explain`]).
///
/// ```
/// use cagd_cli::{slips, Cx};
/// use nalgebra::DMatrix;
/// let cx = Cx::new(cagd::Limits::default());
/// slips::point_matrix(&cx, "CONTROL", &DMatrix::<f64>::zeros(4, 2), false);
/// let w = slips::take(&cx);
/// assert!(w[0].1.message.contains("--rows"), "{}", w[0].1.message);
/// slips::point_matrix(&cx, "CONTROL", &DMatrix::<f64>::zeros(3, 3), false);
/// assert_eq!(slips::take(&cx)[0].1.message, "read as 3 points in 3-D, one per column; --rows if each row is a point");
/// slips::point_matrix(&cx, "CONTROL", &DMatrix::<f64>::zeros(2, 4), false);
/// assert!(slips::take(&cx).is_empty());
/// let stated = Cx::new(cagd::Limits::default()).stating_orientation(true); // --columns or --rows
/// slips::point_matrix(&stated, "CONTROL", &DMatrix::<f64>::zeros(3, 3), false);
/// assert!(slips::take(&stated).is_empty());
/// ```
pub fn point_matrix<T: LiteralScalar>(cx: &Cx, argument: &str, typed: &DMatrix<T>, rows: bool) {
    point_matrix_typed(cx, argument, typed, rows, false);
}

/// [`point_matrix`] of a matrix typed as `text`: a literal transposed as a whole
/// (`"[0 0; 1 2; 3 0]'"`, the thesis's way of writing points as rows) states that its
/// columns are the points, as `--columns` does.
pub fn point_matrix_text<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    text: &str,
    typed: &DMatrix<T>,
    rows: bool,
) {
    let t = text.trim();
    let transposed = t.starts_with('[') && t.ends_with("]'");
    point_matrix_typed(cx, argument, typed, rows, transposed);
}

fn point_matrix_typed<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    typed: &DMatrix<T>,
    rows: bool,
    transposed: bool,
) {
    let (r, c) = typed.shape();
    let (dim, count) = if rows { (c, r) } else { (r, c) };
    let reading = Reading { count, dim, rows };
    cx.noticed().readings.push((argument.to_string(), reading));
    let stated = transposed || cx.noticed().stated;
    let implausible = dim > 3;
    let ambiguous = r > 1 && c > 1 && r <= 3 && c <= 3;
    if implausible || (ambiguous && !stated) {
        warn(cx, argument, reading.to_string());
    }
}

/// What an error about `argument` should add, given how the input was read: the reading of
/// its points (or, for an error of another argument about points, of the points read unless
/// the orientation was stated), and any decimal comma read in it. Empty when there is nothing
/// to add.
pub fn explain(cx: &Cx, argument: &str, problem: &str) -> String {
    {
        let p = cx.noticed();
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
    }
}

/// The decimal comma in `text`, if it looks written with them, as the sources write
/// decimals: Octave — and so the command line — reads `0,5` as two numbers. Looks so: a
/// piece `d,d` (digits, one comma, digits) among pieces separated by white space (`[0,2
/// 0,4]`, `[1 0,5 1]`, a file's line `0,5 1,5`), or every row of the list one such piece
/// (`0,5`, `[2,5]`, `[0,5;1,5]`: a column of decimals; see [`pairs_only`]). A list separated
/// by commas only with more than two numbers in a row (`[0,0,0,1,1,1]`, `[1,2,3;4,5,6]`) or
/// with spaces after its commas (`[0, 0.5, 1]`, `[1, 2; 3, 4]`) reads as written. `lone` says
/// whether rows of one piece count (not on a file's single line, where `x,y` may be a CSV
/// row: [`decimal_commas_in_file`] looks at the whole file).
///
/// ```
/// use cagd_cli::slips::decimal_comma;
/// assert_eq!(decimal_comma("[0,2 0,4]", true), Some(("0".into(), "2".into())));
/// assert_eq!(decimal_comma("[2,5]", true), Some(("2".into(), "5".into())));
/// assert_eq!(decimal_comma("[0,5;1,5]", true), Some(("0".into(), "5".into())));
/// assert_eq!(decimal_comma("[1,2;3,4]", true), Some(("1".into(), "2".into())));
/// for fine in ["[0, 0.5, 1]", "0:0.2:1", "[0,0,0,1,1,1]", "[0.2 0.4]", "[1,2,3;4,5,6]", "[1, 2; 3, 4]"] {
///     assert_eq!(decimal_comma(fine, true), None, "{fine}");
/// }
/// assert_eq!(decimal_comma("0,5", false), None);
/// ```
pub fn decimal_comma(text: &str, lone: bool) -> Option<(String, String)> {
    let pieces = pieces(text);
    let spaced = inner(text).trim().contains(char::is_whitespace);
    if spaced {
        return pieces.iter().find_map(|piece| pair(piece));
    }
    if lone {
        return pairs_only(text);
    }
    None
}

/// The first pair when every row of `text` (rows separated by `;`) is one piece `d,d` and
/// nothing else: `0,5`, `[2,5]`, `[0,5;1,5]` — what a column of decimals written with commas
/// looks like, and also a two-column matrix of whole numbers typed without spaces (`[1,2;3,4]`),
/// which a space after each comma (`[1, 2; 3, 4]`) or a space between (`[1 2; 3 4]`) states.
pub fn pairs_only(text: &str) -> Option<(String, String)> {
    let inner = inner(text);
    if inner.trim().contains(char::is_whitespace) {
        return None;
    }
    let pieces = pieces(text);
    let first = pair(pieces.first()?)?;
    pieces.iter().all(|p| pair(p).is_some()).then_some(first)
}

/// `text` without its brackets and a transposing quote.
fn inner(text: &str) -> &str {
    let inner = text.trim().trim_start_matches('[');
    inner.trim_end_matches('\'').trim_end_matches(']')
}

/// The pieces of `text` between white space and semicolons.
fn pieces(text: &str) -> Vec<&str> {
    inner(text)
        .split(|c: char| c.is_whitespace() || c == ';')
        .filter(|t| !t.is_empty())
        .collect()
}

/// `piece` as `before,after` if it is digits, one comma, digits (a sign before).
fn pair(piece: &str) -> Option<(String, String)> {
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
}

/// The warning for a decimal comma `before,after`.
fn comma_message(before: &str, after: &str) -> String {
    format!("`{before},{after}` read as two numbers {before} and {after}; a decimal point is `{before}.{after}`")
}

/// The warning for rows that are each one pair `before,after` ([`pairs_only`]): both readings
/// are plausible, so it also says how to state the other.
fn pairs_message(before: &str, after: &str) -> String {
    format!(
        "{}; `{before}, {after}` (a space after the comma) if two numbers are meant",
        comma_message(before, after)
    )
}

/// Warns when a list or matrix typed as `argument` looks written with decimal commas (see
/// [`decimal_comma`]), saying how it was read and how to write a decimal; an error about
/// `argument` then says so too ([`explain`]).
///
/// ```
/// use cagd_cli::{slips, Cx};
/// let cx = Cx::new(cagd::Limits::default());
/// slips::decimal_commas(&cx, "--t", "[0,2 0,4]");
/// let w = slips::take(&cx);
/// assert_eq!(w[0].1.message, "`0,2` read as two numbers 0 and 2; a decimal point is `0.2`");
/// slips::decimal_commas(&cx, "--t", "0,5");
/// assert_eq!(slips::take(&cx).len(), 1);
/// for fine in ["[0, 0.5, 1]", "0:0.2:1", "[0,0,0,1,1,1]", "[0.2 0.4]"] {
///     slips::decimal_commas(&cx, "--knots", fine);
/// }
/// assert!(slips::take(&cx).is_empty());
/// ```
pub fn decimal_commas(cx: &Cx, argument: &str, text: &str) {
    let multi_row = pieces(text).len() > 1;
    if let Some((before, after)) = decimal_comma(text, true) {
        let message = if multi_row && pairs_only(text).is_some() {
            pairs_message(&before, &after)
        } else {
            comma_message(&before, &after)
        };
        comma(cx, argument, message);
    }
}

/// [`decimal_commas`] for the lines of a numeric text file: a line of several pieces with a
/// decimal comma among them (`0,5 1,5`), or every line one pair `d,d` (`0,5` on each line: a
/// column of decimals, as the same rows typed `[0,5;1,5]` are). A file whose lines hold more
/// than two numbers between commas (`0,1,2`), a decimal point, or a space after each comma is
/// a CSV file read as written.
///
/// ```
/// use cagd_cli::{slips, Cx};
/// let cx = Cx::new(cagd::Limits::default());
/// slips::decimal_commas_in_file(&cx, "CONTROL", "0,5\n1,5\n2,5\n");
/// assert_eq!(slips::take(&cx)[0].1.message,
///     "`0,5` read as two numbers 0 and 5; a decimal point is `0.5`; `0, 5` (a space after the comma) if two numbers are meant");
/// for csv in ["0,1,0\n1,2,0\n", "0, 1\n1, 2\n", "0.5,1\n1,2\n", "x,y\n0,1\n"] {
///     slips::decimal_commas_in_file(&cx, "CONTROL", csv);
///     assert!(slips::take(&cx).is_empty(), "{csv}");
/// }
/// ```
pub fn decimal_commas_in_file(cx: &Cx, argument: &str, text: &str) {
    let lines: Vec<&str> = text
        .lines()
        .map(|l| l.split(['#', '%']).next().unwrap_or("").trim())
        .filter(|l| !l.is_empty())
        .collect();
    if let Some((before, after)) = lines.iter().find_map(|l| decimal_comma(l, false)) {
        comma(cx, argument, comma_message(&before, &after));
        return;
    }
    let pairs: Vec<_> = lines.iter().map(|l| pairs_only(l)).collect();
    if let Some(Some((before, after))) = pairs.first() {
        if pairs.iter().all(Option::is_some) {
            comma(cx, argument, pairs_message(before, after));
        }
    }
}

fn comma(cx: &Cx, argument: &str, message: String) {
    cx.noticed()
        .commas
        .push((argument.to_string(), message.clone()));
    warn(cx, argument, message);
}

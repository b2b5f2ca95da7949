//! Formatting results: readable text, CSV, JSON (and Octave's text format, see [`Format`]).
//!
//! A command's result is a [`Report`]: named items, each a matrix (points as columns, like `T`
//! in the thesis function `deCasteljau`), a grid of shape (nu, nv, d) (like `P` in
//! `ploskevB`), or a line of text (a curve expression, a step's description).
//!
//! Numbers print as the shortest decimal that reads back to the same double (`0.1`, `3`,
//! `1e-20`), or, with `--exact`, as reduced fractions (`7/2`, `31/15`, integers without `/1`).
//! The readable text format first rounds every double to [`TEXT_DIGITS`] significant digits
//! (`--digits N` chooses another count), so round-off such as `0.30000000000000004` prints as
//! `0.3`, and shows an entry below `10^−digits` times the largest of its matrix as 0 (so
//! `cos(π/2) = 6.1e-17` beside 1 is 0, as Octave displays it); the machine formats (`octave`,
//! `csv`, `json`) keep every bit.
//!
//! Steps may be structured: a [`Value::Record`] of named parts is an object in JSON and a
//! struct in Octave's format, and a [`Value::Shown`] is printed as its text (a de Casteljau
//! triangle, say) in the text format and as its data everywhere else.

use std::fmt::Write as _;

use nalgebra::DMatrix;

use super::{CliError, ErrorKind};
use cagd_octave::literal::LiteralScalar;

/// How results are printed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Format {
    /// Readable text: each item as `name =` followed by aligned columns, grids one coordinate
    /// slice `name(:,:,k)` at a time (as Octave displays them).
    #[default]
    Text,
    /// Octave's `save -text` format, loadable with `load`: every item is a variable (the
    /// answer is `result`; curve points d×k with points as columns, like `T` in
    /// `deCasteljau`; surface grids nu×nv×d, like `P` in `ploskevB`; steps such as `rc`,
    /// `rd`, `rcd` as further variables; text as strings). Octave has no rationals, so with
    /// `--exact` the nearest doubles are written.
    Octave,
    /// Comma-separated values: a matrix row per line; a grid one point per line as
    /// `i,j,x1,…,xd` (1-based indices). With several items, each is preceded by a `# name`
    /// line and followed by an empty line.
    Csv,
    /// One JSON object mapping item names to values: matrices as arrays of rows, grids as
    /// `[i][j][k]` nested arrays (as Octave's `jsonencode`), text as strings; with
    /// `--exact`, numbers are strings such as `"7/2"`.
    Json,
}

pub use cagd_ops::{number_text, number_text_digits, Item, Report, Value, TEXT_DIGITS};

/// Renders a report in the given format (the output ends with a newline).
///
/// ```
/// use cagd_cli::{render, Format, Report, Value};
/// use nalgebra::DMatrix;
/// let mut r = Report::<f64>::new();
/// r.push("result", Value::Matrix(DMatrix::from_row_slice(2, 2, &[1.0, 0.25, -3.0, 10.0])));
/// assert_eq!(render(&r, Format::Text).unwrap(), "result =\n\n     1  0.25\n    -3    10\n\n");
/// assert_eq!(render(&r, Format::Csv).unwrap(), "1,0.25\n-3,10\n");
/// assert_eq!(render(&r, Format::Json).unwrap(), "{\"result\":[[1.0,0.25],[-3.0,10.0]]}\n");
/// ```
pub fn render<T: LiteralScalar>(report: &Report<T>, format: Format) -> Result<String, CliError> {
    render_with(report, format, TEXT_DIGITS)
}

/// [`render`] with doubles rounded to `digits` significant digits in the text format (the
/// other formats keep every bit).
///
/// ```
/// use cagd_cli::{render_with, Format, Report, Value};
/// use nalgebra::DMatrix;
/// let mut r = Report::<f64>::new();
/// r.push("x", Value::Matrix(DMatrix::from_element(1, 1, 0.1 + 0.2)));
/// assert_eq!(render_with(&r, Format::Text, 15).unwrap(), "x = 0.3\n\n");
/// assert_eq!(render_with(&r, Format::Text, 17).unwrap(), "x = 0.30000000000000004\n\n");
/// assert_eq!(render_with(&r, Format::Csv, 15).unwrap(), "0.30000000000000004\n");
/// ```
pub fn render_with<T: LiteralScalar>(
    report: &Report<T>,
    format: Format,
    digits: usize,
) -> Result<String, CliError> {
    match format {
        Format::Text => Ok(render_text(report, digits)),
        Format::Csv => Ok(render_csv(report)),
        Format::Json => render_json(report),
        Format::Octave => render_octave(report),
    }
}

/// An Octave identifier made from an item name (`r_c` stays, `b^1` becomes `b_1`).
fn octave_name(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if !out.starts_with(|c: char| c.is_ascii_alphabetic()) {
        out.insert(0, 'x');
    }
    out
}

fn render_octave<T: LiteralScalar>(report: &Report<T>) -> Result<String, CliError> {
    use cagd_octave::text_format::{self, Workspace};
    let mut ws = Workspace::new();
    for item in &report.items {
        ws.insert(
            octave_name(&item.name),
            octave_value(&item.name, &item.value)?,
        );
    }
    text_format::write_text(&ws).map_err(|e| {
        CliError::new(
            "--format octave",
            e.to_string(),
            "results Octave can store",
            ErrorKind::Internal,
        )
    })
}

/// A value as Octave stores it: matrices and grids as doubles, text as a char matrix, a
/// record as a struct (`name` names it in errors).
fn octave_value<T: LiteralScalar>(
    name: &str,
    value: &Value<T>,
) -> Result<cagd_octave::text_format::Value, CliError> {
    use cagd_octave::text_format::{CharMatrix, Value as OValue};
    Ok(match value {
        Value::Matrix(m) => {
            let mut a = ndarray::Array2::zeros(m.shape());
            for ((i, j), x) in a.indexed_iter_mut() {
                let at = || (format!("{name}({},{})", i + 1, j + 1), j * m.nrows() + i);
                *x = octave_double(&m[(i, j)], at)?;
            }
            OValue::from(a)
        }
        Value::Grid(g) => {
            let (nu, nv, d) = g.dim();
            let mut a = ndarray::Array3::zeros((nu, nv, d));
            for ((i, j, k), x) in a.indexed_iter_mut() {
                let at = || {
                    let place = format!("{name}({},{},{})", i + 1, j + 1, k + 1);
                    (place, (i * nv + j) * d + k)
                };
                *x = octave_double(&g[[i, j, k]], at)?;
            }
            OValue::Matrix(a.into_dyn())
        }
        Value::Text(t) => {
            // A char matrix needs rows of one length: pad with spaces, as Octave's char().
            let lines: Vec<&str> = t.lines().collect();
            let width = lines.iter().map(|l| l.len()).max().unwrap_or(0);
            let mut c = CharMatrix::new("");
            c.rows = lines.iter().map(|l| format!("{l:<width$}")).collect();
            OValue::Str(c)
        }
        Value::Record(items) => OValue::Struct(
            items
                .iter()
                .map(|i| {
                    let inner = format!("{name}.{}", i.name);
                    Ok((octave_name(&i.name), octave_value(&inner, &i.value)?))
                })
                .collect::<Result<_, CliError>>()?,
        ),
        Value::Shown { data, .. } => octave_value(name, data)?,
    })
}

/// The double Octave's format stores for `x`. An exact value is finite, but its double may
/// not be (beyond ±1.8e308): that is refused, naming the entry (`at`: its name and flat
/// index) and the value,
/// rather than written as `Inf`. (Doubles that are not finite are refused before rendering,
/// with the input they came from.)
fn octave_double<T: LiteralScalar>(
    x: &T,
    at: impl Fn() -> (String, usize),
) -> Result<f64, CliError> {
    let v = x.to_f64();
    if v.is_finite() || !T::EXACT {
        return Ok(v);
    }
    let sign = if v > 0.0 { "Inf" } else { "-Inf" };
    let (place, index) = at();
    Err(CliError::new(
        "--format octave",
        format!(
            "{place} is the exact value `{}`, beyond the range of doubles (it would be written as {sign})",
            number_text(x)
        ),
        "results within ±1.8e308 for Octave's doubles (--format text, csv or json write the exact fractions)",
        ErrorKind::Library(Box::new(cagd::Error::NonFinite {
            what: "exact result as a double",
            index,
            value: v,
        })),
    ))
}

/// Right-aligned columns with two spaces before each, indented by two more.
fn aligned(m: &DMatrix<String>) -> String {
    let widths: Vec<usize> = m
        .column_iter()
        .map(|c| c.iter().map(|s| s.chars().count()).max().unwrap_or(0))
        .collect();
    let mut out = String::new();
    for i in 0..m.nrows() {
        out.push_str("  ");
        for (j, w) in widths.iter().enumerate() {
            let _ = write!(out, "  {:>w$}", m[(i, j)], w = w);
        }
        out.push('\n');
    }
    out
}

/// The entries of a matrix as the text format prints them: `digits` significant digits, and
/// doubles below `10^−digits` times the largest magnitude of the matrix as 0 (round-off of a
/// zero, such as cos(π/2) = 6.1e-17 next to 1); fractions in full.
fn text_entries<T: LiteralScalar>(m: &DMatrix<T>, digits: usize) -> DMatrix<String> {
    let scale = m.iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max);
    let floor = scale * 10f64.powi(-(digits.clamp(1, 17) as i32));
    m.map(|x| {
        if !T::EXACT && x.to_f64().abs() < floor {
            "0".to_string()
        } else {
            number_text_digits(&x, digits)
        }
    })
}

fn text_matrix<T: LiteralScalar>(name: &str, m: &DMatrix<T>, digits: usize, out: &mut String) {
    if m.is_empty() {
        let _ = writeln!(out, "{name} = []({}x{})\n", m.nrows(), m.ncols());
    } else if m.len() == 1 {
        let _ = writeln!(out, "{name} = {}\n", number_text_digits(&m[(0, 0)], digits));
    } else {
        let _ = writeln!(out, "{name} =\n");
        out.push_str(&aligned(&text_entries(m, digits)));
        out.push('\n');
    }
}

fn text_item<T: LiteralScalar>(name: &str, value: &Value<T>, digits: usize, out: &mut String) {
    match value {
        Value::Matrix(m) => text_matrix(name, m, digits, out),
        Value::Grid(g) => {
            let (nu, nv, d) = g.dim();
            if nu * nv * d == 0 {
                let _ = writeln!(out, "{name} = []({nu}x{nv}x{d})\n");
            }
            for k in 0..d {
                let slice = DMatrix::from_fn(nu, nv, |i, j| g[[i, j, k]].clone());
                text_matrix(&format!("{name}(:,:,{})", k + 1), &slice, digits, out);
            }
        }
        Value::Text(t) | Value::Shown { text: t, .. } if t.contains('\n') => {
            let _ = writeln!(out, "{name}:\n{}\n", t.trim_end());
        }
        Value::Text(t) | Value::Shown { text: t, .. } => {
            let _ = writeln!(out, "{name} = {t}\n");
        }
        Value::Record(items) => {
            for i in items {
                text_item(&format!("{name}.{}", i.name), &i.value, digits, out);
            }
        }
    }
}

fn render_text<T: LiteralScalar>(report: &Report<T>, digits: usize) -> String {
    let mut out = String::new();
    for item in &report.items {
        text_item(&item.name, &item.value, digits, &mut out);
    }
    out
}

fn csv_item<T: LiteralScalar>(value: &Value<T>, out: &mut String) {
    match value {
        Value::Matrix(m) => {
            for i in 0..m.nrows() {
                let row: Vec<String> = m.row(i).iter().map(number_text).collect();
                let _ = writeln!(out, "{}", row.join(","));
            }
        }
        Value::Grid(g) => {
            let (nu, nv, d) = g.dim();
            for i in 0..nu {
                for j in 0..nv {
                    let mut fields = vec![(i + 1).to_string(), (j + 1).to_string()];
                    fields.extend((0..d).map(|k| number_text(&g[[i, j, k]])));
                    let _ = writeln!(out, "{}", fields.join(","));
                }
            }
        }
        Value::Text(t) => {
            for line in t.lines() {
                let _ = writeln!(out, "# {line}");
            }
        }
        Value::Shown { data, .. } => csv_item(data, out),
        Value::Record(_) => {}
    }
}

/// The leaves of an item: records flattened to `name.part` items.
fn flattened<'a, T: LiteralScalar>(
    name: String,
    value: &'a Value<T>,
    out: &mut Vec<(String, &'a Value<T>)>,
) {
    match value {
        Value::Record(items) => {
            for i in items {
                flattened(format!("{name}.{}", i.name), &i.value, out);
            }
        }
        Value::Shown { data, .. } => flattened(name, data, out),
        other => out.push((name, other)),
    }
}

fn render_csv<T: LiteralScalar>(report: &Report<T>) -> String {
    let mut leaves = Vec::new();
    for item in &report.items {
        flattened(item.name.clone(), &item.value, &mut leaves);
    }
    let mut out = String::new();
    if let [(_, only)] = leaves.as_slice() {
        csv_item(*only, &mut out);
        return out;
    }
    for (name, value) in leaves {
        let _ = writeln!(out, "# {name}");
        csv_item(value, &mut out);
        out.push('\n');
    }
    out
}

fn json_number<T: LiteralScalar>(x: &T) -> Result<serde_json::Value, CliError> {
    if T::EXACT {
        return Ok(serde_json::Value::String(x.to_string()));
    }
    serde_json::Number::from_f64(x.to_f64())
        .map(serde_json::Value::Number)
        .ok_or_else(|| {
            CliError::new(
                "--format json",
                format!("the value {x} is not finite"),
                "finite results",
                ErrorKind::Internal,
            )
        })
}

fn json_error(e: serde_json::Error) -> CliError {
    CliError::new(
        "--format json",
        e.to_string(),
        "serialisable results",
        ErrorKind::Internal,
    )
}

/// The JSON text of a value; records are objects written by hand so that their parts keep
/// their order (serde_json's own maps sort their keys).
fn json_text<T: LiteralScalar>(value: &Value<T>) -> Result<String, CliError> {
    use serde_json::Value as J;
    let v = match value {
        Value::Matrix(m) => J::Array(
            (0..m.nrows())
                .map(|i| {
                    m.row(i)
                        .iter()
                        .map(json_number)
                        .collect::<Result<Vec<_>, _>>()
                        .map(J::Array)
                })
                .collect::<Result<Vec<_>, _>>()?,
        ),
        Value::Grid(g) => {
            let (nu, nv, d) = g.dim();
            let mut rows = Vec::with_capacity(nu);
            for i in 0..nu {
                let mut cols = Vec::with_capacity(nv);
                for j in 0..nv {
                    let p = (0..d)
                        .map(|k| json_number(&g[[i, j, k]]))
                        .collect::<Result<Vec<_>, _>>()?;
                    cols.push(J::Array(p));
                }
                rows.push(J::Array(cols));
            }
            J::Array(rows)
        }
        Value::Text(t) => J::String(t.clone()),
        Value::Record(items) => return json_object(items),
        Value::Shown { data, .. } => return json_text(data),
    };
    serde_json::to_string(&v).map_err(json_error)
}

/// Named items as a JSON object, in order.
fn json_object<T: LiteralScalar>(items: &[Item<T>]) -> Result<String, CliError> {
    let mut entries = Vec::with_capacity(items.len());
    for item in items {
        entries.push(format!(
            "{}:{}",
            serde_json::to_string(&item.name).map_err(json_error)?,
            json_text(&item.value)?
        ));
    }
    Ok(format!("{{{}}}", entries.join(",")))
}

fn render_json<T: LiteralScalar>(report: &Report<T>) -> Result<String, CliError> {
    Ok(format!("{}\n", json_object(&report.items)?))
}

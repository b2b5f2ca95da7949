//! Reading the inputs of a command: matrices, parameter values, curve expressions, scripts.
//!
//! A **matrix argument** (control points, nets) may be
//! - an Octave matrix literal: `"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'"` (may use the variables of a
//!   `--script`);
//! - a path to a plain numeric text file: numbers separated by spaces, tabs, commas or
//!   semicolons, one matrix row per line, `#` and `%` comments — what Octave's
//!   `save -ascii` and `dlmwrite`/`csvwrite` write;
//! - a path to an Octave `save -text` file (recognised by its `# name:` header);
//! - `-` for standard input (either file format).
//!
//! **Parameter arguments** (`--t`, `--u`, `--v`) are a number, a list literal
//! (`"[0 0.25 0.5]"`) or a range (`0:0.1:1`); `--n N` means `linspace(0,1,N)`.

use std::io::Read;
use std::path::Path;

use nalgebra::DMatrix;

use super::{CliError, ErrorKind};
use crate::octave::literal::{Env, Expr, LiteralScalar, ParamExpr};
use crate::octave::script::Script;

/// Largest input file or standard input accepted, in bytes (64 MiB).
pub const MAX_INPUT_BYTES: u64 = 64 << 20;

/// The form of a matrix argument, for error messages.
pub const MATRIX_FORM: &str =
    "an Octave matrix literal such as \"[0 0 0; 1 2 0]'\", a numeric text or CSV file, or - for standard input";
/// The form of a parameter argument, for error messages.
pub const PARAMS_FORM: &str =
    "a number, a list such as \"[0 0.25 0.5]\" or a range such as 0:0.1:1";
/// The form of a curve expression, for error messages.
pub const CURVE_FORM: &str = "an expression in the curve parameter such as \"[u; 0; u-u^2]\"";

/// Reads a file (or standard input for `-`) as text, with the size limit.
pub fn read_text(argument: &str, path: &str) -> Result<String, CliError> {
    let form = "a readable UTF-8 text file (at most 64 MiB), or - for standard input";
    let mut bytes = Vec::new();
    let result = if path == "-" {
        std::io::stdin()
            .lock()
            .take(MAX_INPUT_BYTES + 1)
            .read_to_end(&mut bytes)
    } else {
        std::fs::File::open(path).and_then(|f| f.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes))
    };
    let shown = if path == "-" {
        argument.to_string()
    } else {
        format!("{argument} {path}")
    };
    result.map_err(|e| CliError::io(shown.clone(), &e, form))?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(CliError::new(
            shown,
            "the input is larger than 64 MiB",
            form,
            ErrorKind::Data,
        ));
    }
    String::from_utf8(bytes)
        .map_err(|_| CliError::new(shown, "the file is not UTF-8 text", form, ErrorKind::Data))
}

/// Whether `text` names a file rather than being an expression: it has a data-file extension
/// or contains a path separator, and no white space or brackets.
fn looks_like_path(text: &str) -> bool {
    const EXTENSIONS: &[&str] = &[
        ".txt", ".csv", ".tsv", ".dat", ".mat", ".m", ".out", ".asc", ".text",
    ];
    if text.is_empty() || text.contains(|c: char| c.is_whitespace() || "[](),;:'".contains(c)) {
        return false;
    }
    let lower = text.to_ascii_lowercase();
    EXTENSIONS.iter().any(|e| lower.ends_with(e))
        || text.contains('/') && !text.starts_with(|c: char| c.is_ascii_digit())
}

/// Whether a text file is in Octave's `save -text` format.
fn is_octave_text(text: &str) -> bool {
    text.lines()
        .take(20)
        .any(|l| l.trim_start().starts_with("# name:"))
}

/// Loads a matrix argument (see the module documentation). Literals are evaluated with the
/// variables of `script`, if any.
///
/// ```
/// use cagd::cli::load_matrix;
/// let b = load_matrix::<f64>("--control", "[0 0 0; 0 2 2]'", None).unwrap();
/// assert_eq!(b.shape(), (3, 2));
/// let err = load_matrix::<f64>("--control", "[1 2; 3]", None).unwrap_err();
/// assert!(err.to_string().starts_with("--control: column 7: row 2 has 1 column(s), expected 2; expected"));
/// ```
pub fn load_matrix<T: LiteralScalar>(
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
) -> Result<DMatrix<T>, CliError> {
    let trimmed = text.trim();
    // A variable of the script wins over a file of the same name.
    let is_variable = script.is_some_and(|s| s.get(trimmed).is_some());
    if trimmed == "-" || (!is_variable && !trimmed.starts_with('[') && Path::new(trimmed).is_file())
    {
        let contents = read_text(argument, trimmed)?;
        let shown = if trimmed == "-" {
            argument.to_string()
        } else {
            format!("{argument} {trimmed}")
        };
        return parse_data_text(&shown, &contents);
    }
    if !is_variable && looks_like_path(trimmed) {
        return Err(CliError::io(
            format!("{argument} {trimmed}"),
            &std::io::Error::from(std::io::ErrorKind::NotFound),
            MATRIX_FORM,
        ));
    }
    let mut env = match script {
        Some(s) => s.env().clone(),
        None => Env::new(),
    };
    let expr = Expr::parse_with(text, env.limits())
        .map_err(|e| CliError::literal(argument, e, MATRIX_FORM))?;
    if let Some(s) = script {
        for (name, at) in expr.name_uses() {
            if s.function(&name).is_some() && s.value(&name).is_none() {
                return Err(CliError::new(
                    argument,
                    format!("{at}: `{name}` is a curve in a free parameter, not a matrix"),
                    MATRIX_FORM,
                    ErrorKind::Shape,
                ));
            }
        }
    }
    expr.eval(&mut env)
        .map_err(|e| CliError::literal(argument, e, MATRIX_FORM))
}

/// Parses the contents of a data file: Octave `save -text` (integration point) or plain
/// numeric text.
pub fn parse_data_text<T: LiteralScalar>(
    argument: &str,
    contents: &str,
) -> Result<DMatrix<T>, CliError> {
    if is_octave_text(contents) {
        // INTEGRATION POINT (branch `octave`): read with
        // `crate::octave::text_format` once it is merged, taking the first (or only) variable.
        return Err(CliError::new(
            argument,
            "reading Octave `save -text` files is not available in this build",
            "a plain numeric text file (as `save -ascii` or `dlmwrite` write it) or a matrix literal",
            ErrorKind::Unsupported,
        ));
    }
    parse_numeric_text(contents).map_err(|(line, problem)| {
        CliError::new(
            argument,
            format!("line {line}: {problem}"),
            "rows of numbers separated by spaces, tabs, commas or semicolons, every row as long as the first",
            ErrorKind::Data,
        )
    })
}

/// Parses plain numeric text: one matrix row per line, numbers separated by white space,
/// commas or semicolons; blank lines and `#`/`%` comments are skipped. The error is the
/// line number (from 1) and what was wrong.
///
/// ```
/// let m = cagd::cli::parse_numeric_text::<f64>("# x y\n1, 2\n3\t4\n").unwrap();
/// assert_eq!(m, nalgebra::DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 3.0, 4.0]));
/// assert!(cagd::cli::parse_numeric_text::<f64>("1 2\n3\n").is_err());
/// assert!(cagd::cli::parse_numeric_text::<f64>("1 Inf\n").is_err());
/// ```
pub fn parse_numeric_text<T: LiteralScalar>(text: &str) -> Result<DMatrix<T>, (usize, String)> {
    let mut rows: Vec<Vec<T>> = Vec::new();
    let mut width = None;
    for (k, line) in text.lines().enumerate() {
        let line_no = k + 1;
        let content = line.split(['#', '%']).next().unwrap_or("");
        let fields: Vec<&str> = content
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|f| !f.is_empty())
            .collect();
        if fields.is_empty() {
            continue;
        }
        let mut row = Vec::with_capacity(fields.len());
        for (j, f) in fields.iter().enumerate() {
            let x = crate::octave::literal::parse_number::<T>(f).ok_or_else(|| {
                (
                    line_no,
                    format!("value {} (`{f}`) is not a finite decimal number", j + 1),
                )
            })?;
            row.push(x);
        }
        match width {
            None => width = Some(row.len()),
            Some(w) if w != row.len() => {
                return Err((
                    line_no,
                    format!("the row has {} value(s), the first row {w}", row.len()),
                ))
            }
            _ => {}
        }
        rows.push(row);
    }
    let w = width.unwrap_or(0);
    let n = rows.len();
    if (n as u128) * (w as u128) > crate::octave::literal::Limits::default().max_elements as u128 {
        return Err((n, "too many values".into()));
    }
    Ok(DMatrix::from_fn(n, w, |i, j| rows[i][j].clone()))
}

/// Parses a parameter argument (`--t`, `--u`, `--v`): a number, a list or a range; at least
/// one value.
///
/// ```
/// let t = cagd::cli::load_params::<f64>("--t", "[0 0.5 1]").unwrap();
/// assert_eq!(t, vec![0.0, 0.5, 1.0]);
/// assert!(cagd::cli::load_params::<f64>("--t", "[0 0; 1 1]").is_err());
/// ```
pub fn load_params<T: LiteralScalar>(argument: &str, text: &str) -> Result<Vec<T>, CliError> {
    let values = crate::octave::literal::parse_params::<T>(text)
        .map_err(|e| CliError::literal(argument, e, PARAMS_FORM))?;
    if values.is_empty() {
        return Err(CliError::new(
            argument,
            format!("`{}` has no values", text.trim()),
            PARAMS_FORM,
            ErrorKind::Shape,
        ));
    }
    Ok(values)
}

/// `linspace(0, 1, n)` for `--n`, requiring `n ≥ min` (2 for grids: a grid needs both
/// ends). Octave's doubles for `f64`, exact `i/(n−1)` for rationals.
///
/// ```
/// assert_eq!(cagd::cli::samples::<f64>(5, 2).unwrap(), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
/// assert!(cagd::cli::samples::<f64>(1, 2).is_err());
/// ```
pub fn samples<T: LiteralScalar>(n: usize, min: usize) -> Result<Vec<T>, CliError> {
    const MAX_SAMPLES: usize = 1_000_000;
    if n < min || n > MAX_SAMPLES {
        return Err(CliError::new(
            "--n",
            format!("N = {n} is too {}", if n < min { "small" } else { "large" }),
            format!("an integer N with {min} ≤ N ≤ {MAX_SAMPLES} (samples linspace(0,1,N))"),
            ErrorKind::Shape,
        ));
    }
    Ok(T::linspace(&T::zero(), &T::one(), n))
}

/// Parses a curve or surface expression argument, in the context of `script` (whose curves
/// it may name: `--c1 c1`).
pub fn load_expression<T: LiteralScalar>(
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
) -> Result<ParamExpr, CliError> {
    match script {
        Some(s) => s.resolve(text),
        None => ParamExpr::parse(text),
    }
    .map_err(|e| CliError::literal(argument, e, CURVE_FORM))
}

/// Runs a data script (`--script FILE`, or `-` for standard input) with `initial` variables.
pub fn load_script<T: LiteralScalar>(
    argument: &str,
    path: &str,
    initial: Env<T>,
) -> Result<Script<T>, CliError> {
    let source = read_text(argument, path)?;
    crate::octave::script::run(&source, initial).map_err(|e| {
        CliError::literal(
            format!("{argument} {path}"),
            e,
            "an Octave data script of assignments and for loops",
        )
    })
}

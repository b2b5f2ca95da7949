//! Reading the inputs of a command: matrices, parameter values, curve expressions, scripts.
//!
//! A **matrix argument** (control points, nets) may be
//! - an Octave matrix literal: `"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'"` (may use the variables of a
//!   `--script`);
//! - a path to a plain numeric text file: numbers separated by spaces, tabs, commas or
//!   semicolons, one matrix row per line, `#` and `%` comments — what Octave's
//!   `save -ascii` and `dlmwrite`/`csvwrite` write;
//! - a path to an Octave `save -text` file (recognised by its `# name:` header): the
//!   variable named after a colon (`net.txt:B`), or else the first numeric variable of the
//!   file (scalars, matrices, ranges and logical arrays count; strings, structs and cells are
//!   skipped). With `--exact`, each stored double is read as the shortest decimal that
//!   round-trips (`0.10000000000000001` is read as 1/10);
//! - `-` for standard input (either file format).
//!
//! **Parameter arguments** (`--t`, `--u`, `--v`) are a number, a list literal
//! (`"[0 0.25 0.5]"`) or a range (`0:0.1:1`); `--n N` means `linspace(0,1,N)`.

use cagd::limits::Limits;
use std::io::Read;

use cagd::grid::PointGrid;
use nalgebra::DMatrix;

use super::{CliError, ErrorKind};
use cagd_octave::literal::{Env, Expr, LiteralError, LiteralScalar, ParamExpr, Warning};
use cagd_octave::script::Script;

/// Largest input file or standard input accepted by default, in bytes (64 MiB); the limit in
/// force is [`cagd::limits::Limits::max_input_bytes`].
pub const MAX_INPUT_BYTES: u64 = 64 << 20;

/// The form of a matrix argument, for error messages.
pub const MATRIX_FORM: &str =
    "an Octave matrix literal such as \"[0 0 0; 1 2 0]'\", a numeric text or CSV file, or - for standard input";
/// The form of a parameter argument, for error messages.
pub const PARAMS_FORM: &str =
    "a number, a list such as \"[0 0.25 0.5]\" or a range such as 0:0.1:1";
/// The form of a curve expression, for error messages.
pub const CURVE_FORM: &str = "an expression in the curve parameter such as \"[u; 0; u-u^2]\"";

thread_local! {
    /// Files given in memory by [`with_input_files`], by name.
    static INPUT_FILES: std::cell::RefCell<Vec<(String, String)>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// Runs `f` (typically [`crate::run`]) with `files` (name, contents) readable as input files
/// of that name, before the file system: so the web page, which has no file system, passes a
/// data script typed into the page as `--script data.m`. Only on the calling thread, and only
/// while `f` runs.
///
/// ```
/// let files = vec![("data.m".to_string(), "B = [0 0; 1 2]';".to_string())];
/// let out = cagd_cli::with_input_files(files, || cagd_cli::run(["cagd", "script", "data.m"]));
/// assert!(out.unwrap().stdout.contains("B ="));
/// ```
pub fn with_input_files<R>(files: Vec<(String, String)>, f: impl FnOnce() -> R) -> R {
    let previous = INPUT_FILES.with(|cell| cell.replace(files));
    let result = f();
    INPUT_FILES.with(|cell| cell.replace(previous));
    result
}

fn input_file(path: &str) -> Option<String> {
    INPUT_FILES.with(|cell| {
        cell.borrow()
            .iter()
            .find(|(name, _)| name == path)
            .map(|(_, text)| text.clone())
    })
}

/// Whether `path` names an input file: one given to [`with_input_files`], or something on
/// disk to read as a file: a regular file, or a named pipe, a device or `/dev/stdin` (anything
/// that exists and is not a folder), so that `<(command)` and FIFOs are read rather than
/// reported missing.
pub(crate) fn is_file(path: &str) -> bool {
    input_file(path).is_some() || std::fs::metadata(path).is_ok_and(|m| !m.is_dir())
}

/// Reads a file (or standard input for `-`) as text, with the size limit.
pub fn read_text(limits: &Limits, argument: &str, path: &str) -> Result<String, CliError> {
    let limit = limits.max_input_bytes;
    let size = if limit % (1 << 20) == 0 {
        format!("{} MiB", limit >> 20)
    } else {
        format!("{limit} bytes")
    };
    let form = format!("a readable UTF-8 text file (at most {size}), or - for standard input");
    let form = form.as_str();
    let mut bytes = Vec::new();
    let result = if let Some(text) = input_file(path) {
        bytes = text.into_bytes();
        Ok(bytes.len())
    } else if path == "-" {
        std::io::stdin()
            .lock()
            .take(limit.saturating_add(1))
            .read_to_end(&mut bytes)
    } else {
        std::fs::File::open(path)
            .and_then(|f| f.take(limit.saturating_add(1)).read_to_end(&mut bytes))
    };
    let shown = if path == "-" {
        argument.to_string()
    } else {
        format!("{argument} {path}")
    };
    result.map_err(|e| CliError::io(shown.clone(), &e, form))?;
    if bytes.len() as u64 > limit {
        return Err(CliError::new(
            shown,
            format!("the input is larger than {size} (see --max-input-bytes)"),
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
/// use cagd_cli::load_matrix;
/// let b = load_matrix::<f64>(&cagd::Limits::default(), "--control", "[0 0 0; 0 2 2]'", None).unwrap();
/// assert_eq!(b.shape(), (3, 2));
/// let err = load_matrix::<f64>(&cagd::Limits::default(), "--control", "[1 2; 3]", None).unwrap_err();
/// assert!(err.to_string().starts_with("--control: column 7: row 2 has 1 column(s), expected 2; expected"));
/// ```
pub fn load_matrix<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
) -> Result<DMatrix<T>, CliError> {
    let trimmed = text.trim();
    // A variable of the script wins over a file of the same name.
    let is_variable = script.is_some_and(|s| s.get(trimmed).is_some());
    if let Some((path, variable)) = split_variable(trimmed) {
        if !is_variable {
            let contents = read_text(limits, argument, path)?;
            let shown = format!("{argument} {trimmed}");
            return parse_data_text_variable(limits, &shown, &contents, Some(variable));
        }
    }
    if trimmed == "-" || (!is_variable && !trimmed.starts_with('[') && is_file(trimmed)) {
        let contents = read_text(limits, argument, trimmed)?;
        let shown = if trimmed == "-" {
            argument.to_string()
        } else {
            format!("{argument} {trimmed}")
        };
        if !is_octave_text(&contents) {
            crate::slips::decimal_commas_in_file(argument, &contents);
        }
        return parse_data_text(limits, &shown, &contents);
    }
    if !is_variable {
        missing_file(argument, trimmed)?;
        crate::slips::decimal_commas(argument, text);
    }
    let mut env = match script {
        Some(s) => s.env().clone(),
        None => Env::with_limits(*limits),
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
    let before: Vec<Warning> = env.warnings().cloned().collect();
    let value = expr
        .eval(&mut env)
        .map_err(|e| CliError::literal(argument, e, MATRIX_FORM))?;
    let new = env
        .take_warnings()
        .into_iter()
        .filter(|w| !before.contains(w));
    refuse_lenient(argument, new, MATRIX_FORM)?;
    Ok(value)
}

/// "No such file" for a text that names a file (`net.txt`, `net.txt:B`) that does not exist.
fn missing_file(argument: &str, text: &str) -> Result<(), CliError> {
    let path = split_name(text).map_or(text, |(path, _)| path);
    if !looks_like_path(path) {
        return Ok(());
    }
    Err(CliError::io(
        format!("{argument} {path}"),
        &std::io::Error::from(std::io::ErrorKind::NotFound),
        MATRIX_FORM,
    ))
}

/// Refuses the first of `warnings`: what a data script accepts with a warning (Octave would
/// refuse it), an argument typed on the command line must spell out (`.*` for `*`, …).
fn refuse_lenient(
    argument: &str,
    warnings: impl IntoIterator<Item = Warning>,
    form: &str,
) -> Result<(), CliError> {
    match warnings.into_iter().next() {
        None => Ok(()),
        Some(w) => {
            // "`*` on 1×2 and 1×2 operands is an error in Octave; evaluated element-wise as
            // `.*`": the first clause says what Octave does, the rest how a script reads it.
            let what = w
                .message
                .split("; ")
                .next()
                .unwrap_or(&w.message)
                .to_string();
            let error = LiteralError::Unsupported {
                at: w.at,
                what: format!("{what} (a data script reads it leniently, with a warning; an argument must be valid Octave)"),
            };
            Err(CliError::literal(argument, error, form))
        }
    }
}

/// `file.txt:name` with an existing file `file.txt` and an Octave identifier `name`.
fn split_variable(text: &str) -> Option<(&str, &str)> {
    split_name(text).filter(|(path, _)| is_file(path))
}

/// `path:name` with an Octave identifier `name` (the path need not exist).
fn split_name(text: &str) -> Option<(&str, &str)> {
    let (path, name) = text.rsplit_once(':')?;
    let valid = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    valid.then_some((path, name))
}

/// The form of an Octave text file argument, for error messages.
const OCTAVE_FILE_FORM: &str =
    "an Octave `save -text` file with a numeric variable (choose one with FILE:NAME)";

/// Reads an Octave `save -text` file and picks a numeric variable: `variable` if given, else
/// the first numeric one. The result keeps Octave's dimensions (2 or more).
pub fn read_octave_array(
    limits: &Limits,
    argument: &str,
    contents: &str,
    variable: Option<&str>,
) -> Result<(String, ndarray::ArrayD<f64>), CliError> {
    use cagd_octave::text_format;
    let ws = text_format::read_text_with(contents, limits)
        .map_err(|e| CliError::new(argument, e.to_string(), OCTAVE_FILE_FORM, ErrorKind::Data))?;
    let name = match variable {
        Some(name) => name.to_string(),
        None => ws
            .iter()
            .find(|(_, v)| v.to_array_with(limits).is_some())
            .map(|(n, _)| n.to_string())
            .ok_or_else(|| {
                CliError::new(
                    argument,
                    "the file holds no numeric variable",
                    OCTAVE_FILE_FORM,
                    ErrorKind::Data,
                )
            })?,
    };
    let names: Vec<&str> = ws.names().collect();
    let array = ws.array(&name).map_err(|e| {
        CliError::new(
            argument,
            e.to_string(),
            format!("one of the numeric variables {}", names.join(", ")),
            ErrorKind::Data,
        )
    })?;
    Ok((name, array))
}

/// A stored double as a scalar: itself for `f64`; for rationals the shortest decimal that
/// reads back to it (so that `0.1` as written by Octave is 1/10).
pub fn scalar_from_double<T: LiteralScalar>(x: f64) -> Option<T> {
    if !x.is_finite() {
        return None;
    }
    if T::EXACT {
        cagd_octave::literal::parse_number::<T>(&format!("{x:e}"))
    } else {
        T::from_f64(x)
    }
}

fn array_to_scalars<T: LiteralScalar>(
    argument: &str,
    a: &ndarray::ArrayD<f64>,
) -> Result<ndarray::ArrayD<T>, CliError> {
    let mut out = Vec::with_capacity(a.len());
    for (k, x) in a.iter().enumerate() {
        out.push(scalar_from_double::<T>(*x).ok_or_else(|| {
            CliError::new(
                argument,
                format!("value {} is not finite", k + 1),
                "finite numbers",
                ErrorKind::Data,
            )
        })?);
    }
    Ok(ndarray::ArrayD::from_shape_vec(a.raw_dim(), out).expect("same number of elements"))
}

/// Parses the contents of a data file: Octave `save -text` (the first numeric variable) or
/// plain numeric text.
///
/// ```
/// // (no line of the literal may start with `#`: rustdoc would hide it)
/// let text = concat!(
///     "# name: s\n# type: string\n# elements: 1\n# length: 1\nx\n\n",
///     "# name: B\n# type: matrix\n# rows: 1\n# columns: 2\n 1 0.5\n",
/// );
/// let m = cagd_cli::parse_data_text::<f64>(&cagd::Limits::default(), "--control", text).unwrap();
/// assert_eq!(m, nalgebra::DMatrix::from_row_slice(1, 2, &[1.0, 0.5]));
/// ```
pub fn parse_data_text<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    contents: &str,
) -> Result<DMatrix<T>, CliError> {
    parse_data_text_variable(limits, argument, contents, None)
}

/// [`parse_data_text`] choosing the variable of an Octave text file by name.
pub fn parse_data_text_variable<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    contents: &str,
    variable: Option<&str>,
) -> Result<DMatrix<T>, CliError> {
    if is_octave_text(contents) || variable.is_some() {
        let (name, array) = read_octave_array(limits, argument, contents, variable)?;
        if array.ndim() != 2 {
            return Err(CliError::new(
                argument,
                format!("`{name}` has {} dimensions", array.ndim()),
                "a 2-D matrix",
                ErrorKind::Shape,
            ));
        }
        let a = array_to_scalars::<T>(argument, &array)?;
        let (r, c) = (a.shape()[0], a.shape()[1]);
        return Ok(DMatrix::from_fn(r, c, |i, j| a[[i, j]].clone()));
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

/// Loads a Bézier control net: an Octave `save -text` file holding an
/// `(m+1) × (n+1) × d` array (as `tenzor` produces), or any matrix argument in the packed
/// layout of the thesis's `ploskevB`, `(m+1) × 3(n+1)`, whose row `i` is
/// `[b_i0 b_i1 … b_in]` with each point's three coordinates side by side.
///
/// ```
/// let net = cagd_cli::load_net::<f64>(&cagd::Limits::default(), "NET", "[0 0 0 0 1 0; 1 0 0 1 1 1]", None).unwrap();
/// assert_eq!(net.dim(), (2, 2, 3));
/// assert_eq!(net[[1, 1, 2]], 1.0);
/// ```
pub fn load_net<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
) -> Result<PointGrid<T>, CliError> {
    let trimmed = text.trim();
    let is_variable = script.is_some_and(|s| s.get(trimmed).is_some());
    let file = if is_variable {
        None
    } else if let Some((path, variable)) = split_variable(trimmed) {
        Some((path, Some(variable)))
    } else if trimmed != "-" && is_file(trimmed) {
        Some((trimmed, None))
    } else {
        None
    };
    if let Some((path, variable)) = file {
        let contents = read_text(limits, argument, path)?;
        if is_octave_text(&contents) {
            let shown = format!("{argument} {trimmed}");
            let (_, array) = read_octave_array(limits, &shown, &contents, variable)?;
            if array.ndim() == 3 {
                let a = array_to_scalars::<T>(&shown, &array)?;
                let s = a.shape().to_vec();
                return Ok(PointGrid::from_shape_fn((s[0], s[1], s[2]), |(i, j, k)| {
                    a[[i, j, k]].clone()
                }));
            }
        }
    }
    let packed = load_matrix::<T>(limits, argument, text, script)?;
    unpack_net(argument, &packed)
}

/// Unpacks the thesis's `(m+1) × 3(n+1)` net into an `(m+1) × (n+1) × 3` array (`tenzor`).
pub fn unpack_net<T: LiteralScalar>(
    argument: &str,
    packed: &DMatrix<T>,
) -> Result<PointGrid<T>, CliError> {
    let (rows, cols) = packed.shape();
    if rows == 0 || cols == 0 || cols % 3 != 0 {
        return Err(CliError::new(
            argument,
            format!("the net is {rows}×{cols}"),
            "a packed (m+1)×3(n+1) net as ploskevB takes it, row i = [b_i0 b_i1 … b_in] with x y z side by side, or an Octave (m+1)×(n+1)×3 array file",
            ErrorKind::Shape,
        ));
    }
    Ok(PointGrid::from_shape_fn(
        (rows, cols / 3, 3),
        |(i, j, k)| packed[(i, 3 * j + k)].clone(),
    ))
}

/// Parses plain numeric text: one matrix row per line, numbers separated by white space,
/// commas or semicolons; blank lines and `#`/`%` comments are skipped. The error is the
/// line number (from 1) and what was wrong.
///
/// ```
/// let m = cagd_cli::parse_numeric_text::<f64>("# x y\n1, 2\n3\t4\n").unwrap();
/// assert_eq!(m, nalgebra::DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 3.0, 4.0]));
/// assert!(cagd_cli::parse_numeric_text::<f64>("1 2\n3\n").is_err());
/// assert!(cagd_cli::parse_numeric_text::<f64>("1 Inf\n").is_err());
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
            let x = cagd_octave::literal::parse_number::<T>(f).ok_or_else(|| {
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
    if (n as u128) * (w as u128) > cagd::limits::Limits::default().max_elements as u128 {
        return Err((n, "too many values".into()));
    }
    Ok(DMatrix::from_fn(n, w, |i, j| rows[i][j].clone()))
}

/// Parses a parameter argument (`--t`, `--u`, `--v`): a number, a list or a range; at least
/// one value.
///
/// ```
/// let t = cagd_cli::load_params::<f64>(&cagd::Limits::default(), "--t", "[0 0.5 1]").unwrap();
/// assert_eq!(t, vec![0.0, 0.5, 1.0]);
/// assert!(cagd_cli::load_params::<f64>(&cagd::Limits::default(), "--t", "[0 0; 1 1]").is_err());
/// ```
pub fn load_params<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
) -> Result<Vec<T>, CliError> {
    crate::slips::decimal_commas(argument, text);
    let (values, warnings) = cagd_octave::literal::parse_params_warning::<T>(text, limits)
        .map_err(|e| CliError::literal(argument, e, PARAMS_FORM))?;
    refuse_lenient(argument, warnings, PARAMS_FORM)?;
    if values.is_empty() {
        return Err(CliError::new(
            argument,
            format!("`{}` has no values", text.trim()),
            PARAMS_FORM,
            ErrorKind::Shape,
        ));
    }
    limits
        .check_samples("parameter values", values.len())
        .map_err(|e| CliError::library(argument, e, PARAMS_FORM))?;
    Ok(values)
}

/// `linspace(0, 1, n)` for `--n`, requiring `n ≥ min` (2 for grids: a grid needs both
/// ends). Octave's doubles for `f64`, exact `i/(n−1)` for rationals.
///
/// ```
/// assert_eq!(cagd_cli::samples::<f64>(&cagd::Limits::default(), 5, 2).unwrap(), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
/// assert!(cagd_cli::samples::<f64>(&cagd::Limits::default(), 1, 2).is_err());
/// ```
pub fn samples<T: LiteralScalar>(
    limits: &Limits,
    n: usize,
    min: usize,
) -> Result<Vec<T>, CliError> {
    let max = limits.max_samples;
    if n < min {
        return Err(CliError::new(
            "--n",
            format!("N = {n} is too small"),
            format!("an integer N with {min} ≤ N ≤ {max} (samples linspace(0,1,N))"),
            ErrorKind::Shape,
        ));
    }
    limits.check_samples("samples N", n).map_err(|e| {
        CliError::library(
            "--n",
            e,
            &format!("an integer N with {min} ≤ N ≤ {max} (samples linspace(0,1,N))"),
        )
    })?;
    Ok(T::linspace(&T::zero(), &T::one(), n))
}

/// Parses a curve or surface expression argument, in the context of `script` (whose curves
/// it may name: `--c1 c1`).
pub fn load_expression<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
) -> Result<ParamExpr, CliError> {
    match script {
        Some(s) => s.resolve(text),
        None => ParamExpr::parse_with(text, limits),
    }
    .map_err(|e| CliError::literal(argument, e, CURVE_FORM))
}

/// Runs a data script (`--script FILE`, or `-` for standard input) with `initial` variables.
pub fn load_script<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    path: &str,
    initial: Env<T>,
) -> Result<Script<T>, CliError> {
    let source = read_text(limits, argument, path)?;
    cagd_octave::script::run(&source, initial).map_err(|e| {
        CliError::literal(
            format!("{argument} {path}"),
            e,
            "an Octave data script of assignments and for loops",
        )
    })
}

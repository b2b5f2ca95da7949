//! GNU Octave's text file format: what `save -text` writes and `load` reads.
//!
//! Every expected number of the crate's tests is written by Octave in this format, and data moves
//! between the crate and Octave scripts through it. The reader accepts what Octave 7 writes for
//! the types below; the writer produces files that Octave's `load` reads back to identical values
//! (checked against live Octave by `tests/octave_format.rs`).
//!
//! # The format
//!
//! A file is a list of named variables, each introduced by two header lines and followed by its
//! data (lines starting with `#` before the first `# name:`, such as
//! `# Created by Octave 7.3.0, …`, are comments):
//!
//! ```text
//! # name: P
//! # type: matrix
//! # rows: 2
//! # columns: 3
//!  0 8 4
//!  0 2 0.10000000000000001
//! ```
//!
//! | `# type:` | [`Value`] | data |
//! |---|---|---|
//! | `scalar` | [`Value::Scalar`] | one number |
//! | `matrix` | [`Value::Matrix`] | `# rows:`/`# columns:` and one line per row, or `# ndims:`, the dimensions, and one value per line in column-major order |
//! | `double_range` (`range`) | [`Value::Range`] | `# base, limit, increment` and the three numbers |
//! | `bool` / `bool matrix` | [`Value::Bool`] / [`Value::BoolMatrix`] | as scalar / matrix, with `0`/`1` |
//! | `sq_string` / `string` | [`Value::Str`] | `# elements:` (rows), then per row `# length:` and the row's bytes |
//! | `scalar struct` | [`Value::Struct`] | `# ndims: 2`, ` 1 1`, `# length:` (fields), then each field as a named variable |
//! | `cell` | [`Value::Cell`] | `# rows:`/`# columns:` or `# ndims:`, then each element (column-major) as a variable named `<cell-element>` |
//!
//! Numbers are decimal (`%.17g` with `save_precision(17)`), plus `Inf`, `-Inf`, `NaN` and `NA`
//! (Octave's "missing value", a NaN with the payload `0x7FF840F440000000`, kept distinct here
//! so that it survives a round trip).
//!
//! Complex values, integer types, struct arrays, sparse matrices and function handles are not
//! supported: reading them gives [`TextFormatError::Unsupported`].
//!
//! # Array layout
//!
//! Matrices and N-d arrays are [`ndarray::ArrayD<f64>`] indexed exactly as in Octave, from 0:
//! `a[[i, j, k]]` is Octave's `A(i+1, j+1, k+1)`. Octave writes N-d data column-major (first index
//! fastest), one value per line; the reader and writer convert.
//!
//! Plain numeric text, as written by `save -ascii` and `dlmwrite`, is read by
//! [`read_numeric_text`].
//!
//! # Example
//!
//! ```
//! use cagd::octave::text_format::{read_text, write_text, Value, Workspace};
//! use ndarray::array;
//!
//! let mut ws = Workspace::new();
//! ws.insert("P", Value::from(array![[0.0, 8.0, 4.0], [0.0, 2.0, 0.1]]));
//! ws.insert("N", Value::Scalar(3.0));
//! let text = write_text(&ws)?;
//! assert!(text.contains("# name: P\n# type: matrix\n# rows: 2\n# columns: 3\n 0 8 4\n 0 2 0.1\n"));
//! let back = read_text(&text)?;
//! assert_eq!(back, ws);
//! assert_eq!(back.matrix("P")?[[1, 2]], 0.1);
//! # Ok::<(), cagd::octave::TextFormatError>(())
//! ```

use std::fmt::Write as _;
use std::path::Path;

use ndarray::{Array2, ArrayD, IxDyn, ShapeBuilder};
use thiserror::Error;

/// Bit pattern of Octave's `NA` ("missing value"): a quiet NaN with a particular payload.
pub const NA_BITS: u64 = 0x7FF8_40F4_4000_0000;

/// Octave's `NA` as a double. `na().is_nan()` holds; use [`is_na`] to tell it from other NaNs.
///
/// ```
/// use cagd::octave::text_format::{is_na, na};
/// assert!(na().is_nan() && is_na(na()));
/// ```
pub fn na() -> f64 {
    f64::from_bits(NA_BITS)
}

/// Whether `x` is Octave's `NA` (and not just any NaN).
///
/// ```
/// use cagd::octave::text_format::{is_na, na};
/// assert!(is_na(na()));
/// assert!(!is_na(f64::NAN));
/// ```
pub fn is_na(x: f64) -> bool {
    x.to_bits() == NA_BITS
}

/// What can be wrong with an Octave text file, or with a value asked of it.
///
/// Every reading error carries the 1-based line number where the problem was found.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum TextFormatError {
    /// The file ended while more was expected.
    #[error("line {line}: unexpected end of file: expected {expected}")]
    Truncated {
        /// The line after the last line of the file.
        line: usize,
        /// What was still expected, in words.
        expected: String,
    },
    /// A header line (`# name:`, `# type:`, `# rows:`, …) is missing or malformed.
    #[error("line {line}: expected `{expected}`, found `{found}`")]
    BadHeader {
        /// Line of the offending text.
        line: usize,
        /// The header expected, e.g. `# rows: <count>`.
        expected: String,
        /// The text found instead.
        found: String,
    },
    /// A `# type:` that Octave does not write (or that is misspelt).
    #[error("line {line}: unknown type `{type_name}`")]
    UnknownType {
        /// Line of the `# type:` header.
        line: usize,
        /// The type name found.
        type_name: String,
    },
    /// A type Octave writes but this reader does not support (complex, integer, struct array,
    /// sparse, function handle, N-d char array, …).
    #[error("line {line}: type `{type_name}` is not supported")]
    Unsupported {
        /// Line of the `# type:` header (or of the unsupported detail).
        line: usize,
        /// The type name found.
        type_name: String,
    },
    /// A token that should be a number is not one.
    #[error("line {line}: `{token}` is not a number")]
    NotANumber {
        /// Line of the token.
        line: usize,
        /// The token.
        token: String,
    },
    /// A data line holds the wrong number of values (for a matrix: not `# columns:`; for plain
    /// numeric text: not as many as the first row).
    #[error("line {line}: expected {expected} value(s) on the line, found {found}")]
    WrongCount {
        /// Line of the data.
        line: usize,
        /// The number of values expected.
        expected: usize,
        /// The number found.
        found: usize,
    },
    /// Fewer data lines than the header declared (`# rows:` too large, or a truncated array).
    #[error("line {line}: `{name}` declares {declared} data line(s) but only {found} follow")]
    MissingData {
        /// Line where the next data line was expected.
        line: usize,
        /// The variable being read.
        name: String,
        /// The number of data lines the header declared.
        declared: usize,
        /// The number found.
        found: usize,
    },
    /// Data where a `# name:` line was expected: more data lines than the header declared (for
    /// example a `# rows:` that is too small), or text outside any variable.
    #[error("line {line}: unexpected data `{found}` (more data lines than declared?)")]
    UnexpectedData {
        /// Line of the data.
        line: usize,
        /// The text found.
        found: String,
    },
    /// A string's bytes do not match its `# length:` or are not valid UTF-8.
    #[error("line {line}: bad string data: {message}")]
    BadString {
        /// Line of the string data.
        line: usize,
        /// What was wrong.
        message: String,
    },
    /// The file could not be read or written.
    #[error("{path}: {message}")]
    Io {
        /// The file.
        path: String,
        /// The operating system's message.
        message: String,
    },
    /// A variable asked for is not in the file.
    #[error("no variable `{name}`")]
    MissingVariable {
        /// The name asked for.
        name: String,
    },
    /// A variable has another type or shape than asked for.
    #[error("variable `{name}`: expected {expected}, found {found}")]
    WrongType {
        /// The variable.
        name: String,
        /// What was asked for, e.g. `a 2-D numeric matrix`.
        expected: String,
        /// What the variable is.
        found: String,
    },
    /// The writer was given something Octave cannot load: an invalid variable or field name,
    /// a char matrix with rows of different lengths, a string row containing a newline where
    /// it would be ambiguous.
    #[error("cannot write `{name}`: {message}")]
    Unwritable {
        /// The variable (or `variable.field`).
        name: String,
        /// What is wrong.
        message: String,
    },
}

/// `Result` of this module.
pub type Result<T, E = TextFormatError> = std::result::Result<T, E>;

/// How a character matrix was quoted in Octave: `'…'` (`sq_string`) or `"…"` (`string`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Quote {
    /// Single-quoted, `# type: sq_string` (Octave's default for `'text'`).
    #[default]
    Single,
    /// Double-quoted, `# type: string`.
    Double,
}

/// A character matrix: `rows.len()` rows, all of the same length in bytes (Octave stores UTF-8
/// text as bytes, so `'é'` is a 1×2 char array). `''` is a matrix with no rows.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct CharMatrix {
    /// The rows, top to bottom.
    pub rows: Vec<String>,
    /// How Octave quotes it.
    pub quote: Quote,
}

impl CharMatrix {
    /// A one-row, single-quoted string.
    pub fn new(text: impl Into<String>) -> Self {
        CharMatrix {
            rows: vec![text.into()],
            quote: Quote::Single,
        }
    }
}

/// One Octave value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A real double, `# type: scalar`.
    Scalar(f64),
    /// A real double array of two or more dimensions, `# type: matrix`, indexed as in Octave
    /// (`a[[i, j]]` is `A(i+1, j+1)`). The writer writes a 0-d array as 1×1 and a 1-d array as
    /// a row vector.
    Matrix(ArrayD<f64>),
    /// A range such as `1:3`, `# type: double_range`, kept as Octave stores it. See
    /// [`Value::to_array`] for its elements.
    Range {
        /// First element.
        base: f64,
        /// Upper (or, for a negative increment, lower) limit.
        limit: f64,
        /// Step.
        increment: f64,
    },
    /// A logical scalar, `# type: bool`.
    Bool(bool),
    /// A logical array, `# type: bool matrix`.
    BoolMatrix(ArrayD<bool>),
    /// A character matrix, `# type: sq_string` or `string`.
    Str(CharMatrix),
    /// A scalar struct, `# type: scalar struct`: fields in order.
    Struct(Vec<(String, Value)>),
    /// A cell array, `# type: cell`, indexed as in Octave.
    Cell(ArrayD<Value>),
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Scalar(x)
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Self {
        Value::Bool(b)
    }
}

impl From<&str> for Value {
    fn from(s: &str) -> Self {
        Value::Str(CharMatrix::new(s))
    }
}

impl From<Array2<f64>> for Value {
    fn from(a: Array2<f64>) -> Self {
        Value::Matrix(a.into_dyn())
    }
}

impl From<ArrayD<f64>> for Value {
    fn from(a: ArrayD<f64>) -> Self {
        Value::Matrix(a)
    }
}

impl Value {
    /// A short description of the type, as in error messages (`matrix 3x4`, `scalar`, …).
    pub fn describe(&self) -> String {
        fn dims(shape: &[usize]) -> String {
            shape
                .iter()
                .map(|d| d.to_string())
                .collect::<Vec<_>>()
                .join("x")
        }
        match self {
            Value::Scalar(_) => "scalar".into(),
            Value::Matrix(a) => format!("matrix {}", dims(a.shape())),
            Value::Range { .. } => "range".into(),
            Value::Bool(_) => "bool".into(),
            Value::BoolMatrix(a) => format!("bool matrix {}", dims(a.shape())),
            Value::Str(s) => format!("string with {} row(s)", s.rows.len()),
            Value::Struct(f) => format!("scalar struct with {} field(s)", f.len()),
            Value::Cell(c) => format!("cell {}", dims(c.shape())),
        }
    }

    /// The numbers of a numeric value as an N-d array (at least 2-D, like Octave): a scalar is
    /// 1×1, a range is expanded to a row. `None` for other types.
    ///
    /// A range `base:increment:limit` has `floor((limit-base)/increment) + 1` elements
    /// `base + i*increment` (with a relative allowance of a few ULPs in the count, so that
    /// `0:0.1:1` has 11 elements); the last element is clipped to `limit`. This is exact for
    /// integer ranges; for fractional ranges Octave's own elements may differ in the last bit.
    /// Ranges of more elements than [`crate::limits::Limits::max_elements`] (4 000 000 by
    /// default) give `None`.
    pub fn to_array(&self) -> Option<ArrayD<f64>> {
        match self {
            Value::Scalar(x) => Some(ArrayD::from_elem(IxDyn(&[1, 1]), *x)),
            Value::Matrix(a) => Some(match a.ndim() {
                0 => a.clone().into_shape_with_order(IxDyn(&[1, 1])).ok()?,
                1 => a.clone().into_shape_with_order(IxDyn(&[1, a.len()])).ok()?,
                _ => a.clone(),
            }),
            Value::Range {
                base,
                limit,
                increment,
            } => {
                let n = range_count(*base, *limit, *increment)?;
                let row: Vec<f64> = (0..n)
                    .map(|i| {
                        let x = base + i as f64 * increment;
                        if (*increment > 0.0 && x > *limit) || (*increment < 0.0 && x < *limit) {
                            *limit
                        } else {
                            x
                        }
                    })
                    .collect();
                ArrayD::from_shape_vec(IxDyn(&[1, n]), row).ok()
            }
            _ => None,
        }
    }

    /// The numbers of a numeric value as a 2-D matrix (see [`Value::to_array`]); `None` for
    /// other types and for arrays of more than two dimensions.
    pub fn to_matrix(&self) -> Option<Array2<f64>> {
        self.to_array()?.into_dimensionality().ok()
    }

    /// The value of a scalar (or of a 1×1 matrix).
    pub fn to_scalar(&self) -> Option<f64> {
        match self {
            Value::Scalar(x) => Some(*x),
            Value::Matrix(a) if a.len() == 1 => a.iter().next().copied(),
            _ => None,
        }
    }

    /// The text of a one-row string (`''` gives `""`).
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::Str(s) if s.rows.len() == 1 => Some(&s.rows[0]),
            Value::Str(s) if s.rows.is_empty() => Some(""),
            _ => None,
        }
    }

    /// A field of a scalar struct.
    pub fn field(&self, name: &str) -> Option<&Value> {
        match self {
            Value::Struct(fields) => fields.iter().find(|(n, _)| n == name).map(|(_, v)| v),
            _ => None,
        }
    }
}

/// The number of elements of the range `base:increment:limit`.
fn range_count(base: f64, limit: f64, increment: f64) -> Option<usize> {
    if increment == 0.0
        || !(base.is_finite() && limit.is_finite() && increment.is_finite())
        || (increment > 0.0 && limit < base)
        || (increment < 0.0 && limit > base)
    {
        return Some(0);
    }
    let q = (limit - base) / increment;
    // Allow a few ULPs, as Octave does, so that 0:0.1:1 has 11 elements and not 10.
    let n = (q + q.abs() * 4.0 * f64::EPSILON).floor();
    // A malformed file must not make the reader allocate without bound: a range is expanded
    // only up to the element limit in force (found by fuzzing: `1 16666666666 8` asked for
    // 16 GB).
    if n >= crate::limits::Limits::current().max_elements as f64 {
        return None;
    }
    Some(n as usize + 1)
}

/// The variables of one file, in order (as `save` wrote them and `load` returns them).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Workspace {
    vars: Vec<(String, Value)>,
}

impl Workspace {
    /// An empty list.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a variable, or replaces the value of one of the same name (keeping its position).
    pub fn insert(&mut self, name: impl Into<String>, value: impl Into<Value>) {
        let name = name.into();
        let value = value.into();
        match self.vars.iter_mut().find(|(n, _)| *n == name) {
            Some(slot) => slot.1 = value,
            None => self.vars.push((name, value)),
        }
    }

    /// The value of a variable.
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.vars.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }

    /// The variable names, in order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.vars.iter().map(|(n, _)| n.as_str())
    }

    /// The variables, in order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.vars.iter().map(|(n, v)| (n.as_str(), v))
    }

    /// The number of variables.
    pub fn len(&self) -> usize {
        self.vars.len()
    }

    /// Whether there are no variables.
    pub fn is_empty(&self) -> bool {
        self.vars.is_empty()
    }

    fn require(&self, name: &str) -> Result<&Value> {
        self.get(name)
            .ok_or_else(|| TextFormatError::MissingVariable { name: name.into() })
    }

    /// A numeric variable as an N-d array (see [`Value::to_array`]).
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`] if it is not
    /// numeric.
    pub fn array(&self, name: &str) -> Result<ArrayD<f64>> {
        let v = self.require(name)?;
        v.to_array().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a numeric array".into(),
            found: v.describe(),
        })
    }

    /// A numeric variable as a 2-D matrix (a scalar is 1×1).
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`] if it is not
    /// numeric or has more than two dimensions.
    pub fn matrix(&self, name: &str) -> Result<Array2<f64>> {
        let v = self.require(name)?;
        v.to_matrix().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a 2-D numeric matrix".into(),
            found: v.describe(),
        })
    }

    /// A numeric variable holding one number.
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`].
    pub fn scalar(&self, name: &str) -> Result<f64> {
        let v = self.require(name)?;
        v.to_scalar().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a scalar".into(),
            found: v.describe(),
        })
    }

    /// A one-row string variable.
    ///
    /// # Errors
    /// [`TextFormatError::MissingVariable`], or [`TextFormatError::WrongType`].
    pub fn string(&self, name: &str) -> Result<&str> {
        let v = self.require(name)?;
        v.as_str().ok_or_else(|| TextFormatError::WrongType {
            name: name.into(),
            expected: "a one-row string".into(),
            found: v.describe(),
        })
    }
}

impl FromIterator<(String, Value)> for Workspace {
    fn from_iter<I: IntoIterator<Item = (String, Value)>>(iter: I) -> Self {
        let mut ws = Workspace::new();
        for (n, v) in iter {
            ws.insert(n, v);
        }
        ws
    }
}

// ---------------------------------------------------------------------------------------------
// Reading

/// A cursor over the text that knows its line number.
struct Cursor<'a> {
    text: &'a str,
    pos: usize,
    /// 1-based number of the line that starts at `pos`.
    line: usize,
}

impl<'a> Cursor<'a> {
    fn new(text: &'a str) -> Self {
        Cursor {
            text,
            pos: 0,
            line: 1,
        }
    }

    fn at_end(&self) -> bool {
        self.pos >= self.text.len()
    }

    /// The next line without consuming it (without its `\n` and a trailing `\r`).
    fn peek(&self) -> Option<&'a str> {
        if self.at_end() {
            return None;
        }
        let rest = &self.text[self.pos..];
        let end = rest.find('\n').unwrap_or(rest.len());
        Some(rest[..end].strip_suffix('\r').unwrap_or(&rest[..end]))
    }

    /// Consumes the next line; returns its number and text.
    fn next_line(&mut self) -> Option<(usize, &'a str)> {
        let line = self.peek()?;
        let rest = &self.text[self.pos..];
        let end = rest.find('\n').map_or(rest.len(), |e| e + 1);
        self.pos += end;
        let n = self.line;
        self.line += 1;
        Some((n, line))
    }

    fn skip_blank(&mut self) {
        while let Some(l) = self.peek() {
            if !l.trim().is_empty() {
                break;
            }
            self.next_line();
        }
    }

    fn truncated(&self, expected: impl Into<String>) -> TextFormatError {
        TextFormatError::Truncated {
            line: self.line,
            expected: expected.into(),
        }
    }

    /// Reads the header `# key: value` and returns its line number and value.
    fn header(&mut self, key: &str) -> Result<(usize, &'a str)> {
        let (line, text) = self
            .next_line()
            .ok_or_else(|| self.truncated(format!("`# {key}:`")))?;
        parse_header(text, key)
            .map(|v| (line, v))
            .ok_or_else(|| TextFormatError::BadHeader {
                line,
                expected: format!("# {key}: …"),
                found: text.into(),
            })
    }

    fn count_header(&mut self, key: &str) -> Result<usize> {
        let (line, value) = self.header(key)?;
        value.parse().map_err(|_| TextFormatError::BadHeader {
            line,
            expected: format!("# {key}: <count>"),
            found: format!("# {key}: {value}"),
        })
    }

    /// Reads exactly `n` bytes of string data plus the newline that ends them.
    fn string_bytes(&mut self, n: usize) -> Result<&'a str> {
        let start_line = self.line;
        let end = match self.pos.checked_add(n) {
            Some(end) if end <= self.text.len() => end,
            _ => return Err(self.truncated(format!("{n} byte(s) of string data"))),
        };
        if end > self.text.len() {
            return Err(self.truncated(format!("{n} byte(s) of string data")));
        }
        if !self.text.is_char_boundary(end) {
            return Err(TextFormatError::BadString {
                line: start_line,
                message: format!("`# length: {n}` ends inside a UTF-8 character"),
            });
        }
        let s = &self.text[self.pos..end];
        self.line += s.matches('\n').count();
        self.pos = end;
        match self.text[self.pos..].chars().next() {
            None => {}
            Some('\n') => {
                self.pos += 1;
                self.line += 1;
            }
            Some('\r') if self.text[self.pos..].starts_with("\r\n") => {
                self.pos += 2;
                self.line += 1;
            }
            Some(_) => {
                return Err(TextFormatError::BadString {
                    line: self.line,
                    message: format!("the row is longer than its `# length: {n}`"),
                })
            }
        }
        Ok(s)
    }
}

fn parse_header<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    let rest = text.strip_prefix('#')?.trim_start();
    let rest = rest.strip_prefix(key)?;
    let rest = rest.strip_prefix(':')?;
    Some(rest.trim())
}

/// Parses one number as Octave writes it: decimal, `Inf`, `-Inf`, `NaN`, `NA`.
fn parse_number(token: &str, line: usize) -> Result<f64> {
    let lower = token.to_ascii_lowercase();
    let (neg, body) = match lower.strip_prefix('-') {
        Some(b) => (true, b),
        None => (false, lower.strip_prefix('+').unwrap_or(&lower)),
    };
    let special = match body {
        "inf" | "infinity" => Some(f64::INFINITY),
        "nan" => Some(f64::NAN),
        "na" => Some(na()),
        _ => None,
    };
    if let Some(x) = special {
        return Ok(if neg && !x.is_nan() { -x } else { x });
    }
    // Rust's parser is correctly rounded, like the C library Octave uses, but also accepts
    // spellings Octave never writes; only digits, sign, point and exponent get this far.
    let plausible = !body.is_empty()
        && body
            .bytes()
            .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'+' | b'-'));
    match token.parse::<f64>() {
        Ok(x) if plausible => Ok(x),
        _ => Err(TextFormatError::NotANumber {
            line,
            token: token.into(),
        }),
    }
}

fn parse_numbers(text: &str, line: usize, expected: usize) -> Result<Vec<f64>> {
    let tokens: Vec<&str> = text.split_whitespace().collect();
    if tokens.len() != expected {
        // A token that is not a number says more than a wrong count.
        for t in &tokens {
            parse_number(t, line)?;
        }
        return Err(TextFormatError::WrongCount {
            line,
            expected,
            found: tokens.len(),
        });
    }
    tokens.iter().map(|t| parse_number(t, line)).collect()
}

/// Reads `count` data lines of `per_line` values each, for the variable `name`.
fn data_lines(cur: &mut Cursor<'_>, name: &str, count: usize, per_line: usize) -> Result<Vec<f64>> {
    // No preallocation from the header's counts: they are not trusted.
    let mut out = Vec::new();
    for k in 0..count {
        let missing = |line| TextFormatError::MissingData {
            line,
            name: name.into(),
            declared: count,
            found: k,
        };
        match cur.peek() {
            None => return Err(missing(cur.line)),
            Some(l) if l.trim_start().starts_with('#') || l.trim().is_empty() => {
                return Err(missing(cur.line))
            }
            Some(_) => {}
        }
        let (line, text) = cur.next_line().expect("peeked");
        out.extend(parse_numbers(text, line, per_line)?);
    }
    Ok(out)
}

/// Reads `# ndims:` and the dimension line.
fn dims(cur: &mut Cursor<'_>) -> Result<Vec<usize>> {
    let nd = cur.count_header("ndims")?;
    let (line, text) = cur
        .next_line()
        .ok_or_else(|| cur.truncated("the dimensions after `# ndims:`"))?;
    let d: Vec<usize> = text
        .split_whitespace()
        .map(|t| {
            t.parse().map_err(|_| TextFormatError::BadHeader {
                line,
                expected: format!("{nd} dimension(s)"),
                found: text.into(),
            })
        })
        .collect::<Result<_>>()?;
    if d.len() != nd || nd < 2 {
        return Err(TextFormatError::BadHeader {
            line,
            expected: format!("{nd} dimension(s), at least 2"),
            found: text.into(),
        });
    }
    Ok(d)
}

/// The number of elements of an array of this shape, or an error if it cannot exist.
fn element_count(shape: &[usize], line: usize) -> Result<usize> {
    // No length may exceed the element limit, even in an empty array: Octave writes one
    // (blank) line per row of an R×0 matrix, so a 20 000 000×0 matrix in a 200-byte file
    // would be written back as 20 MB (found by fuzzing).
    let max = crate::limits::Limits::current().max_elements;
    if let Some(&too_long) = shape.iter().find(|&&d| d > max) {
        return Err(TextFormatError::BadHeader {
            line,
            expected: format!(
                "array lengths of at most {max} (the element limit: --max-elements or \
                 CAGD_MAX_ELEMENTS)"
            ),
            found: format!("a length of {too_long}"),
        });
    }
    // Like ndarray, also bound the product of the non-zero lengths: a 2^64 x 0 array has no
    // elements but no valid shape either.
    let nonzero = shape
        .iter()
        .filter(|&&d| d != 0)
        .try_fold(1usize, |acc, &d| acc.checked_mul(d))
        .filter(|&n| n <= isize::MAX as usize);
    match nonzero {
        Some(n) if !shape.contains(&0) => Ok(n),
        Some(_) => Ok(0),
        None => Err(TextFormatError::BadHeader {
            line,
            expected: "dimensions of an array that fits in memory".into(),
            found: format!("{shape:?}"),
        }),
    }
}

/// Reads a numeric matrix body (after `# type:`): `# rows:`/`# columns:` or `# ndims:`.
fn numeric_array(cur: &mut Cursor<'_>, name: &str) -> Result<ArrayD<f64>> {
    let starts_nd = cur.peek().and_then(|l| parse_header(l, "ndims")).is_some();
    if starts_nd {
        let shape = dims(cur)?;
        let total = element_count(&shape, cur.line - 1)?;
        let data = data_lines(cur, name, total, 1)?;
        Ok(ArrayD::from_shape_vec(IxDyn(&shape).f(), data).expect("sizes checked"))
    } else {
        let rows = cur.count_header("rows")?;
        let cols = cur.count_header("columns")?;
        element_count(&[rows, cols], cur.line - 1)?;
        // An R x 0 matrix has no data lines at all.
        let data = if cols == 0 {
            Vec::new()
        } else {
            data_lines(cur, name, rows, cols)?
        };
        Ok(ArrayD::from_shape_vec(IxDyn(&[rows, cols]), data).expect("sizes checked"))
    }
}

fn to_bool(a: ArrayD<f64>, line: usize) -> Result<ArrayD<bool>> {
    if let Some(bad) = a.iter().find(|&&x| x != 0.0 && x != 1.0) {
        return Err(TextFormatError::NotANumber {
            line,
            token: format!("{bad} (a bool must be 0 or 1)"),
        });
    }
    Ok(a.mapv(|x| x == 1.0))
}

const UNSUPPORTED: &[&str] = &[
    "complex scalar",
    "complex matrix",
    "float complex scalar",
    "float complex matrix",
    "float scalar",
    "float matrix",
    "struct",
    "sparse matrix",
    "sparse complex matrix",
    "sparse bool matrix",
    "function handle",
    "inline function",
    "diagonal matrix",
    "complex diagonal matrix",
    "permutation matrix",
    "null_matrix",
    "null_string",
    "null_sq_string",
    "object",
    "class",
];

fn is_int_type(t: &str) -> bool {
    let base = t
        .strip_suffix(" scalar")
        .or_else(|| t.strip_suffix(" matrix"))
        .unwrap_or("");
    matches!(
        base,
        "int8" | "int16" | "int32" | "int64" | "uint8" | "uint16" | "uint32" | "uint64"
    )
}

/// Reads the value of the variable `name` whose `# type:` header (on `type_line`) said
/// `type_name`.
fn value(cur: &mut Cursor<'_>, name: &str, type_name: &str, type_line: usize) -> Result<Value> {
    let type_name = type_name.strip_prefix("global ").unwrap_or(type_name);
    match type_name {
        "scalar" => Ok(Value::Scalar(data_lines(cur, name, 1, 1)?[0])),
        "matrix" => Ok(Value::Matrix(numeric_array(cur, name)?)),
        "bool" => {
            let x = data_lines(cur, name, 1, 1)?[0];
            let b = to_bool(ArrayD::from_elem(IxDyn(&[1]), x), cur.line - 1)?;
            Ok(Value::Bool(b[[0]]))
        }
        "bool matrix" => {
            let first = cur.line;
            let a = numeric_array(cur, name)?;
            Ok(Value::BoolMatrix(to_bool(a, first)?))
        }
        "double_range" | "range" => {
            let (line, text) = cur
                .next_line()
                .ok_or_else(|| cur.truncated("`# base, limit, increment`"))?;
            if !text.starts_with('#') {
                return Err(TextFormatError::BadHeader {
                    line,
                    expected: "# base, limit, increment".into(),
                    found: text.into(),
                });
            }
            let v = data_lines(cur, name, 1, 3)?;
            Ok(Value::Range {
                base: v[0],
                limit: v[1],
                increment: v[2],
            })
        }
        "sq_string" | "string" => {
            let quote = if type_name == "string" {
                Quote::Double
            } else {
                Quote::Single
            };
            if cur.peek().and_then(|l| parse_header(l, "ndims")).is_some() {
                return Err(TextFormatError::Unsupported {
                    line: cur.line,
                    type_name: format!("{type_name} with `# ndims:` (N-d char array)"),
                });
            }
            let elements = cur.count_header("elements")?;
            let mut rows = Vec::new();
            for _ in 0..elements {
                let length = cur.count_header("length")?;
                rows.push(cur.string_bytes(length)?.to_string());
            }
            Ok(Value::Str(CharMatrix { rows, quote }))
        }
        "scalar struct" => {
            let d = dims(cur)?;
            if d.iter().any(|&x| x != 1) {
                return Err(TextFormatError::Unsupported {
                    line: cur.line - 1,
                    type_name: "scalar struct with dimensions other than 1x1".into(),
                });
            }
            let n = cur.count_header("length")?;
            let mut fields = Vec::new();
            for _ in 0..n {
                cur.skip_blank();
                fields.push(named(cur)?);
            }
            Ok(Value::Struct(fields))
        }
        "cell" => {
            let shape = if cur.peek().and_then(|l| parse_header(l, "ndims")).is_some() {
                dims(cur)?
            } else {
                let r = cur.count_header("rows")?;
                let c = cur.count_header("columns")?;
                vec![r, c]
            };
            let total = element_count(&shape, cur.line - 1)?;
            let mut elems = Vec::new();
            for _ in 0..total {
                cur.skip_blank();
                let (_, v) = named(cur)?;
                elems.push(v);
            }
            Ok(Value::Cell(
                ArrayD::from_shape_vec(IxDyn(&shape).f(), elems).expect("sizes checked"),
            ))
        }
        t if UNSUPPORTED.contains(&t) || is_int_type(t) => Err(TextFormatError::Unsupported {
            line: type_line,
            type_name: t.into(),
        }),
        t => Err(TextFormatError::UnknownType {
            line: type_line,
            type_name: t.into(),
        }),
    }
}

/// Reads `# name:`, `# type:` and the value.
fn named(cur: &mut Cursor<'_>) -> Result<(String, Value)> {
    let (_, name) = cur.header("name")?;
    let name = name.to_string();
    let (type_line, type_name) = cur.header("type")?;
    let v = value(cur, &name, type_name, type_line)?;
    Ok((name, v))
}

/// Parses a file written by Octave's `save -text` (or by [`write_text`]).
///
/// Lines starting with `#` before a `# name:` line (such as `# Created by Octave …`) and blank
/// lines between variables are skipped.
///
/// # Errors
/// A [`TextFormatError`] with the line number for anything malformed or unsupported; never
/// panics.
///
/// ```
/// use cagd::octave::text_format::{read_text, TextFormatError};
/// let ws = read_text("# name: x\n# type: scalar\n2.5\n")?;
/// assert_eq!(ws.scalar("x")?, 2.5);
/// let err = read_text("# name: A\n# type: matrix\n# rows: 2\n# columns: 1\n 1\n").unwrap_err();
/// assert!(matches!(err, TextFormatError::MissingData { line: 6, declared: 2, found: 1, .. }));
/// # Ok::<(), TextFormatError>(())
/// ```
pub fn read_text(text: &str) -> Result<Workspace> {
    let mut cur = Cursor::new(text);
    let mut ws = Workspace::new();
    while let Some(line) = cur.peek() {
        if parse_header(line, "name").is_some() {
            let (name, v) = named(&mut cur)?;
            ws.insert(name, v);
        } else if line.trim().is_empty() || line.trim_start().starts_with('#') {
            cur.next_line();
        } else {
            return Err(TextFormatError::UnexpectedData {
                line: cur.line,
                found: line.into(),
            });
        }
    }
    Ok(ws)
}

/// Byte contents of a file as text, or an error naming the line of the first invalid byte.
fn utf8(bytes: Vec<u8>) -> Result<String> {
    String::from_utf8(bytes).map_err(|e| {
        let upto = e.utf8_error().valid_up_to();
        let line = e.as_bytes()[..upto].iter().filter(|&&b| b == b'\n').count() + 1;
        TextFormatError::BadString {
            line,
            message: "the file is not valid UTF-8".into(),
        }
    })
}

fn read_file(path: &Path) -> Result<String> {
    let bytes = std::fs::read(path).map_err(|e| TextFormatError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })?;
    utf8(bytes)
}

/// [`read_text`] on the contents of a file.
///
/// # Errors
/// [`TextFormatError::Io`] if it cannot be read, otherwise as [`read_text`].
pub fn read_text_file(path: impl AsRef<Path>) -> Result<Workspace> {
    read_text(&read_file(path.as_ref())?)
}

/// Reads plain numeric text, as written by `save -ascii` and `dlmwrite`: one matrix row per
/// line, values separated by spaces, tabs, commas or semicolons (a run of separators counts as
/// one). Blank lines and comments (from `%` or `#` to the end of the line) are skipped. Every
/// row must have as many values as the first. No lines gives a 0×0 matrix.
///
/// # Errors
/// [`TextFormatError::NotANumber`] or [`TextFormatError::WrongCount`], with the line number.
///
/// ```
/// use cagd::octave::text_format::read_numeric_text;
/// let a = read_numeric_text(" 1.00000000e+00 2.00000000e+00\n 3.00000000e+00 4.00000000e+00\n")?;
/// assert_eq!(a, ndarray::array![[1.0, 2.0], [3.0, 4.0]]);
/// let b = read_numeric_text("1,2\n3,4")?;
/// assert_eq!(a, b);
/// # Ok::<(), cagd::octave::TextFormatError>(())
/// ```
pub fn read_numeric_text(text: &str) -> Result<Array2<f64>> {
    let mut data = Vec::new();
    let mut cols: Option<usize> = None;
    let mut rows = 0;
    for (k, raw) in text.lines().enumerate() {
        let line = k + 1;
        let body = raw.split(['%', '#']).next().unwrap_or("");
        let tokens: Vec<&str> = body
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|t| !t.is_empty())
            .collect();
        if tokens.is_empty() {
            continue;
        }
        for t in &tokens {
            data.push(parse_number(t, line)?);
        }
        match cols {
            None => cols = Some(tokens.len()),
            Some(c) if c != tokens.len() => {
                return Err(TextFormatError::WrongCount {
                    line,
                    expected: c,
                    found: tokens.len(),
                })
            }
            Some(_) => {}
        }
        rows += 1;
    }
    Ok(Array2::from_shape_vec((rows, cols.unwrap_or(0)), data).expect("sizes checked"))
}

/// [`read_numeric_text`] on the contents of a file.
///
/// # Errors
/// [`TextFormatError::Io`] if it cannot be read, otherwise as [`read_numeric_text`].
pub fn read_numeric_file(path: impl AsRef<Path>) -> Result<Array2<f64>> {
    read_numeric_text(&read_file(path.as_ref())?)
}

// ---------------------------------------------------------------------------------------------
// Writing

/// Formats a double so that Octave (and Rust) read back exactly the same value: the shortest
/// decimal that round-trips, in `%g` style (`0.1`, `1e+20`, `5e-324`), and `Inf`, `-Inf`, `NaN`,
/// `NA`, `-0` as Octave writes them.
///
/// ```
/// use cagd::octave::text_format::{format_number, na};
/// assert_eq!(format_number(0.1), "0.1");
/// assert_eq!(format_number(1e20), "1e+20");
/// assert_eq!(format_number(-0.0), "-0");
/// assert_eq!(format_number(f64::NEG_INFINITY), "-Inf");
/// assert_eq!(format_number(na()), "NA");
/// assert_eq!(format_number(123456.5), "123456.5");
/// assert_eq!(format_number(1.5e-7), "1.5e-07");
/// ```
pub fn format_number(x: f64) -> String {
    if x.is_nan() {
        return if is_na(x) { "NA" } else { "NaN" }.into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "Inf" } else { "-Inf" }.into();
    }
    if x == 0.0 {
        return if x.is_sign_negative() { "-0" } else { "0" }.into();
    }
    // `{:e}` gives the shortest round-trip digits: "-1.2345e-7".
    let sci = format!("{x:e}");
    let (mantissa, exp) = sci.split_once('e').expect("`{:e}` always has an exponent");
    let exp: i32 = exp.parse().expect("`{:e}` exponent is an integer");
    let (sign, mantissa) = match mantissa.strip_prefix('-') {
        Some(m) => ("-", m),
        None => ("", mantissa),
    };
    let digits: String = mantissa.chars().filter(|c| *c != '.').collect();
    let nd = digits.len() as i32;
    if (-4..17).contains(&exp) {
        // Fixed notation, like %g.
        if exp >= nd - 1 {
            format!("{sign}{digits}{}", "0".repeat((exp - nd + 1) as usize))
        } else if exp >= 0 {
            let (int, frac) = digits.split_at(exp as usize + 1);
            format!("{sign}{int}.{frac}")
        } else {
            format!("{sign}0.{}{digits}", "0".repeat((-exp - 1) as usize))
        }
    } else {
        let esign = if exp < 0 { '-' } else { '+' };
        format!("{sign}{mantissa}e{esign}{:02}", exp.abs())
    }
}

fn valid_name(name: &str) -> bool {
    let mut chars = name.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Writes the data of a numeric (or bool) array after its `# type:` line.
fn write_array<T: Copy>(
    out: &mut String,
    a: &ArrayD<T>,
    fmt: impl Fn(T) -> String,
    force_nd: bool,
) {
    let shape: Vec<usize> = match a.ndim() {
        0 => vec![1, 1],
        1 => vec![1, a.len()],
        _ => a.shape().to_vec(),
    };
    if shape.len() == 2 && !force_nd {
        let (r, c) = (shape[0], shape[1]);
        let _ = writeln!(out, "# rows: {r}\n# columns: {c}");
        let flat: Vec<T> = a.iter().copied().collect(); // row-major, logical order
        for i in 0..r {
            for j in 0..c {
                let _ = write!(out, " {}", fmt(flat[i * c + j]));
            }
            out.push('\n');
        }
    } else {
        let _ = writeln!(out, "# ndims: {}", shape.len());
        for d in &shape {
            let _ = write!(out, " {d}");
        }
        out.push('\n');
        // Column-major: iterate the axes-reversed view in logical order.
        for x in a.view().reversed_axes().iter() {
            let _ = writeln!(out, " {}", fmt(*x));
        }
    }
}

fn write_value(out: &mut String, name: &str, path: &str, v: &Value) -> Result<()> {
    let _ = writeln!(out, "# name: {name}");
    match v {
        Value::Scalar(x) => {
            let _ = writeln!(out, "# type: scalar\n{}", format_number(*x));
        }
        Value::Matrix(a) => {
            out.push_str("# type: matrix\n");
            write_array(out, a, format_number, false);
        }
        Value::Range {
            base,
            limit,
            increment,
        } => {
            let _ = writeln!(
                out,
                "# type: double_range\n# base, limit, increment\n{} {} {}",
                format_number(*base),
                format_number(*limit),
                format_number(*increment)
            );
        }
        Value::Bool(b) => {
            let _ = writeln!(out, "# type: bool\n{}", u8::from(*b));
        }
        Value::BoolMatrix(a) => {
            out.push_str("# type: bool matrix\n");
            write_array(out, a, |b| u8::from(b).to_string(), a.ndim() > 2);
        }
        Value::Str(s) => {
            let t = match s.quote {
                Quote::Single => "sq_string",
                Quote::Double => "string",
            };
            if let Some(first) = s.rows.first() {
                if s.rows.iter().any(|r| r.len() != first.len()) {
                    return Err(TextFormatError::Unwritable {
                        name: path.into(),
                        message: "the rows of a char matrix must all have the same length".into(),
                    });
                }
            }
            let _ = writeln!(out, "# type: {t}\n# elements: {}", s.rows.len());
            for r in &s.rows {
                let _ = writeln!(out, "# length: {}\n{r}", r.len());
            }
        }
        Value::Struct(fields) => {
            let _ = writeln!(
                out,
                "# type: scalar struct\n# ndims: 2\n 1 1\n# length: {}",
                fields.len()
            );
            for (f, fv) in fields {
                let fpath = format!("{path}.{f}");
                if !valid_name(f) {
                    return Err(TextFormatError::Unwritable {
                        name: fpath,
                        message: "not a valid field name".into(),
                    });
                }
                write_value(out, f, &fpath, fv)?;
                out.push_str("\n\n");
            }
            out.push_str("\n\n");
        }
        Value::Cell(c) => {
            out.push_str("# type: cell\n");
            if c.ndim() == 2 {
                let _ = writeln!(out, "# rows: {}\n# columns: {}", c.shape()[0], c.shape()[1]);
            } else {
                let shape: Vec<usize> = match c.ndim() {
                    0 => vec![1, 1],
                    1 => vec![1, c.len()],
                    _ => c.shape().to_vec(),
                };
                let _ = writeln!(out, "# ndims: {}", shape.len());
                for d in &shape {
                    let _ = write!(out, " {d}");
                }
                out.push('\n');
            }
            for (k, e) in c.view().reversed_axes().iter().enumerate() {
                write_value(out, "<cell-element>", &format!("{path}{{{}}}", k + 1), e)?;
                out.push_str("\n\n");
            }
            out.push_str("\n\n");
        }
    }
    Ok(())
}

/// Writes variables in Octave's text format, for `load` (in Octave) or [`read_text`].
///
/// Numbers are written by [`format_number`] (shortest round-trip decimals), matrices one row
/// per line, N-d arrays column-major one value per line, exactly as Octave lays them out.
///
/// # Errors
/// [`TextFormatError::Unwritable`] for an invalid variable or field name (Octave's identifiers:
/// a letter or `_`, then letters, digits, `_`) or a char matrix with rows of different lengths.
pub fn write_text(ws: &Workspace) -> Result<String> {
    let mut out = String::from("# Created by cagd (Octave text format)\n");
    for (name, v) in ws.iter() {
        if !valid_name(name) {
            return Err(TextFormatError::Unwritable {
                name: name.into(),
                message: "not a valid Octave variable name".into(),
            });
        }
        write_value(&mut out, name, name, v)?;
        out.push_str("\n\n");
    }
    Ok(out)
}

/// [`write_text`] into a file, atomically ([`crate::cli::write_atomic`]: a temporary file in
/// the same folder renamed over `path`, so the file is complete or absent, never partial).
///
/// # Errors
/// As [`write_text`], and [`TextFormatError::Io`] if the file cannot be written.
pub fn write_text_file(path: impl AsRef<Path>, ws: &Workspace) -> Result<()> {
    let text = write_text(ws)?;
    crate::cli::write_atomic(path.as_ref(), text.as_bytes()).map_err(|e| TextFormatError::Io {
        path: path.as_ref().display().to_string(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::{array, Array3};

    /// Exactly what Octave 7.3 wrote for these values (`save_precision(17)`).
    const OCTAVE_SAMPLE: &str = "# Created by Octave 7.3.0, Sat Nov 21 05:32:43 2026 UTC <root@vm>
# name: a
# type: scalar
3.5


# name: b
# type: matrix
# rows: 2
# columns: 2
 1 2
 3 4


# name: bm
# type: bool matrix
# rows: 2
# columns: 2
 1 0
 0 1


# name: bt
# type: bool
1


# name: c
# type: matrix
# ndims: 3
 2 3 2
 1
 2
 3
 4
 5
 6
 7
 8
 9
 10
 11
 12


# name: s2
# type: sq_string
# elements: 2
# length: 2
ab
# length: 2
cd


# name: ds
# type: string
# elements: 1
# length: 3
a
b


# name: em
# type: sq_string
# elements: 0


# name: r
# type: double_range
# base, limit, increment
1 3 1


# name: sp
# type: matrix
# rows: 1
# columns: 8
 Inf -Inf NaN NA 1e-300 5.5626846462680035e-309 -0 0.10000000000000001


# name: e
# type: matrix
# rows: 0
# columns: 3


";

    #[test]
    fn reads_what_octave_writes() {
        let ws = read_text(OCTAVE_SAMPLE).unwrap();
        assert_eq!(
            ws.names().collect::<Vec<_>>(),
            ["a", "b", "bm", "bt", "c", "s2", "ds", "em", "r", "sp", "e"]
        );
        assert_eq!(ws.scalar("a").unwrap(), 3.5);
        assert_eq!(ws.matrix("b").unwrap(), array![[1.0, 2.0], [3.0, 4.0]]);
        assert_eq!(
            ws.get("bm"),
            Some(&Value::BoolMatrix(
                array![[true, false], [false, true]].into_dyn()
            ))
        );
        assert_eq!(ws.get("bt"), Some(&Value::Bool(true)));
        let s2 = ws.get("s2").unwrap();
        assert_eq!(
            s2,
            &Value::Str(CharMatrix {
                rows: vec!["ab".into(), "cd".into()],
                quote: Quote::Single
            })
        );
        assert_eq!(ws.string("ds").unwrap(), "a\nb");
        assert_eq!(ws.string("em").unwrap(), "");
        assert_eq!(ws.matrix("r").unwrap(), array![[1.0, 2.0, 3.0]]);
        let sp = ws.matrix("sp").unwrap();
        assert_eq!(sp[[0, 0]], f64::INFINITY);
        assert_eq!(sp[[0, 1]], f64::NEG_INFINITY);
        assert!(sp[[0, 2]].is_nan() && !is_na(sp[[0, 2]]));
        assert!(is_na(sp[[0, 3]]));
        assert_eq!(sp[[0, 4]], 1e-300);
        assert_eq!(sp[[0, 5]], f64::MIN_POSITIVE / 4.0);
        assert!(sp[[0, 6]] == 0.0 && sp[[0, 6]].is_sign_negative());
        assert_eq!(sp[[0, 7]], 0.1);
        assert_eq!(ws.matrix("e").unwrap().dim(), (0, 3));
    }

    #[test]
    fn nd_arrays_are_column_major() {
        let ws = read_text(OCTAVE_SAMPLE).unwrap();
        let c = ws.array("c").unwrap();
        assert_eq!(c.shape(), &[2, 3, 2]);
        // Octave: c(i,j,k) = i + 2(j-1) + 6(k-1) for the data 1..12.
        for i in 0..2 {
            for j in 0..3 {
                for k in 0..2 {
                    assert_eq!(c[[i, j, k]], (1 + i + 2 * j + 6 * k) as f64);
                }
            }
        }
        let text = write_text(&ws).unwrap();
        assert!(text.contains("# ndims: 3\n 2 3 2\n 1\n 2\n 3\n 4\n"));
    }

    #[test]
    fn round_trip_through_our_writer() {
        let ws = read_text(OCTAVE_SAMPLE).unwrap();
        let back = read_text(&write_text(&ws).unwrap()).unwrap();
        // NaN != NaN, so compare the text of both and the NaN positions separately.
        assert_eq!(write_text(&back).unwrap(), write_text(&ws).unwrap());
        let sp = back.matrix("sp").unwrap();
        assert!(is_na(sp[[0, 3]]) && sp[[0, 2]].is_nan() && !is_na(sp[[0, 2]]));
        assert!(sp[[0, 6]].is_sign_negative());
    }

    #[test]
    fn struct_and_cell_as_octave_nurbs_writes_them() {
        // nrbmak(coefs, {[0 0 1 1], [0 0 1 1]}): knots is a cell for surfaces.
        let text = "# name: srf
# type: scalar struct
# ndims: 2
 1 1
# length: 3
# name: form
# type: sq_string
# elements: 1
# length: 7
B-NURBS


# name: number
# type: matrix
# rows: 1
# columns: 2
 2 2


# name: knots
# type: cell
# rows: 1
# columns: 2
# name: <cell-element>
# type: matrix
# rows: 1
# columns: 4
 0 0 1 1



# name: <cell-element>
# type: matrix
# rows: 1
# columns: 4
 0 0 1 1





";
        let ws = read_text(text).unwrap();
        let srf = ws.get("srf").unwrap();
        assert_eq!(srf.field("form").and_then(Value::as_str), Some("B-NURBS"));
        assert_eq!(
            srf.field("number").and_then(Value::to_matrix),
            Some(array![[2.0, 2.0]])
        );
        let Some(Value::Cell(knots)) = srf.field("knots") else {
            panic!("knots is not a cell")
        };
        assert_eq!(knots.shape(), &[1, 2]);
        assert_eq!(
            knots[[0, 1]].to_matrix(),
            Some(array![[0.0, 0.0, 1.0, 1.0]])
        );
        assert_eq!(read_text(&write_text(&ws).unwrap()).unwrap(), ws);
    }

    #[test]
    fn cells_are_column_major() {
        let text = "# name: ce\n# type: cell\n# rows: 2\n# columns: 2\n\
            # name: <cell-element>\n# type: scalar\n1\n\n\n\
            # name: <cell-element>\n# type: scalar\n2\n\n\n\n\
            # name: <cell-element>\n# type: scalar\n3\n\n\n\
            # name: <cell-element>\n# type: scalar\n4\n\n\n\n\n";
        let ws = read_text(text).unwrap();
        let Some(Value::Cell(c)) = ws.get("ce") else {
            panic!()
        };
        assert_eq!(c[[1, 0]], Value::Scalar(2.0));
        assert_eq!(c[[0, 1]], Value::Scalar(3.0));
        assert_eq!(read_text(&write_text(&ws).unwrap()).unwrap(), ws);
    }

    #[test]
    fn string_data_is_read_by_length_not_by_line() {
        let text = "# name: s\n# type: string\n# elements: 2\n# length: 3\nx\ny\n# length: 3\néz\n";
        let ws = read_text(text).unwrap();
        let Some(Value::Str(s)) = ws.get("s") else {
            panic!()
        };
        assert_eq!(s.rows, ["x\ny", "éz"]);
        assert_eq!(s.quote, Quote::Double);
        let empty_rows =
            "# name: e\n# type: sq_string\n# elements: 2\n# length: 0\n\n# length: 0\n\n";
        let ws = read_text(empty_rows).unwrap();
        assert_eq!(
            ws.get("e"),
            Some(&Value::Str(CharMatrix {
                rows: vec![String::new(), String::new()],
                quote: Quote::Single
            }))
        );
    }

    #[test]
    fn number_formatting_round_trips() {
        let samples = [
            0.1,
            1.0 / 3.0,
            -2.5,
            1e-300,
            f64::MIN_POSITIVE,
            f64::MIN_POSITIVE / 4.0,
            5e-324,
            f64::MAX,
            -f64::MAX,
            1e16,
            1e17,
            123456789012345680.0,
            0.00001,
            0.0001234,
            std::f64::consts::PI,
        ];
        for x in samples {
            let s = format_number(x);
            assert_eq!(parse_number(&s, 1).unwrap().to_bits(), x.to_bits(), "{s}");
        }
        assert_eq!(format_number(1e16), "10000000000000000");
        assert_eq!(format_number(1e17), "1e+17");
        assert_eq!(format_number(0.0001234), "0.0001234");
        assert_eq!(format_number(0.00001), "1e-05");
        assert_eq!(format_number(5e-324), "5e-324");
        assert_eq!(format_number(-2.5), "-2.5");
    }

    #[test]
    fn writer_lays_out_like_octave() {
        let mut ws = Workspace::new();
        ws.insert("x", 3.5);
        ws.insert("flag", true);
        ws.insert("name", "B-NURBS");
        let a = Array3::from_shape_fn((2, 1, 2), |(i, _, k)| (i + 2 * k) as f64);
        ws.insert("A", a.into_dyn());
        let text = write_text(&ws).unwrap();
        assert!(text.contains("# name: x\n# type: scalar\n3.5\n"));
        assert!(text.contains("# name: flag\n# type: bool\n1\n"));
        assert!(
            text.contains("# name: name\n# type: sq_string\n# elements: 1\n# length: 7\nB-NURBS\n")
        );
        assert!(text.contains("# name: A\n# type: matrix\n# ndims: 3\n 2 1 2\n 0\n 1\n 2\n 3\n"));
    }

    #[test]
    fn writer_rejects_what_octave_cannot_load() {
        let mut ws = Workspace::new();
        ws.insert("1x", 1.0);
        assert!(matches!(
            write_text(&ws),
            Err(TextFormatError::Unwritable { .. })
        ));
        let mut ws = Workspace::new();
        ws.insert(
            "s",
            Value::Str(CharMatrix {
                rows: vec!["ab".into(), "c".into()],
                quote: Quote::Single,
            }),
        );
        assert!(matches!(
            write_text(&ws),
            Err(TextFormatError::Unwritable { .. })
        ));
        let mut ws = Workspace::new();
        ws.insert(
            "s",
            Value::Struct(vec![("bad name".into(), Value::Scalar(1.0))]),
        );
        assert_eq!(
            write_text(&ws),
            Err(TextFormatError::Unwritable {
                name: "s.bad name".into(),
                message: "not a valid field name".into()
            })
        );
    }

    #[test]
    fn one_and_zero_dimensional_arrays_are_written_as_rows() {
        let mut ws = Workspace::new();
        ws.insert("v", ndarray::arr1(&[1.0, 2.0]).into_dyn());
        ws.insert("z", ndarray::arr0(7.0).into_dyn());
        let back = read_text(&write_text(&ws).unwrap()).unwrap();
        assert_eq!(back.matrix("v").unwrap(), array![[1.0, 2.0]]);
        assert_eq!(back.matrix("z").unwrap(), array![[7.0]]);
    }

    #[test]
    fn ranges_expand() {
        let r = |base, limit, increment| {
            Value::Range {
                base,
                limit,
                increment,
            }
            .to_matrix()
            .unwrap()
        };
        assert_eq!(r(1.0, 3.0, 1.0), array![[1.0, 2.0, 3.0]]);
        assert_eq!(r(5.0, 1.0, -2.0), array![[5.0, 3.0, 1.0]]);
        assert_eq!(r(0.0, 1.0, 0.1).len(), 11);
        assert_eq!(r(1.0, 0.0, 1.0).dim(), (1, 0));
    }

    #[test]
    fn plain_numeric_text() {
        let a = read_numeric_text("% comment\n1\t2 , 3\n\n4;5;6 # trailing\n").unwrap();
        assert_eq!(a, array![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
        assert_eq!(read_numeric_text("").unwrap().dim(), (0, 0));
        let x = read_numeric_text("Inf,-Inf,NaN,NA\n").unwrap();
        assert!(x[[0, 0]].is_infinite() && x[[0, 1]] < 0.0 && is_na(x[[0, 3]]));
        assert_eq!(
            read_numeric_text("1 2\n3\n"),
            Err(TextFormatError::WrongCount {
                line: 2,
                expected: 2,
                found: 1
            })
        );
        assert_eq!(
            read_numeric_text("1 2\n\n3 x\n"),
            Err(TextFormatError::NotANumber {
                line: 3,
                token: "x".into()
            })
        );
    }

    // ----- malformed input: a typed error with the line number, never a panic -----

    fn err(text: &str) -> TextFormatError {
        read_text(text).unwrap_err()
    }

    #[test]
    fn truncated_files() {
        assert_eq!(
            err("# name: x\n"),
            TextFormatError::Truncated {
                line: 2,
                expected: "`# type:`".into()
            }
        );
        assert_eq!(
            err("# name: x\n# type: scalar\n"),
            TextFormatError::MissingData {
                line: 3,
                name: "x".into(),
                declared: 1,
                found: 0
            }
        );
        assert!(matches!(
            err("# name: s\n# type: sq_string\n# elements: 1\n# length: 10\nabc\n"),
            TextFormatError::Truncated { line: 5, .. }
        ));
        assert!(matches!(
            err("# name: c\n# type: cell\n# rows: 1\n# columns: 2\n# name: <cell-element>\n# type: scalar\n1\n"),
            TextFormatError::Truncated { line: 8, .. }
        ));
        assert!(matches!(
            err("# name: c\n# type: matrix\n# ndims: 3\n 1 1 2\n 1\n"),
            TextFormatError::MissingData {
                line: 6,
                declared: 2,
                found: 1,
                ..
            }
        ));
    }

    #[test]
    fn wrong_row_counts() {
        // `# rows:` too large: the next variable's header comes too early.
        let too_few = "# name: A\n# type: matrix\n# rows: 3\n# columns: 2\n 1 2\n 3 4\n\n\n# name: b\n# type: scalar\n1\n";
        assert_eq!(
            err(too_few),
            TextFormatError::MissingData {
                line: 7,
                name: "A".into(),
                declared: 3,
                found: 2
            }
        );
        // `# rows:` too small: a data line where a `# name:` belongs.
        let too_many = "# name: A\n# type: matrix\n# rows: 1\n# columns: 2\n 1 2\n 3 4\n";
        assert_eq!(
            err(too_many),
            TextFormatError::UnexpectedData {
                line: 6,
                found: " 3 4".into()
            }
        );
        // wrong number of columns on a line
        assert_eq!(
            err("# name: A\n# type: matrix\n# rows: 1\n# columns: 3\n 1 2\n"),
            TextFormatError::WrongCount {
                line: 5,
                expected: 3,
                found: 2
            }
        );
        assert!(matches!(
            err("# name: A\n# type: matrix\n# rows: two\n# columns: 3\n"),
            TextFormatError::BadHeader { line: 3, .. }
        ));
    }

    #[test]
    fn unknown_and_unsupported_types() {
        assert_eq!(
            err("# name: A\n# type: quaternion\n1\n"),
            TextFormatError::UnknownType {
                line: 2,
                type_name: "quaternion".into()
            }
        );
        assert_eq!(
            err("# name: z\n# type: complex scalar\n(1,2)\n"),
            TextFormatError::Unsupported {
                line: 2,
                type_name: "complex scalar".into()
            }
        );
        assert!(matches!(
            err("# name: i\n# type: int32 scalar\n5\n"),
            TextFormatError::Unsupported { line: 2, .. }
        ));
    }

    #[test]
    fn non_numeric_data() {
        assert_eq!(
            err("# name: A\n# type: matrix\n# rows: 1\n# columns: 2\n 1 abc\n"),
            TextFormatError::NotANumber {
                line: 5,
                token: "abc".into()
            }
        );
        assert!(matches!(
            err("# name: x\n# type: scalar\n0x10\n"),
            TextFormatError::NotANumber { line: 3, .. }
        ));
        assert!(matches!(
            err("# name: b\n# type: bool\n2\n"),
            TextFormatError::NotANumber { line: 3, .. }
        ));
        assert!(matches!(
            err("stray text\n"),
            TextFormatError::UnexpectedData { line: 1, .. }
        ));
        assert!(matches!(
            err("# name: s\n# type: sq_string\n# elements: 1\n# length: 2\nabc\n"),
            TextFormatError::BadString { line: 5, .. }
        ));
        assert!(matches!(
            err("# name: s\n# type: sq_string\n# elements: 1\n# length: 1\né\n"),
            TextFormatError::BadString { line: 5, .. }
        ));
    }

    #[test]
    fn hostile_counts_give_errors_not_panics_or_huge_allocations() {
        let huge = "18446744073709551615";
        for text in [
            format!("# name: s\n# type: sq_string\n# elements: 1\n# length: {huge}\nab\n"),
            format!("# name: s\n# type: sq_string\n# elements: {huge}\n# length: 1\na\n"),
            format!("# name: A\n# type: matrix\n# rows: {huge}\n# columns: 2\n 1 2\n"),
            format!("# name: A\n# type: matrix\n# rows: 2\n# columns: {huge}\n 1 2\n"),
            "# name: A\n# type: matrix\n# ndims: 3\n 4294967296 4294967296 2\n 1\n".into(),
            format!("# name: c\n# type: cell\n# rows: {huge}\n# columns: {huge}\n"),
            format!("# name: c\n# type: cell\n# rows: {huge}\n# columns: 0\n"),
            format!("# name: A\n# type: matrix\n# rows: {huge}\n# columns: 0\n"),
            format!("# name: A\n# type: bool matrix\n# ndims: 3\n 0 {huge} 2\n"),
            format!("# name: s\n# type: scalar struct\n# ndims: 2\n 1 1\n# length: {huge}\n"),
        ] {
            assert!(read_text(&text).is_err(), "{text}");
        }
        let ws =
            read_text("# name: r\n# type: double_range\n# base, limit, increment\n0 1 1e-300\n")
                .unwrap();
        assert!(matches!(
            ws.matrix("r"),
            Err(TextFormatError::WrongType { .. })
        ));
    }

    #[test]
    fn never_panics_on_prefixes_of_a_valid_file() {
        // Every prefix of a valid file either parses or gives a typed error.
        for end in 0..OCTAVE_SAMPLE.len() {
            if OCTAVE_SAMPLE.is_char_boundary(end) {
                let _ = read_text(&OCTAVE_SAMPLE[..end]);
            }
        }
    }

    #[test]
    fn workspace_lookup_errors() {
        let ws = read_text(OCTAVE_SAMPLE).unwrap();
        assert_eq!(
            ws.matrix("nope"),
            Err(TextFormatError::MissingVariable {
                name: "nope".into()
            })
        );
        assert!(matches!(
            ws.matrix("c"),
            Err(TextFormatError::WrongType { .. })
        ));
        assert!(matches!(
            ws.scalar("b"),
            Err(TextFormatError::WrongType { .. })
        ));
        assert!(matches!(
            ws.string("a"),
            Err(TextFormatError::WrongType { .. })
        ));
    }

    mod properties {
        use super::super::*;
        use proptest::prelude::*;

        /// Any double: every bit pattern, NaN payloads included.
        fn any_double() -> impl Strategy<Value = f64> {
            any::<u64>().prop_map(f64::from_bits)
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(512))]

            /// Every finite double, ±Inf and ±0 are written so that they read back bit for bit;
            /// NaN reads back as NaN (NA as NA).
            #[test]
            fn numbers_round_trip(x in any_double()) {
                let y = parse_number(&format_number(x), 1).unwrap();
                if x.is_nan() {
                    prop_assert!(y.is_nan());
                    prop_assert_eq!(is_na(x), is_na(y));
                } else {
                    prop_assert_eq!(x.to_bits(), y.to_bits());
                }
            }
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(128))]

            /// Matrices and N-d arrays of any shape (zero sizes included) round-trip through
            /// the writer and the reader, bit for bit and in Octave's index order.
            #[test]
            fn arrays_round_trip(
                shape in prop::collection::vec(0usize..4, 2..5),
                seed in prop::collection::vec(-1e6..1e6f64, 64),
            ) {
                let total: usize = shape.iter().product();
                let data: Vec<f64> = (0..total).map(|k| seed[k % seed.len()] / (k + 1) as f64).collect();
                let a = ArrayD::from_shape_vec(IxDyn(&shape), data).unwrap();
                let mut ws = Workspace::new();
                ws.insert("a", a.clone());
                let back = read_text(&write_text(&ws).unwrap()).unwrap().array("a").unwrap();
                // Octave keeps trailing singleton dimensions only up to 2-D; we write them all,
                // so the shape comes back unchanged.
                prop_assert_eq!(back.shape(), a.shape());
                for (x, y) in back.iter().zip(a.iter()) {
                    prop_assert_eq!(x.to_bits(), y.to_bits());
                }
            }

            /// Any text made of format fragments parses or gives a typed error, never a panic.
            #[test]
            fn malformed_text_never_panics(
                lines in prop::collection::vec(
                    prop::sample::select(vec![
                        "# name: x", "# name: <cell-element>", "# type: matrix", "# type: scalar",
                        "# type: cell", "# type: sq_string", "# type: scalar struct",
                        "# type: bool matrix", "# type: double_range", "# rows: 2",
                        "# rows: 0", "# columns: 3", "# columns: 1", "# ndims: 3", " 2 1 2",
                        " 1 1", "# length: 2", "# length: 1", "# elements: 1", " 1 2 3",
                        " 1", "NaN", "Inf -Inf NA", "ab", "é", "", "x y", "# base, limit, increment",
                        "1 3 1", "# length: 18446744073709551615",
                        "# elements: 18446744073709551615", "# rows: 18446744073709551615",
                        "# columns: 18446744073709551615", "# ndims: 2",
                        " 4294967296 4294967296", " 18446744073709551615 2", "0 1 1e-300",
                    ]),
                    0..40,
                ),
            ) {
                let text = lines.join("\n");
                let _ = read_text(&text);
                let _ = read_numeric_text(&text);
            }
        }
    }
}

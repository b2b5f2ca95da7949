//! Reading Octave's text format, and plain numeric text.

use std::path::Path;

use cagd::limits::Limits;
use ndarray::{Array2, ArrayD, IxDyn, ShapeBuilder};

use super::value::{CharMatrix, Quote, Value, Workspace};
use super::{na, Result, TextFormatError};

/// A cursor over the text that knows its line number.
struct Cursor<'a> {
    text: &'a str,
    pos: usize,
    /// 1-based number of the line that starts at `pos`.
    line: usize,
    /// The element limit: no array length may exceed it.
    max_elements: usize,
    /// Structs and cells being read around the current value.
    depth: usize,
    /// The depth limit.
    max_depth: usize,
}

impl<'a> Cursor<'a> {
    fn new(text: &'a str, limits: &Limits) -> Self {
        Cursor {
            text,
            pos: 0,
            line: 1,
            max_elements: limits.max_elements,
            depth: 0,
            max_depth: limits.max_depth,
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
pub(super) fn parse_number(token: &str, line: usize) -> Result<f64> {
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
fn element_count(shape: &[usize], line: usize, max: usize) -> Result<usize> {
    // No length may exceed the element limit, even in an empty array: Octave writes one
    // (blank) line per row of an R×0 matrix, so a 20 000 000×0 matrix in a 200-byte file
    // would be written back as 20 MB (found by fuzzing).
    if let Some(&too_long) = shape.iter().find(|&&d| d > max) {
        return Err(TextFormatError::BadHeader {
            line,
            expected: format!(
                "array lengths of at most {max} (the element limit, Limits::max_elements)"
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
        let total = element_count(&shape, cur.line - 1, cur.max_elements)?;
        let data = data_lines(cur, name, total, 1)?;
        Ok(ArrayD::from_shape_vec(IxDyn(&shape).f(), data).expect("sizes checked"))
    } else {
        let rows = cur.count_header("rows")?;
        let cols = cur.count_header("columns")?;
        element_count(&[rows, cols], cur.line - 1, cur.max_elements)?;
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
            let total = element_count(&shape, cur.line - 1, cur.max_elements)?;
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
    let (name_line, name) = cur.header("name")?;
    let name = name.to_string();
    let (type_line, type_name) = cur.header("type")?;
    // Each struct field and cell element is read by a recursive call: bound the depth.
    if cur.depth >= cur.max_depth {
        return Err(TextFormatError::TooDeep {
            line: name_line,
            limit: cur.max_depth,
        });
    }
    cur.depth += 1;
    let v = value(cur, &name, type_name, type_line);
    cur.depth -= 1;
    Ok((name, v?))
}

/// Parses a file written by Octave's `save -text` (or by [`write_text`](super::write_text)).
///
/// Lines starting with `#` before a `# name:` line (such as `# Created by Octave …`) and blank
/// lines between variables are skipped.
///
/// # Errors
/// A [`TextFormatError`] with the line number for anything malformed or unsupported; never
/// panics.
///
/// ```
/// use cagd_octave::text_format::{read_text, TextFormatError};
/// let ws = read_text("# name: x\n# type: scalar\n2.5\n")?;
/// assert_eq!(ws.scalar("x")?, 2.5);
/// let err = read_text("# name: A\n# type: matrix\n# rows: 2\n# columns: 1\n 1\n").unwrap_err();
/// assert!(matches!(err, TextFormatError::MissingData { line: 6, declared: 2, found: 1, .. }));
/// # Ok::<(), TextFormatError>(())
/// ```
pub fn read_text(text: &str) -> Result<Workspace> {
    read_text_with(text, &Limits::default())
}

/// [`read_text`] with the given limits: no array length may exceed
/// `limits.max_elements`.
///
/// # Errors
/// As [`read_text`]; [`TextFormatError::BadHeader`] for a length above the limit.
///
/// ```
/// use cagd::limits::Limits;
/// use cagd_octave::text_format::{read_text_with, TextFormatError};
/// let text = "# name: A\n# type: matrix\n# rows: 5\n# columns: 0\n";
/// let small = Limits { max_elements: 4, ..Limits::default() };
/// let err = read_text_with(text, &small).unwrap_err();
/// assert!(matches!(err, TextFormatError::BadHeader { .. }));
/// assert!(read_text_with(text, &Limits::default()).is_ok());
/// # Ok::<(), TextFormatError>(())
/// ```
pub fn read_text_with(text: &str, limits: &Limits) -> Result<Workspace> {
    let mut cur = Cursor::new(text, limits);
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
/// use cagd_octave::text_format::read_numeric_text;
/// let a = read_numeric_text(" 1.00000000e+00 2.00000000e+00\n 3.00000000e+00 4.00000000e+00\n")?;
/// assert_eq!(a, ndarray::array![[1.0, 2.0], [3.0, 4.0]]);
/// let b = read_numeric_text("1,2\n3,4")?;
/// assert_eq!(a, b);
/// # Ok::<(), cagd_octave::TextFormatError>(())
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

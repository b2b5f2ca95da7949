//! Writing Octave's text format, so that `load` reads back identical values.

use std::fmt::Write as _;
use std::path::Path;

use ndarray::ArrayD;

use super::value::{Quote, Value, Workspace};
use super::{is_na, Result, TextFormatError};

/// Formats a double so that Octave (and Rust) read back exactly the same value: the shortest
/// decimal that round-trips, in `%g` style (`0.1`, `1e+20`, `5e-324`), and `Inf`, `-Inf`, `NaN`,
/// `NA`, `-0` as Octave writes them.
///
/// ```
/// use cagd_octave::text_format::{format_number, na};
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

/// Structs and cells nested deeper than this are not written: the writer recurses once per level.
const MAX_WRITE_DEPTH: usize = 256;

fn write_value(out: &mut String, name: &str, path: &str, v: &Value, depth: usize) -> Result<()> {
    if depth > MAX_WRITE_DEPTH {
        return Err(TextFormatError::Unwritable {
            name: path.into(),
            message: format!("structs and cells nested deeper than {MAX_WRITE_DEPTH} levels"),
        });
    }
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
                write_value(out, f, &fpath, fv, depth + 1)?;
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
                write_value(
                    out,
                    "<cell-element>",
                    &format!("{path}{{{}}}", k + 1),
                    e,
                    depth + 1,
                )?;
                out.push_str("\n\n");
            }
            out.push_str("\n\n");
        }
    }
    Ok(())
}

/// Writes variables in Octave's text format, for `load` (in Octave) or [`read_text`](super::read_text).
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
        write_value(&mut out, name, name, v, 0)?;
        out.push_str("\n\n");
    }
    Ok(out)
}

/// [`write_text`] into a file (the text is complete before the file is touched; the command
/// line writes its files atomically on top of [`write_text`]).
///
/// # Errors
/// As [`write_text`], and [`TextFormatError::Io`] if the file cannot be written.
pub fn write_text_file(path: impl AsRef<Path>, ws: &Workspace) -> Result<()> {
    let text = write_text(ws)?;
    std::fs::write(path.as_ref(), text.as_bytes()).map_err(|e| TextFormatError::Io {
        path: path.as_ref().display().to_string(),
        message: e.to_string(),
    })
}

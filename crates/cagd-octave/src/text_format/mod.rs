//! GNU Octave's text file format: what `save -text` writes and `load` reads.
//!
//! Every expected number of the crate's tests is written by Octave in this format, and data moves
//! between the crate and Octave scripts through it. The reader accepts what Octave 7 writes for
//! the types below; the writer produces files that Octave's `load` reads back to identical values
//! (checked against live Octave by `crates/cagd-octave/tests/it/octave_format.rs`).
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
//! use cagd_octave::text_format::{read_text, write_text, Value, Workspace};
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
//! # Ok::<(), cagd_octave::TextFormatError>(())
//! ```

use thiserror::Error;

mod reader;
mod value;
mod writer;

pub use reader::{read_numeric_file, read_numeric_text, read_text, read_text_file, read_text_with};
pub use value::{CharMatrix, Quote, Value, Workspace};
pub use writer::{format_number, write_text, write_text_file};

/// Bit pattern of Octave's `NA` ("missing value"): a quiet NaN with a particular payload.
pub const NA_BITS: u64 = 0x7FF8_40F4_4000_0000;

/// Octave's `NA` as a double. `na().is_nan()` holds; use [`is_na`] to tell it from other NaNs.
///
/// ```
/// use cagd_octave::text_format::{is_na, na};
/// assert!(na().is_nan() && is_na(na()));
/// ```
pub fn na() -> f64 {
    f64::from_bits(NA_BITS)
}

/// Whether `x` is Octave's `NA` (and not just any NaN).
///
/// ```
/// use cagd_octave::text_format::{is_na, na};
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
    /// Structs and cells nested deeper than the depth limit
    /// ([`cagd::limits::Limits::max_depth`]); the reader recurses once per level, so a
    /// hostile file must not overflow the stack.
    #[error("line {line}: structs and cells are nested deeper than {limit} levels")]
    TooDeep {
        /// Line of the `# name:` header of the value that went one level too deep.
        line: usize,
        /// The depth limit.
        limit: usize,
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

#[cfg(test)]
mod tests;

//! Where a literal went wrong and how: [`Position`], [`LiteralError`], and the [`Warning`]s
//! of what was read more leniently than Octave would.

use std::fmt;

/// Where in the input something was found.
///
/// `column` counts characters from 1. `line` counts from 1 in multi-line input (scripts and
/// literals containing new lines); it is 0 for single-line input, where only the column is
/// reported.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Position {
    /// Line number from 1, or 0 for single-line input.
    pub line: usize,
    /// Column (character) number from 1.
    pub column: usize,
}

impl Position {
    /// `"column 7"` or `"line 3, column 7"`.
    pub fn describe(&self) -> String {
        self.to_string()
    }
}

impl fmt::Display for Position {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "column {}", self.column)
        } else {
            write!(f, "line {}, column {}", self.line, self.column)
        }
    }
}

/// Everything that can be wrong with a literal, an expression or a data script.
///
/// Every variant carries the [`Position`] of the offending text (except [`TooLong`], which
/// concerns the whole input) and reads as one line.
///
/// ```
/// use cagd_octave::literal::{parse_matrix, LiteralError};
///
/// let err = parse_matrix::<f64>("[1 2; 3]").unwrap_err();
/// assert!(matches!(err, LiteralError::RaggedRows { row: 2, found: 1, expected: 2, .. }));
/// assert_eq!(err.to_string(), "column 7: row 2 has 1 column(s), expected 2");
/// ```
///
/// [`TooLong`]: LiteralError::TooLong
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LiteralError {
    /// The text does not follow the grammar.
    #[error("{at}: expected {expected}, found {found}")]
    Syntax {
        /// Where.
        at: Position,
        /// What the grammar allows here, in words.
        expected: String,
        /// What was found instead.
        found: String,
    },
    /// A name that is neither bound nor a known constant.
    #[error("{at}: unknown variable `{name}`")]
    UnknownVariable {
        /// Where.
        at: Position,
        /// The name.
        name: String,
    },
    /// `name(...)` where `name` is neither a variable nor a supported function.
    #[error("{at}: unknown function `{name}`")]
    UnknownFunction {
        /// Where.
        at: Position,
        /// The name.
        name: String,
    },
    /// A matrix literal whose rows have different numbers of columns (`[1 2; 3]`).
    #[error("{at}: row {row} has {found} column(s), expected {expected}")]
    RaggedRows {
        /// Where the offending row starts.
        at: Position,
        /// The row number, from 1.
        row: usize,
        /// Its number of columns.
        found: usize,
        /// The number of columns of the first row.
        expected: usize,
    },
    /// Operands or concatenated parts of incompatible sizes, or an index out of bounds.
    #[error("{at}: {message}")]
    Shape {
        /// Where.
        at: Position,
        /// The sizes involved, in words.
        message: String,
    },
    /// A builtin function called with the wrong number or kind of arguments.
    #[error("{at}: {function}: {message}")]
    Argument {
        /// Where.
        at: Position,
        /// The function.
        function: String,
        /// What was wrong and what was expected.
        message: String,
    },
    /// `Inf`, `NaN`, or an operation whose result is not a finite real number.
    #[error("{at}: {what}; expected finite real values")]
    NonFinite {
        /// Where.
        at: Position,
        /// What produced the non-finite value.
        what: String,
    },
    /// A number literal too long or with too large an exponent.
    #[error("{at}: the number `{text}` is out of range")]
    NumberOutOfRange {
        /// Where.
        at: Position,
        /// The literal (possibly shortened).
        text: String,
    },
    /// Exact evaluation met something that has no exact rational value.
    #[error("{at}: `{name}` has no exact rational value; exact evaluation allows only numbers, + - * / and integer powers")]
    NotRational {
        /// Where.
        at: Position,
        /// The function, constant or operation.
        name: String,
    },
    /// Exact division by zero.
    #[error("{at}: division by zero")]
    DivisionByZero {
        /// Where.
        at: Position,
    },
    /// Valid Octave that this reader does not support (strings, complex numbers, matrix
    /// powers, comparison operators, statements other than assignments and `for` loops, ...).
    #[error("{at}: not supported: {what}")]
    Unsupported {
        /// Where.
        at: Position,
        /// What, in words.
        what: String,
    },
    /// `a = b = 0`: not valid Octave (the thesis's `krpaGordon` writes it).
    #[error("{at}: chained assignment `a = b = ...` is not valid Octave; expected one assignment per statement")]
    ChainedAssignment {
        /// Where the second `=` is.
        at: Position,
    },
    /// Parentheses, brackets or unary operators nested deeper than [`Limits::max_depth`](cagd::limits::Limits::max_depth).
    #[error("{at}: nested more than {limit} levels deep")]
    TooDeep {
        /// Where the limit was exceeded.
        at: Position,
        /// The limit.
        limit: usize,
    },
    /// Input longer than [`Limits::max_expression_bytes`](cagd::limits::Limits::max_expression_bytes).
    #[error("input is {length} bytes long, more than the limit of {limit}")]
    TooLong {
        /// The length of the input in bytes.
        length: usize,
        /// The limit.
        limit: usize,
    },
    /// A matrix or range with more elements than [`Limits::max_elements`](cagd::limits::Limits::max_elements), or a loop running
    /// more than [`Limits::max_iterations`](cagd::limits::Limits::max_iterations) times.
    #[error("{at}: {what} would have {count} elements or steps, more than the limit of {limit}")]
    TooLarge {
        /// Where.
        at: Position,
        /// What would be too large.
        what: String,
        /// Its size (saturated).
        count: u128,
        /// The limit.
        limit: usize,
    },
}

impl LiteralError {
    /// The position of the error, if it has one.
    pub fn position(&self) -> Option<Position> {
        use LiteralError::*;
        match self {
            Syntax { at, .. }
            | UnknownVariable { at, .. }
            | UnknownFunction { at, .. }
            | RaggedRows { at, .. }
            | Shape { at, .. }
            | Argument { at, .. }
            | NonFinite { at, .. }
            | NumberOutOfRange { at, .. }
            | NotRational { at, .. }
            | DivisionByZero { at }
            | Unsupported { at, .. }
            | ChainedAssignment { at }
            | TooDeep { at, .. }
            | TooLarge { at, .. } => Some(*at),
            TooLong { .. } => None,
        }
    }
}

/// Something evaluated more leniently than Octave would (see the module documentation).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Warning {
    /// Where.
    pub at: Position,
    /// What was done, one line.
    pub message: String,
}

impl fmt::Display for Warning {
    /// `line 3, column 7: message`, or the message alone for a warning about a whole argument
    /// (position column 0).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.at.column == 0 {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.at, self.message)
        }
    }
}

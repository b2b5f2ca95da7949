//! Octave matrix literals, ranges and curve expressions, as a user types them.
//!
//! The command line takes control points, parameters and boundary curves the way the thesis
//! writes them in Octave:
//!
//! - **matrix literals**: `[0 0 0; 0 2 2; 8 2 0; 4 0 0]'` — elements separated by spaces or
//!   commas, rows by `;` or new lines, `'` and `.'` transpose, unary minus, nested
//!   concatenation of bound variables (`[g00 g10 g20; g01 g11 g21]`), numbers such as `1e-3`
//!   and `.5`; white space inside brackets follows Octave (`[1 -2]` has two elements,
//!   `[1 - 2]` one);
//! - **ranges** `0:0.1:1` and `a:b`, with the very elements Octave computes (see
//!   [`parse_params`]);
//! - **expressions in a parameter**, exactly as the thesis data scripts write curves:
//!   `[u; 0; u-u^2]`, `[0.5; v; 0.25+v]` — numbers, the parameters `u`, `v`, `t`, the
//!   operators `+ - * / ^` and `.* ./ .^`, unary minus, parentheses, the functions `sin`,
//!   `cos`, `tan`, `sqrt`, `exp`, `log`, `abs`, the constants `pi` and `e`, and the builtins
//!   `linspace`, `zeros`, `ones`, `numel`, `length`, `size`. A [`ParamExpr`] is evaluated once
//!   per sample, so `u^2` is the square of the sample (what the author meant), not a matrix
//!   power.
//!
//! Evaluation is generic over [`LiteralScalar`]: in `f64`, or in exact rationals
//! ([`BigRational`]), where the decimal `0.2` is exactly 1/5 (via
//! [`cagd::scalar::rational_from_decimal`]) and anything not rational (`sin`, `sqrt`, `pi`,
//! non-integer powers) is the error [`LiteralError::NotRational`].
//!
//! **Policies.** `Inf` and `NaN` are rejected (every value must be finite; an operation whose
//! result is not finite, such as `1/0`, is an error). Input length, nesting depth, element
//! counts and loop iterations are limited ([`Limits`]), so no input overflows the stack or
//! exhausts memory; every failure is a typed [`LiteralError`] with its position.
//!
//! **Where we are more lenient than Octave**, always with a [`Warning`]: `^`, `*` and `/`
//! applied to two vectors of the same shape (or a vector and a scalar power) are evaluated
//! element-wise — Octave rejects them, but the thesis writes `u^2` for a sampled `u` — and a
//! constant 1×1 row in a column of sampled rows (`[u; 0; u-u^2]` with `u` a 1×N vector) is
//! repeated along the row. Octave itself would stop with "vertical dimensions mismatch".
//!
//! ```
//! use cagd_octave::literal::{parse_matrix, parse_params, ParamExpr, Env};
//!
//! // Control points of a cubic, one point per column after the transpose.
//! let b = parse_matrix::<f64>("[0 0 0; 0 2 2; 8 2 0; 4 0 0]'").unwrap();
//! assert_eq!(b.shape(), (3, 4));
//! assert_eq!(b[(2, 1)], 2.0);
//!
//! // Parameters: a number, a list or a range.
//! assert_eq!(parse_params::<f64>("0:0.25:1").unwrap(), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
//!
//! // The thesis curve c1(u) = [u; 0; u - u^2], sampled at u = 0.5.
//! let c1 = ParamExpr::parse("[u; 0; u-u^2]").unwrap();
//! let p = c1.sample_curve(&mut Env::<f64>::new(), "u", &[0.5]).unwrap();
//! assert_eq!(p.as_slice(), &[0.5, 0.0, 0.25]);
//! ```

pub(crate) mod eval;
pub(crate) mod lexer;
pub(crate) mod parser;
mod range;

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

use nalgebra::DMatrix;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use cagd::grid::PointGrid;
use cagd::limits::Limits;
use cagd::scalar::{rational_from_decimal, Scalar};

use parser::{Node, Parser};

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
    /// Parentheses, brackets or unary operators nested deeper than [`Limits::max_depth`].
    #[error("{at}: nested more than {limit} levels deep")]
    TooDeep {
        /// Where the limit was exceeded.
        at: Position,
        /// The limit.
        limit: usize,
    },
    /// Input longer than [`Limits::max_expression_bytes`].
    #[error("input is {length} bytes long, more than the limit of {limit}")]
    TooLong {
        /// The length of the input in bytes.
        length: usize,
        /// The limit.
        limit: usize,
    },
    /// A matrix or range with more elements than [`Limits::max_elements`], or a loop running
    /// more than [`Limits::max_iterations`] times.
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
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.at, self.message)
    }
}

/// A function applied element-wise.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Function {
    /// `sin`
    Sin,
    /// `cos`
    Cos,
    /// `tan`
    Tan,
    /// `sqrt`
    Sqrt,
    /// `exp`
    Exp,
    /// `log` (natural)
    Log,
    /// `abs`
    Abs,
}

impl Function {
    /// The function of that Octave name.
    pub fn from_name(name: &str) -> Option<Function> {
        Some(match name {
            "sin" => Function::Sin,
            "cos" => Function::Cos,
            "tan" => Function::Tan,
            "sqrt" => Function::Sqrt,
            "exp" => Function::Exp,
            "log" => Function::Log,
            "abs" => Function::Abs,
            _ => return None,
        })
    }

    /// The Octave name.
    pub fn name(self) -> &'static str {
        match self {
            Function::Sin => "sin",
            Function::Cos => "cos",
            Function::Tan => "tan",
            Function::Sqrt => "sqrt",
            Function::Exp => "exp",
            Function::Log => "log",
            Function::Abs => "abs",
        }
    }
}

/// Why a power has no value in the scalar type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PowerError {
    /// No exact rational value (non-integer exponent).
    NotRational,
    /// Zero to a negative power.
    DivisionByZero,
    /// The exact result would be unreasonably large.
    TooLarge,
}

/// A number type the evaluator works in: `f64` (as Octave) or [`BigRational`] (exact).
pub trait LiteralScalar: Scalar {
    /// Whether arithmetic is exact (no rounding).
    const EXACT: bool;

    /// Whether an exact number has grown too large to compute with in reasonable time
    /// (numerator and denominator together longer than [`MAX_EXACT_BITS`]); never for `f64`.
    fn is_oversized(&self) -> bool {
        false
    }

    /// The length of the number in 64-bit words (numerator and denominator together, at least
    /// 1; always 1 for `f64`). An exact operation on operands of `a` and `b` words is
    /// charged `32 (a + b)²` element operations against an evaluation's work limit — the
    /// binary gcd that reduces every exact result is quadratic in the length (found by fuzzing: a short expression on
    /// 1000-bit rationals over a range of a few hundred elements took a third of a second
    /// while charged as a few thousand operations).
    fn words(&self) -> u128 {
        1
    }

    /// The length of the number in bits, numerator and denominator together (exact numbers;
    /// 0 for `f64`, whose cost does not depend on the value). Estimates of exact work weigh
    /// each operation by the size its numbers reach ([`cagd::limits::exact_op_cost`]).
    fn bits(&self) -> u128 {
        0
    }

    /// The value of a decimal literal (`text` as lexed; `nearest` its nearest double).
    /// `None` if it is not finite in this type.
    fn from_literal(text: &str, nearest: f64) -> Option<Self>;

    /// `f(x)`, or `None` where the value is not representable (any transcendental function
    /// in exact arithmetic). Non-finite `f64` results are returned and rejected by the caller.
    fn apply(f: Function, x: &Self) -> Option<Self>;

    /// `pi` or `e`; `None` in exact arithmetic.
    fn constant(name: &str) -> Option<Self>;

    /// `base ^ exponent` for scalars, as Octave's `xpow(double, double)` (`std::pow`).
    fn pow(base: &Self, exponent: &Self) -> Result<Self, PowerError>;

    /// `base .^ exponent` for one element of a non-scalar array. Octave's `elem_xpow`
    /// computes `x.^2` as `x*x`, `x.^3` as `x*x*x` and `x.^-1` as `1/x`, which may differ in
    /// the last bit from `pow`; the default is [`LiteralScalar::pow`].
    fn pow_in_array(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        Self::pow(base, exponent)
    }

    /// `a / b`, or `None` for an exact division by zero (`f64` returns ±∞ or NaN, rejected by
    /// the caller).
    fn checked_div(a: &Self, b: &Self) -> Option<Self>;

    /// The value as a non-negative integer count or index, if it is one.
    fn to_count(&self) -> Option<usize>;

    /// `linspace(a, b, n)`: Octave's doubles ([`cagd::linspace()`]) for `f64`; exact
    /// `a + i(b−a)/(n−1)` for rationals.
    fn linspace(a: &Self, b: &Self, n: usize) -> Vec<Self>;

    /// The range `base:increment:limit` (Octave's elements for `f64`, exact for rationals);
    /// `Err(count)` if it would have more than `max` elements.
    fn range(base: &Self, increment: &Self, limit: &Self, max: usize) -> Result<Vec<Self>, u128>;
}

impl LiteralScalar for f64 {
    const EXACT: bool = false;

    fn from_literal(_text: &str, nearest: f64) -> Option<Self> {
        nearest.is_finite().then_some(nearest)
    }

    fn apply(f: Function, x: &Self) -> Option<Self> {
        Some(match f {
            Function::Sin => x.sin(),
            Function::Cos => x.cos(),
            Function::Tan => x.tan(),
            Function::Sqrt => x.sqrt(),
            Function::Exp => x.exp(),
            Function::Log => x.ln(),
            Function::Abs => x.abs(),
        })
    }

    fn constant(name: &str) -> Option<Self> {
        match name {
            "pi" => Some(std::f64::consts::PI),
            "e" => Some(std::f64::consts::E),
            _ => None,
        }
    }

    fn pow(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        Ok(base.powf(*exponent))
    }

    fn pow_in_array(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        Ok(match *exponent {
            2.0 => base * base,
            3.0 => base * base * base,
            -1.0 => 1.0 / base,
            _ => base.powf(*exponent),
        })
    }

    fn checked_div(a: &Self, b: &Self) -> Option<Self> {
        Some(a / b)
    }

    fn to_count(&self) -> Option<usize> {
        (*self >= 0.0 && self.fract() == 0.0 && *self < 9.0e15).then_some(*self as usize)
    }

    fn linspace(a: &Self, b: &Self, n: usize) -> Vec<Self> {
        cagd::linspace(*a, *b, n)
    }

    fn range(base: &Self, increment: &Self, limit: &Self, max: usize) -> Result<Vec<Self>, u128> {
        range::octave_range(*base, *increment, *limit, max)
            .map_err(|range::RangeError::TooLarge(n)| n)
    }
}

/// Largest size, in bits, of an exact number's numerator plus denominator (about 1 200
/// decimal digits): exact literals and results beyond it are refused
/// ([`LiteralError::NumberOutOfRange`], [`LiteralError::TooLarge`]), since every operation on
/// them costs a gcd quadratic in their size (found by fuzzing: `24.445^46913` took minutes,
/// a range stepping by `1e-5828 - 2` took seconds per thousand elements).
pub const MAX_EXACT_BITS: u64 = 1 << 12;

impl LiteralScalar for BigRational {
    const EXACT: bool = true;

    fn is_oversized(&self) -> bool {
        self.numer().bits() + self.denom().bits() > MAX_EXACT_BITS
    }

    fn words(&self) -> u128 {
        self.bits().div_ceil(64).max(1)
    }

    fn bits(&self) -> u128 {
        u128::from(self.numer().bits() + self.denom().bits())
    }

    fn from_literal(text: &str, _nearest: f64) -> Option<Self> {
        rational_from_decimal(text).filter(|x| !x.is_oversized())
    }

    fn apply(f: Function, x: &Self) -> Option<Self> {
        match f {
            Function::Abs => Some(x.abs()),
            _ => None,
        }
    }

    fn constant(_name: &str) -> Option<Self> {
        None
    }

    fn pow(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        if !exponent.is_integer() {
            return Err(PowerError::NotRational);
        }
        let n = exponent.to_integer();
        if base.is_zero() {
            return match n.sign() {
                num_bigint::Sign::Minus => Err(PowerError::DivisionByZero),
                num_bigint::Sign::NoSign => Ok(BigRational::one()),
                num_bigint::Sign::Plus => Ok(BigRational::zero()),
            };
        }
        if base.abs().is_one() {
            let odd = n.bit(0);
            return Ok(if base.is_negative() && odd {
                -BigRational::one()
            } else {
                BigRational::one()
            });
        }
        let bits = base.numer().bits() + base.denom().bits();
        let magnitude = n.magnitude().to_u64().unwrap_or(u64::MAX);
        if magnitude.saturating_mul(bits) > MAX_EXACT_BITS {
            return Err(PowerError::TooLarge);
        }
        // Numerator and denominator are coprime, so are their powers: no gcd needed (a gcd
        // at every squaring made large powers quadratic).
        let e = magnitude as u32;
        let p = BigRational::new_raw(
            num_traits::pow(base.numer().clone(), e as usize),
            num_traits::pow(base.denom().clone(), e as usize),
        );
        Ok(if n.is_negative() { p.recip() } else { p })
    }

    fn checked_div(a: &Self, b: &Self) -> Option<Self> {
        (!b.is_zero()).then(|| a / b)
    }

    fn to_count(&self) -> Option<usize> {
        if self.is_integer() && !self.is_negative() {
            self.to_integer().to_usize()
        } else {
            None
        }
    }

    fn linspace(a: &Self, b: &Self, n: usize) -> Vec<Self> {
        match n {
            0 => Vec::new(),
            1 => vec![b.clone()],
            _ => {
                let step = (b - a) / BigRational::from_integer(BigInt::from(n - 1));
                let mut out: Vec<Self> = (0..n)
                    .map(|i| a + &step * BigRational::from_integer(BigInt::from(i)))
                    .collect();
                out[n - 1] = b.clone();
                out
            }
        }
    }

    fn range(base: &Self, increment: &Self, limit: &Self, max: usize) -> Result<Vec<Self>, u128> {
        range::exact_range(base, increment, limit, max).map_err(|range::RangeError::TooLarge(n)| n)
    }
}

/// Variables bound to matrices, the limits in force, and the warnings collected while
/// evaluating.
#[derive(Debug, Clone, PartialEq)]
pub struct Env<T: LiteralScalar = f64> {
    vars: BTreeMap<String, DMatrix<T>>,
    warnings: BTreeSet<Warning>,
    limits: Limits,
    pub(crate) meter: eval::Meter,
}

impl<T: LiteralScalar> Default for Env<T> {
    fn default() -> Self {
        Env {
            vars: BTreeMap::new(),
            warnings: BTreeSet::new(),
            limits: Limits::default(),
            meter: eval::Meter::default(),
        }
    }
}

impl<T: LiteralScalar> Env<T> {
    /// An empty environment with the default [`Limits`].
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty environment with the given limits.
    pub fn with_limits(limits: Limits) -> Self {
        Env {
            limits,
            ..Self::default()
        }
    }

    /// The limits in force.
    pub fn limits(&self) -> &Limits {
        &self.limits
    }

    /// Binds `name` to a matrix (replacing any previous value).
    pub fn bind(&mut self, name: &str, value: DMatrix<T>) {
        self.vars.insert(name.to_string(), value);
    }

    /// Binds `name` to a scalar (a 1×1 matrix).
    pub fn bind_scalar(&mut self, name: &str, value: T) {
        self.bind(name, DMatrix::from_element(1, 1, value));
    }

    /// Removes a binding.
    pub fn unbind(&mut self, name: &str) -> Option<DMatrix<T>> {
        self.vars.remove(name)
    }

    /// The value bound to `name`.
    pub fn get(&self, name: &str) -> Option<&DMatrix<T>> {
        self.vars.get(name)
    }

    /// All bound names, sorted.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.vars.keys().map(String::as_str)
    }

    /// The warnings collected so far, sorted by position.
    pub fn warnings(&self) -> impl Iterator<Item = &Warning> {
        self.warnings.iter()
    }

    /// Removes and returns the warnings collected so far.
    pub fn take_warnings(&mut self) -> Vec<Warning> {
        std::mem::take(&mut self.warnings).into_iter().collect()
    }

    pub(crate) fn warn(&mut self, at: Position, message: String) {
        self.warnings.insert(Warning { at, message });
    }
}

/// A parsed expression: a matrix literal, a range, or an expression in bound variables.
///
/// ```
/// use cagd_octave::literal::{Env, Expr};
///
/// let e = Expr::parse("[g00 g10; g01 g11]").unwrap();
/// let mut env = Env::<f64>::new();
/// for (name, x) in [("g00", 0.0), ("g10", 1.0), ("g01", 2.0), ("g11", 3.0)] {
///     env.bind_scalar(name, x);
/// }
/// let m = e.eval(&mut env).unwrap();
/// assert_eq!(m.shape(), (2, 2));
/// assert_eq!(m[(1, 0)], 2.0);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    pub(crate) node: Node,
    pub(crate) at: Position,
}

impl Expr {
    /// Parses one expression with the default [`Limits`]. A trailing `;` and surrounding
    /// white space or comments are allowed; an assignment is not (use a data script).
    pub fn parse(text: &str) -> Result<Expr, LiteralError> {
        Self::parse_with(text, &Limits::default())
    }

    /// Parses one expression with the given limits.
    pub fn parse_with(text: &str, limits: &Limits) -> Result<Expr, LiteralError> {
        if text.len() > limits.max_expression_bytes {
            return Err(LiteralError::TooLong {
                length: text.len(),
                limit: limits.max_expression_bytes,
            });
        }
        let tokens = lexer::lex(text, text.contains('\n'))?;
        let mut p = Parser::new(&tokens, limits.max_depth);
        while p.peek().tok == lexer::Tok::Newline {
            p.bump();
        }
        if p.peek().tok == lexer::Tok::Eof {
            return Err(p.unexpected("an expression"));
        }
        let e = p.expr()?;
        while matches!(p.peek().tok, lexer::Tok::Newline | lexer::Tok::Semi) {
            p.bump();
        }
        match p.peek().tok {
            lexer::Tok::Eof => Ok(e),
            lexer::Tok::Assign => Err(LiteralError::Unsupported {
                at: p.peek().at,
                what: "assignments outside a data script".into(),
            }),
            _ => Err(p.unexpected("end of input")),
        }
    }

    /// Evaluates the expression with the variables of `env` (warnings are added to `env`).
    pub fn eval<T: LiteralScalar>(&self, env: &mut Env<T>) -> Result<DMatrix<T>, LiteralError> {
        eval::eval(self, env)
    }

    /// Position of the expression in its source.
    pub fn position(&self) -> Position {
        self.at
    }

    /// The size of the expression: its number of nodes (numbers, names, operands, call
    /// arguments, matrix elements). Evaluating it does about that many operations on values
    /// of the size of its operands, so it is the cost of one evaluation on scalars.
    ///
    /// ```
    /// use cagd_octave::literal::Expr;
    /// // The matrix, its three elements, the two operands of `u-u^2` and the two of `u^2`.
    /// assert_eq!(Expr::parse("[u; 0; u-u^2]").unwrap().node_count(), 8);
    /// ```
    pub fn node_count(&self) -> usize {
        eval::node_count(self)
    }

    /// The names the expression reads (variables and the names of calls and indexings),
    /// sorted, without builtin functions and constants.
    pub fn free_names(&self) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        eval::collect_names(self, &mut out);
        out
    }

    /// Every name read, with the position of its first use.
    pub fn name_uses(&self) -> BTreeMap<String, Position> {
        let mut out = BTreeMap::new();
        eval::collect_name_uses(self, &mut out);
        out
    }
}

/// Parses and evaluates a constant matrix literal (no variables).
///
/// ```
/// use num_rational::BigRational;
/// let m = cagd_octave::literal::parse_matrix::<BigRational>("[0.2, -.5; 1e-1 3]").unwrap();
/// assert_eq!(m[(0, 0)], BigRational::new(1.into(), 5.into()));
/// assert_eq!(m[(1, 0)], BigRational::new(1.into(), 10.into()));
/// ```
pub fn parse_matrix<T: LiteralScalar>(text: &str) -> Result<DMatrix<T>, LiteralError> {
    parse_matrix_with(text, &Limits::default())
}

/// [`parse_matrix`] within the given limits.
pub fn parse_matrix_with<T: LiteralScalar>(
    text: &str,
    limits: &Limits,
) -> Result<DMatrix<T>, LiteralError> {
    Expr::parse_with(text, limits)?.eval(&mut Env::with_limits(*limits))
}

/// Parses parameter values: a number (`0.5`), a list (`[0 0.25 0.5]`), a range (`0:0.1:1`,
/// `a:b`) or any expression giving a row or column vector (`linspace(0,1,5)`).
///
/// Ranges have Octave's elements: element `i` is `base + i·increment`, the number of elements
/// is Octave's tolerant count of `(limit − base)/increment + 1`, and the last element is
/// clamped to the limit — so `0:0.1:1` gives exactly the doubles Octave prints for it, and
/// `0:0.1:0.3` ends in `0.3`. In exact arithmetic the elements are exact (`1/10`, `1/5`, …).
///
/// ```
/// let t = cagd_octave::literal::parse_params::<f64>("0:0.1:0.3").unwrap();
/// assert_eq!(t, vec![0.0, 0.1, 0.2, 0.3]);
/// assert_eq!(cagd_octave::literal::parse_params::<f64>("0.5").unwrap(), vec![0.5]);
/// ```
pub fn parse_params<T: LiteralScalar>(text: &str) -> Result<Vec<T>, LiteralError> {
    parse_params_with(text, &Limits::default())
}

/// [`parse_params`] within the given limits.
pub fn parse_params_with<T: LiteralScalar>(
    text: &str,
    limits: &Limits,
) -> Result<Vec<T>, LiteralError> {
    let e = Expr::parse_with(text, limits)?;
    let m = e.eval(&mut Env::with_limits(*limits))?;
    vector_of(m, e.at)
}

/// Parses one plain decimal number (optional sign, digits with an optional point, optional
/// exponent `e`/`E`/`d`/`D`), as numeric text files hold them. `None` for anything else,
/// including `Inf` and `NaN`, and for numbers out of range (more than 400 characters, an
/// exponent beyond ±10000, or not finite in `T`).
///
/// ```
/// use cagd_octave::literal::parse_number;
/// assert_eq!(parse_number::<f64>("-1.5e+00"), Some(-1.5));
/// assert_eq!(parse_number::<f64>("Inf"), None);
/// assert_eq!(parse_number::<f64>("1e999"), None);
/// ```
pub fn parse_number<T: LiteralScalar>(text: &str) -> Option<T> {
    if text.is_empty() || text.len() > 400 {
        return None;
    }
    let body = text.strip_prefix(['+', '-']).unwrap_or(text);
    let (mantissa, exponent) = match body.find(['e', 'E', 'd', 'D']) {
        Some(k) => (&body[..k], Some(&body[k + 1..])),
        None => (body, None),
    };
    let mut digits = 0;
    let mut points = 0;
    for c in mantissa.chars() {
        match c {
            '0'..='9' => digits += 1,
            '.' => points += 1,
            _ => return None,
        }
    }
    if digits == 0 || points > 1 {
        return None;
    }
    let mut normalized = format!("{}{mantissa}", &text[..text.len() - body.len()]);
    if let Some(e) = exponent {
        let unsigned = e.strip_prefix(['+', '-']).unwrap_or(e);
        if unsigned.is_empty() || !unsigned.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        if unsigned.len() > 6 || unsigned.parse::<u32>().ok()? > 10_000 {
            return None;
        }
        normalized.push('e');
        normalized.push_str(e);
    }
    let nearest = normalized.parse::<f64>().ok()?;
    T::from_literal(&normalized, nearest)
}

/// The elements of a row or column vector (or scalar), in order.
pub(crate) fn vector_of<T: LiteralScalar>(
    m: DMatrix<T>,
    at: Position,
) -> Result<Vec<T>, LiteralError> {
    if m.nrows() > 1 && m.ncols() > 1 {
        return Err(LiteralError::Shape {
            at,
            message: format!(
                "expected a number, a list or a range, got a {}×{} matrix",
                m.nrows(),
                m.ncols()
            ),
        });
    }
    Ok(m.iter().cloned().collect())
}

/// The parameter names an expression may leave free: `u`, `v` and `t`.
pub const PARAMETERS: [&str; 3] = ["u", "v", "t"];

/// An expression in free parameters (`u`, `v`, `t`) evaluated once per sample — how the
/// thesis writes curves: `c1 = [u; 0; u-u^2]`, `d1 = [0.5; v; 0.25+v]`.
///
/// Each evaluation binds the parameter to one scalar sample, so `u^2` is the square of that
/// sample. The value at a sample must be a scalar, a row or a column vector (the point); the
/// samples of a curve become the columns of a d × k matrix, like `T` in the thesis function
/// `deCasteljau`. Sampling evaluates in a copy of the environment and adds only its warnings
/// to it.
///
/// A `ParamExpr` may read other bound variables (from `--script` files: see
/// [`crate::script`]) and may depend on other parameter expressions of a script,
/// which are evaluated first at every sample (its *prelude*).
#[derive(Debug, Clone, PartialEq)]
pub struct ParamExpr {
    pub(crate) prelude: Vec<(String, Expr)>,
    pub(crate) expr: Expr,
    pub(crate) source: String,
}

impl ParamExpr {
    /// Parses an expression (with the default [`Limits`]).
    pub fn parse(text: &str) -> Result<ParamExpr, LiteralError> {
        Self::parse_with(text, &Limits::default())
    }

    /// Parses an expression within the given limits.
    pub fn parse_with(text: &str, limits: &Limits) -> Result<ParamExpr, LiteralError> {
        Ok(ParamExpr {
            prelude: Vec::new(),
            expr: Expr::parse_with(text, limits)?,
            source: text.to_string(),
        })
    }

    /// The source text.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The size of one evaluation: the nodes of the expression and of its prelude
    /// ([`Expr::node_count`]). Sampling at `k` parameter values costs about `k` times this.
    ///
    /// ```
    /// use cagd_octave::literal::ParamExpr;
    /// assert_eq!(ParamExpr::parse("[u; 0; u-u^2]").unwrap().node_count(), 8);
    /// ```
    pub fn node_count(&self) -> usize {
        self.prelude
            .iter()
            .map(|(_, e)| e.node_count())
            .fold(self.expr.node_count(), usize::saturating_add)
    }

    /// The parameters (`u`, `v`, `t`) used but not bound in `env`, sorted.
    pub fn parameters<T: LiteralScalar>(&self, env: &Env<T>) -> Vec<&'static str> {
        let mut bound: BTreeSet<&str> = env.names().collect();
        let mut used = BTreeSet::new();
        for (name, e) in &self.prelude {
            for n in e.free_names() {
                if !bound.contains(n.as_str()) {
                    used.insert(n);
                }
            }
            bound.insert(name.as_str());
        }
        for n in self.expr.free_names() {
            if !bound.contains(n.as_str()) {
                used.insert(n);
            }
        }
        PARAMETERS
            .iter()
            .copied()
            .filter(|p| used.contains(*p))
            .collect()
    }

    /// Checks that every name is bound in `env`, is one of `params`, or is computed by the
    /// prelude — so that an unknown name is reported once, before sampling.
    pub fn check<T: LiteralScalar>(
        &self,
        env: &Env<T>,
        params: &[&str],
    ) -> Result<(), LiteralError> {
        let mut known: BTreeSet<String> = env.names().map(str::to_string).collect();
        known.extend(params.iter().map(|p| p.to_string()));
        let check = |e: &Expr, known: &BTreeSet<String>| -> Result<(), LiteralError> {
            for (name, at) in e.name_uses() {
                if !known.contains(&name) && !eval::is_builtin_name(&name) {
                    return Err(eval::unknown_name_error(e, &name, at));
                }
            }
            Ok(())
        };
        for (name, e) in &self.prelude {
            check(e, &known)?;
            known.insert(name.clone());
        }
        check(&self.expr, &known)
    }

    /// The value with the parameters bound as given (e.g. `[("u", 0.5)]`).
    pub fn eval_at<T: LiteralScalar>(
        &self,
        env: &Env<T>,
        bindings: &[(&str, T)],
    ) -> Result<DMatrix<T>, LiteralError> {
        let mut local = env.clone();
        self.eval_in(&mut local, bindings)
    }

    /// The value with the parameters bound as given, and the work its evaluation did: element
    /// results and matrix-product terms, an exact operation on numbers of `a` and `b` words
    /// counting `32 (a + b)²` (the measure of an evaluation's own limit). The command line
    /// evaluates an expression once at its largest parameter this way to estimate what
    /// sampling it will cost before it starts.
    ///
    /// ```
    /// use cagd_octave::literal::{Env, ParamExpr};
    /// use num_rational::BigRational;
    /// let e = ParamExpr::parse("[u; u^2]").unwrap();
    /// let (_, cheap) = e.eval_metered(&Env::<f64>::new(), &[("u", 0.5)]).unwrap();
    /// let half = BigRational::new(1.into(), 2.into());
    /// let (p, exact) = e.eval_metered(&Env::<BigRational>::new(), &[("u", half)]).unwrap();
    /// assert_eq!(p[(1, 0)], BigRational::new(1.into(), 4.into()));
    /// assert!(cheap < exact);
    /// ```
    ///
    /// # Errors
    /// As [`ParamExpr::eval_at`].
    pub fn eval_metered<T: LiteralScalar>(
        &self,
        env: &Env<T>,
        bindings: &[(&str, T)],
    ) -> Result<(DMatrix<T>, u128), LiteralError> {
        let mut local = env.clone();
        for (name, value) in bindings {
            local.bind_scalar(name, value.clone());
        }
        let mut work: u128 = 0;
        for (name, e) in &self.prelude {
            let value = e.eval(&mut local)?;
            work = work.saturating_add(local.meter.work());
            local.bind(name, value);
        }
        let value = self.expr.eval(&mut local)?;
        Ok((value, work.saturating_add(local.meter.work())))
    }

    fn eval_in<T: LiteralScalar>(
        &self,
        local: &mut Env<T>,
        bindings: &[(&str, T)],
    ) -> Result<DMatrix<T>, LiteralError> {
        for (name, value) in bindings {
            local.bind_scalar(name, value.clone());
        }
        for (name, e) in &self.prelude {
            let value = e.eval(local)?;
            local.bind(name, value);
        }
        self.expr.eval(local)
    }

    /// Samples a curve in parameter `param` at `values`: a d × k matrix whose column `j` is
    /// the point at `values[j]`. Each sample must evaluate to a vector of the same length d.
    ///
    /// ```
    /// use cagd_octave::literal::{Env, ParamExpr};
    /// let d1 = ParamExpr::parse("[0.5; v; 0.25+v]").unwrap();
    /// let pts = d1.sample_curve(&mut Env::<f64>::new(), "v", &[0.0, 1.0]).unwrap();
    /// assert_eq!(pts.column(1).as_slice(), &[0.5, 1.0, 1.25]);
    /// ```
    pub fn sample_curve<T: LiteralScalar>(
        &self,
        env: &mut Env<T>,
        param: &str,
        values: &[T],
    ) -> Result<DMatrix<T>, LiteralError> {
        self.check(env, &[param])?;
        let mut local = env.clone();
        let mut columns: Vec<T> = Vec::new();
        let mut dim = None;
        for t in values {
            let p = self.eval_in(&mut local, &[(param, t.clone())])?;
            let d = self.point_dim(&p, dim)?;
            dim = Some(d);
            columns.extend(p.iter().cloned());
        }
        env.warnings.append(&mut local.warnings);
        Ok(DMatrix::from_vec(dim.unwrap_or(0), values.len(), columns))
    }

    /// Samples a surface in `u` and `v` on the grid `us × vs`: a [`PointGrid`] of shape
    /// `(us.len(), vs.len(), d)` with `grid[[i, j, k]]` coordinate `k` of the point at
    /// `(us[i], vs[j])` (the layout of `P(i,j,:)` in the thesis function `ploskevB`).
    pub fn sample_surface<T: LiteralScalar>(
        &self,
        env: &mut Env<T>,
        us: &[T],
        vs: &[T],
    ) -> Result<PointGrid<T>, LiteralError> {
        self.check(env, &["u", "v"])?;
        let total = us.len().saturating_mul(vs.len());
        if total > env.limits.max_elements {
            return Err(LiteralError::TooLarge {
                at: self.expr.at,
                what: "the sample grid".into(),
                count: total as u128,
                limit: env.limits.max_elements,
            });
        }
        let mut local = env.clone();
        let mut points: Vec<DMatrix<T>> = Vec::with_capacity(total);
        let mut dim = None;
        for u in us {
            for v in vs {
                let p = self.eval_in(&mut local, &[("u", u.clone()), ("v", v.clone())])?;
                dim = Some(self.point_dim(&p, dim)?);
                points.push(p);
            }
        }
        let d = dim.unwrap_or(0);
        env.warnings.append(&mut local.warnings);
        Ok(PointGrid::from_shape_fn(
            (us.len(), vs.len(), d),
            |(i, j, k)| points[i * vs.len() + j][k].clone(),
        ))
    }

    fn point_dim<T: LiteralScalar>(
        &self,
        p: &DMatrix<T>,
        previous: Option<usize>,
    ) -> Result<usize, LiteralError> {
        if p.nrows() > 1 && p.ncols() > 1 {
            return Err(LiteralError::Shape {
                at: self.expr.at,
                message: format!(
                    "a curve point must be a vector, but the expression gives a {}×{} matrix",
                    p.nrows(),
                    p.ncols()
                ),
            });
        }
        let d = p.len();
        match previous {
            Some(prev) if prev != d => Err(LiteralError::Shape {
                at: self.expr.at,
                message: format!(
                    "points of different dimensions at different samples ({prev} and {d})"
                ),
            }),
            _ => Ok(d),
        }
    }
}

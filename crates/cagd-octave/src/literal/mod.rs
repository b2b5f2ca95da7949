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
//!   power. [`ParamExpr::derivative`] differentiates one symbolically (`d/du [u; 0; u-u^2]`
//!   is `[1; 0; 1 - 2 .* u .* 1]`), exact wherever the expression is rational.
//!
//! Evaluation is generic over [`LiteralScalar`]: in `f64`, or in exact rationals
//! ([`BigRational`](num_rational::BigRational)), where the decimal `0.2` is exactly 1/5 (via
//! [`cagd::scalar::rational_from_decimal`]) and anything not rational (`sin`, `sqrt`, `pi`,
//! non-integer powers) is the error [`LiteralError::NotRational`].
//!
//! **Policies.** `Inf` and `NaN` are rejected (every value must be finite; an operation whose
//! result is not finite, such as `1/0`, is an error). Input length, nesting depth, element
//! counts and loop iterations are limited ([`Limits`](cagd::limits::Limits)), so no input overflows the stack or
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

mod derivative;
mod env;
mod error;
pub(crate) mod eval;
mod expr;
pub(crate) mod lexer;
mod param_expr;
pub(crate) mod parser;
mod range;
mod scalar;

pub use env::Env;
pub use error::{LiteralError, Position, Warning};
pub use expr::{
    parse_matrix, parse_matrix_with, parse_number, parse_params, parse_params_warning,
    parse_params_with,
};
pub use param_expr::{ParamExpr, PARAMETERS};
pub use parser::Expr;
pub use scalar::{Function, LiteralScalar, PowerError, MAX_EXACT_BITS};

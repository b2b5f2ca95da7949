//! Parsing and evaluating an [`Expr`], and the entry points for constant literals and
//! parameter lists.

use std::collections::{BTreeMap, BTreeSet};

use nalgebra::DMatrix;

use cagd::limits::Limits;

use super::lexer;
use super::parser::Parser;
use super::{eval, Env, Expr, LiteralError, LiteralScalar, Position, Warning};

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
    parse_params_warning(text, limits).map(|(values, _)| values)
}

/// [`parse_params_with`], also returning the [`Warning`]s of what was read more leniently
/// than Octave would (the command line refuses those in an argument).
///
/// ```
/// use cagd::limits::Limits;
/// use cagd_octave::literal::parse_params_warning;
/// let (t, warnings) = parse_params_warning::<f64>("[1 2]*[3 4]", &Limits::default()).unwrap();
/// assert_eq!(t, vec![3.0, 8.0]);
/// assert_eq!(warnings.len(), 1);
/// ```
pub fn parse_params_warning<T: LiteralScalar>(
    text: &str,
    limits: &Limits,
) -> Result<(Vec<T>, Vec<Warning>), LiteralError> {
    let e = Expr::parse_with(text, limits)?;
    let mut env = Env::with_limits(*limits);
    let m = e.eval(&mut env)?;
    Ok((vector_of(m, e.at)?, env.take_warnings()))
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
fn vector_of<T: LiteralScalar>(m: DMatrix<T>, at: Position) -> Result<Vec<T>, LiteralError> {
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

//! Evaluation of parsed expressions over any [`LiteralScalar`].
//!
//! Values are matrices (`DMatrix<T>`, a scalar is 1×1), combined with Octave's rules:
//! element-wise operators broadcast dimensions of length 1, `*` is the matrix product, `'`
//! transposes, `[...]` concatenates. The lenient rules for vectors are documented in the
//! parent module.

use std::collections::{BTreeMap, BTreeSet};

use nalgebra::DMatrix;

use super::parser::{BinOp, Node, Row};
use super::{Env, Expr, Function, LiteralError, LiteralScalar, Position, PowerError};

/// Builtin functions other than the element-wise [`Function`]s.
const BUILTINS: &[&str] = &["linspace", "zeros", "ones", "numel", "length", "size"];
/// Named constants.
const CONSTANTS: &[&str] = &["pi", "e"];

/// Whether `name` is a builtin function or constant.
pub(crate) fn is_builtin_name(name: &str) -> bool {
    Function::from_name(name).is_some() || BUILTINS.contains(&name) || CONSTANTS.contains(&name)
}

/// The error for a name that is not bound (special names get their own message).
pub(crate) fn unknown_name_error(e: &Expr, name: &str, at: Position) -> LiteralError {
    let is_call = is_called(e, name, at);
    unknown_name(name, at, is_call)
}

fn unknown_name(name: &str, at: Position, is_call: bool) -> LiteralError {
    match name {
        "Inf" | "inf" | "NaN" | "nan" | "NA" => LiteralError::NonFinite {
            at,
            what: format!("`{name}` is not accepted"),
        },
        "i" | "j" | "I" | "J" => LiteralError::Unsupported {
            at,
            what: format!("complex numbers (`{name}` is the imaginary unit)"),
        },
        _ if is_call => LiteralError::UnknownFunction {
            at,
            name: name.to_string(),
        },
        _ => LiteralError::UnknownVariable {
            at,
            name: name.to_string(),
        },
    }
}

/// Calls `f` on every node of the tree (pre-order).
pub(crate) fn walk<'e>(e: &'e Expr, f: &mut dyn FnMut(&'e Expr)) {
    f(e);
    match &e.node {
        Node::Number { .. } | Node::Var(_) | Node::Colon => {}
        Node::Call { args, .. } => args.iter().for_each(|a| walk(a, f)),
        Node::Neg(x) | Node::Transpose(x) => walk(x, f),
        Node::Chain { first, rest } => {
            walk(first, f);
            rest.iter().for_each(|(_, _, x)| walk(x, f));
        }
        Node::Range {
            base,
            increment,
            limit,
        } => {
            walk(base, f);
            if let Some(s) = increment {
                walk(s, f);
            }
            walk(limit, f);
        }
        Node::Matrix(rows) => rows
            .iter()
            .flat_map(|r| r.elements.iter())
            .for_each(|x| walk(x, f)),
    }
}

/// The number of nodes of the tree: numbers, names, operands of a chain, calls and their
/// arguments, matrix elements, range parts.
pub(crate) fn node_count(e: &Expr) -> usize {
    let mut count = 0usize;
    walk(e, &mut |_| count += 1);
    count
}

fn is_called(e: &Expr, name: &str, at: Position) -> bool {
    let mut found = false;
    walk(e, &mut |x| {
        if let Node::Call { name: n, .. } = &x.node {
            if n == name && x.at == at {
                found = true;
            }
        }
    });
    found
}

/// Names read by the expression: every variable, and every called name that is not a
/// builtin function.
pub(crate) fn collect_names(e: &Expr, out: &mut BTreeSet<String>) {
    walk(e, &mut |x| match &x.node {
        Node::Var(n) => {
            out.insert(n.clone());
        }
        Node::Call { name, .. } if !is_builtin_name(name) || CONSTANTS.contains(&name.as_str()) => {
            out.insert(name.clone());
        }
        _ => {}
    });
}

/// Like [`collect_names`], with the position of each name's first use.
pub(crate) fn collect_name_uses(e: &Expr, out: &mut BTreeMap<String, Position>) {
    walk(e, &mut |x| match &x.node {
        Node::Var(n) => {
            out.entry(n.clone()).or_insert(x.at);
        }
        Node::Call { name, .. } if !is_builtin_name(name) || CONSTANTS.contains(&name.as_str()) => {
            out.entry(name.clone()).or_insert(x.at);
        }
        _ => {}
    });
}

/// Whether the expression reads a variable bound in `env`.
fn reads_variables<T: LiteralScalar>(e: &Expr, env: &Env<T>) -> bool {
    let mut found = false;
    walk(e, &mut |x| match &x.node {
        Node::Var(n) | Node::Call { name: n, .. } if env.get(n).is_some() => found = true,
        _ => {}
    });
    found
}

fn scalar<T: LiteralScalar>(x: T) -> DMatrix<T> {
    DMatrix::from_element(1, 1, x)
}

fn shape<T: LiteralScalar>(m: &DMatrix<T>) -> String {
    format!("{}×{}", m.nrows(), m.ncols())
}

fn check_size(at: Position, what: &str, count: u128, env_max: usize) -> Result<(), LiteralError> {
    if count > env_max as u128 {
        return Err(LiteralError::TooLarge {
            at,
            what: what.to_string(),
            count,
            limit: env_max,
        });
    }
    Ok(())
}

fn finite<T: LiteralScalar>(
    x: T,
    at: Position,
    what: impl FnOnce() -> String,
) -> Result<T, LiteralError> {
    if x.is_oversized() {
        Err(LiteralError::TooLarge {
            at,
            what: "an exact number's numerator and denominator (in bits)".into(),
            count: u128::from(crate::literal::MAX_EXACT_BITS) + 1,
            limit: crate::literal::MAX_EXACT_BITS as usize,
        })
    } else if x.is_finite_value() {
        Ok(x)
    } else {
        Err(LiteralError::NonFinite { at, what: what() })
    }
}

/// How many element operations one evaluation may do, per allowed element.
const WORK_PER_ELEMENT: u128 = 64;

fn charge<T: LiteralScalar>(
    env: &mut Env<T>,
    at: Position,
    work: u128,
) -> Result<(), LiteralError> {
    env.meter.work = env.meter.work.saturating_add(work);
    let max = env.limits().max_elements;
    let limit = WORK_PER_ELEMENT * max as u128;
    if env.meter.work > limit {
        return Err(work_exceeded(env.meter.work, limit, at));
    }
    Ok(())
}

fn work_exceeded(work: u128, limit: u128, at: Position) -> LiteralError {
    LiteralError::TooLarge {
        at,
        what: "the evaluation's work (element operations)".into(),
        count: work,
        limit: usize::try_from(limit).unwrap_or(usize::MAX),
    }
}

/// The work still allowed to the evaluation in progress.
fn remaining_work<T: LiteralScalar>(env: &Env<T>) -> u128 {
    let limit = WORK_PER_ELEMENT * env.limits().max_elements as u128;
    limit.saturating_sub(env.meter.work)
}

/// The largest [`LiteralScalar::words`] among `xs` (1 for `f64` without looking).
fn largest_words<'a, T: LiteralScalar + 'a>(xs: impl IntoIterator<Item = &'a T>) -> u128 {
    if T::EXACT {
        xs.into_iter().map(T::words).max().unwrap_or(1)
    } else {
        1
    }
}

/// The cost of one operation on operands of `a` and `b` words: 1 in `f64`,
/// `EXACT_WORD_COST · (a + b)²` for exact numbers (see [`LiteralScalar::words`]).
fn op_cost<T: LiteralScalar>(a: u128, b: u128) -> u128 {
    if T::EXACT {
        let w = a.saturating_add(b);
        EXACT_WORD_COST.saturating_mul(w.saturating_mul(w))
    } else {
        1
    }
}

/// What one squared word of an exact operation costs, in `f64` element operations. Measured:
/// adding 1 to a rational with a 283-bit denominator (a binary gcd over 6 words) takes about
/// 7 µs, multiplying 17- and 6-word rationals about 80 µs, against a few nanoseconds per
/// element of `f64` work (found by fuzzing: `1e-85*9-3e-31:3555*2`, an exact range of 7 111
/// such elements, cost 48 ms while charged 256 000 units).
const EXACT_WORD_COST: u128 = 32;

/// Evaluates `e` in `env`, within the work limit of one evaluation.
pub(crate) fn eval<T: LiteralScalar>(
    e: &Expr,
    env: &mut Env<T>,
) -> Result<DMatrix<T>, LiteralError> {
    if env.meter.depth == 0 {
        env.meter.work = 0;
    }
    env.meter.depth += 1;
    let result = eval_node(e, env);
    env.meter.depth -= 1;
    let m = result?;
    charge(env, e.at, m.len() as u128)?;
    Ok(m)
}

fn eval_node<T: LiteralScalar>(e: &Expr, env: &mut Env<T>) -> Result<DMatrix<T>, LiteralError> {
    match &e.node {
        Node::Number { text, value } => {
            T::from_literal(text, *value).map(scalar).ok_or_else(|| {
                LiteralError::NumberOutOfRange {
                    at: e.at,
                    text: text.clone(),
                }
            })
        }
        Node::Var(name) => variable(name, e.at, env),
        Node::Colon => Err(LiteralError::Syntax {
            at: e.at,
            expected: "a value".into(),
            found: "`:` (a lone colon is only allowed as an index)".into(),
        }),
        Node::Call { name, args } => call(name, args, e.at, env),
        Node::Neg(x) => Ok(eval(x, env)?.map(|v| -v)),
        Node::Transpose(x) => Ok(eval(x, env)?.transpose()),
        Node::Chain { first, rest } => {
            let mut acc = eval(first, env)?;
            for (op, at, rhs) in rest {
                let r = eval(rhs, env)?;
                acc = binary(*op, acc, r, *at, env)?;
                charge(env, *at, acc.len() as u128)?;
            }
            Ok(acc)
        }
        Node::Range {
            base,
            increment,
            limit,
        } => {
            let b = range_bound(base, env, "the start of a range")?;
            let s = match increment {
                Some(s) => range_bound(s, env, "the increment of a range")?,
                None => T::one(),
            };
            let l = range_bound(limit, env, "the limit of a range")?;
            let max = env.limits().max_elements;
            // Each element is one operation on numbers the size of the bounds: a range the
            // remaining work cannot pay for is refused before it is built.
            let cost = op_cost::<T>(largest_words([&b, &l]), largest_words([&s]));
            let affordable = usize::try_from(remaining_work(env) / cost).unwrap_or(usize::MAX);
            let values = match T::range(&b, &s, &l, max.min(affordable)) {
                Ok(values) => values,
                Err(count) if count <= max as u128 => {
                    let limit = WORK_PER_ELEMENT * max as u128;
                    let work = env.meter.work.saturating_add(count.saturating_mul(cost));
                    return Err(work_exceeded(work, limit, e.at));
                }
                Err(count) => {
                    return Err(LiteralError::TooLarge {
                        at: e.at,
                        what: "the range".into(),
                        count,
                        limit: max,
                    });
                }
            };
            charge(env, e.at, values.len() as u128 * cost)?;
            Ok(DMatrix::from_row_slice(1, values.len(), &values))
        }
        Node::Matrix(rows) => concatenate(rows, e.at, env),
    }
}

fn range_bound<T: LiteralScalar>(
    e: &Expr,
    env: &mut Env<T>,
    what: &str,
) -> Result<T, LiteralError> {
    let m = eval(e, env)?;
    if m.len() != 1 {
        return Err(LiteralError::Shape {
            at: e.at,
            message: format!("{what} must be a scalar, got a {} matrix", shape(&m)),
        });
    }
    Ok(m[(0, 0)].clone())
}

fn variable<T: LiteralScalar>(
    name: &str,
    at: Position,
    env: &Env<T>,
) -> Result<DMatrix<T>, LiteralError> {
    if let Some(m) = env.get(name) {
        return Ok(m.clone());
    }
    if CONSTANTS.contains(&name) {
        return T::constant(name)
            .map(scalar)
            .ok_or_else(|| LiteralError::NotRational {
                at,
                name: name.to_string(),
            });
    }
    Err(unknown_name(name, at, false))
}

/// An evaluated index: the 1-based positions, and whether they were written as a column.
enum Index {
    All,
    List(Vec<usize>, bool),
}

fn index_arg<T: LiteralScalar>(a: &Expr, env: &mut Env<T>) -> Result<Index, LiteralError> {
    if a.node == Node::Colon {
        return Ok(Index::All);
    }
    let m = eval(a, env)?;
    let column = m.ncols() == 1 && m.nrows() > 1;
    let mut list = Vec::with_capacity(m.len());
    for x in m.iter() {
        match x.to_count() {
            Some(i) if i >= 1 => list.push(i),
            _ => {
                return Err(LiteralError::Shape {
                    at: a.at,
                    message: format!("index ({x}) must be a positive integer"),
                })
            }
        }
    }
    Ok(Index::List(list, column))
}

fn resolve(
    index: &Index,
    extent: usize,
    name: &str,
    m_shape: &str,
    at: Position,
) -> Result<Vec<usize>, LiteralError> {
    match index {
        Index::All => Ok((0..extent).collect()),
        Index::List(list, _) => list
            .iter()
            .map(|&i| {
                if i <= extent {
                    Ok(i - 1)
                } else {
                    Err(LiteralError::Shape {
                        at,
                        message: format!("index ({i}) out of bound; `{name}` is {m_shape}"),
                    })
                }
            })
            .collect(),
    }
}

fn call<T: LiteralScalar>(
    name: &str,
    args: &[Expr],
    at: Position,
    env: &mut Env<T>,
) -> Result<DMatrix<T>, LiteralError> {
    if env.get(name).is_some() {
        let indices = args
            .iter()
            .map(|a| index_arg(a, env))
            .collect::<Result<Vec<_>, _>>()?;
        // Indexed in place: `v(i)` in a loop must not copy all of `v` (found by fuzzing: a
        // data script indexing 860-element exact rows 740 000 times took 20 s).
        let m = env.get(name).ok_or_else(|| unknown_name(name, at, false))?;
        return index(m, &indices, name, at);
    }
    if let Some(f) = Function::from_name(name) {
        let x = one_argument(name, args, at, env)?;
        let mut out = Vec::with_capacity(x.len());
        for v in x.iter() {
            let r = T::apply(f, v).ok_or_else(|| LiteralError::NotRational {
                at,
                name: name.to_string(),
            })?;
            out.push(finite(r, at, || {
                format!("{name}({v}) is not a finite real number")
            })?);
        }
        return Ok(DMatrix::from_vec(x.nrows(), x.ncols(), out));
    }
    let argument_error = |message: String| LiteralError::Argument {
        at,
        function: name.to_string(),
        message,
    };
    let max = env.limits().max_elements;
    match name {
        "pi" | "e" if args.is_empty() => variable(name, at, env),
        "linspace" => {
            if args.len() != 3 {
                return Err(argument_error(format!(
                    "expected 3 arguments (a, b, n), got {}",
                    args.len()
                )));
            }
            let a = scalar_argument(name, &args[0], env)?;
            let b = scalar_argument(name, &args[1], env)?;
            let n = count_argument(name, &args[2], env)?;
            check_size(at, "linspace", n as u128, max)?;
            let values = T::linspace(&a, &b, n);
            Ok(DMatrix::from_row_slice(1, values.len(), &values))
        }
        "zeros" | "ones" => {
            let (r, c) = match args.len() {
                1 => {
                    let n = count_argument(name, &args[0], env)?;
                    (n, n)
                }
                2 => (
                    count_argument(name, &args[0], env)?,
                    count_argument(name, &args[1], env)?,
                ),
                k => {
                    return Err(argument_error(format!(
                        "expected 1 or 2 arguments (n, or rows and columns), got {k}"
                    )))
                }
            };
            check_size(at, name, r as u128 * c as u128, max)?;
            let fill = if name == "zeros" { T::zero() } else { T::one() };
            Ok(DMatrix::from_element(r, c, fill))
        }
        "numel" | "length" => {
            let x = one_argument(name, args, at, env)?;
            let n = if name == "numel" {
                x.len()
            } else if x.is_empty() {
                0
            } else {
                x.nrows().max(x.ncols())
            };
            Ok(scalar(T::from_usize(n)))
        }
        "size" => match args.len() {
            1 => {
                let x = eval(&args[0], env)?;
                Ok(DMatrix::from_row_slice(
                    1,
                    2,
                    &[T::from_usize(x.nrows()), T::from_usize(x.ncols())],
                ))
            }
            2 => {
                let x = eval(&args[0], env)?;
                let d = count_argument(name, &args[1], env)?;
                let n = match d {
                    1 => x.nrows(),
                    2 => x.ncols(),
                    0 => return Err(argument_error("dimension 0 does not exist".into())),
                    _ => 1,
                };
                Ok(scalar(T::from_usize(n)))
            }
            k => Err(argument_error(format!(
                "expected 1 or 2 arguments, got {k}"
            ))),
        },
        _ => Err(unknown_name(name, at, true)),
    }
}

fn one_argument<T: LiteralScalar>(
    name: &str,
    args: &[Expr],
    at: Position,
    env: &mut Env<T>,
) -> Result<DMatrix<T>, LiteralError> {
    if args.len() != 1 {
        return Err(LiteralError::Argument {
            at,
            function: name.to_string(),
            message: format!("expected 1 argument, got {}", args.len()),
        });
    }
    eval(&args[0], env)
}

fn scalar_argument<T: LiteralScalar>(
    name: &str,
    a: &Expr,
    env: &mut Env<T>,
) -> Result<T, LiteralError> {
    let m = eval(a, env)?;
    if m.len() != 1 {
        return Err(LiteralError::Argument {
            at: a.at,
            function: name.to_string(),
            message: format!("expected a scalar argument, got a {} matrix", shape(&m)),
        });
    }
    Ok(m[(0, 0)].clone())
}

fn count_argument<T: LiteralScalar>(
    name: &str,
    a: &Expr,
    env: &mut Env<T>,
) -> Result<usize, LiteralError> {
    let x = scalar_argument(name, a, env)?;
    x.to_count().ok_or_else(|| LiteralError::Argument {
        at: a.at,
        function: name.to_string(),
        message: format!("expected a non-negative integer, got {x}"),
    })
}

fn index<T: LiteralScalar>(
    m: &DMatrix<T>,
    indices: &[Index],
    name: &str,
    at: Position,
) -> Result<DMatrix<T>, LiteralError> {
    let m_shape = shape(m);
    match indices {
        [] => Ok(m.clone()),
        [i] => {
            let picks = resolve(i, m.len(), name, &m_shape, at)?;
            let values: Vec<T> = picks.iter().map(|&k| m[k].clone()).collect();
            let as_column = match i {
                Index::All => true,
                Index::List(_, column) => {
                    if m.nrows() == 1 && m.ncols() != 1 {
                        false
                    } else if m.ncols() == 1 && m.nrows() != 1 {
                        true
                    } else {
                        *column
                    }
                }
            };
            Ok(if as_column {
                DMatrix::from_vec(values.len(), 1, values)
            } else {
                DMatrix::from_vec(1, values.len(), values)
            })
        }
        [i, j] => {
            let rows = resolve(i, m.nrows(), name, &m_shape, at)?;
            let cols = resolve(j, m.ncols(), name, &m_shape, at)?;
            Ok(DMatrix::from_fn(rows.len(), cols.len(), |r, c| {
                m[(rows[r], cols[c])].clone()
            }))
        }
        _ => Err(LiteralError::Unsupported {
            at,
            what: "more than two indices".into(),
        }),
    }
}

/// Broadcast length of one dimension, or `None` if incompatible.
fn broadcast_dim(a: usize, b: usize) -> Option<usize> {
    if a == b {
        Some(a)
    } else if a == 1 {
        Some(b)
    } else if b == 1 {
        Some(a)
    } else {
        None
    }
}

fn elementwise<T: LiteralScalar>(
    op: BinOp,
    a: &DMatrix<T>,
    b: &DMatrix<T>,
    at: Position,
    max: usize,
) -> Result<DMatrix<T>, LiteralError> {
    let (ar, ac) = a.shape();
    let (br, bc) = b.shape();
    let (Some(r), Some(c)) = (broadcast_dim(ar, br), broadcast_dim(ac, bc)) else {
        return Err(LiteralError::Shape {
            at,
            message: format!(
                "operator {}: nonconformant arguments (op1 is {}, op2 is {})",
                op.symbol(),
                shape(a),
                shape(b)
            ),
        });
    };
    check_size(at, "the result", r as u128 * c as u128, max)?;
    let in_array = !(a.len() == 1 && b.len() == 1);
    let mut data = Vec::with_capacity(r * c);
    for j in 0..c {
        for i in 0..r {
            let x = &a[(if ar == 1 { 0 } else { i }, if ac == 1 { 0 } else { j })];
            let y = &b[(if br == 1 { 0 } else { i }, if bc == 1 { 0 } else { j })];
            let value = match op {
                BinOp::Add => x.clone() + y.clone(),
                BinOp::Sub => x.clone() - y.clone(),
                BinOp::Mul | BinOp::ElMul => x.clone() * y.clone(),
                BinOp::Div | BinOp::ElDiv => {
                    T::checked_div(x, y).ok_or(LiteralError::DivisionByZero { at })?
                }
                BinOp::Pow | BinOp::ElPow => {
                    let p = if in_array {
                        T::pow_in_array(x, y)
                    } else {
                        T::pow(x, y)
                    };
                    p.map_err(|err| match err {
                        PowerError::NotRational => LiteralError::NotRational {
                            at,
                            name: format!("{x}^{y}"),
                        },
                        PowerError::DivisionByZero => LiteralError::DivisionByZero { at },
                        PowerError::TooLarge => LiteralError::NumberOutOfRange {
                            at,
                            text: format!("{x}^{y}"),
                        },
                    })?
                }
            };
            data.push(finite(value, at, || {
                format!("{x} {} {y} is not a finite real number", op.symbol())
            })?);
        }
    }
    Ok(DMatrix::from_vec(r, c, data))
}

fn is_vector<T: LiteralScalar>(m: &DMatrix<T>) -> bool {
    (m.nrows() == 1 || m.ncols() == 1) && m.len() > 1
}

fn binary<T: LiteralScalar>(
    op: BinOp,
    a: DMatrix<T>,
    b: DMatrix<T>,
    at: Position,
    env: &mut Env<T>,
) -> Result<DMatrix<T>, LiteralError> {
    let max = env.limits().max_elements;
    let (a_scalar, b_scalar) = (a.len() == 1, b.len() == 1);
    let same_shape_vectors = is_vector(&a) && a.shape() == b.shape();
    let lenient = |env: &mut Env<T>, dotted: &str| {
        env.warn(
            at,
            format!(
                "`{}` on {} and {} operands is an error in Octave; evaluated element-wise as `{dotted}`",
                op.symbol(),
                shape(&a),
                shape(&b)
            ),
        );
    };
    // Exact operations cost more the longer their operands: charged before computing.
    if T::EXACT {
        let cost = op_cost::<T>(largest_words(a.iter()), largest_words(b.iter()));
        let n = a.len().max(b.len()) as u128;
        let inner = if op == BinOp::Mul && !a_scalar && !b_scalar {
            a.ncols() as u128
        } else {
            1
        };
        charge(env, at, n.saturating_mul(inner).saturating_mul(cost))?;
    }
    match op {
        BinOp::Add | BinOp::Sub | BinOp::ElMul | BinOp::ElDiv | BinOp::ElPow => {
            elementwise(op, &a, &b, at, max)
        }
        BinOp::Mul => {
            if a_scalar || b_scalar {
                elementwise(op, &a, &b, at, max)
            } else if a.ncols() == b.nrows() {
                let terms = a.nrows() as u128 * b.ncols() as u128 * a.ncols() as u128;
                charge(env, at, terms)?;
                matrix_product(&a, &b, at, max)
            } else if same_shape_vectors {
                lenient(env, ".*");
                elementwise(op, &a, &b, at, max)
            } else {
                Err(LiteralError::Shape {
                    at,
                    message: format!(
                        "operator *: nonconformant arguments (op1 is {}, op2 is {})",
                        shape(&a),
                        shape(&b)
                    ),
                })
            }
        }
        BinOp::Div => {
            if b_scalar {
                elementwise(op, &a, &b, at, max)
            } else if same_shape_vectors {
                lenient(env, "./");
                elementwise(op, &a, &b, at, max)
            } else {
                Err(LiteralError::Unsupported {
                    at,
                    what: format!(
                        "matrix right division `/` by a {} matrix; use `./` for element-wise division",
                        shape(&b)
                    ),
                })
            }
        }
        BinOp::Pow => {
            if a_scalar && b_scalar {
                elementwise(op, &a, &b, at, max)
            } else if (is_vector(&a) && b_scalar) || (a_scalar && is_vector(&b)) {
                lenient(env, ".^");
                elementwise(op, &a, &b, at, max)
            } else {
                Err(LiteralError::Unsupported {
                    at,
                    what: format!(
                        "matrix power `^` on {} and {} operands; use `.^` for an element-wise power",
                        shape(&a),
                        shape(&b)
                    ),
                })
            }
        }
    }
}

fn matrix_product<T: LiteralScalar>(
    a: &DMatrix<T>,
    b: &DMatrix<T>,
    at: Position,
    max: usize,
) -> Result<DMatrix<T>, LiteralError> {
    let (r, k, c) = (a.nrows(), a.ncols(), b.ncols());
    check_size(at, "the matrix product", r as u128 * c as u128, max)?;
    check_size(
        at,
        "the matrix product's work",
        r as u128 * c as u128 * k as u128,
        max.saturating_mul(64),
    )?;
    let mut data = Vec::with_capacity(r * c);
    for j in 0..c {
        for i in 0..r {
            let mut sum = T::zero();
            for l in 0..k {
                sum = sum + a[(i, l)].clone() * b[(l, j)].clone();
            }
            data.push(finite(sum, at, || {
                "the matrix product is not finite".to_string()
            })?);
        }
    }
    Ok(DMatrix::from_vec(r, c, data))
}

/// One evaluated row of a matrix literal.
struct Block<T: LiteralScalar> {
    value: DMatrix<T>,
    at: Position,
    number: usize,
    constant: bool,
}

fn concatenate<T: LiteralScalar>(
    rows: &[Row],
    at: Position,
    env: &mut Env<T>,
) -> Result<DMatrix<T>, LiteralError> {
    let max = env.limits().max_elements;
    let mut blocks: Vec<Block<T>> = Vec::new();
    for (k, row) in rows.iter().enumerate() {
        let mut parts: Vec<(DMatrix<T>, Position)> = Vec::new();
        for e in &row.elements {
            let m = eval(e, env)?;
            if !m.is_empty() {
                parts.push((m, e.at));
            }
        }
        let Some((first, _)) = parts.first() else {
            continue;
        };
        let height = first.nrows();
        let mut width: usize = 0;
        for (m, pos) in &parts {
            if m.nrows() != height {
                return Err(LiteralError::Shape {
                    at: *pos,
                    message: format!(
                        "horizontal dimensions mismatch ({} vs {}) in row {}",
                        shape(first),
                        shape(m),
                        k + 1
                    ),
                });
            }
            width = width.saturating_add(m.ncols());
        }
        check_size(row.at, "the row", height as u128 * width as u128, max)?;
        let mut data: Vec<T> = Vec::with_capacity(height * width);
        for (m, _) in &parts {
            data.extend(m.iter().cloned());
        }
        let constant = !row.elements.iter().any(|e| reads_variables(e, env));
        blocks.push(Block {
            value: DMatrix::from_vec(height, width, data),
            at: row.at,
            number: k + 1,
            constant,
        });
    }
    let Some(first) = blocks.first() else {
        return Ok(DMatrix::from_vec(0, 0, Vec::new()));
    };
    let expected = first.value.ncols();
    let widest = blocks.iter().map(|b| b.value.ncols()).max().unwrap_or(0);
    let broadcast = widest > 1
        && blocks
            .iter()
            .all(|b| b.value.ncols() == widest || (b.value.len() == 1 && b.constant))
        && blocks
            .iter()
            .any(|b| b.value.ncols() == widest && !b.constant);
    if broadcast {
        for b in blocks.iter_mut().filter(|b| b.value.ncols() != widest) {
            env.warn(
                b.at,
                format!(
                    "the constant row {} is repeated to 1×{widest} to match the rows next to it; Octave rejects this (vertical dimensions mismatch)",
                    b.number
                ),
            );
            b.value = DMatrix::from_element(1, widest, b.value[(0, 0)].clone());
        }
    } else if let Some(b) = blocks.iter().find(|b| b.value.ncols() != expected) {
        return Err(LiteralError::RaggedRows {
            at: b.at,
            row: b.number,
            found: b.value.ncols(),
            expected,
        });
    }
    let width = blocks[0].value.ncols();
    let height: usize = blocks
        .iter()
        .map(|b| b.value.nrows())
        .fold(0, usize::saturating_add);
    check_size(at, "the matrix", height as u128 * width as u128, max)?;
    let mut data: Vec<T> = Vec::with_capacity(height * width);
    for j in 0..width {
        for b in &blocks {
            data.extend(b.value.column(j).iter().cloned());
        }
    }
    Ok(DMatrix::from_vec(height, width, data))
}

//! Reading a curve argument (`--c1`, `--u-curve`, `--first`, …) into the operation layer's
//! [`CurveArg`]:
//! - `bezier(P)`, `bspline(P, U)`, `nurbs(P, W, U)`: a curve of the library, `P` its control
//!   points as columns (rows with `--rows`), `U` its knot vector (the degree is
//!   `numel(U) − columns(P) − 1`), `W` its weights — each argument a literal, a file or a
//!   variable of the `--script`; the curve keeps its own domain, which the construction maps
//!   onto `[0, 1]`;
//! - a constant matrix or a data file: the control points of a Bézier curve;
//! - an expression in one parameter (`[u; 0; u-u^2]`), or a curve of the script: evaluated
//!   exactly where the construction needs it;
//! - with `--samples`, a data file or a matrix of the script: samples of the curve, one column
//!   per parameter (the script's `u`/`v`, else `linspace(0,1,N)`), as appendix C's data scripts
//!   sample their boundaries.

use std::cell::RefCell;
use std::rc::Rc;

use cagd::bezier::BezierCurve;
use cagd::bspline::BSplineCurve;
use cagd::nurbs::NurbsCurve;
use cagd::param::SampledCurve;
use cagd_octave::literal::{Env, LiteralScalar};
use cagd_octave::script::{Binding, Script};
use cagd_ops::curves::CurveArg;
use nalgebra::DMatrix;

use super::answer::op_error;
use super::common::{lib, shape};
use super::expr_curve::{ExprCurve, CURVE_FORM};
use super::run::Names;
use crate::cx::Cx;
use crate::{load_expression, load_matrix, load_params, CliError};

/// The form of a curve argument, for error messages.
pub(crate) const CURVE_ARG_FORM: &str = "an expression in the curve parameter such as \"[u; 0; u-u^2]\", Bézier control points (columns) such as \"[0 0 0; 1 0 1]'\", or bezier(P), bspline(P, U), nurbs(P, W, U)";

/// How a curve argument is read.
#[derive(Debug)]
pub(crate) struct Reading<'a, T: LiteralScalar> {
    /// The data script (`--script`), whose variables the argument may name.
    pub script: Option<&'a Script<T>>,
    /// Points are rows (`--rows`).
    pub rows: bool,
    /// With `--samples`: data is samples of the curve at the script's variable of this name.
    pub samples: Option<&'static str>,
}

impl<T: LiteralScalar> Clone for Reading<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T: LiteralScalar> Copy for Reading<'_, T> {}

/// A curve argument (see the module documentation).
pub(crate) fn curve_arg<T: LiteralScalar>(
    cx: &mut Cx,
    argument: &str,
    text: &str,
    how: Reading<'_, T>,
    env: &Rc<RefCell<Env<T>>>,
) -> Result<CurveArg<T>, CliError> {
    if let Some(curve) = library_call(cx, argument, text, how)? {
        return Ok(curve.into_arg());
    }
    let data = names_data(cx, text, how.script);
    if let (Some(param), true) = (how.samples, data) {
        return samples(cx, argument, text, how, param);
    }
    warn_matrix_as_control(cx, argument, text, how);
    if data {
        let m = load_matrix(cx, argument, text, how.script)?;
        return bezier(cx, argument, text, m, how.rows);
    }
    expression_curve(cx, argument, text, how, env)
}

/// With `--samples`, data read as samples of the curve, one column per parameter: the
/// script's variable `param`, else `linspace(0,1,N)`.
fn samples<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    text: &str,
    how: Reading<'_, T>,
    param: &str,
) -> Result<CurveArg<T>, CliError> {
    let m = orient(load_matrix(cx, argument, text, how.script)?, how.rows);
    let params = match how.script {
        Some(s) => script_params(s, param, m.ncols()),
        None => T::linspace(&T::zero(), &T::one(), m.ncols()),
    };
    SampledCurve::new(params, m)
        .map(CurveArg::Samples)
        .map_err(lib(argument, "a curve sampled at increasing parameters"))
}

/// A warning when a matrix of the script (not a row or column) is about to be read as control
/// points: the thesis's data scripts hold samples, which need `--samples`.
fn warn_matrix_as_control<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    text: &str,
    how: Reading<'_, T>,
) {
    let Some(m) = how.script.and_then(|s| s.value(text.trim())) else {
        return;
    };
    if m.ncols() > 1 && m.nrows() > 1 {
        let degree = if how.rows { m.nrows() } else { m.ncols() } - 1;
        crate::slips::warn(
            cx,
            argument,
            format!(
                "`{}` is a {}×{} matrix of the script, read as the control points of a Bézier curve of degree {degree}; if its columns are samples of the curve (as in the thesis's data scripts), add --samples",
                text.trim(),
                m.nrows(),
                m.ncols(),
            ),
        );
    }
}

/// An expression: constant, the control points of a Bézier curve; in one parameter, a curve
/// evaluated where the construction needs it; in more, an error naming them.
fn expression_curve<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    text: &str,
    how: Reading<'_, T>,
    env: &Rc<RefCell<Env<T>>>,
) -> Result<CurveArg<T>, CliError> {
    let expr = load_expression(cx, argument, text, how.script)?;
    let params = expr.parameters(&env.borrow());
    match params.as_slice() {
        [] => {
            let m = expr
                .eval_at(&env.borrow(), &[])
                .map_err(|e| CliError::literal(argument, e, CURVE_ARG_FORM))?;
            bezier(cx, argument, text, m, how.rows)
        }
        [p] => Ok(CurveArg::Evaluated(Box::new(ExprCurve::new(
            expr,
            p,
            env.clone(),
            cx.limits,
            CURVE_FORM,
        )))),
        _ => Err(shape(
            argument,
            format!(
                "`{}` uses the parameters {}",
                text.trim(),
                params.join(" and ")
            ),
            CURVE_ARG_FORM,
        )),
    }
}

/// A script's variable as a curve (no argument given): a curve expression, or sampled data
/// whose parameters are the script's `param` variable (or `linspace(0,1,N)`).
pub(crate) fn script_curve<T: LiteralScalar>(
    cx: &Cx,
    script: &Script<T>,
    name: &str,
    param: &str,
    env: &Rc<RefCell<Env<T>>>,
) -> Option<CurveArg<T>> {
    match script.get(name)? {
        Binding::Function(f) => {
            let params = f.parameters(script.env());
            let p = params.first().copied().unwrap_or("t");
            let expr = script.resolve(name).ok()?;
            Some(CurveArg::Evaluated(Box::new(ExprCurve::new(
                expr,
                p,
                env.clone(),
                cx.limits,
                CURVE_FORM,
            ))))
        }
        Binding::Value(m) => SampledCurve::new(script_params(script, param, m.ncols()), m.clone())
            .ok()
            .map(CurveArg::Samples),
    }
}

/// The script's parameter row `name` if it has `count` values, else `linspace(0,1,count)`.
pub(crate) fn script_params<T: LiteralScalar>(
    script: &Script<T>,
    name: &str,
    count: usize,
) -> Vec<T> {
    match script.value(name) {
        Some(m) if m.len() == count && (m.nrows() == 1 || m.ncols() == 1) => {
            m.iter().cloned().collect()
        }
        _ => T::linspace(&T::zero(), &T::one(), count),
    }
}

/// Whether a curve argument names data: a file (`file`, `file:var`, `-`) or a matrix of the
/// script.
pub(crate) fn names_data<T: LiteralScalar>(
    cx: &Cx,
    text: &str,
    script: Option<&Script<T>>,
) -> bool {
    let t = text.trim();
    let file = t == "-"
        || crate::input::is_file(cx, t)
        || t.rsplit_once(':')
            .is_some_and(|(p, _)| !p.is_empty() && crate::input::is_file(cx, p));
    file || script.is_some_and(|s| s.value(t).is_some())
}

fn orient<T: LiteralScalar>(m: DMatrix<T>, rows: bool) -> DMatrix<T> {
    if rows {
        m.transpose()
    } else {
        m
    }
}

/// A Bézier curve of control points `m` (as typed), with the orientation slip noticed.
fn bezier<T: LiteralScalar>(
    cx: &Cx,
    argument: &str,
    text: &str,
    m: DMatrix<T>,
    rows: bool,
) -> Result<CurveArg<T>, CliError> {
    // A constant expression is read here, not by load_matrix: its decimal commas too.
    crate::slips::decimal_commas(cx, argument, text);
    crate::slips::point_matrix_text(cx, argument, text, &m, rows);
    BezierCurve::new(orient(m, rows))
        .map(CurveArg::curve)
        .map_err(lib(argument, "control points, one per column"))
}

/// A curve of the library, as `bezier(P)`, `bspline(P, U)`, `nurbs(P, W, U)` (or control
/// points) make it.
pub(crate) enum LibraryCurve<T: LiteralScalar> {
    /// `bezier(P)` or control points.
    Bezier(BezierCurve<T>),
    /// `bspline(P, U)`.
    BSpline(BSplineCurve<T>),
    /// `nurbs(P, W, U)`.
    Nurbs(NurbsCurve<T>),
}

impl<T: LiteralScalar> LibraryCurve<T> {
    /// As a curve argument of a construction taking any curve.
    pub fn into_arg(self) -> CurveArg<T> {
        match self {
            LibraryCurve::Bezier(c) => CurveArg::curve(c),
            LibraryCurve::BSpline(c) => CurveArg::curve(c),
            LibraryCurve::Nurbs(c) => CurveArg::curve(c),
        }
    }

    /// As a curve that knows its second derivative.
    pub fn into_deriv2(self) -> Box<dyn cagd::curvature::CurveDeriv2<T> + Send + Sync> {
        match self {
            LibraryCurve::Bezier(c) => Box::new(c),
            LibraryCurve::BSpline(c) => Box::new(c),
            LibraryCurve::Nurbs(c) => Box::new(c),
        }
    }
}

/// A library curve: `bezier(P)`, `bspline(P, U)`, `nurbs(P, W, U)`, or control points (a
/// Bézier curve).
pub(crate) fn library_curve<T: LiteralScalar>(
    cx: &mut Cx,
    argument: &str,
    text: &str,
    how: Reading<'_, T>,
) -> Result<LibraryCurve<T>, CliError> {
    if let Some(curve) = library_call(cx, argument, text, how)? {
        return Ok(curve);
    }
    let m = load_matrix(cx, argument, text, how.script)?;
    crate::slips::point_matrix_text(cx, argument, text, &m, how.rows);
    BezierCurve::new(orient(m, how.rows))
        .map(LibraryCurve::Bezier)
        .map_err(lib(argument, "control points, one per column"))
}

/// The names of a call's roles (each error is then about the curve argument itself).
const CALL_NAMES: Names = Names {
    input: "CURVE",
    special: &[],
};

/// `bezier(P)`, `bspline(P, U)` or `nurbs(P, W, U)`, if `text` is such a call.
fn library_call<T: LiteralScalar>(
    cx: &mut Cx,
    argument: &str,
    text: &str,
    how: Reading<'_, T>,
) -> Result<Option<LibraryCurve<T>>, CliError> {
    let Some((name, args)) = split_call(text) else {
        return Ok(None);
    };
    let form = match name {
        "bezier" => "bezier(P): P the control points, one per column",
        "bspline" => "bspline(P, U): P the control points (columns), U the knot vector (numel(U) − columns(P) − 1 is the degree)",
        _ => "nurbs(P, W, U): P the control points (columns), W their weights, U the knot vector",
    };
    let want = match name {
        "bezier" => 1,
        "bspline" => 2,
        _ => 3,
    };
    if args.len() != want {
        return Err(shape(
            argument,
            format!("{name}( … ) with {} argument(s)", args.len()),
            form,
        ));
    }
    let points = load_matrix(cx, argument, args[0], how.script)?;
    crate::slips::point_matrix_text(cx, argument, args[0], &points, how.rows);
    let points = orient(points, how.rows);
    let list = |cx: &mut Cx, k: usize| load_params::<T>(cx, argument, args[k]);
    let degree = |knots: &[T]| call_degree(argument, knots, points.ncols());
    let curve = match name {
        "bezier" => BezierCurve::new(points.clone()).map(LibraryCurve::Bezier),
        "bspline" => {
            let knots = list(cx, 1)?;
            let p = degree(&knots)?;
            BSplineCurve::new(p, knots, points.clone()).map(LibraryCurve::BSpline)
        }
        _ => {
            let weights = list(cx, 1)?;
            let knots = list(cx, 2)?;
            let p = degree(&knots)?;
            NurbsCurve::new(p, knots, points.clone(), weights).map(LibraryCurve::Nurbs)
        }
    };
    curve.map(Some).map_err(lib(argument, form))
}

/// The degree `numel(U) − columns(P) − 1` of a call's `n` control points and `knots`, the
/// knots checked by the one knot rule, in the words every command with knots uses.
fn call_degree<T: LiteralScalar>(argument: &str, knots: &[T], n: usize) -> Result<usize, CliError> {
    let p = knots.len().checked_sub(n + 1).ok_or_else(|| {
        shape(
            argument,
            format!("{} knots for {n} control points", knots.len()),
            "at least columns(P) + 1 knots: the degree is numel(U) − columns(P) − 1",
        )
    })?;
    cagd_ops::knots::check_knots(knots, p, n, cagd_ops::knots::CURVE).map_err(|e| CliError {
        argument: argument.to_string(),
        ..op_error(&CALL_NAMES, e)
    })?;
    Ok(p)
}

/// `name(a, b, …)` split at its top-level commas (commas inside brackets and parentheses
/// belong to the arguments).
fn split_call(text: &str) -> Option<(&str, Vec<&str>)> {
    let t = text.trim();
    let open = t.find('(')?;
    let name = t[..open].trim();
    if !t.ends_with(')') || !matches!(name, "bezier" | "bspline" | "nurbs") {
        return None;
    }
    let inner = &t[open + 1..t.len() - 1];
    let mut args = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '[' | '(' | '{' => depth += 1,
            ']' | ')' | '}' => depth -= 1,
            ',' if depth == 0 => {
                args.push(inner[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    args.push(inner[start..].trim());
    Some((name, args))
}

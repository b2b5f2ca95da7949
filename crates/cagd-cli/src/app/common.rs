//! Helpers shared by the subcommands: loading curves given as expressions or control points,
//! parameter lists, library errors, pictures and meshes.

use cagd::limits::Limits;
use std::path::Path;

use cagd::grid::PointGrid;
use nalgebra::{DMatrix, DVector};

use crate::args::OutputArgs;
use crate::plot::{Figure, ImageKind};
use crate::{
    load_expression, load_matrix, load_params, samples, CliError, ErrorKind, PendingWrites, Report,
    CURVE_FORM,
};
use cagd::bezier::BezierCurve;
use cagd::{Curve, SampledCurve};
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr, Warning};
use cagd_octave::script::{Binding, Script};

pub(crate) use super::curve::CliCurve;
use super::outcome::Outcome;
use super::work::{check_expression_work, Sampling};
pub(crate) use crate::error::{lib, shape, usage};

/// The argument of a non-finite result until `run` names the command's input.
pub const RESULT: &str = "RESULT";

/// Samples taken when neither `--t`/`--u`/`--v` nor `--n` is given: 0:0.1:1.
pub const DEFAULT_SAMPLES: usize = 11;

/// The form of a boundary or network curve argument.
pub const CURVE_ARG_FORM: &str = "an expression in the curve parameter such as \"[u; 0; u-u^2]\", or control points (columns) of a Bézier curve such as \"[0 0 0; 1 0 1]'\"";

/// A matrix argument with points as columns (or rows with `--rows`).
pub fn points<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
    rows: bool,
) -> Result<DMatrix<T>, CliError> {
    let m = load_matrix(limits, argument, text, script)?;
    crate::slips::point_matrix(argument, &m, rows);
    Ok(if rows { m.transpose() } else { m })
}

/// Parameter values: the given list, or `linspace(0,1,N)` (`N` from `--n`, else `default`).
pub fn params_or_samples<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    given: &Option<String>,
    n: Option<usize>,
    default: usize,
) -> Result<Vec<T>, CliError> {
    match given {
        Some(text) => load_params(limits, argument, text),
        None => samples(limits, n.unwrap_or(default), 2),
    }
}

/// Refuses a grid of `nu × nv` points above [`cagd::limits::Limits::max_grid_points`].
pub fn check_grid(limits: &Limits, nu: usize, nv: usize) -> Result<(), CliError> {
    limits.check_grid("surface grid", nu, nv).map_err(lib(
        "--u/--v",
        "fewer grid points (a smaller --n, --u, --v), or a higher --max-grid-points",
    ))
}

/// Refuses a degree above [`cagd::limits::Limits::max_degree`].
pub fn check_degree(limits: &Limits, argument: &str, degree: usize) -> Result<(), CliError> {
    limits.check_degree("degree", degree).map_err(lib(
        argument,
        "a lower degree (fewer control points or nodes), or a higher --max-degree",
    ))
}

/// Builds curves, each exact at its parameters, after refusing the lot if sampling their
/// expressions would cost more than `--max-work` ([`check_expression_work`]): each of
/// `parts` is (argument, source, parameters).
pub fn build_curves<T: LiteralScalar>(
    limits: &Limits,
    parts: &[(&str, &CurveSource<T>, &[T])],
    env: &mut Env<T>,
) -> Result<Vec<CliCurve<T>>, CliError> {
    let expressions: Vec<Sampling<'_, T>> = parts
        .iter()
        .filter_map(|(argument, s, at)| match s {
            CurveSource::Expr(expr, p) => Some(Sampling {
                argument,
                expr,
                params: vec![(*p, *at)],
            }),
            _ => None,
        })
        .collect();
    check_expression_work(limits, &expressions, env)?;
    parts
        .iter()
        .map(|(arg, s, at)| s.build(arg, at, env))
        .collect()
}

/// A 1×k row of values.
pub fn row<T: LiteralScalar>(values: &[T]) -> DMatrix<T> {
    DMatrix::from_row_slice(1, values.len(), values)
}

/// A column point as a d×1 matrix.
pub fn column<T: LiteralScalar>(p: &DVector<T>) -> DMatrix<T> {
    DMatrix::from_column_slice(p.len(), 1, p.as_slice())
}

/// A matrix in doubles, for pictures.
pub fn to_f64<T: LiteralScalar>(m: &DMatrix<T>) -> DMatrix<f64> {
    m.map(|x| x.to_f64())
}

/// A grid in doubles, for pictures and meshes.
pub fn grid_f64<T: LiteralScalar>(g: &PointGrid<T>) -> PointGrid<f64> {
    g.map(|x| x.to_f64())
}

/// Sorted distinct values of `lists` together with 0 and 1: where a sampled curve must be
/// exact.
pub fn needed<T: LiteralScalar>(lists: &[&[T]]) -> Vec<T> {
    let mut all: Vec<T> = vec![T::zero(), T::one()];
    for l in lists {
        all.extend(l.iter().cloned());
    }
    all.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    all.dedup();
    all
}

/// A curve argument before it is sampled.
#[derive(Debug, Clone)]
pub enum CurveSource<T: LiteralScalar> {
    /// An expression in one parameter.
    Expr(ParamExpr, &'static str),
    /// Bézier control points (columns).
    Bezier(BezierCurve<T>),
    /// Samples of a thesis data script at the given parameters.
    Samples(Vec<T>, DMatrix<T>),
}

/// Whether `text` names a data file (`file`, `file:var` or `-`).
fn is_file_arg(text: &str) -> bool {
    let t = text.trim();
    t == "-"
        || crate::input::is_file(t)
        || t.rsplit_once(':')
            .is_some_and(|(p, _)| !p.is_empty() && crate::input::is_file(p))
}

/// Loads a curve argument: a data file or a constant matrix gives Bézier control points; an
/// expression in one of `allowed` (or t) gives an expression curve.
pub fn load_curve<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
    rows: bool,
    env: &Env<T>,
) -> Result<CurveSource<T>, CliError> {
    load_curve_as(limits, argument, text, script, rows, env, None)
}

/// Whether a curve argument names sampled data: a data file or a matrix of the script.
pub fn names_data<T: LiteralScalar>(text: &str, script: Option<&Script<T>>) -> bool {
    is_file_arg(text) || script.is_some_and(|s| s.value(text.trim()).is_some())
}

/// [`load_curve`], with `samples = Some(param)` (`--samples`) reading a data file or a matrix
/// of the script as samples of the curve, one column per parameter value (the script's
/// `param` variable if it has one per column, else `linspace(0,1,N)`), as appendix C's data
/// scripts sample their boundary curves. Without it such data is read as Bézier control
/// points, and a matrix of the script gets a warning saying so.
pub fn load_curve_as<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    text: &str,
    script: Option<&Script<T>>,
    rows: bool,
    env: &Env<T>,
    samples: Option<&str>,
) -> Result<CurveSource<T>, CliError> {
    if let Some(param) = samples {
        if names_data(text, script) {
            let m = load_matrix(limits, argument, text, script)?;
            let m = if rows { m.transpose() } else { m };
            let params = match script {
                Some(s) => script_params(s, param, m.ncols()),
                None => T::linspace(&T::zero(), &T::one(), m.ncols()),
            };
            return Ok(CurveSource::Samples(params, m));
        }
    }
    if let Some(m) = script.and_then(|s| s.value(text.trim())) {
        if m.ncols() > 1 && m.nrows() > 1 {
            crate::slips::warn(
                argument,
                format!(
                    "`{}` is a {}×{} matrix of the script, read as the control points of a Bézier curve of degree {}; if its columns are samples of the curve (as in the thesis's data scripts), add --samples",
                    text.trim(),
                    m.nrows(),
                    m.ncols(),
                    if rows { m.nrows() - 1 } else { m.ncols() - 1 }
                ),
            );
        }
    }
    let bezier = |m: DMatrix<T>| -> Result<CurveSource<T>, CliError> {
        crate::slips::point_matrix(argument, &m, rows);
        let m = if rows { m.transpose() } else { m };
        BezierCurve::new(m)
            .map(CurveSource::Bezier)
            .map_err(lib(argument, "control points, one per column"))
    };
    if is_file_arg(text) {
        return bezier(load_matrix(limits, argument, text, script)?);
    }
    let expr = load_expression(limits, argument, text, script)?;
    let params = expr.parameters(env);
    match params.as_slice() {
        [] => {
            let m = expr
                .eval_at(env, &[])
                .map_err(|e| CliError::literal(argument, e, CURVE_ARG_FORM))?;
            bezier(m)
        }
        [p] => Ok(CurveSource::Expr(expr, p)),
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

/// A script's variable as a curve: a curve expression, or a sampled 3×N matrix whose
/// parameters are the script's `param` variable (or `linspace(0,1,N)`).
pub fn script_curve<T: LiteralScalar>(
    script: &Script<T>,
    name: &str,
    param: &str,
) -> Option<CurveSource<T>> {
    match script.get(name)? {
        Binding::Function(f) => {
            let params = f.parameters(script.env());
            let p = params.first().copied().unwrap_or("t");
            Some(CurveSource::Expr(script.resolve(name).ok()?, p))
        }
        Binding::Value(m) => Some(CurveSource::Samples(
            script_params(script, param, m.ncols()),
            m.clone(),
        )),
    }
}

/// The script's parameter row `name` if it has `count` values, else `linspace(0,1,count)`.
pub fn script_params<T: LiteralScalar>(script: &Script<T>, name: &str, count: usize) -> Vec<T> {
    match script.value(name) {
        Some(m) if m.len() == count && (m.nrows() == 1 || m.ncols() == 1) => {
            m.iter().cloned().collect()
        }
        _ => T::linspace(&T::zero(), &T::one(), count),
    }
}

impl<T: LiteralScalar> CurveSource<T> {
    /// The curve, exact at every value of `at` (expressions are evaluated there).
    pub fn build(
        &self,
        argument: &str,
        at: &[T],
        env: &mut Env<T>,
    ) -> Result<CliCurve<T>, CliError> {
        match self {
            CurveSource::Bezier(b) => Ok(CliCurve::Bezier(b.clone())),
            CurveSource::Expr(e, p) => {
                let m = e
                    .sample_curve(env, p, at)
                    .map_err(|e| CliError::literal(argument, e, CURVE_FORM))?;
                // An expression is a curve on [0, 1], sampled also where the grid reaches beyond.
                SampledCurve::new(at.to_vec(), m)
                    .and_then(|c| c.with_domain(T::zero(), T::one()))
                    .map(CliCurve::Sampled)
                    .map_err(lib(argument, CURVE_ARG_FORM))
            }
            CurveSource::Samples(params, m) => SampledCurve::new(params.clone(), m.clone())
                .map(CliCurve::Sampled)
                .map_err(lib(argument, "a curve sampled at increasing parameters")),
        }
    }

    /// The parameters of thesis-style samples, if that is what this is.
    pub fn sample_params(&self) -> Option<&[T]> {
        match self {
            CurveSource::Samples(p, _) => Some(p),
            _ => None,
        }
    }
}

/// Samples a curve at `ts` as a d×k matrix.
pub fn sample<T: LiteralScalar, C: Curve<T>>(c: &C, ts: &[T]) -> DMatrix<T> {
    let cols: Vec<DVector<T>> = ts.iter().map(|t| c.eval(t.clone())).collect();
    DMatrix::from_columns(&cols)
}

/// Adds a picture to the pending files.
pub fn add_plot(
    files: &mut PendingWrites,
    argument: &str,
    path: &Path,
    figure: &Figure,
) -> Result<(), CliError> {
    let plot_error =
        |e: crate::plot::PlotError| CliError::plot(format!("{argument} {}", path.display()), &e);
    // Standard output gets SVG, the picture format that is text.
    let kind = if path.as_os_str() == "-" {
        ImageKind::Svg
    } else {
        ImageKind::from_path(path).map_err(plot_error)?
    };
    let bytes = figure.render(kind).map_err(plot_error)?;
    files.add(argument, path, bytes);
    Ok(())
}

/// Adds a triangle mesh of a grid to the pending files.
pub fn add_mesh(
    files: &mut PendingWrites,
    argument: &str,
    path: &Path,
    grid: &PointGrid<f64>,
) -> Result<(), CliError> {
    let mesh_error =
        |e: crate::mesh::MeshError| CliError::mesh(format!("{argument} {}", path.display()), &e);
    // Standard output gets OBJ, a mesh format that is text.
    let format = if path.as_os_str() == "-" {
        crate::mesh::MeshFormat::Obj
    } else {
        crate::mesh::MeshFormat::from_path(path).map_err(mesh_error)?
    };
    let bytes = crate::mesh::encode(grid, format).map_err(mesh_error)?;
    files.add(argument, path, bytes);
    Ok(())
}

/// The end of every subcommand: the result text goes to standard output, or with `-o FILE`
/// to that file (staged with the other `files`), and is handed back with the files and the
/// warnings.
pub fn finish<T: LiteralScalar>(
    report: &Report<T>,
    output: &OutputArgs,
    mut files: PendingWrites,
    warnings: Vec<(String, Warning)>,
) -> Result<Outcome, CliError> {
    if let Some((name, index, value)) = report.first_non_finite() {
        // `run` names the command's input in place of RESULT (see `Command::input`).
        return Err(CliError::new(
            RESULT,
            format!("the result overflows the range of doubles ({name}, element {index}: {value})"),
            "inputs whose result stays within ±1.8e308 (smaller coordinates, parameters or orders)",
            ErrorKind::Library(Box::new(cagd::Error::NonFinite {
                what: "result",
                index,
                value,
            })),
        ));
    }
    let text = crate::render_in(report, output.format, output.text_digits(), output.lang)?;
    let stdout = match &output.output {
        Some(path) => {
            files.add("--output", path, text.into_bytes());
            String::new()
        }
        None => text,
    };
    Ok(Outcome {
        stdout,
        files,
        warnings,
    })
}

/// Warnings of a script and of an evaluation environment, named by argument.
pub fn warnings<T: LiteralScalar>(
    script_path: &Option<String>,
    script: Option<&Script<T>>,
    env: &mut Env<T>,
) -> Vec<(String, Warning)> {
    let mut out: Vec<(String, Warning)> = match (script_path, script) {
        (Some(path), Some(s)) => s
            .warnings()
            .into_iter()
            .map(|w| (format!("--script {path}"), w))
            .collect(),
        _ => Vec::new(),
    };
    // The environment starts as a copy of the script's, so it repeats the script's warnings:
    // each is reported once, about the script.
    let from_script: Vec<Warning> = out.iter().map(|(_, w)| w.clone()).collect();
    out.extend(
        env.take_warnings()
            .into_iter()
            .filter(|w| !from_script.contains(w))
            .map(|w| ("expression".to_string(), w)),
    );
    out
}

/// Pushes a surface result: the grid `us × vs × d` (`result(i,j,:)` at `(us[i], vs[j])`), or
/// with `list` (`--list`) a matrix with one row `u v x y z` per grid point, `u` varying
/// slowest.
pub fn push_surface<T: LiteralScalar>(
    report: &mut Report<T>,
    name: &str,
    (us, vs): (&[T], &[T]),
    grid: PointGrid<T>,
    list: bool,
) {
    if !list {
        report.push(name, crate::Value::Grid(grid));
        return;
    }
    let (nu, nv, d) = grid.dim();
    let rows = DMatrix::from_fn(nu * nv, d + 2, |k, c| {
        let (i, j) = (k / nv, k % nv);
        match c {
            0 => us[i].clone(),
            1 => vs[j].clone(),
            _ => grid[[i, j, c - 2]].clone(),
        }
    });
    report.push(name, crate::Value::Matrix(rows));
}

/// The degree `p` of a B-spline from `--degree P` or the notes' `--order K = p + 1`
/// (`default` when neither is given).
pub fn spline_degree(
    degree: Option<usize>,
    order: Option<usize>,
    default: usize,
) -> Result<usize, CliError> {
    match (degree, order) {
        (Some(_), Some(_)) => Err(usage(
            "--order",
            "cannot be used together with --degree",
            "only one of them (the order k is the degree p + 1)",
        )),
        (None, Some(0)) => Err(shape(
            "--order",
            "order k = 0".to_string(),
            "an order k ≥ 1 (the degree p = k − 1)",
        )),
        (None, Some(k)) => Ok(k - 1),
        (Some(p), None) => Ok(p),
        (None, None) => Ok(default),
    }
}

/// Named values as a [`crate::Value::Record`].
pub fn record<T: LiteralScalar>(parts: Vec<(&str, crate::Value<T>)>) -> crate::Value<T> {
    crate::Value::Record(
        parts
            .into_iter()
            .map(|(name, value)| crate::Item {
                name: name.to_string(),
                value,
            })
            .collect(),
    )
}

/// The net of `--x`, `--y`, `--z` (the lecture notes' `X`, `Y`, `Z` of a patch): one
/// `(m+1) × (n+1)` matrix per coordinate given (`--x` at least), entry `(i, j)` of point
/// `P_ij`.
pub fn coordinate_net<T: LiteralScalar>(
    limits: &Limits,
    given: [&Option<String>; 3],
    script: Option<&Script<T>>,
) -> Result<PointGrid<T>, CliError> {
    let mut coords = Vec::with_capacity(3);
    for (arg, given) in ["--x", "--y", "--z"].into_iter().zip(given) {
        if let Some(text) = given {
            coords.push((arg, load_matrix::<T>(limits, arg, text, script)?));
        }
    }
    let Some((_, first)) = coords.first() else {
        return Err(usage(
            "--x",
            "missing",
            "the coordinate matrices --x, --y (and --z)",
        ));
    };
    let shape0 = first.shape();
    if let Some((arg, m)) = coords.iter().find(|(_, m)| m.shape() != shape0) {
        return Err(shape(
            arg,
            format!(
                "a {}×{} matrix, but --x is {}×{}",
                m.nrows(),
                m.ncols(),
                shape0.0,
                shape0.1
            ),
            "coordinate matrices of one shape (m+1)×(n+1)",
        ));
    }
    Ok(PointGrid::from_shape_fn(
        (shape0.0, shape0.1, coords.len()),
        |(i, j, k)| coords[k].1[(i, j)].clone(),
    ))
}

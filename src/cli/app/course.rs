//! The course material of seeds 001 and 004: `spline`, `hermite`, `bspline`, `nurbs`.

use clap::{Args, ValueEnum};
use nalgebra::{DMatrix, DVector};

use crate::cli::args::{CurveParamArgs, OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::cli::{load_params, samples, CliError, PendingWrites, Report, Value};
use crate::octave::literal::LiteralScalar;
use crate::plot::{Colour, Figure};
use crate::{BSplineCurve, CubicSpline, EndCondition, HermiteCubic, NurbsCurve};

use super::common::*;
use super::Outcome;

fn vector<T: LiteralScalar>(arg: &str, text: &str) -> Result<DVector<T>, CliError> {
    let m = crate::cli::load_matrix::<T>(arg, text, None)?;
    if m.nrows() != 1 && m.ncols() != 1 {
        return Err(shape(
            arg,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            "a vector such as \"[1;1]\"",
        ));
    }
    Ok(DVector::from_iterator(m.len(), m.iter().cloned()))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum End {
    /// Given end tangents (--start-tangent, --end-tangent).
    Clamped,
    /// Zero second derivatives at the ends.
    Natural,
    /// A closed (periodic) spline.
    Closed,
}

#[derive(Debug, Args)]
pub struct SplineCommand {
    /// The points to interpolate, one per column.
    #[arg(value_name = "POINTS", allow_hyphen_values = true)]
    pub points: String,
    /// The end condition.
    #[arg(long, value_enum, default_value_t = End::Natural)]
    pub end: End,
    /// The tangent at the first point (with --end clamped).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub start_tangent: Option<String>,
    /// The tangent at the last point (with --end clamped).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub end_tangent: Option<String>,
    /// Curve parameters (segment k runs over [k, k+1]).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub t: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// An interpolating cubic spline.
pub fn spline<T: LiteralScalar>(cmd: &SplineCommand) -> Result<Outcome, CliError> {
    let pts = points("POINTS", &cmd.points, None, cmd.rows.rows)?;
    let end = match cmd.end {
        End::Natural => EndCondition::Natural,
        End::Closed => EndCondition::Closed,
        End::Clamped => {
            let need = |arg: &str, v: &Option<String>| -> Result<DVector<T>, CliError> {
                let text = v.as_ref().ok_or_else(|| {
                    usage(
                        arg,
                        "missing with --end clamped",
                        "a tangent vector such as \"[1;1]\"",
                    )
                })?;
                vector(arg, text)
            };
            EndCondition::Clamped {
                start: need("--start-tangent", &cmd.start_tangent)?,
                end: need("--end-tangent", &cmd.end_tangent)?,
            }
        }
    };
    let s = CubicSpline::interpolate(pts, end).map_err(lib(
        "POINTS",
        "at least 2 points (3 for closed) as columns, tangents of the same dimension",
    ))?;
    let segments = s.segment_count();
    let ts: Vec<T> = match &cmd.t {
        Some(t) => load_params("--t", t)?,
        None => {
            let unit: Vec<T> = samples(10 * segments + 1, 2)?;
            let k = T::from_usize(segments);
            unit.into_iter().map(|x| x * k.clone()).collect()
        }
    };
    let mut report = Report::new();
    report.push("tangents", Value::Matrix(s.tangents().clone()));
    report.push("t", Value::Matrix(row(&ts)));
    let values = s.eval_many(&ts);
    report.push("result", Value::Matrix(values.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let figure = Figure::new("interpolating cubic spline")
            .curve(to_f64(&values), Colour::Blue, "spline")
            .control_polygon(to_f64(s.points()), "points");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

#[derive(Debug, Args)]
pub struct HermiteCommand {
    /// The start point x(0).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub p0: String,
    /// The end point x(1).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub p1: String,
    /// The start tangent x'(0).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub t0: String,
    /// The end tangent x'(1).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub t1: String,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// A Hermite / Ferguson cubic.
pub fn hermite<T: LiteralScalar>(cmd: &HermiteCommand) -> Result<Outcome, CliError> {
    let h = HermiteCubic::new(
        vector("--p0", &cmd.p0)?,
        vector("--p1", &cmd.p1)?,
        vector("--t0", &cmd.t0)?,
        vector("--t1", &cmd.t1)?,
    )
    .map_err(lib(
        "--p0/--p1/--t0/--t1",
        "four vectors of the same dimension",
    ))?;
    let ts: Vec<T> = params_or_samples("--t", &cmd.params.t, cmd.params.n, DEFAULT_SAMPLES)?;
    let mut report = Report::new();
    if cmd.steps.steps {
        let basis = DMatrix::from_fn(ts.len(), 4, |i, j| {
            crate::hermite::hermite_basis(ts[i].clone())[j].clone()
        });
        report.push("hermite_basis", Value::Matrix(basis));
        report.push(
            "bezier_control",
            Value::Matrix(h.to_bezier().control().clone()),
        );
    }
    let values = DMatrix::from_columns(&ts.iter().map(|t| h.eval(t.clone())).collect::<Vec<_>>());
    report.push("t", Value::Matrix(row(&ts)));
    report.push("result", Value::Matrix(values.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let dense: Vec<T> = T::linspace(&T::zero(), &T::one(), 101);
        let line =
            DMatrix::from_columns(&dense.iter().map(|t| h.eval(t.clone())).collect::<Vec<_>>());
        let figure = Figure::new("Hermite cubic")
            .curve(to_f64(&line), Colour::Blue, "x(t)")
            .control_polygon(to_f64(h.to_bezier().control()), "Bézier control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

#[derive(Debug, Args)]
pub struct BSplineCommand {
    /// Control points, one per column.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The degree p.
    #[arg(long, value_name = "P", default_value_t = 3)]
    pub degree: usize,
    /// The knot vector (n+p+2 non-decreasing values); default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The parameters of a knot vector's domain: given, or `--n` samples of it.
fn domain_params<T: LiteralScalar>(
    params: &CurveParamArgs,
    (a, b): (T, T),
) -> Result<Vec<T>, CliError> {
    match &params.t {
        Some(t) => load_params("--t", t),
        None => {
            let unit: Vec<T> = samples(params.n.unwrap_or(DEFAULT_SAMPLES), 2)?;
            Ok(unit
                .into_iter()
                .map(|x| a.clone() + x * (b.clone() - a.clone()))
                .collect())
        }
    }
}

/// A B-spline curve.
pub fn bspline<T: LiteralScalar>(cmd: &BSplineCommand) -> Result<Outcome, CliError> {
    check_degree("--degree", cmd.degree)?;
    let control = points::<T>("CONTROL", &cmd.control, None, cmd.rows.rows)?;
    let form = "degree p, n+1 ≥ p+1 control points and n+p+2 non-decreasing knots";
    let curve = match &cmd.knots {
        Some(k) => BSplineCurve::new(cmd.degree, load_params("--knots", k)?, control),
        None => BSplineCurve::clamped(cmd.degree, control),
    }
    .map_err(lib("CONTROL/--degree/--knots", form))?;
    let ts = domain_params(&cmd.params, curve.domain())?;
    let values = curve
        .eval_many(&ts)
        .map_err(lib("--t", "parameters inside the knot span"))?;
    let mut report = Report::new();
    if cmd.steps.steps {
        let mut rows = Vec::with_capacity(ts.len());
        for t in &ts {
            rows.push(
                curve
                    .basis(t)
                    .map_err(lib("--t", "parameters inside the knot span"))?,
            );
        }
        let n = rows.first().map_or(0, Vec::len);
        report.push(
            "basis",
            Value::Matrix(DMatrix::from_fn(ts.len(), n, |i, j| rows[i][j].clone())),
        );
    }
    report.push("t", Value::Matrix(row(&ts)));
    report.push("result", Value::Matrix(values));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let (a, b) = curve.domain();
        let dense: Vec<T> = T::linspace(&a, &b, 201);
        let line = curve.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let figure = Figure::new("B-spline curve")
            .curve(to_f64(&line), Colour::Blue, "curve")
            .control_polygon(to_f64(curve.control()), "control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

#[derive(Debug, Args)]
pub struct NurbsCommand {
    /// Control points, one per column.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The weights, one per control point, positive.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub weights: String,
    /// The degree p.
    #[arg(long, value_name = "P", default_value_t = 2)]
    pub degree: usize,
    /// The knot vector; default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// A NURBS curve.
pub fn nurbs<T: LiteralScalar>(cmd: &NurbsCommand) -> Result<Outcome, CliError> {
    check_degree("--degree", cmd.degree)?;
    let control = points("CONTROL", &cmd.control, None, cmd.rows.rows)?;
    let weights: Vec<T> = load_params("--weights", &cmd.weights)?;
    let n = control.ncols();
    let knots: Vec<T> = match &cmd.knots {
        Some(k) => load_params("--knots", k)?,
        None => {
            let p = cmd.degree;
            if n < p + 1 {
                return Err(shape(
                    "CONTROL",
                    format!("{n} control point(s) for degree {p}"),
                    "at least p+1 control points",
                ));
            }
            let inner = n - p;
            let mut k = vec![T::zero(); p + 1];
            for i in 1..inner {
                k.push(T::from_ratio(i as i64, inner as i64));
            }
            k.extend(std::iter::repeat_n(T::one(), p + 1));
            k
        }
    };
    let curve = NurbsCurve::new(cmd.degree, knots, control, weights).map_err(lib(
        "CONTROL/--weights/--knots",
        "one positive weight per control point and n+p+2 non-decreasing knots",
    ))?;
    let ts = domain_params(&cmd.params, curve.domain())?;
    let mut cols = Vec::with_capacity(ts.len());
    for t in &ts {
        cols.push(
            curve
                .try_eval(t.clone())
                .map_err(lib("--t", "parameters inside the knot span"))?,
        );
    }
    let values = DMatrix::from_columns(&cols);
    let mut report = Report::new();
    if cmd.steps.steps {
        let mut rows = Vec::with_capacity(ts.len());
        for t in &ts {
            rows.push(
                curve
                    .basis(t)
                    .map_err(lib("--t", "parameters inside the knot span"))?,
            );
        }
        let k = rows.first().map_or(0, Vec::len);
        report.push(
            "basis",
            Value::Matrix(DMatrix::from_fn(ts.len(), k, |i, j| rows[i][j].clone())),
        );
    }
    report.push("t", Value::Matrix(row(&ts)));
    report.push("result", Value::Matrix(values));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let (a, b) = curve.domain();
        let dense: Vec<T> = T::linspace(&a, &b, 201);
        let mut cols = Vec::with_capacity(dense.len());
        for t in &dense {
            cols.push(
                curve
                    .try_eval(t.clone())
                    .map_err(lib("--plot", "a curve"))?,
            );
        }
        let figure = Figure::new("NURBS curve")
            .curve(to_f64(&DMatrix::from_columns(&cols)), Colour::Blue, "curve")
            .control_polygon(to_f64(&curve.points()), "control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

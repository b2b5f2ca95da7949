//! `elevate`: degree elevation of a Bézier curve (thesis §2, the CAD notes §1.1) or of a
//! clamped B-spline curve (the CAD notes §1.2).

use cagd::bezier::BezierCurve;
use cagd::limits::Limits;
use cagd::BSplineCurve;
use cagd_octave::literal::LiteralScalar;
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, CliError, PendingWrites, Report, Value};

use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::Cost;

/// Raise the degree of a Bézier curve (or of a clamped B-spline curve) without changing it.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: control points as columns (rows with --rows); --by R. A Bézier curve, or a B-spline with
--degree/--order and --knots (clamped: first and last knot p+1 times; default clamped uniform).
Layout: control is d×(n+R+1); for a B-spline also knots (each distinct knot R times more, as
octave-nurbs nrbdegelev). --steps prints every intermediate Bézier polygon
b'_i = i/(n+1)·b_(i-1) + (1 − i/(n+1))·b_i.

Examples:
  cagd elevate \"[0 0; 1 2; 3 2; 4 0]\" --rows --by 1 --steps --exact
  cagd elevate \"[0 0; 1 2; 3 2; 4 0]\" --rows --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --by 1 --exact")]
pub struct ElevateCommand {
    /// Control points, one per column (rows with --rows).
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// Raise the degree by R.
    #[arg(long = "by", short = 'r', value_name = "R", default_value_t = 1)]
    pub by: usize,
    /// A B-spline of degree P (with --knots, default clamped uniform on [0, 1]) instead of a
    /// Bézier curve.
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// A B-spline of order K = P + 1 (the lecture notes count by order).
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// The knot vector of the B-spline (clamped: first and last knot P+1 times).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// Degree elevation.
pub fn elevate<T: LiteralScalar>(
    limits: &Limits,
    cmd: &ElevateCommand,
) -> Result<Outcome, CliError> {
    let control = points::<T>(limits, "CONTROL", &cmd.control, None, cmd.rows.rows)?;
    let n1 = control.ncols();
    let bspline = cmd.degree.is_some() || cmd.order.is_some() || cmd.knots.is_some();
    let degree = if bspline {
        spline_degree(cmd.degree, cmd.order, 3)?
    } else {
        n1.saturating_sub(1)
    };
    check_degree(limits, "--by", degree.saturating_add(cmd.by))?;
    // Each step (n+2)·d combinations; a B-spline's blossoms (p+1)² per Bézier point and q² per
    // new control point, on numbers growing by about log2(q) bits a step.
    let q = (degree + cmd.by) as u128;
    let spans = n1 as u128 + 1;
    let d = control.nrows() as u128;
    check_work(
        limits,
        "--by",
        weigh::<T>(Cost::new(
            d * (q + 1) * (q + 1) * spans * (q + 1),
            bits(control.iter()) + 2 * q + 8,
        )),
    )?;
    let mut report = Report::new();
    let mut files = PendingWrites::new();
    if !bspline {
        let curve = BezierCurve::new(control).map_err(lib(
            "CONTROL",
            "control points b_0..b_n, one per column (or per row with --rows)",
        ))?;
        let mut steps = vec![curve.clone()];
        for _ in 0..cmd.by {
            let next = steps[steps.len() - 1].elevate();
            steps.push(next);
        }
        if cmd.steps.steps {
            // b'_i = i/(n+1) b_{i−1} + (1 − i/(n+1)) b_i at each step.
            for s in &steps[1..] {
                report.push(
                    format!("degree_{}", s.degree()),
                    Value::Matrix(s.control().clone()),
                );
            }
        }
        let last = steps.pop().expect("at least the curve");
        report.push("control", Value::Matrix(last.control().clone()));
        if let Some(path) = &cmd.plot.plot {
            let dense: Vec<T> = T::linspace(&T::zero(), &T::one(), 101);
            let line = curve.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
            let figure = Figure::new(format!(
                "degree elevation {} → {}",
                curve.degree(),
                last.degree()
            ))
            .curve(to_f64(&line), Colour::Blue, "curve")
            .boundary(to_f64(curve.control()), Colour::Black, "original polygon")
            .control_polygon(to_f64(last.control()), "elevated polygon");
            add_plot(&mut files, "--plot", path, &figure)?;
        }
        return finish(&report, &cmd.output, files, Vec::new());
    }
    let form = "degree p, n ≥ p+1 control points and n+p+1 non-decreasing knots, clamped";
    let curve = match &cmd.knots {
        Some(k) => BSplineCurve::new(degree, load_params(limits, "--knots", k)?, control),
        None => BSplineCurve::clamped(degree, control),
    }
    .map_err(lib("CONTROL/--degree/--knots", form))?;
    let elevated = curve.elevate(cmd.by).map_err(lib(
        "--knots",
        "a clamped knot vector (first and last knots p+1 times)",
    ))?;
    if cmd.steps.steps {
        report.push("knots_before", Value::Matrix(row(curve.knots().as_slice())));
        report.push(
            "degree",
            Value::Matrix(DMatrix::from_element(
                1,
                1,
                T::from_usize(elevated.degree()),
            )),
        );
    }
    report.push("knots", Value::Matrix(row(elevated.knots().as_slice())));
    report.push("control", Value::Matrix(elevated.control().clone()));
    if let Some(path) = &cmd.plot.plot {
        let (a, b) = curve.domain();
        let dense: Vec<T> = T::linspace(&a, &b, 201);
        let line = curve.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let figure = Figure::new(format!(
            "B-spline degree elevation {} → {}",
            curve.degree(),
            elevated.degree()
        ))
        .curve(to_f64(&line), Colour::Blue, "curve")
        .boundary(to_f64(curve.control()), Colour::Black, "original polygon")
        .control_polygon(to_f64(elevated.control()), "elevated polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

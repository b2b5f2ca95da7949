//! `circle` and `arc`: circular arcs as exact NURBS curves (the CAD notes §1.3: "conic sections
//! are NURBS"), built as octave-nurbs `nrbcirc`: the sweep is split into 1–4 equal arcs of at
//! most 90°, each a rational quadratic with control points at the arc's ends and at the
//! intersection of their tangents, middle weight `cos(Δ/2)`, joined with double knots.

use cagd::limits::Limits;
use cagd::NurbsCurve;
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, CliError, PendingWrites, Report, Value};

use super::common::*;
use super::work::check_work;
use super::Outcome;

/// A circle as an exact NURBS curve (octave-nurbs nrbcirc).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --radius (default 1), --center (2 or 3 coordinates, default [0 0]).
Layout: knots, control (d×9: four quarter arcs), weights (1 and √2/2), and the points at --t
(default --n 11 samples of [0, 1]). --steps prints the homogeneous coefficients (w·x, w·y, w),
as octave-nurbs stores them.

Example:
  cagd circle --radius 2 --center \"[1 -1]\" --n 9 --plot circle.svg")]
pub struct CircleCommand {
    /// The radius r > 0.
    #[arg(
        long,
        value_name = "R",
        default_value = "1",
        allow_hyphen_values = true
    )]
    pub radius: String,
    /// The center, 2 or 3 coordinates (the circle lies in the plane z = center z).
    #[arg(
        long,
        value_name = "VECTOR",
        default_value = "[0 0]",
        allow_hyphen_values = true
    )]
    pub center: String,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// A circular arc as an exact NURBS curve (octave-nurbs nrbcirc with angles).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: as for circle, with --start and --end angles in radians (expressions such as pi/2).
Layout: as for circle; 1 to 4 rational quadratic pieces of at most 90° each.

Example:
  cagd arc --radius 1 --start 0 --end pi/2 --n 5")]
pub struct ArcCommand {
    #[command(flatten)]
    pub circle: CircleCommand,
    /// The start angle in radians (anticlockwise from the x axis); expressions such as pi/4
    /// are allowed.
    #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
    pub start: String,
    /// The end angle in radians (at most one full turn from the start).
    #[arg(long, value_name = "ANGLE", allow_hyphen_values = true)]
    pub end: String,
}

/// One number of an argument (an expression such as `pi/2` is allowed).
fn number(limits: &Limits, argument: &str, text: &str) -> Result<f64, CliError> {
    let form = "one number, or an expression such as pi/2";
    let expr = cagd_octave::literal::ParamExpr::parse_with(text, limits)
        .map_err(|e| CliError::literal(argument, e, form))?;
    let m = expr
        .eval_at(&cagd_octave::literal::Env::with_limits(*limits), &[])
        .map_err(|e| CliError::literal(argument, e, form))?;
    match m.as_slice() {
        [x] => Ok(*x),
        _ => Err(shape(
            argument,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            form,
        )),
    }
}

fn run(
    limits: &Limits,
    cmd: &CircleCommand,
    angles: Option<(f64, f64)>,
) -> Result<Outcome, CliError> {
    if cmd.output.exact {
        return Err(usage(
            "--exact",
            "a circle's NURBS weights cos(Δ/2) (√2/2 for quarter arcs) are irrational",
            "the circle in doubles (leave out --exact)",
        ));
    }
    let radius = number(limits, "--radius", &cmd.radius)?;
    let center = crate::load_matrix::<f64>(limits, "--center", &cmd.center, None)?;
    let center: Vec<f64> = center.iter().copied().collect();
    let form = "a positive radius, a center of 2 or 3 coordinates, and at most one full turn";
    let curve = match angles {
        Some((a, b)) => NurbsCurve::arc(radius, &center, a, b),
        None => NurbsCurve::circle(radius, &center),
    }
    .map_err(lib("--radius/--center", form))?;
    let ts: Vec<f64> = match &cmd.params.t {
        Some(t) => load_params(limits, "--t", t)?,
        None => crate::samples(limits, cmd.params.n.unwrap_or(DEFAULT_SAMPLES), 2)?,
    };
    crate::slips::outside(
        "--t",
        &ts,
        &0.0,
        &1.0,
        "outside its domain a NURBS curve is not defined",
    );
    check_work(limits, "--t", 40 * (ts.len() as u128 + 201))?;
    let mut cols = Vec::with_capacity(ts.len());
    for t in &ts {
        cols.push(
            curve
                .try_eval(*t)
                .map_err(lib("--t", "parameters in [0, 1]"))?,
        );
    }
    let mut report = Report::new();
    if cmd.steps.steps {
        report.push(
            "coefs",
            Value::Matrix(curve.homogeneous().control().clone()),
        );
    }
    report.push("knots", Value::Matrix(row(curve.knots())));
    report.push("control", Value::Matrix(curve.points()));
    report.push("weights", Value::Matrix(row(&curve.weights())));
    report.push("t", Value::Matrix(row(&ts)));
    report.push("result", Value::Matrix(DMatrix::from_columns(&cols)));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let dense: Vec<f64> = (0..=200).map(|k| k as f64 / 200.0).collect();
        let mut line = Vec::with_capacity(dense.len());
        for t in &dense {
            line.push(curve.try_eval(*t).map_err(lib("--plot", "a curve"))?);
        }
        let title = if angles.is_some() {
            "circular arc (NURBS)"
        } else {
            "circle (NURBS)"
        };
        let figure = Figure::new(title)
            .curve(DMatrix::from_columns(&line), Colour::Blue, "curve")
            .control_polygon(curve.points(), "control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

/// A full circle.
pub fn circle(limits: &Limits, cmd: &CircleCommand) -> Result<Outcome, CliError> {
    run(limits, cmd, None)
}

/// A circular arc.
pub fn arc(limits: &Limits, cmd: &ArcCommand) -> Result<Outcome, CliError> {
    let a = number(limits, "--start", &cmd.start)?;
    let b = number(limits, "--end", &cmd.end)?;
    run(limits, &cmd.circle, Some((a, b)))
}

//! `subdivide`: a Bézier curve split at `t` into two Bézier curves whose control polygons are
//! the two edges of the de Casteljau scheme (thesis §2.1).

use cagd::bezier::BezierCurve;
use cagd::limits::Limits;
use cagd_octave::literal::LiteralScalar;
use clap::Args;

use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, CliError, PendingWrites, Report, Value};

use super::bezier::interval;
use super::common::*;
use super::scheme::{curve_scheme, Marks};
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::polynomial_bits;
use cagd::cost::Cost;

/// Split a Bézier curve at t into two Bézier curves (de Casteljau subdivision).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: control points as columns (rows with --rows); --t (default the middle of the interval).
Layout: left and right are d×(n+1), the control polygons of the parts before and after t.
--steps prints the de Casteljau scheme with the two polygons marked: L on the diagonal
b_0^r (left part), R on the last row b_(n-r)^r (right part).

Example:
  cagd subdivide \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'\" --t 0.5 --steps --exact")]
pub struct SubdivideCommand {
    /// Control points b_0..b_n, one per column (rows with --rows).
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// Where to split: one parameter inside the interval (default its middle).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub t: Option<String>,
    /// The parameter interval [a, b] of the curve (default 0,1).
    #[arg(long, value_name = "A,B", allow_hyphen_values = true)]
    pub interval: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// Subdivision at one parameter.
pub fn subdivide<T: LiteralScalar>(
    limits: &Limits,
    cmd: &SubdivideCommand,
) -> Result<Outcome, CliError> {
    let control = points::<T>(limits, "CONTROL", &cmd.control, None, cmd.rows.rows)?;
    check_degree(limits, "CONTROL", control.ncols().saturating_sub(1))?;
    let (a, b) = interval::<T>(limits, &cmd.interval)?;
    let curve = BezierCurve::new_on_interval(control, a.clone(), b.clone()).map_err(lib(
        "CONTROL",
        "control points b_0..b_n, one per column (or per row with --rows)",
    ))?;
    let t: T = match &cmd.t {
        Some(text) => {
            let values: Vec<T> = load_params(limits, "--t", text)?;
            match values.as_slice() {
                [t] => t.clone(),
                _ => {
                    return Err(shape(
                        "--t",
                        format!("{} values", values.len()),
                        "one parameter t with a < t < b",
                    ))
                }
            }
        }
        None => (a.clone() + b.clone()) / T::from_usize(2),
    };
    let (n, d) = (curve.degree() as u128, curve.dim() as u128);
    let size = polynomial_bits(
        curve.degree(),
        bits(std::slice::from_ref(&t)),
        bits(curve.control().iter()),
    );
    let picture = if cmd.plot.plot.is_some() { 101 } else { 0 };
    check_work(
        limits,
        "CONTROL",
        weigh::<T>(Cost::new(d * (n + 1) * (n + 1) * (1 + picture), size)),
    )?;
    let (left, right) = curve.subdivide(t.clone()).map_err(lib(
        "--t",
        "a parameter strictly inside the curve's interval (both parts non-empty)",
    ))?;
    let mut report = Report::new();
    if cmd.steps.steps {
        report.push(
            "scheme",
            curve_scheme(
                &curve.scheme(t.clone()),
                cmd.output.text_digits(),
                Marks::Subdivision,
            ),
        );
    }
    report.push("t", Value::Matrix(row(std::slice::from_ref(&t))));
    report.push("left", Value::Matrix(left.control().clone()));
    report.push("right", Value::Matrix(right.control().clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let dense: Vec<T> = T::linspace(&a, &b, 101);
        let line = curve.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let figure = Figure::new("subdivision (de Casteljau)")
            .curve(to_f64(&line), Colour::Blue, "curve")
            .boundary(to_f64(curve.control()), Colour::Black, "control polygon")
            .control_polygon(to_f64(left.control()), "left part")
            .boundary(to_f64(right.control()), Colour::Green, "right part");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

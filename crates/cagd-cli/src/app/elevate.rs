//! `cagd elevate`: degree elevation of a Bézier curve (thesis §2, the CAD notes §1.1) or of a
//! clamped B-spline curve (the CAD notes §1.2).

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Elevate;
use clap::Args;

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::{bspline_arg, points};
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::{CliError, Outcome};

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
    #[arg(long, value_name = "K", conflicts_with = "degree")]
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

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "CONTROL",
    special: &[],
};

impl Run for ElevateCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op = Elevate::<T> {
            control: points(cx, "CONTROL", &self.control, None, self.rows.rows)?,
            by: self.by,
            bspline: bspline_arg(cx, self.degree, self.order, &self.knots)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
        };
        let to = Destinations {
            output: &self.output,
            plot: self.plot.plot.as_deref(),
            mesh: None,
        };
        respond(cx, &NAMES, &op, to)
    }
}

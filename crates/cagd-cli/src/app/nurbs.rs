//! `cagd nurbs`: points of a NURBS curve.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Nurbs;
use clap::Args;

use super::answer::{respond, Destinations};
use super::read::{curve_params, points};
use super::run::{Names, Run};
use super::spline_args::{degree, values};
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::cx::Cx;
use crate::{load_params, CliError, Outcome};

/// A NURBS curve (the CAD notes): rational B-spline with weights.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: n control points as columns (rows with --rows), --weights (one per point, positive),
--degree p (default 3, cubic) or --order k = p + 1, --knots: n + p + 1 non-decreasing values
u_1..u_(n+p+1), numbered from 1 as the notes number them (default clamped uniform on [0, 1]).
The curve is defined on its domain [u_(p+1), u_(n+1)]; --n samples it.
Layout: t is 1×k, result d×k (one point per column); --steps prints the rational basis
functions R_1,p(t)..R_n,p(t) (k×n, row = parameter).

Example (a quarter circle):
  cagd nurbs \"[1 0; 1 1; 0 1]'\" --weights \"[1 0.7071067811865476 1]\" --degree 2 --n 5")]
#[command(mut_arg("n", |a| a.help("Sample the knot domain [u_(p+1), u_(n+1)] (not [0, 1]) at N equally spaced parameters")))]
pub struct NurbsCommand {
    /// Control points, one per column.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The weights, one per control point, positive.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub weights: String,
    /// The degree p (default 3).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order k = p + 1 instead of the degree.
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// The knot vector: n + p + 1 non-decreasing values for n control points; default clamped
    /// uniform on [0, 1].
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

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "CONTROL",
    special: &[],
};

impl Run for NurbsCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op: Nurbs<T> = Nurbs {
            control: points(cx, "CONTROL", &self.control, None, self.rows.rows)?,
            weights: load_params(cx, "--weights", &self.weights)?,
            degree: degree(&NAMES, self.degree, self.order)?,
            knots: values(cx, "--knots", &self.knots)?,
            t: curve_params(cx, &self.params)?,
            basis: false,
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

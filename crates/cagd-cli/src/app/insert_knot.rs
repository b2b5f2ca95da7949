//! `cagd insert-knot`: knot insertion into a B-spline or NURBS curve (Boehm's algorithm).

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::InsertKnot;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::read::points;
use super::run::{Names, Run};
use super::spline_args::{degree, values};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::cx::Cx;
use crate::{load_params, CliError, Outcome};

/// Insert knots into a B-spline or NURBS curve (Boehm's algorithm).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: n control points as columns (rows with --rows), --degree p (default 3, cubic) or
--order k = p + 1, --knots: n + p + 1 non-decreasing values u_1..u_(n+p+1), numbered from 1
as the notes number them (default clamped uniform on [0, 1]), --insert the r knots to add
(strictly inside the domain [u_(p+1), u_(n+1)]); --weights for a NURBS curve (the
homogeneous points (w P, w) are refined).
Layout: knots 1×(n + p + 1 + r) and control d×(n+r) (weights 1×(n+r) for NURBS). --steps prints each
insertion: the span s (u_s ≤ u < u_(s+1)), α_i = (u − u_i)/(u_(i+p) − u_i) for
i = s−p+1..s, and the new polygon.

Example:
  cagd insert-knot \"[0 0; 1 2; 3 2; 4 0]\" --rows --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --insert 0.25 --steps --exact")]
pub struct InsertKnotCommand {
    /// Control points, one per column (rows with --rows).
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The knots to insert (any order, repeats allowed), each strictly inside the domain.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub insert: String,
    /// The degree p (default 3).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order k = p + 1 instead of the degree (the lecture notes count by order).
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// The knot vector: n + p + 1 non-decreasing values for n control points; default clamped
    /// uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    /// Weights of a NURBS curve, one per control point (positive).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub weights: Option<String>,
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
    special: &[(Role::At, "--insert")],
};

impl Run for InsertKnotCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op: InsertKnot<T> = InsertKnot {
            control: points(cx, "CONTROL", &self.control, None, self.rows.rows)?,
            weights: values(cx, "--weights", &self.weights)?,
            degree: degree(&NAMES, self.degree, self.order)?,
            knots: values(cx, "--knots", &self.knots)?,
            insert: load_params(cx, "--insert", &self.insert)?,
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

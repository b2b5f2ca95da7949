//! `cagd continuity`: what holds where two Bézier curves join — `C⁰`, `C¹`, `G¹`, `C²` — with
//! the numbers compared (the lecture notes, "napojování"), and the free control point of the
//! lecture notes' example ([`cagd_ops::ops::Continuity`]).

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Continuity;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::{one_value, points};
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::{CliError, Outcome};

/// Continuity (C0, C1, G1, C2) where two Bézier curves join; the free point of a C1 joint.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: FIRST (ends at u = 1) and SECOND (starts at v = 0), Bézier control points as columns
(rows with --rows). With --free-point the second-to-last point of FIRST is unknown and left out:
the line x_(n-1)(k) = x_n + k·(m/n)(y_0 − y_1) of points giving x'(1) = k·¹x'(0) is printed
(k = 1: C1; k > 0: G1, which the lecture notes call C1), and the joint with k = --k (default 1).
Layout: end, start (x(1), ¹x(0)), d_end, d_start (first derivatives), dd_end, dd_start
(second), k if the tangents are parallel, continuity (1 = holds), verdict (the comparison);
--steps adds each curve's control points and derivative polygons (first.d1, first.d2, …).

Examples:
  cagd continuity \"[2 3 4; 3 1 5; 3 4 3]\" \"[3 4 3; 2 6 0; 5 7 5; 5 2 3]\" --rows --free-point --exact
  cagd continuity \"[0 0; 1 1; 2 1]'\" \"[2 1; 3 1; 4 0]'\" --exact")]
pub struct ContinuityCommand {
    /// Control points of the first curve x(u), ending at u = 1 (columns; rows with --rows).
    #[arg(value_name = "FIRST", allow_hyphen_values = true)]
    pub first: String,
    /// Control points of the second curve ¹x(v), starting at v = 0.
    #[arg(value_name = "SECOND", allow_hyphen_values = true)]
    pub second: String,
    /// The second-to-last control point of FIRST is unknown and left out of FIRST: print the
    /// line of points that makes the joint smooth (the lecture notes' example).
    #[arg(long)]
    pub free_point: bool,
    /// With --free-point: the factor k of x'(1) = k·¹x'(0) for the point printed (default 1,
    /// the C1 point).
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    pub k: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    /// Also print the control points of the first and second derivatives of both curves
    /// (n Δb_i and n(n−1) Δ²b_i), whose ends are compared.
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "FIRST/SECOND",
    special: &[(Role::First, "FIRST"), (Role::Second, "SECOND")],
};

impl Run for ContinuityCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op = Continuity::<T> {
            first: points(cx, "FIRST", &self.first, None, self.rows.rows)?,
            second: points(cx, "SECOND", &self.second, None, self.rows.rows)?,
            free_point: self.free_point,
            k: match &self.k {
                Some(text) => Some(one_value(cx, "--k", text, "one number k")?),
                None => None,
            },
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

//! `cagd hermite`: the Hermite (Ferguson) cubic of two end points and two end tangents.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Hermite;
use clap::Args;

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::curve_params;
use super::run::{Names, Run};
use super::spline_args::matrix;
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, StepsArgs};
use crate::{CliError, Outcome};

/// A Hermite (Ferguson) cubic from end points and end tangents (the lecture notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: result d×k at the parameters; --steps prints the Hermite basis values and the Bézier
control points of the same cubic.

Example:
  cagd hermite --p0 \"[0;0]\" --p1 \"[1;0]\" --t0 \"[1;1]\" --t1 \"[1;-1]\" --t 0.5 --exact")]
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

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "--p0/--p1/--t0/--t1",
    special: &[],
};

impl Run for HermiteCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op: Hermite<T> = Hermite {
            data: [
                matrix(cx, "--p0", &self.p0)?,
                matrix(cx, "--p1", &self.p1)?,
                matrix(cx, "--t0", &self.t0)?,
                matrix(cx, "--t1", &self.t1)?,
            ],
            t: curve_params(cx, &self.params)?,
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

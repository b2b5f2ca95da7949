//! `cagd bernstein`: the Bernstein polynomials of one degree.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Bernstein;
use clap::Args;

use super::answer::{respond, Destinations};
use super::read::curve_params;
use super::run::{Names, Run};
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// Bernstein polynomial values B_i^n(t).
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: t is 1×k (one column per parameter), result k×(n+1) (row = parameter, column =
B_0^n..B_n^n), or k×1 with --i. --plot draws the polynomials B_i^n(t) over [0, 1] and
marks their values at each t.

Examples:
  cagd bernstein --degree 3 --t 0.5 --exact
  cagd bernstein --degree 3 --i 1 --n 5")]
pub struct BernsteinCommand {
    /// The degree n.
    #[arg(long, value_name = "N")]
    pub degree: usize,
    /// Only B_i^n (default: all of B_0^n..B_n^n).
    #[arg(long, value_name = "I")]
    pub i: Option<usize>,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "--degree",
    special: &[],
};

impl Run for BernsteinCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op = Bernstein::<T> {
            degree: self.degree,
            index: self.i,
            t: curve_params(cx, &self.params)?,
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

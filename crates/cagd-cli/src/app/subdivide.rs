//! `cagd subdivide`: a Bézier curve split at `t` into two Bézier curves whose control polygons
//! are the two edges of the de Casteljau scheme (thesis §2.1).

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Subdivide;
use clap::Args;

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::{interval, one_value, points};
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::{CliError, Outcome};

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

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "CONTROL",
    special: &[],
};

impl Run for SubdivideCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let form = "one parameter t with a < t < b";
        let op = Subdivide::<T> {
            control: points(cx, "CONTROL", &self.control, None, self.rows.rows)?,
            interval: interval(cx, &self.interval)?,
            t: match &self.t {
                Some(text) => Some(one_value(cx, "--t", text, form)?),
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

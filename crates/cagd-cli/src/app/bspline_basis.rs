//! `cagd bspline-basis`: the B-spline basis functions `N_{i,p}(u)` of a knot vector alone.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::BSplineBasis;
use clap::Args;

use super::answer::{respond, Destinations};
use super::read::curve_params;
use super::run::{Names, Run};
use super::spline_args::degree;
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, StepsArgs};
use crate::cx::Cx;
use crate::{load_params, CliError, Outcome};

/// B-spline basis functions N_i,p(u) of a knot vector (Cox–de Boor).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --knots u_1..u_(n+p+1), numbered from 1 as the notes number them (n + p + 1
non-decreasing values for n basis functions of degree p), --degree p (default 3, cubic) or
--order k = p + 1 (as the lecture notes count); --t in the knot range [u_1, u_(n+p+1)], or --n
samples of it.
Layout: t is 1×k (one column per parameter), result k×n (row = parameter, column =
N_1,p..N_n,p; N_i,p lives on [u_i, u_(i+p+1)]). --steps prints the Cox–de Boor triangle
N_i,j(t) for j = 0..p (triangle.p0 … triangle.pP). --plot draws the functions N_i,p(t).

Examples:
  cagd bspline-basis --knots \"[0 0 0 1 2 3 3 3]\" --degree 2 --t 1.5 --steps --exact
  cagd bspline-basis --knots 0:7 --order 4 --n 50 --plot basis.svg")]
#[command(mut_arg("n", |a| a.help("Sample the whole knot range [u_1, u_(n+p+1)] at N equally spaced parameters")))]
pub struct BSplineBasisCommand {
    /// The knot vector u_1 ≤ … ≤ u_(n+p+1): n + p + 1 non-decreasing values for n basis
    /// functions of degree p.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: String,
    /// The degree p (default 3).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order k = p + 1 instead of the degree (the lecture notes count by order: N_i,k).
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
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
    input: "--knots",
    special: &[],
};

impl Run for BSplineBasisCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op: BSplineBasis<T> = BSplineBasis {
            knots: load_params(cx, "--knots", &self.knots)?,
            degree: degree(&NAMES, self.degree, self.order)?,
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

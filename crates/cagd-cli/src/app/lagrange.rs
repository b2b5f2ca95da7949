//! `cagd lagrange`: the Lagrange basis at parameters, or the polynomial through values at
//! nodes.

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Lagrange;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::{curve_params, points};
use super::run::{Names, Run};
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, RowsArgs};
use crate::{load_params, CliError, Outcome};

/// Lagrange basis polynomials, or the polynomial interpolating values at nodes.
#[derive(Debug, Args)]
#[command(after_help = "\
Nodes: distinct, in any order (the lecture notes' Příklad 1 takes 0, 1/2, 1/4, 1).
Layout: without --points, result is k×(m+1): row = parameter, column = L_0..L_m (in the order of
the nodes given). With --points (d×(m+1), one column per node), result is d×k, the interpolant
at each t. --coefficients adds coefficients (row i: L_i, highest power first, the lecture notes'
G) and with --points polynomial (the interpolant's, A = X G). --linear interpolates --points
piecewise linearly instead (the lecture notes' linear interpolation; increasing nodes).

Examples:
  cagd lagrange --nodes \"[0 0.5 1]\" --t 0.25 --exact
  cagd lagrange --nodes 1:5 --points \"[1 2 3 2 1]\" --t 1:0.5:5")]
#[command(mut_arg("n", |a| a.help("Sample [smallest node, largest node] at N equally spaced parameters")))]
pub struct LagrangeCommand {
    /// The nodes x_0..x_m: a list such as "[0 0.5 1]" or a range.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub nodes: String,
    /// Values at the nodes, one column per node (a d×(m+1) matrix, or 1×(m+1) for numbers):
    /// then the interpolating polynomial's values are printed; without it, the basis
    /// polynomials L_0..L_m.
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub points: Option<String>,
    /// Also print the monomial coefficients (highest power first, as Octave's polyfit):
    /// `coefficients`, row i those of L_i (the lecture notes' blending matrix G), and with
    /// --points `polynomial`, those of the interpolant (the lecture notes' A = X G).
    #[arg(long)]
    pub coefficients: bool,
    /// Piecewise-linear interpolation of --points instead of the polynomial (the lecture
    /// notes' "lineární interpolace"; the nodes must increase, the end pieces are extended).
    #[arg(long, requires = "points", conflicts_with = "coefficients")]
    pub linear: bool,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "--nodes/--points",
    special: &[(Role::Points, "--points")],
};

impl Run for LagrangeCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let values = match &self.points {
            Some(text) => Some(points(cx, "--points", text, None, self.rows.rows)?),
            None => None,
        };
        let op: Lagrange<T> = Lagrange {
            nodes: load_params(&cx.limits, "--nodes", &self.nodes)?,
            values,
            coefficients: self.coefficients,
            linear: self.linear,
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

//! `cagd integrate`: antiderivatives and definite integrals of Bernstein polynomials, Bézier
//! curves and B-spline curves (the CAD notes §1.1–1.2; formulas in `cagd::integral`).

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Integrate;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::read::{bspline_arg, given_or_samples, interval, points};
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// Antiderivative and definite integral of Bernstein polynomials, Bézier or B-spline curves.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: Bézier control points as columns (rows with --rows) over [0, 1] or --interval a,b; with
--degree p, --order k = p + 1 or --knots a B-spline of n control points: degree p (default 3,
cubic), knots n + p + 1 non-decreasing values u_1..u_(n+p+1), numbered from 1 as the notes
number them (default clamped uniform on [0, 1]); or --bernstein N [--i I] alone.
Layout: antiderivative holds the control points of ∫ (d×(n+2) for a Bézier curve of degree n;
d×(n+1) for a B-spline of n control points, with its knots (u_1, u_1, …, u_(n+p+1),
u_(n+p+1))); integral the definite integral over the domain ([0, 1], --interval, or
[u_(p+1), u_(n+1)]; d×1); with --t (t is 1×k), result holds ∫ from the start of the domain to
t. Bernstein: rows of Bernstein coefficients of degree N+1 of ∫₀ᵗ B_i^N, and
∫₀¹ B_i^N = 1/(N+1).

Examples:
  cagd integrate \"[0 0; 1 2; 2 0]\" --rows --exact
  cagd integrate --bernstein 3 --exact
  cagd integrate \"[6 0 0 0]\" --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --exact")]
pub struct IntegrateCommand {
    /// Control points of a Bézier curve (or with --knots/--degree/--order of a B-spline),
    /// one per column (rows with --rows). Leave out with --bernstein.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: Option<String>,
    /// Integrate the Bernstein polynomials B_i^N of degree N instead of a curve.
    #[arg(long, value_name = "N")]
    pub bernstein: Option<usize>,
    /// With --bernstein: only B_i^N.
    #[arg(long, value_name = "I")]
    pub i: Option<usize>,
    /// A B-spline curve of degree P (with --knots, default clamped uniform on [0, 1]).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// A B-spline curve of order K = P + 1.
    #[arg(long, value_name = "K", conflicts_with = "degree")]
    pub order: Option<usize>,
    /// The knot vector of a B-spline curve: n + p + 1 non-decreasing values for n control
    /// points (with --degree or --order; default cubic).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    /// The parameter interval [a, b] of a Bézier curve (default 0,1).
    #[arg(long, value_name = "A,B", allow_hyphen_values = true)]
    pub interval: Option<String>,
    /// Also the antiderivative's values at these parameters (∫ from the start of the domain).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub t: Option<String>,
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
    special: &[(Role::Degree, "--bernstein")],
};

impl Run for IntegrateCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op = Integrate::<T> {
            bernstein: self.bernstein,
            index: self.i,
            control: match &self.control {
                Some(text) => Some(points(cx, "CONTROL", text, None, self.rows.rows)?),
                None => None,
            },
            bspline: bspline_arg(cx, self.degree, self.order, &self.knots)?,
            interval: interval(cx, &self.interval)?,
            t: match &self.t {
                Some(_) => Some(given_or_samples(cx, "--t", &self.t, None)?),
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

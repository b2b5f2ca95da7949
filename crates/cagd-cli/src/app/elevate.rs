//! `cagd elevate`: degree elevation of a Bézier curve (thesis §2, the CAD notes §1.1) or of a
//! clamped B-spline curve (the CAD notes §1.2).

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Elevate;
use clap::Args;

use super::answer::{respond, Destinations};
use super::read::{params, points};
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::cx::Cx;
use crate::error::shape;
use crate::{CliError, Outcome};
use cagd_ops::bspline_arg::{BSplineArg, SplineDegree};

/// Raise the degree of a Bézier curve (or of a clamped B-spline curve) without changing it.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: n control points as columns (rows with --rows); --by R, or the degree after elevation
--degree P (the order after elevation --order K = P + 1; an error if it contradicts --by or lies
below the degree, a warning if it is the degree: nothing to raise). A Bézier curve of degree
n − 1, or with --knots a clamped B-spline: n + p + 1 non-decreasing knots for n control points
(the first and the last p + 1 times), so of degree p = numel(knots) − n − 1.
Layout: control is d×(n+R) for a Bézier curve; for a B-spline also knots (each distinct knot R
times more, as octave-nurbs nrbdegelev). --steps prints every intermediate Bézier polygon
b'_i = i/(q+1)·b_(i-1) + (1 − i/(q+1))·b_i of each step from degree q to q + 1.

Examples:
  cagd elevate \"[0 0; 1 2; 3 2; 4 0]\" --rows --by 1 --steps --exact
  cagd elevate \"[0 0; 1 2; 3 2; 4 0]\" --rows --degree 5 --exact
  cagd elevate \"[0 0; 1 2; 3 2; 4 0]\" --rows --knots \"[0 0 0 0.5 1 1 1]\" --by 1 --exact")]
pub struct ElevateCommand {
    /// Control points, one per column (rows with --rows).
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// Raise the degree by R (default 1, or up to --degree).
    #[arg(long = "by", short = 'r', value_name = "R")]
    pub by: Option<usize>,
    /// The degree P after elevation (the target, as "elevate to degree P" says); with --by,
    /// it must equal the degree before plus R.
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order K = P + 1 after elevation (the lecture notes count by order).
    #[arg(long, value_name = "K", conflicts_with = "degree")]
    pub order: Option<usize>,
    /// A clamped B-spline with this knot vector (its degree is numel(knots) − n − 1 for n
    /// control points) instead of a Bézier curve.
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
        let control = points(cx, "CONTROL", &self.control, None, self.rows.rows)?;
        let knots: Option<Vec<T>> = match &self.knots {
            Some(text) => Some(params(cx, "--knots", text)?),
            None => None,
        };
        // The degree before: n − 1 for a Bézier curve of n points, numel(U) − n − 1 for a
        // B-spline (a count that fits no degree is the request's error to word).
        let n = control.ncols();
        let before = match &knots {
            Some(u) => u.len().checked_sub(n + 1),
            None => n.checked_sub(1),
        };
        let by = self.by_for(cx, before)?;
        let op = Elevate::<T> {
            control,
            by,
            bspline: knots.map(|knots| BSplineArg {
                degree: SplineDegree::Degree(before.unwrap_or(0)),
                knots: Some(knots),
            }),
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

impl ElevateCommand {
    /// The elevation R: `--by`, or the target `--degree`/`--order` less the degree `before`;
    /// an error when the target contradicts `--by` or lies below the degree before, a warning
    /// when it is the degree before (R = 0, the same curve: `--degree 3` on a cubic was likely
    /// meant as `--by 3`).
    fn by_for(&self, cx: &Cx, before: Option<usize>) -> Result<usize, CliError> {
        let (argument, target) = match (self.degree, self.order) {
            (Some(p), _) => ("--degree", p),
            (None, Some(k)) => ("--order", k.saturating_sub(1)),
            (None, None) => return Ok(self.by.unwrap_or(1)),
        };
        let Some(before) = before else {
            return Ok(self.by.unwrap_or(1));
        };
        let expected = "the degree after elevation (the degree before plus --by), or --by alone";
        match (target.checked_sub(before), self.by) {
            (Some(0), None) => {
                let typed = self.degree.or(self.order).unwrap_or(target);
                let word = if self.degree.is_some() { "degree" } else { "order" };
                crate::slips::warn(
                    cx,
                    argument,
                    format!(
                        "the {word} after elevation {typed} is the curve's {word}: nothing is raised (R = 0); --by {typed} raises the degree by {typed}"
                    ),
                );
                Ok(0)
            }
            (Some(r), None) => Ok(r),
            (Some(r), Some(by)) if r == by => Ok(r),
            (Some(_), Some(by)) => Err(shape(
                argument,
                format!(
                    "the degree after elevation {target} contradicts --by {by} (degree {before} + {by} = {})",
                    before + by
                ),
                expected,
            )),
            (None, _) => Err(shape(
                argument,
                format!(
                    "the degree after elevation {target} is below the curve's degree {before} (elevation cannot lower it)"
                ),
                expected,
            )),
        }
    }
}

//! `cagd curvature`: the curvature and the Frenet frame of a curve.

use clap::Args;

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Curvature;

use super::answer::{respond, Destinations};
use super::curve_arg::{library_curve, Reading};
use super::cx::Cx;
use super::read::curve_params;
use super::run::{Names, Run};
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs};
use crate::{CliError, Outcome};

/// Curvature κ = |x′ × x″| / |x′|³ and the Frenet frame of a Bézier, B-spline or NURBS curve.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: CURVE is the control points of a Bézier curve (columns, or rows with --rows), or
bezier(P), bspline(P, U), nurbs(P, W, U) (P control points as columns, U the knot vector, whose
length minus columns(P) minus 1 is the degree, W the weights).
Layout: result is κ at each t (1×k): signed in the plane (positive turning left), ≥ 0 in space;
tangent and normal (d×k) are the unit vectors T and N, binormal (3×k, space curves) is
B = T × N. --steps also prints d1 = x′(t) and d2 = x″(t). With --exact, result is κ², which is
rational (κ and the frame need a square root); d1 and d2 are exact too. --plot draws the curve
with T (orange) and N (purple) at each point.

Examples:
  cagd curvature \"[0 1 2; 0 2 0]\" --t 0.5
  cagd curvature \"bspline([0 1 2 3; 0 1 0 1], [0 0 0 0.5 1 1 1])\" --t \"[0 0.25 0.5]\" --steps --exact
  cagd curvature \"nurbs([1 1 0; 0 1 1], [1 1 2], [0 0 0 1 1 1])\" --t 0.5")]
pub struct CurvatureCommand {
    /// The curve: control points of a Bézier curve, or bezier(P), bspline(P, U), nurbs(P, W, U).
    #[arg(value_name = "CURVE", allow_hyphen_values = true)]
    pub curve: String,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub script: ScriptArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "CURVE",
    special: &[(cagd_ops::Role::Control, "CURVE")],
};

impl Run for CurvatureCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, None)?;
        let how = Reading {
            script: script.as_ref(),
            rows: self.rows.rows,
            samples: None,
        };
        let op = Curvature {
            curve: library_curve(cx, "CURVE", &self.curve, how)?.into_deriv2(),
            t: curve_params(cx, &self.params)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
        };
        let to = Destinations {
            output: &self.output,
            plot: self.plot.plot.as_deref(),
            mesh: None,
        };
        respond(cx, &NAMES, &op, to).map(|o| o.with_script_warnings(&self.script, script.as_ref()))
    }
}

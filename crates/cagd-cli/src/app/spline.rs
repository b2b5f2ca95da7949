//! `cagd spline`: the interpolating cubic spline of the lecture notes.

use cagd::spline::Parametrization;
use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::spline::{Ends, Knots, Spline};
use cagd_ops::Role;
use clap::{Args, ValueEnum};

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::{given_or_samples, points};
use super::run::{Names, Run};
use super::spline_args::matrix;
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::{load_params, CliError, Outcome};

/// The end conditions of `--end`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum End {
    /// Given end tangents (--start-tangent, --end-tangent), case a of the lecture notes.
    Clamped,
    /// Zero second derivatives at the ends, case b.
    Natural,
    /// A closed (periodic) spline, case c.
    Closed,
}

/// An interpolating cubic spline (the lecture notes): tangents at the points and curve samples.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: points as columns (rows with --rows); --end clamped (with --start-tangent and
--end-tangent; the default when a tangent is given), natural (the default without tangents)
or closed (a tangent with natural or closed is an error). --params uniform (t_k = k, the lecture notes: segment k over [k, k+1]),
chord, centripetal or a list of values. A closed spline is periodic: every t is on the curve.
Layout: tangents is d×m (one per point); result d×k at --t (default: 10 samples per segment).
--steps prints params, the linear system (system, m×m, and rhs, d×m: system · tangentsᵀ = rhsᵀ,
as the lecture notes write it) and each segment's hermite data [x_k x_(k+1) h·x'_k h·x'_(k+1)]
and bezier control points.

Example:
  cagd spline \"[0 0; 2 1; 4 4; 6 0]'\" --end clamped --start-tangent \"[1;1]\" --end-tangent \"[-1;1]\" --exact")]
pub struct SplineCommand {
    /// The points to interpolate, one per column.
    #[arg(value_name = "POINTS", allow_hyphen_values = true)]
    pub points: String,
    /// The end condition (default: clamped when a tangent is given, else natural).
    #[arg(long, value_enum)]
    pub end: Option<End>,
    /// The tangent at the first point (clamped ends).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub start_tangent: Option<String>,
    /// The tangent at the last point (clamped ends).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub end_tangent: Option<String>,
    /// The parameters of the points: uniform (t_k = k, the lecture notes), chord, centripetal,
    /// or a list of increasing values (one per point, one more for a closed spline).
    #[arg(long, value_name = "CHOICE|VALUES", allow_hyphen_values = true)]
    pub params: Option<String>,
    /// Curve parameters (with uniform parameters segment k runs over [k, k+1]); a closed
    /// spline is periodic, so any value is on the curve.
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
    input: "POINTS",
    special: &[
        (Role::Nodes, "--params"),
        (Role::T0, "--start-tangent"),
        (Role::T1, "--end-tangent"),
        (Role::Ends, "--end"),
    ],
};

impl Run for SplineCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let tangent = |cx: &Cx, argument: &str, given: &Option<String>| {
            given
                .as_ref()
                .map(|text| matrix(cx, argument, text))
                .transpose()
        };
        let op = Spline {
            points: points(cx, "POINTS", &self.points, None, self.rows.rows)?,
            ends: self.end.map(|e| match e {
                End::Clamped => Ends::Clamped,
                End::Natural => Ends::Natural,
                End::Closed => Ends::Closed,
            }),
            start_tangent: tangent(cx, "--start-tangent", &self.start_tangent)?,
            end_tangent: tangent(cx, "--end-tangent", &self.end_tangent)?,
            knots: params(cx, self.params.as_deref())?,
            t: given_or_samples::<T>(cx, "--t", &self.t, None)?,
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

/// `--params`: uniform, chord, centripetal, or a list of values.
fn params<T: LiteralScalar>(cx: &Cx, given: Option<&str>) -> Result<Knots<T>, CliError> {
    let Some(text) = given else {
        return Ok(Knots::Chosen(Parametrization::Uniform));
    };
    Ok(match text.trim().to_ascii_lowercase().as_str() {
        "uniform" => Knots::Chosen(Parametrization::Uniform),
        "chord" => Knots::Chosen(Parametrization::Chord),
        "centripetal" => Knots::Chosen(Parametrization::Centripetal),
        _ => Knots::Given(load_params(&cx.limits, "--params", text)?),
    })
}

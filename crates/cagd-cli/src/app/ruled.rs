//! `cagd ruled`: the ruled surface `x(u, v) = (1 − v) ¹x(u) + v ²x(u)` between two curves (the
//! lecture notes, "plochy válcové").

use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Ruled;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::curve_arg::{curve_arg, Reading};
use super::expr_curve::{expression_env, with_env_warnings};
use super::read::surface_params;
use super::run::{Names, Run};
use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// The ruled surface (1 − v)·¹x(u) + v·²x(u) between two curves (the lecture notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --first ¹x(u) and --second ²x(u): expressions in u such as \"[u;0;u-u^2]\", Bézier
control points (columns; rows with --rows), or bezier(P), bspline(P, U), nurbs(P, W, U) (P the
control points as columns, U the knots, W the weights; each curve's domain is mapped onto
[0, 1], so the rulings join points at the same fraction of the two domains).
Layout: single --u and --v give the d×1 point; otherwise the grid nu×nv×d (like P), or with
--list one row u v x y z per point. --steps prints both curves at the u's.

Examples:
  cagd ruled --first \"[u;0;0]\" --second \"[u;1;u-u^2]\" --u 0.5 --v 0.25 --exact
  cagd ruled --first \"nurbs([1 1 0; 0 1 1; 0 0 0], [1 1 2], [0 0 0 1 1 1])\" --second \"nurbs([1 1 0; 0 1 1; 1 1 1], [1 1 2], [0 0 0 1 1 1])\" --u 0.5 --v 0.5 --exact
  cagd ruled --first \"[0 0 0; 1 0 1; 2 0 0]'\" --second \"[0 1 1; 2 1 1]'\" --n 10 --plot ruled.png")]
pub struct RuledCommand {
    /// The curve ¹x(u) at v = 0: an expression in u such as "[u;0;u-u^2]", Bézier control
    /// points (columns), or bezier(P), bspline(P, U), nurbs(P, W, U).
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub first: String,
    /// The curve ²x(u) at v = 1.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub second: String,
    #[command(flatten)]
    pub params: SurfaceParamArgs,
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
    #[command(flatten)]
    pub mesh: MeshArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "--first/--second",
    special: &[(Role::Boundary, "--first/--second")],
};

impl Run for RuledCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let env = expression_env(cx.limits, script.as_ref());
        let how = Reading {
            script: script.as_ref(),
            rows: self.rows.rows,
            samples: None,
        };
        let op = Ruled {
            first: curve_arg(cx, "--first", &self.first, how, &env)?,
            second: curve_arg(cx, "--second", &self.second, how, &env)?,
            at: surface_params(cx, &self.params)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
            mesh: self.mesh.mesh.is_some(),
        };
        let to = Destinations::surface(&self.output, &self.plot, &self.mesh);
        let outcome = respond(cx, &NAMES, &op, to)?;
        Ok(with_env_warnings(
            outcome.with_script_warnings(&self.script, script.as_ref()),
            &env,
        ))
    }
}

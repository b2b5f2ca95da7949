//! `cagd surface`: a surface given as an expression in `u` and `v`, sampled on a grid
//! ([`cagd_ops::ops::SurfaceSamples`]; the expression is evaluated here, where the request asks).

use std::cell::RefCell;
use std::rc::Rc;

use cagd::grid::PointGrid;
use cagd::limits::Limits;
use cagd_octave::literal::{Env, LiteralScalar, ParamExpr};
use cagd_ops::curves::Work;
use cagd_ops::ops::{SurfaceEvaluator, SurfaceSamples};
use cagd_ops::{Kind, OpError, Role};
use clap::Args;

use super::answer::{respond, Destinations};
use super::expr_curve::{env_warnings, expression_env};
use super::read::surface_params;
use super::run::{Names, Run};
use super::work::Sampling;
use crate::args::{MeshArgs, OutputArgs, PlotArgs, ScriptArgs, SurfaceParamArgs};
use crate::cx::Cx;
use crate::{load_expression, CliError, Outcome};

/// The form of a surface expression.
const SURFACE_FORM: &str = "an expression in u and v such as \"[u; v; u.*v]\"";

/// Sample a surface given as an expression in u and v on a grid.
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: the result is a grid of shape (nu, nv, d): result(i,j,:) is the point at (u(i), v(j)),
like P in the thesis's ploskevB.

Examples:
  cagd surface \"[u; v; u.*v]\" --n 3
  cagd surface \"[u; v; u-u^2+v]\" --n 20 --plot patch.png --mesh patch.stl")]
pub struct SurfaceCommand {
    /// The surface: an expression in u and v, e.g. "[u; v; u.*v]".
    #[arg(value_name = "EXPR", allow_hyphen_values = true)]
    pub expr: String,
    #[command(flatten)]
    pub params: SurfaceParamArgs,
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
    input: "EXPR",
    special: &[(Role::Control, "EXPR")],
};

impl Run for SurfaceCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let expr = load_expression(cx, "EXPR", &self.expr, script.as_ref())?;
        let env = expression_env(cx.limits, script.as_ref());
        let surface = ExprSurface {
            expr,
            env: env.clone(),
            limits: cx.limits,
        };
        let op = SurfaceSamples {
            at: surface_params(cx, &self.params)?,
            drawing: self.plot.plot.is_some(),
            mesh: self.mesh.mesh.is_some(),
            ..SurfaceSamples::new(Box::new(surface), &self.expr)
        };
        let to = Destinations::surface(&self.output, &self.plot, &self.mesh);
        let mut outcome =
            respond(cx, &NAMES, &op, to)?.with_script_warnings(&self.script, script.as_ref());
        outcome.warnings.extend(env_warnings("EXPR", &env));
        Ok(outcome)
    }
}

/// An expression in `u` and `v`, evaluated in a shared environment (whose warnings the
/// command reports afterwards).
struct ExprSurface<T: LiteralScalar> {
    expr: ParamExpr,
    env: Rc<RefCell<Env<T>>>,
    limits: Limits,
}

impl<T: LiteralScalar> SurfaceEvaluator<T> for ExprSurface<T> {
    fn grid(&self, us: &[T], vs: &[T]) -> cagd_ops::Result<PointGrid<T>> {
        let mut env = self.env.borrow_mut();
        self.expr.sample_surface(&mut env, us, vs).map_err(|e| {
            OpError::new(Role::Result, Kind::Value, e.to_string(), SURFACE_FORM).caused_by(e)
        })
    }

    fn work(&self, us: &[T], vs: &[T]) -> Work {
        let sampling = Sampling {
            expr: &self.expr,
            params: vec![("u", us), ("v", vs)],
        };
        sampling.work(&self.env.borrow(), &self.limits)
    }
}

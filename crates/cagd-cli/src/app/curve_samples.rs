//! `cagd curve`: a curve given as an expression in its parameter, as the thesis writes curves,
//! sampled ([`cagd_ops::ops::CurveSamples`]; the expression is evaluated here, where the request
//! asks).

use cagd_octave::literal::{Env, LiteralScalar, ParamExpr};
use cagd_ops::ops::CurveSamples;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::common::shape;
use super::cx::Cx;
use super::expr_curve::{env_warnings, expression_env, ExprCurve, CURVE_FORM};
use super::read::curve_params;
use super::run::{Names, Run};
use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, ScriptArgs};
use crate::{load_expression, CliError, Outcome};

/// Sample a curve given as an expression in its parameter, as the thesis writes curves.
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: the result is d × k, one point per column (like T in the thesis's deCasteljau).

Examples:
  cagd curve \"[u; 0; u-u^2]\" --n 5
  cagd curve \"[u; 0.5; 0.5+u-u^2]\" --t \"[0 0.25 0.5]\" --exact
  cagd curve \"[cos(2*pi*t); sin(2*pi*t)]\" --n 50 --plot circle.svg")]
pub struct CurveCommand {
    /// The curve: an expression in one parameter t, u or v, e.g. "[u; 0; u-u^2]".
    #[arg(value_name = "EXPR", allow_hyphen_values = true)]
    pub expr: String,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub script: ScriptArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "EXPR",
    special: &[(Role::Control, "EXPR")],
};

impl Run for CurveCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let expr = load_expression(&cx.limits, "EXPR", &self.expr, script.as_ref())?;
        let env = expression_env(cx.limits, script.as_ref());
        let param = self.parameter(&expr, &env.borrow())?;
        let curve = ExprCurve::new(expr, param, env.clone(), cx.limits, CURVE_FORM);
        let op = CurveSamples {
            t: curve_params(cx, &self.params)?,
            drawing: self.plot.plot.is_some(),
            ..CurveSamples::new(Box::new(curve), param, &self.expr)
        };
        let to = Destinations {
            output: &self.output,
            plot: self.plot.plot.as_deref(),
            mesh: None,
        };
        let mut outcome =
            respond(cx, &NAMES, &op, to)?.with_script_warnings(&self.script, script.as_ref());
        outcome.warnings.extend(env_warnings("EXPR", &env));
        Ok(outcome)
    }
}

impl CurveCommand {
    /// The expression's one parameter (`t` if it has none).
    fn parameter<T: LiteralScalar>(
        &self,
        expr: &ParamExpr,
        env: &Env<T>,
    ) -> Result<&'static str, CliError> {
        match expr.parameters(env).as_slice() {
            [] => Ok("t"),
            [p] => Ok(p),
            params => Err(shape(
                "EXPR",
                format!(
                    "`{}` uses the parameters {}",
                    self.expr.trim(),
                    params.join(" and ")
                ),
                "a curve in one parameter (t, u or v); use `cagd surface` for u and v",
            )),
        }
    }
}

//! `cagd coons`: the Coons patch of four boundary curves.

use std::cell::RefCell;
use std::rc::Rc;

use cagd_octave::literal::{Env, LiteralScalar, ParamExpr};
use cagd_ops::ops::coons::BLEND_FORM;
use cagd_ops::ops::{Blend, Coons};
use clap::Args;

use super::answer::{respond, Destinations};
use super::boundary::{boundary, script_corners, BoundaryArgs};
use super::expr_curve::{env_warnings, expression_env, ExprCurve};
use super::read::surface_params;
use super::run::{Names, Run};
use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// A bilinearly blended Coons patch x = r_c + r_d - r_cd (thesis 4.1, algorithms 5, 6).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --c1 x(u,0), --c2 x(u,1) (expressions in u), --d1 x(0,v), --d2 x(1,v) (in v), as the
thesis writes them, e.g. \"[u;0;u-u^2]\"; a constant matrix or data file instead gives the
control points (columns) of a Bézier curve; bezier(P), bspline(P, U) and nurbs(P, W, U) give a
Bézier, B-spline or NURBS curve (P control points as columns, U the knots, W the weights; the
curve's domain is mapped onto [0, 1]). Or --script FILE: the appendix C data script (sampled
c1, c2, d1, d2 and corners P1..P4); --n binds its N. A script's matrix named in a curve
argument (--c1 c1) is read as Bézier control points, with a warning; --samples reads it as
samples of the curve, as appendix C means. --blend linear|hermite|EXPR chooses the blending
functions of thesis (4.4) (hermite: the partially bicubic patch of §4.2).
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3 (like P), or with
--list one row u v x y z per point. --steps also prints rc, rd, rcd (same layout). --plot draws
the surface with c1, c2 in red and d1, d2 in green, as appendix C does.

Examples:
  cagd coons --c1 \"[u;0;u-u^2]\" --c2 \"[u;1;u]\" --d1 \"[0;v^2;v-v^2]\" --d2 \"[1;v;v]\" --u 0.2 --v 0.5 --steps --exact
  cagd coons --c1 \"bspline([0 1 2 3 4; 0 0 0 0 0; 0 1 0 1 0], [0 0 0 1 2 3 3 3])\" --c2 \"[4*u; 1; 0]\" --d1 \"[0; v; 0]\" --d2 \"[4; v; 0]\" --u 0.5 --v 0 --exact
  cagd coons --script appendix_c.m --n 10 --plot coons.png --mesh coons.obj")]
pub struct CoonsCommand {
    #[command(flatten)]
    pub boundary: BoundaryArgs,
    /// The blending functions (thesis (4.4)) in u and v: linear (1 − t, t), the bilinear patch
    /// (default); hermite (H0³, H3³), the partially bicubic patch of §4.2; or f1 as an
    /// expression in t (f2 = 1 − f1), or a pair "[f1; f2]". They must satisfy f1(0) = 1,
    /// f1(1) = 0 and f1 + f2 = 1 (checked at t = k/32).
    #[arg(long, value_name = "linear|hermite|EXPR", allow_hyphen_values = true)]
    pub blend: Option<String>,
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
    input: "--c1/--c2/--d1/--d2",
    special: &[],
};

impl Run for CoonsCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let env = expression_env(cx.limits, script.as_ref());
        let op = Coons {
            boundary: boundary(cx, &self.boundary, script.as_ref(), self.rows.rows, &env)?,
            corners: script_corners(&self.boundary, script.as_ref()),
            blend: blend(cx, self.blend.as_deref(), &env)?,
            at: surface_params(cx, &self.params)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
            mesh: self.mesh.mesh.is_some(),
        };
        let to = Destinations::surface(&self.output, &self.plot, &self.mesh);
        let mut outcome =
            respond(cx, &NAMES, &op, to)?.with_script_warnings(&self.script, script.as_ref());
        outcome.warnings.extend(env_warnings("expression", &env));
        Ok(outcome)
    }
}

/// The blending functions of `--blend`.
fn blend<T: LiteralScalar>(
    cx: &Cx,
    text: Option<&str>,
    env: &Rc<RefCell<Env<T>>>,
) -> Result<Blend<T>, CliError> {
    let text = match text.map(str::trim) {
        None | Some("linear") => return Ok(Blend::Linear),
        Some("hermite") => return Ok(Blend::Hermite),
        Some(t) => t,
    };
    let expr = ParamExpr::parse_with(text, &cx.limits)
        .map_err(|e| CliError::literal("--blend", e, BLEND_FORM))?;
    let params = expr.parameters(&env.borrow());
    let name = match params.as_slice() {
        [] => "t",
        [p] => *p,
        _ => {
            return Err(super::common::shape(
                "--blend",
                format!("`{text}` uses the parameters {}", params.join(" and ")),
                BLEND_FORM,
            ))
        }
    };
    Ok(Blend::Custom(Box::new(ExprCurve::new(
        expr,
        name,
        env.clone(),
        cx.limits,
        BLEND_FORM,
    ))))
}

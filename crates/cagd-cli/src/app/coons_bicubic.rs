//! `cagd coons-bicubic`: the bicubically blended Coons patch with cross-boundary derivatives.

use std::cell::RefCell;
use std::rc::Rc;

use cagd_octave::literal::{Env, LiteralScalar};
use cagd_octave::script::Script;
use cagd_ops::curves::CurveArg;
use cagd_ops::ops::{CoonsBicubic, TwistChoice};
use clap::{Args, ValueEnum};

use super::answer::{respond, Destinations};
use super::boundary::{boundary, BoundaryArgs};
use super::common::usage;
use super::curve_arg::{curve_arg, Reading};
use super::expr_curve::{expression_env, with_env_warnings};
use super::read::{points, surface_params};
use super::run::{Names, Run};
use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// The corner twists of `--twist`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Twist {
    /// All four corner twists zero.
    Zero,
    /// Gregory's square from the derivatives of the cross-boundary curves.
    Gregory,
    /// Given with --twists.
    Given,
}

/// A bicubically blended Coons patch with cross-boundary derivatives (thesis 4.3).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: the boundaries as for coons, and the cross-boundary derivative curves --c1v x_v(u,0),
--c2v x_v(u,1) (in u), --d1u x_u(0,v), --d2u x_u(1,v) (in v): expressions, Bézier control
points, or bezier(P), bspline(P, U), nurbs(P, W, U) (each curve's domain mapped onto [0, 1]);
every curve is used with its derivative (an expression's is found symbolically). --twist
zero|gregory|given chooses the corner twists x_uv (given: --twists, a d×4 matrix for P1..P4;
gregory: Gregory's square from the derivatives of the cross-boundary curves).
Layout: as for coons; --steps prints the three parts of thesis (4.5): hc (the curves in v
blended along u), hd (the curves in u blended along v) and hcd (the corner data), x = hc + hd − hcd.

Examples:
  cagd coons-bicubic --c1 \"[u;0;0]\" --c2 \"[u;1;0]\" --d1 \"[0;v;0]\" --d2 \"[1;v;0]\" --c1v \"[0;1;0]\" --c2v \"[0;1;0]\" --d1u \"[1;0;0]\" --d2u \"[1;0;0]\" --n 5
  cagd coons-bicubic --c1 \"bspline([0 1 2; 0 0 0; 0 0 0], [0 0 1 2 2])\" --c2 \"bspline([0 1 2; 1 1 1; 0 1 2], [0 0 1 2 2])\" \\
          --d1 \"[0 0; 0 1; 0 0]\" --d2 \"[1 1; 0 1; 0 1]\" --c1v \"[0 0; 1 1; 0 1]\" --c2v \"[0 0; 1 1; 0 1]\" \\
          --d1u \"[1 1; 0 0; 0 1]\" --d2u \"[1 1; 0 0; 0 1]\" --twist gregory --u 0.5 --v 0.25 --exact")]
pub struct CoonsBicubicCommand {
    #[command(flatten)]
    pub boundary: BoundaryArgs,
    /// x_v(u,0), the derivative across c1: an expression in u, Bézier control points, or
    /// bezier(P), bspline(P, U), nurbs(P, W, U).
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub c1v: Option<String>,
    /// x_v(u,1), across c2, in u.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub c2v: Option<String>,
    /// x_u(0,v), across d1, in v.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub d1u: Option<String>,
    /// x_u(1,v), across d2, in v.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub d2u: Option<String>,
    /// The corner twists x_uv.
    #[arg(long, value_enum, default_value_t = Twist::Zero)]
    pub twist: Twist,
    /// With --twist given: the twists at P1..P4 = (0,0),(1,0),(0,1),(1,1) as the columns of
    /// a d×4 matrix.
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub twists: Option<String>,
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

impl Run for CoonsBicubicCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let env = expression_env(cx.limits, script.as_ref());
        let op = CoonsBicubic {
            boundary: boundary(cx, &self.boundary, script.as_ref(), self.rows.rows, &env)?,
            cross: self.cross(cx, script.as_ref(), &env)?,
            twist: self.twist(cx, script.as_ref())?,
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

impl CoonsBicubicCommand {
    /// The cross-boundary curves `[c1v, c2v, d1u, d2u]`, all four required (asked for in the
    /// order d1u, d2u, c1v, c2v).
    fn cross<T: LiteralScalar>(
        &self,
        cx: &mut Cx,
        script: Option<&Script<T>>,
        env: &Rc<RefCell<Env<T>>>,
    ) -> Result<[CurveArg<T>; 4], CliError> {
        let given = [
            ("--d1u", &self.d1u),
            ("--d2u", &self.d2u),
            ("--c1v", &self.c1v),
            ("--c2v", &self.c2v),
        ];
        let how = Reading {
            script,
            rows: self.rows.rows,
            samples: None,
        };
        let mut curves = Vec::with_capacity(4);
        for (argument, text) in given {
            let text = text.as_deref().ok_or_else(|| {
                usage(
                    argument,
                    "missing",
                    "a cross-boundary derivative curve (expression, Bézier control points, bezier(P), bspline(P, U), nurbs(P, W, U)); all of --c1v --c2v --d1u --d2u",
                )
            })?;
            curves.push(curve_arg(cx, argument, text, how, env)?);
        }
        let [d1u, d2u, c1v, c2v]: [CurveArg<T>; 4] = curves
            .try_into()
            .map_err(|_| usage("--c1v", "not four curves", "four cross-boundary curves"))?;
        Ok([c1v, c2v, d1u, d2u])
    }

    /// The twist choice, with the matrix of `--twists` for `given`.
    fn twist<T: LiteralScalar>(
        &self,
        cx: &mut Cx,
        script: Option<&Script<T>>,
    ) -> Result<TwistChoice<T>, CliError> {
        Ok(match self.twist {
            Twist::Zero => TwistChoice::Zero,
            Twist::Gregory => TwistChoice::Gregory,
            Twist::Given => {
                let text = self.twists.as_deref().ok_or_else(|| {
                    usage(
                        "--twists",
                        "missing with --twist given",
                        "a d×4 matrix of corner twists",
                    )
                })?;
                TwistChoice::Given(points(cx, "--twists", text, script, self.rows.rows)?)
            }
        })
    }
}

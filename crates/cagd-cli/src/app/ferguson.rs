//! `cagd ferguson`: the Hermite bicubic (Ferguson) patch of the lecture notes ("Hermitova
//! plocha") from its corner points, tangents and twists, or from four boundary curves.

use std::cell::RefCell;
use std::rc::Rc;

use cagd_octave::literal::{Env, LiteralScalar};
use cagd_octave::script::Script;
use cagd_ops::curves::CurveArg;
use cagd_ops::ops::{Ferguson, FergusonData};
use cagd_ops::Role;
use clap::Args;
use nalgebra::DMatrix;

use super::answer::{respond, Destinations};
use super::boundary::{boundary, BoundaryArgs};
use super::common::usage;
use super::expr_curve::{expression_env, with_env_warnings};
use super::read::{points, surface_params};
use super::run::{Names, Run};
use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::cx::Cx;
use crate::{CliError, Outcome};

/// The Hermite bicubic (Ferguson) patch from corner points, tangents and twists.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --points, --du, --dv, --twists (default zero: the F-patch): d×4 matrices whose columns
are the vectors at the corners (u,v) = (0,0), (1,0), (0,1), (1,1) (rows with --rows). Or, in
place of --points, --du, --dv, four boundary curves as for coons (--c1 x(u,0), --c2 x(u,1),
--d1 x(0,v), --d2 x(1,v): expressions, Bézier control points, bezier(P), bspline(P, U),
nurbs(P, W, U)), whose ends and end tangents (each domain mapped onto [0, 1]) are the corner
data; the patch's edges are then the Hermite cubics of those data (the curves themselves when
they are cubics).
Layout: single --u and --v give the d×1 point; otherwise the grid nu×nv×d, or --list. --steps
prints the geometry matrices G (one per coordinate, rows x(0,·) x(1,·) x_u(0,·) x_u(1,·),
columns x(·,0) x(·,1) x_v(·,0) x_v(·,1)): x(u,v) = f(u)ᵀ G f(v) with the Hermite basis f. The
lecture notes write vᵀ M_Hᵀ X_H M_H u with X_H = Gᵀ.

Examples (z = uv):
  cagd ferguson --points \"[0 0 0; 1 0 0; 0 1 0; 1 1 1]'\" --du \"[1 0 0; 1 0 0; 1 0 1; 1 0 1]'\" \\
            --dv \"[0 1 0; 0 1 1; 0 1 0; 0 1 1]'\" --twists \"[0 0 1; 0 0 1; 0 0 1; 0 0 1]'\" --u 0.5 --v 0.25 --exact
  cagd ferguson --c1 \"bezier([0 1; 0 0; 0 0])\" --c2 \"bezier([0 1; 1 1; 0 1])\" --d1 \"bezier([0 0; 0 1; 0 0])\" \\
            --d2 \"bezier([1 1; 0 1; 0 1])\" --twists \"[0 0 1; 0 0 1; 0 0 1; 0 0 1]'\" --u 0.5 --v 0.25 --exact")]
pub struct FergusonCommand {
    /// The corner points x(0,0), x(1,0), x(0,1), x(1,1) as the columns of a d×4 matrix.
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub points: Option<String>,
    /// The u-tangents ∂x/∂u at the corners, in the same order (d×4).
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub du: Option<String>,
    /// The v-tangents ∂x/∂v at the corners (d×4).
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub dv: Option<String>,
    /// The twists ∂²x/∂u∂v at the corners (d×4; default zero, the lecture notes' F-patch).
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub twists: Option<String>,
    #[command(flatten)]
    pub boundary: BoundaryArgs,
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
    input: "--points/--du/--dv/--twists",
    special: &[(Role::Points, "--points")],
};

/// The form of a matrix of corner vectors.
const CORNERS: &str = "a d×4 matrix: the vectors at the corners (0,0), (1,0), (0,1), (1,1) as columns (or four boundary curves --c1 --c2 --d1 --d2)";

impl Run for FergusonCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let env = expression_env(cx.limits, script.as_ref());
        let data = self.data(cx, script.as_ref(), &env)?;
        let twists = match &self.twists {
            Some(text) => Some(points(
                cx,
                "--twists",
                text,
                script.as_ref(),
                self.rows.rows,
            )?),
            None => None,
        };
        let op = Ferguson {
            data,
            twists,
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

impl FergusonCommand {
    /// The corner points and tangents: the matrices given, or the four boundary curves.
    fn data<T: LiteralScalar>(
        &self,
        cx: &mut Cx,
        script: Option<&Script<T>>,
        env: &Rc<RefCell<Env<T>>>,
    ) -> Result<FergusonData<T>, CliError> {
        let b = &self.boundary;
        if !(b.samples || [&b.c1, &b.c2, &b.d1, &b.d2].iter().any(|c| c.is_some())) {
            return Ok(FergusonData::Corners {
                points: self.corners(cx, "--points", &self.points, script)?,
                du: self.corners(cx, "--du", &self.du, script)?,
                dv: self.corners(cx, "--dv", &self.dv, script)?,
            });
        }
        let given = [
            ("--points", &self.points),
            ("--du", &self.du),
            ("--dv", &self.dv),
        ];
        if let Some((argument, _)) = given.iter().find(|(_, g)| g.is_some()) {
            return Err(usage(
                argument,
                "has no effect with boundary curves (their ends and tangents are the corner data)",
                "either --points, --du and --dv, or --c1, --c2, --d1 and --d2",
            ));
        }
        let curves: [CurveArg<T>; 4] = boundary(cx, b, script, self.rows.rows, env)?;
        Ok(FergusonData::Boundary(Box::new(curves)))
    }

    /// A matrix of corner vectors (columns, rows with `--rows`), which must be given.
    fn corners<T: LiteralScalar>(
        &self,
        cx: &mut Cx,
        argument: &str,
        given: &Option<String>,
        script: Option<&Script<T>>,
    ) -> Result<DMatrix<T>, CliError> {
        let text = given
            .as_deref()
            .ok_or_else(|| usage(argument, "missing", CORNERS))?;
        points(cx, argument, text, script, self.rows.rows)
    }
}

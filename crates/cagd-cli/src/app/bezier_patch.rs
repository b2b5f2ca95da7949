//! `cagd bezier-patch`: points of a Bézier patch, or of one of its partial derivatives.

use cagd::grid::PointGrid;
use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::BezierPatchPoints;
use cagd_ops::Role;
use clap::Args;

use super::answer::{respond, Destinations};
use super::common::{coordinate_net, usage};
use super::read::surface_params;
use super::run::{Names, Run};
use crate::args::{MeshArgs, OutputArgs, PlotArgs, ScriptArgs, StepsArgs, SurfaceParamArgs};
use crate::cx::Cx;
use crate::{load_net, CliError, Outcome};

/// Points of a Bézier patch (thesis algorithms 2-4, ploskevB/bilinearna/tenzor).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: the net packed (m+1)×3(n+1) as ploskevB takes it (row i = [b_i0 b_i1 ... b_in], x y z
side by side), or an Octave save -text file with an (m+1)×(n+1)×3 array.
Instead of NET: --x, --y, --z, the coordinate matrices (m+1)×(n+1) (entry (i,j) of b_ij).
Layout: with single --u and --v, result is the 3×1 point; otherwise result is the grid
nu×nv×3 (result(i,j,:) at (u(i), v(j)), like P in ploskevB), or with --list one row u v x y z
per point. --steps prints the tensor de Casteljau scheme for each (u, v). --du R --dv S give
the partial derivative ∂^(R+S)x/∂u^R∂v^S (thesis Trditev 3.3; --du 1 --dv 1 the twist): its
values as result and its net as net.

Examples:
  cagd bezier-patch \"[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0]\" --u 0.5 --v 0.5 --steps
  cagd bezier-patch net.txt --n 20 --plot patch.png --mesh patch.stl")]
pub struct BezierPatchCommand {
    /// The control net: packed (m+1)×3(n+1) like ploskevB's input (row i = [b_i0 b_i1 …
    /// b_in], each point's x y z side by side), or an Octave save -text file holding an
    /// (m+1)×(n+1)×3 array (FILE or FILE.txt:NAME).
    #[arg(value_name = "NET", allow_hyphen_values = true)]
    pub net: Option<String>,
    /// Instead of NET: the x coordinates of the control points as an (m+1)×(n+1) matrix,
    /// entry (i, j) of b_ij (i along u). The lecture notes' X_B, with x(u,v) = vᵀM_BᵀX_BM_Bu,
    /// has its rows along v: pass its transpose.
    #[arg(
        long,
        value_name = "MATRIX",
        allow_hyphen_values = true,
        conflicts_with = "net"
    )]
    pub x: Option<String>,
    /// The y coordinates (with --x), as --x.
    #[arg(
        long,
        value_name = "MATRIX",
        allow_hyphen_values = true,
        requires = "x"
    )]
    pub y: Option<String>,
    /// The z coordinates (with --x and --y), as --x.
    #[arg(
        long,
        value_name = "MATRIX",
        allow_hyphen_values = true,
        requires = "y"
    )]
    pub z: Option<String>,
    /// Differentiate R times along u: the partial derivative patch (thesis Trditev 3.3),
    /// whose net is printed as `net`.
    #[arg(long, value_name = "R", default_value_t = 0)]
    pub du: usize,
    /// Differentiate S times along v (--du 1 --dv 1 is the twist x_uv).
    #[arg(long, value_name = "S", default_value_t = 0)]
    pub dv: usize,
    #[command(flatten)]
    pub params: SurfaceParamArgs,
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
    input: "NET",
    special: &[(Role::DerivativeOrder, "--du/--dv")],
};

impl Run for BezierPatchCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let op = BezierPatchPoints {
            net: self.net(cx, script.as_ref())?,
            du: self.du,
            dv: self.dv,
            at: surface_params(cx, &self.params)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
            mesh: self.mesh.mesh.is_some(),
        };
        let to = Destinations::surface(&self.output, &self.plot, &self.mesh);
        respond(cx, &NAMES, &op, to).map(|o| o.with_script_warnings(&self.script, script.as_ref()))
    }
}

impl BezierPatchCommand {
    /// The net of NET, or of the coordinate matrices --x, --y, --z.
    fn net<T: LiteralScalar>(
        &self,
        cx: &mut Cx,
        script: Option<&cagd_octave::script::Script<T>>,
    ) -> Result<PointGrid<T>, CliError> {
        match (&self.net, &self.x) {
            (Some(text), _) => load_net::<T>(cx, "NET", text, script),
            (None, Some(_)) => coordinate_net(cx, [&self.x, &self.y, &self.z], script),
            (None, None) => Err(usage(
                "NET",
                "missing",
                "a control net NET, or its coordinate matrices --x, --y (and --z)",
            )),
        }
    }
}

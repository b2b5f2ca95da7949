//! `bezier-patch`.

use cagd::limits::Limits;
use clap::Args;

use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::plot::{Colour, Figure};
use crate::{load_net, CliError, PendingWrites, Report, Value};
use cagd::bezier::BezierPatch;
use cagd_octave::literal::{Env, LiteralScalar};

use super::common::*;
use super::work::{bits, check_work, weigh};
use super::{prepare_script, Outcome};

/// The interval `a,b` of `--interval` (default `[0, 1]`).
pub fn interval<T: LiteralScalar>(
    limits: &Limits,
    given: &Option<String>,
) -> Result<(T, T), CliError> {
    let Some(text) = given else {
        return Ok((T::zero(), T::one()));
    };
    let form = "two numbers a,b with a < b, e.g. --interval 2,5";
    let inner = text.trim().trim_start_matches('[').trim_end_matches(']');
    // Not load_params: the comma between a and b is not a decimal comma.
    let values: Vec<T> = cagd_octave::literal::parse_params_with(&format!("[{inner}]"), limits)
        .map_err(|e| crate::CliError::literal("--interval", e, form))?;
    match values.as_slice() {
        [a, b] if a < b => Ok((a.clone(), b.clone())),
        _ => Err(shape(
            "--interval",
            format!("`{}` is not an interval a < b", text.trim()),
            form,
        )),
    }
}

/// How much more `--steps` costs than the points alone: each scheme is computed again and
/// written out, about as many numbers as operations (`(n+1)(n+2)/2` points of a curve's
/// scheme), each number some 50 operations to format and about 16 bytes of text. So a
/// command whose schemes would fill gigabytes of memory (a 10⁷-point grid of 3×3-net schemes
/// is 6.6 GB of text) is refused up front like any other large work.
const STEPS_FACTOR: u128 = 50;

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

/// Whether `--u` and `--v` ask for one point.
pub fn point_mode(limits: &Limits, params: &SurfaceParamArgs) -> bool {
    let single = |s: &Option<String>| {
        s.as_ref().is_some_and(|t| {
            cagd_octave::literal::parse_params_with::<f64>(t, limits).is_ok_and(|v| v.len() == 1)
        })
    };
    params.n.is_none() && single(&params.u) && single(&params.v)
}

/// Points of a Bézier patch (thesis algorithms 2–4, `ploskevB`, `bilinearna`, `tenzor`).
pub fn bezier_patch<T: LiteralScalar>(
    limits: &Limits,
    cmd: &BezierPatchCommand,
) -> Result<Outcome, CliError> {
    let script = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let net = match (&cmd.net, &cmd.x) {
        (Some(text), _) => load_net::<T>(limits, "NET", text, script.as_ref())?,
        (None, Some(_)) => coordinate_net(limits, [&cmd.x, &cmd.y, &cmd.z], script.as_ref())?,
        (None, None) => {
            return Err(usage(
                "NET",
                "missing",
                "a control net NET, or its coordinate matrices --x, --y (and --z)",
            ))
        }
    };
    let (m1, n1, _) = net.dim();
    check_degree(limits, "NET", m1.max(n1).saturating_sub(1))?;
    let patch = BezierPatch::from_grid(&net).map_err(lib(
        "NET",
        "a packed (m+1)×3(n+1) control net as ploskevB takes it",
    ))?;
    let differentiated = cmd.du > 0 || cmd.dv > 0;
    let patch = if differentiated {
        patch.derivative(cmd.du, cmd.dv).map_err(lib(
            "--du/--dv",
            "orders R ≤ m and S ≤ n (the degrees of the patch)",
        ))?
    } else {
        patch
    };
    let net = if differentiated { patch.to_grid() } else { net };
    let us: Vec<T> =
        params_or_samples(limits, "--u", &cmd.params.u, cmd.params.n, DEFAULT_SAMPLES)?;
    let vs: Vec<T> =
        params_or_samples(limits, "--v", &cmd.params.v, cmd.params.n, DEFAULT_SAMPLES)?;
    check_grid(limits, us.len(), vs.len())?;
    crate::slips::outside(
        "--u",
        &us,
        &T::zero(),
        &T::one(),
        "the patch is extrapolated there",
    );
    crate::slips::outside(
        "--v",
        &vs,
        &T::zero(),
        &T::one(),
        "the patch is extrapolated there",
    );
    let single = point_mode(limits, &cmd.params);
    let picture: Vec<T> = T::linspace(&T::zero(), &T::one(), 21);
    // The grid (BezierPatch::grid_cost per point); --steps adds a tensor de Casteljau scheme
    // per point (BezierPatch::scheme_cost), STEPS_FACTOR times for writing it out; the
    // 21 × 21 picture of a single point is a grid.
    let coefficients = bits(net.iter());
    let grid_work = |us: &[T], vs: &[T], steps: bool| {
        let (u_bits, v_bits) = (bits(us), bits(vs));
        let mut per = patch.grid_cost(u_bits, v_bits, coefficients);
        if steps {
            per = per.and(
                patch
                    .scheme_cost(u_bits, v_bits, coefficients)
                    .times(STEPS_FACTOR),
            );
        }
        weigh::<T>(per.times(us.len() as u128 * vs.len() as u128))
    };
    let pictures = single && (cmd.plot.plot.is_some() || cmd.mesh.mesh.is_some());
    let picture = if pictures { picture } else { Vec::new() };
    check_work(
        limits,
        "--u/--v",
        grid_work(&us, &vs, cmd.steps.steps).saturating_add(grid_work(&picture, &picture, false)),
    )?;
    let grid = patch
        .try_eval_grid(&us, &vs)
        .map_err(lib("--u/--v", "finite parameter values"))?;
    let mut report = Report::new();
    if cmd.steps.steps {
        let mut k = 0;
        for u in &us {
            for v in &vs {
                k += 1;
                let name = if single {
                    "scheme".to_string()
                } else {
                    format!("scheme_{k}")
                };
                report.push(
                    name,
                    super::scheme::patch_scheme(&patch.scheme(u.clone(), v.clone())),
                );
            }
        }
    }
    if differentiated {
        report.push("net", Value::Grid(net.clone()));
    }
    report.push("u", Value::Matrix(row(&us)));
    report.push("v", Value::Matrix(row(&vs)));
    if single && !cmd.params.list {
        report.push(
            "result",
            Value::Matrix(column(&patch.eval(us[0].clone(), vs[0].clone()))),
        );
    } else {
        push_surface(
            &mut report,
            "result",
            (&us, &vs),
            grid.clone(),
            cmd.params.list,
        );
    }
    let mut files = PendingWrites::new();
    let picture_grid = if pictures {
        patch
            .try_eval_grid(&picture, &picture)
            .map_err(lib("--plot", "a patch"))?
    } else {
        grid
    };
    if let Some(path) = &cmd.plot.plot {
        let figure = Figure::new("Bézier patch")
            .surface(grid_f64(&picture_grid), "patch")
            .net(grid_f64(&net), Colour::Red, "control net");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    if let Some(path) = &cmd.mesh.mesh {
        add_mesh(&mut files, "--mesh", path, &grid_f64(&picture_grid))?;
    }
    finish(
        &report,
        &cmd.output,
        files,
        warnings(
            &cmd.script.script,
            script.as_ref(),
            &mut Env::with_limits(*limits),
        ),
    )
}

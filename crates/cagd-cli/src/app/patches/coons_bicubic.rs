//! `coons-bicubic`: the bicubically blended Coons patch with cross-boundary derivatives.

use cagd::limits::Limits;
use clap::{Args, ValueEnum};

use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::{CliError, Report, Value};
use cagd::coons::{bicubic_point_cost, BicubicCoonsPatch, CoonsBoundary, CrossDerivatives, Twist};
use cagd::{Curve, Tolerance};
use cagd_octave::literal::LiteralScalar;

use super::super::bezier::point_mode;
use super::super::common::*;
use super::super::curve::curve_costs;
use super::super::work::{bits, check_work, weigh};
use super::super::{prepare_script, Outcome};

use super::*;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TwistChoice {
    /// All four corner twists zero.
    Zero,
    /// Gregory's square from the derivatives of the cross-boundary curves (needs Bézier
    /// cross-boundary curves).
    Gregory,
    /// Given with --twists.
    Given,
}

/// A bicubically blended Coons patch with cross-boundary derivatives (thesis 4.3).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: the boundaries as for coons, and the cross-boundary derivative curves --c1v x_v(u,0),
--c2v x_v(u,1) (in u), --d1u x_u(0,v), --d2u x_u(1,v) (in v). --twist zero|gregory|given
chooses the corner twists x_uv (given: --twists, a d×4 matrix for P1..P4; gregory needs
Bézier cross-boundary curves, whose derivatives it uses).
Layout: as for coons; --steps prints the three parts of thesis (4.5): hc (the curves in v
blended along u), hd (the curves in u blended along v) and hcd (the corner data), x = hc + hd − hcd.

Example:
  cagd coons-bicubic --c1 \"[u;0;0]\" --c2 \"[u;1;0]\" --d1 \"[0;v;0]\" --d2 \"[1;v;0]\" --c1v \"[0;1;0]\" --c2v \"[0;1;0]\" --d1u \"[1;0;0]\" --d2u \"[1;0;0]\" --n 5")]
pub struct CoonsBicubicCommand {
    #[command(flatten)]
    pub boundary: BoundaryArgs,
    /// x_v(u,0), the derivative across c1: an expression in u or Bézier control points.
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
    #[arg(long, value_enum, default_value_t = TwistChoice::Zero)]
    pub twist: TwistChoice,
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

/// The bicubically blended Coons patch (thesis §4.3).
pub fn coons_bicubic<T: LiteralScalar>(
    limits: &Limits,
    cmd: &CoonsBicubicCommand,
) -> Result<Outcome, CliError> {
    let script = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let mut env = script.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let sources = boundary_sources(limits, &cmd.boundary, script.as_ref(), cmd.rows.rows, &env)?;
    let single = point_mode(limits, &cmd.params);
    let (us, vs) = surface_params(limits, &cmd.params, (None, None))?;
    let (pictures, pus, pvs) = picture_params((&us, &vs), single, &cmd.plot, &cmd.mesh);
    let at_u = needed(&[&us, &pus]);
    let at_v = needed(&[&vs, &pvs]);
    let mut cross = Vec::with_capacity(4);
    for (arg, given, at) in [
        ("--d1u", &cmd.d1u, &at_v),
        ("--d2u", &cmd.d2u, &at_v),
        ("--c1v", &cmd.c1v, &at_u),
        ("--c2v", &cmd.c2v, &at_u),
    ] {
        let text = given.as_ref().ok_or_else(|| {
            usage(
                arg,
                "missing",
                "a cross-boundary derivative curve (expression or Bézier control points); all of --c1v --c2v --d1u --d2u",
            )
        })?;
        let source = load_curve(limits, arg, text, script.as_ref(), cmd.rows.rows, &env)?;
        cross.push((arg, source, at.as_slice()));
    }
    // All eight curves are estimated together, before any is sampled.
    let mut parts = boundary_parts(&sources, &at_u, &at_v);
    parts.extend(cross.iter().map(|(arg, s, at)| (*arg, s, *at)));
    let mut curves = build_curves(limits, &parts, &mut env)?;
    // Cubic Hermite blending of eight curves and four twists: about 64 operations per
    // coordinate and point, with blending functions cubic in u and v.
    let uv_curves: Vec<(&CliCurve<T>, &[T])> = curves
        .iter()
        .enumerate()
        .map(|(k, c)| {
            (
                c,
                if matches!(k, 0 | 1 | 6 | 7) {
                    &at_u[..]
                } else {
                    &at_v[..]
                },
            )
        })
        .collect();
    let per_point = bicubic_point_cost(
        curve_costs(&uv_curves),
        curves[0].dim(),
        bits(&at_u),
        bits(&at_v),
    );
    check_work(
        limits,
        "--u/--v",
        weigh::<T>(per_point.times(evaluated_points((&us, &vs), pictures, (&pus, &pvs)))),
    )?;
    let [du0, du1, dv0, dv1] = four(curves.split_off(4));
    let [c1, c2, d1, d2] = four(curves);
    let twist = match cmd.twist {
        TwistChoice::Zero => Twist::Zero,
        TwistChoice::Gregory => Twist::Gregory,
        TwistChoice::Given => {
            let text = cmd.twists.as_ref().ok_or_else(|| {
                usage(
                    "--twists",
                    "missing with --twist given",
                    "a d×4 matrix of corner twists",
                )
            })?;
            let m = points(limits, "--twists", text, script.as_ref(), cmd.rows.rows)?;
            if m.ncols() != 4 {
                return Err(shape(
                    "--twists",
                    format!("a {}×{} matrix", m.nrows(), m.ncols()),
                    "a d×4 matrix, the twists at P1..P4 as columns",
                ));
            }
            let col = |k: usize| m.column(k).into_owned();
            Twist::Given([col(0), col(1), col(2), col(3)])
        }
    };
    let boundary = CoonsBoundary::new(
        c1.clone(),
        c2.clone(),
        d1.clone(),
        d2.clone(),
        Tolerance::default(),
    )
    .map_err(lib(
        "--c1/--c2/--d1/--d2",
        "four boundary curves that meet at the corners",
    ))?;
    let patch = BicubicCoonsPatch::new(boundary, CrossDerivatives { du0, du1, dv0, dv1 }, twist)
        .map_err(lib(
            "--c1v/--c2v/--d1u/--d2u",
            "cross-boundary derivatives that agree with the boundary tangents at the corners (Gregory twists need Bézier cross-boundary curves)",
        ))?;
    let mut report = Report::new();
    report.push("u", Value::Matrix(row(&us)));
    report.push("v", Value::Matrix(row(&vs)));
    push_terms(
        &mut report,
        ["hc", "hd", "hcd"],
        (cmd.steps.steps, cmd.params.list),
        (&us, &vs),
        single,
        c1.dim(),
        |u, v| {
            let p = patch.eval_parts(u, v);
            [p.hc, p.hd, p.hcd, p.x]
        },
    );
    coons_outcome(
        "bicubic Coons patch",
        &patch,
        [&c1, &c2, &d1, &d2],
        (&pus, &pvs),
        (&cmd.plot, &cmd.mesh, &cmd.output),
        &report,
        warnings(&cmd.script.script, script.as_ref(), &mut env),
    )
}

//! `coons`: the bilinearly (or otherwise) blended Coons patch of four boundary curves.

use cagd::limits::Limits;
use clap::Args;

use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::{CliError, Report, Value};
use cagd::coons::coons_point_cost;
use cagd::Curve;
use cagd_octave::literal::LiteralScalar;

use super::super::bezier::point_mode;
use super::super::common::*;
use super::super::curve::curve_costs;
use super::super::work::{bits, check_work, weigh};
use super::super::{prepare_script, Outcome};

use super::*;

/// A bilinearly blended Coons patch x = r_c + r_d - r_cd (thesis 4.1, algorithms 5, 6).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --c1 x(u,0), --c2 x(u,1) (expressions in u), --d1 x(0,v), --d2 x(1,v) (in v), as the
thesis writes them, e.g. \"[u;0;u-u^2]\"; a constant matrix or data file instead gives the
control points (columns) of a Bézier curve. Or --script FILE: the appendix C data script
(sampled c1, c2, d1, d2 and corners P1..P4); --n binds its N. A script's matrix named in a
curve argument (--c1 c1) is read as Bézier control points, with a warning; --samples reads it
as samples of the curve, as appendix C means. --blend linear|hermite|EXPR chooses the blending
functions of thesis (4.4) (hermite: the partially bicubic patch of §4.2).
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3 (like P), or with
--list one row u v x y z per point. --steps also prints rc, rd, rcd (same layout). --plot draws
the surface with c1, c2 in red and d1, d2 in green, as appendix C does.

Examples:
  cagd coons --c1 \"[u;0;u-u^2]\" --c2 \"[u;1;u]\" --d1 \"[0;v^2;v-v^2]\" --d2 \"[1;v;v]\" --u 0.2 --v 0.5 --steps --exact
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

/// The bilinearly blended Coons patch (thesis §4.1, algorithms 5 and 6).
pub fn coons<T: LiteralScalar>(limits: &Limits, cmd: &CoonsCommand) -> Result<Outcome, CliError> {
    let script = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let mut env = script.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let sources = boundary_sources(limits, &cmd.boundary, script.as_ref(), cmd.rows.rows, &env)?;
    let single = point_mode(limits, &cmd.params);
    let (us, vs) = surface_params(
        limits,
        &cmd.params,
        (sources[0].sample_params(), sources[2].sample_params()),
    )?;
    let (pictures, pus, pvs) = picture_params((&us, &vs), single, &cmd.plot, &cmd.mesh);
    let at_u = needed(&[&us, &pus]);
    let at_v = needed(&[&vs, &pvs]);
    let [c1, c2, d1, d2] = four(build_curves(
        limits,
        &boundary_parts(&sources, &at_u, &at_v),
        &mut env,
    )?);
    let expected = "four boundary curves that meet at the corners: c1(0)=d1(0), c1(1)=d2(0), c2(0)=d1(1), c2(1)=d2(1)";
    let pair =
        super::super::blend::blending_pair(limits, cmd.blend.as_deref(), &needed(&[&at_u, &at_v]))?;
    let corners = match script_corners(script.as_ref()) {
        Some(corners) if cmd.boundary.c1.is_none() => Some(corners),
        _ => None,
    };
    let patch = super::super::blend::coons_patch(
        [c1.clone(), c2.clone(), d1.clone(), d2.clone()],
        corners,
        pair,
    )
    .map_err(|e| {
        let (argument, form) = match e {
            cagd::Error::BlendingCondition { .. } => ("--blend", super::super::blend::BLEND_FORM),
            _ => ("--c1/--c2/--d1/--d2", expected),
        };
        CliError::library(argument, e, form)
    })?;
    // x = rc + rd − rcd at every point (cagd::coons::coons_point_cost).
    let per_point = coons_point_cost(
        curve_costs(&[(&c1, &at_u), (&c2, &at_u), (&d1, &at_v), (&d2, &at_v)]),
        c1.dim(),
        bits(&at_u),
        bits(&at_v),
    );
    check_work(
        limits,
        "--u/--v",
        weigh::<T>(per_point.times(evaluated_points((&us, &vs), pictures, (&pus, &pvs)))),
    )?;
    let mut report = Report::new();
    report.push("u", Value::Matrix(row(&us)));
    report.push("v", Value::Matrix(row(&vs)));
    push_terms(
        &mut report,
        ["rc", "rd", "rcd"],
        (cmd.steps.steps, cmd.params.list),
        (&us, &vs),
        single,
        c1.dim(),
        |u, v| {
            let p = patch.parts(u, v);
            [p.rc, p.rd, p.rcd, p.x]
        },
    );
    coons_outcome(
        "Coons patch",
        &patch,
        [&c1, &c2, &d1, &d2],
        (&pus, &pvs),
        (&cmd.plot, &cmd.mesh, &cmd.output),
        &report,
        warnings(&cmd.script.script, script.as_ref(), &mut env),
    )
}

//! `gordon`: the Gordon surface of a curve network (curves or a packed data script).

use cagd::limits::Limits;
use clap::Args;

use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::plot::{Colour, Figure};
use crate::{load_params, CliError, PendingWrites, Report, Value};
use cagd::gordon::{gordon_point_cost, gordon_setup_cost};
use cagd::{Curve, GordonSurface, SampledCurve, Surface, Tolerance};
use cagd_octave::compat::PackedNetwork;
use cagd_octave::literal::LiteralScalar;
use cagd_octave::script::Script;

use super::super::bezier::point_mode;
use super::super::common::*;
use super::super::curve::{curve_cost, curve_costs};
use super::super::work::{bits, check_work, weigh};
use super::super::{prepare_script, Outcome};

use super::*;

/// A Gordon surface g = g1 + g2 - g12 of a curve network (thesis 4.4, algorithm 7).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: repeated --u-curve g(u_i, v) (expressions in v) and --v-curve g(u, v_j) (in u), in node
order, with --u-nodes and --v-nodes (default equally spaced); or --script FILE with appendix
D's packed g_u (3×kN), g_v, g_uv (k×3k) and nodes x, read as krpa_gordon reads them: each curve
is the polyline through its N samples (at the script's u and v, else linspace(0,1,N)), with the
crossing from g_uv added where a node is not a sample; default --u/--v: the samples.
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3. --steps also prints
g1, g2, g12. The conditioning line gives the Lebesgue constants of the node vectors.

Examples:
  cagd gordon --v-curve \"[u;0;u-u^2]\" --v-curve \"[u;0.5;0.5+u-u^2]\" --v-curve \"[u;1;1+u-u^2]\" \\
          --u-curve \"[0;v;v]\" --u-curve \"[0.5;v;0.25+v]\" --u-curve \"[1;v;v]\" --u 0.25 --v 0.75 --steps --exact
  cagd gordon --script appendix_d.m --n 10 --plot gordon.png")]
pub struct GordonCommand {
    /// A curve g(u_i, v) of the network, in v (repeat, one per u-node, in order); an
    /// expression such as "[0.5; v; 0.25+v]" or Bézier control points.
    #[arg(long = "u-curve", value_name = "CURVE", allow_hyphen_values = true)]
    pub u_curves: Vec<String>,
    /// A curve g(u, v_j) of the network, in u (repeat, one per v-node, in order).
    #[arg(long = "v-curve", value_name = "CURVE", allow_hyphen_values = true)]
    pub v_curves: Vec<String>,
    /// The nodes u_i (default: equally spaced on [0, 1], or the script's x).
    #[arg(long = "u-nodes", value_name = "VALUES", allow_hyphen_values = true)]
    pub u_nodes: Option<String>,
    /// The nodes v_j (default: equally spaced on [0, 1], or the script's x).
    #[arg(long = "v-nodes", value_name = "VALUES", allow_hyphen_values = true)]
    pub v_nodes: Option<String>,
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

/// The network of appendix D's packed data (`g_u`, `g_v`, `g_uv`, nodes `x` in both
/// directions), unpacked by [`PackedNetwork::unpack`] — the unpacker of
/// [`cagd_octave::compat::krpa_gordon`] too, so both give the same surface. Each curve is
/// sampled at the script's `u` (or `v`) if it has one value per sample, else at
/// `linspace(0,1,N)`; where a node is not a sample parameter the crossing from `g_uv` is added
/// to the curve.
fn packed_network<T: LiteralScalar>(
    limits: &Limits,
    s: &Script<T>,
) -> Result<PackedNetwork<T>, CliError> {
    let need = |name: &str| {
        s.value(name).cloned().ok_or_else(|| {
            usage(
                "--script",
                &format!("the script defines no matrix `{name}`"),
                "appendix D's g_u, g_v, g_uv and x (or --u-curve/--v-curve)",
            )
        })
    };
    let (g_u, g_v, g_uv, x) = (need("g_u")?, need("g_v")?, need("g_uv")?, need("x")?);
    let nodes: Vec<T> = x.iter().cloned().collect();
    check_degree(limits, "--script", nodes.len().saturating_sub(1))?;
    PackedNetwork::unpack(&g_u, &g_v, &g_uv, nodes.clone(), nodes, |param, n| {
        script_params(s, param, n)
    })
    .map_err(|e| match e {
        cagd::Error::ShapeMismatch {
            what,
            expected,
            found,
        } => shape("--script", format!("`{what}` is {found}"), &expected),
        cagd::Error::TooFewCurves { .. } => CliError::library(
            "--script",
            e,
            "at least 2 nodes x, one curve per node in g_u and in g_v",
        ),
        cagd::Error::UnsortedNodes { .. }
        | cagd::Error::DuplicateNodes { .. }
        | cagd::Error::NonFinite {
            what: "x_u" | "x_v",
            ..
        } => CliError::library("--script", e, "increasing distinct nodes x"),
        _ => CliError::library(
            "--script",
            e,
            "curves sampled at increasing parameters u and v, finite samples and crossings",
        ),
    })
}

/// The Gordon surface of a curve network (thesis §4.4, algorithm 7).
pub fn gordon<T: LiteralScalar>(limits: &Limits, cmd: &GordonCommand) -> Result<Outcome, CliError> {
    let script = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let mut env = script.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let form_nodes = "increasing distinct values, one per curve";
    let (u_nodes, v_nodes, at_u, at_v, packed) = if cmd.u_curves.is_empty()
        && cmd.v_curves.is_empty()
    {
        let s = script.as_ref().ok_or_else(|| {
            usage(
                "--u-curve",
                "missing",
                "repeated --u-curve and --v-curve (or --script with appendix D's g_u, g_v, g_uv, x)",
            )
        })?;
        for (arg, given) in [("--u-nodes", &cmd.u_nodes), ("--v-nodes", &cmd.v_nodes)] {
            if given.is_some() {
                return Err(usage(
                    arg,
                    "has no effect with the script's packed network (its nodes are x)",
                    "--u-curve/--v-curve with --u-nodes/--v-nodes, or the script alone",
                ));
            }
        }
        let p = packed_network(limits, s)?;
        let samples = |curves: &[SampledCurve<T>]| -> Vec<CurveSource<T>> {
            curves
                .iter()
                .map(|c| CurveSource::Samples(c.params().to_vec(), c.samples().clone()))
                .collect()
        };
        (
            p.u_nodes().to_vec(),
            p.v_nodes().to_vec(),
            samples(p.curves_at_u()),
            samples(p.curves_at_v()),
            Some((
                p.points().to_vec(),
                p.u_samples().to_vec(),
                p.v_samples().to_vec(),
            )),
        )
    } else {
        let load_all = |arg: &str, list: &[String]| -> Result<Vec<CurveSource<T>>, CliError> {
            list.iter()
                .map(|t| load_curve(limits, arg, t, script.as_ref(), cmd.rows.rows, &env))
                .collect()
        };
        let at_u = load_all("--u-curve", &cmd.u_curves)?;
        let at_v = load_all("--v-curve", &cmd.v_curves)?;
        let nodes = |arg: &str, given: &Option<String>, count: usize| -> Result<Vec<T>, CliError> {
            match given {
                Some(t) => load_params(limits, arg, t),
                None if count >= 2 => Ok(T::linspace(&T::zero(), &T::one(), count)),
                None => Err(shape(
                    if arg == "--u-nodes" {
                        "--u-curve"
                    } else {
                        "--v-curve"
                    },
                    format!("{count} curve(limits, s)"),
                    "at least 2 curves in each direction",
                )),
            }
        };
        check_degree(limits, "--u-curve", at_u.len().saturating_sub(1))?;
        check_degree(limits, "--v-curve", at_v.len().saturating_sub(1))?;
        let un = nodes("--u-nodes", &cmd.u_nodes, at_u.len())?;
        let vn = nodes("--v-nodes", &cmd.v_nodes, at_v.len())?;
        (un, vn, at_u, at_v, None)
    };
    let single = point_mode(limits, &cmd.params);
    // By default the surface is evaluated where the network is sampled: at the packed data's
    // own sample parameters (without the crossings added at nodes), else at those of the
    // first sampled curve.
    let (points, sampled_u, sampled_v) = match packed {
        Some((p, su, sv)) => (Some(p), Some(su), Some(sv)),
        None => (
            None,
            at_v.first()
                .and_then(|c| c.sample_params())
                .map(<[T]>::to_vec),
            at_u.first()
                .and_then(|c| c.sample_params())
                .map(<[T]>::to_vec),
        ),
    };
    let (us, vs) = surface_params(
        limits,
        &cmd.params,
        (sampled_u.as_deref(), sampled_v.as_deref()),
    )?;
    let (pictures, pus, pvs) = picture_params((&us, &vs), single, &cmd.plot, &cmd.mesh);
    let need_u = needed(&[&us, &pus, &u_nodes]);
    let need_v = needed(&[&vs, &pvs, &v_nodes]);
    // Curves g(u_i, ·) are sampled in v, curves g(·, v_j) in u.
    let parts: Vec<(&str, &CurveSource<T>, &[T])> = at_u
        .iter()
        .map(|c| ("--u-curve", c, need_v.as_slice()))
        .chain(at_v.iter().map(|c| ("--v-curve", c, need_u.as_slice())))
        .collect();
    let mut curves_u = build_curves(limits, &parts, &mut env)?;
    let curves_v = curves_u.split_off(at_u.len());
    // The set-up (crossings checked, Lagrange weights) before it runs
    // (cagd::gordon::gordon_setup_cost): exact weights of many nodes take minutes.
    let at_nodes = |curves: &[CliCurve<T>], nodes: &[T]| -> Vec<cagd::cost::Cost> {
        curves.iter().map(|c| curve_cost(c, nodes)).collect()
    };
    check_work(
        limits,
        "--u-curve/--v-curve",
        weigh::<T>(gordon_setup_cost(
            at_nodes(&curves_u, &v_nodes),
            at_nodes(&curves_v, &u_nodes),
            (bits(&u_nodes), bits(&v_nodes)),
        )),
    )?;
    let expected =
        "a compatible network: g(u_i, ·) at v_j equals g(·, v_j) at u_i, one curve per node";
    let surface = match points {
        Some(p) => GordonSurface::with_points(
            u_nodes.clone(),
            v_nodes.clone(),
            curves_u.clone(),
            curves_v.clone(),
            p,
            Tolerance::default(),
        ),
        None => GordonSurface::new(
            u_nodes.clone(),
            v_nodes.clone(),
            curves_u.clone(),
            curves_v.clone(),
        ),
    }
    .map_err(|e| {
        let form = match e {
            cagd::Error::UnsortedNodes { .. } | cagd::Error::DuplicateNodes { .. } => form_nodes,
            _ => expected,
        };
        CliError::library("--u-curve/--v-curve", e, form)
    })?;
    // g = g1 + g2 − g12 at every point (cagd::gordon::gordon_point_cost).
    let network: Vec<(&CliCurve<T>, &[T])> = curves_u
        .iter()
        .map(|c| (c, &need_v[..]))
        .chain(curves_v.iter().map(|c| (c, &need_u[..])))
        .collect();
    let per_point = gordon_point_cost(
        curve_costs(&network),
        (curves_u.len(), curves_v.len()),
        curves_u[0].dim(),
        (bits(&need_u), bits(&u_nodes)),
        (bits(&need_v), bits(&v_nodes)),
    );
    check_work(
        limits,
        "--u/--v",
        weigh::<T>(per_point.times(evaluated_points((&us, &vs), pictures, (&pus, &pvs)))),
    )?;
    let mut report = Report::new();
    report.push("u", Value::Matrix(row(&us)));
    report.push("v", Value::Matrix(row(&vs)));
    let d = curves_u[0].dim();
    push_terms(
        &mut report,
        ["g1", "g2", "g12"],
        (cmd.steps.steps, cmd.params.list),
        (&us, &vs),
        single,
        d,
        |u, v| {
            let p = surface.eval_parts(u, v);
            [p.g1, p.g2, p.g12, p.g]
        },
    );
    let c = surface.conditioning();
    report.push(
        "conditioning",
        Value::Text(format!(
            "Lebesgue constants Λ_u = {:.4}, Λ_v = {:.4}; network errors are amplified at most {:.4}-fold",
            c.u.value,
            c.v.value,
            c.amplification()
        )),
    );
    let mut files = PendingWrites::new();
    if pictures {
        let grid = grid_f64(&surface.eval_grid(&pus, &pvs));
        if let Some(path) = &cmd.plot.plot {
            let mut figure = Figure::new("Gordon surface").surface(grid.clone(), "g(u,v)");
            for (k, c) in curves_u.iter().enumerate() {
                let label = if k == 0 { "g(u_i, v)" } else { "" };
                figure = figure.boundary(to_f64(&sample(c, &pvs)), Colour::Red, label);
            }
            for (k, c) in curves_v.iter().enumerate() {
                let label = if k == 0 { "g(u, v_j)" } else { "" };
                figure = figure.boundary(to_f64(&sample(c, &pus)), Colour::Green, label);
            }
            add_plot(&mut files, "--plot", path, &figure)?;
        }
        if let Some(path) = &cmd.mesh.mesh {
            add_mesh(&mut files, "--mesh", path, &grid)?;
        }
    }
    finish(
        &report,
        &cmd.output,
        files,
        warnings(&cmd.script.script, script.as_ref(), &mut env),
    )
}

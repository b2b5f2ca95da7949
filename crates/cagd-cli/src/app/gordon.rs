//! `cagd gordon`: the Gordon surface of a curve network (curves or a packed data script).

use cagd_octave::compat::PackedNetwork;
use cagd_octave::literal::LiteralScalar;
use cagd_octave::script::Script;
use cagd_ops::curves::CurveArg;
use cagd_ops::ops::Gordon;
use clap::Args;

use super::answer::{respond, Destinations};
use super::common::{check_degree, shape, usage};
use super::curve_arg::{curve_arg, script_params, Reading};
use super::expr_curve::{expression_env, with_env_warnings};
use super::read::surface_params;
use super::run::{Names, Run};
use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::cx::Cx;
use crate::{load_params, CliError, Outcome};

/// A Gordon surface g = g1 + g2 - g12 of a curve network (thesis §4.5, algorithm 7).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: repeated --u-curve g(u_i, v) (expressions in v) and --v-curve g(u, v_j) (in u), in node
order, with --u-nodes and --v-nodes (default equally spaced); a curve may also be Bézier
control points, or bezier(P), bspline(P, U), nurbs(P, W, U) (P the control points as columns,
U the knots, W the weights; its domain is mapped onto [0, 1]). Or --script FILE with appendix
D's packed g_u (3×kN), g_v, g_uv (k×3k) and nodes x, read as krpa_gordon reads them: each
curve is the polyline through its N samples (at the script's u and v, else linspace(0,1,N)),
with the crossing from g_uv added where a node is not a sample; default --u/--v: the samples.
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3. --steps also prints
g1, g2, g12. The conditioning line gives the Lebesgue constants of the node vectors.

Examples:
  cagd gordon --v-curve \"[u;0;u-u^2]\" --v-curve \"[u;0.5;0.5+u-u^2]\" --v-curve \"[u;1;1+u-u^2]\" \\
          --u-curve \"[0;v;v]\" --u-curve \"[0.5;v;0.25+v]\" --u-curve \"[1;v;v]\" --u 0.25 --v 0.75 --steps --exact
  cagd gordon --u-curve \"bspline([0 0 0 0; 0 1 2 3; 0 1 1 0], [0 0 0 1 2 2 2])\" --u-curve \"bspline([1 1 1 1; 0 1 2 3; 1 2 2 1], [0 0 0 1 2 2 2])\" \\
          --v-curve \"[0 1; 0 0; 0 1]\" --v-curve \"[0 1; 3 3; 0 1]\" --u 0.5 --v 0.25 --exact
  cagd gordon --script appendix_d.m --n 10 --plot gordon.png")]
pub struct GordonCommand {
    /// A curve g(u_i, v) of the network, in v (repeat, one per u-node, in order); an
    /// expression such as "[0.5; v; 0.25+v]", Bézier control points, or bezier(P),
    /// bspline(P, U), nurbs(P, W, U).
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

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "--u-curve/--v-curve",
    special: &[],
};

impl Run for GordonCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let script = cx.script::<T>(&self.script, self.params.n)?;
        let env = expression_env(cx.limits, script.as_ref());
        let mut op = if self.u_curves.is_empty() && self.v_curves.is_empty() {
            self.packed(cx, script.as_ref())?
        } else {
            let how = Reading {
                script: script.as_ref(),
                rows: self.rows.rows,
                samples: None,
            };
            let mut curves = |argument: &str, list: &[String]| -> Result<Vec<_>, CliError> {
                list.iter()
                    .map(|text| curve_arg(cx, argument, text, how, &env))
                    .collect()
            };
            let mut op = Gordon::new(
                curves("--u-curve", &self.u_curves)?,
                curves("--v-curve", &self.v_curves)?,
            );
            let nodes = |argument: &str, given: &Option<String>| {
                given
                    .as_deref()
                    .map(|text| load_params(cx, argument, text))
                    .transpose()
            };
            op.u_nodes = nodes("--u-nodes", &self.u_nodes)?;
            op.v_nodes = nodes("--v-nodes", &self.v_nodes)?;
            op
        };
        op.at = surface_params(cx, &self.params)?;
        op.steps = self.steps.steps;
        op.drawing = self.plot.plot.is_some();
        op.mesh = self.mesh.mesh.is_some();
        let to = Destinations::surface(&self.output, &self.plot, &self.mesh);
        let outcome = respond(cx, &NAMES, &op, to)?;
        Ok(with_env_warnings(
            outcome.with_script_warnings(&self.script, script.as_ref()),
            &env,
        ))
    }
}

impl GordonCommand {
    /// The network of the script's packed data (no curve arguments given).
    fn packed<T: LiteralScalar>(
        &self,
        cx: &Cx,
        script: Option<&Script<T>>,
    ) -> Result<Gordon<T>, CliError> {
        let s = script.ok_or_else(|| {
            usage(
                "--u-curve",
                "missing",
                "repeated --u-curve and --v-curve (or --script with appendix D's g_u, g_v, g_uv, x)",
            )
        })?;
        for (argument, given) in [("--u-nodes", &self.u_nodes), ("--v-nodes", &self.v_nodes)] {
            if given.is_some() {
                return Err(usage(
                    argument,
                    "has no effect with the script's packed network (its nodes are x)",
                    "--u-curve/--v-curve with --u-nodes/--v-nodes, or the script alone",
                ));
            }
        }
        let p = packed_network(cx, s)?;
        let samples = |curves: &[cagd::SampledCurve<T>]| -> Vec<CurveArg<T>> {
            curves.iter().cloned().map(CurveArg::Samples).collect()
        };
        let mut op = Gordon::new(samples(p.curves_at_u()), samples(p.curves_at_v()));
        op.u_nodes = Some(p.u_nodes().to_vec());
        op.v_nodes = Some(p.v_nodes().to_vec());
        op.crossings = Some(p.points().to_vec());
        // By default the surface is evaluated where the network is sampled (without the
        // crossings added at nodes).
        op.sampled_at = Some((p.u_samples().to_vec(), p.v_samples().to_vec()));
        Ok(op)
    }
}

/// The network of appendix D's packed data (`g_u`, `g_v`, `g_uv`, nodes `x` in both
/// directions), unpacked by [`PackedNetwork::unpack`] — the unpacker of
/// [`cagd_octave::compat::krpa_gordon`] too, so both give the same surface. Each curve is
/// sampled at the script's `u` (or `v`) if it has one value per sample, else at
/// `linspace(0,1,N)`; where a node is not a sample parameter the crossing from `g_uv` is added
/// to the curve.
fn packed_network<T: LiteralScalar>(cx: &Cx, s: &Script<T>) -> Result<PackedNetwork<T>, CliError> {
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
    check_degree(&cx.limits, "--script", nodes.len().saturating_sub(1))?;
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

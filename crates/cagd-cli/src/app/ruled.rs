//! `ruled`: the ruled surface `x(u, v) = (1 − v) ¹x(u) + v ²x(u)` between two curves (the
//! lecture notes, "plochy válcové").

use cagd::limits::Limits;
use cagd::surfaces::RuledSurface;
use cagd::{Curve, Surface};
use cagd_octave::literal::LiteralScalar;
use clap::Args;

use crate::args::{
    MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs, SurfaceParamArgs,
};
use crate::plot::{Colour, Figure};
use crate::{CliError, PendingWrites, Report, Value};

use super::bezier::point_mode;
use super::common::*;
use super::curve::curve_costs;
use super::work::{bits, check_work, weigh};
use super::{prepare_script, Outcome};

/// The ruled surface (1 − v)·¹x(u) + v·²x(u) between two curves (the lecture notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --first ¹x(u) and --second ²x(u): expressions in u such as \"[u;0;u-u^2]\", or Bézier
control points (columns; rows with --rows).
Layout: single --u and --v give the d×1 point; otherwise the grid nu×nv×d (like P), or with
--list one row u v x y z per point. --steps prints both curves at the u's.

Examples:
  cagd ruled --first \"[u;0;0]\" --second \"[u;1;u-u^2]\" --u 0.5 --v 0.25 --exact
  cagd ruled --first \"[0 0 0; 1 0 1; 2 0 0]'\" --second \"[0 1 1; 2 1 1]'\" --n 10 --plot ruled.png")]
pub struct RuledCommand {
    /// The curve ¹x(u) at v = 0: an expression in u such as "[u;0;u-u^2]", or Bézier control
    /// points (columns).
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub first: String,
    /// The curve ²x(u) at v = 1.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub second: String,
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

/// The ruled surface between two curves.
pub fn ruled<T: LiteralScalar>(limits: &Limits, cmd: &RuledCommand) -> Result<Outcome, CliError> {
    let script = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let mut env = script.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let first = load_curve(
        limits,
        "--first",
        &cmd.first,
        script.as_ref(),
        cmd.rows.rows,
        &env,
    )?;
    let second = load_curve(
        limits,
        "--second",
        &cmd.second,
        script.as_ref(),
        cmd.rows.rows,
        &env,
    )?;
    let single = point_mode(limits, &cmd.params);
    let us: Vec<T> =
        params_or_samples(limits, "--u", &cmd.params.u, cmd.params.n, DEFAULT_SAMPLES)?;
    let vs: Vec<T> =
        params_or_samples(limits, "--v", &cmd.params.v, cmd.params.n, DEFAULT_SAMPLES)?;
    check_grid(limits, us.len(), vs.len())?;
    let (zero, one) = (T::zero(), T::one());
    crate::slips::outside("--u", &us, &zero, &one, "the curves are extrapolated there");
    crate::slips::outside(
        "--v",
        &vs,
        &zero,
        &one,
        "the surface is extrapolated beyond its curves",
    );
    let pictures = cmd.plot.plot.is_some() || cmd.mesh.mesh.is_some();
    let (pus, pvs) = if single && pictures {
        let t = T::linspace(&zero, &one, 21);
        (t.clone(), t)
    } else {
        (us.clone(), vs.clone())
    };
    let at_u = needed(&[&us, &pus]);
    let mut curves = build_curves(
        limits,
        &[("--first", &first, &at_u), ("--second", &second, &at_u)],
        &mut env,
    )?;
    let b = curves.pop().expect("two curves");
    let a = curves.pop().expect("two curves");
    let points = us.len() as u128 * vs.len() as u128
        + if pictures {
            pus.len() as u128 * pvs.len() as u128
        } else {
            0
        };
    check_work(
        limits,
        "--u/--v",
        weigh::<T>(
            cagd::cost::blended(
                curve_costs(&[(&a, &at_u), (&b, &at_u)]),
                4 * a.dim() as u128,
                bits(&at_u) + bits(&vs) + 2,
            )
            .times(points),
        ),
    )?;
    let surface = RuledSurface::new(a.clone(), b.clone())
        .map_err(lib("--first/--second", "two curves of the same dimension"))?;
    let mut report = Report::new();
    report.push("u", Value::Matrix(row(&us)));
    report.push("v", Value::Matrix(row(&vs)));
    if cmd.steps.steps {
        report.push("first", Value::Matrix(sample(&a, &us)));
        report.push("second", Value::Matrix(sample(&b, &us)));
    }
    if single && !cmd.params.list {
        report.push(
            "result",
            Value::Matrix(column(&surface.eval(us[0].clone(), vs[0].clone()))),
        );
    } else {
        push_surface(
            &mut report,
            "result",
            (&us, &vs),
            surface.eval_grid(&us, &vs),
            cmd.params.list,
        );
    }
    let mut files = PendingWrites::new();
    if pictures {
        let grid = grid_f64(&surface.eval_grid(&pus, &pvs));
        if let Some(path) = &cmd.plot.plot {
            let figure = Figure::new("ruled surface")
                .surface(grid.clone(), "x(u,v)")
                .boundary(to_f64(&sample(&a, &pus)), Colour::Red, "¹x(u)")
                .boundary(to_f64(&sample(&b, &pus)), Colour::Green, "²x(u)");
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

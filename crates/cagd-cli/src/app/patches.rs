//! `coons`, `coons-bicubic`, `discrete-coons`, `gordon`, `lagrange`.

use cagd::grid::PointGrid;
use cagd::limits::Limits;
use clap::{Args, ValueEnum};
use nalgebra::{DMatrix, DVector};

use crate::args::{
    CurveParamArgs, MeshArgs, OutputArgs, PlotArgs, RowsArgs, ScriptArgs, StepsArgs,
    SurfaceParamArgs,
};
use crate::plot::{Colour, Figure};
use crate::{load_net, load_params, CliError, PendingWrites, Report, Value};
use cagd::coons::{
    bicubic_point_cost, coons_point_cost, discrete_coons, solve_mask, BicubicCoonsPatch,
    CoonsBoundary, CrossDerivatives, Mask, Twist,
};
use cagd::gordon::gordon_point_cost;
use cagd::lagrange::Lagrange;
use cagd::{Curve, GordonSurface, SampledCurve, Surface, Tolerance};
use cagd_octave::compat::PackedNetwork;
use cagd_octave::literal::{Env, LiteralScalar, Warning};
use cagd_octave::script::Script;

use super::bezier::point_mode;
use super::common::*;
use super::curve::curve_costs;
use super::work::{bits, check_work, weigh};
use super::{prepare_script, Outcome};

/// The boundary curve arguments shared by `coons` and `coons-bicubic`.
#[derive(Debug, Clone, Args)]
pub struct BoundaryArgs {
    /// x(u,0): an expression in u such as "[u;0;u-u^2]", or Bézier control points.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub c1: Option<String>,
    /// x(u,1), in u.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub c2: Option<String>,
    /// x(0,v), in v.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub d1: Option<String>,
    /// x(1,v), in v.
    #[arg(long, value_name = "CURVE", allow_hyphen_values = true)]
    pub d2: Option<String>,
    /// Curves given as data (a matrix of the --script, a data file) are samples of the
    /// curve, one column per parameter value (the script's u or v, else linspace(0,1,N)),
    /// not Bézier control points.
    #[arg(long)]
    pub samples: bool,
}

/// The four boundary sources: from the arguments, else from the script's c1, c2, d1, d2.
fn boundary_sources<T: LiteralScalar>(
    limits: &Limits,
    b: &BoundaryArgs,
    script: Option<&Script<T>>,
    rows: bool,
    env: &Env<T>,
) -> Result<[CurveSource<T>; 4], CliError> {
    let given = [&b.c1, &b.c2, &b.d1, &b.d2];
    if b.samples
        && !given
            .iter()
            .any(|g| g.as_deref().is_some_and(|t| names_data(t, script)))
    {
        return Err(usage(
            "--samples",
            "has no effect: no curve argument names a matrix of the script or a data file",
            "--samples with curves such as --c1 c1 from a --script, or without --samples",
        ));
    }
    let mut out = Vec::with_capacity(4);
    for (arg, given, name, param) in [
        ("--c1", &b.c1, "c1", "u"),
        ("--c2", &b.c2, "c2", "u"),
        ("--d1", &b.d1, "d1", "v"),
        ("--d2", &b.d2, "d2", "v"),
    ] {
        let source = match (given, script) {
            (Some(text), _) => load_curve_as(
                limits,
                arg,
                text,
                script,
                rows,
                env,
                b.samples.then_some(param),
            )?,
            (None, Some(s)) => script_curve(s, name, param).ok_or_else(|| {
                usage(
                    arg,
                    &format!("missing, and the script defines no `{name}`"),
                    CURVE_ARG_FORM,
                )
            })?,
            (None, None) => return Err(usage(arg, "missing", CURVE_ARG_FORM)),
        };
        out.push(source);
    }
    Ok(out.try_into().unwrap_or_else(|_| unreachable!()))
}

/// The script's corner points P1..P4 if it defines all four as 3-vectors.
fn script_corners<T: LiteralScalar>(script: Option<&Script<T>>) -> Option<[DVector<T>; 4]> {
    let s = script?;
    let get = |n: &str| {
        s.value(n)
            .filter(|m| m.ncols() == 1 || m.nrows() == 1)
            .map(|m| DVector::from_iterator(m.len(), m.iter().cloned()))
    };
    Some([get("P1")?, get("P2")?, get("P3")?, get("P4")?])
}

/// Parameters of a Coons or Gordon evaluation: the given lists, the samples of a thesis data
/// script, or `--n`.
fn surface_params<T: LiteralScalar>(
    limits: &Limits,
    params: &SurfaceParamArgs,
    from_script: (Option<&[T]>, Option<&[T]>),
) -> Result<(Vec<T>, Vec<T>), CliError> {
    let pick = |arg: &str, given: &Option<String>, s: Option<&[T]>| match (given, params.n, s) {
        (None, None, Some(s)) => Ok(s.to_vec()),
        _ => params_or_samples(limits, arg, given, params.n, DEFAULT_SAMPLES),
    };
    let (us, vs) = (
        pick("--u", &params.u, from_script.0)?,
        pick("--v", &params.v, from_script.1)?,
    );
    check_grid(limits, us.len(), vs.len())?;
    let (zero, one) = (T::zero(), T::one());
    crate::slips::outside("--u", &us, &zero, &one, "the patch is extrapolated there");
    crate::slips::outside("--v", &vs, &zero, &one, "the patch is extrapolated there");
    Ok((us, vs))
}

/// The parameters of the pictures of a patch: the result's, or a 21 × 21 grid when the
/// result is a single point; and whether there are pictures (`--plot` or `--mesh`) at all.
fn picture_params<T: LiteralScalar>(
    (us, vs): (&[T], &[T]),
    single: bool,
    plot: &PlotArgs,
    mesh: &MeshArgs,
) -> (bool, Vec<T>, Vec<T>) {
    let pictures = plot.plot.is_some() || mesh.mesh.is_some();
    if single && pictures {
        let t = T::linspace(&T::zero(), &T::one(), 21);
        (pictures, t.clone(), t)
    } else {
        (pictures, us.to_vec(), vs.to_vec())
    }
}

/// The points at which a patch is evaluated: the result's, and again the pictures' if any.
fn evaluated_points<T>((us, vs): (&[T], &[T]), pictures: bool, (pus, pvs): (&[T], &[T])) -> u128 {
    let result = us.len() as u128 * vs.len() as u128;
    if pictures {
        result + pus.len() as u128 * pvs.len() as u128
    } else {
        result
    }
}

/// The four boundary curves as parts for [`build_curves`]: c1, c2 sampled at `at_u`, d1, d2
/// at `at_v`.
fn boundary_parts<'a, T: LiteralScalar>(
    sources: &'a [CurveSource<T>; 4],
    at_u: &'a [T],
    at_v: &'a [T],
) -> Vec<(&'static str, &'a CurveSource<T>, &'a [T])> {
    ["--c1", "--c2", "--d1", "--d2"]
        .into_iter()
        .zip(sources)
        .enumerate()
        .map(|(k, (arg, s))| (arg, s, if k < 2 { at_u } else { at_v }))
        .collect()
}

/// Four curves from a vector of four.
fn four<T: LiteralScalar>(curves: Vec<CliCurve<T>>) -> [CliCurve<T>; 4] {
    curves.try_into().unwrap_or_else(|_| unreachable!())
}

#[derive(Debug, Args)]
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
    let pair = super::blend::blending_pair(limits, cmd.blend.as_deref(), &needed(&[&at_u, &at_v]))?;
    let corners = match script_corners(script.as_ref()) {
        Some(corners) if cmd.boundary.c1.is_none() => Some(corners),
        _ => None,
    };
    let patch = super::blend::coons_patch(
        [c1.clone(), c2.clone(), d1.clone(), d2.clone()],
        corners,
        pair,
    )
    .map_err(|e| {
        let (argument, form) = match e {
            cagd::Error::BlendingCondition { .. } => ("--blend", super::blend::BLEND_FORM),
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

/// The result of a patch that is a sum of terms (Coons: x = rc + rd − rcd; Gordon:
/// g = g1 + g2 − g12), `terms(u, v)` giving the three terms and the sum: at a single point
/// the d×1 columns, else the grids `us × vs × d`; the three terms too, under `names`, with
/// `--steps`.
fn push_terms<T: LiteralScalar>(
    report: &mut Report<T>,
    names: [&str; 3],
    (steps, list): (bool, bool),
    (us, vs): (&[T], &[T]),
    single: bool,
    d: usize,
    terms: impl Fn(T, T) -> [DVector<T>; 4],
) {
    if single && !list {
        let [a, b, c, x] = terms(us[0].clone(), vs[0].clone());
        if steps {
            for (name, term) in names.into_iter().zip([a, b, c]) {
                report.push(name, Value::Matrix(column(&term)));
            }
        }
        report.push("result", Value::Matrix(column(&x)));
        return;
    }
    let shape = (us.len(), vs.len(), d);
    let mut grids: [PointGrid<T>; 4] =
        std::array::from_fn(|_| PointGrid::from_elem(shape, T::zero()));
    for (i, u) in us.iter().enumerate() {
        for (j, v) in vs.iter().enumerate() {
            for (grid, term) in grids.iter_mut().zip(terms(u.clone(), v.clone())) {
                for k in 0..d {
                    grid[[i, j, k]] = term[k].clone();
                }
            }
        }
    }
    let [a, b, c, x] = grids;
    if steps {
        for (name, grid) in names.into_iter().zip([a, b, c]) {
            push_surface(report, name, (us, vs), grid, list);
        }
    }
    push_surface(report, "result", (us, vs), x, list);
}

/// The outcome of a Coons-type subcommand: the report (written as `--format`/`-o` say) and the
/// `--plot` and `--mesh` files of the patch sampled at `us × vs` — the picture is
/// [`coons_figure`], the mesh the grid itself; the patch is sampled only if either is asked
/// for.
fn coons_outcome<T: LiteralScalar, C: Curve<T>, S: Surface<T>>(
    title: &str,
    patch: &S,
    curves: [&C; 4],
    (us, vs): (&[T], &[T]),
    (plot, mesh, output): (&PlotArgs, &MeshArgs, &OutputArgs),
    report: &Report<T>,
    warnings: Vec<(String, Warning)>,
) -> Result<Outcome, CliError> {
    let mut files = PendingWrites::new();
    if plot.plot.is_some() || mesh.mesh.is_some() {
        let grid = grid_f64(&patch.eval_grid(us, vs));
        if let Some(path) = &plot.plot {
            let figure = coons_figure(title, grid.clone(), curves, us, vs);
            add_plot(&mut files, "--plot", path, &figure)?;
        }
        if let Some(path) = &mesh.mesh {
            add_mesh(&mut files, "--mesh", path, &grid)?;
        }
    }
    finish(report, output, files, warnings)
}

/// The picture of appendix C: the surface, c1 and c2 in red, d1 and d2 in green. Each curve
/// is drawn as the patch uses it: its domain `[a, b]` mapped onto the grid's `[0, 1]`.
pub fn coons_figure<T: LiteralScalar, C: Curve<T>>(
    title: &str,
    grid: PointGrid<f64>,
    [c1, c2, d1, d2]: [&C; 4],
    us: &[T],
    vs: &[T],
) -> Figure {
    let along = |c: &C, ts: &[T]| {
        let (a, b) = c.domain();
        let own: Vec<T> = ts
            .iter()
            .map(|s| a.clone() + (b.clone() - a.clone()) * s.clone())
            .collect();
        to_f64(&sample(c, &own))
    };
    Figure::new(title)
        .surface(grid, "x(u,v)")
        .boundary(along(c1, us), Colour::Red, "c1, c2")
        .boundary(along(c2, us), Colour::Red, "")
        .boundary(along(d1, vs), Colour::Green, "d1, d2")
        .boundary(along(d2, vs), Colour::Green, "")
}

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

#[derive(Debug, Args)]
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

#[derive(Debug, Args)]
pub struct DiscreteCoonsCommand {
    /// A Bézier control net, packed (m+1)×3(n+1) as ploskevB takes it, or an Octave
    /// (m+1)×(n+1)×3 array file. Only its boundary rows and columns are used.
    #[arg(value_name = "NET", allow_hyphen_values = true)]
    pub net: String,
    /// Solve the affine mask P_ij = α·(the 4 diagonal neighbours) + β·(the 4 edge neighbours)
    /// for every interior point instead of the discrete Coons formula; α + β must be 1/4.
    /// α = −1/4, β = 1/2 is the mask the permanence principle gives (the CAD notes (7)–(8)):
    /// the discrete Coons patch again; α = 0, β = 1/4 is the discrete Laplace mask (each
    /// point the average of its 4 edge neighbours). E.g. --mask=-0.25,0.5.
    #[arg(long, value_name = "ALPHA,BETA", allow_hyphen_values = true)]
    pub mask: Option<String>,
    /// Also print the three parts of the discrete Coons formula (the CAD notes (6)):
    /// b^u = (1 − i/m) P_0j + (i/m) P_mj, b^v = (1 − j/n) P_i0 + (j/n) P_in and the corner
    /// term b^uv; the net is b^u + b^v − b^uv.
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub script: ScriptArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The work of the exact band solve of a mask on `net` ([`Mask::solve_cost`] for every
/// coordinate), on numbers as large as the net's and the mask's. The library refuses the
/// operation count itself above `--max-work`, counting each as one.
fn exact_mask_work<T: LiteralScalar>(net: &PointGrid<T>, mask: &Mask<T>) -> u128 {
    let (m1, n1, d) = net.dim();
    let size_bits = bits(net.iter()).max(bits(&[mask.alpha(), mask.beta()]));
    weigh::<T>(
        mask.solve_cost(m1.saturating_sub(1), n1.saturating_sub(1))
            .times(d as u128)
            .grown(size_bits),
    )
}

/// The interior control points from the boundary of a net.
pub fn discrete<T: LiteralScalar>(
    limits: &Limits,
    cmd: &DiscreteCoonsCommand,
) -> Result<Outcome, CliError> {
    let script = prepare_script::<T>(limits, &cmd.script, None)?;
    let net = load_net::<T>(limits, "NET", &cmd.net, script.as_ref())?;
    let (m1, n1, d) = net.dim();
    check_degree(limits, "NET", m1.max(n1).saturating_sub(1))?;
    let coords: Vec<DMatrix<T>> = (0..d)
        .map(|k| DMatrix::from_fn(m1, n1, |i, j| net[[i, j, k]].clone()))
        .collect();
    let expected = "a net of at least 3×3 points";
    let full = match &cmd.mask {
        None => discrete_coons(&coords).map_err(lib("NET", expected))?,
        Some(text) => {
            let form = "two numbers α,β with α + β = 1/4, e.g. -0.25,0.5";
            // Not load_params: the comma between α and β is not a decimal comma.
            let values: Vec<T> =
                cagd_octave::literal::parse_params_with(&format!("[{text}]"), limits)
                    .map_err(|e| CliError::literal("--mask", e, form))?;
            let [alpha, beta]: [T; 2] = values
                .try_into()
                .map_err(|v: Vec<T>| shape("--mask", format!("{} value(s)", v.len()), form))?;
            let mask = Mask::new(alpha, beta).map_err(lib("--mask", form))?;
            if T::EXACT {
                check_work(limits, "NET", exact_mask_work(&net, &mask))?;
            }
            solve_mask(&coords, &mask, limits).map_err(lib("NET", expected))?
        }
    };
    let grid = PointGrid::from_shape_fn((m1, n1, d), |(i, j, k)| full[k][(i, j)].clone());
    let mut report = Report::new();
    if cmd.steps.steps {
        if cmd.mask.is_some() {
            return Err(usage(
                "--steps",
                "has no effect with --mask (the mask is solved as one linear system)",
                "--steps without --mask (the parts of the discrete Coons formula)",
            ));
        }
        let [bu, bv, buv] = super::discrete_parts::parts(&net);
        report.push("bu", Value::Grid(bu));
        report.push("bv", Value::Grid(bv));
        report.push("buv", Value::Grid(buv));
    }
    report.push("result", Value::Grid(grid.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let g = grid_f64(&grid);
        let figure = Figure::new("discrete Coons net")
            .surface(g.clone(), "net as a surface")
            .net(g, Colour::Red, "control net");
        add_plot(&mut files, "--plot", path, &figure)?;
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

#[derive(Debug, Args)]
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

#[derive(Debug, Args)]
pub struct LagrangeCommand {
    /// The nodes x_0..x_m: a list such as "[0 0.5 1]" or a range.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub nodes: String,
    /// Values at the nodes, one column per node (a d×(m+1) matrix, or 1×(m+1) for numbers):
    /// then the interpolating polynomial's values are printed; without it, the basis
    /// polynomials L_0..L_m.
    #[arg(long, value_name = "MATRIX", allow_hyphen_values = true)]
    pub points: Option<String>,
    /// Also print the monomial coefficients (highest power first, as Octave's polyfit):
    /// `coefficients`, row i those of L_i (the lecture notes' blending matrix G), and with
    /// --points `polynomial`, those of the interpolant (the lecture notes' A = X G).
    #[arg(long)]
    pub coefficients: bool,
    /// Piecewise-linear interpolation of --points instead of the polynomial (the lecture
    /// notes' "lineární interpolace"; the nodes must increase, the end pieces are extended).
    #[arg(long, requires = "points", conflicts_with = "coefficients")]
    pub linear: bool,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// Lagrange basis values or interpolation (thesis algorithm 8, `Lagrange`).
pub fn lagrange<T: LiteralScalar>(
    limits: &Limits,
    cmd: &LagrangeCommand,
) -> Result<Outcome, CliError> {
    let nodes: Vec<T> = load_params(limits, "--nodes", &cmd.nodes)?;
    check_degree(limits, "--nodes", nodes.len().saturating_sub(1))?;
    // Any order of distinct nodes (the lecture notes' Příklad 1 takes 0, 1/2, 1/4, 1): the
    // barycentric basis is built on the sorted nodes and read back in the order given.
    let mut order: Vec<usize> = (0..nodes.len()).collect();
    order.sort_by(|&a, &b| {
        nodes[a]
            .partial_cmp(&nodes[b])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    let sorted: Vec<T> = order.iter().map(|&k| nodes[k].clone()).collect();
    let basis = Lagrange::new(sorted.clone())
        .map_err(lib("--nodes", "distinct finite nodes, at least one"))?;
    let ts: Vec<T> =
        params_or_samples(limits, "--t", &cmd.params.t, cmd.params.n, DEFAULT_SAMPLES)?;
    crate::slips::outside(
        "--t",
        &ts,
        &sorted[0],
        &sorted[sorted.len() - 1],
        "the polynomial is extrapolated beyond its nodes",
    );
    // The weights (Lagrange::weights_cost), then per parameter the barycentric basis
    // (Lagrange::basis_cost) or, with values, the interpolant (Lagrange::interpolation_cost).
    // Without values the m+1 basis values of every parameter are written out: about 100
    // operations each to format.
    let values = match &cmd.points {
        Some(text) => Some(points::<T>(limits, "--points", text, None, cmd.rows.rows)?),
        None => None,
    };
    let m1 = nodes.len() as u128;
    let k = ts.len() as u128;
    let (node_bits, param_bits) = (bits(&nodes), bits(&ts));
    let (per_param, written) = match &values {
        Some(v) => (
            basis.interpolation_cost(v.nrows(), param_bits, node_bits, bits(v.iter())),
            0,
        ),
        None => (basis.basis_cost(param_bits, node_bits), 100 * k * m1),
    };
    check_work(
        limits,
        "--t",
        weigh::<T>(basis.weights_cost(node_bits))
            .saturating_add(weigh::<T>(per_param.times(k)))
            .saturating_add(written),
    )?;
    if cmd.linear {
        let values = values.unwrap_or_else(|| DMatrix::zeros(0, 0));
        let mut rows = Vec::with_capacity(values.nrows());
        for r in 0..values.nrows() {
            let f = cagd::interpolation::PiecewiseLinear::new(
                nodes.clone(),
                values.row(r).iter().cloned().collect(),
            )
            .map_err(lib(
                "--nodes/--points",
                "increasing nodes and one value per node (a d×(m+1) --points)",
            ))?;
            rows.push(ts.iter().map(|t| f.eval(t.clone())).collect::<Vec<T>>());
        }
        let mut report = Report::new();
        report.push("t", Value::Matrix(row(&ts)));
        report.push(
            "result",
            Value::Matrix(DMatrix::from_fn(rows.len(), ts.len(), |r, k| {
                rows[r][k].clone()
            })),
        );
        return finish(&report, &cmd.output, PendingWrites::new(), Vec::new());
    }
    let mut report = Report::new();
    if cmd.coefficients {
        let g = cagd::interpolation::blending_matrix(&nodes)
            .map_err(lib("--nodes", "distinct finite nodes, at least one"))?;
        if let Some(v) = &values {
            if v.ncols() == nodes.len() {
                report.push("polynomial", Value::Matrix(T::mat_mul(v, &g)));
            }
        }
        report.push("coefficients", Value::Matrix(g));
    }
    report.push("t", Value::Matrix(row(&ts)));
    let mut files = PendingWrites::new();
    // Position k of the sorted nodes is node order[k] as given.
    let unsorted = |b: Vec<T>| -> Vec<T> {
        let mut out = b.clone();
        for (k, v) in b.into_iter().enumerate() {
            out[order[k]] = v;
        }
        out
    };
    match values {
        None => {
            let rows: Vec<Vec<T>> = ts.iter().map(|t| unsorted(basis.basis(t))).collect();
            let m = DMatrix::from_fn(ts.len(), nodes.len(), |i, j| rows[i][j].clone());
            report.push("result", Value::Matrix(m));
        }
        Some(values) => {
            if values.ncols() == nodes.len()
                && values.nrows() > 1
                && order.iter().enumerate().any(|(k, &j)| k != j)
            {
                crate::slips::warn(
                    "--nodes",
                    "the nodes do not increase, so the curve passes the points in the order of their nodes, not in the order given",
                );
            }
            let sorted_values = if values.ncols() == nodes.len() {
                DMatrix::from_fn(values.nrows(), values.ncols(), |r, k| {
                    values[(r, order[k])].clone()
                })
            } else {
                values.clone()
            };
            let mut cols = Vec::with_capacity(ts.len());
            for t in &ts {
                cols.push(
                    basis
                        .interpolate(&sorted_values, t)
                        .map_err(lib("--points", "one column of values per node"))?,
                );
            }
            let result = DMatrix::from_columns(&cols);
            if let Some(path) = &cmd.plot.plot {
                let (line, pts) = if result.nrows() == 1 {
                    // Numbers: plot (t, p(t)) and (x_i, y_i).
                    let l = DMatrix::from_fn(2, ts.len(), |r, k| {
                        if r == 0 {
                            ts[k].to_f64()
                        } else {
                            result[(0, k)].to_f64()
                        }
                    });
                    let p = DMatrix::from_fn(2, nodes.len(), |r, k| {
                        if r == 0 {
                            nodes[k].to_f64()
                        } else {
                            values[(0, k)].to_f64()
                        }
                    });
                    (l, p)
                } else {
                    (to_f64(&result), to_f64(&values))
                };
                let figure = Figure::new("Lagrange interpolation")
                    .curve(line, Colour::Blue, "interpolating polynomial")
                    .control_polygon(pts, "data");
                add_plot(&mut files, "--plot", path, &figure)?;
            }
            report.push("result", Value::Matrix(result));
        }
    }
    finish(&report, &cmd.output, files, Vec::new())
}

//! The patches of boundary curves and networks: `coons`, `coons-bicubic`, `discrete-coons`,
//! `gordon`, one file each, and what they share (boundary arguments, grids, terms, pictures).

use cagd::grid::PointGrid;
use cagd::limits::Limits;
use clap::Args;
use nalgebra::DVector;

use crate::args::{MeshArgs, OutputArgs, PlotArgs, SurfaceParamArgs};
use crate::plot::{Colour, Figure};
use crate::{CliError, PendingWrites, Report, Value};
use cagd::{Curve, Surface};
use cagd_octave::literal::{Env, LiteralScalar, Warning};
use cagd_octave::script::Script;

use super::common::*;
use super::Outcome;

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

mod coons_bicubic;
mod discrete_coons;
mod gordon;

pub use coons_bicubic::{coons_bicubic, CoonsBicubicCommand};
pub use discrete_coons::{discrete, DiscreteCoonsCommand};
pub use gordon::{gordon, GordonCommand};

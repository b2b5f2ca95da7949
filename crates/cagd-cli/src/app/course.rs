//! The course material of the CAD notes and the lecture notes: `spline`, `hermite`, `bspline`, `nurbs`.

use cagd::limits::Limits;
use clap::{Args, ValueEnum};
use nalgebra::{DMatrix, DVector};

use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, samples, CliError, PendingWrites, Report, Value};
use cagd::{BSplineCurve, CubicSpline, EndCondition, HermiteCubic, NurbsCurve};
use cagd_octave::literal::LiteralScalar;

use super::common::*;
use super::work::{bits, check_work, plotted, weigh};
use super::Outcome;

fn vector<T: LiteralScalar>(
    limits: &Limits,
    arg: &str,
    text: &str,
) -> Result<DVector<T>, CliError> {
    let m = crate::load_matrix::<T>(limits, arg, text, None)?;
    if m.nrows() != 1 && m.ncols() != 1 {
        return Err(shape(
            arg,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            "a vector such as \"[1;1]\"",
        ));
    }
    Ok(DVector::from_iterator(m.len(), m.iter().cloned()))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum End {
    /// Given end tangents (--start-tangent, --end-tangent), case a of the lecture notes.
    Clamped,
    /// Zero second derivatives at the ends, case b.
    Natural,
    /// A closed (periodic) spline, case c.
    Closed,
}

/// An interpolating cubic spline (the lecture notes): tangents at the points and curve samples.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: points as columns (rows with --rows); --end clamped (with --start-tangent and
--end-tangent; the default when both are given), natural or closed (a tangent with natural or
closed is an error). --params uniform (t_k = k, the lecture notes: segment k over [k, k+1]),
chord, centripetal or a list of values. A closed spline is periodic: every t is on the curve.
Layout: tangents is d×m (one per point); result d×k at --t (default: 10 samples per segment).
--steps prints params, the linear system (system, m×m, and rhs, d×m: system · tangentsᵀ = rhsᵀ,
as the lecture notes write it) and each segment's hermite data [x_k x_(k+1) h·x'_k h·x'_(k+1)]
and bezier control points.

Example:
  cagd spline \"[0 0; 2 1; 4 4; 6 0]'\" --end clamped --start-tangent \"[1;1]\" --end-tangent \"[-1;1]\" --exact")]
pub struct SplineCommand {
    /// The points to interpolate, one per column.
    #[arg(value_name = "POINTS", allow_hyphen_values = true)]
    pub points: String,
    /// The end condition (default: clamped when both tangents are given, else natural).
    #[arg(long, value_enum)]
    pub end: Option<End>,
    /// The tangent at the first point (clamped ends).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub start_tangent: Option<String>,
    /// The tangent at the last point (clamped ends).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub end_tangent: Option<String>,
    /// The parameters of the points: uniform (t_k = k, the lecture notes), chord, centripetal,
    /// or a list of increasing values (one per point, one more for a closed spline).
    #[arg(long, value_name = "CHOICE|VALUES", allow_hyphen_values = true)]
    pub params: Option<String>,
    /// Curve parameters (with uniform parameters segment k runs over [k, k+1]); a closed
    /// spline is periodic, so any value is on the curve.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub t: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// An interpolating cubic spline.
pub fn spline<T: LiteralScalar>(limits: &Limits, cmd: &SplineCommand) -> Result<Outcome, CliError> {
    let pts = points(limits, "POINTS", &cmd.points, None, cmd.rows.rows)?;
    let tangents = cmd.start_tangent.is_some() || cmd.end_tangent.is_some();
    let chosen = cmd
        .end
        .unwrap_or(if tangents { End::Clamped } else { End::Natural });
    if chosen != End::Clamped {
        // A tangent that the end condition ignores is a slip, not a choice.
        let name = if chosen == End::Natural {
            "natural"
        } else {
            "closed"
        };
        for (arg, given) in [
            ("--start-tangent", &cmd.start_tangent),
            ("--end-tangent", &cmd.end_tangent),
        ] {
            if given.is_some() {
                return Err(usage(
                    arg,
                    &format!("has no effect with --end {name}"),
                    "--end clamped with both tangents (or no --end), or no tangents",
                ));
            }
        }
    }
    let end = match chosen {
        End::Natural => EndCondition::Natural,
        End::Closed => EndCondition::Closed,
        End::Clamped => {
            let need = |arg: &str, v: &Option<String>| -> Result<DVector<T>, CliError> {
                let text = v.as_ref().ok_or_else(|| {
                    usage(
                        arg,
                        "missing with --end clamped",
                        "a tangent vector such as \"[1;1]\"",
                    )
                })?;
                vector(limits, arg, text)
            };
            EndCondition::Clamped {
                start: need("--start-tangent", &cmd.start_tangent)?,
                end: need("--end-tangent", &cmd.end_tangent)?,
            }
        }
    };
    let closed = chosen == End::Closed;
    let params = super::spline_steps::parameters(limits, cmd.params.as_deref(), &pts, closed)?;
    let given: Option<Vec<T>> = cmd
        .t
        .as_ref()
        .map(|t| load_params(limits, "--t", t))
        .transpose()?;
    check_work(limits, "POINTS", spline_work(&pts, &end, given.as_deref()))?;
    let clamped = match &end {
        EndCondition::Clamped { start, end } => Some((start.clone(), end.clone())),
        _ => None,
    };
    let s = CubicSpline::interpolate_with_params(pts, params, end).map_err(lib(
        "POINTS",
        "at least 2 points (3 for closed) as columns, tangents of the same dimension, increasing --params",
    ))?;
    let segments = s.segment_count();
    let (first, last) = (s.params()[0].clone(), s.params()[segments].clone());
    let ts: Vec<T> = match given {
        Some(t) => t,
        None => {
            // Ten samples per segment: too many points is about POINTS (spline has no --n).
            let count = 10 * segments + 1;
            limits
                .check_samples("samples (10 per segment)", count)
                .map_err(lib(
                "POINTS",
                "fewer points (10 samples per segment), parameters --t, or a higher --max-samples",
            ))?;
            let unit: Vec<T> = samples(limits, count, 2)?;
            let span = last.clone() - first.clone();
            unit.into_iter()
                .map(|x| first.clone() + x * span.clone())
                .collect()
        }
    };
    let at: Vec<T> = if closed {
        ts.iter()
            .map(|t| super::spline_steps::periodic(t, s.params()))
            .collect()
    } else {
        crate::slips::outside(
            "--t",
            &ts,
            &first,
            &last,
            "the end segments are extended there",
        );
        ts.clone()
    };
    let mut report = Report::new();
    if cmd.steps.steps {
        let (a, rhs) = super::spline_steps::system(&s, clamped.as_ref().map(|(a, b)| (a, b)));
        report.push("params", Value::Matrix(row(s.params())));
        report.push("system", Value::Matrix(a));
        report.push("rhs", Value::Matrix(rhs));
        for item in super::spline_steps::segments(&s)? {
            report.items.push(item);
        }
    }
    report.push("tangents", Value::Matrix(s.tangents().clone()));
    report.push("t", Value::Matrix(row(&ts)));
    let values = s.eval_many(&at);
    report.push("result", Value::Matrix(values.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let dense: Vec<T> = T::linspace(&first, &last, 10 * segments + 1);
        let figure = Figure::new("interpolating cubic spline")
            .curve(to_f64(&s.eval_many(&dense)), Colour::Blue, "spline")
            .control_polygon(to_f64(s.points()), "points");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

/// The work of an interpolating spline through the columns of `pts`: the (cyclic)
/// tridiagonal solve ([`cagd::spline::interpolation_cost`]) on the points and end tangents,
/// then a cubic at every parameter ([`cagd::spline::sample_cost`]; at `ts`, else 10 per
/// segment, whose parameters `k/10s` have about twice the bits of the sample count).
fn spline_work<T: LiteralScalar>(
    pts: &DMatrix<T>,
    end: &EndCondition<T>,
    ts: Option<&[T]>,
) -> u128 {
    let (d, n) = (pts.nrows(), pts.ncols());
    let data_bits = match end {
        EndCondition::Clamped { start, end } => {
            bits(pts.iter().chain(start.iter()).chain(end.iter()))
        }
        EndCondition::Closed | EndCondition::Natural => bits(pts.iter()),
    };
    let default_samples = 10 * n as u128 + 1;
    let samples = ts.map_or(default_samples, |t| t.len() as u128);
    let param_bits = ts.map_or(2 * (128 - default_samples.leading_zeros() as u128), |t| {
        bits(t)
    });
    weigh::<T>(cagd::spline::interpolation_cost(n, d, end, data_bits)).saturating_add(weigh::<T>(
        cagd::spline::sample_cost(n, d, data_bits, param_bits).times(samples),
    ))
}

/// A Hermite (Ferguson) cubic from end points and end tangents (the lecture notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Layout: result d×k at the parameters; --steps prints the Hermite basis values and the Bézier
control points of the same cubic.

Example:
  cagd hermite --p0 \"[0;0]\" --p1 \"[1;0]\" --t0 \"[1;1]\" --t1 \"[1;-1]\" --t 0.5 --exact")]
pub struct HermiteCommand {
    /// The start point x(0).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub p0: String,
    /// The end point x(1).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub p1: String,
    /// The start tangent x'(0).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub t0: String,
    /// The end tangent x'(1).
    #[arg(long, value_name = "VECTOR", allow_hyphen_values = true)]
    pub t1: String,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// A Hermite / Ferguson cubic.
pub fn hermite<T: LiteralScalar>(
    limits: &Limits,
    cmd: &HermiteCommand,
) -> Result<Outcome, CliError> {
    let h = HermiteCubic::new(
        vector(limits, "--p0", &cmd.p0)?,
        vector(limits, "--p1", &cmd.p1)?,
        vector(limits, "--t0", &cmd.t0)?,
        vector(limits, "--t1", &cmd.t1)?,
    )
    .map_err(lib(
        "--p0/--p1/--t0/--t1",
        "four vectors of the same dimension",
    ))?;
    let ts: Vec<T> =
        params_or_samples(limits, "--t", &cmd.params.t, cmd.params.n, DEFAULT_SAMPLES)?;
    crate::slips::outside(
        "--t",
        &ts,
        &T::zero(),
        &T::one(),
        "the cubic is extrapolated there",
    );
    let dense: Vec<T> = T::linspace(&T::zero(), &T::one(), 101);
    // The Bézier form of the cubic (drawn, and printed with --steps); its inner points are
    // x_1 ± x'/3, which overflow for end points and tangents near ±1.8e308.
    let bezier = h.to_bezier().map_err(lib(
        "--p0/--p1/--t0/--t1",
        "end points and tangents whose Bézier points x ± x'/3 stay within ±1.8e308",
    ))?;
    // Per parameter the point (HermiteCubic::eval_cost); --steps adds the basis rows.
    let bezier_bits = bits(bezier.control().iter());
    let at = |params: &[T], steps: bool| {
        let mut per = h.eval_cost(bits(params), bezier_bits);
        if steps {
            per = per.and(cagd::hermite::basis_cost(bits(params)));
        }
        weigh::<T>(per.times(params.len() as u128))
    };
    let picture = plotted(&cmd.plot, &dense);
    check_work(
        limits,
        "--t",
        at(&ts, cmd.steps.steps).saturating_add(at(picture, false)),
    )?;
    let mut report = Report::new();
    if cmd.steps.steps {
        let rows: Vec<[T; 4]> = ts
            .iter()
            .map(|t| cagd::hermite::hermite_basis(t.clone()))
            .collect();
        let basis = DMatrix::from_fn(ts.len(), 4, |i, j| rows[i][j].clone());
        report.push("hermite_basis", Value::Matrix(basis));
        report.push("bezier_control", Value::Matrix(bezier.control().clone()));
    }
    let values = DMatrix::from_columns(&ts.iter().map(|t| h.eval(t.clone())).collect::<Vec<_>>());
    report.push("t", Value::Matrix(row(&ts)));
    report.push("result", Value::Matrix(values.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let line =
            DMatrix::from_columns(&dense.iter().map(|t| h.eval(t.clone())).collect::<Vec<_>>());
        let figure = Figure::new("Hermite cubic")
            .curve(to_f64(&line), Colour::Blue, "x(t)")
            .control_polygon(to_f64(bezier.control()), "Bézier control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

/// A B-spline curve by de Boor's algorithm (the CAD notes and the lecture notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: control points as columns, --degree p or --order k = p + 1 (as the lecture notes
count), --knots (n+p+2 values; default clamped uniform). --n samples the knot domain.
Layout: result d×k at the parameters; --steps prints the basis functions N_i,p(t) (k×(n+1)) and
the de Boor scheme of each t (span, α's and levels d0..dp).

Example:
  cagd bspline \"[0 0; 1 2; 3 2; 4 0]'\" --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --t 0.25 --steps --exact")]
#[command(mut_arg("n", |a| a.help("Sample the knot domain [u_p, u_n] (not [0, 1]) at N equally spaced parameters")))]
pub struct BSplineCommand {
    /// Control points, one per column.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The degree p (default 3).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order k = p + 1 instead of the degree (the lecture notes count B-splines by order).
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// The knot vector (n+p+2 non-decreasing values); default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The parameters of a knot vector's domain: given, or `--n` samples of it.
fn domain_params<T: LiteralScalar>(
    limits: &Limits,
    params: &CurveParamArgs,
    (a, b): (T, T),
) -> Result<Vec<T>, CliError> {
    match &params.t {
        Some(t) => load_params(limits, "--t", t),
        None => {
            let unit: Vec<T> = samples(limits, params.n.unwrap_or(DEFAULT_SAMPLES), 2)?;
            Ok(unit
                .into_iter()
                .map(|x| a.clone() + x * (b.clone() - a.clone()))
                .collect())
        }
    }
}

/// A B-spline curve.
pub fn bspline<T: LiteralScalar>(
    limits: &Limits,
    cmd: &BSplineCommand,
) -> Result<Outcome, CliError> {
    let degree = spline_degree(cmd.degree, cmd.order, 3)?;
    check_degree(limits, "--degree", degree)?;
    let control = points::<T>(limits, "CONTROL", &cmd.control, None, cmd.rows.rows)?;
    let form = "degree p, n+1 ≥ p+1 control points and n+p+2 non-decreasing knots";
    let curve = match &cmd.knots {
        Some(k) => BSplineCurve::new(degree, load_params(limits, "--knots", k)?, control),
        None => BSplineCurve::clamped(degree, control),
    }
    .map_err(lib("CONTROL/--degree/--knots", form))?;
    let ts = domain_params(limits, &cmd.params, curve.domain())?;
    let (a, b) = curve.domain();
    let dense: Vec<T> = T::linspace(&a, &b, 201);
    check_work(
        limits,
        "--t",
        spline_basis_work(
            (degree, curve.dim(), bits(curve.knots().as_slice())),
            bits(curve.control().iter()),
            &ts,
            cmd.steps.steps,
            plotted(&cmd.plot, &dense),
        ),
    )?;
    let values = curve
        .eval_many(&ts)
        .map_err(lib("--t", "parameters inside the knot span"))?;
    let mut report = Report::new();
    if cmd.steps.steps {
        let mut rows = Vec::with_capacity(ts.len());
        for t in &ts {
            rows.push(
                curve
                    .basis(t)
                    .map_err(lib("--t", "parameters inside the knot span"))?,
            );
        }
        let n = rows.first().map_or(0, Vec::len);
        report.push(
            "basis",
            Value::Matrix(DMatrix::from_fn(ts.len(), n, |i, j| rows[i][j].clone())),
        );
        // The de Boor scheme of every parameter: span, α's and levels.
        for (k, t) in ts.iter().enumerate() {
            let scheme = curve
                .de_boor_scheme(t.clone())
                .map_err(lib("--t", "parameters inside the knot span"))?;
            let item = |name: String, value: Value<T>| crate::Item { name, value };
            let mut parts = vec![
                item("t".into(), Value::Matrix(row(std::slice::from_ref(t)))),
                item(
                    "span".into(),
                    Value::Matrix(DMatrix::from_element(1, 1, T::from_usize(scheme.span))),
                ),
            ];
            for (r, level) in scheme.levels.iter().enumerate() {
                if r > 0 {
                    parts.push(item(
                        format!("alpha{r}"),
                        Value::Matrix(row(&scheme.alphas[r - 1])),
                    ));
                }
                parts.push(item(format!("d{r}"), Value::Matrix(level.clone())));
            }
            let name = if ts.len() == 1 {
                "de_boor".to_string()
            } else {
                format!("de_boor_{}", k + 1)
            };
            report.push(name, Value::Record(parts));
        }
    }
    report.push("t", Value::Matrix(row(&ts)));
    report.push("result", Value::Matrix(values));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let line = curve.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let figure = Figure::new("B-spline curve")
            .curve(to_f64(&line), Colour::Blue, "curve")
            .control_polygon(to_f64(curve.control()), "control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

/// The work of a B-spline or NURBS curve of degree p in d coordinates (`(p, d, knot bits)`)
/// at `ts` (the basis twice with `steps`) and at `dense` (a picture):
/// [`cagd::bspline::curve_point_cost`] per parameter, plus [`cagd::bspline::basis_cost`] with
/// `steps`.
fn spline_basis_work<T: LiteralScalar>(
    (p, d, knot_bits): (usize, usize, u128),
    coefficient_bits: u128,
    ts: &[T],
    steps: bool,
    dense: &[T],
) -> u128 {
    let at = |params: &[T], steps: bool| {
        let param_bits = bits(params);
        let mut per =
            cagd::bspline::curve_point_cost(p, d, param_bits, knot_bits, coefficient_bits);
        if steps {
            per = per.and(cagd::bspline::basis_cost(p, param_bits, knot_bits));
        }
        weigh::<T>(per.times(params.len() as u128))
    };
    at(ts, steps).saturating_add(at(dense, false))
}

/// A NURBS curve (the CAD notes): rational B-spline with weights.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: control points as columns, --weights (one per point, positive), --degree (or --order),
--knots.
Layout: result d×k; --steps prints the rational basis functions R_i,p(t).

Example (a quarter circle):
  cagd nurbs \"[1 0; 1 1; 0 1]'\" --weights \"[1 0.7071067811865476 1]\" --degree 2 --n 5")]
#[command(mut_arg("n", |a| a.help("Sample the knot domain [u_p, u_n] (not [0, 1]) at N equally spaced parameters")))]
pub struct NurbsCommand {
    /// Control points, one per column.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The weights, one per control point, positive.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub weights: String,
    /// The degree p (default 2).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order k = p + 1 instead of the degree.
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// The knot vector; default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// A NURBS curve.
pub fn nurbs<T: LiteralScalar>(limits: &Limits, cmd: &NurbsCommand) -> Result<Outcome, CliError> {
    let degree = spline_degree(cmd.degree, cmd.order, 2)?;
    check_degree(limits, "--degree", degree)?;
    let control = points(limits, "CONTROL", &cmd.control, None, cmd.rows.rows)?;
    let weights: Vec<T> = load_params(limits, "--weights", &cmd.weights)?;
    let n = control.ncols();
    let knots: Vec<T> = match &cmd.knots {
        Some(k) => load_params(limits, "--knots", k)?,
        None => {
            let p = degree;
            if n < p + 1 {
                return Err(shape(
                    "CONTROL",
                    format!("{n} control point(s) for degree {p}"),
                    "at least p+1 control points",
                ));
            }
            let inner = n - p;
            let mut k = vec![T::zero(); p + 1];
            for i in 1..inner {
                k.push(T::from_ratio(i as i64, inner as i64));
            }
            k.extend(std::iter::repeat_n(T::one(), p + 1));
            k
        }
    };
    let curve = NurbsCurve::new(degree, knots, control, weights).map_err(lib(
        "CONTROL/--weights/--knots",
        "one positive weight per control point and n+p+2 non-decreasing knots",
    ))?;
    let ts = domain_params(limits, &cmd.params, curve.domain())?;
    let (a, b) = curve.domain();
    let dense: Vec<T> = T::linspace(&a, &b, 201);
    check_work(
        limits,
        "--t",
        spline_basis_work(
            (degree, curve.dim() + 1, bits(curve.knots())),
            bits(curve.points().iter()) + bits(&curve.weights()),
            &ts,
            cmd.steps.steps,
            plotted(&cmd.plot, &dense),
        ),
    )?;
    let mut cols = Vec::with_capacity(ts.len());
    for t in &ts {
        cols.push(
            curve
                .try_eval(t.clone())
                .map_err(lib("--t", "parameters inside the knot span"))?,
        );
    }
    let values = DMatrix::from_columns(&cols);
    let mut report = Report::new();
    if cmd.steps.steps {
        let mut rows = Vec::with_capacity(ts.len());
        for t in &ts {
            rows.push(
                curve
                    .basis(t)
                    .map_err(lib("--t", "parameters inside the knot span"))?,
            );
        }
        let k = rows.first().map_or(0, Vec::len);
        report.push(
            "basis",
            Value::Matrix(DMatrix::from_fn(ts.len(), k, |i, j| rows[i][j].clone())),
        );
    }
    report.push("t", Value::Matrix(row(&ts)));
    report.push("result", Value::Matrix(values));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let mut cols = Vec::with_capacity(dense.len());
        for t in &dense {
            cols.push(
                curve
                    .try_eval(t.clone())
                    .map_err(lib("--plot", "a curve"))?,
            );
        }
        let figure = Figure::new("NURBS curve")
            .curve(to_f64(&DMatrix::from_columns(&cols)), Colour::Blue, "curve")
            .control_polygon(to_f64(&curve.points()), "control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

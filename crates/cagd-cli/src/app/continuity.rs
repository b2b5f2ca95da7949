//! `continuity`: what holds where two Bézier curves join — `C⁰`, `C¹`, `G¹`, `C²` — with the
//! numbers compared (the lecture notes, "napojování"), and the free control point of the
//! lecture notes' example.
//!
//! The first curve `x` (degree `n`, control points `x_0 … x_n`) ends at `u = 1`, the second
//! `¹x` (degree `m`, `y_0 … y_m`) starts at `v = 0`:
//! `x(1) = x_n`, `¹x(0) = y_0`, `x'(1) = n (x_n − x_{n−1})`, `¹x'(0) = m (y_1 − y_0)`,
//! `x''(1) = n(n−1)(x_n − 2x_{n−1} + x_{n−2})`, `¹x''(0) = m(m−1)(y_2 − 2y_1 + y_0)`.
//! `C¹` needs `x'(1) = ¹x'(0)`; `x'(1) = k · ¹x'(0)` with `k > 0` is `G¹` (the lecture notes call
//! it `C¹`). With the second-to-last point of the first curve free, `x'(1) = k · ¹x'(0)` gives
//! `x_{n−1}(k) = x_n + k · (m/n)(y_0 − y_1)`: for the notes' data `x = 3 + k, y = 4 − 2k,
//! z = 3 + 3k`, and `k = 1` is the `C¹` point.

use cagd::bezier::BezierCurve;
use cagd::continuity::joint;
use cagd::limits::Limits;
use cagd_octave::literal::LiteralScalar;
use clap::Args;
use nalgebra::{DMatrix, DVector};

use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, number_text_digits, CliError, PendingWrites, Report, Value};

use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::Cost;

/// Continuity (C0, C1, G1, C2) where two Bézier curves join; the free point of a C1 joint.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: FIRST (ends at u = 1) and SECOND (starts at v = 0), Bézier control points as columns
(rows with --rows). With --free-point the second-to-last point of FIRST is unknown and left out:
the line x_(n-1)(k) = x_n + k·(m/n)(y_0 − y_1) of points giving x'(1) = k·¹x'(0) is printed
(k = 1: C1; k > 0: G1, which the lecture notes call C1), and the joint with k = --k (default 1).
Layout: end, start (x(1), ¹x(0)), d_end, d_start (first derivatives), dd_end, dd_start
(second), k if the tangents are parallel, continuity (1 = holds), verdict (the comparison);
--steps adds each curve's control points and derivative polygons (first.d1, first.d2, …).

Examples:
  cagd continuity \"[2 3 4; 3 1 5; 3 4 3]\" \"[3 4 3; 2 6 0; 5 7 5; 5 2 3]\" --rows --free-point --exact
  cagd continuity \"[0 0; 1 1; 2 1]'\" \"[2 1; 3 1; 4 0]'\" --exact")]
pub struct ContinuityCommand {
    /// Control points of the first curve x(u), ending at u = 1 (columns; rows with --rows).
    #[arg(value_name = "FIRST", allow_hyphen_values = true)]
    pub first: String,
    /// Control points of the second curve ¹x(v), starting at v = 0.
    #[arg(value_name = "SECOND", allow_hyphen_values = true)]
    pub second: String,
    /// The second-to-last control point of FIRST is unknown and left out of FIRST: print the
    /// line of points that makes the joint smooth (the lecture notes' example).
    #[arg(long)]
    pub free_point: bool,
    /// With --free-point: the factor k of x'(1) = k·¹x'(0) for the point printed (default 1,
    /// the C1 point).
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    pub k: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    /// Also print the control points of the first and second derivatives of both curves
    /// (n Δb_i and n(n−1) Δ²b_i), whose ends are compared.
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

fn column<T: LiteralScalar>(v: &DVector<T>) -> Value<T> {
    Value::Matrix(DMatrix::from_column_slice(v.len(), 1, v.as_slice()))
}

/// `r`-th derivative at `t` (zero if the degree is below `r`).
fn derivative_at<T: LiteralScalar>(c: &BezierCurve<T>, r: usize, t: T) -> DVector<T> {
    match c.derivative(r) {
        Ok(d) => d.eval(t),
        Err(_) => DVector::from_element(c.dim(), T::zero()),
    }
}

/// `k` with `a = k b`, if `a` and `b` are parallel and `b ≠ 0` (within `tol`).
fn factor<T: LiteralScalar>(a: &DVector<T>, b: &DVector<T>, tol: &T) -> Option<T> {
    let bb = b.iter().fold(T::zero(), |s, x| s + x.clone() * x.clone());
    if bb.is_zero() {
        return None;
    }
    let k = a
        .iter()
        .zip(b.iter())
        .fold(T::zero(), |s, (x, y)| s + x.clone() * y.clone())
        / bb;
    a.iter()
        .zip(b.iter())
        .all(|(x, y)| (x.clone() - k.clone() * y.clone()).abs() <= *tol)
        .then_some(k)
}

fn point_text<T: LiteralScalar>(v: &DVector<T>, digits: usize) -> String {
    let parts: Vec<String> = v.iter().map(|x| number_text_digits(x, digits)).collect();
    format!("({})", parts.join(", "))
}

/// The analysis of the joint of `a` and `b`, as report items.
fn analyse<T: LiteralScalar>(
    report: &mut Report<T>,
    a: &BezierCurve<T>,
    b: &BezierCurve<T>,
    digits: usize,
) -> Result<(), CliError> {
    let (one, zero) = (T::one(), T::zero());
    let (p, q) = (a.eval(one.clone()), b.eval(zero.clone()));
    let (dp, dq) = (
        derivative_at(a, 1, one.clone()),
        derivative_at(b, 1, zero.clone()),
    );
    let (ddp, ddq) = (derivative_at(a, 2, one), derivative_at(b, 2, zero));
    let scale = a
        .control()
        .iter()
        .chain(b.control().iter())
        .fold(T::one(), |m, x| if x.abs() > m { x.abs() } else { m });
    let tol = if T::EXACT {
        T::zero()
    } else {
        scale * T::from_f64(1e-12).unwrap_or_else(T::zero)
    };
    let j = joint((&p, &dp), (&q, &dq), tol.clone())
        .map_err(lib("FIRST/SECOND", "two curves of the same dimension"))?;
    let same = |x: &DVector<T>, y: &DVector<T>| {
        x.iter()
            .zip(y.iter())
            .all(|(s, t)| (s.clone() - t.clone()).abs() <= tol)
    };
    let c2 = j.c1 && same(&ddp, &ddq);
    let k = factor(&dp, &dq, &tol);
    let yes = |b: bool| if b { "yes" } else { "no" };
    let mut verdict = vec![
        format!(
            "C0: {}: x(1) = {}, ¹x(0) = {}",
            yes(j.c0),
            point_text(&p, digits),
            point_text(&q, digits)
        ),
        format!(
            "C1: {}: x'(1) = {}, ¹x'(0) = {}",
            yes(j.c1),
            point_text(&dp, digits),
            point_text(&dq, digits)
        ),
    ];
    verdict.push(match (&k, j.g1) {
        (Some(k), true) => format!(
            "G1: yes: x'(1) = k·¹x'(0) with k = {} > 0 (the lecture notes call this C1; C1 needs k = 1)",
            number_text_digits(k, digits)
        ),
        (Some(k), false) if j.c0 => format!(
            "G1: no: the tangents are parallel but k = {} is not positive",
            number_text_digits(k, digits)
        ),
        _ if !j.c0 => "G1: no: the curves do not meet".to_string(),
        _ => "G1: no: the tangents are not parallel".to_string(),
    });
    verdict.push(format!(
        "C2: {}: x''(1) = {}, ¹x''(0) = {}",
        yes(c2),
        point_text(&ddp, digits),
        point_text(&ddq, digits)
    ));
    report.push("end", column(&p));
    report.push("start", column(&q));
    report.push("d_end", column(&dp));
    report.push("d_start", column(&dq));
    report.push("dd_end", column(&ddp));
    report.push("dd_start", column(&ddq));
    if let Some(k) = k {
        report.push("k", Value::Matrix(DMatrix::from_element(1, 1, k)));
    }
    report.push(
        "continuity",
        record(vec![
            ("C0", flag(j.c0)),
            ("C1", flag(j.c1)),
            ("G1", flag(j.g1)),
            ("C2", flag(c2)),
        ]),
    );
    report.push("verdict", Value::Text(verdict.join("\n")));
    Ok(())
}

fn flag<T: LiteralScalar>(b: bool) -> Value<T> {
    Value::Matrix(DMatrix::from_element(
        1,
        1,
        if b { T::one() } else { T::zero() },
    ))
}

/// Continuity at a joint.
pub fn continuity<T: LiteralScalar>(
    limits: &Limits,
    cmd: &ContinuityCommand,
) -> Result<Outcome, CliError> {
    let first = points::<T>(limits, "FIRST", &cmd.first, None, cmd.rows.rows)?;
    let second = points::<T>(limits, "SECOND", &cmd.second, None, cmd.rows.rows)?;
    check_degree(limits, "FIRST", first.ncols())?;
    check_degree(limits, "SECOND", second.ncols().saturating_sub(1))?;
    if cmd.k.is_some() && !cmd.free_point {
        return Err(usage(
            "--k",
            "has no effect without --free-point",
            "--free-point with --k, or no --k",
        ));
    }
    // Three derivatives of each curve: (n+1)² per coordinate.
    let n = first.ncols().max(second.ncols()) as u128 + 1;
    check_work(
        limits,
        "FIRST/SECOND",
        weigh::<T>(Cost::new(
            8 * n * n * first.nrows() as u128,
            bits(first.iter()).max(bits(second.iter())) + 2 * n,
        )),
    )?;
    let form = "control points, one per column (or per row with --rows), of the same dimension";
    let b = BezierCurve::new(second.clone()).map_err(lib("SECOND", form))?;
    let digits = cmd.output.text_digits();
    let mut report = Report::new();
    let a = if cmd.free_point {
        let n = first.ncols();
        if n < 2 || b.degree() < 1 || first.nrows() != second.nrows() {
            return Err(shape(
                "FIRST",
                format!("{n} known point(s) of dimension {}", first.nrows()),
                "with --free-point: the first curve's control points without its second-to-last (at least 2), the second curve of degree ≥ 1, both of the same dimension",
            ));
        }
        let d = first.nrows();
        let last = first.column(n - 1).into_owned();
        let (y0, y1) = (second.column(0).into_owned(), second.column(1).into_owned());
        if last != y0 {
            crate::slips::warn(
                "FIRST/SECOND",
                "the curves do not meet (the last point of FIRST is not the first of SECOND), so no free point makes the joint even C0",
            );
        }
        // Degree of the full first curve: the n given points and the free one.
        let ratio = T::from_ratio(b.degree() as i64, n as i64);
        let direction = DVector::from_fn(d, |r, _| ratio.clone() * (y0[r].clone() - y1[r].clone()));
        let k: T = match &cmd.k {
            Some(text) => match load_params::<T>(limits, "--k", text)?.as_slice() {
                [k] => k.clone(),
                other => {
                    return Err(shape(
                        "--k",
                        format!("{} values", other.len()),
                        "one number k",
                    ))
                }
            },
            None => T::one(),
        };
        let point = DVector::from_fn(d, |r, _| last[r].clone() + k.clone() * direction[r].clone());
        let names = ["x", "y", "z"];
        let line: Vec<String> = (0..d)
            .map(|r| {
                let name = if d <= 3 {
                    names[r].to_string()
                } else {
                    format!("x{}", r + 1)
                };
                let (c, s) = (&last[r], &direction[r]);
                let base = number_text_digits(c, digits);
                if s.is_zero() {
                    format!("{name} = {base}")
                } else {
                    let sign = if *s < T::zero() { "-" } else { "+" };
                    let mag = s.abs();
                    let coef = if mag == T::one() {
                        String::new()
                    } else {
                        number_text_digits(&mag, digits)
                    };
                    format!("{name} = {base} {sign} {coef}k")
                }
            })
            .collect();
        report.push("free_base", column(&last));
        report.push("free_direction", column(&direction));
        report.push(
            "free_point",
            Value::Text(format!(
                "x_(n-1)(k) = {} + k·{}: {}; k = 1 gives C1, every k > 0 G1",
                point_text(&last, digits),
                point_text(&direction, digits),
                line.join(", ")
            )),
        );
        report.push("k_used", Value::Matrix(DMatrix::from_element(1, 1, k)));
        report.push("point", column(&point));
        let mut columns: Vec<DVector<T>> = first.column_iter().map(|c| c.into_owned()).collect();
        columns.insert(n - 1, point);
        BezierCurve::new(DMatrix::from_columns(&columns)).map_err(lib("FIRST", form))?
    } else {
        BezierCurve::new(first).map_err(lib("FIRST", form))?
    };
    if a.dim() != b.dim() {
        return Err(shape(
            "FIRST/SECOND",
            format!("points of dimension {} and {}", a.dim(), b.dim()),
            form,
        ));
    }
    if cmd.steps.steps {
        for (name, curve) in [("first", &a), ("second", &b)] {
            let mut parts = vec![("control", Value::Matrix(curve.control().clone()))];
            for (r, label) in [(1, "d1"), (2, "d2")] {
                if let Ok(d) = curve.derivative(r) {
                    parts.push((label, Value::Matrix(d.control().clone())));
                }
            }
            report.push(name, record(parts));
        }
    }
    analyse(&mut report, &a, &b, digits)?;
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let dense: Vec<T> = T::linspace(&T::zero(), &T::one(), 101);
        let la = a.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let lb = b.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let figure = Figure::new("the joint of two Bézier curves")
            .curve(to_f64(&la), Colour::Blue, "x(u)")
            .curve(to_f64(&lb), Colour::Green, "¹x(v)")
            .control_polygon(to_f64(a.control()), "control polygons")
            .control_polygon(to_f64(b.control()), "");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

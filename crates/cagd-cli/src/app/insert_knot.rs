//! `insert-knot`: knot insertion into a B-spline or NURBS curve (Boehm's algorithm, the CAD
//! notes §1.2 "adding a knot").
//!
//! Inserting `u` into the span `[u_k, u_{k+1})` of a degree-`p` curve replaces the control
//! points `P_{k−p+1} … P_k` by `Q_i = (1 − α_i) P_{i−1} + α_i P_i`,
//! `α_i = (u − u_i)/(u_{i+p} − u_i)`, and keeps the others; the curve does not change. A NURBS
//! curve does this to its homogeneous points `(w P, w)`.

use cagd::bspline::find_span;
use cagd::limits::Limits;
use cagd::{BSplineCurve, NurbsCurve};
use cagd_octave::literal::LiteralScalar;
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, CliError, PendingWrites, Report, Value};

use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::Cost;

/// Insert knots into a B-spline or NURBS curve (Boehm's algorithm).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: control points as columns (rows with --rows), --degree P (or --order K), --knots
(default clamped uniform), --insert the knots to add (strictly inside the domain); --weights for
a NURBS curve (the homogeneous points (w P, w) are refined).
Layout: knots 1×(n+p+1+r) and control d×(n+r) (weights 1×(n+r) for NURBS). --steps prints each
insertion: the span k, α_i = (u − u_i)/(u_(i+p) − u_i) for i = k−p+1..k, and the new polygon.

Example:
  cagd insert-knot \"[0 0; 1 2; 3 2; 4 0]\" --rows --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --insert 0.25 --steps --exact")]
pub struct InsertKnotCommand {
    /// Control points, one per column (rows with --rows).
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: String,
    /// The knots to insert (any order, repeats allowed), each strictly inside the domain.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub insert: String,
    /// The degree p (default 3).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order k = p + 1 instead of the degree (the lecture notes count by order).
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// The knot vector (n+p+1 non-decreasing values); default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    /// Weights of a NURBS curve, one per control point (positive).
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub weights: Option<String>,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// One Boehm step on `curve` inserting `u`: the span, the `α_i` and the new curve.
fn boehm_step<T: LiteralScalar>(
    curve: &BSplineCurve<T>,
    u: &T,
) -> Result<(usize, Vec<T>, BSplineCurve<T>), CliError> {
    let form = "knots strictly inside the domain, each at most p+1 times";
    let p = curve.degree();
    let knots = curve.knots().as_slice();
    let k = find_span(p, curve.control().ncols(), knots, u).map_err(lib("--insert", form))?;
    let alphas = (k + 1 - p..=k)
        .map(|i| (u.clone() - knots[i].clone()) / (knots[i + p].clone() - knots[i].clone()))
        .collect();
    let next = curve
        .insert_knot(u.clone())
        .map_err(lib("--insert", form))?;
    Ok((k, alphas, next))
}

/// Knot insertion.
pub fn insert_knot<T: LiteralScalar>(
    limits: &Limits,
    cmd: &InsertKnotCommand,
) -> Result<Outcome, CliError> {
    let degree = spline_degree(cmd.degree, cmd.order, 3)?;
    check_degree(limits, "--degree", degree)?;
    let control = points::<T>(limits, "CONTROL", &cmd.control, None, cmd.rows.rows)?;
    let inserted: Vec<T> = load_params(limits, "--insert", &cmd.insert)?;
    let n = control.ncols();
    let knots: Vec<T> = match &cmd.knots {
        Some(k) => load_params(limits, "--knots", k)?,
        None => cagd::KnotVector::<T>::clamped_uniform(degree, n)
            .map_err(lib("CONTROL", "at least p+1 control points"))?
            .as_slice()
            .to_vec(),
    };
    // Each insertion: (p+1)·(d+1) combinations, then a copy of the n control points.
    let (p1, d1, r) = (
        degree as u128 + 1,
        control.nrows() as u128 + 1,
        inserted.len() as u128,
    );
    let total = n as u128 + r;
    let steps = if cmd.steps.steps { 2 } else { 1 };
    check_work(
        limits,
        "--insert",
        weigh::<T>(Cost::new(
            steps * r * (p1 * d1 + total * d1),
            bits(control.iter()) + bits(&knots) * 2 + 2 * r * (bits(&inserted) + 1),
        )),
    )?;
    let form = "degree p, n ≥ p+1 control points and n+p+1 non-decreasing knots";
    // The homogeneous B-spline of a NURBS curve, or the B-spline itself.
    let (curve, nurbs) = match &cmd.weights {
        Some(w) => {
            let weights: Vec<T> = load_params(limits, "--weights", w)?;
            let c = NurbsCurve::new(degree, knots, control, weights).map_err(lib(
                "CONTROL/--weights/--knots",
                "one positive weight per control point and n+p+1 non-decreasing knots",
            ))?;
            (c.homogeneous().clone(), true)
        }
        None => (
            BSplineCurve::new(degree, knots, control)
                .map_err(lib("CONTROL/--degree/--knots", form))?,
            false,
        ),
    };
    let form_insert = "knots strictly inside the domain, each at most p+1 times";
    let result = curve
        .insert_knots(&inserted)
        .map_err(lib("--insert", form_insert))?;
    let mut report = Report::new();
    if cmd.steps.steps {
        let mut current = curve.clone();
        for (k, u) in inserted.iter().enumerate() {
            let (span, alphas, next) = boehm_step(&current, u)?;
            report.push(
                format!("insert_{}", k + 1),
                record(vec![
                    ("u", Value::Matrix(row(std::slice::from_ref(u)))),
                    (
                        "span",
                        Value::Matrix(DMatrix::from_element(1, 1, T::from_usize(span))),
                    ),
                    ("alpha", Value::Matrix(row(&alphas))),
                    ("control", Value::Matrix(next.control().clone())),
                ]),
            );
            current = next;
        }
    }
    report.push("knots", Value::Matrix(row(result.knots().as_slice())));
    let shown = if nurbs {
        let c = NurbsCurve::from_homogeneous(result.clone())
            .map_err(lib("--weights", "positive weights"))?;
        report.push("control", Value::Matrix(c.points()));
        report.push("weights", Value::Matrix(row(&c.weights())));
        c.points()
    } else {
        report.push("control", Value::Matrix(result.control().clone()));
        result.control().clone()
    };
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let (a, b) = curve.domain();
        let dense: Vec<T> = T::linspace(&a, &b, 201);
        let line = if nurbs {
            let c = NurbsCurve::from_homogeneous(curve.clone())
                .map_err(lib("--weights", "positive weights"))?;
            let mut cols = Vec::with_capacity(dense.len());
            for t in &dense {
                cols.push(c.try_eval(t.clone()).map_err(lib("--plot", "a curve"))?);
            }
            DMatrix::from_columns(&cols)
        } else {
            curve.eval_many(&dense).map_err(lib("--plot", "a curve"))?
        };
        let original = if nurbs {
            NurbsCurve::from_homogeneous(curve.clone())
                .map_err(lib("--weights", "positive weights"))?
                .points()
        } else {
            curve.control().clone()
        };
        let figure = Figure::new("knot insertion (Boehm)")
            .curve(to_f64(&line), Colour::Blue, "curve")
            .boundary(to_f64(&original), Colour::Black, "original polygon")
            .control_polygon(to_f64(&shown), "refined polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

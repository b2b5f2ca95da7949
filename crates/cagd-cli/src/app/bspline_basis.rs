//! `bspline-basis`: the B-spline basis functions `N_{i,p}(u)` of a knot vector alone (the CAD
//! notes §1.2, the lecture notes), with the Cox–de Boor triangle as steps.

use cagd::bspline::{cox_de_boor_triangle, KnotVector};
use cagd::limits::Limits;
use cagd_octave::literal::LiteralScalar;
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{CurveParamArgs, OutputArgs, PlotArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, samples, CliError, Item, PendingWrites, Report, Value};

use super::common::*;
use super::work::{bits, check_work, plotted, weigh};
use super::Outcome;
use cagd::cost::polynomial_bits;
use cagd::cost::Cost;

/// B-spline basis functions N_i,p(u) of a knot vector (Cox–de Boor).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: --knots u_0..u_m, --degree P (or --order K = P + 1, as the lecture notes count); --t in
[u_0, u_m], or --n samples of it.
Layout: t is k×1, result k×n (row = parameter, column = N_0,p..N_(n-1),p, n = m − p). --steps
prints the Cox–de Boor triangle N_i,j(t) for j = 0..p (triangle.p0 … triangle.pP). --plot draws
the functions.

Examples:
  cagd bspline-basis --knots \"[0 0 0 1 2 3 3 3]\" --degree 2 --t 1.5 --steps --exact
  cagd bspline-basis --knots 0:7 --order 4 --n 50 --plot basis.svg")]
#[command(mut_arg("n", |a| a.help("Sample the whole knot range [u_0, u_m] at N equally spaced parameters")))]
pub struct BSplineBasisCommand {
    /// The knot vector u_0 ≤ … ≤ u_m.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: String,
    /// The degree p (default 3).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// The order k = p + 1 instead of the degree (the lecture notes count by order: N_i,k).
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    #[command(flatten)]
    pub params: CurveParamArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// Basis function values of a knot vector.
pub fn bspline_basis<T: LiteralScalar>(
    limits: &Limits,
    cmd: &BSplineBasisCommand,
) -> Result<Outcome, CliError> {
    let p = spline_degree(cmd.degree, cmd.order, 3)?;
    check_degree(limits, "--degree", p)?;
    let knots: Vec<T> = load_params(limits, "--knots", &cmd.knots)?;
    let form =
        "non-decreasing knots, at least p+2 of them (n = m − p ≥ 1 basis functions), not all equal";
    KnotVector::new(knots.clone()).map_err(lib("--knots", form))?;
    if knots.len() < p + 2 {
        return Err(shape(
            "--knots",
            format!("{} knot(s) for degree {p}", knots.len()),
            form,
        ));
    }
    let n = knots.len() - p - 1;
    // Every basis function N_i,p lives on [u_i, u_(i+p+1)]: the values are taken over the
    // whole knot range, not only the domain [u_p, u_n] of a spline.
    let (a, b) = (knots[0].clone(), knots[knots.len() - 1].clone());
    if a >= b {
        return Err(shape("--knots", format!("all knots equal {a}"), form));
    }
    let ts: Vec<T> = match &cmd.params.t {
        Some(t) => load_params(limits, "--t", t)?,
        None => {
            let unit: Vec<T> = samples(limits, cmd.params.n.unwrap_or(DEFAULT_SAMPLES), 2)?;
            unit.into_iter()
                .map(|x| a.clone() + x * (b.clone() - a.clone()))
                .collect()
        }
    };
    if let Some(x) = ts.iter().find(|x| **x < a || **x > b) {
        return Err(shape(
            "--t",
            format!(
                "{} is outside the knots [{}, {}]",
                crate::number_text(x),
                crate::number_text(&a),
                crate::number_text(&b)
            ),
            "parameters between the first and the last knot",
        ));
    }
    let dense: Vec<T> = T::linspace(&a, &b, 201);
    // Per parameter the triangle: (p+1)·m operations, on numbers of p levels of
    // (u − u_i)/(u_{i+j} − u_i); written out, every value about 100 operations.
    let m = knots.len() as u128;
    let per = 4 * (p as u128 + 1) * m + 100 * n as u128;
    let triangle = if cmd.steps.steps {
        100 * (p as u128 + 1) * m
    } else {
        0
    };
    let size = |params: &[T]| polynomial_bits(p, bits(params) + 3 * bits(&knots), 0);
    let picture = plotted(&cmd.plot, &dense);
    check_work(
        limits,
        "--t",
        weigh::<T>(Cost::new(ts.len() as u128 * (per + triangle), size(&ts))).saturating_add(
            weigh::<T>(Cost::new(picture.len() as u128 * per, size(picture))),
        ),
    )?;
    // The top level of the Cox–de Boor triangle: N_0,p … N_(n−1),p.
    let top = |t: &T| -> Vec<T> {
        cox_de_boor_triangle(p, &knots, t)
            .pop()
            .expect("p + 1 levels")
    };
    let rows: Vec<Vec<T>> = ts.iter().map(top).collect();
    let mut report = Report::new();
    if cmd.steps.steps {
        for (k, t) in ts.iter().enumerate() {
            let levels = cox_de_boor_triangle(p, &knots, t);
            let mut parts = vec![Item {
                name: "t".into(),
                value: Value::Matrix(row(std::slice::from_ref(t))),
            }];
            for (j, level) in levels.iter().enumerate() {
                parts.push(Item {
                    name: format!("p{j}"),
                    value: Value::Matrix(row(level)),
                });
            }
            let name = if ts.len() == 1 {
                "triangle".to_string()
            } else {
                format!("triangle_{}", k + 1)
            };
            report.push(name, Value::Record(parts));
        }
    }
    report.push(
        "t",
        Value::Matrix(DMatrix::from_column_slice(ts.len(), 1, &ts)),
    );
    report.push(
        "result",
        Value::Matrix(DMatrix::from_fn(ts.len(), n, |i, j| rows[i][j].clone())),
    );
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let values: Vec<Vec<T>> = dense.iter().map(top).collect();
        let colours = [
            Colour::Blue,
            Colour::Red,
            Colour::Green,
            Colour::Orange,
            Colour::Purple,
            Colour::Black,
        ];
        let mut figure = Figure::new(format!("B-spline basis functions, degree {p}"));
        for i in 0..n {
            let line = DMatrix::from_fn(2, dense.len(), |r, k| {
                if r == 0 {
                    dense[k].to_f64()
                } else {
                    values[k][i].to_f64()
                }
            });
            // Six labelled functions at most, so that the legend stays small.
            let label = match (n <= 6, i) {
                (true, _) => format!("N_{i},{p}"),
                (false, 0) => format!("N_i,{p}, i = 0..{}", n - 1),
                _ => String::new(),
            };
            figure = figure.curve(line, colours[i % colours.len()], label);
        }
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

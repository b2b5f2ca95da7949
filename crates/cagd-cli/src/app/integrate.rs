//! `integrate`: antiderivatives and definite integrals of Bernstein polynomials, Bézier curves
//! and B-spline curves (the CAD notes §1.1–1.2; formulas in `cagd::integral`).

use cagd::bezier::BezierCurve;
use cagd::integral::{
    bernstein_antiderivative, bezier_antiderivative, bezier_integral, bspline_antiderivative,
    bspline_integral,
};
use cagd::limits::Limits;
use cagd::BSplineCurve;
use cagd_octave::literal::LiteralScalar;
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{load_params, CliError, PendingWrites, Report, Value};

use super::bezier::interval;
use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::polynomial_bits;
use cagd::cost::Cost;

#[derive(Debug, Args)]
pub struct IntegrateCommand {
    /// Control points of a Bézier curve (or with --knots/--degree/--order of a B-spline),
    /// one per column (rows with --rows). Leave out with --bernstein.
    #[arg(value_name = "CONTROL", allow_hyphen_values = true)]
    pub control: Option<String>,
    /// Integrate the Bernstein polynomials B_i^N of degree N instead of a curve.
    #[arg(long, value_name = "N")]
    pub bernstein: Option<usize>,
    /// With --bernstein: only B_i^N.
    #[arg(long, value_name = "I")]
    pub i: Option<usize>,
    /// A B-spline curve of degree P (with --knots, default clamped uniform on [0, 1]).
    #[arg(long, value_name = "P")]
    pub degree: Option<usize>,
    /// A B-spline curve of order K = P + 1.
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// The knot vector of a B-spline curve.
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub knots: Option<String>,
    /// The parameter interval [a, b] of a Bézier curve (default 0,1).
    #[arg(long, value_name = "A,B", allow_hyphen_values = true)]
    pub interval: Option<String>,
    /// Also the antiderivative's values at these parameters (∫ from the start of the domain).
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

/// Integrals.
pub fn integrate<T: LiteralScalar>(
    limits: &Limits,
    cmd: &IntegrateCommand,
) -> Result<Outcome, CliError> {
    let bspline = cmd.degree.is_some() || cmd.order.is_some() || cmd.knots.is_some();
    let ts: Vec<T> = match &cmd.t {
        Some(t) => load_params(limits, "--t", t)?,
        None => Vec::new(),
    };
    if cmd.i.is_some() && cmd.bernstein.is_none() {
        return Err(usage(
            "--i",
            "has no effect without --bernstein",
            "--bernstein N --i I, or no --i",
        ));
    }
    let mut report = Report::new();
    let mut files = PendingWrites::new();
    if let Some(n) = cmd.bernstein {
        for (arg, given) in [
            ("CONTROL", cmd.control.is_some()),
            ("--knots", bspline),
            ("--interval", cmd.interval.is_some()),
        ] {
            if given {
                return Err(usage(
                    arg,
                    "has no effect with --bernstein",
                    "--bernstein N [--i I] [--t VALUES] alone",
                ));
            }
        }
        check_degree(limits, "--bernstein", n + 1)?;
        if let Some(i) = cmd.i {
            if i > n {
                return Err(shape(
                    "--i",
                    format!("i = {i} exceeds the degree {n}"),
                    "an index 0 ≤ i ≤ N",
                ));
            }
        }
        let rows: Vec<usize> = match cmd.i {
            Some(i) => vec![i],
            None => (0..=n).collect(),
        };
        let n2 = n as u128 + 2;
        check_work(
            limits,
            "--t",
            weigh::<T>(Cost::new(
                (rows.len() as u128 + ts.len() as u128) * n2 * n2,
                polynomial_bits(n + 1, bits(&ts), 2 * n2),
            )),
        )?;
        let coefficients: Vec<Vec<T>> = rows
            .iter()
            .map(|&i| bernstein_antiderivative::<T>(n, i))
            .collect();
        report.push(
            "antiderivative",
            Value::Matrix(DMatrix::from_fn(rows.len(), n + 2, |r, j| {
                coefficients[r][j].clone()
            })),
        );
        report.push(
            "integral",
            Value::Matrix(DMatrix::from_element(
                rows.len(),
                1,
                T::from_ratio(1, n as i64 + 1),
            )),
        );
        if !ts.is_empty() {
            crate::slips::outside(
                "--t",
                &ts,
                &T::zero(),
                &T::one(),
                "the polynomials are extrapolated there",
            );
            let basis = cagd::bernstein::basis_matrix(n + 1, &ts);
            let values = DMatrix::from_fn(ts.len(), rows.len(), |k, r| {
                (0..n + 2).fold(T::zero(), |s, j| {
                    s + basis[(k, j)].clone() * coefficients[r][j].clone()
                })
            });
            report.push(
                "t",
                Value::Matrix(DMatrix::from_column_slice(ts.len(), 1, &ts)),
            );
            report.push("result", Value::Matrix(values));
        }
        return finish(&report, &cmd.output, files, Vec::new());
    }
    let text = cmd.control.as_ref().ok_or_else(|| {
        usage(
            "CONTROL",
            "missing",
            "control points of a curve, or --bernstein N",
        )
    })?;
    let control = points::<T>(limits, "CONTROL", text, None, cmd.rows.rows)?;
    let d = control.nrows() as u128;
    let n1 = control.ncols() as u128 + 1;
    let p = if bspline {
        spline_degree(cmd.degree, cmd.order, 3)?
    } else {
        control.ncols().saturating_sub(1)
    };
    check_degree(limits, "CONTROL", p + 1)?;
    // The partial sums, then the antiderivative at --t (a curve of degree p + 1).
    let p2 = p as u128 + 2;
    check_work(
        limits,
        "--t",
        weigh::<T>(Cost::new(
            4 * d * n1 + ts.len() as u128 * d * p2 * p2,
            polynomial_bits(p + 1, bits(&ts), bits(control.iter()) + 2 * p2),
        )),
    )?;
    if bspline {
        if cmd.interval.is_some() {
            return Err(usage(
                "--interval",
                "has no effect on a B-spline (its domain is [u_p, u_n])",
                "--interval with a Bézier curve only",
            ));
        }
        let form = "degree p, n ≥ p+1 control points and n+p+1 non-decreasing knots";
        let curve = match &cmd.knots {
            Some(k) => BSplineCurve::new(p, load_params(limits, "--knots", k)?, control),
            None => BSplineCurve::clamped(p, control),
        }
        .map_err(lib("CONTROL/--degree/--knots", form))?;
        let anti = bspline_antiderivative(&curve).map_err(lib("CONTROL", form))?;
        let integral = bspline_integral(&curve).map_err(lib("CONTROL", form))?;
        let (a, b) = curve.domain();
        if cmd.steps.steps {
            let u = curve.knots().as_slice();
            let widths: Vec<T> = (0..curve.control().ncols())
                .map(|i| (u[i + p + 1].clone() - u[i].clone()) / T::from_usize(p + 1))
                .collect();
            report.push("basis_integrals", Value::Matrix(row(&widths)));
        }
        report.push("knots", Value::Matrix(row(anti.knots().as_slice())));
        report.push("antiderivative", Value::Matrix(anti.control().clone()));
        report.push(
            "integral",
            Value::Matrix(DMatrix::from_column_slice(
                integral.len(),
                1,
                integral.as_slice(),
            )),
        );
        if !ts.is_empty() {
            let mut cols = Vec::with_capacity(ts.len());
            let start = anti.try_eval(a.clone()).map_err(lib("CONTROL", form))?;
            for t in &ts {
                let v = anti
                    .try_eval(t.clone())
                    .map_err(lib("--t", "parameters inside the domain [u_p, u_n]"))?;
                cols.push(nalgebra::DVector::from_fn(v.len(), |r, _| {
                    v[r].clone() - start[r].clone()
                }));
            }
            report.push("t", Value::Matrix(row(&ts)));
            report.push("result", Value::Matrix(DMatrix::from_columns(&cols)));
        }
        if let Some(path) = &cmd.plot.plot {
            let dense: Vec<T> = T::linspace(&a, &b, 201);
            let line = anti.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
            let figure = Figure::new("antiderivative of a B-spline curve")
                .curve(to_f64(&line), Colour::Blue, "∫ C")
                .control_polygon(to_f64(anti.control()), "its control polygon");
            add_plot(&mut files, "--plot", path, &figure)?;
        }
        return finish(&report, &cmd.output, files, Vec::new());
    }
    let (a, b) = interval::<T>(limits, &cmd.interval)?;
    let curve = BezierCurve::new_on_interval(control, a.clone(), b.clone()).map_err(lib(
        "CONTROL",
        "control points b_0..b_n, one per column (or per row with --rows)",
    ))?;
    let sums = "control points whose integral stays within the range of doubles";
    let anti = bezier_antiderivative(&curve).map_err(lib("CONTROL", sums))?;
    let integral = bezier_integral(&curve).map_err(lib("CONTROL", sums))?;
    if cmd.steps.steps {
        report.push(
            "factor",
            Value::Matrix(DMatrix::from_element(
                1,
                1,
                (b.clone() - a.clone()) / T::from_usize(curve.degree() + 1),
            )),
        );
    }
    report.push("antiderivative", Value::Matrix(anti.control().clone()));
    report.push(
        "integral",
        Value::Matrix(DMatrix::from_column_slice(
            integral.len(),
            1,
            integral.as_slice(),
        )),
    );
    if !ts.is_empty() {
        crate::slips::outside(
            "--t",
            &ts,
            &a,
            &b,
            "the antiderivative is extrapolated there",
        );
        let values = anti
            .eval_many(&ts)
            .map_err(lib("--t", "finite parameters"))?;
        report.push("t", Value::Matrix(row(&ts)));
        report.push("result", Value::Matrix(values));
    }
    if let Some(path) = &cmd.plot.plot {
        let dense: Vec<T> = T::linspace(&a, &b, 101);
        let line = anti.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let figure = Figure::new("antiderivative of a Bézier curve")
            .curve(to_f64(&line), Colour::Blue, "∫ c")
            .control_polygon(to_f64(anti.control()), "its control polygon");
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

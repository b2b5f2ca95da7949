//! `convert`: a polynomial curve from one representation to another (the lecture notes,
//! "Konverze mezi reprezentacemi"; the matrix-form notes' product `P · M`).
//!
//! Every form is a geometry matrix `X` (one column per vector) that describes the curve
//! together with a basis: Hermite `[x(0) x(1) x'(0) x'(1)]`, Bézier `[b_0 … b_n]`, the
//! uniform cubic B-spline segment `[x_{i−1} x_i x_{i+1} x_{i+2}]`, the monomial coefficients
//! `[a_0 … a_n]` of `1, t, …, t^n` (the matrix-form notes' `P · M`) and the lecture notes'
//! algebraic form `A = [a b c d]` of `u³, u², u, 1`. Two forms describe the same curve when
//! `X_to = X_from · T`; the conversion matrix `T` goes through the Bézier form:
//! `T = T_{from→Bézier} · T_{Bézier→to}`, with the lecture notes' `M_F M_G⁻¹` between the
//! cubic forms and the Bernstein-to-monomial matrix `M` of degree `n` (`M[i, j] = (−1)^{j−i}
//! C(n, j) C(j, i)`) and its inverse for the monomial forms.

use cagd::bezier::{bezier_to_monomial_matrix, BezierCurve};
use cagd::conversion::{conversion_matrix, invert, CubicForm};
use cagd::limits::Limits;
use cagd_octave::literal::LiteralScalar;
use clap::{Args, ValueEnum};
use nalgebra::DMatrix;

use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::plot::{Colour, Figure};
use crate::{CliError, PendingWrites, Report, Value};

use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::Cost;

/// A representation of a polynomial curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Form {
    /// Hermite (Ferguson) cubic: [x(0) x(1) x'(0) x'(1)].
    Hermite,
    /// Bézier control points b_0 … b_n (any degree).
    Bezier,
    /// Uniform cubic B-spline segment ("Coons cubic"): [x_(i-1) x_i x_(i+1) x_(i+2)].
    Bspline,
    /// Monomial coefficients a_0 … a_n of 1, t, …, t^n (the matrix-form notes' P·M).
    Monomial,
    /// The lecture notes' algebraic form [a b c d] of u³, u², u, 1 (powers descending).
    Algebraic,
}

impl Form {
    fn cubic(self) -> Option<CubicForm> {
        match self {
            Form::Hermite => Some(CubicForm::Hermite),
            Form::Bezier => Some(CubicForm::Bezier),
            Form::Bspline => Some(CubicForm::BSpline),
            Form::Monomial | Form::Algebraic => None,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Form::Hermite => "hermite",
            Form::Bezier => "bezier",
            Form::Bspline => "bspline",
            Form::Monomial => "monomial",
            Form::Algebraic => "algebraic",
        }
    }
}

#[derive(Debug, Args)]
pub struct ConvertCommand {
    /// The geometry matrix of the curve, one vector per column (rows with --rows).
    #[arg(value_name = "GEOMETRY", allow_hyphen_values = true)]
    pub geometry: String,
    /// The form GEOMETRY is in.
    #[arg(long, value_enum)]
    pub from: Form,
    /// The form to convert to.
    #[arg(long, value_enum)]
    pub to: Form,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The `(n+1) × (n+1)` matrix reversing the order of columns.
fn reversal<T: LiteralScalar>(k: usize) -> DMatrix<T> {
    DMatrix::from_fn(
        k,
        k,
        |i, j| if i + j + 1 == k { T::one() } else { T::zero() },
    )
}

/// The `k × k` identity.
fn identity<T: LiteralScalar>(k: usize) -> DMatrix<T> {
    DMatrix::from_fn(k, k, |i, j| if i == j { T::one() } else { T::zero() })
}

/// `T` with `X_bezier = X_form · T` (`k` columns).
fn to_bezier<T: LiteralScalar>(form: Form, k: usize) -> cagd::Result<DMatrix<T>> {
    if form == Form::Bezier {
        return Ok(identity(k));
    }
    Ok(match form.cubic() {
        Some(c) => conversion_matrix(c, CubicForm::Bezier),
        None => {
            // Triangular with a non-zero diagonal: invertible; its entries may overflow.
            let inverse = invert(&bezier_to_monomial_matrix::<T>(k - 1)?)?;
            if form == Form::Algebraic {
                T::mat_mul(&reversal(k), &inverse)
            } else {
                inverse
            }
        }
    })
}

/// `T` with `X_form = X_bezier · T` (`k` columns).
fn from_bezier<T: LiteralScalar>(form: Form, k: usize) -> cagd::Result<DMatrix<T>> {
    if form == Form::Bezier {
        return Ok(identity(k));
    }
    Ok(match form.cubic() {
        Some(c) => conversion_matrix(CubicForm::Bezier, c),
        None => {
            let m = bezier_to_monomial_matrix::<T>(k - 1)?;
            if form == Form::Algebraic {
                T::mat_mul(&m, &reversal(k))
            } else {
                m
            }
        }
    })
}

/// Converts a curve between representations.
pub fn convert<T: LiteralScalar>(
    limits: &Limits,
    cmd: &ConvertCommand,
) -> Result<Outcome, CliError> {
    let x = points::<T>(limits, "GEOMETRY", &cmd.geometry, None, cmd.rows.rows)?;
    let k = x.ncols();
    check_degree(limits, "GEOMETRY", k.saturating_sub(1))?;
    if k == 0 || x.nrows() == 0 {
        return Err(shape(
            "GEOMETRY",
            format!("a {}×{} matrix", x.nrows(), x.ncols()),
            "a d×(n+1) geometry matrix, one vector per column",
        ));
    }
    for form in [cmd.from, cmd.to] {
        if form.cubic().is_some() && form != Form::Bezier && k != 4 {
            return Err(shape(
                "GEOMETRY",
                format!("{k} column(s) for the {} form", form.name()),
                "4 columns: the Hermite and B-spline forms are cubic (bezier, monomial and algebraic take any degree)",
            ));
        }
    }
    // Products of (n+1)×(n+1) matrices, the inverse of M and the geometry times T, on
    // numbers of the binomials' size (about n bits) over the input's.
    let kk = k as u128;
    check_work(
        limits,
        "GEOMETRY",
        weigh::<T>(Cost::new(
            4 * kk * kk * kk + 2 * x.nrows() as u128 * kk * kk,
            bits(x.iter()) + 2 * kk + 8,
        )),
    )?;
    let degree = "a geometry whose conversion matrices stay within the range of doubles";
    let into = to_bezier::<T>(cmd.from, k).map_err(lib("GEOMETRY", degree))?;
    let out = from_bezier::<T>(cmd.to, k).map_err(lib("GEOMETRY", degree))?;
    let t = T::mat_mul(&into, &out);
    let result = T::mat_mul(&x, &t);
    let bezier = BezierCurve::new(T::mat_mul(&x, &into)).map_err(lib(
        "GEOMETRY",
        "a d×(n+1) geometry matrix of finite numbers",
    ))?;
    let mut report = Report::new();
    if cmd.steps.steps {
        if let (Some(f), Some(g)) = (cmd.from.cubic(), cmd.to.cubic()) {
            // The lecture notes' table: T = M_from · M_to⁻¹.
            let m_to = g.lecture_notes_matrix::<T>();
            report.push("M_from", Value::Matrix(f.lecture_notes_matrix::<T>()));
            report.push("M_to", Value::Matrix(m_to.clone()));
            report.push(
                "M_to_inverse",
                Value::Matrix(invert(&m_to).expect("basis matrices are invertible")),
            );
        } else {
            report.push("to_bezier", Value::Matrix(into.clone()));
            report.push("from_bezier", Value::Matrix(out.clone()));
        }
        report.push("T", Value::Matrix(t));
    }
    report.push("result", Value::Matrix(result.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let dense: Vec<T> = T::linspace(&T::zero(), &T::one(), 101);
        let line = bezier.eval_many(&dense).map_err(lib("--plot", "a curve"))?;
        let mut figure = Figure::new(format!("{} → {}", cmd.from.name(), cmd.to.name()))
            .curve(to_f64(&line), Colour::Blue, "curve")
            .control_polygon(to_f64(bezier.control()), "Bézier control polygon");
        for (form, geometry) in [(cmd.from, &x), (cmd.to, &result)] {
            if form == Form::Bspline {
                figure = figure.boundary(to_f64(geometry), Colour::Green, "B-spline polygon");
            }
        }
        add_plot(&mut files, "--plot", path, &figure)?;
    }
    finish(&report, &cmd.output, files, Vec::new())
}

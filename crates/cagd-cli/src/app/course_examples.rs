//! `cagd course`: the main worked examples of the three sets of course notes (the matrix-form
//! notes, the lecture notes, the CAD notes), computed exactly where the maths is rational,
//! with the errors of the printed text named, and pictures into `--out` (as `cagd thesis` does
//! for the thesis).

use std::fmt::Write as _;
use std::path::PathBuf;

use cagd::bezier::{cubic_bezier_matrix, BezierCurve};
use cagd::conversion::{conversion_matrix, convert, invert, CubicForm};
use cagd::coons::{discrete_coons, solve_mask, Mask};
use cagd::interpolation::{blending_matrix, LagrangePolynomial, PiecewiseLinear};
use cagd::limits::Limits;
use cagd::{CubicSpline, EndCondition, NurbsCurve};
use clap::Args;
use nalgebra::{DMatrix, DVector};

use crate::plot::{Colour, Figure};
use crate::{CliError, PendingWrites, Report, Value};

use super::common::*;
use super::run::Run;
use super::worked::{curve_line, dense_line, heading, q, text, Files, Q};
use super::Outcome;
use crate::cx::Cx;
use cagd_octave::literal::LiteralScalar;

/// Reproduce the worked examples of the course notes (matrix-form, lecture and CAD notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Needs no input. Prints, exactly where the maths is rational, the matrix-form notes' table
(P·M = [0 3 0 0; 0 3 -6 4] and the points at t = 0, 0.2, …, 1), the lecture notes' conversion
table on their Bézier example (Bézier → Hermite → B-spline and back), the three splines of
the lecture notes (clamped, natural, closed; the printed sign error of the clamped example
named), the Lagrange example and Příklad 1, the C1 joint with its free point, the NURBS
circle of the CAD notes and the discrete Coons patch with its 3×3 masks. Pictures (SVG and
PNG) go to --out, written atomically.

Example:
  cagd course --out cagd-course")]
pub struct CourseCommand {
    /// The folder for the pictures (created if missing).
    #[arg(long, value_name = "DIR", default_value = "cagd-course")]
    pub out: PathBuf,
}

impl Run for CourseCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        course(&cx.limits, self)
    }
}

const INTERNAL: &str = "a valid built-in example";

/// A `d × k` rational matrix from integer points (one per row, as the notes write them).
fn rows_q(points: &[&[i64]]) -> DMatrix<Q> {
    DMatrix::from_fn(points[0].len(), points.len(), |r, c| q(points[c][r], 1))
}

fn f64m(m: &DMatrix<Q>) -> DMatrix<f64> {
    to_f64(m)
}

/// The worked examples of the course notes.
pub fn course(limits: &Limits, cmd: &CourseCommand) -> Result<Outcome, CliError> {
    // A folder that cannot be created is refused before the examples are computed.
    PendingWrites::check_dir(&format!("--out {}", cmd.out.display()), &cmd.out)?;
    let mut out = String::new();
    let mut files = Files {
        dir: &cmd.out,
        pending: PendingWrites::new(),
        written: Vec::new(),
    };
    matrix_form_table(&mut out, &mut files)?;
    conversions(&mut out, &mut files)?;
    splines(&mut out, &mut files)?;
    lagrange(&mut out, &mut files)?;
    c1_joint(&mut out, &mut files)?;
    nurbs_circle(&mut out, &mut files)?;
    discrete_mask(limits, &mut out, &mut files)?;
    let _ = writeln!(
        out,
        "Files written to {}:\n  {}",
        cmd.out.display(),
        files.written.join("\n  ")
    );
    let mut pending = files.pending;
    pending.create_dir(format!("--out {}", cmd.out.display()), &cmd.out);
    Ok(Outcome {
        stdout: out,
        files: pending,
        warnings: Vec::new(),
    })
}

/// The matrix-form notes §1.2–1.3: `p(t) = P · M · [1 t t² t³]ᵀ` and the table at
/// `t = 0, 0.2, …, 1`.
fn matrix_form_table(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(
        out,
        "Matrix-form notes §1.3: a cubic Bézier curve in matrix form",
    );
    out.push_str(
        "p0 = (0,0), p1 = (1,1), p2 = (2,0), p3 = (3,1); p(t) = P · M · [1 t t² t³]ᵀ, exactly.\n\
         (cagd convert \"[0 0; 1 1; 2 0; 3 1]\" --rows --from bezier --to monomial --steps --exact)\n\n",
    );
    let p = rows_q(&[&[0, 0], &[1, 1], &[2, 0], &[3, 1]]);
    let m = cubic_bezier_matrix::<Q>();
    let curve = BezierCurve::new(p.clone()).map_err(lib("course", INTERNAL))?;
    let form = curve.matrix_form().map_err(lib("course", INTERNAL))?;
    let ts: Vec<Q> = (0..=5).map(|k| q(k, 5)).collect();
    let table = DMatrix::from_columns(&ts.iter().map(|t| form.eval(t.clone())).collect::<Vec<_>>());
    let mut r = Report::<Q>::new();
    r.push("M", Value::Matrix(m));
    r.push("P·M", Value::Matrix(form.coefficients().clone()));
    r.push("t", Value::Matrix(row(&ts)));
    r.push("p(t)", Value::Matrix(table.clone()));
    out.push_str(&text(&r));
    let mut r = Report::<f64>::new();
    r.push("p(t) in decimals", Value::Matrix(f64m(&table)));
    out.push_str(&text(&r));
    out.push_str(
        "The notes print P·M = [0 3 0 0; 0 3 -6 4] and the points (0, 0), (0,6, 0,392),\n\
         (1,2, 0,496), (1,8, 0,504), (2,4, 0,608), (3, 1) with decimal commas: the same\n\
         (0,392 = 49/125). Their parametric form p(t) = 0p_0B_0^3(t) + … has a stray 0 in\n\
         front of p_0; the matrix form is printed correctly.\n\n",
    );
    let dense = curve_line(&curve, (&q(0, 1), &q(1, 1)), 101)?;
    let figure = Figure::new("Matrix-form notes: the cubic and its table of points")
        .curve(dense, Colour::Blue, "p(t)")
        .control_polygon(f64m(&p), "control polygon")
        .points(
            f64m(&table),
            (0..=5).map(|k| format!("t = {}", k as f64 / 5.0)).collect(),
            "p(0), p(0.2), …, p(1)",
        );
    files.picture("matrix_form", &figure)
}

trait ToF64Value {
    fn to_f64_value(&self) -> f64;
}

impl ToF64Value for Q {
    fn to_f64_value(&self) -> f64 {
        cagd::Scalar::to_f64(self)
    }
}

/// The lecture notes' Bézier example and the conversion table (Hermite ↔ Bézier ↔ B-spline).
fn conversions(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(
        out,
        "Lecture notes: Bézier → Hermite → B-spline (the conversion table)",
    );
    out.push_str(
        "x0 = (2,3), x1 = (3,5), x2 = (4,7) (or (4,1)), x3 = (5,3). The same cubic in the three forms:\n\
         X_to = X_from · T with T = M_from · M_to⁻¹ (entry of the notes' table in row \"to\", column\n\
         \"from\"); all nine printed matrices are right.\n\
         (cagd convert \"[2 3; 3 5; 4 7; 5 3]\" --rows --from bezier --to bspline --steps --exact)\n\n",
    );
    conversion_matrices(out);
    let mut figure = Figure::new("Lecture notes: one cubic, its Bézier and B-spline polygons");
    for (k, x2) in [[4, 7], [4, 1]].iter().enumerate() {
        let (b, s) = converted_cubic(out, x2)?;
        if k == 0 {
            let curve = BezierCurve::new(b.clone()).map_err(lib("course", INTERNAL))?;
            let dense = curve
                .eval_many(&(0..=100).map(|k| q(k, 100)).collect::<Vec<_>>())
                .map_err(lib("course", INTERNAL))?;
            figure = figure
                .curve(f64m(&dense), Colour::Blue, "the cubic (x2 = (4,7))")
                .control_polygon(f64m(&b), "Bézier polygon X_B")
                .boundary(f64m(&s), Colour::Green, "B-spline polygon X_C");
        }
    }
    files.picture("conversion", &figure)
}

/// The conversion matrices T of the notes' table that the example uses.
fn conversion_matrices(out: &mut String) {
    let mut r = Report::<Q>::new();
    for (name, from, to) in [
        ("T(bezier → hermite)", CubicForm::Bezier, CubicForm::Hermite),
        ("T(hermite → bezier)", CubicForm::Hermite, CubicForm::Bezier),
        ("T(bezier → bspline)", CubicForm::Bezier, CubicForm::BSpline),
        (
            "T(hermite → bspline)",
            CubicForm::Hermite,
            CubicForm::BSpline,
        ),
    ] {
        r.push(name, Value::Matrix(conversion_matrix(from, to)));
    }
    out.push_str(&text(&r));
    out.push_str(
        "T(bezier → hermite) is the notes' M_BH = [1 0 -3 0; 0 0 3 0; 0 0 0 -3; 0 1 0 3]:\n\
         x'(0) = 3(x1 − x0), x'(1) = 3(x3 − x2), as they state.\n\n",
    );
}

/// The notes' cubic with the third point `x2` in its Bézier, Hermite and B-spline forms, and
/// back from the B-spline form; returns the Bézier and B-spline polygons.
fn converted_cubic(out: &mut String, x2: &[i64; 2]) -> Result<(DMatrix<Q>, DMatrix<Q>), CliError> {
    let b = rows_q(&[&[2, 3], &[3, 5], x2, &[5, 3]]);
    let conv = |g: &DMatrix<Q>, from, to| convert(g, from, to).map_err(lib("course", INTERNAL));
    let h = conv(&b, CubicForm::Bezier, CubicForm::Hermite)?;
    let s = conv(&b, CubicForm::Bezier, CubicForm::BSpline)?;
    let back = conv(&s, CubicForm::BSpline, CubicForm::Bezier)?;
    let _ = writeln!(out, "x2 = ({}, {}):\n", x2[0], x2[1]);
    let mut r = Report::<Q>::new();
    r.push("X_B", Value::Matrix(b.clone()));
    r.push("X_H = [x(0) x(1) x'(0) x'(1)]", Value::Matrix(h));
    r.push("X_C (uniform cubic B-spline)", Value::Matrix(s.clone()));
    out.push_str(&text(&r));
    let _ = writeln!(
        out,
        "and back from X_C to Bézier: {}.\n",
        if back == b {
            "X_B again, exactly"
        } else {
            "DIFFERENT (a bug)"
        }
    );
    Ok((b, s))
}

/// An end condition of the lecture notes' splines: its title, the condition, and what the
/// notes print about it.
type SplineCase = (&'static str, EndCondition<Q>, &'static str);

/// The three splines of the lecture notes (cases a, b, c) on the points of their example.
fn splines(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(
        out,
        "Lecture notes: the three cubic splines (cases a, b, c)",
    );
    out.push_str(
        "Points x0 = (0,0), x1 = (2,1), x2 = (4,4), x3 = (6,0), every segment over ⟨0,1⟩.\n\
         (cagd spline \"[0 0; 2 1; 4 4; 6 0]\" --rows --start-tangent \"[1;1]\" --end-tangent \"[-1;1]\" --steps --exact)\n\n",
    );
    let pts = rows_q(&[&[0, 0], &[2, 1], &[4, 4], &[6, 0]]);
    let colours = [Colour::Blue, Colour::Orange, Colour::Purple];
    let mut figure = Figure::new("Lecture notes: clamped, natural and closed cubic splines");
    for (k, (title, end, note)) in spline_cases().into_iter().enumerate() {
        let s =
            CubicSpline::interpolate(pts.clone(), end.clone()).map_err(lib("course", INTERNAL))?;
        spline_system(out, &s, title, &end, k == 0)?;
        out.push_str(note);
        let segs = s.segment_count();
        let ends = (&q(0, 1), &q(segs as i64, 1));
        figure = figure.curve(
            curve_line(&s, ends, 20 * segs + 1)?,
            colours[k],
            title.split(',').next().unwrap_or(title),
        );
    }
    figure = figure.control_polygon(f64m(&pts), "points x0..x3");
    files.picture("splines", &figure)
}

/// The end conditions of the notes' cases a, b and c, with the errors of their printed text.
fn spline_cases() -> [SplineCase; 3] {
    let v = |x: i64, y: i64| DVector::from_vec(vec![q(x, 1), q(y, 1)]);
    [
        (
            "a) clamped, x'0 = (1,1), x'3 = (-1,1)",
            EndCondition::Clamped {
                start: v(1, 1),
                end: v(-1, 1),
            },
            "The notes print the x-tangents 1/15·[15 31 41 -15] (right) and the y-tangents\n\
             1/15·[15 48 27 15]: the third is wrong, it is -27/15 (y'1 + 4y'2 = 3(0 − 1) − 1 = −4\n\
             with 4y'1 + y'2 = 12 − 1 = 11). Their inverse 1/15·[15 0 0 0; -4 4 -1 1; 1 -1 4 -4; 0 0 0 15]\n\
             of the system matrix is right. Their general joint equation prints the right-hand side\n\
             3(x'1 − x0) for 3(x2 − x0).\n\n",
        ),
        (
            "b) natural, x'' = 0 at both ends",
            EndCondition::Natural,
            "The notes' matrix for case b is right; the last entry of their right-hand side,\n\
             3(x_(m-1) − x_(m-3)), must be 3(x_(m-1) − x_(m-2)) (from x''(1) = 0 on the last segment).\n\n",
        ),
        (
            "c) closed",
            EndCondition::Closed,
            "The first entry of the notes' right-hand side, 3(x1 − x0), must be 3(x1 − x_(m-1))\n\
             (the joint at x0 joins the segment from x_(m-1)).\n\n",
        ),
    ]
}

/// The linear system of spline `s` under `end` and its tangents (with the system's inverse if
/// `inverse`).
fn spline_system(
    out: &mut String,
    s: &CubicSpline<Q>,
    title: &str,
    end: &EndCondition<Q>,
    inverse: bool,
) -> Result<(), CliError> {
    let (a, rhs) = s.system(end);
    let _ = writeln!(out, "{title}:\n");
    let mut r = Report::<Q>::new();
    r.push("system A", Value::Matrix(a.clone()));
    r.push("right-hand sides (rows x, y)", Value::Matrix(rhs));
    if inverse {
        let inverse = invert(&a).map_err(lib("course", INTERNAL))?;
        r.push("A⁻¹", Value::Matrix(inverse));
    }
    r.push(
        "tangents (rows x', y')",
        Value::Matrix(s.tangents().clone()),
    );
    out.push_str(&text(&r));
    Ok(())
}

/// The lecture notes' interpolation example and Příklad 1.
fn lagrange(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(
        out,
        "Lecture notes: Lagrange and piecewise-linear interpolation",
    );
    out.push_str(
        "Through (1,1), (2,2), (3,3), (4,2), (5,1).\n\
         (cagd lagrange --nodes 1:5 --points \"[1 2 3 2 1]\" --coefficients --exact)\n\n",
    );
    let xs: Vec<Q> = (1..=5).map(|k| q(k, 1)).collect();
    let ys: Vec<Q> = [1, 2, 3, 2, 1].iter().map(|&k| q(k, 1)).collect();
    let f = LagrangePolynomial::new(xs.clone(), ys.clone()).map_err(lib("course", INTERNAL))?;
    let lin = PiecewiseLinear::new(xs.clone(), ys.clone()).map_err(lib("course", INTERNAL))?;
    let mut r = Report::<Q>::new();
    r.push(
        "coefficients of x⁴ … 1",
        Value::Matrix(row(&f.coefficients().map_err(lib("course", INTERNAL))?)),
    );
    r.push(
        "f(5/2)",
        Value::Matrix(DMatrix::from_element(1, 1, f.eval(q(5, 2)))),
    );
    r.push(
        "piecewise linear at 5/2",
        Value::Matrix(DMatrix::from_element(1, 1, lin.eval(q(5, 2)))),
    );
    out.push_str(&text(&r));
    out.push_str(
        "f(x) = x⁴/6 − 2x³ + 47x²/6 − 11x + 6 = 3 − 7/6 (x−3)² + 1/6 (x−3)⁴. The notes print the\n\
         linear interpolation with the last factor (x_(i+1) − x_i) for (x − x_i), which would be\n\
         constant; the Lagrange basis is right.\n\n",
    );
    blending_example(out)?;
    files.picture("lagrange", &lagrange_figure(&f, &xs, &ys)?)
}

/// Příklad 1 of the lecture notes: the blending matrix for parameters out of order, and for
/// the uniform ones the notes print.
fn blending_example(out: &mut String) -> Result<(), CliError> {
    out.push_str(
        "Příklad 1 asks what happens with the parameters (0, 1/2, 1/4, 1), not monotone: the\n\
         blending matrix G (rows: the cubic L_i, highest power first) exists for any distinct\n\
         values, and the curve passes x1, x3, x2, x4 in the order of the parameters.\n\
         (cagd lagrange --nodes \"[0 0.5 0.25 1]\" --coefficients --exact)\n\n",
    );
    let g =
        blending_matrix(&[q(0, 1), q(1, 2), q(1, 4), q(1, 1)]).map_err(lib("course", INTERNAL))?;
    let mut r = Report::<Q>::new();
    r.push("G for (0, 1/2, 1/4, 1)", Value::Matrix(g));
    r.push(
        "G for (0, 1/3, 2/3, 1)",
        Value::Matrix(
            blending_matrix(&[q(0, 1), q(1, 3), q(2, 3), q(1, 1)])
                .map_err(lib("course", INTERNAL))?,
        ),
    );
    out.push_str(&text(&r));
    out.push_str("The second is the notes' G with rows (-4.5, 9, -5.5, 1), (13.5, -22.5, 9, 0), …: the same.\n\n");
    Ok(())
}

/// The Lagrange polynomial `f` over [1, 5] and the piecewise-linear interpolant of its data.
fn lagrange_figure(f: &LagrangePolynomial<Q>, xs: &[Q], ys: &[Q]) -> Result<Figure, CliError> {
    let poly = dense_line((&q(1, 1), &q(5, 1)), 81, |dense| {
        DMatrix::from_fn(2, dense.len(), |r, k| {
            if r == 0 {
                dense[k].to_f64_value()
            } else {
                f.eval(dense[k].clone()).to_f64_value()
            }
        })
    })?;
    let data = DMatrix::from_fn(2, 5, |r, k| {
        if r == 0 {
            xs[k].to_f64_value()
        } else {
            ys[k].to_f64_value()
        }
    });
    Ok(
        Figure::new("Lecture notes: Lagrange polynomial and piecewise-linear interpolant")
            .curve(poly, Colour::Blue, "Lagrange polynomial")
            .boundary(data.clone(), Colour::Green, "piecewise linear")
            .control_polygon(data, "data points"),
    )
}

/// The lecture notes' C1 example: the free point of two cubic Bézier segments.
fn c1_joint(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(out, "Lecture notes: the C1 joint of two Bézier cubics");
    out.push_str(
        "x(u): xA = (2,3,4), xB = (3,1,5), xC = (x,y,z), xD = (3,4,3); ¹x(u): xD, xE = (2,6,0),\n\
         xF = (5,7,5), xG = (5,2,3). x'(1) = 3(xD − xC) = k·¹x'(0) = 3k(xE − xD) gives\n\
         xC(k) = xD + k(xD − xE):\n\
         (cagd continuity \"[2 3 4; 3 1 5; 3 4 3]\" \"[3 4 3; 2 6 0; 5 7 5; 5 2 3]\" --rows --free-point --exact)\n\n",
    );
    let d = rows_q(&[&[3, 4, 3]]).column(0).into_owned();
    let e = rows_q(&[&[2, 6, 0]]).column(0).into_owned();
    let (base, dir) = cagd::continuity::c1_free_point(&d, &e).map_err(lib("course", INTERNAL))?;
    let _ = writeln!(
        out,
        "xC(k) = ({}, {}, {}) + k·({}, {}, {}): x = 3 + k, y = 4 − 2k, z = 3 + 3k, as the notes print.\n",
        base[0], base[1], base[2], dir[0], dir[1], dir[2]
    );
    let c = DVector::from_fn(3, |r, _| base[r].clone() + dir[r].clone());
    let first = rows_q(&[&[2, 3, 4], &[3, 1, 5], &[4, 2, 6], &[3, 4, 3]]);
    let second = rows_q(&[&[3, 4, 3], &[2, 6, 0], &[5, 7, 5], &[5, 2, 3]]);
    let a = BezierCurve::new(first.clone()).map_err(lib("course", INTERNAL))?;
    let b = BezierCurve::new(second.clone()).map_err(lib("course", INTERNAL))?;
    let j = cagd::continuity::curve_joint(&a, q(1, 1), &b, q(0, 1), q(0, 1))
        .map_err(lib("course", INTERNAL))?;
    let _ = writeln!(
        out,
        "With k = 1, xC = ({}, {}, {}): C0 {}, C1 {}, G1 {}. Any k > 0 gives G1 only — the notes call\n\
         x'(1) = k·¹x'(0), k > 0, C1; that condition is G1 (C1 needs k = 1).\n",
        c[0],
        c[1],
        c[2],
        j.c0,
        j.c1,
        j.g1
    );
    let unit = (&q(0, 1), &q(1, 1));
    let figure = Figure::new("Lecture notes: two cubics joined C1 (k = 1)")
        .curve(curve_line(&a, unit, 51)?, Colour::Blue, "x(u)")
        .curve(curve_line(&b, unit, 51)?, Colour::Green, "¹x(u)")
        .control_polygon(f64m(&first), "control polygons")
        .control_polygon(f64m(&second), "");
    files.picture("c1_joint", &figure)
}

/// The circle as a NURBS curve (the CAD notes §1.3, octave-nurbs `nrbcirc`).
fn nurbs_circle(out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(out, "CAD notes §1.3: the unit circle as a NURBS curve");
    out.push_str(
        "Four rational quadratic quarter arcs, middle weights cos(45°) = √2/2, double knots\n\
         (octave-nurbs nrbcirc; cagd circle --n 9):\n\n",
    );
    let c = NurbsCurve::circle(1.0, &[0.0, 0.0]).map_err(lib("course", INTERNAL))?;
    let ts = cagd::linspace(0.0, 1.0, 401);
    let mut worst: f64 = 0.0;
    let mut cols = Vec::with_capacity(ts.len());
    for t in &ts {
        let p = c.try_eval(*t).map_err(lib("course", INTERNAL))?;
        worst = worst.max((p[0].hypot(p[1]) - 1.0).abs());
        cols.push(p);
    }
    let mut r = Report::<f64>::new();
    r.push("knots", Value::Matrix(row(c.knots())));
    r.push("control", Value::Matrix(c.points()));
    r.push("weights", Value::Matrix(row(&c.weights())));
    out.push_str(&text(&r));
    let _ = writeln!(
        out,
        "At 401 parameters the distance from the centre differs from 1 by at most {worst:.1e}\n\
         (round-off: the curve is the circle exactly).\n"
    );
    let figure = Figure::new("CAD notes: the circle as a NURBS curve")
        .curve(DMatrix::from_columns(&cols), Colour::Blue, "circle")
        .control_polygon(c.points(), "control polygon (weights 1, √2/2)");
    files.picture("nurbs_circle", &figure)
}

/// The discrete Coons patch and the masks of the CAD notes (6)–(9).
fn discrete_mask(limits: &Limits, out: &mut String, files: &mut Files) -> Result<(), CliError> {
    heading(
        out,
        "CAD notes §2.1: the discrete Coons patch and its 3×3 mask",
    );
    out.push_str(
        "A 4×4 net P_ij = (i, j, z_ij) with the boundary heights below (interior unknown). The\n\
         discrete Coons formula (6) and the mask (7)–(8), α = −1/4 on the diagonal neighbours and\n\
         β = 1/2 on the edge neighbours, give the same interior (the permanence principle); the\n\
         discrete Laplace mask α = 0, β = 1/4 another.\n\
         (cagd discrete-coons NET --steps --exact; cagd discrete-coons NET --mask=0,0.25 --exact)\n\n",
    );
    let boundary = [[0, 1, 2, 0], [1, 0, 0, 0], [1, 0, 0, 2], [0, 2, 1, 0]];
    let z = DMatrix::from_fn(4, 4, |i, j| q(boundary[i][j], 1));
    let x = DMatrix::from_fn(4, 4, |i, _| q(i as i64, 1));
    let y = DMatrix::from_fn(4, 4, |_, j| q(j as i64, 1));
    let net = vec![x, y, z.clone()];
    let coons = discrete_coons(&net).map_err(lib("course", INTERNAL))?;
    let mask = solve_mask(&net, &Mask::coons(), limits).map_err(lib("course", INTERNAL))?;
    let laplace = solve_mask(
        &net,
        &Mask::new(q(0, 1), q(1, 4)).map_err(lib("course", INTERNAL))?,
        limits,
    )
    .map_err(lib("course", INTERNAL))?;
    let mut r = Report::<Q>::new();
    r.push("boundary z (interior 0 = unknown)", Value::Matrix(z));
    r.push("z by the formula (6)", Value::Matrix(coons[2].clone()));
    r.push(
        "z by the mask α = -1/4, β = 1/2",
        Value::Matrix(mask[2].clone()),
    );
    r.push(
        "z by the mask α = 0, β = 1/4",
        Value::Matrix(laplace[2].clone()),
    );
    out.push_str(&text(&r));
    let _ = writeln!(
        out,
        "Formula and Coons mask agree: {}. The notes print the mask as 0.25·[-1 2 -1; 2 * 2; -1 2 -1]:\n\
         right.\n",
        if coons == mask { "yes, exactly" } else { "NO (a bug)" }
    );
    let grid = |c: &[DMatrix<Q>]| {
        cagd::grid::PointGrid::from_shape_fn((4, 4, 3), |(i, j, k)| c[k][(i, j)].to_f64_value())
    };
    let figure =
        Figure::new("CAD notes: discrete Coons net (red) and discrete Laplace net (green)")
            .surface(grid(&coons), "Coons net as a surface")
            .net(grid(&coons), Colour::Red, "Coons mask α = -1/4, β = 1/2")
            .net(grid(&laplace), Colour::Green, "Laplace mask α = 0, β = 1/4");
    files.picture("discrete_coons", &figure)
}

//! `integrate`: antiderivatives and definite integrals (the CAD notes §1.1–1.2; the formulas
//! are the core's, [`cagd::integral`]):
//!
//! - Bernstein polynomials: `∫₀ᵗ B_i^n = 1/(n+1) Σ_{j>i} B_j^{n+1}(t)`, `∫₀¹ B_i^n = 1/(n+1)`;
//! - a Bézier curve over `[a, b]`: the antiderivative of degree `n + 1` with control points
//!   `c_0 = 0`, `c_k = (b − a)/(n + 1) (b_0 + … + b_{k−1})`, and `∫_a^b c = c_{n+1}`;
//! - a B-spline curve of degree `p`: `∫ N_{i,p} = (u_{i+p+1} − u_i)/(p + 1) Σ_{j>i} N_{j,p+1}`,
//!   the antiderivative of degree `p + 1` over the knots with one more at each end.
//!
//! ```
//! use cagd_ops::{execute, ops::Integrate, Context};
//! use num_rational::BigRational;
//! use nalgebra::DMatrix;
//! // ∫₀¹ of the parabola 0, 2, 0 (x) is 2/3.
//! let q = |x: i64| BigRational::from_integer(x.into());
//! let op = Integrate::curve(DMatrix::from_row_slice(1, 3, &[q(0), q(2), q(0)]));
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("integral").unwrap()[0], BigRational::new(2.into(), 3.into()));
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::bezier::BezierCurve;
use cagd::cost::max_bits;
use cagd::integral::{
    antiderivative_cost, bernstein_antiderivative, bernstein_antiderivative_cost,
    bernstein_antiderivative_values, bernstein_integral, bezier_antiderivative,
    bezier_antiderivative_factor, bezier_integral, bspline_antiderivative, bspline_basis_integrals,
    bspline_integral, bspline_integral_to,
};
use cagd::{Curve, Scalar};
use nalgebra::DMatrix;

use super::bernstein::{graph_lines, graphs, marked};
use super::decasteljau::CONTROL_FORM;
use super::{eval_points, to_f64};
use crate::bspline_arg::{BSplineArg, BSPLINE_FORM};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The form of the Bernstein case.
const BERNSTEIN_FORM: &str =
    "the Bernstein polynomials of degree N alone (with an index i and parameters t)";

/// An antiderivative and a definite integral: of the Bernstein polynomials of one degree, of a
/// Bézier curve, or of a B-spline curve. Exactly one of `bernstein` and `control`; `index`
/// only with `bernstein`, `interval` only with a Bézier curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Integrate<T> {
    /// The degree `N` of the Bernstein polynomials to integrate ([`Role::Degree`]).
    pub bernstein: Option<usize>,
    /// Only `B_i^N` ([`Role::Index`]).
    pub index: Option<usize>,
    /// The control points of a curve, one per column.
    pub control: Option<DMatrix<T>>,
    /// A B-spline curve of these degree and knots (else a Bézier curve).
    pub bspline: Option<BSplineArg<T>>,
    /// The parameter interval `[a, b]` of a Bézier curve (default `[0, 1]`).
    pub interval: Option<(T, T)>,
    /// Where the antiderivative's values (`∫` from the start of the domain) are wanted.
    pub t: Option<Params<T>>,
    /// The factors of the partial sums.
    pub steps: bool,
    /// A picture: the antiderivative and its control polygon (the Bernstein case: each
    /// `∫₀ᵗ B_i^N` as the plane curve `(t, ∫₀ᵗ B_i^N)`).
    pub drawing: bool,
}

impl<T> Integrate<T> {
    /// The integrals of the Bézier curve of `control` on `[0, 1]`.
    pub fn curve(control: DMatrix<T>) -> Self {
        Integrate {
            bernstein: None,
            index: None,
            control: Some(control),
            bspline: None,
            interval: None,
            t: None,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Integrate<T> {
    /// `antiderivative` (Bernstein: one row of coefficients of degree `N + 1` per polynomial;
    /// a curve: its control points, `d × (n+2)`, a B-spline's after its `knots`), `integral`
    /// (`rows × 1`, or `d × 1`); with parameters `t` and `result` (Bernstein: `t` is `k × 1`
    /// and `result` `k × rows`; a curve: `1 × k` and `d × k`). Steps: `factor` (Bézier) or
    /// `basis_integrals` (B-spline).
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        self.check_usage()?;
        match (&self.bernstein, &self.control, &self.bspline) {
            (Some(n), _, _) => self.bernstein(cx, *n),
            (None, Some(control), Some(arg)) => self.spline(cx, control, arg),
            (None, Some(control), None) => self.bezier(cx, control),
            (None, None, _) => Err(OpError::new(
                Role::Control,
                Kind::Usage,
                "missing",
                "control points of a curve, or the degree N of the Bernstein polynomials",
            )),
        }
    }
}

impl<T: Scalar> Integrate<T> {
    /// Arguments that have no effect in the case chosen.
    fn check_usage(&self) -> Result<()> {
        let unused = |role: Role, problem: &str, expected: &str| {
            Err(OpError::new(role, Kind::Usage, problem, expected))
        };
        if self.bernstein.is_none() && self.index.is_some() {
            return unused(
                Role::Index,
                "has no effect without the Bernstein polynomials",
                "an index i of the Bernstein polynomials of degree N, or none",
            );
        }
        if self.bernstein.is_some() {
            let with = "has no effect with the Bernstein polynomials";
            for (role, given) in [
                (Role::Control, self.control.is_some()),
                (Role::Knots, self.bspline.is_some()),
                (Role::Interval, self.interval.is_some()),
            ] {
                if given {
                    return unused(role, with, BERNSTEIN_FORM);
                }
            }
        }
        if self.bspline.is_some() && self.interval.is_some() {
            return unused(
                Role::Interval,
                "has no effect on a B-spline (its domain is [u_(p+1), u_(n+1)])",
                "an interval with a Bézier curve only",
            );
        }
        Ok(())
    }

    /// `∫₀ᵗ B_i^N` for every `i` (or the one asked for).
    fn bernstein(&self, cx: &mut Context, n: usize) -> Result<Answer<T>> {
        cx.check_degree(Role::Degree, n.saturating_add(1))?;
        if let Some(i) = self.index.filter(|&i| i > n) {
            return Err(OpError::new(
                Role::Index,
                Kind::Shape,
                format!("i = {i} exceeds the degree {n}"),
                "an index 0 ≤ i ≤ N",
            ));
        }
        let rows: Vec<usize> = match self.index {
            Some(i) => vec![i],
            None => (0..=n).collect(),
        };
        let unit = (&T::zero(), &T::one());
        let ts = self.params(unit, "the polynomials are extrapolated there", cx)?;
        let picture = if self.drawing { PICTURE_SAMPLES } else { 0 };
        let cost = bernstein_antiderivative_cost(n, rows.len(), ts.len() + picture, max_bits(&ts));
        cx.check_cost(Role::T, cost, T::EXACT)?;
        let coefficients: Vec<Vec<T>> = rows
            .iter()
            .map(|&i| bernstein_antiderivative::<T>(n, i))
            .collect();
        let mut report = Report::new();
        report.push(
            "antiderivative",
            Value::Matrix(DMatrix::from_fn(rows.len(), n + 2, |r, j| {
                coefficients[r][j].clone()
            })),
        );
        let integral = DMatrix::from_element(rows.len(), 1, bernstein_integral::<T>(n));
        report.push("integral", Value::Matrix(integral));
        let mut marks = None;
        if self.t.is_some() {
            let values = bernstein_antiderivative_values(n, &rows, &ts).map_err(lib(
                Role::T,
                "parameters whose integrals stay within the range of doubles",
            ))?;
            report.push("t", Value::row(&ts));
            report.push("result", Value::Matrix(values.clone()));
            marks = Some(values);
        }
        let drawing = if self.drawing {
            let picture = bernstein_picture::<T>(n, &rows, cx)?;
            Some(match &marks {
                Some(values) => marked(picture, &ts, values),
                None => picture,
            })
        } else {
            None
        };
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }

    /// The antiderivative of a Bézier curve over `[a, b]`.
    fn bezier(&self, cx: &mut Context, control: &DMatrix<T>) -> Result<Answer<T>> {
        let n = control.ncols().saturating_sub(1);
        cx.check_degree(Role::Control, n.saturating_add(1))?;
        let cost = antiderivative_cost(
            control.ncols(),
            control.nrows(),
            n,
            max_bits(control.iter()),
        );
        cx.check_cost(Role::T, cost, T::EXACT)?;
        let (a, b) = self
            .interval
            .clone()
            .unwrap_or_else(|| (T::zero(), T::one()));
        // The control points and the interval checked apart, each error naming its own
        // argument (an interval [-1e308, 1e308] is the interval's fault, not the points').
        let curve = BezierCurve::new(control.clone())
            .map_err(lib(Role::Control, CONTROL_FORM))?
            .with_interval(a.clone(), b.clone())
            .map_err(lib(
                Role::Interval,
                "two finite ends a < b whose width b - a is a finite double",
            ))?;
        let sums =
            "control points and an interval whose integrals stay within the range of doubles";
        let anti = bezier_antiderivative(&curve).map_err(lib(Role::Control, sums))?;
        let integral = bezier_integral(&curve).map_err(lib(Role::Control, sums))?;
        let ts = self.params((&a, &b), "the antiderivative is extrapolated there", cx)?;
        self.check_values_cost(cx, &anti, &ts)?;
        let mut report = Report::new();
        if self.steps {
            let factor = bezier_antiderivative_factor(&curve).map_err(lib(Role::Control, sums))?;
            report.push("factor", Value::scalar(factor));
        }
        report.push("antiderivative", Value::Matrix(anti.control().clone()));
        report.push("integral", Value::column(&integral));
        if self.t.is_some() {
            let values = eval_points(&anti, &ts, Role::T, cx)?;
            report.push("t", Value::row(&ts));
            report.push("result", Value::Matrix(values));
        }
        let drawing = self.picture(
            cx,
            &anti,
            anti.control(),
            "antiderivative of a Bézier curve",
            "∫ c",
        )?;
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }

    /// The antiderivative of a B-spline curve.
    fn spline(
        &self,
        cx: &mut Context,
        control: &DMatrix<T>,
        arg: &BSplineArg<T>,
    ) -> Result<Answer<T>> {
        let p = arg.degree.degree()?;
        cx.check_degree(Role::Control, p.saturating_add(1))?;
        let cost = antiderivative_cost(
            control.ncols(),
            control.nrows(),
            p,
            max_bits(control.iter()),
        );
        cx.check_cost(Role::T, cost, T::EXACT)?;
        let curve = arg.curve(control.clone())?;
        let anti = bspline_antiderivative(&curve).map_err(lib(Role::Spline, BSPLINE_FORM))?;
        let integral = bspline_integral(&curve).map_err(lib(Role::Spline, BSPLINE_FORM))?;
        let (a, b) = curve.domain();
        let ts = self.params((&a, &b), "the antiderivative is not defined there", cx)?;
        self.check_values_cost(cx, &anti, &ts)?;
        let mut report = Report::new();
        if self.steps {
            report.push(
                "basis_integrals",
                Value::row(&bspline_basis_integrals(&curve)),
            );
        }
        report.push("knots", Value::row(anti.knots().as_slice()));
        report.push("antiderivative", Value::Matrix(anti.control().clone()));
        report.push("integral", Value::column(&integral));
        if self.t.is_some() {
            let values = bspline_integral_to(&anti, a.clone(), &ts).map_err(lib(
                Role::T,
                "parameters inside the domain [u_(p+1), u_(n+1)]",
            ))?;
            report.push("t", Value::row(&ts));
            report.push("result", Value::Matrix(values));
        }
        // The antiderivative's domain [u_(p+1), u_(n+1)] is the curve's (a knot more at each end).
        let title = "antiderivative of a B-spline curve";
        let drawing = self.picture(cx, &anti, anti.control(), title, "∫ C")?;
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }

    /// The parameters asked for on the domain `[a, b]` (none if none).
    fn params(&self, (a, b): (&T, &T), consequence: &str, cx: &mut Context) -> Result<Vec<T>> {
        match &self.t {
            Some(t) => t.resolve(Role::T, (a, b), consequence, cx),
            None => Ok(Vec::new()),
        }
    }

    /// The work of the antiderivative's values at `ts` and at the picture's samples.
    fn check_values_cost<C: Curve<T>>(&self, cx: &Context, anti: &C, ts: &[T]) -> Result<()> {
        let picture = if self.drawing { PICTURE_SAMPLES } else { 0 };
        let at = |bits: u128, count: usize| anti.point_cost(bits).times(count as u128);
        let cost = at(max_bits(ts), ts.len()).and(at(0, picture));
        cx.check_cost(Role::T, cost, T::EXACT)
    }

    /// The antiderivative over `[a, b]` and its control polygon.
    fn picture<C: Curve<T>>(
        &self,
        cx: &Context,
        anti: &C,
        control: &DMatrix<T>,
        title: &str,
        label: &str,
    ) -> Result<Option<Drawing>> {
        if !self.drawing {
            return Ok(None);
        }
        let (a, b) = anti.domain();
        let line = crate::picture::curve_line(anti, (&a, &b), PICTURE_SAMPLES, Role::T, cx)?;
        Ok(Some(
            Drawing::new(title)
                .curve(line, Colour::Blue, label)
                .control_polygon(to_f64(control), "its control polygon"),
        ))
    }
}

/// Samples of a curve in a picture.
const PICTURE_SAMPLES: usize = 201;

/// Each `∫₀ᵗ B_i^N` over `[0, 1]` as the plane curve `(t, ∫₀ᵗ B_i^N)`.
fn bernstein_picture<T: Scalar>(n: usize, rows: &[usize], cx: &Context) -> Result<Drawing> {
    let lines = crate::picture::picture_lines(
        (&T::zero(), &T::one()),
        PICTURE_SAMPLES,
        true,
        |dense| {
            let values = bernstein_antiderivative_values(n, rows, dense)
                .map_err(lib(Role::Degree, "a picture"))?;
            Ok(graph_lines(dense, &values))
        },
        |dense| {
            let cost = bernstein_antiderivative_cost(n, rows.len(), dense.len(), max_bits(dense));
            cx.check_cost(Role::T, cost, T::EXACT).is_ok()
        },
    )?;
    let title = format!("integrals of the Bernstein polynomials of degree {n}");
    let axes = Drawing::graph(title, "t", &format!("∫₀ᵗ B_i^{n}"));
    Ok(graphs(axes, lines, rows, |i| format!("∫ B_{i}^{n}")))
}

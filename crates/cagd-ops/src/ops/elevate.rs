//! `elevate`: the same curve written with a higher degree.
//!
//! A Bézier curve of degree `n` (thesis §2.3, the CAD notes §1.1), one degree at a time:
//! `b'_i = i/(n+1) · b_{i−1} + (1 − i/(n+1)) · b_i`, `i = 0, …, n + 1`. A clamped B-spline
//! curve of degree `p` (the CAD notes §1.2, octave-nurbs `nrbdegelev`) by `r` at once: every
//! distinct knot occurs `r` times more, and the new control points are values of the degree-
//! `(p + r)` blossom.
//!
//! ```
//! use cagd_ops::{execute, ops::Elevate, Context};
//! use num_rational::BigRational;
//! use nalgebra::DMatrix;
//! // The segment 0 → 3 raised by 2: 0, 1, 2, 3.
//! let q = |x: i64| BigRational::from_integer(x.into());
//! let op = Elevate { by: 2, ..Elevate::new(DMatrix::from_row_slice(1, 2, &[q(0), q(3)])) };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("control").unwrap().as_slice(), &[q(0), q(1), q(2), q(3)]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::bezier::BezierCurve;
use cagd::cost::max_bits;
use cagd::{Curve, Scalar};
use nalgebra::DMatrix;

use super::decasteljau::CONTROL_FORM;
use super::to_f64;
use crate::bspline_arg::BSplineArg;
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// Degree elevation of a Bézier or clamped B-spline curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Elevate<T> {
    /// Control points, one per column.
    pub control: DMatrix<T>,
    /// Raise the degree by this much.
    pub by: usize,
    /// A B-spline curve of these degree and knots (else a Bézier curve on `[0, 1]`).
    pub bspline: Option<BSplineArg<T>>,
    /// Every intermediate Bézier polygon (a B-spline's knots before and its new degree).
    pub steps: bool,
    /// A picture: the curve, its polygon and the elevated polygon.
    pub drawing: bool,
}

impl<T> Elevate<T> {
    /// The Bézier curve of `control` raised by one degree.
    pub fn new(control: DMatrix<T>) -> Self {
        Elevate {
            control,
            by: 1,
            bspline: None,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Elevate<T> {
    /// `control` (`d × (n+r+1)`); for a B-spline first `knots`; with steps the intermediate
    /// polygons `degree_<k>` (Bézier) or `knots_before` and `degree` (B-spline).
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        match &self.bspline {
            None => self.bezier(cx),
            Some(arg) => self.spline(cx, arg),
        }
    }
}

impl<T: Scalar> Elevate<T> {
    fn bezier(&self, cx: &mut Context) -> Result<Answer<T>> {
        let n = self.control.ncols().saturating_sub(1);
        cx.check_degree(Role::By, n.saturating_add(self.by))?;
        let curve =
            BezierCurve::new(self.control.clone()).map_err(lib(Role::Control, CONTROL_FORM))?;
        let cost = curve.elevate_cost(self.by, max_bits(self.control.iter()));
        cx.check_cost(
            Role::By,
            cost.and(picture_cost(&curve, self.drawing)),
            T::EXACT,
        )?;
        let mut report = Report::new();
        let mut last = curve.clone();
        for _ in 0..self.by {
            cx.check_interrupt()?;
            last = last.elevate();
            if self.steps {
                // b'_i = i/(n+1) b_{i−1} + (1 − i/(n+1)) b_i at each step.
                let name = format!("degree_{}", last.degree());
                report.push(name, Value::Matrix(last.control().clone()));
            }
        }
        report.push("control", Value::Matrix(last.control().clone()));
        let title = format!("degree elevation {} → {}", curve.degree(), last.degree());
        let drawing = self.picture(cx, &curve, last.control(), title)?;
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }

    fn spline(&self, cx: &mut Context, arg: &BSplineArg<T>) -> Result<Answer<T>> {
        let degree = arg.degree.degree()?;
        cx.check_degree(Role::By, degree.saturating_add(self.by))?;
        let curve = arg.curve(self.control.clone())?;
        let knots = curve.knots().as_slice();
        let cost = curve.elevate_cost(self.by, max_bits(self.control.iter()), max_bits(knots));
        cx.check_cost(
            Role::By,
            cost.and(picture_cost(&curve, self.drawing)),
            T::EXACT,
        )?;
        let elevated = curve.elevate(self.by).map_err(lib(
            Role::Knots,
            "a clamped knot vector (first and last knots p+1 times)",
        ))?;
        let mut report = Report::new();
        if self.steps {
            report.push("knots_before", Value::row(knots));
            report.push("degree", Value::scalar(T::from_usize(elevated.degree())));
        }
        report.push("knots", Value::row(elevated.knots().as_slice()));
        report.push("control", Value::Matrix(elevated.control().clone()));
        let title = format!(
            "B-spline degree elevation {} → {}",
            curve.degree(),
            elevated.degree()
        );
        let drawing = self.picture(cx, &curve, elevated.control(), title)?;
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }

    /// The curve over its domain, its polygon in black and the elevated polygon in red.
    fn picture<C: Curve<T>>(
        &self,
        cx: &Context,
        curve: &C,
        elevated: &DMatrix<T>,
        title: String,
    ) -> Result<Option<Drawing>> {
        if !self.drawing {
            return Ok(None);
        }
        let (a, b) = curve.domain();
        let line = crate::picture::curve_line(curve, (&a, &b), PICTURE_SAMPLES, Role::Control, cx)?;
        Ok(Some(
            Drawing::new(title)
                .curve(line, Colour::Blue, "curve")
                .boundary(to_f64(&self.control), Colour::Black, "original polygon")
                .control_polygon(to_f64(elevated), "elevated polygon"),
        ))
    }
}

/// Samples of the curve in the picture, at first ([`crate::picture`]).
const PICTURE_SAMPLES: usize = 201;

/// The work of the picture's samples of `curve`, if one is drawn.
fn picture_cost<T: Scalar, C: Curve<T>>(curve: &C, drawing: bool) -> cagd::cost::Cost {
    if drawing {
        curve.point_cost(0).times(PICTURE_SAMPLES as u128)
    } else {
        cagd::cost::Cost::default()
    }
}

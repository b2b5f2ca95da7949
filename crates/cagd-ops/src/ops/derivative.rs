//! `derivative`: the `r`-th derivative of a Bézier curve of degree `n` (thesis (2.5) and its
//! repetition), itself a Bézier curve of degree `n − r`:
//!
//! `x^(r)(t) = n!/(n−r)! Σ_{i=0}^{n−r} Δ^r b_i B_i^{n−r}(t)`,
//!
//! its control points `n!/(n−r)! Δ^r b_i`, and its values where asked.
//!
//! ```
//! use cagd_ops::{execute, ops::Derivative, Context, Params};
//! use nalgebra::dmatrix;
//! // Primer 2.4's cubic: x'(1/2) = (9, 0, −3/2), control points 3 Δb_i.
//! let b = dmatrix![0.0, 0.0, 8.0, 4.0; 0.0, 2.0, 2.0, 0.0; 0.0, 2.0, 0.0, 0.0];
//! let op = Derivative { t: Some(Params::Given(vec![0.5])), ..Derivative::new(b, 1) };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[9.0, 0.0, -1.5]);
//! assert_eq!(answer.report.matrix("control").unwrap().column(1).as_slice(), &[24.0, 0.0, -6.0]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::cost::max_bits;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::decasteljau::bezier_on;
use super::{eval_points, point_labels, to_f64};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The derivative of a Bézier curve on `[0, 1]` (or on an interval `[a, b]`: then
/// `x^(r)(t) = n!/(n−r)! / (b − a)^r Σ Δ^r b_i B_i^{n−r}((t − a)/(b − a))`).
#[derive(Debug, Clone, PartialEq)]
pub struct Derivative<T> {
    /// Control points `b_0..b_n`, one per column.
    pub control: DMatrix<T>,
    /// The parameter interval `[a, b]` of the curve (default `[0, 1]`).
    pub interval: Option<(T, T)>,
    /// The order `r` (`r ≤ n`).
    pub order: usize,
    /// Where the derivative's values are wanted (none: its control points only).
    pub t: Option<Params<T>>,
    /// A picture: the derivative curve over `[0, 1]` and its control polygon.
    pub drawing: bool,
}

impl<T> Derivative<T> {
    /// The `order`-th derivative of the curve of `control`, its control points only.
    pub fn new(control: DMatrix<T>, order: usize) -> Self {
        Derivative {
            control,
            interval: None,
            order,
            t: None,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Derivative<T> {
    /// `control` (`d × (n−r+1)`), and with parameters `t` (`1 × k`) and `result` (`d × k`).
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        cx.check_degree(Role::Control, self.control.ncols().saturating_sub(1))?;
        let (curve, (a, b)) = bezier_on(&self.control, self.interval.as_ref())?;
        let derivative = curve
            .derivative(self.order)
            .map_err(lib(Role::DerivativeOrder, "an order r ≤ the degree n"))?;
        let ts = match &self.t {
            Some(t) => t.resolve(
                Role::T,
                (&a, &b),
                "the derivative is extrapolated there",
                cx,
            )?,
            None => Vec::new(),
        };
        let dense = if self.drawing {
            cagd::linspace::linspace_in(&a, &b, 101).map_err(lib(Role::T, "a curve"))?
        } else {
            Vec::new()
        };
        let control_bits = max_bits(derivative.control().iter());
        let at = |params: &[T]| {
            derivative
                .eval_cost(max_bits(params), control_bits)
                .times(params.len() as u128)
        };
        cx.check_cost(Role::T, at(&ts).and(at(&dense)), T::EXACT)?;
        let mut report = Report::new();
        report.push("control", Value::Matrix(derivative.control().clone()));
        let values = if self.t.is_some() {
            let values = eval_points(&derivative, &ts, Role::T, cx)?;
            report.push("t", Value::row(&ts));
            report.push("result", Value::Matrix(values.clone()));
            Some(values)
        } else {
            None
        };
        let drawing = if self.drawing {
            let line = crate::picture::curve_line(&derivative, (&a, &b), dense.len(), Role::T, cx)?;
            let mut drawing = Drawing::new(format!("derivative of order {}", self.order))
                .curve(line, Colour::Blue, "derivative curve")
                .control_polygon(to_f64(derivative.control()), "its control polygon");
            if let Some(values) = values {
                drawing = drawing.points(to_f64(&values), point_labels("t", &ts), "values at t");
            }
            Some(drawing)
        } else {
            None
        };
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }
}

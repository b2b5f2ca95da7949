//! `subdivide`: a Bézier curve on `[a, b]` split at `a < t < b` into the two Bézier curves
//! over `[a, t]` and `[t, b]` (thesis §2.1): their control polygons are the two edges of the
//! de Casteljau scheme at `t`, the diagonal `b_0^0, b_0^1, …, b_0^n` and the last row
//! `b_0^n, b_1^{n−1}, …, b_n^0`.
//!
//! ```
//! use cagd_ops::{execute, ops::Subdivide, Context};
//! use nalgebra::dmatrix;
//! // Primer 2.4: both halves meet at b(1/2) = (7/2, 3/2, 3/4).
//! let b = dmatrix![0.0, 0.0, 8.0, 4.0; 0.0, 2.0, 2.0, 0.0; 0.0, 2.0, 0.0, 0.0];
//! let answer = execute(&Subdivide::new(b), &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("left").unwrap().column(3).as_slice(), &[3.5, 1.5, 0.75]);
//! assert_eq!(answer.report.matrix("right").unwrap().column(1).as_slice(), &[5.0, 1.5, 0.5]);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::cost::max_bits;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::decasteljau::bezier_on;
use super::{eval_points, point_labels, to_f64};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::layout::scheme::{curve_scheme, Marks};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// Samples of the curve in the picture.
const PICTURE_SAMPLES: usize = 101;

/// The subdivision of a Bézier curve at one parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Subdivide<T> {
    /// Control points `b_0..b_n`, one per column.
    pub control: DMatrix<T>,
    /// The parameter interval `[a, b]` (default `[0, 1]`).
    pub interval: Option<(T, T)>,
    /// Where to split (default the middle of the interval).
    pub t: Option<T>,
    /// The de Casteljau scheme with the two control polygons marked.
    pub steps: bool,
    /// A picture: the curve, its control polygon and the two parts' polygons.
    pub drawing: bool,
}

impl<T> Subdivide<T> {
    /// The curve of `control` on `[0, 1]` split in the middle.
    pub fn new(control: DMatrix<T>) -> Self {
        Subdivide {
            control,
            interval: None,
            t: None,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Subdivide<T> {
    /// `t` (`1 × 1`), `left` and `right` (`d × (n+1)`); with steps first `scheme`.
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        cx.check_degree(Role::Control, self.control.ncols().saturating_sub(1))?;
        let (curve, (a, b)) = bezier_on(&self.control, self.interval.as_ref())?;
        let t = self
            .t
            .clone()
            .unwrap_or_else(|| (a.clone() + b.clone()) / T::from_usize(2));
        // One de Casteljau scheme at t (the split), and the picture's points.
        let picture = if self.drawing { PICTURE_SAMPLES } else { 0 };
        let split = curve.eval_cost(
            max_bits(std::slice::from_ref(&t)),
            max_bits(curve.control().iter()),
        );
        cx.check_cost(Role::Control, split.times(1 + picture as u128), T::EXACT)?;
        let (left, right) = curve.subdivide(t.clone()).map_err(lib(
            Role::T,
            "a parameter strictly inside the curve's interval (both parts non-empty)",
        ))?;
        let mut report = Report::new();
        if self.steps {
            let scheme = curve.scheme(t.clone());
            report.push(
                "scheme",
                curve_scheme(&scheme, cx.digits, Marks::Subdivision),
            );
        }
        report.push("t", Value::row(std::slice::from_ref(&t)));
        report.push("left", Value::Matrix(left.control().clone()));
        report.push("right", Value::Matrix(right.control().clone()));
        let drawing = if self.drawing {
            let line = crate::picture::curve_line(&curve, (&a, &b), PICTURE_SAMPLES, Role::T, cx)?;
            let at = eval_points(&curve, std::slice::from_ref(&t), Role::T, cx)?;
            Some(
                Drawing::new("subdivision (de Casteljau)")
                    .curve(line, Colour::Blue, "curve")
                    .boundary(to_f64(curve.control()), Colour::Black, "control polygon")
                    .control_polygon(to_f64(left.control()), "left part")
                    .boundary(to_f64(right.control()), Colour::Green, "right part")
                    .points(
                        to_f64(&at),
                        point_labels("t", std::slice::from_ref(&t)),
                        "split at t",
                    ),
            )
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

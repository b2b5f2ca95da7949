//! `decasteljau`: points of a Bézier curve by de Casteljau's algorithm (thesis algorithm 1),
//! with the whole scheme as steps.
//!
//! `b_i^r(t) = (1 − t) b_i^{r−1}(t) + t b_{i+1}^{r−1}(t)`, `b(t) = b_0^n(t)`; on an interval
//! `[a, b]` (thesis §2.3.2) the weights are `(b − t)/(b − a)` and `(t − a)/(b − a)`.

use cagd::bezier::BezierCurve;
use cagd::cost::max_bits;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::{eval_points, point_labels, to_f64, STEPS_FACTOR};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::layout::scheme::{curve_scheme, Marks};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The form of control points.
pub const CONTROL_FORM: &str = "control points b_0..b_n, one per column";

/// Points of a Bézier curve by de Casteljau's algorithm.
///
/// ```
/// use cagd_ops::{ops::DeCasteljau, Context, Operation, Params};
/// use num_rational::BigRational;
/// use nalgebra::DMatrix;
/// let q = |x: i64| BigRational::from_integer(x.into());
/// // Thesis Primer 2.4: b(1/2) = (7/2, 3/2, 3/4).
/// let control = DMatrix::from_row_slice(3, 4, &[0, 0, 8, 4, 0, 2, 2, 0, 0, 2, 0, 0].map(q));
/// let op = DeCasteljau { t: Params::Given(vec![BigRational::new(1.into(), 2.into())]), ..DeCasteljau::new(control) };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// let x = answer.report.matrix("result").unwrap();
/// assert_eq!(x.column(0).iter().map(|v| v.to_string()).collect::<Vec<_>>(), ["7/2", "3/2", "3/4"]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct DeCasteljau<T> {
    /// Control points `b_0..b_n`, one per column.
    pub control: DMatrix<T>,
    /// The parameter interval `[a, b]` (default `[0, 1]`).
    pub interval: Option<(T, T)>,
    /// The parameters (samples cover `[a, b]`).
    pub t: Params<T>,
    /// The scheme of every parameter as steps.
    pub steps: bool,
    /// A picture: the curve over `[a, b]`, its control polygon and the points at `t`.
    pub drawing: bool,
}

impl<T: Scalar> DeCasteljau<T> {
    /// The curve of `control` at the default parameters, no steps, no picture.
    pub fn new(control: DMatrix<T>) -> Self {
        DeCasteljau {
            control,
            interval: None,
            t: Params::Default,
            steps: false,
            drawing: false,
        }
    }
}

/// The Bézier curve of `control` on `interval` (default `[0, 1]`), with its interval: what
/// every Bézier request with an interval builds first.
///
/// # Errors
/// The library's errors about the control points (an empty interval among them).
pub(crate) fn bezier_on<T: Scalar>(
    control: &DMatrix<T>,
    interval: Option<&(T, T)>,
) -> Result<(BezierCurve<T>, (T, T))> {
    let (a, b) = interval.cloned().unwrap_or_else(|| (T::zero(), T::one()));
    let curve = BezierCurve::new_on_interval(control.clone(), a.clone(), b.clone())
        .map_err(lib(Role::Control, CONTROL_FORM))?;
    Ok((curve, (a, b)))
}

impl<T: Scalar> Operation<T> for DeCasteljau<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        crate::check::points(Role::Control, &self.control, 1, "control points")?;
        cx.check_degree(Role::Control, self.control.ncols().saturating_sub(1))?;
        let (curve, (a, b)) = bezier_on(&self.control, self.interval.as_ref())?;
        let ts = self
            .t
            .resolve(Role::T, (&a, &b), "the curve is extrapolated there", cx)?;
        // The picture always shows the whole curve over [a, b], as the thesis's plot3.
        let dense = if self.drawing {
            cagd::linspace::linspace_in(&a, &b, 101).map_err(lib(Role::T, "a curve"))?
        } else {
            Vec::new()
        };
        let control_bits = max_bits(self.control.iter());
        let at = |params: &[T], times: u128| {
            curve
                .eval_cost(max_bits(params), control_bits)
                .times(params.len() as u128 * times)
        };
        let cost = at(&ts, if self.steps { STEPS_FACTOR } else { 1 }).and(at(&dense, 1));
        cx.check_cost(Role::T, cost, T::EXACT)?;
        let values = eval_points(&curve, &ts, Role::T, cx)?;
        let mut report = Report::new();
        if self.steps {
            for (k, t) in ts.iter().enumerate() {
                let name = if ts.len() == 1 {
                    "scheme".to_string()
                } else {
                    format!("scheme_{}", k + 1)
                };
                report.push(
                    name,
                    curve_scheme(&curve.scheme(t.clone()), cx.digits, Marks::None),
                );
            }
        }
        report.push("t", Value::row(&ts));
        report.push("result", Value::Matrix(values.clone()));
        let drawing = if self.drawing {
            let line = crate::picture::curve_line(&curve, (&a, &b), dense.len(), Role::T, cx)?;
            Some(
                Drawing::new("Bézier curve (de Casteljau)")
                    .curve(line, Colour::Blue, "curve")
                    .control_polygon(to_f64(curve.control()), "control polygon")
                    .points(to_f64(&values), point_labels("t", &ts), "points at t"),
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

//! `circle` and `arc`: circular arcs as exact NURBS curves (the CAD notes §1.3: "conic
//! sections are NURBS"), built as octave-nurbs `nrbcirc`: the sweep is split into 1–4 equal
//! arcs of at most 90°, each a rational quadratic with control points at the arc's ends and at
//! the intersection of their tangents, middle weight `cos(Δ/2)`, joined with double knots.
//!
//! The weights are irrational (`√2/2` for quarter arcs): the request computes in doubles.

use cagd::cost::max_bits;
use cagd::nurbs::NurbsCurve;
use cagd::Curve;

use super::bspline::{picture, picture_line, picture_params, points_in_order};
use crate::error::{lib, Result};
use crate::knots::{self, DOMAIN_FORM};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The form of a circle's radius and centre.
pub const CIRCLE_FORM: &str = "a positive radius and a center of 2 or 3 coordinates";

/// The form of an arc's angles.
pub const ANGLES_FORM: &str = "start and end angles in radians at most one full turn apart";

/// A circle, or a circular arc, as a NURBS curve on `[0, 1]`.
///
/// ```
/// use cagd_ops::{ops::Circle, Context, Operation, Params};
/// let op = Circle { t: Params::Given(vec![0.25]), ..Circle::new(2.0, vec![1.0, -1.0]) };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// let x = answer.report.matrix("result").unwrap();
/// assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15); // a quarter turn
/// assert_eq!(answer.report.matrix("control").unwrap().ncols(), 9);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Circle {
    /// The radius `r > 0`.
    pub radius: f64,
    /// The centre, 2 or 3 coordinates (the circle lies in the plane `z = ` its `z`).
    pub center: Vec<f64>,
    /// The start and end angles of an arc (anticlockwise from the `x` axis), or the full
    /// circle.
    pub angles: Option<(f64, f64)>,
    /// The parameters (samples cover `[0, 1]`; outside it an error).
    pub t: Params<f64>,
    /// The homogeneous coefficients `(w·x, w·y, w)` as octave-nurbs stores them (`coefs`).
    pub steps: bool,
    /// A picture: the arc, its control polygon and the points at `t`.
    pub drawing: bool,
}

impl Circle {
    /// The circle of `radius` about `center` at the default parameters.
    pub fn new(radius: f64, center: Vec<f64>) -> Self {
        Circle {
            radius,
            center,
            angles: None,
            t: Params::Default,
            steps: false,
            drawing: false,
        }
    }

    /// The curve: a radius or centre at fault is about the radius; an arc whose full circle
    /// exists but which does not, about its angles.
    fn curve(&self) -> Result<NurbsCurve<f64>> {
        let circle = NurbsCurve::circle(self.radius, &self.center)
            .map_err(lib(Role::Radius, CIRCLE_FORM))?;
        match self.angles {
            None => Ok(circle),
            Some((a, b)) => NurbsCurve::arc(self.radius, &self.center, a, b)
                .map_err(lib(Role::Angles, ANGLES_FORM)),
        }
    }
}

impl Operation<f64> for Circle {
    fn run(&self, cx: &mut Context) -> Result<Answer<f64>> {
        let curve = self.curve()?;
        let what = (
            if self.angles.is_some() {
                "circular arc"
            } else {
                "circle"
            },
            DOMAIN_FORM,
        );
        let ts = knots::params_within(&self.t, Role::T, (&0.0, &1.0), what, cx)?;
        let dense = picture_params(self.drawing, (&0.0, &1.0))?;
        let per = curve.point_cost(max_bits(&ts));
        cx.check_cost(Role::T, per.times((ts.len() + dense.len()) as u128), false)?;
        let fill = |us: &[f64], out: &mut [f64]| curve.try_eval_many_into(us, out);
        let values = points_in_order((curve.dim(), curve.point_cost(0)), &ts, cx, &fill)?;
        let mut report = Report::new();
        if self.steps {
            report.push(
                "coefs",
                Value::Matrix(curve.homogeneous().control().clone()),
            );
        }
        report.push("knots", Value::row(curve.knots()));
        report.push("control", Value::Matrix(curve.points()));
        report.push("weights", Value::row(&curve.weights()));
        report.push("t", Value::row(&ts));
        report.push("result", Value::Matrix(values.clone()));
        let drawing = if self.drawing {
            let point = |bits| curve.point_cost(bits);
            let line = picture_line((&0.0, &1.0), &fill, curve.dim(), point, cx)?;
            let title = if self.angles.is_some() {
                "circular arc (NURBS)"
            } else {
                "circle (NURBS)"
            };
            Some(picture(title, line, &curve.points(), (&values, &ts)))
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

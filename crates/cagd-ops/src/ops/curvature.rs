//! `curvature`: the curvature `κ = |x′ × x″| / |x′|³` and the Frenet frame `T`, `N`, `B` of a
//! Bézier, B-spline or NURBS curve at parameters `t` ([`cagd::curvature`]). In exact arithmetic
//! the answer is `κ²`, which is rational (`κ` and the frame need a square root).

use cagd::cost::max_bits;
use cagd::curvature::{curvature_cost, curvature_squared, frenet, CurveDeriv2};
use cagd::Scalar;
use nalgebra::DMatrix;

use super::{eval_points, point_labels, to_f64};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The curvature and the Frenet frame of a curve.
///
/// ```
/// use cagd::BezierCurve;
/// use cagd_ops::{execute, ops::Curvature, Context, Params};
/// use nalgebra::dmatrix;
/// // The parabola (t, t²) as a quadratic Bézier curve: κ(1/2) = 2/(1+1)^{3/2} = 1/√2.
/// let parabola = BezierCurve::new(dmatrix![0.0, 0.5, 1.0; 0.0, 0.0, 1.0])?;
/// let op = Curvature { t: Params::Given(vec![0.5]), ..Curvature::new(Box::new(parabola)) };
/// let answer = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
/// let kappa = answer.report.matrix("result").unwrap()[(0, 0)];
/// assert!((kappa - 0.5f64.sqrt()).abs() < 1e-15);
/// # Ok::<(), cagd::Error>(())
/// ```
pub struct Curvature<T: Scalar> {
    /// The curve (it must know its second derivative).
    pub curve: Box<dyn CurveDeriv2<T> + Send + Sync>,
    /// The parameters (samples cover the curve's domain).
    pub t: Params<T>,
    /// `x′` and `x″` at every parameter as steps.
    pub steps: bool,
    /// A picture: the curve, the points, their tangents and normals.
    pub drawing: bool,
}

impl<T: Scalar> std::fmt::Debug for Curvature<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Curvature")
            .field("t", &self.t)
            .field("steps", &self.steps)
            .finish_non_exhaustive()
    }
}

impl<T: Scalar> Curvature<T> {
    /// The curvature of `curve` at the default parameters.
    pub fn new(curve: Box<dyn CurveDeriv2<T> + Send + Sync>) -> Self {
        Curvature {
            curve,
            t: Params::Default,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Curvature<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let c = self.curve.as_ref();
        let (a, b) = c.domain();
        let ts = self
            .t
            .resolve(Role::T, (&a, &b), "the curve is continued there", cx)?;
        // x, x′, x″ cost about three evaluations each, then the curvature itself.
        let bits = max_bits(&ts);
        let per_point = c
            .point_cost(bits)
            .times(3)
            .and(curvature_cost(c.dim(), c.point_cost(bits).bits()));
        cx.check_cost(Role::T, per_point.times(ts.len() as u128), T::EXACT)?;
        let d = c.dim();
        let mut d1 = DMatrix::from_element(d, ts.len(), T::zero());
        let mut d2 = d1.clone();
        for (k, t) in ts.iter().enumerate() {
            cx.check_interrupt()?;
            d1.set_column(k, &c.eval_derivative(t.clone()));
            d2.set_column(k, &c.eval_second_derivative(t.clone()));
        }
        let mut report = Report::new();
        report.push("t", Value::row(&ts));
        if self.steps {
            report.push("d1", Value::Matrix(d1.clone()));
            report.push("d2", Value::Matrix(d2.clone()));
        }
        if T::EXACT {
            let kappa2 = (0..ts.len())
                .map(|k| curvature_squared(&d1.column(k).into(), &d2.column(k).into()))
                .collect::<cagd::Result<Vec<T>>>()
                .map_err(lib(Role::T, "parameters where the tangent is not zero"))?;
            report.push("result", Value::row(&kappa2));
        } else {
            self.frame(&mut report, (&to_f64(&d1), &to_f64(&d2)), &ts, cx)?;
        }
        let drawing = if self.drawing {
            Some(self.picture(&ts, (&to_f64(&d1), &to_f64(&d2)), cx)?)
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

impl<T: Scalar> Curvature<T> {
    /// `κ` (the result), `T`, `N` and, in space, `B` at every parameter.
    fn frame(
        &self,
        report: &mut Report<T>,
        (d1, d2): (&DMatrix<f64>, &DMatrix<f64>),
        ts: &[T],
        cx: &mut Context,
    ) -> Result<()> {
        let d = d1.nrows();
        let k = ts.len();
        let lift = |m: DMatrix<f64>| m.map(|x| T::from_f64(x).unwrap_or_else(T::zero));
        let (mut kappa, mut tangent, mut normal) = (
            DMatrix::zeros(1, k),
            DMatrix::zeros(d, k),
            DMatrix::zeros(d, k),
        );
        let mut binormal = DMatrix::zeros(3, k);
        let mut straight = Vec::new();
        for j in 0..k {
            let f = frenet(&d1.column(j).into(), &d2.column(j).into()).map_err(|e| match e {
                cagd::Error::ShapeMismatch { .. } => {
                    crate::OpError::library(Role::Control, e, "a plane or space curve")
                }
                _ => {
                    crate::OpError::library(Role::T, e, "parameters where the tangent is not zero")
                }
            })?;
            kappa[(0, j)] = f.curvature;
            tangent.set_column(j, &f.tangent);
            match (f.normal, f.binormal) {
                (Some(n), b) => {
                    normal.set_column(j, &n);
                    if let Some(b) = b {
                        binormal.set_column(j, &b);
                    }
                }
                (None, _) => straight.push(crate::number_text(&ts[j])),
            }
        }
        if !straight.is_empty() {
            cx.warn(
                Role::T,
                format!(
                    "the curve is straight (κ = 0) at t = {}: N and B are not defined there and are given as 0",
                    straight.join(", ")
                ),
            );
        }
        report.push("tangent", Value::Matrix(lift(tangent)));
        report.push("normal", Value::Matrix(lift(normal)));
        if d == 3 {
            report.push("binormal", Value::Matrix(lift(binormal)));
        }
        report.push("result", Value::Matrix(lift(kappa)));
        Ok(())
    }

    /// The curve over its domain, the points at `t` with their unit tangents (blue) and
    /// normals (red) drawn from them.
    fn picture(
        &self,
        ts: &[T],
        (d1, d2): (&DMatrix<f64>, &DMatrix<f64>),
        cx: &Context,
    ) -> Result<Drawing> {
        let c = self.curve.as_ref();
        let (a, b) = c.domain();
        let line = crate::picture::curve_line(c, (&a, &b), 201, Role::T, cx)?;
        let points = to_f64(&eval_points(c, ts, Role::T, cx)?);
        let scale = 0.15 * extent(&line);
        let mut drawing = Drawing::new("curvature and Frenet frame")
            .curve(line, Colour::Blue, "curve")
            .points(points.clone(), point_labels("t", ts), "points at t");
        for j in 0..ts.len() {
            let Ok(f) = frenet(&d1.column(j).into(), &d2.column(j).into()) else {
                continue;
            };
            let p = points.column(j).into_owned();
            let arrow =
                |v: &nalgebra::DVector<f64>| DMatrix::from_columns(&[p.clone(), &p + v * scale]);
            let (tl, nl) = if j == 0 { ("T", "N") } else { ("", "") };
            drawing = drawing.curve(arrow(&f.tangent), Colour::Orange, tl);
            if let Some(n) = f.normal {
                drawing = drawing.curve(arrow(&n), Colour::Purple, nl);
            }
        }
        Ok(drawing)
    }
}

/// The largest extent of the points along a coordinate (1 for a single point).
fn extent(points: &DMatrix<f64>) -> f64 {
    let span = points
        .row_iter()
        .map(|r| r.max() - r.min())
        .fold(0.0f64, f64::max);
    if span > 0.0 {
        span
    } else {
        1.0
    }
}

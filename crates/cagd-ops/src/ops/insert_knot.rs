//! `insert-knot`: knot insertion into a B-spline or NURBS curve (Boehm's algorithm, the CAD
//! notes §1.2 "adding a knot"), with each insertion as a step.
//!
//! Inserting `u` into the span `[u_k, u_{k+1})` of a degree-`p` curve replaces the control
//! points `P_{k−p+1} … P_k` by `Q_i = (1 − α_i) P_{i−1} + α_i P_i`,
//! `α_i = (u − u_i)/(u_{i+p} − u_i)`, and keeps the others; the curve does not change. A NURBS
//! curve does this to its homogeneous points `(w P, w)`.

use cagd::bspline::{BSplineCurve, BoehmStep};
use cagd::cost::max_bits;
use cagd::nurbs::NurbsCurve;
use cagd::{Curve, Scalar};
use nalgebra::DMatrix;

use super::bspline::{picture_params, points_in_order, CONTROL_FORM};
use super::nurbs::WEIGHTS_FORM;
use super::{point_labels, to_f64};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::knots::{self, Degree};
use crate::params::check_given;
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of the knots to insert.
pub const INSERT_FORM: &str =
    "knots strictly inside the domain [u_(p+1), u_(n+1)], each at most p + 1 times in the result";

/// Knots inserted into a B-spline or NURBS curve.
///
/// ```
/// use cagd_ops::{ops::InsertKnot, knots::Degree, Context, Operation};
/// use nalgebra::dmatrix;
/// // The quadratic on (0,0), (1,2), (3,2), (4,0) with ¼ inserted: Q_1 = ½P_0 + ½P_1.
/// let op = InsertKnot {
///     degree: Degree::Degree(2),
///     knots: Some(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]),
///     ..InsertKnot::new(dmatrix![0.0, 1.0, 3.0, 4.0; 0.0, 2.0, 2.0, 0.0], vec![0.25])
/// };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// let q = answer.report.matrix("control").unwrap();
/// assert_eq!(q.column(1).as_slice(), &[0.5, 1.0]);
/// assert_eq!(q.ncols(), 5);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct InsertKnot<T> {
    /// Control points, one per column.
    pub control: DMatrix<T>,
    /// The weights of a NURBS curve, one per control point.
    pub weights: Option<Vec<T>>,
    /// The degree (or order).
    pub degree: Degree,
    /// The knots (`n + p + 1`), or the clamped uniform vector on `[0, 1]`.
    pub knots: Option<Vec<T>>,
    /// The knots to insert, in any order, repeats allowed.
    pub insert: Vec<T>,
    /// Each insertion as a step `insert_k`: `u`, `span`, `alpha`, `control` (homogeneous
    /// for NURBS).
    pub steps: bool,
    /// A picture: the curve, its polygon before and after, the points at the new knots.
    pub drawing: bool,
}

impl<T: Scalar> InsertKnot<T> {
    /// `insert` into the clamped cubic B-spline of `control`.
    pub fn new(control: DMatrix<T>, insert: Vec<T>) -> Self {
        InsertKnot {
            control,
            weights: None,
            degree: Degree::Default,
            knots: None,
            insert,
            steps: false,
            drawing: false,
        }
    }

    /// The B-spline curve refined: the curve itself, or a NURBS curve's homogeneous one.
    fn curve(&self, cx: &Context) -> Result<BSplineCurve<T>> {
        let knots = self.knots.as_deref();
        if let Some(w) = &self.weights {
            let c = super::nurbs::curve(&self.control, w, self.degree, knots, cx)?;
            return Ok(c.homogeneous().clone());
        }
        let p = self.degree.resolve(cx)?;
        let knots = knots::knots_or_clamped(knots, p, self.control.ncols(), knots::CURVE)?;
        BSplineCurve::new(p, knots, self.control.clone()).map_err(lib(Role::Control, CONTROL_FORM))
    }
}

impl<T: Scalar> Operation<T> for InsertKnot<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let curve = self.curve(cx)?;
        check_given(Role::At, &self.insert, cx)?;
        let times = if self.steps { 2 } else { 1 };
        let insertion = curve.insertion_cost(self.insert.len(), max_bits(&self.insert));
        let (a, b) = curve.domain();
        let dense = picture_params(self.drawing, (&a, &b))?;
        let picture = curve
            .point_cost(max_bits(&dense))
            .times(dense.len() as u128 + 1);
        cx.check_cost(Role::At, insertion.times(times).and(picture), T::EXACT)?;
        let refined = curve
            .insert_knots(&self.insert)
            .map_err(lib(Role::At, INSERT_FORM))?;
        let mut report = Report::new();
        if self.steps {
            let steps = curve
                .boehm_scheme(&self.insert)
                .map_err(lib(Role::At, INSERT_FORM))?;
            for (k, step) in steps.iter().enumerate() {
                report.push(format!("insert_{}", k + 1), boehm_step(step));
            }
        }
        report.push("knots", Value::row(refined.knots().as_slice()));
        let (before, after) = if self.weights.is_some() {
            let c = projected(&refined)?;
            report.push("control", Value::Matrix(c.points()));
            report.push("weights", Value::row(&c.weights()));
            (projected(&curve)?.points(), c.points())
        } else {
            report.push("control", Value::Matrix(refined.control().clone()));
            (curve.control().clone(), refined.control().clone())
        };
        let drawing = if self.drawing {
            Some(self.picture(&curve, &dense, (&before, &after), cx)?)
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

impl<T: Scalar> InsertKnot<T> {
    /// The curve, the polygons before (black) and after (red), the points at the new knots.
    fn picture(
        &self,
        curve: &BSplineCurve<T>,
        dense: &[T],
        (before, after): (&DMatrix<T>, &DMatrix<T>),
        cx: &Context,
    ) -> Result<Drawing> {
        let eval = |us: &[T]| -> Result<DMatrix<T>> {
            if self.weights.is_some() {
                let c = projected(curve)?;
                points_in_order((c.dim(), c.point_cost(0)), us, cx, &|u, out| {
                    c.try_eval_many_into(u, out)
                })
            } else {
                points_in_order((curve.dim(), curve.point_cost(0)), us, cx, &|u, out| {
                    curve.try_eval_many_into(u, out)
                })
            }
        };
        let (a, b) = curve.domain();
        let line = crate::picture::picture_line(
            (&a, &b),
            dense.len(),
            false,
            |us| eval(us).map(|m| to_f64(&m)),
            |us| crate::picture::allowed(cx, us, |bits| curve.point_cost(bits)),
        )?;
        Ok(Drawing::new("knot insertion (Boehm)")
            .curve(line, Colour::Blue, "curve")
            .boundary(to_f64(before), Colour::Black, "original polygon")
            .control_polygon(to_f64(after), "refined polygon")
            .points(
                to_f64(&eval(&self.insert)?),
                point_labels("u", &self.insert),
                "points at the new knots",
            ))
    }
}

/// The NURBS curve of a homogeneous B-spline curve.
fn projected<T: Scalar>(h: &BSplineCurve<T>) -> Result<NurbsCurve<T>> {
    NurbsCurve::from_homogeneous(h.clone()).map_err(lib(Role::Weights, WEIGHTS_FORM))
}

/// One insertion: `u`, `span` (the `k` of `u_k ≤ u < u_(k+1)`, knots numbered from 1 as the
/// CAD notes number them), `alpha` (`α_{k−p+1} … α_k`) and the new `control` polygon.
fn boehm_step<T: Scalar>(step: &BoehmStep<T>) -> Value<T> {
    Value::record(vec![
        ("u", Value::scalar(step.knot.clone())),
        ("span", Value::scalar(T::from_usize(step.span + 1))),
        ("alpha", Value::row(&step.alphas)),
        ("control", Value::Matrix(step.curve.control().clone())),
    ])
}

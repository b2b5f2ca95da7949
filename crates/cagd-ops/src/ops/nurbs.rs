//! `nurbs`: points of a NURBS curve (the CAD notes §1.3, eq. (4)), with the rational basis
//! functions as steps:
//!
//! `C(u) = Σ_k R_{k,p}(u) P_k`, `R_{k,p}(u) = w_k N_{k,p}(u) / Σ_j w_j N_{j,p}(u)`: the
//! B-spline curve of the homogeneous points `(w_k P_k, w_k)` projected onto `w = 1`.
//!
//! The weights are checked first (one per control point, positive), then the degree and the
//! knots by the one convention of [`crate::knots`].

use cagd::bspline::{basis_cost, BSplineCurve};
use cagd::cost::max_bits;
use cagd::nurbs::NurbsCurve;
use cagd::{Curve, Scalar};
use nalgebra::DMatrix;

use super::bspline::{
    basis_matrix, picture, picture_line, picture_params, points_in_order, CONTROL_FORM,
};
use crate::error::{lib, Result};
use crate::knots::{self, Degree, DOMAIN_FORM};
use crate::{Answer, Context, Operation, Params, Report, Role, Value};

/// The form of NURBS weights.
pub const WEIGHTS_FORM: &str = "one positive weight per control point";

/// Points of a NURBS curve.
///
/// ```
/// use cagd_ops::{ops::Nurbs, knots::Degree, Context, Operation, Params};
/// use num_rational::BigRational;
/// use nalgebra::DMatrix;
/// let q = |a: i64| BigRational::from_integer(a.into());
/// // A quadratic with weights 1, 2, 1 on 0, 1, 2: C(1/3) = 10/13 (the package's example).
/// let op = Nurbs {
///     degree: Degree::Degree(2),
///     t: Params::Given(vec![BigRational::new(1.into(), 3.into())]),
///     ..Nurbs::new(DMatrix::from_row_slice(1, 3, &[q(0), q(1), q(2)]), vec![q(1), q(2), q(1)])
/// };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap()[0].to_string(), "10/13");
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Nurbs<T> {
    /// Control points `P_0..P_{n−1}`, one per column.
    pub control: DMatrix<T>,
    /// The weights, one per control point.
    pub weights: Vec<T>,
    /// The degree (or order).
    pub degree: Degree,
    /// The knots (`n + p + 1`), or the clamped uniform vector on `[0, 1]`.
    pub knots: Option<Vec<T>>,
    /// The parameters (samples cover the domain `[u_(p+1), u_(n+1)]`; outside it an error).
    pub t: Params<T>,
    /// The rational basis functions at `t` as the item `basis` (`k × n`).
    pub basis: bool,
    /// The rational basis as steps.
    pub steps: bool,
    /// A picture: the curve over its domain, its control polygon and the points at `t`.
    pub drawing: bool,
}

impl<T: Scalar> Nurbs<T> {
    /// The clamped cubic of `control` and `weights` at the default parameters.
    pub fn new(control: DMatrix<T>, weights: Vec<T>) -> Self {
        Nurbs {
            control,
            weights,
            degree: Degree::Default,
            knots: None,
            t: Params::Default,
            basis: false,
            steps: false,
            drawing: false,
        }
    }

    /// The curve: the weights checked, the degree resolved, the knots checked (or clamped).
    ///
    /// # Errors
    /// [`crate::Kind::Shape`], [`crate::Kind::Weights`] about the weights; the rules of
    /// [`crate::knots`].
    pub fn curve(&self, cx: &Context) -> Result<NurbsCurve<T>> {
        curve(
            &self.control,
            &self.weights,
            self.degree,
            self.knots.as_deref(),
            cx,
        )
    }
}

/// The NURBS curve of `control` and `weights` of `degree` on `knots` (or clamped).
///
/// # Errors
/// As [`Nurbs::curve`].
pub(crate) fn curve<T: Scalar>(
    control: &DMatrix<T>,
    weights: &[T],
    degree: Degree,
    knots: Option<&[T]>,
    cx: &Context,
) -> Result<NurbsCurve<T>> {
    crate::check::points(Role::Control, control, 1, "control points")?;
    crate::check::finite(Role::Weights, weights)?;
    let h = cagd::nurbs::homogenize("NURBS weights", control, weights)
        .map_err(lib(Role::Weights, WEIGHTS_FORM))?;
    let p = degree.resolve(cx)?;
    let knots = knots::knots_or_clamped(knots, p, control.ncols(), knots::CURVE)?;
    let homogeneous = BSplineCurve::new(p, knots, h).map_err(lib(Role::Control, CONTROL_FORM))?;
    NurbsCurve::from_homogeneous(homogeneous).map_err(lib(Role::Weights, WEIGHTS_FORM))
}

impl<T: Scalar> Operation<T> for Nurbs<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let curve = self.curve(cx)?;
        let (a, b) = curve.domain();
        let ts = knots::params_within(&self.t, Role::T, (&a, &b), ("NURBS", DOMAIN_FORM), cx)?;
        let dense = picture_params(self.drawing, (&a, &b))?;
        let knot_bits = max_bits(curve.knots());
        let at = |params: &[T], basis: bool| {
            let bits = max_bits(params);
            let mut per = curve.point_cost(bits);
            if basis {
                per = per.and(basis_cost(curve.degree(), bits, knot_bits));
            }
            per.times(params.len() as u128)
        };
        let cost = at(&ts, self.basis || self.steps).and(at(&dense, false));
        cx.check_cost(Role::T, cost, T::EXACT)?;
        let fill = |us: &[T], out: &mut [T]| curve.try_eval_many_into(us, out);
        let values = points_in_order((curve.dim(), curve.point_cost(0)), &ts, cx, &fill)?;
        let mut report = Report::new();
        if self.basis || self.steps {
            let rows = (0..ts.len()).map(|k| curve.basis(&ts[k]));
            report.push("basis", basis_matrix(rows, ts.len(), self.control.ncols())?);
        }
        report.push("t", Value::row(&ts));
        report.push("result", Value::Matrix(values.clone()));
        let drawing = if self.drawing {
            let point = |bits| curve.point_cost(bits);
            let line = picture_line((&a, &b), &fill, curve.dim(), point, cx)?;
            Some(picture(
                "NURBS curve",
                line,
                &curve.points(),
                (&values, &ts),
            ))
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

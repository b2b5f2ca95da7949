//! `bspline`: points of a B-spline curve (the CAD notes eq. (3), the lecture notes "B-spline
//! křivky"), with the basis functions and de Boor's scheme as steps:
//!
//! `C(u) = Σ_{i=1}^{n} P_i N_{i,p}(u)`, `u ∈ [u_(p+1), u_(n+1)]` (knots and control points
//! numbered from 1, as the CAD notes number them); de Boor's levels
//! `d_i^r = (1 − α_i^r) d_{i−1}^{r−1} + α_i^r d_i^{r−1}`, `α_i^r = (u − u_i)/(u_{i+p+1−r} − u_i)`.
//!
//! The degree and the knots follow the one convention of [`crate::knots`].

use cagd::bspline::{basis_cost, BSplineCurve, DeBoorScheme};
use cagd::cost::{max_bits, Cost};
use cagd::{Curve, Scalar};
use nalgebra::DMatrix;

use super::{point_labels, to_f64};
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Result};
use crate::knots::{self, Degree, DOMAIN_FORM};
use crate::{Answer, Context, Item, Operation, Params, Report, Role, Value};

/// The form of control points.
pub const CONTROL_FORM: &str = "control points P_0..P_(n−1), one per column";

/// Samples of a spline's picture.
pub(crate) const PICTURE_SAMPLES: usize = 201;

/// Points of a B-spline curve.
///
/// ```
/// use cagd_ops::{ops::BSpline, knots::Degree, Context, Operation, Params};
/// use nalgebra::dmatrix;
/// // The quadratic on (0,0), (1,2), (3,2), (4,0), knots 0,0,0,½,1,1,1: C(½) = (2, 2).
/// let op = BSpline {
///     degree: Degree::Degree(2),
///     knots: Some(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]),
///     t: Params::Given(vec![0.5]),
///     ..BSpline::new(dmatrix![0.0, 1.0, 3.0, 4.0; 0.0, 2.0, 2.0, 0.0])
/// };
/// let answer = op.run(&mut Context::new(cagd::Limits::default()))?;
/// assert_eq!(answer.report.matrix("result").unwrap().as_slice(), &[2.0, 2.0]);
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSpline<T> {
    /// Control points `P_0..P_{n−1}`, one per column.
    pub control: DMatrix<T>,
    /// The degree (or order).
    pub degree: Degree,
    /// The knots (`n + p + 1`), or the clamped uniform vector on `[0, 1]`.
    pub knots: Option<Vec<T>>,
    /// The parameters (samples cover the domain `[u_(p+1), u_(n+1)]`; outside it an error).
    pub t: Params<T>,
    /// The basis functions at `t` as the item `basis` (`k × n`, row = parameter).
    pub basis: bool,
    /// The basis and the de Boor scheme of every parameter (`de_boor`: `t`, `span`,
    /// `alpha1..`, levels `d0..dp`).
    pub steps: bool,
    /// A picture: the curve over its domain, its control polygon and the points at `t`.
    pub drawing: bool,
}

impl<T: Scalar> BSpline<T> {
    /// The clamped cubic of `control` at the default parameters.
    pub fn new(control: DMatrix<T>) -> Self {
        BSpline {
            control,
            degree: Degree::Default,
            knots: None,
            t: Params::Default,
            basis: false,
            steps: false,
            drawing: false,
        }
    }

    /// The curve: the degree resolved, the knots checked (or clamped).
    ///
    /// # Errors
    /// The rules of [`crate::knots`]; non-finite control points.
    pub fn curve(&self, cx: &Context) -> Result<BSplineCurve<T>> {
        crate::check::points(Role::Control, &self.control, 1, "control points")?;
        let p = self.degree.resolve(cx)?;
        let n = self.control.ncols();
        let knots = knots::knots_or_clamped(self.knots.as_deref(), p, n, knots::CURVE)?;
        BSplineCurve::new(p, knots, self.control.clone()).map_err(lib(Role::Control, CONTROL_FORM))
    }
}

impl<T: Scalar> Operation<T> for BSpline<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let curve = self.curve(cx)?;
        let (a, b) = curve.domain();
        let ts = knots::params_within(&self.t, Role::T, (&a, &b), ("B-spline", DOMAIN_FORM), cx)?;
        let dense = picture_params(self.drawing, (&a, &b))?;
        let knot_bits = max_bits(curve.knots().as_slice());
        let at = |params: &[T], steps: bool, basis: bool| {
            let bits = max_bits(params);
            let point = curve.point_cost(bits);
            let mut per = point;
            if basis || steps {
                per = per.and(basis_cost(curve.degree(), bits, knot_bits));
            }
            if steps {
                per = per.and(point);
            }
            per.times(params.len() as u128)
        };
        let cost = at(&ts, self.steps, self.basis).and(at(&dense, false, false));
        cx.check_cost(Role::T, cost, T::EXACT)?;
        let fill = |us: &[T], out: &mut [T]| curve.try_eval_many_into(us, out);
        let values = points_in_order((curve.dim(), curve.point_cost(0)), &ts, cx, &fill)?;
        let mut report = Report::new();
        if self.basis || self.steps {
            let rows = (0..ts.len()).map(|k| curve.basis(&ts[k]));
            report.push(
                "basis",
                basis_matrix(rows, ts.len(), curve.control().ncols())?,
            );
        }
        if self.steps {
            for (k, t) in ts.iter().enumerate() {
                let scheme = curve
                    .de_boor_scheme(t.clone())
                    .map_err(lib(Role::T, DOMAIN_FORM))?;
                report.push(step_name("de_boor", k, ts.len()), de_boor(t, &scheme));
            }
        }
        report.push("t", Value::row(&ts));
        report.push("result", Value::Matrix(values.clone()));
        let drawing = if self.drawing {
            let point = |bits| curve.point_cost(bits);
            let line = picture_line((&a, &b), &fill, curve.dim(), point, cx)?;
            Some(picture(
                "B-spline curve",
                line,
                curve.control(),
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

/// `name` for one parameter, `name_k` for the `k`-th of several.
pub(crate) fn step_name(name: &str, k: usize, count: usize) -> String {
    if count == 1 {
        name.to_string()
    } else {
        format!("{name}_{}", k + 1)
    }
}

/// The de Boor scheme at `t`: `t`, `span` (the `k` of `u_k ≤ t < u_(k+1)` with the knots
/// numbered from 1, as the CAD notes number them — one more than the core's index from 0),
/// then per level `alpha{r}` (from level 1) and `d{r}` (`d × (p + 1 − r)`).
fn de_boor<T: Scalar>(t: &T, scheme: &DeBoorScheme<T>) -> Value<T> {
    let item = |name: String, value: Value<T>| Item { name, value };
    let mut parts = vec![
        item("t".into(), Value::scalar(t.clone())),
        item("span".into(), Value::scalar(T::from_usize(scheme.span + 1))),
    ];
    for (r, level) in scheme.levels.iter().enumerate() {
        if r > 0 {
            parts.push(item(format!("alpha{r}"), Value::row(&scheme.alphas[r - 1])));
        }
        parts.push(item(format!("d{r}"), Value::Matrix(level.clone())));
    }
    Value::Record(parts)
}

/// The basis rows (one per parameter, `n` values each) as a `k × n` matrix.
pub(crate) fn basis_matrix<T: Scalar>(
    rows: impl Iterator<Item = cagd::Result<Vec<T>>>,
    k: usize,
    n: usize,
) -> Result<Value<T>> {
    let mut flat = Vec::with_capacity(k * n);
    for row in rows {
        flat.extend(row.map_err(lib(Role::T, DOMAIN_FORM))?);
    }
    Ok(Value::Matrix(DMatrix::from_row_slice(k, n, &flat)))
}

/// The parameters of a spline's picture: [`PICTURE_SAMPLES`] over its domain, if drawn.
pub(crate) fn picture_params<T: Scalar>(drawn: bool, (a, b): (&T, &T)) -> Result<Vec<T>> {
    if !drawn {
        return Ok(Vec::new());
    }
    cagd::linspace::linspace_in(a, b, PICTURE_SAMPLES).map_err(lib(Role::T, "a curve"))
}

/// The polyline of a spline's picture over `[a, b]`: from [`PICTURE_SAMPLES`] samples, as
/// many as make its chords short ([`crate::picture::picture_line`]), a point costing
/// `point(bits)`.
pub(crate) fn picture_line<T: Scalar>(
    (a, b): (&T, &T),
    fill: &Fill<T>,
    dim: usize,
    point: impl Fn(u128) -> cagd::cost::Cost,
    cx: &Context,
) -> Result<DMatrix<f64>> {
    crate::picture::picture_line(
        (a, b),
        PICTURE_SAMPLES,
        false,
        |ts| points_in_order((dim, point(0)), ts, cx, fill).map(|m| to_f64(&m)),
        |ts| crate::picture::allowed(cx, ts, &point),
    )
}

/// A spline's picture: the curve (its polyline `line`), its control polygon, the points at
/// `t`.
pub(crate) fn picture<T: Scalar>(
    title: &str,
    line: DMatrix<f64>,
    control: &DMatrix<T>,
    (values, ts): (&DMatrix<T>, &[T]),
) -> Drawing {
    Drawing::new(title)
        .curve(line, Colour::Blue, "curve")
        .control_polygon(to_f64(control), "control polygon")
        .points(to_f64(values), point_labels("t", ts), "points at t")
}

/// An evaluation of a spline at parameters into a buffer (`d` values per parameter).
pub(crate) type Fill<'a, T> = dyn Fn(&[T], &mut [T]) -> cagd::Result<()> + 'a;

/// The points at `ts` (in the domain) by `fill` — a spline's evaluation in the operation
/// order of octave-nurbs (`bspeval`, `nrbeval`), the values of `try_eval` bit for bit —
/// `d × k`, a chunk at a time between which the front end may interrupt (chunks of about
/// [`CHECK_WORK`](super::CHECK_WORK) operations, each point weighing `per_point`).
pub(crate) fn points_in_order<T: Scalar>(
    (d, per_point): (usize, Cost),
    ts: &[T],
    cx: &Context,
    fill: &Fill<'_, T>,
) -> Result<DMatrix<T>> {
    let mut out = DMatrix::from_element(d, ts.len(), T::zero());
    let chunk = super::chunk_points(per_point.weigh(T::EXACT));
    for (chunk, buffer) in ts
        .chunks(chunk)
        .zip(out.as_mut_slice().chunks_mut(chunk * d.max(1)))
    {
        cx.check_interrupt()?;
        fill(chunk, buffer).map_err(lib(Role::T, DOMAIN_FORM))?;
    }
    Ok(out)
}

//! `cagd.BezierCurve` (thesis §2): the core's [`BezierCurve`], points as rows. The patch is in
//! [`super::bezier_patch`].

use cagd::bezier::BezierCurve;
use cagd_ops::error::lib;
use cagd_ops::ops::{Derivative, Elevate, Subdivide};
use cagd_ops::Role;
use pyo3::prelude::*;

use super::shared::{build, exactness, on, point_out, Ex, Exact};
use super::steps::{request_steps, steps_getter, Steps, StepsOf};
use crate::convert::{points_as_rows, rows_out, Num};
use crate::error::IntoPy;
use crate::ops::{execute, item, with_context, Names};

/// How `BezierCurve` names the roles of its requests.
const CURVE_NAMES: Names = &[
    (Role::Control, "points"),
    (Role::DerivativeOrder, "r"),
    (Role::By, "times"),
    (Role::T, "t"),
];

type CurveEx = Ex<BezierCurve<f64>, BezierCurve<Exact>>;

/// A Bézier curve `b(t) = Σ_{i=0}^n b_i B_i^n(t)`, `t ∈ [0, 1]` (thesis (2.1)), with the control
/// points `b_0 … b_n` as the rows of an `(n+1, d)` array.
///
/// Exact with `exact=True` or `Fraction` entries; then every result is in `Fraction`s. A curve
/// made by `elevate` or `subdivide` keeps the steps of that construction (`steps`).
///
/// >>> c = cagd.BezierCurve([[0, 0, 0], [0, 2, 2], [8, 2, 0], [4, 0, 0]], exact=True)
/// >>> [str(x) for x in c(Fraction(1, 2))]          # thesis Primer 2.4
/// ['7/2', '3/2', '3/4']
/// >>> left, right = c.subdivide(Fraction(1, 2))
/// >>> left.control_points[-1].tolist() == right.control_points[0].tolist()
/// True
/// >>> left.steps["scheme.r3"].tolist()               # the point on the curve, b_0^3
/// [[Fraction(7, 2), Fraction(3, 2), Fraction(3, 4)]]
/// >>> c.elevate().control_points[1].tolist()
/// [Fraction(0, 1), Fraction(3, 2), Fraction(3, 2)]
// The doc comment is the class's Python docstring: its examples index arrays and print lists
// (`[1]`, `[[0], [1]]`), which are no Rust links.
#[allow(rustdoc::broken_intra_doc_links)]
#[pyclass(module = "cagd", name = "BezierCurve", frozen)]
#[derive(Clone)]
pub struct PyBezierCurve {
    pub(crate) inner: CurveEx,
    /// The steps of the construction that made the curve.
    pub(crate) steps: Option<StepsOf>,
}

impl PyBezierCurve {
    /// The Python object of a core curve (given directly: no steps).
    pub fn from_inner(inner: CurveEx) -> Self {
        PyBezierCurve { inner, steps: None }
    }

    fn with_steps(inner: CurveEx, steps: StepsOf) -> Self {
        PyBezierCurve {
            inner,
            steps: Some(steps),
        }
    }
}

/// The curve of the control points: the operation layer's checks of a Bézier curve's points
/// (at least one, finite, the degree within the limit), as its requests make them.
fn new_curve<T: Num>(points: &Bound<'_, PyAny>) -> PyResult<BezierCurve<T>> {
    let control = points_as_rows::<T>(points, "points")?;
    with_context(points.py(), CURVE_NAMES, |cx| {
        cagd_ops::check::points(Role::Control, &control, 1, "control points")?;
        cx.check_degree(Role::Control, control.ncols().saturating_sub(1))?;
        BezierCurve::new(control).map_err(lib(Role::Control, cagd_ops::ops::BEZIER_CONTROL_FORM))
    })
}

/// The curve on `[a, b]` of the control points `name` of a request's report.
fn curve_item<T: Num>(
    report: &cagd_ops::Report<T>,
    name: &str,
    (a, b): (&T, &T),
) -> PyResult<BezierCurve<T>> {
    BezierCurve::new_on_interval(item(report, name)?, a.clone(), b.clone()).py()
}

/// The interval of `c`, owned.
fn interval<T: Num>(c: &BezierCurve<T>) -> (T, T) {
    let (a, b) = c.interval();
    (a.clone(), b.clone())
}

/// The derivative of order `r` (on the curve's interval) by the request [`Derivative`].
fn derivative<T: Num>(py: Python<'_>, c: &BezierCurve<T>, r: usize) -> PyResult<BezierCurve<T>> {
    let op = Derivative {
        interval: Some(interval(c)),
        ..Derivative::new(c.control().clone(), r)
    };
    curve_item(&execute(py, CURVE_NAMES, &op)?, "control", c.interval())
}

/// The curve elevated `times` times by the request [`Elevate`] (on the curve's interval: the
/// elevated control points do not depend on it), with its steps: the polygon of every degree.
fn elevate<T: Num>(
    py: Python<'_>,
    c: &BezierCurve<T>,
    times: usize,
) -> PyResult<(BezierCurve<T>, StepsOf)> {
    let op = Elevate {
        by: times,
        ..Elevate::new(c.control().clone())
    };
    let elevated = curve_item(&execute(py, CURVE_NAMES, &op)?, "control", c.interval())?;
    let title = format!("degree elevation {} → {}", c.degree(), elevated.degree());
    let steps = Elevate { steps: true, ..op };
    Ok((elevated, request_steps(steps, CURVE_NAMES, title, &[])))
}

/// The two halves at `t` by the request [`Subdivide`], on `[a, t]` and `[t, b]`, with the
/// steps of both: the de Casteljau scheme at `t`, the halves' points marked on its edges.
fn subdivide<T: Num>(
    c: &BezierCurve<T>,
    t: &Bound<'_, PyAny>,
) -> PyResult<(BezierCurve<T>, BezierCurve<T>, StepsOf)> {
    let at = T::scalar(t, "t")?;
    let op = Subdivide {
        interval: Some(interval(c)),
        t: Some(at.clone()),
        ..Subdivide::new(c.control().clone())
    };
    let report = execute(t.py(), CURVE_NAMES, &op)?;
    let (a, b) = c.interval();
    let title = "subdivision by de Casteljau's scheme".to_string();
    Ok((
        curve_item(&report, "left", (a, &at))?,
        curve_item(&report, "right", (&at, b))?,
        request_steps(Subdivide { steps: true, ..op }, CURVE_NAMES, title, &[]),
    ))
}

#[pymethods]
impl PyBezierCurve {
    #[new]
    #[pyo3(signature = (points, exact = None))]
    fn new(points: &Bound<'_, PyAny>, exact: Option<bool>) -> PyResult<Self> {
        let exact = exactness(exact, &[points])?;
        Ok(Self::from_inner(build!(exact, new_curve(points))))
    }

    /// The degree `n`.
    #[getter]
    fn degree(&self) -> usize {
        on!(self.inner, c => c.degree())
    }

    /// The control points, `(n+1, d)`.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => rows_out(py, c.control()))
    }

    /// The whole de Casteljau scheme at `t`: `b_i^r = (1−t) b_i^{r−1} + t b_{i+1}^{r−1}`
    /// (thesis (2.2)); level `r` holds `b_0^r … b_{n−r}^r` as rows, the last is `b(t)`.
    fn scheme(&self, py: Python<'_>, t: &Bound<'_, PyAny>) -> PyResult<Steps> {
        on!(self.inner, c => scheme_steps(py, c, t))
    }

    /// The derivative of order `r` as a Bézier curve of degree `n − r`:
    /// `b^{(r)}(t) = n!/(n−r)! Σ Δ^r b_i B_i^{n−r}(t)` (thesis (2.4)).
    #[pyo3(signature = (r = 1))]
    fn derivative(&self, py: Python<'_>, r: usize) -> PyResult<Self> {
        Ok(Self::from_inner(match &self.inner {
            Ex::F(c) => Ex::F(derivative(py, c, r)?),
            Ex::E(c) => Ex::E(derivative(py, c, r)?),
        }))
    }

    /// The same curve of degree `n + times`: `b_i^{(1)} = i/(n+1) b_{i−1} + (1 − i/(n+1)) b_i`;
    /// its `steps` are the polygons of every degree on the way.
    #[pyo3(signature = (times = 1))]
    fn elevate(&self, py: Python<'_>, times: usize) -> PyResult<Self> {
        Ok(match &self.inner {
            Ex::F(c) => {
                let (e, steps) = elevate(py, c, times)?;
                Self::with_steps(Ex::F(e), steps)
            }
            Ex::E(c) => {
                let (e, steps) = elevate(py, c, times)?;
                Self::with_steps(Ex::E(e), steps)
            }
        })
    }

    /// The two halves at `t`: their control points are the two edges of the scheme at `t`
    /// (both halves' `steps`: that scheme, the diagonal marked `L`, the last row `R`).
    fn subdivide(&self, t: &Bound<'_, PyAny>) -> PyResult<(Self, Self)> {
        Ok(match &self.inner {
            Ex::F(c) => {
                let (a, b, steps) = subdivide(c, t)?;
                (
                    Self::with_steps(Ex::F(a), steps.clone()),
                    Self::with_steps(Ex::F(b), steps),
                )
            }
            Ex::E(c) => {
                let (a, b, steps) = subdivide(c, t)?;
                (
                    Self::with_steps(Ex::E(a), steps.clone()),
                    Self::with_steps(Ex::E(b), steps),
                )
            }
        })
    }

    /// The curve run backwards, `b(1 − t)`.
    fn reversed(&self) -> Self {
        Self::from_inner(match &self.inner {
            Ex::F(c) => Ex::F(c.reversed()),
            Ex::E(c) => Ex::E(c.reversed()),
        })
    }

    /// `∫_0^1 b(t) dt = (b_0 + … + b_n)/(n + 1)` (the CAD notes), a point.
    fn integral<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => point_out(py, &cagd::integral::bezier_integral(c).py()?))
    }

    /// The antiderivative `∫_0^t b`, degree `n + 1`, control points the partial sums
    /// `Σ_{j<i} b_j/(n+1)`.
    fn antiderivative(&self) -> PyResult<Self> {
        Ok(Self::from_inner(match &self.inner {
            Ex::F(c) => Ex::F(cagd::integral::bezier_antiderivative(c).py()?),
            Ex::E(c) => Ex::E(cagd::integral::bezier_antiderivative(c).py()?),
        }))
    }

    /// The same curve as a B-spline of one span (knots `0` and `1`, each `n + 1` times).
    fn to_bspline(&self) -> super::splines::PyBSplineCurve {
        super::splines::PyBSplineCurve::from_inner(match &self.inner {
            Ex::F(c) => Ex::F(cagd::BSplineCurve::from_bezier(c)),
            Ex::E(c) => Ex::E(cagd::BSplineCurve::from_bezier(c)),
        })
    }
}

super::shared::curve_methods!(PyBezierCurve, "BezierCurve");
steps_getter!(PyBezierCurve);

fn scheme_steps<T: Num>(
    py: Python<'_>,
    c: &BezierCurve<T>,
    t: &Bound<'_, PyAny>,
) -> PyResult<Steps> {
    let s = c.scheme(T::scalar(t, "t")?);
    let mut items = Vec::new();
    for (r, level) in s.levels().iter().enumerate() {
        items.push((format!("r = {r}"), rows_out(py, level)?.unbind()));
    }
    items.push(("point".into(), point_out(py, &s.point_on_curve())?.unbind()));
    Ok(Steps::new(
        "de Casteljau scheme",
        Some(s.to_string()),
        items,
    ))
}

/// Registers the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyBezierCurve>()
}

//! `cagd.BezierCurve` and `cagd.BezierPatch` (thesis §2–3): the core's [`BezierCurve`] and
//! [`BezierPatch`], points as rows.

use cagd::bezier::{BezierCurve, BezierPatch, Edge};
use cagd_ops::error::lib;
use cagd_ops::ops::{Derivative, Elevate, Subdivide};
use cagd_ops::Role;
use pyo3::prelude::*;

use super::shared::{build, exactness, on, point_out, Ex, Exact};
use super::steps::Steps;
use crate::convert::{net_in, net_out, points_as_rows, rows_out, Num};
use crate::error::IntoPy;
use crate::ops::{execute, item, with_context, Names};

/// How `BezierCurve` names the roles of its requests.
const CURVE_NAMES: Names = &[
    (Role::Control, "points"),
    (Role::DerivativeOrder, "r"),
    (Role::By, "times"),
    (Role::T, "t"),
];

/// How `BezierPatch` names the roles of its checks.
const PATCH_NAMES: Names = &[(Role::Net, "net")];

type CurveEx = Ex<BezierCurve<f64>, BezierCurve<Exact>>;
type PatchEx = Ex<BezierPatch<f64>, BezierPatch<Exact>>;

/// A Bézier curve `b(t) = Σ_{i=0}^n b_i B_i^n(t)`, `t ∈ [0, 1]` (thesis (2.1)), with the control
/// points `b_0 … b_n` as the rows of an `(n+1, d)` array.
///
/// Exact with `exact=True` or `Fraction` entries; then every result is in `Fraction`s.
///
/// >>> c = cagd.BezierCurve([[0, 0, 0], [0, 2, 2], [8, 2, 0], [4, 0, 0]], exact=True)
/// >>> [str(x) for x in c(Fraction(1, 2))]          # thesis Primer 2.4
/// ['7/2', '3/2', '3/4']
#[pyclass(module = "cagd", name = "BezierCurve", frozen)]
#[derive(Clone)]
pub struct PyBezierCurve {
    pub(crate) inner: CurveEx,
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
/// elevated control points do not depend on it).
fn elevate<T: Num>(py: Python<'_>, c: &BezierCurve<T>, times: usize) -> PyResult<BezierCurve<T>> {
    let op = Elevate {
        by: times,
        ..Elevate::new(c.control().clone())
    };
    curve_item(&execute(py, CURVE_NAMES, &op)?, "control", c.interval())
}

/// The two halves at `t` by the request [`Subdivide`], on `[a, t]` and `[t, b]`.
fn subdivide<T: Num>(
    c: &BezierCurve<T>,
    t: &Bound<'_, PyAny>,
) -> PyResult<(BezierCurve<T>, BezierCurve<T>)> {
    let at = T::scalar(t, "t")?;
    let op = Subdivide {
        interval: Some(interval(c)),
        t: Some(at.clone()),
        ..Subdivide::new(c.control().clone())
    };
    let report = execute(t.py(), CURVE_NAMES, &op)?;
    let (a, b) = c.interval();
    Ok((
        curve_item(&report, "left", (a, &at))?,
        curve_item(&report, "right", (&at, b))?,
    ))
}

fn wrap_curve(inner: CurveEx) -> PyBezierCurve {
    PyBezierCurve { inner }
}

#[pymethods]
impl PyBezierCurve {
    #[new]
    #[pyo3(signature = (points, exact = None))]
    fn new(points: &Bound<'_, PyAny>, exact: Option<bool>) -> PyResult<Self> {
        let exact = exactness(exact, &[points])?;
        Ok(wrap_curve(build!(exact, new_curve(points))))
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
        Ok(wrap_curve(match &self.inner {
            Ex::F(c) => Ex::F(derivative(py, c, r)?),
            Ex::E(c) => Ex::E(derivative(py, c, r)?),
        }))
    }

    /// The same curve of degree `n + times`: `b_i^{(1)} = i/(n+1) b_{i−1} + (1 − i/(n+1)) b_i`.
    #[pyo3(signature = (times = 1))]
    fn elevate(&self, py: Python<'_>, times: usize) -> PyResult<Self> {
        Ok(wrap_curve(match &self.inner {
            Ex::F(c) => Ex::F(elevate(py, c, times)?),
            Ex::E(c) => Ex::E(elevate(py, c, times)?),
        }))
    }

    /// The two halves at `t`: their control points are the two edges of the scheme at `t`.
    fn subdivide(&self, t: &Bound<'_, PyAny>) -> PyResult<(Self, Self)> {
        Ok(match &self.inner {
            Ex::F(c) => {
                let (a, b) = subdivide(c, t)?;
                (wrap_curve(Ex::F(a)), wrap_curve(Ex::F(b)))
            }
            Ex::E(c) => {
                let (a, b) = subdivide(c, t)?;
                (wrap_curve(Ex::E(a)), wrap_curve(Ex::E(b)))
            }
        })
    }

    /// The curve run backwards, `b(1 − t)`.
    fn reversed(&self) -> Self {
        wrap_curve(match &self.inner {
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
        Ok(wrap_curve(match &self.inner {
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
super::shared::surface_methods!(PyBezierPatch, "BezierPatch");

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

/// A tensor-product Bézier patch `x(u, v) = Σ_i Σ_j b_ij B_i^m(u) B_j^n(v)` on `[0, 1]²`
/// (thesis (3.1)), the control net an `(m+1, n+1, d)` array, `net[i, j] = b_ij`.
///
/// `patch(u, v)` evaluates on the grid `u × v`: shape `(len(u), len(v), d)` (numbers: `(d,)`).
#[pyclass(module = "cagd", name = "BezierPatch", frozen)]
#[derive(Clone)]
pub struct PyBezierPatch {
    pub(crate) inner: PatchEx,
}

/// The patch of the net: the operation layer's checks of a Bézier patch's net (finite, the
/// degree within the limit), as its request makes them.
fn new_patch<T: Num>(net: &Bound<'_, PyAny>) -> PyResult<BezierPatch<T>> {
    let coords = net_in::<T>(net, "net")?;
    let (m, n) = coords.first().map_or((0, 0), |c| (c.nrows(), c.ncols()));
    with_context(net.py(), PATCH_NAMES, |cx| {
        cagd_ops::check::finite(Role::Net, coords.iter().flat_map(|c| c.iter()))?;
        cx.check_degree(Role::Net, m.max(n).saturating_sub(1))?;
        BezierPatch::new(coords).map_err(lib(Role::Net, cagd_ops::ops::BEZIER_NET_FORM))
    })
}

fn edge(name: &str) -> PyResult<Edge> {
    match name {
        "u0" => Ok(Edge::U0),
        "u1" => Ok(Edge::U1),
        "v0" => Ok(Edge::V0),
        "v1" => Ok(Edge::V1),
        _ => Err(crate::error::conversion(
            "edge",
            "expected 'u0', 'u1', 'v0' or 'v1'",
        )),
    }
}

#[pymethods]
impl PyBezierPatch {
    #[new]
    #[pyo3(signature = (net, exact = None))]
    fn new(net: &Bound<'_, PyAny>, exact: Option<bool>) -> PyResult<Self> {
        let exact = exactness(exact, &[net])?;
        Ok(PyBezierPatch {
            inner: build!(exact, new_patch(net)),
        })
    }

    /// The degrees `(m, n)`.
    #[getter]
    fn degree(&self) -> (usize, usize) {
        on!(self.inner, p => p.degree())
    }

    /// The control net, `(m+1, n+1, d)`.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, p => net_out(py, p.coordinates()))
    }

    /// The tensor de Casteljau scheme at `(u, v)` (thesis Algoritem 3): `min(m, n)` bilinear
    /// steps, then linear steps in the direction whose degree remains; level `k` is an array
    /// `(rows, cols, d)`.
    fn scheme(
        &self,
        py: Python<'_>,
        u: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
    ) -> PyResult<Steps> {
        on!(self.inner, p => patch_scheme(py, p, u, v))
    }

    /// The partial derivative `∂^{r+s} x/∂u^r ∂v^s` as a Bézier patch.
    #[pyo3(signature = (r = 1, s = 0))]
    fn derivative(&self, r: usize, s: usize) -> PyResult<Self> {
        Ok(PyBezierPatch {
            inner: match &self.inner {
                Ex::F(p) => Ex::F(p.derivative(r, s).py()?),
                Ex::E(p) => Ex::E(p.derivative(r, s).py()?),
            },
        })
    }

    /// The boundary curve `'u0'` (`x(0, v)`), `'u1'`, `'v0'` (`x(u, 0)`) or `'v1'`.
    fn boundary(&self, edge_name: &str) -> PyResult<PyBezierCurve> {
        let e = edge(edge_name)?;
        Ok(wrap_curve(match &self.inner {
            Ex::F(p) => Ex::F(p.boundary(e)),
            Ex::E(p) => Ex::E(p.boundary(e)),
        }))
    }
}

fn patch_scheme<T: Num>(
    py: Python<'_>,
    p: &BezierPatch<T>,
    u: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
) -> PyResult<Steps> {
    let s = p.scheme(T::scalar(u, "u")?, T::scalar(v, "v")?);
    let mut items = Vec::new();
    for k in 0..s.level_count() {
        if let Some(level) = s.level(k) {
            items.push((format!("level {k}"), net_out(py, level)?.unbind()));
        }
    }
    items.push((
        "point".into(),
        point_out(py, &s.point_on_surface())?.unbind(),
    ));
    Ok(Steps::new(
        "tensor de Casteljau scheme",
        Some(s.to_string()),
        items,
    ))
}

/// Registers the classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyBezierCurve>()?;
    m.add_class::<PyBezierPatch>()?;
    Ok(())
}

//! `cagd.BezierCurve` and `cagd.BezierPatch` (thesis §2–3): the core's [`BezierCurve`] and
//! [`BezierPatch`], points as rows.

use cagd::bezier::{BezierCurve, BezierPatch, Edge};
use pyo3::prelude::*;

use super::shared::{build, exactness, on, point_out, Ex, Exact};
use super::steps::Steps;
use crate::convert::{net_in, net_out, points_as_rows, rows_out, Num};
use crate::error::IntoPy;

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

fn new_curve<T: Num>(points: &Bound<'_, PyAny>) -> PyResult<BezierCurve<T>> {
    let limits = crate::limits::current();
    let control = points_as_rows::<T>(points, "points")?;
    limits
        .check_degree("points (degree)", control.ncols().saturating_sub(1))
        .py()?;
    BezierCurve::new(control).py()
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
    fn derivative(&self, r: usize) -> PyResult<Self> {
        Ok(wrap_curve(match &self.inner {
            Ex::F(c) => Ex::F(c.derivative(r).py()?),
            Ex::E(c) => Ex::E(c.derivative(r).py()?),
        }))
    }

    /// The same curve of degree `n + times`: `b_i^{(1)} = i/(n+1) b_{i−1} + (1 − i/(n+1)) b_i`.
    #[pyo3(signature = (times = 1))]
    fn elevate(&self, times: usize) -> PyResult<Self> {
        crate::limits::current()
            .check_degree("times (degree)", self.degree().saturating_add(times))
            .py()?;
        let mut out = self.inner.clone();
        for _ in 0..times {
            out = match &out {
                Ex::F(c) => Ex::F(c.elevate()),
                Ex::E(c) => Ex::E(c.elevate()),
            };
        }
        Ok(wrap_curve(out))
    }

    /// The two halves at `t`: their control points are the two edges of the scheme at `t`.
    fn subdivide(&self, t: &Bound<'_, PyAny>) -> PyResult<(Self, Self)> {
        Ok(match &self.inner {
            Ex::F(c) => {
                let (a, b) = c.subdivide(f64::scalar(t, "t")?).py()?;
                (wrap_curve(Ex::F(a)), wrap_curve(Ex::F(b)))
            }
            Ex::E(c) => {
                let (a, b) = c.subdivide(Exact::scalar(t, "t")?).py()?;
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
        on!(self.inner, c => point_out(py, &cagd::integral::bezier_integral(c)))
    }

    /// The antiderivative `∫_0^t b`, degree `n + 1`, control points the partial sums
    /// `Σ_{j<i} b_j/(n+1)`.
    fn antiderivative(&self) -> Self {
        wrap_curve(match &self.inner {
            Ex::F(c) => Ex::F(cagd::integral::bezier_antiderivative(c)),
            Ex::E(c) => Ex::E(cagd::integral::bezier_antiderivative(c)),
        })
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

fn new_patch<T: Num>(net: &Bound<'_, PyAny>) -> PyResult<BezierPatch<T>> {
    let coords = net_in::<T>(net, "net")?;
    let (m, n) = coords.first().map_or((0, 0), |c| (c.nrows(), c.ncols()));
    crate::limits::current()
        .check_degree("net (degree)", m.max(n).saturating_sub(1))
        .py()?;
    BezierPatch::new(coords).py()
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

//! `cagd.BSplineCurve`, `cagd.BSplineSurface`, `cagd.NurbsCurve`, `cagd.NurbsSurface` (the CAD
//! notes §1.2–1.3, octave-nurbs' conventions): the core's types, points as rows.

use cagd::bspline::{BSplineCurve, BSplineSurface};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd_ops::bspline_arg::{BSplineArg, SplineDegree};
use cagd_ops::knots::Degree;
use cagd_ops::ops::{self, Elevate, InsertKnot};
use cagd_ops::{Params, Role};
use nalgebra::DMatrix;
use pyo3::prelude::*;

use super::shared::{build, exactness, on, point_out, Ex, Exact};
use super::steps::{from_record, request_steps, steps_getter, Steps, StepsOf};
use crate::convert::{grid_in, net_out, params, points_as_rows, rows_out, vector_out, Num};
use crate::error::IntoPy;
use crate::ops::{execute, item, with_context, Names};

/// How the curve classes name the roles of their requests.
const CURVE_NAMES: Names = &[
    (Role::Control, "points"),
    (Role::Knots, "knots"),
    (Role::Degree, "degree"),
    (Role::Weights, "weights"),
    (Role::By, "r"),
    (Role::At, "u"),
    (Role::Spline, "knots"),
];

/// How the surface classes name the roles of their requests.
const SURFACE_NAMES: Names = &[
    (Role::Net, "net"),
    (Role::UKnots, "knots_u"),
    (Role::VKnots, "knots_v"),
    (Role::Degree, "degrees"),
    (Role::Weights, "weights"),
];

/// A 1-D array of numbers (knots, weights, parameters) as a vector.
fn values<T: Num>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<T>> {
    Ok(params::<T>(obj, what)?.1)
}

/// A B-spline curve `C(u) = Σ_{i=0}^{n−1} P_i N_{i,p}(u)`, `u ∈ [u_p, u_n]`, with `n + p + 1`
/// knots `u_0 … u_{n+p}` and the control points as the rows of an `(n, d)` array (degree `p`;
/// in steps, spans are counted from 1 as the CAD notes count the knots). Outside the domain
/// the end pieces continue. A curve made by `insert_knots` or `elevate` keeps the steps of
/// that construction (`steps`).
///
/// >>> c = cagd.BSplineCurve(2, [0, 0, 0, 1, 2, 2, 2], [[0, 0], [1, 2], [3, 2], [4, 0]], exact=True)
/// >>> c(1).tolist()
/// [Fraction(2, 1), Fraction(2, 1)]
/// >>> s = c.de_boor(Fraction(1, 2))
/// >>> s["span"], s["alpha1"].tolist()
/// (3, [Fraction(1, 2), Fraction(1, 4)])
/// >>> r = c.insert_knots(1)
/// >>> r.knots.tolist() == [0, 0, 0, 1, 1, 2, 2, 2], r.steps["insert_1.alpha"].tolist()
/// (True, [Fraction(1, 2), Fraction(0, 1)])
#[pyclass(module = "cagd", name = "BSplineCurve", frozen)]
#[derive(Clone)]
pub struct PyBSplineCurve {
    pub(crate) inner: Ex<BSplineCurve<f64>, BSplineCurve<Exact>>,
    /// The steps of the construction that made the curve.
    pub(crate) steps: Option<StepsOf>,
}

impl PyBSplineCurve {
    /// The Python object of a core curve (given directly: no steps).
    pub fn from_inner(inner: Ex<BSplineCurve<f64>, BSplineCurve<Exact>>) -> Self {
        PyBSplineCurve { inner, steps: None }
    }

    fn with_steps(inner: Ex<BSplineCurve<f64>, BSplineCurve<Exact>>, steps: StepsOf) -> Self {
        PyBSplineCurve {
            inner,
            steps: Some(steps),
        }
    }
}

/// The curve of degree `degree` on `knots` (clamped uniform on `[0, 1]` without), built by
/// the operation layer: the degree within the limit, the knots and the points checked by its
/// one rule ([`cagd_ops::knots`]).
fn new_bspline<T: Num>(
    degree: usize,
    knots: Option<&Bound<'_, PyAny>>,
    points: &Bound<'_, PyAny>,
) -> PyResult<BSplineCurve<T>> {
    let knots = knots.map(|k| values::<T>(k, "knots")).transpose()?;
    let op = ops::BSpline {
        degree: Degree::Degree(degree),
        knots,
        ..ops::BSpline::new(points_as_rows::<T>(points, "points")?)
    };
    with_context(points.py(), CURVE_NAMES, |cx| op.curve(cx))
}

/// The curve elevated `r` times by the request [`Elevate`] (clamped knots), with its steps
/// (the knots before, the new degree).
fn elevate<T: Num>(
    py: Python<'_>,
    c: &BSplineCurve<T>,
    r: usize,
) -> PyResult<(BSplineCurve<T>, StepsOf)> {
    let op = Elevate {
        by: r,
        bspline: Some(BSplineArg {
            degree: SplineDegree::Degree(c.degree()),
            knots: Some(c.knots().as_slice().to_vec()),
        }),
        ..Elevate::new(c.control().clone())
    };
    let report = execute(py, CURVE_NAMES, &op)?;
    let knots = item(&report, "knots")?;
    let elevated = BSplineCurve::new(
        c.degree().saturating_add(r),
        knots.as_slice().to_vec(),
        item(&report, "control")?,
    )
    .py()?;
    let title = format!(
        "B-spline degree elevation {} → {}",
        c.degree(),
        elevated.degree()
    );
    let steps = request_steps(Elevate { steps: true, ..op }, CURVE_NAMES, title, &[]);
    Ok((elevated, steps))
}

/// The knots `u` inserted by the request [`InsertKnot`] (Boehm): its report (the refined
/// knots, control points and, for a NURBS curve, weights) and its steps (each insertion's
/// span, `α` and polygon).
fn insert<T: Num>(
    u: &Bound<'_, PyAny>,
    (degree, knots, control, weights): (usize, &[T], DMatrix<T>, Option<Vec<T>>),
) -> PyResult<(cagd_ops::Report<T>, StepsOf)> {
    let op = InsertKnot {
        degree: Degree::Degree(degree),
        knots: Some(knots.to_vec()),
        weights,
        ..InsertKnot::new(control, values::<T>(u, "u")?)
    };
    let report = execute(u.py(), CURVE_NAMES, &op)?;
    let title = "knot insertion (Boehm)".to_string();
    Ok((
        report,
        request_steps(InsertKnot { steps: true, ..op }, CURVE_NAMES, title, &[]),
    ))
}

fn insert_bspline<T: Num>(
    c: &BSplineCurve<T>,
    u: &Bound<'_, PyAny>,
) -> PyResult<(BSplineCurve<T>, StepsOf)> {
    let data = (c.degree(), c.knots().as_slice(), c.control().clone(), None);
    let (report, steps) = insert(u, data)?;
    let knots = item(&report, "knots")?;
    let curve = BSplineCurve::new(
        c.degree(),
        knots.as_slice().to_vec(),
        item(&report, "control")?,
    )
    .py()?;
    Ok((curve, steps))
}

fn insert_nurbs<T: Num>(
    c: &NurbsCurve<T>,
    u: &Bound<'_, PyAny>,
) -> PyResult<(NurbsCurve<T>, StepsOf)> {
    let data = (c.degree(), c.knots(), c.points(), Some(c.weights()));
    let (report, steps) = insert(u, data)?;
    let (knots, weights) = (item(&report, "knots")?, item(&report, "weights")?);
    let control = item(&report, "control")?;
    let curve = NurbsCurve::new(
        c.degree(),
        knots.as_slice().to_vec(),
        control,
        weights.as_slice().to_vec(),
    )
    .py()?;
    Ok((curve, steps))
}

/// de Boor's scheme at `u` by the request [`ops::BSpline`] with its steps, as
/// `cagd bspline --steps` prints it: `t`, `span` (the `k` of `u_k ≤ u < u_(k+1)`, knots
/// counted from 1), `d0`, then `alpha{r}` and `d{r}` per level; then the basis and the point.
fn de_boor<T: Num>(py: Python<'_>, c: &BSplineCurve<T>, u: &Bound<'_, PyAny>) -> PyResult<Steps> {
    let op = ops::BSpline {
        degree: Degree::Degree(c.degree()),
        knots: Some(c.knots().as_slice().to_vec()),
        t: Params::Given(vec![T::scalar(u, "u")?]),
        steps: true,
        ..ops::BSpline::new(c.control().clone())
    };
    let report = execute(py, CURVE_NAMES, &op)?;
    from_record(
        py,
        "de Boor scheme",
        &report,
        "de_boor",
        &["basis", "result"],
    )
}

#[pymethods]
impl PyBSplineCurve {
    #[new]
    #[pyo3(signature = (degree, knots, points, exact = None))]
    fn new(
        degree: usize,
        knots: &Bound<'_, PyAny>,
        points: &Bound<'_, PyAny>,
        exact: Option<bool>,
    ) -> PyResult<Self> {
        let exact = exactness(exact, &[knots, points])?;
        Ok(Self::from_inner(build!(
            exact,
            new_bspline(degree, Some(knots), points)
        )))
    }

    /// The curve with clamped uniform knots on `[0, 1]`: it starts at the first and ends at
    /// the last control point.
    #[staticmethod]
    #[pyo3(signature = (degree, points, exact = None))]
    fn clamped(degree: usize, points: &Bound<'_, PyAny>, exact: Option<bool>) -> PyResult<Self> {
        let exact = exactness(exact, &[points])?;
        Ok(Self::from_inner(build!(
            exact,
            new_bspline(degree, None, points)
        )))
    }

    /// The degree `p`.
    #[getter]
    fn degree(&self) -> usize {
        on!(self.inner, c => c.degree())
    }

    /// The knots `u_0 … u_{n+p}`.
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => vector_out(py, c.knots().as_slice()))
    }

    /// The control points, `(n, d)`.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => rows_out(py, c.control()))
    }

    /// The values `N_{0,p}(u) … N_{n−1,p}(u)` of all basis functions at `u` (in the domain).
    fn basis<'py>(&self, py: Python<'py>, u: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => vector_out(py, &c.basis(&Num::scalar(u, "u")?).py()?))
    }

    /// de Boor's scheme at `u` (in the domain): `d_i^r = (1 − α_i^r) d_{i−1}^{r−1} + α_i^r
    /// d_i^{r−1}`, `α_i^r = (u − u_i)/(u_{i+p+1−r} − u_i)`; items `t`, `span` (counted from 1,
    /// as `cagd bspline --steps` prints it), `d0`, `alpha1`, `d1`, …, `basis` and `result`
    /// (`C(u)`), levels as rows.
    fn de_boor(&self, py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<Steps> {
        on!(self.inner, c => de_boor(py, c, u))
    }

    /// The derivative curve `C'(u) = Σ Q_i N_{i,p−1}(u)`,
    /// `Q_i = p (P_{i+1} − P_i)/(u_{i+p+1} − u_{i+1})`.
    fn derivative(&self) -> PyResult<Self> {
        Ok(Self::from_inner(match &self.inner {
            Ex::F(c) => Ex::F(c.derivative().py()?),
            Ex::E(c) => Ex::E(c.derivative().py()?),
        }))
    }

    /// The same curve with the knots `u` (a number or a list) inserted (Boehm; Piegl & Tiller
    /// A5.4); its `steps` give each insertion's span, `α` and polygon.
    fn insert_knots(&self, u: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(match &self.inner {
            Ex::F(c) => {
                let (r, steps) = insert_bspline(c, u)?;
                Self::with_steps(Ex::F(r), steps)
            }
            Ex::E(c) => {
                let (r, steps) = insert_bspline(c, u)?;
                Self::with_steps(Ex::E(r), steps)
            }
        })
    }

    /// The same curve of degree `p + r` (Piegl & Tiller A5.9; clamped knots).
    #[pyo3(signature = (r = 1))]
    fn elevate(&self, py: Python<'_>, r: usize) -> PyResult<Self> {
        Ok(match &self.inner {
            Ex::F(c) => {
                let (e, steps) = elevate(py, c, r)?;
                Self::with_steps(Ex::F(e), steps)
            }
            Ex::E(c) => {
                let (e, steps) = elevate(py, c, r)?;
                Self::with_steps(Ex::E(e), steps)
            }
        })
    }

    /// `∫_{u_p}^{u_n} C(u) du`, a point.
    fn integral<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => point_out(py, &cagd::integral::bspline_integral(c).py()?))
    }
}

/// A NURBS curve `C(u) = Σ w_i P_i N_{i,p}(u) / Σ w_i N_{i,p}(u)` (the CAD notes (5)): a
/// B-spline in homogeneous coordinates `(w_i P_i, w_i)`. Points as rows `(n, d)`, weights `(n,)`.
/// A curve made by `insert_knots` keeps Boehm's steps (`steps`, the polygons homogeneous).
///
/// >>> arc = cagd.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1]], [1, 1, 2], exact=True)
/// >>> arc(Fraction(1, 2)).tolist()                    # ((1−t²), 2t)/(1+t²): a quarter circle
/// [Fraction(3, 5), Fraction(4, 5)]
/// >>> arc.insert_knots(Fraction(1, 2)).weights.tolist()
/// [Fraction(1, 1), Fraction(1, 1), Fraction(3, 2), Fraction(2, 1)]
#[pyclass(module = "cagd", name = "NurbsCurve", frozen)]
#[derive(Clone)]
pub struct PyNurbsCurve {
    pub(crate) inner: Ex<NurbsCurve<f64>, NurbsCurve<Exact>>,
    /// The steps of the construction that made the curve.
    pub(crate) steps: Option<StepsOf>,
}

impl PyNurbsCurve {
    /// The Python object of a core curve (given directly: no steps).
    pub fn from_inner(inner: Ex<NurbsCurve<f64>, NurbsCurve<Exact>>) -> Self {
        PyNurbsCurve { inner, steps: None }
    }
}

/// The curve built by the operation layer: the weights (one per point, finite, positive), the
/// degree and the knots checked by its rules, as the request [`ops::Nurbs`] checks them.
fn new_nurbs<T: Num>(
    degree: usize,
    knots: &Bound<'_, PyAny>,
    points: &Bound<'_, PyAny>,
    weights: &Bound<'_, PyAny>,
) -> PyResult<NurbsCurve<T>> {
    let op = ops::Nurbs {
        degree: Degree::Degree(degree),
        knots: Some(values::<T>(knots, "knots")?),
        ..ops::Nurbs::new(
            points_as_rows::<T>(points, "points")?,
            values::<T>(weights, "weights")?,
        )
    };
    with_context(points.py(), CURVE_NAMES, |cx| op.curve(cx))
}

#[pymethods]
impl PyNurbsCurve {
    #[new]
    #[pyo3(signature = (degree, knots, points, weights, exact = None))]
    fn new(
        degree: usize,
        knots: &Bound<'_, PyAny>,
        points: &Bound<'_, PyAny>,
        weights: &Bound<'_, PyAny>,
        exact: Option<bool>,
    ) -> PyResult<Self> {
        let exact = exactness(exact, &[knots, points, weights])?;
        Ok(Self::from_inner(build!(
            exact,
            new_nurbs(degree, knots, points, weights)
        )))
    }

    /// The full circle of radius `radius` about `center` (octave-nurbs `nrbcirc`; in doubles:
    /// its weights are `cos(π/4)`).
    #[staticmethod]
    #[pyo3(signature = (radius = 1.0, center = None))]
    fn circle(radius: f64, center: Option<Vec<f64>>) -> PyResult<Self> {
        let center = center.unwrap_or_else(|| vec![0.0, 0.0]);
        Ok(Self::from_inner(Ex::F(
            NurbsCurve::circle(radius, &center).py()?,
        )))
    }

    /// The arc of radius `radius` about `center` from angle `start` to `end` (radians).
    #[staticmethod]
    fn arc(radius: f64, center: Vec<f64>, start: f64, end: f64) -> PyResult<Self> {
        Ok(Self::from_inner(Ex::F(
            NurbsCurve::arc(radius, &center, start, end).py()?,
        )))
    }

    /// The first derivative `C'(u)` (in the domain).
    fn tangent<'py>(&self, py: Python<'py>, u: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => point_out(py, &c.try_eval_derivative(Num::scalar(u, "u")?).py()?))
    }

    /// The degree `p`.
    #[getter]
    fn degree(&self) -> usize {
        on!(self.inner, c => c.degree())
    }

    /// The knots.
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => vector_out(py, c.knots()))
    }

    /// The control points, `(n, d)`.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => rows_out(py, &c.points()))
    }

    /// The weights, `(n,)`.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => vector_out(py, &c.weights()))
    }

    /// The same curve with the knots `u` inserted (Boehm on the homogeneous B-spline); its
    /// `steps` give each insertion's span, `α` and homogeneous polygon `(w P, w)`.
    fn insert_knots(&self, u: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (inner, steps) = match &self.inner {
            Ex::F(c) => {
                let (r, steps) = insert_nurbs(c, u)?;
                (Ex::F(r), steps)
            }
            Ex::E(c) => {
                let (r, steps) = insert_nurbs(c, u)?;
                (Ex::E(r), steps)
            }
        };
        Ok(PyNurbsCurve {
            inner,
            steps: Some(steps),
        })
    }
}

/// A tensor-product B-spline surface `S(u, v) = Σ_i Σ_j P_ij N_{i,p}(u) N_{j,q}(v)`; the net
/// an `(nu, nv, d)` array. `surface(u, v)` evaluates on the grid `u × v`.
///
/// >>> net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]      # bilinear: (u, v, uv)
/// >>> s = cagd.BSplineSurface((1, 1), [0, 0, 1, 1], [0, 0, 1, 1], net, exact=True)
/// >>> s(Fraction(1, 2), Fraction(1, 3)).tolist()
/// [Fraction(1, 2), Fraction(1, 3), Fraction(1, 6)]
/// >>> s([0, 1], [0, 1]).shape
/// (2, 2, 3)
#[pyclass(module = "cagd", name = "BSplineSurface", frozen)]
pub struct PyBSplineSurface {
    inner: Ex<BSplineSurface<f64>, BSplineSurface<Exact>>,
}

impl PyBSplineSurface {
    /// The Python object of a core surface.
    pub fn from_inner(inner: Ex<BSplineSurface<f64>, BSplineSurface<Exact>>) -> Self {
        PyBSplineSurface { inner }
    }
}

/// The request [`ops::BSplineSurface`] of the arguments (its surface not yet built).
fn surface_request<T: Num>(
    (p, q): (usize, usize),
    knots: (&Bound<'_, PyAny>, &Bound<'_, PyAny>),
    net: &Bound<'_, PyAny>,
) -> PyResult<ops::BSplineSurface<T>> {
    let net = grid_in::<T>(net, "net")?;
    Ok(ops::BSplineSurface {
        degrees: [Degree::Degree(p), Degree::Degree(q)],
        knots: [
            Some(values::<T>(knots.0, "knots_u")?),
            Some(values::<T>(knots.1, "knots_v")?),
        ],
        ..ops::BSplineSurface::new(net)
    })
}

/// The surface built by the operation layer: the degrees, the knots of both directions and
/// the net checked by its rules.
fn new_bspline_surface<T: Num>(
    degrees: (usize, usize),
    knots: (&Bound<'_, PyAny>, &Bound<'_, PyAny>),
    net: &Bound<'_, PyAny>,
) -> PyResult<BSplineSurface<T>> {
    let op = surface_request::<T>(degrees, knots, net)?;
    with_context(net.py(), SURFACE_NAMES, |cx| op.surface(cx))
}

#[pymethods]
impl PyBSplineSurface {
    #[new]
    #[pyo3(signature = (degrees, knots_u, knots_v, net, exact = None))]
    fn new(
        degrees: (usize, usize),
        knots_u: &Bound<'_, PyAny>,
        knots_v: &Bound<'_, PyAny>,
        net: &Bound<'_, PyAny>,
        exact: Option<bool>,
    ) -> PyResult<Self> {
        let exact = exactness(exact, &[knots_u, knots_v, net])?;
        Ok(PyBSplineSurface {
            inner: build!(exact, new_bspline_surface(degrees, (knots_u, knots_v), net)),
        })
    }

    /// The degrees `(p, q)`.
    #[getter]
    fn degree(&self) -> (usize, usize) {
        on!(self.inner, s => s.degrees())
    }

    /// The control net, `(nu, nv, d)`.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, s => net_out(py, s.coordinates()))
    }
}

/// A NURBS surface `S(u, v) = Σ w_ij P_ij N_i N_j / Σ w_ij N_i N_j`; net `(nu, nv, d)`,
/// weights `(nu, nv)`.
///
/// >>> net = [[[1, 0, 0], [1, 0, 1]], [[1, 1, 0], [1, 1, 1]], [[0, 1, 0], [0, 1, 1]]]
/// >>> w = [[1, 1], [1, 1], [2, 2]]                     # a quarter cylinder of radius 1
/// >>> s = cagd.NurbsSurface((2, 1), [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], net, w, exact=True)
/// >>> s(Fraction(1, 2), Fraction(1, 4)).tolist()
/// [Fraction(3, 5), Fraction(4, 5), Fraction(1, 4)]
#[pyclass(module = "cagd", name = "NurbsSurface", frozen)]
pub struct PyNurbsSurface {
    inner: Ex<NurbsSurface<f64>, NurbsSurface<Exact>>,
}

fn new_nurbs_surface<T: Num>(
    (p, q): (usize, usize),
    knots: (&Bound<'_, PyAny>, &Bound<'_, PyAny>),
    net: &Bound<'_, PyAny>,
    weights: &Bound<'_, PyAny>,
) -> PyResult<NurbsSurface<T>> {
    let weights = T::with_values(weights, "weights", |shape, v| match *shape {
        [r, c] => Ok(DMatrix::from_row_slice(r, c, v)),
        _ => Err(crate::convert::rank_error(
            "weights",
            "an (nu, nv) array",
            shape,
        )),
    })?;
    let op = ops::NurbsSurface {
        spline: surface_request::<T>((p, q), knots, net)?,
        weights,
    };
    with_context(net.py(), SURFACE_NAMES, |cx| op.surface(cx))
}

#[pymethods]
impl PyNurbsSurface {
    #[new]
    #[pyo3(signature = (degrees, knots_u, knots_v, net, weights, exact = None))]
    fn new(
        degrees: (usize, usize),
        knots_u: &Bound<'_, PyAny>,
        knots_v: &Bound<'_, PyAny>,
        net: &Bound<'_, PyAny>,
        weights: &Bound<'_, PyAny>,
        exact: Option<bool>,
    ) -> PyResult<Self> {
        let exact = exactness(exact, &[knots_u, knots_v, net, weights])?;
        Ok(PyNurbsSurface {
            inner: build!(
                exact,
                new_nurbs_surface(degrees, (knots_u, knots_v), net, weights)
            ),
        })
    }

    /// The ruled surface between two NURBS curves (`nrbruled`).
    #[staticmethod]
    fn ruled(c1: &PyNurbsCurve, c2: &PyNurbsCurve) -> PyResult<Self> {
        let inner = match (&c1.inner, &c2.inner) {
            (Ex::F(a), Ex::F(b)) => Ex::F(NurbsSurface::ruled(a, b).py()?),
            (Ex::E(a), Ex::E(b)) => Ex::E(NurbsSurface::ruled(a, b).py()?),
            _ => return Err(super::shared::mixed("c2")),
        };
        Ok(PyNurbsSurface { inner })
    }
}

super::shared::curve_methods!(PyBSplineCurve, "BSplineCurve");
super::shared::curve_methods!(PyNurbsCurve, "NurbsCurve");
steps_getter!(PyBSplineCurve);
steps_getter!(PyNurbsCurve);
super::shared::surface_methods!(PyBSplineSurface, "BSplineSurface");
super::shared::surface_methods!(PyNurbsSurface, "NurbsSurface");

/// Registers the classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyBSplineCurve>()?;
    m.add_class::<PyNurbsCurve>()?;
    m.add_class::<PyBSplineSurface>()?;
    m.add_class::<PyNurbsSurface>()?;
    Ok(())
}

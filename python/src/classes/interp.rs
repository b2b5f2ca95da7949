//! `cagd.HermiteCubic` (Ferguson cubic), `cagd.CubicSpline` (interpolating cubic spline) and
//! `cagd.Lagrange` (the interpolating polynomial curve, barycentric): the lecture notes'
//! interpolation, points as rows.

use cagd::hermite::HermiteCubic;
use cagd::lagrange::{Lagrange, LagrangeInterpolant};
use cagd::spline::{CubicSpline, Parametrization};
use cagd_ops::error::lib;
use cagd_ops::ops::{self, spline::Ends, spline::Knots};
use cagd_ops::{Params, Role};
use nalgebra::DMatrix;
use pyo3::prelude::*;

use super::bezier::PyBezierCurve;
use super::shared::{exactness, on, point_out, Ex, Exact};
use super::steps::{request_steps, steps_getter, StepsOf};
use crate::convert::{params, points_as_rows, rows_out, vector_out, Num};
use crate::error::{conversion, IntoPy};
use crate::ops::{with_context, Names};

/// How `HermiteCubic` names its arguments.
const HERMITE_NAMES: Names = &[
    (Role::P0, "x1"),
    (Role::P1, "x2"),
    (Role::T0, "t1"),
    (Role::T1, "t2"),
    (Role::Hermite, "x1, x2, t1, t2"),
];

/// How `CubicSpline` names its arguments.
const SPLINE_NAMES: Names = &[
    (Role::Points, "points"),
    (Role::T0, "start"),
    (Role::T1, "end_tangent"),
    (Role::Nodes, "params"),
    (Role::Ends, "end"),
];

/// How `Lagrange` names its arguments.
const LAGRANGE_NAMES: Names = &[(Role::Nodes, "nodes"), (Role::Points, "points")];

/// A point or vector (any array of `d` numbers) as a `d × 1` column.
fn column_in<T: Num>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<DMatrix<T>> {
    let (_, v) = params::<T>(obj, what)?;
    Ok(DMatrix::from_vec(v.len(), 1, v))
}

/// `Ex::F(…)` or `Ex::E(…)` of `$f::<T>(…)` by `exact`, with the steps it returns beside.
macro_rules! build_with_steps {
    ($exact:expr, $f:ident ( $($arg:expr),* )) => {
        if $exact {
            let (x, steps) = $f::<Exact>($($arg),*)?;
            (Ex::E(x), steps)
        } else {
            let (x, steps) = $f::<f64>($($arg),*)?;
            (Ex::F(x), steps)
        }
    };
}

/// The Ferguson (Hermite) cubic `x(u) = x1 H0(u) + x2 H3(u) + t1 H1(u) + t2 H2(u)`,
/// `u ∈ [0, 1]`, through `x1`, `x2` with the tangents `t1`, `t2` (the lecture notes). Its
/// `steps`: the Hermite basis at `u = 0, 1/2, 1` (a row per `u`, in the order of the geometry
/// `[x1 x2 t1 t2]`: `H0, H3, H1, H2`), the Bézier points `x1, x1 + t1/3, x2 − t2/3, x2`, and the
/// points at those `u`.
///
/// >>> h = cagd.HermiteCubic([0, 0], [3, 0], [3, 3], [3, -3], exact=True)
/// >>> h(Fraction(1, 2)).tolist()
/// [Fraction(3, 2), Fraction(3, 4)]
/// >>> h.steps["bezier_control"].tolist() == [[0, 0], [1, 1], [2, 1], [3, 0]]
/// True
#[pyclass(module = "cagd", name = "HermiteCubic", frozen)]
#[derive(Clone)]
pub struct PyHermiteCubic {
    pub(crate) inner: Ex<HermiteCubic<f64>, HermiteCubic<Exact>>,
    /// The steps of the construction (none for a spline's segment).
    pub(crate) steps: Option<StepsOf>,
}

/// The cubic built by the request [`ops::Hermite`] (its checks of the four vectors), and its
/// steps at `u = 0, 1/2, 1`.
fn new_hermite<T: Num>(args: [&Bound<'_, PyAny>; 4]) -> PyResult<(HermiteCubic<T>, StepsOf)> {
    let [x1, x2, t1, t2] = args;
    let op = ops::Hermite::new([
        column_in(x1, "x1")?,
        column_in(x2, "x2")?,
        column_in(t1, "t1")?,
        column_in(t2, "t2")?,
    ]);
    let cubic = with_context(x1.py(), HERMITE_NAMES, |_| op.cubic())?;
    let half = T::one() / T::from_usize(2);
    let steps = ops::Hermite {
        t: Params::Given(vec![T::zero(), half, T::one()]),
        steps: true,
        ..op
    };
    let title = "Hermite (Ferguson) cubic".to_string();
    Ok((cubic, request_steps(steps, HERMITE_NAMES, title, &[])))
}

#[pymethods]
impl PyHermiteCubic {
    #[new]
    #[pyo3(signature = (x1, x2, t1, t2, exact = None))]
    fn new(
        x1: &Bound<'_, PyAny>,
        x2: &Bound<'_, PyAny>,
        t1: &Bound<'_, PyAny>,
        t2: &Bound<'_, PyAny>,
        exact: Option<bool>,
    ) -> PyResult<Self> {
        let exact = exactness(exact, &[x1, x2, t1, t2])?;
        let (inner, steps) = build_with_steps!(exact, new_hermite([x1, x2, t1, t2]));
        Ok(PyHermiteCubic {
            inner,
            steps: Some(steps),
        })
    }

    /// The tangent `x'(u)`.
    fn tangent<'py>(&self, py: Python<'py>, u: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => point_out(py, &c.eval_derivative(Num::scalar(u, "u")?)))
    }

    /// The same cubic as a Bézier curve: `b0 = x1`, `b1 = x1 + t1/3`, `b2 = x2 − t2/3`,
    /// `b3 = x2`.
    fn to_bezier(&self) -> PyResult<PyBezierCurve> {
        Ok(PyBezierCurve::from_inner(match &self.inner {
            Ex::F(c) => Ex::F(c.to_bezier().py()?),
            Ex::E(c) => Ex::E(c.to_bezier().py()?),
        }))
    }

    /// The geometry `[x1 x2 t1 t2]` as rows, `(4, d)`.
    #[getter]
    fn geometry<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => rows_out(py, c.geometry()))
    }
}

/// The interpolating cubic spline through the points (rows, `(m, d)`), piecewise Ferguson
/// cubics with continuous second derivative; `end='natural'` (`x'' = 0` at the ends),
/// `'closed'` (periodic), or `'clamped'` with the end tangents `start`, `end_tangent`.
/// `params` (optional): the parameter of each point (default `0, 1, …, m−1`). Its `steps`:
/// the parameters, the system `A · tangents = rhs` for the tangents, and every segment as a
/// Hermite geometry and as Bézier points.
///
/// >>> s = cagd.CubicSpline([[0, 0], [1, 1], [2, 0]], exact=True)
/// >>> s.tangents.tolist()
/// [[Fraction(1, 1), Fraction(3, 2)], [Fraction(1, 1), Fraction(0, 1)], [Fraction(1, 1), Fraction(-3, 2)]]
/// >>> s.steps["system"].tolist()
/// [[Fraction(2, 1), Fraction(1, 1), Fraction(0, 1)], [Fraction(1, 1), Fraction(4, 1), Fraction(1, 1)], [Fraction(0, 1), Fraction(1, 1), Fraction(2, 1)]]
#[pyclass(module = "cagd", name = "CubicSpline", frozen)]
#[derive(Clone)]
pub struct PyCubicSpline {
    pub(crate) inner: Ex<CubicSpline<f64>, CubicSpline<Exact>>,
    /// The steps of the interpolation.
    pub(crate) steps: Option<StepsOf>,
}

/// The spline built by the request [`ops::Spline`]: its end condition (the tangents it needs
/// or ignores), the parameters of the points and the work checked by the operation layer; and
/// the request's steps (at the first parameter, its points and samples left out).
fn new_spline<T: Num>(
    points: &Bound<'_, PyAny>,
    end: &str,
    tangents: (Option<&Bound<'_, PyAny>>, Option<&Bound<'_, PyAny>>),
    ps: Option<&Bound<'_, PyAny>>,
) -> PyResult<(CubicSpline<T>, StepsOf)> {
    let ends = match end {
        "natural" => Ends::Natural,
        "closed" => Ends::Closed,
        "clamped" => Ends::Clamped,
        _ => {
            return Err(conversion(
                "end",
                "expected 'natural', 'closed' or 'clamped' with start= and end_tangent=",
            ))
        }
    };
    let op = ops::Spline {
        ends: Some(ends),
        start_tangent: tangents.0.map(|s| column_in(s, "start")).transpose()?,
        end_tangent: tangents
            .1
            .map(|e| column_in(e, "end_tangent"))
            .transpose()?,
        knots: match ps {
            None => Knots::Chosen(Parametrization::Uniform),
            Some(p) => Knots::Given(params::<T>(p, "params")?.1),
        },
        ..ops::Spline::new(points_as_rows::<T>(points, "points")?)
    };
    let spline = with_context(points.py(), SPLINE_NAMES, |cx| op.spline(cx))?;
    let steps = ops::Spline {
        t: Params::Given(spline.params()[..1].to_vec()),
        steps: true,
        ..op
    };
    let title = "interpolating cubic spline".to_string();
    let steps = request_steps(steps, SPLINE_NAMES, title, &["t", "result"]);
    Ok((spline, steps))
}

#[pymethods]
impl PyCubicSpline {
    #[new]
    #[pyo3(signature = (points, end = "natural", start = None, end_tangent = None, params = None, exact = None))]
    fn new(
        points: &Bound<'_, PyAny>,
        end: &str,
        start: Option<&Bound<'_, PyAny>>,
        end_tangent: Option<&Bound<'_, PyAny>>,
        params: Option<&Bound<'_, PyAny>>,
        exact: Option<bool>,
    ) -> PyResult<Self> {
        let mut objs = vec![points];
        objs.extend(start.iter().copied().chain(end_tangent).chain(params));
        let exact = exactness(exact, &objs)?;
        let (inner, steps) =
            build_with_steps!(exact, new_spline(points, end, (start, end_tangent), params));
        Ok(PyCubicSpline {
            inner,
            steps: Some(steps),
        })
    }

    /// The tangents at the points, `(m, d)`.
    #[getter]
    fn tangents<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => rows_out(py, c.tangents()))
    }

    /// The parameters of the points.
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => vector_out(py, c.params()))
    }

    /// Segment `k` as a Ferguson cubic on `[0, 1]`.
    fn segment(&self, k: usize) -> PyResult<PyHermiteCubic> {
        Ok(PyHermiteCubic {
            inner: match &self.inner {
                Ex::F(c) => Ex::F(c.segment(k).py()?),
                Ex::E(c) => Ex::E(c.segment(k).py()?),
            },
            steps: None,
        })
    }
}

/// The Lagrange interpolating polynomial curve through the points (rows, `(m+1, d)`) at the
/// nodes `t_0 … t_m`: `x(t) = Σ_i L_i(t) x_i`, `L_i(t) = Π_{j≠i} (t − t_j)/(t_i − t_j)`,
/// evaluated in barycentric form. `basis(t)` gives `L_0(t) … L_m(t)`. Its `steps`: the
/// lecture notes' blending matrix `G` (`coefficients`, row `i` the powers of `L_i`, highest
/// first) and the polynomial's coefficients `A = X G` (`polynomial`, one point a power).
///
/// >>> c = cagd.Lagrange([1, 2, 3, 4, 5], [[1], [2], [3], [2], [1]], exact=True)
/// >>> c(Fraction(5, 2)).tolist()                        # the lecture notes: 87/32
/// [Fraction(87, 32)]
/// >>> cagd.Lagrange([0, 1, 2], [[0], [1], [4]], exact=True).steps["polynomial"].tolist()
/// [[Fraction(1, 1)], [Fraction(0, 1)], [Fraction(0, 1)]]
// The doc comment is the class's Python docstring: its examples index arrays and print lists
// (`[1]`, `[[0], [1]]`), which are no Rust links.
#[allow(rustdoc::broken_intra_doc_links)]
#[pyclass(module = "cagd", name = "Lagrange", frozen)]
#[derive(Clone)]
pub struct PyLagrange {
    pub(crate) inner: Ex<LagrangeInterpolant<f64>, LagrangeInterpolant<Exact>>,
    /// The steps of the interpolation.
    pub(crate) steps: Option<StepsOf>,
}

fn new_lagrange<T: Num>(
    nodes: &Bound<'_, PyAny>,
    points: &Bound<'_, PyAny>,
) -> PyResult<(LagrangeInterpolant<T>, StepsOf)> {
    let (_, n) = params::<T>(nodes, "nodes")?;
    let values = points_as_rows::<T>(points, "points")?;
    // The checks of the request [`ops::Lagrange`]: the degree within the limit, the nodes
    // given and finite; the core's barycentric form keeps the nodes in the order given.
    let curve = with_context(nodes.py(), LAGRANGE_NAMES, |cx| {
        cx.check_degree(Role::Nodes, n.len().saturating_sub(1))?;
        cagd_ops::params::check_given(Role::Nodes, &n, cx)?;
        let basis = Lagrange::new(n.clone()).map_err(lib(Role::Nodes, ops::LAGRANGE_NODES_FORM))?;
        LagrangeInterpolant::new(basis, values.clone())
            .map_err(lib(Role::Points, ops::LAGRANGE_VALUES_FORM))
    })?;
    let steps = ops::Lagrange {
        values: Some(values),
        coefficients: true,
        t: Params::Given(n[..1].to_vec()),
        ..ops::Lagrange::new(n)
    };
    let title = "Lagrange interpolation".to_string();
    Ok((
        curve,
        request_steps(steps, LAGRANGE_NAMES, title, &["t", "result"]),
    ))
}

#[pymethods]
impl PyLagrange {
    #[new]
    #[pyo3(signature = (nodes, points, exact = None))]
    fn new(
        nodes: &Bound<'_, PyAny>,
        points: &Bound<'_, PyAny>,
        exact: Option<bool>,
    ) -> PyResult<Self> {
        let exact = exactness(exact, &[nodes, points])?;
        let (inner, steps) = build_with_steps!(exact, new_lagrange(nodes, points));
        Ok(PyLagrange {
            inner,
            steps: Some(steps),
        })
    }

    /// The basis values `L_0(t) … L_m(t)`.
    fn basis<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => vector_out(py, &c.basis().basis(&Num::scalar(t, "t")?)))
    }

    /// The barycentric weights `w_i = 1/Π_{j≠i}(t_i − t_j)`.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, c => vector_out(py, c.basis().weights()))
    }
}

super::shared::curve_methods!(PyHermiteCubic, "HermiteCubic");
super::shared::curve_methods!(PyCubicSpline, "CubicSpline");
super::shared::curve_methods!(PyLagrange, "Lagrange");
steps_getter!(PyHermiteCubic);
steps_getter!(PyCubicSpline);
steps_getter!(PyLagrange);

/// Registers the classes.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyHermiteCubic>()?;
    m.add_class::<PyCubicSpline>()?;
    m.add_class::<PyLagrange>()?;
    Ok(())
}

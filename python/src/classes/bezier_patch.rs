//! `cagd.BezierPatch` (thesis §3): the core's [`BezierPatch`], the net an `(m+1, n+1, d)`
//! array — evaluation, the tensor de Casteljau scheme, partial derivatives, boundary curves,
//! degree elevation, subdivision, the antiderivative and the integral.

use cagd::bezier::{BezierPatch, Direction, Edge};
use cagd::cost::max_bits;
use cagd_ops::error::lib;
use cagd_ops::layout::scheme::{curve_scheme, Marks};
use cagd_ops::{Report, Role, Value};
use pyo3::prelude::*;

use super::bezier::PyBezierCurve;
use super::shared::{build, exactness, on, point_out, Ex, Exact};
use super::steps::{from_report, steps_getter, Steps, StepsOf};
use crate::convert::{net_in, net_out, Num};
use crate::error::{conversion, IntoPy};
use crate::ops::{with_context, Names};

/// How `BezierPatch` names the roles of its checks.
const PATCH_NAMES: Names = &[(Role::Net, "net"), (Role::By, "r, s"), (Role::T, "t")];

type PatchEx = Ex<BezierPatch<f64>, BezierPatch<Exact>>;

/// A tensor-product Bézier patch `x(u, v) = Σ_i Σ_j b_ij B_i^m(u) B_j^n(v)` on `[0, 1]²`
/// (thesis (3.1)), the control net an `(m+1, n+1, d)` array, `net[i, j] = b_ij`.
///
/// `patch(u, v)` evaluates on the grid `u × v`: shape `(len(u), len(v), d)` (numbers: `(d,)`).
/// A patch made by `elevate` or `subdivide` keeps the steps of that construction (`steps`).
///
/// >>> p = cagd.BezierPatch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], exact=True)
/// >>> p(Fraction(1, 2), Fraction(1, 4)).tolist()       # (u, v, uv)
/// [Fraction(1, 2), Fraction(1, 4), Fraction(1, 8)]
/// >>> p.elevate(1, 2).degree
/// (2, 3)
/// >>> first, second = p.subdivide(Fraction(1, 2), "u")
/// >>> first(1, 1).tolist() == p(Fraction(1, 2), 1).tolist()
/// True
/// >>> p.integral().tolist()                             # ∫∫ (u, v, uv) du dv
/// [Fraction(1, 2), Fraction(1, 2), Fraction(1, 4)]
#[pyclass(module = "cagd", name = "BezierPatch", frozen)]
#[derive(Clone)]
pub struct PyBezierPatch {
    pub(crate) inner: PatchEx,
    /// The steps of the construction that made the patch.
    pub(crate) steps: Option<StepsOf>,
}

impl PyBezierPatch {
    /// The Python object of a core patch (given directly: no steps).
    pub fn from_inner(inner: PatchEx) -> Self {
        PyBezierPatch { inner, steps: None }
    }
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
        _ => Err(conversion("edge", "expected 'u0', 'u1', 'v0' or 'v1'")),
    }
}

fn direction(name: &str) -> PyResult<Direction> {
    match name {
        "u" => Ok(Direction::U),
        "v" => Ok(Direction::V),
        _ => Err(conversion("direction", "expected 'u' or 'v'")),
    }
}

/// The size in bits of the net's largest number.
fn net_bits<T: Num>(p: &BezierPatch<T>) -> u128 {
    max_bits(p.coordinates().iter().flat_map(|x| x.iter()))
}

/// The patch raised to degree `(m + r, n + s)`: the degrees and the work ([`BezierPatch::
/// elevate_cost`]) checked against the interpreter's limits first.
fn elevate<T: Num>(
    py: Python<'_>,
    p: &BezierPatch<T>,
    (r, s): (usize, usize),
) -> PyResult<BezierPatch<T>> {
    with_context(py, PATCH_NAMES, |cx| {
        let (m, n) = p.degree();
        cx.check_degree(Role::By, m.saturating_add(r))?;
        cx.check_degree(Role::By, n.saturating_add(s))?;
        cx.check_cost(Role::By, p.elevate_cost(r, s, net_bits(p)), T::EXACT)?;
        p.elevate(r, s)
            .map_err(lib(Role::By, "degrees within the limit"))
    })
}

/// The steps of an elevation by `(r, s)`: the net of every degree on the way, `u` first.
fn elevation_steps<T: Num>(p: BezierPatch<T>, (r, s): (usize, usize)) -> StepsOf {
    std::sync::Arc::new(move |py| {
        let (m, n) = p.degree();
        let title = format!("degree elevation ({m}, {n}) → ({}, {})", m + r, n + s);
        let mut net = p.clone();
        let mut items = vec![(
            format!("degree_{m}_{n}"),
            net_out(py, net.coordinates())?.unbind(),
        )];
        for by in std::iter::repeat_n((1, 0), r).chain(std::iter::repeat_n((0, 1), s)) {
            net = elevate(py, &net, by)?;
            let (a, b) = net.degree();
            items.push((
                format!("degree_{a}_{b}"),
                net_out(py, net.coordinates())?.unbind(),
            ));
        }
        Ok(Steps::new(title, None, items))
    })
}

/// The two parts of the patch split at `t` in `dir`, the work checked first.
fn subdivide<T: Num>(
    py: Python<'_>,
    p: &BezierPatch<T>,
    dir: Direction,
    t: &T,
) -> PyResult<(BezierPatch<T>, BezierPatch<T>)> {
    with_context(py, PATCH_NAMES, |cx| {
        let cost = p.subdivide_cost(dir, max_bits(std::slice::from_ref(t)), net_bits(p));
        cx.check_cost(Role::T, cost, T::EXACT)?;
        p.subdivide(dir, t.clone())
            .map_err(lib(Role::T, "a parameter strictly inside (0, 1)"))
    })
}

/// The steps of a split at `t` in `dir`: the de Casteljau scheme of every control curve along
/// `dir` (the operation layer's layout, the parts' points marked), then the two nets.
fn subdivision_steps<T: Num>(
    p: BezierPatch<T>,
    dir: Direction,
    t: T,
    parts: (BezierPatch<T>, BezierPatch<T>),
) -> StepsOf {
    std::sync::Arc::new(move |py| {
        let (name, index, range) = match dir {
            Direction::U => ("u", "j", "b_(0,j) … b_(m,j)"),
            Direction::V => ("v", "i", "b_(i,0) … b_(i,n)"),
        };
        let mut report = Report::new();
        for (k, curve) in p.control_curves(dir).iter().enumerate() {
            let scheme = curve_scheme(
                &curve.scheme(t.clone()),
                cagd_ops::TEXT_DIGITS,
                Marks::Subdivision,
            );
            let Value::Shown { text, data } = scheme else {
                continue;
            };
            let text = format!("control curve {index} = {k} ({range}):\n{text}");
            report.push(format!("curve_{}", k + 1), Value::Shown { text, data });
        }
        report.push("first", Value::Grid(parts.0.to_grid()));
        report.push("second", Value::Grid(parts.1.to_grid()));
        let title = format!(
            "subdivision at {name} = {} by de Casteljau's scheme of each control curve",
            cagd_ops::number_text(&t)
        );
        from_report(py, &title, &report, &[])
    })
}

/// The antiderivative in `dir`, the work checked first.
fn antiderivative<T: Num>(
    py: Python<'_>,
    p: &BezierPatch<T>,
    dir: Direction,
) -> PyResult<BezierPatch<T>> {
    with_context(py, PATCH_NAMES, |cx| {
        cx.check_cost(Role::Net, p.antiderivative_cost(dir, net_bits(p)), T::EXACT)?;
        p.antiderivative(dir).map_err(lib(
            Role::Net,
            "control points whose partial sums stay within ±1.8e308",
        ))
    })
}

/// The integral over `[0, 1]²`, the work checked first.
fn integral<'py, T: Num>(py: Python<'py>, p: &BezierPatch<T>) -> PyResult<Bound<'py, PyAny>> {
    let value = with_context(py, PATCH_NAMES, |cx| {
        cx.check_cost(Role::Net, p.integral_cost(net_bits(p)), T::EXACT)?;
        p.integral().map_err(lib(
            Role::Net,
            "control points whose mean stays within ±1.8e308",
        ))
    })?;
    point_out(py, &value)
}

/// `$f(py, p, …)` on the patch in its arithmetic, rewrapped.
macro_rules! map_patch {
    ($self:expr, $py:expr, $f:ident ( $($arg:expr),* )) => {
        PyBezierPatch::from_inner(match &$self.inner {
            Ex::F(p) => Ex::F($f($py, p, $($arg),*)?),
            Ex::E(p) => Ex::E($f($py, p, $($arg),*)?),
        })
    };
}

#[pymethods]
impl PyBezierPatch {
    #[new]
    #[pyo3(signature = (net, exact = None))]
    fn new(net: &Bound<'_, PyAny>, exact: Option<bool>) -> PyResult<Self> {
        let exact = exactness(exact, &[net])?;
        Ok(Self::from_inner(build!(exact, new_patch(net))))
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
        Ok(Self::from_inner(match &self.inner {
            Ex::F(p) => Ex::F(p.derivative(r, s).py()?),
            Ex::E(p) => Ex::E(p.derivative(r, s).py()?),
        }))
    }

    /// The boundary curve `'u0'` (`x(0, v)`), `'u1'`, `'v0'` (`x(u, 0)`) or `'v1'`.
    fn boundary(&self, edge_name: &str) -> PyResult<PyBezierCurve> {
        let e = edge(edge_name)?;
        Ok(PyBezierCurve::from_inner(match &self.inner {
            Ex::F(p) => Ex::F(p.boundary(e)),
            Ex::E(p) => Ex::E(p.boundary(e)),
        }))
    }

    /// The same patch of degree `(m + r, n + s)`: every column of the net raised `r` times,
    /// `b'_ij = i/(m+1) b_(i−1)j + (1 − i/(m+1)) b_ij`, then every row `s` times; its `steps`
    /// are the nets of every degree on the way.
    #[pyo3(signature = (r = 1, s = 0))]
    fn elevate(&self, py: Python<'_>, r: usize, s: usize) -> PyResult<Self> {
        let steps = on!(self.inner, p => elevation_steps(p.clone(), (r, s)));
        Ok(Self {
            steps: Some(steps),
            ..map_patch!(self, py, elevate((r, s)))
        })
    }

    /// The two patches of the split at `u = t` (`direction='u'`) or `v = t`, each over
    /// `[0, 1]²`: `first(s, v) = x(t·s, v)`, `second(s, v) = x(t + (1−t)·s, v)` (for `'u'`).
    /// Their nets are the edges of the de Casteljau schemes of the control curves along the
    /// direction (their `steps`).
    #[pyo3(signature = (t, direction = "u"))]
    fn subdivide(&self, t: &Bound<'_, PyAny>, direction: &str) -> PyResult<(Self, Self)> {
        let dir = self::direction(direction)?;
        fn split<T: Num>(
            p: &BezierPatch<T>,
            dir: Direction,
            t: &Bound<'_, PyAny>,
        ) -> PyResult<(BezierPatch<T>, BezierPatch<T>, StepsOf)> {
            let at = T::scalar(t, "t")?;
            let (a, b) = subdivide(t.py(), p, dir, &at)?;
            let steps = subdivision_steps(p.clone(), dir, at, (a.clone(), b.clone()));
            Ok((a, b, steps))
        }
        let wrap = |inner: PatchEx, steps: &StepsOf| PyBezierPatch {
            inner,
            steps: Some(steps.clone()),
        };
        Ok(match &self.inner {
            Ex::F(p) => {
                let (a, b, steps) = split(p, dir, t)?;
                (wrap(Ex::F(a), &steps), wrap(Ex::F(b), &steps))
            }
            Ex::E(p) => {
                let (a, b, steps) = split(p, dir, t)?;
                (wrap(Ex::E(a), &steps), wrap(Ex::E(b), &steps))
            }
        })
    }

    /// The antiderivative `∫_0^u x(s, v) ds` (`direction='u'`, degree `(m+1, n)`,
    /// `c_kj = Σ_(i<k) b_ij / (m+1)`) or `∫_0^v x(u, s) ds` (`'v'`); both in turn give
    /// `∫_0^u ∫_0^v x`.
    #[pyo3(signature = (direction = "u"))]
    fn antiderivative(&self, py: Python<'_>, direction: &str) -> PyResult<Self> {
        let dir = self::direction(direction)?;
        Ok(map_patch!(self, py, antiderivative(dir)))
    }

    /// `∫_0^1 ∫_0^1 x(u, v) du dv = Σ_ij b_ij / ((m+1)(n+1))`, a point.
    fn integral<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        on!(self.inner, p => integral(py, p))
    }
}

super::shared::surface_methods!(PyBezierPatch, "BezierPatch");
steps_getter!(PyBezierPatch);

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

/// Registers the class.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyBezierPatch>()
}

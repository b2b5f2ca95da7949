//! `cagd.CoonsPatch` (every blend of the thesis §4: bilinear, Hermite-blended, bicubic with
//! cross-boundary derivatives), `cagd.GordonSurface` (§5) and `cagd.discrete_coons` (the CAD
//! notes): the core's constructions over any of the package's curves.

use cagd::bezier::BezierCurve;
use cagd::bspline::BSplineCurve;
use cagd::coons::{
    BicubicCoonsPatch, BlendingPair, CoonsBoundary, CoonsPatch, CrossDerivatives,
    GeneralizedCoonsPatch, Tolerance, Twist,
};
use cagd::gordon::GordonSurface;
use cagd::param::{Curve, Surface};
use cagd_ops::error::lib;
use cagd_ops::ops::coons::boundary_error;
use cagd_ops::ops::coons_bicubic::CROSS_FORM;
use cagd_ops::ops::gordon::network_error;
use cagd_ops::ops::DiscreteCoons;
use cagd_ops::params::check_given;
use cagd_ops::{Role, Value};
use nalgebra::DVector;
use pyo3::prelude::*;

use super::bezier::PyBezierCurve;
use super::bezier_patch::PyBezierPatch;
use super::interp::{PyCubicSpline, PyHermiteCubic, PyLagrange};
use super::shared::mixed;
use super::shared::{on, point_out, Ex, Exact};
use super::splines::{PyBSplineCurve, PyBSplineSurface, PyNurbsCurve};
use super::steps::Steps;
use crate::convert::{grid_in, grid_out, params, Num};
use crate::error::{conversion, IntoPy};
use crate::ops::{execute, with_context, Names, OpIntoPy};

/// How `CoonsPatch` names the roles of its checks.
const COONS_NAMES: Names = &[
    (Role::C1, "c1"),
    (Role::C2, "c2"),
    (Role::D1, "d1"),
    (Role::D2, "d2"),
    (Role::Boundary, "c1, c2, d1, d2"),
    (Role::Blend, "blend"),
    (Role::Cross, "du0, du1, dv0, dv1"),
];

/// How `GordonSurface` names the roles of its checks.
const GORDON_NAMES: Names = &[
    (Role::UNodes, "u_nodes"),
    (Role::VNodes, "v_nodes"),
    (Role::UCurves, "curves_at_u"),
    (Role::VCurves, "curves_at_v"),
    (Role::Network, "curves_at_u, curves_at_v"),
];

/// Any curve of the package, in the core's arithmetic `T`.
pub type AnyCurve<T> = Box<dyn cagd::CurveDeriv<T> + Send + Sync>;

/// A curve object as the core's curve in `f64` (`Ok(Err(..))` for an exact one).
fn any_curve(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Ex<AnyCurve<f64>, AnyCurve<Exact>>> {
    macro_rules! take {
        ($t:ty) => {
            if let Ok(c) = obj.cast::<$t>() {
                return Ok(match &c.get().inner {
                    Ex::F(x) => Ex::F(Box::new(x.clone())),
                    Ex::E(x) => Ex::E(Box::new(x.clone())),
                });
            }
        };
    }
    take!(PyBezierCurve);
    take!(PyBSplineCurve);
    take!(PyNurbsCurve);
    take!(PyHermiteCubic);
    take!(PyCubicSpline);
    take!(PyLagrange);
    Err(conversion(
        what,
        "expected a cagd curve (BezierCurve, BSplineCurve, NurbsCurve, HermiteCubic, CubicSpline, Lagrange)",
    ))
}

/// Curves in doubles or in exact rationals.
type Curves = Ex<Vec<AnyCurve<f64>>, Vec<AnyCurve<Exact>>>;

/// The curves `objs` as the core's curves of the class `$class` (with the field `inner`), all
/// in one arithmetic; `None` if one of them is of another class or arithmetic.
macro_rules! typed_curves {
    ($objs:expr, $class:ty) => {{
        let (mut floats, mut exacts) = (Vec::new(), Vec::new());
        let mut all = true;
        for obj in $objs {
            match obj.cast::<$class>().map(|c| c.get().inner.clone()) {
                Ok(Ex::F(c)) => floats.push(c),
                Ok(Ex::E(c)) => exacts.push(c),
                Err(_) => all = false,
            }
        }
        match (all, floats.is_empty(), exacts.is_empty()) {
            (true, false, true) => Some(Ex::F(floats)),
            (true, true, false) => Some(Ex::E(exacts)),
            _ => None,
        }
    }};
}

/// A bilinearly blended Coons patch of four curves of one type `C` (in `f64` or exact).
type TypedCoons<C, D> = Ex<CoonsPatch<C, f64>, CoonsPatch<D, Exact>>;

/// The bilinear Coons patch of four curves of one type, for the conversions of that type.
fn typed_coons<C: Curve<f64>, D: Curve<Exact>>(
    curves: Option<Ex<Vec<C>, Vec<D>>>,
) -> PyResult<Option<TypedCoons<C, D>>> {
    fn four<C, T: cagd::Scalar>(c: Vec<C>) -> PyResult<CoonsPatch<C, T>>
    where
        C: Curve<T>,
    {
        let [c1, c2, d1, d2]: [C; 4] = c
            .try_into()
            .map_err(|_| conversion("curves", "expected four curves"))?;
        CoonsPatch::new(c1, c2, d1, d2)
            .map_err(boundary_error)
            .named(COONS_NAMES)
    }
    Ok(match curves {
        None => None,
        Some(Ex::F(c)) => Some(Ex::F(four(c)?)),
        Some(Ex::E(c)) => Some(Ex::E(four(c)?)),
    })
}

/// The curves `objs`, all in one arithmetic.
fn curves(objs: &[(&Bound<'_, PyAny>, &str)]) -> PyResult<Curves> {
    let mut floats = Vec::new();
    let mut exacts = Vec::new();
    for (obj, what) in objs {
        match any_curve(obj, what)? {
            Ex::F(c) if exacts.is_empty() => floats.push(c),
            Ex::E(c) if floats.is_empty() => exacts.push(c),
            _ => return Err(mixed(what)),
        }
    }
    Ok(if exacts.is_empty() {
        Ex::F(floats)
    } else {
        Ex::E(exacts)
    })
}

/// The kinds of Coons patch.
pub enum Coons<T: cagd::Scalar> {
    /// Bilinearly blended (thesis (4.4)).
    Bilinear(CoonsPatch<AnyCurve<T>, T>),
    /// Blended by the pair `(f1, f2)` in both directions (thesis remark after (4.4)).
    Blended(GeneralizedCoonsPatch<AnyCurve<T>, T>),
    /// Bicubically blended with cross-boundary derivatives (thesis §4.3, (4.5)).
    Bicubic(Box<BicubicCoonsPatch<AnyCurve<T>, AnyCurve<T>, T>>),
}

impl<T: cagd::Scalar> Coons<T> {
    fn surface(&self) -> &(dyn Surface<T> + Sync) {
        match self {
            Coons::Bilinear(p) => p,
            Coons::Blended(p) => p,
            Coons::Bicubic(p) => p.as_ref(),
        }
    }

    /// The point with its parts, as the core names them.
    fn parts(&self, u: T, v: T) -> Vec<(&'static str, DVector<T>)> {
        match self {
            Coons::Bilinear(p) => {
                let x = p.eval_parts(u, v);
                vec![("rc", x.rc), ("rd", x.rd), ("rcd", x.rcd), ("x", x.x)]
            }
            Coons::Blended(p) => {
                let x = p.eval_parts(u, v);
                vec![("rc", x.rc), ("rd", x.rd), ("rcd", x.rcd), ("x", x.x)]
            }
            Coons::Bicubic(p) => {
                let x = p.eval_parts(u, v);
                vec![("hc", x.hc), ("hd", x.hd), ("hcd", x.hcd), ("x", x.x)]
            }
        }
    }
}

/// Each kind of Coons patch is a surface of the core: the calls go to it.
impl<T: cagd::Scalar> Surface<T> for Coons<T> {
    fn dim(&self) -> usize {
        self.surface().dim()
    }

    fn domain(&self) -> ((T, T), (T, T)) {
        self.surface().domain()
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        self.surface().eval(u, v)
    }

    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> cagd::Result<()> {
        self.surface().eval_grid_into(us, vs, out)
    }
}

/// A Coons patch through four boundary curves `c1 = x(u, 0)`, `c2 = x(u, 1)`,
/// `d1 = x(0, v)`, `d2 = x(1, v)` (any cagd curves; each used on its domain mapped onto
/// `[0, 1]`): `x = r_c + r_d − r_cd` (thesis (4.1)–(4.4)).
///
/// `blend='linear'` (bilinearly blended, the thesis's `krpaCoons`) or `'hermite'` (the cubic
/// Hermite pair `(H0, H3)` of the partially bicubic patch, §4.2); `CoonsPatch.bicubic(…)` adds
/// the cross-boundary derivatives (§4.3). `patch(u, v)` evaluates on the grid `u × v`;
/// `patch.parts(u, v)` gives `r_c`, `r_d`, `r_cd` and `x` (thesis `vrednostCoons`). A
/// bilinear patch of four `BezierCurve`s converts to one Bézier patch (`to_bezier`), of four
/// `BSplineCurve`s to one B-spline surface (`to_bspline`).
///
/// >>> line = lambda a, b: cagd.BezierCurve([a, b], exact=True)
/// >>> c1 = cagd.BezierCurve([[0, 0, 0], [Fraction(1, 2), 0, 1], [1, 0, 0]], exact=True)
/// >>> p = cagd.CoonsPatch(c1, line([0, 1, 0], [1, 1, 0]), line([0, 0, 0], [0, 1, 0]), line([1, 0, 0], [1, 1, 0]))
/// >>> half = Fraction(1, 2)
/// >>> p(half, half).tolist()
/// [Fraction(1, 2), Fraction(1, 2), Fraction(1, 4)]
/// >>> p.parts(half, half)["rc"].tolist()
/// [Fraction(1, 2), Fraction(1, 2), Fraction(1, 4)]
/// >>> b = p.to_bezier()
/// >>> b.degree, b(half, half).tolist() == p(half, half).tolist()
/// ((2, 1), True)
#[pyclass(module = "cagd", name = "CoonsPatch", frozen)]
pub struct PyCoonsPatch {
    inner: Ex<Coons<f64>, Coons<Exact>>,
    /// The same bilinear patch of four Bézier curves, for `to_bezier`.
    bezier: Option<TypedCoons<BezierCurve<f64>, BezierCurve<Exact>>>,
    /// The same bilinear patch of four B-spline curves, for `to_bspline`.
    bspline: Option<TypedCoons<BSplineCurve<f64>, BSplineCurve<Exact>>>,
}

fn coons_of<T: cagd::Scalar>(c: Vec<AnyCurve<T>>, blend: &str) -> PyResult<Coons<T>> {
    let [c1, c2, d1, d2]: [AnyCurve<T>; 4] = c
        .try_into()
        .map_err(|_| conversion("curves", "expected four curves"))?;
    Ok(match blend {
        "linear" => Coons::Bilinear(
            CoonsPatch::new(c1, c2, d1, d2)
                .map_err(boundary_error)
                .named(COONS_NAMES)?,
        ),
        "hermite" => {
            let (f, g) = (BlendingPair::hermite_cubic(), BlendingPair::hermite_cubic());
            Coons::Blended(
                GeneralizedCoonsPatch::new(c1, c2, d1, d2, f, g)
                    .map_err(boundary_error)
                    .named(COONS_NAMES)?,
            )
        }
        other => {
            return Err(conversion(
                "blend",
                format!("expected 'linear' or 'hermite', got '{other}'"),
            ))
        }
    })
}

fn bicubic_of<T: cagd::Scalar>(c: Vec<AnyCurve<T>>, twist: &str) -> PyResult<Coons<T>> {
    let [c1, c2, d1, d2, du0, du1, dv0, dv1]: [AnyCurve<T>; 8] = c
        .try_into()
        .map_err(|_| conversion("curves", "expected eight curves"))?;
    let twist = match twist {
        "zero" => Twist::Zero,
        "gregory" => Twist::Gregory,
        other => {
            return Err(conversion(
                "twist",
                format!("expected 'zero' or 'gregory', got '{other}'"),
            ))
        }
    };
    let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default())
        .map_err(boundary_error)
        .named(COONS_NAMES)?;
    let cross = CrossDerivatives { du0, du1, dv0, dv1 };
    let patch = BicubicCoonsPatch::new(boundary, cross, twist)
        .map_err(lib(Role::Cross, CROSS_FORM))
        .named(COONS_NAMES)?;
    Ok(Coons::Bicubic(Box::new(patch)))
}

fn parts_steps<T: Num>(
    py: Python<'_>,
    parts: Vec<(&'static str, DVector<T>)>,
    title: &str,
) -> PyResult<Steps> {
    let mut items = Vec::new();
    for (name, p) in parts {
        items.push((name.to_string(), point_out(py, &p)?.unbind()));
    }
    Ok(Steps::new(title, None, items))
}

#[pymethods]
impl PyCoonsPatch {
    #[new]
    #[pyo3(signature = (c1, c2, d1, d2, blend = "linear"))]
    fn new(
        c1: &Bound<'_, PyAny>,
        c2: &Bound<'_, PyAny>,
        d1: &Bound<'_, PyAny>,
        d2: &Bound<'_, PyAny>,
        blend: &str,
    ) -> PyResult<Self> {
        let objs = [(c1, "c1"), (c2, "c2"), (d1, "d1"), (d2, "d2")];
        let inner = match curves(&objs)? {
            Ex::F(c) => Ex::F(coons_of(c, blend)?),
            Ex::E(c) => Ex::E(coons_of(c, blend)?),
        };
        let linear = blend == "linear";
        let given = [c1, c2, d1, d2];
        Ok(PyCoonsPatch {
            inner,
            bezier: typed_coons(typed_curves!(
                given.iter().filter(|_| linear),
                PyBezierCurve
            ))?,
            bspline: typed_coons(typed_curves!(
                given.iter().filter(|_| linear),
                PyBSplineCurve
            ))?,
        })
    }

    /// The bicubically blended patch (thesis (4.5)): the boundary curves and the four
    /// cross-boundary derivative curves `du0 = x_u(0, v)`, `du1 = x_u(1, v)`,
    /// `dv0 = x_v(u, 0)`, `dv1 = x_v(u, 1)`; corner twists `'zero'` or `'gregory'`.
    #[staticmethod]
    #[pyo3(signature = (c1, c2, d1, d2, du0, du1, dv0, dv1, twist = "zero"))]
    #[allow(clippy::too_many_arguments)] // the four curves and the four cross derivatives
    fn bicubic(
        c1: &Bound<'_, PyAny>,
        c2: &Bound<'_, PyAny>,
        d1: &Bound<'_, PyAny>,
        d2: &Bound<'_, PyAny>,
        du0: &Bound<'_, PyAny>,
        du1: &Bound<'_, PyAny>,
        dv0: &Bound<'_, PyAny>,
        dv1: &Bound<'_, PyAny>,
        twist: &str,
    ) -> PyResult<Self> {
        let objs = [
            (c1, "c1"),
            (c2, "c2"),
            (d1, "d1"),
            (d2, "d2"),
            (du0, "du0"),
            (du1, "du1"),
            (dv0, "dv0"),
            (dv1, "dv1"),
        ];
        Ok(PyCoonsPatch {
            inner: match curves(&objs)? {
                Ex::F(c) => Ex::F(bicubic_of(c, twist)?),
                Ex::E(c) => Ex::E(bicubic_of(c, twist)?),
            },
            bezier: None,
            bspline: None,
        })
    }

    /// The point at `(u, v)` with its parts: `rc`, `rd`, `rcd`, `x` (`hc`, `hd`, `hcd`, `x` for
    /// the bicubic patch).
    fn parts(&self, py: Python<'_>, u: &Bound<'_, PyAny>, v: &Bound<'_, PyAny>) -> PyResult<Steps> {
        on!(self.inner, p => parts_steps(py, p.parts(Num::scalar(u, "u")?, Num::scalar(v, "v")?), "Coons patch point"))
    }

    /// The same surface as one Bézier patch (the bilinearly blended patch of four Bézier
    /// curves: the Gordon net of the nodes `{0, 1}`); degree `(max deg c, max deg d)` raised to
    /// at least 1.
    fn to_bezier(&self) -> PyResult<PyBezierPatch> {
        Ok(PyBezierPatch::from_inner(match &self.bezier {
            Some(Ex::F(c)) => Ex::F(c.to_bezier().py()?),
            Some(Ex::E(c)) => Ex::E(c.to_bezier().py()?),
            None => return Err(conversion(
                "c1, c2, d1, d2",
                "to_bezier needs four BezierCurve boundaries (all exact or all floats) and blend='linear'",
            )),
        }))
    }

    /// The same surface as one B-spline surface (the bilinearly blended patch of four
    /// B-spline curves with clamped knots, each reparametrised onto `[0, 1]`: octave-nurbs'
    /// `nrbcoons`, the boolean sum of three B-spline surfaces made compatible).
    fn to_bspline(&self) -> PyResult<PyBSplineSurface> {
        Ok(PyBSplineSurface::from_inner(match &self.bspline {
            Some(Ex::F(c)) => Ex::F(c.to_bspline().py()?),
            Some(Ex::E(c)) => Ex::E(c.to_bspline().py()?),
            None => return Err(conversion(
                "c1, c2, d1, d2",
                "to_bspline needs four BSplineCurve boundaries (all exact or all floats) and blend='linear'",
            )),
        }))
    }
}

/// A Gordon surface through a network of curves (thesis §5, (5.3)):
/// `g = g1 + g2 − g12`, `g1 = Σ_i L_i(u) g(u_i, v)`, `g2 = Σ_j L_j(v) g(u, v_j)`,
/// `g12 = Σ_i Σ_j L_i(u) L_j(v) g(u_i, v_j)` with Lagrange polynomials over the nodes.
///
/// `curves_at_u[i]` is the curve `g(u_i, ·)`, `curves_at_v[j]` the curve `g(·, v_j)`; they must
/// cross at `g(u_i, v_j)`. A network of `BezierCurve`s converts to one Bézier patch
/// (`to_bezier`).
///
/// >>> L = lambda a, b: cagd.BezierCurve([a, b], exact=True)
/// >>> g = cagd.GordonSurface([0, 1], [0, 1], [L([0, 0], [0, 1]), L([1, 0], [1, 1])],
/// ...                        [L([0, 0], [1, 0]), L([0, 1], [1, 1])])
/// >>> g(Fraction(1, 4), Fraction(1, 2)).tolist()
/// [Fraction(1, 4), Fraction(1, 2)]
/// >>> g.parts(Fraction(1, 4), Fraction(1, 2))["g12"].tolist()
/// [Fraction(1, 4), Fraction(1, 2)]
/// >>> g.to_bezier().degree
/// (1, 1)
#[pyclass(module = "cagd", name = "GordonSurface", frozen)]
pub struct PyGordonSurface {
    inner: Ex<GordonSurface<AnyCurve<f64>, f64>, GordonSurface<AnyCurve<Exact>, Exact>>,
    /// The same surface of a network of Bézier curves, for `to_bezier`.
    bezier: Option<BezierGordon>,
}

/// A Gordon surface of Bézier curves, in `f64` or exact.
type BezierGordon =
    Ex<GordonSurface<BezierCurve<f64>, f64>, GordonSurface<BezierCurve<Exact>, Exact>>;

fn gordon_of<T: Num, C: Curve<T> + Send>(
    u: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    mut c: Vec<C>,
    split: usize,
) -> PyResult<GordonSurface<C, T>> {
    let (_, un) = params::<T>(u, "u_nodes")?;
    let (_, vn) = params::<T>(v, "v_nodes")?;
    let at_v = c.split_off(split);
    // The checks of the request [`cagd_ops::ops::Gordon`]: as many curves as nodes within the
    // degree limit, the nodes given and finite, the network's refusal worded by it.
    with_context(u.py(), GORDON_NAMES, |cx| {
        cx.check_degree(Role::UCurves, c.len().saturating_sub(1))?;
        cx.check_degree(Role::VCurves, at_v.len().saturating_sub(1))?;
        check_given(Role::UNodes, &un, cx)?;
        check_given(Role::VNodes, &vn, cx)?;
        GordonSurface::new(un, vn, c, at_v).map_err(network_error)
    })
}

#[pymethods]
impl PyGordonSurface {
    #[new]
    fn new(
        u_nodes: &Bound<'_, PyAny>,
        v_nodes: &Bound<'_, PyAny>,
        curves_at_u: Vec<Bound<'_, PyAny>>,
        curves_at_v: Vec<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let mut objs: Vec<(&Bound<'_, PyAny>, &str)> =
            curves_at_u.iter().map(|c| (c, "curves_at_u")).collect();
        objs.extend(curves_at_v.iter().map(|c| (c, "curves_at_v")));
        let split = curves_at_u.len();
        let inner = match curves(&objs)? {
            Ex::F(c) => Ex::F(gordon_of(u_nodes, v_nodes, c, split)?),
            Ex::E(c) => Ex::E(gordon_of(u_nodes, v_nodes, c, split)?),
        };
        let all = curves_at_u.iter().chain(&curves_at_v);
        let bezier = match typed_curves!(all, PyBezierCurve) {
            None => None,
            Some(Ex::F(c)) => Some(Ex::F(gordon_of(u_nodes, v_nodes, c, split)?)),
            Some(Ex::E(c)) => Some(Ex::E(gordon_of(u_nodes, v_nodes, c, split)?)),
        };
        Ok(PyGordonSurface { inner, bezier })
    }

    /// The same surface as one Bézier patch, for a network of Bézier curves: the Lagrange
    /// blends written in Bernstein form (degree `(max(deg, k_u − 1), max(deg, k_v − 1))`).
    fn to_bezier(&self) -> PyResult<PyBezierPatch> {
        Ok(PyBezierPatch::from_inner(match &self.bezier {
            Some(Ex::F(g)) => Ex::F(g.to_bezier().py()?),
            Some(Ex::E(g)) => Ex::E(g.to_bezier().py()?),
            None => {
                return Err(conversion(
                    "curves_at_u, curves_at_v",
                    "to_bezier needs a network of BezierCurve curves (all exact or all floats)",
                ))
            }
        }))
    }

    /// The point at `(u, v)` with its parts `g1`, `g2`, `g12`, `g`.
    fn parts(&self, py: Python<'_>, u: &Bound<'_, PyAny>, v: &Bound<'_, PyAny>) -> PyResult<Steps> {
        on!(self.inner, s => {
            let p = s.eval_parts(Num::scalar(u, "u")?, Num::scalar(v, "v")?);
            parts_steps(py, vec![("g1", p.g1), ("g2", p.g2), ("g12", p.g12), ("g", p.g)], "Gordon surface point")
        })
    }
}

/// The discrete Coons patch of the CAD notes: the inner points of a control net `(m+1, n+1, d)`
/// from its boundary rows and columns, `b_ij = (1−i/m) b_0j + (i/m) b_mj + (1−j/n) b_i0 +
/// (j/n) b_in − (bilinear blend of the corners)`. The inner points given are ignored.
///
/// >>> net = np.array([[[Fraction(j, 2)] for j in range(3)] for i in range(3)])   # b_ij = j/2
/// >>> net[1, 1, 0] = 7                                          # an inner point: ignored
/// >>> cagd.discrete_coons(net)[1, 1].tolist()
/// [Fraction(1, 2)]
#[pyfunction]
#[pyo3(signature = (net, exact = None))]
fn discrete_coons<'py>(
    net: &Bound<'py, PyAny>,
    exact: Option<bool>,
) -> PyResult<Bound<'py, PyAny>> {
    fn run<'py, T: Num>(net: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        const NAMES: Names = &[(Role::Net, "net")];
        let op = DiscreteCoons::new(grid_in::<T>(net, "net")?);
        let report = execute(net.py(), NAMES, &op)?;
        match report.get("result") {
            Some(Value::Grid(g)) => grid_out(net.py(), g),
            _ => Err(crate::error::cagd_error(
                "Internal",
                None,
                "the request answered no grid 'result'".into(),
            )),
        }
    }
    if super::shared::exactness(exact, &[net])? {
        run::<Exact>(net)
    } else {
        run::<f64>(net)
    }
}

super::shared::surface_methods!(PyCoonsPatch, "CoonsPatch");
super::shared::surface_methods!(PyGordonSurface, "GordonSurface");

/// Registers the classes and functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyCoonsPatch>()?;
    m.add_class::<PyGordonSurface>()?;
    m.add_function(wrap_pyfunction!(discrete_coons, m)?)?;
    Ok(())
}

/// The joint of two curves of the package (`first` at the end of its domain, `second` at the
/// start of its), by the core's [`cagd::continuity::curve_joint`].
pub fn joint(
    first: &Bound<'_, PyAny>,
    second: &Bound<'_, PyAny>,
    tol: f64,
) -> PyResult<cagd::continuity::Joint> {
    match curves(&[(first, "first"), (second, "second")])? {
        Ex::F(c) => {
            let (a, b) = (&c[0], &c[1]);
            cagd::continuity::curve_joint(a, a.domain().1, b, b.domain().0, tol).py()
        }
        Ex::E(c) => {
            let (a, b) = (&c[0], &c[1]);
            let tol = <Exact as cagd::Scalar>::from_f64(tol)
                .ok_or_else(|| conversion("tol", "not a finite number"))?;
            cagd::continuity::curve_joint(a, a.domain().1, b, b.domain().0, tol).py()
        }
    }
}

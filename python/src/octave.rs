//! `cagd.octave`: the eight thesis functions, fixed, with the arguments, layouts and outputs of
//! `octave_ref/fixed/` (points as columns, several outputs as a tuple), each the twin of
//! `cagd_octave::compat` called on the arrays as they come (no copy for contiguous `float64`
//! input), plus Octave's text format (`load`, `save`).
//!
//! | Octave | Python |
//! |---|---|
//! | `T = deCasteljau(kontrolneT, N)` | `T = cagd.octave.deCasteljau(kontrolneT, N)` |
//! | `P = ploskevB(kontrolneT, N)` | `P = cagd.octave.ploskevB(kontrolneT, N)` |
//! | `L = bilinearna(B, u, v, N)` | `L = cagd.octave.bilinearna(B, u, v, N)` |
//! | `A = tenzor(B)` | `A = cagd.octave.tenzor(B)` |
//! | `[R, P] = krpaCoons(c1, c2, d1, d2, P1, P2, P3, P4)` | `R, P = cagd.octave.krpaCoons(…)` |
//! | `[T, rc, rd, rcd] = vrednostCoons(u, v, c1, …, P4)` | `T, rc, rd, rcd = cagd.octave.vrednostCoons(…)` |
//! | `[R, P] = krpaGordon(g_u, g_v, g_uv, x_u, x_v, N)` | `R, P = cagd.octave.krpaGordon(…)` |
//! | `v = Lagrange(x, m, u)` | `v = cagd.octave.Lagrange(x, m, u)` |

use cagd_octave::compat;
use nalgebra::DMatrix;
use ndarray::{ArrayView2, ArrayViewD, IxDyn};
use num_rational::BigRational;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use cagd_ops::Role;

use crate::convert::{any_exact, rank_error, Num};
use crate::error::IntoPy;
use crate::limits::current as limits;
use crate::ops::{checked, finite, Names};

/// Runs `$f::<T>(args)` in exact arithmetic when any of `$objs` is exact, else in doubles.
macro_rules! by_exactness {
    ([$($obj:expr),*], $f:ident ( $($arg:expr),* )) => {
        if any_exact(&[$($obj),*])? {
            $f::<BigRational>($($arg),*)
        } else {
            $f::<f64>($($arg),*)
        }
    };
}

/// An Octave matrix: a 2-D array, a 1-D array as a row (`1 × n`), a number as `1 × 1`.
fn matrix<'a, T>(what: &'static str, shape: &[usize], v: &'a [T]) -> PyResult<ArrayView2<'a, T>> {
    let (r, c) = match *shape {
        [] => (1, 1),
        [n] => (1, n),
        [r, c] => (r, c),
        _ => return Err(rank_error(what, "a matrix (2-D array)", shape)),
    };
    ArrayView2::from_shape((r, c), v).map_err(|e| crate::error::conversion(what, e.to_string()))
}

/// Calls `f` with the matrix views of `objs` (all read in `T`).
fn with_matrices<T: Num, R>(
    objs: &[(&Bound<'_, PyAny>, &'static str)],
    f: &mut dyn FnMut(&[ArrayView2<'_, T>]) -> PyResult<R>,
) -> PyResult<R> {
    fn go<T: Num, R>(
        objs: &[(&Bound<'_, PyAny>, &'static str)],
        done: &mut Vec<ArrayView2<'_, T>>,
        f: &mut dyn FnMut(&[ArrayView2<'_, T>]) -> PyResult<R>,
    ) -> PyResult<R> {
        let Some(((obj, what), rest)) = objs.split_first() else {
            return f(done);
        };
        T::with_values(obj, what, |shape, v| {
            let view = matrix(what, shape, v)?;
            // Counted as Octave counts: down the columns.
            finite(what, view.t().iter())?;
            // Each view lives as long as the values `with_values` lends: the recursion keeps
            // them all alive until `f` has run.
            let mut all: Vec<ArrayView2<'_, T>> = done.iter().map(|a| a.view()).collect();
            all.push(view);
            go(rest, &mut all, f)
        })
    }
    go(objs, &mut Vec::new(), f)
}

/// The size in bits of the largest number of `a` (0 in doubles, whose cost does not depend on
/// the value).
fn bits<T: Num>(a: &ArrayView2<'_, T>) -> u128 {
    a.iter().map(|x| x.bits()).max().unwrap_or(0)
}

/// The size in bits of the samples `k/(N−1)` in exact arithmetic (0 in doubles).
fn sample_bits<T: Num>(n: usize) -> u128 {
    if T::EXACT {
        2 * u128::from(usize::BITS - n.leading_zeros())
    } else {
        0
    }
}

/// Refuses `points` evaluations of `cost` each above the limit on work, by the operation
/// layer's check about `role` (named by `names`).
fn check_work<T: Num>(
    names: Names,
    role: Role,
    (points, cost): (usize, cagd::cost::Cost),
) -> PyResult<()> {
    checked(names, |cx| {
        cx.check_cost(role, cost.times(points as u128), T::EXACT)
    })
}

/// One number, finite.
fn finite_scalar<T: Num>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<T> {
    let x = T::scalar(obj, what)?;
    finite(what, [&x])?;
    Ok(x)
}

/// The cost of one look-up on a curve of `samples` samples of `bits` bits (the sampled
/// curves of `krpaCoons` and `krpaGordon`).
fn sampled_cost<T: Num>(samples: usize, bits: u128) -> cagd::cost::Cost {
    let k = samples.max(2);
    cagd::param::SampledCurve::new(
        compat::samples::<T>(k),
        DMatrix::from_element(1, k, T::zero()),
    )
    .map(|c| c.eval_cost(sample_bits::<T>(k), bits))
    .unwrap_or_default()
}

/// The patch of a packed net, for its cost (the twin builds its own).
fn patch_of<T: Num>(b: &ArrayView2<'_, T>) -> PyResult<cagd::BezierPatch<T>> {
    let a = compat::tenzor(b.view()).py()?;
    cagd_octave::arrays::patch_from_array3(&a).py()
}

/// The degrees `(m, n)` of a packed net with `cols / 3` points a row.
fn net_degree(b: &ArrayView2<'_, impl Sized>) -> usize {
    b.nrows().max(b.ncols() / 3).saturating_sub(1)
}

/// `T = deCasteljau(kontrolneT, N)`: the Bézier curve with control points the columns of
/// `kontrolneT` (`d × (n+1)`) at `t = linspace(0, 1, N)`, one point a column (`d × N`).
///
/// >>> B = np.array([[0, 0, 8, 4], [0, 2, 2, 0], [0, 2, 0, 0]])   # thesis Primer 2.4
/// >>> cagd.octave.deCasteljau(B, 3)[:, 1].tolist()               # b(1/2)
/// [3.5, 1.5, 0.75]
/// >>> cagd.octave.deCasteljau(B.astype(object), 3)[:, 1].tolist()
/// [Fraction(7, 2), Fraction(3, 2), Fraction(3, 4)]
#[pyfunction]
#[pyo3(name = "deCasteljau")]
#[allow(non_snake_case)] // the thesis's argument names, for keyword calls
fn de_casteljau<'py>(kontrolneT: &Bound<'py, PyAny>, N: usize) -> PyResult<Bound<'py, PyAny>> {
    by_exactness!([kontrolneT], de_casteljau_in(kontrolneT, N))
}

fn de_casteljau_in<'py, T: Num>(p: &Bound<'py, PyAny>, n: usize) -> PyResult<Bound<'py, PyAny>> {
    const NAMES: Names = &[(Role::Control, "kontrolneT"), (Role::Samples, "N")];
    let py = p.py();
    limits().check_samples("N", n).py()?;
    with_matrices::<T, _>(&[(p, "kontrolneT")], &mut |m| {
        let degree = m[0].ncols().saturating_sub(1);
        let control = DMatrix::from_fn(m[0].nrows(), m[0].ncols(), |i, j| m[0][[i, j]].clone());
        let cost = cagd::BezierCurve::new(control)
            .map(|c| c.eval_cost(sample_bits::<T>(n), bits(&m[0])))
            .unwrap_or_default();
        checked(NAMES, |cx| cx.check_degree(Role::Control, degree))?;
        check_work::<T>(NAMES, Role::Samples, (n, cost))?;
        let t = py.detach(|| compat::de_casteljau(m[0].view(), n)).py()?;
        T::from_array(py, t)
    })
}

/// `P = ploskevB(kontrolneT, N)`: the Bézier patch of the packed net `(m+1) × 3(n+1)` on
/// `linspace(0, 1, N)²`, `P[i, j, :]` the point at `(t[i], t[j])` (`N × N × 3`).
///
/// >>> B = np.array([[0, 0, 0, 0, 1, 0], [1, 0, 0, 1, 1, 1]])    # b_00 b_01; b_10 b_11: (u, v, uv)
/// >>> P = cagd.octave.ploskevB(B, 3)
/// >>> P.shape, P[1, 2].tolist()                                 # x(1/2, 1)
/// ((3, 3, 3), [0.5, 1.0, 0.5])
#[pyfunction]
#[pyo3(name = "ploskevB")]
#[allow(non_snake_case)] // the thesis's argument names, for keyword calls
fn ploskev_b<'py>(kontrolneT: &Bound<'py, PyAny>, N: usize) -> PyResult<Bound<'py, PyAny>> {
    by_exactness!([kontrolneT], ploskev_b_in(kontrolneT, N))
}

fn ploskev_b_in<'py, T: Num>(b: &Bound<'py, PyAny>, n: usize) -> PyResult<Bound<'py, PyAny>> {
    const NAMES: Names = &[(Role::Net, "kontrolneT"), (Role::Grid, "N")];
    let py = b.py();
    checked(NAMES, |cx| cx.check_grid(Role::Grid, n, n))?;
    with_matrices::<T, _>(&[(b, "kontrolneT")], &mut |m| {
        checked(NAMES, |cx| cx.check_degree(Role::Net, net_degree(&m[0])))?;
        let (b, tb) = (bits(&m[0]), sample_bits::<T>(n));
        let cost = patch_of(&m[0])?.scheme_cost(tb, tb, b);
        check_work::<T>(NAMES, Role::Grid, (n.saturating_mul(n), cost))?;
        let p = py.detach(|| compat::ploskev_b(m[0].view(), n)).py()?;
        T::from_array(py, p)
    })
}

/// `L = bilinearna(B, u, v, N)`: the point `x(u, v)` of the Bézier patch of the packed net `B`
/// as a `1 × 1 × 3` array (`N` is accepted and ignored, as in the fixed code).
///
/// >>> B = np.array([[0, 0, 0, 0, 1, 0], [1, 0, 0, 1, 1, 1]])    # (u, v, uv)
/// >>> L = cagd.octave.bilinearna(B, 0.5, 0.25, 3)
/// >>> L.shape, L.ravel().tolist()
/// ((1, 1, 3), [0.5, 0.25, 0.125])
#[pyfunction]
#[pyo3(name = "bilinearna")]
#[allow(non_snake_case)] // the thesis's argument names, for keyword calls
fn bilinearna<'py>(
    B: &Bound<'py, PyAny>,
    u: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
    N: usize,
) -> PyResult<Bound<'py, PyAny>> {
    by_exactness!([B, u, v], bilinearna_in(B, u, v, N))
}

fn bilinearna_in<'py, T: Num>(
    b: &Bound<'py, PyAny>,
    u: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
    n: usize,
) -> PyResult<Bound<'py, PyAny>> {
    const NAMES: Names = &[(Role::Net, "B")];
    let py = b.py();
    let (u, v) = (finite_scalar::<T>(u, "u")?, finite_scalar::<T>(v, "v")?);
    with_matrices::<T, _>(&[(b, "B")], &mut |m| {
        checked(NAMES, |cx| cx.check_degree(Role::Net, net_degree(&m[0])))?;
        let cost = patch_of(&m[0])?.scheme_cost(u.bits(), v.bits(), bits(&m[0]));
        check_work::<T>(NAMES, Role::Net, (1, cost))?;
        let (u, v) = (u.clone(), v.clone());
        let l = py
            .detach(|| compat::bilinearna(m[0].view(), u, v, n))
            .py()?;
        T::from_array(py, l)
    })
}

/// `A = tenzor(B)`: the packed net `(m+1) × 3(n+1)` as the array `(m+1) × (n+1) × 3`,
/// `A[i, j, :] = b_ij`.
///
/// >>> B = np.array([[0, 0, 0, 0, 1, 0], [1, 0, 0, 1, 1, 1]])
/// >>> A = cagd.octave.tenzor(B)
/// >>> A.shape, A[0, 1].tolist(), A[1, 1].tolist()
/// ((2, 2, 3), [0.0, 1.0, 0.0], [1.0, 1.0, 1.0])
#[pyfunction]
#[pyo3(name = "tenzor")]
#[allow(non_snake_case)] // the thesis's argument name, for keyword calls
fn tenzor<'py>(B: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    by_exactness!([B], tenzor_in(B))
}

fn tenzor_in<'py, T: Num>(b: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    with_matrices::<T, _>(&[(b, "B")], &mut |m| {
        T::from_array(b.py(), compat::tenzor(m[0].view()).py()?)
    })
}

/// `R, P = krpaCoons(c1, c2, d1, d2, P1, P2, P3, P4)`: the bilinearly blended Coons patch of
/// four boundary curves sampled at `linspace(0, 1, N)` (`3 × N` each: `c1 = x(u, 0)`,
/// `c2 = x(u, 1)`, `d1 = x(0, v)`, `d2 = x(1, v)`) with the corners `P1..P4` = `x(0,0)`,
/// `x(1,0)`, `x(0,1)`, `x(1,1)` (`3 × 1`), on `linspace(0, 1, N)²`: `R` packed `N × 3N`, `P`
/// `N × N × 3`. Both outputs always come back (Octave's `R = krpaCoons(...)` is
/// `R, _ = krpaCoons(...)` here).
///
/// >>> t, o, z = np.linspace(0, 1, 3), np.ones(3), np.zeros(3)  # the edges of (u, v, uv)
/// >>> c1, c2 = np.array([t, z, z]), np.array([t, o, t])
/// >>> d1, d2 = np.array([z, t, z]), np.array([o, t, t])
/// >>> corners = [np.array([[x], [y], [x * y]]) for y in (0, 1) for x in (0, 1)]
/// >>> R, P = cagd.octave.krpaCoons(c1, c2, d1, d2, *corners)
/// >>> R.shape, P.shape, P[1, 2].tolist()                        # x(1/2, 1)
/// ((3, 9), (3, 3, 3), [0.5, 1.0, 0.5])
#[pyfunction]
#[pyo3(name = "krpaCoons")]
#[allow(clippy::too_many_arguments, non_snake_case)] // the thesis signature, argument for argument
fn krpa_coons<'py>(
    c1: &Bound<'py, PyAny>,
    c2: &Bound<'py, PyAny>,
    d1: &Bound<'py, PyAny>,
    d2: &Bound<'py, PyAny>,
    P1: &Bound<'py, PyAny>,
    P2: &Bound<'py, PyAny>,
    P3: &Bound<'py, PyAny>,
    P4: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyTuple>> {
    let args = [c1, c2, d1, d2, P1, P2, P3, P4];
    by_exactness!([c1, c2, d1, d2, P1, P2, P3, P4], krpa_coons_in(&args))
}

fn krpa_coons_in<'py, T: Num>(args: &[&Bound<'py, PyAny>; 8]) -> PyResult<Bound<'py, PyTuple>> {
    const NAMES: [&str; 8] = ["c1", "c2", "d1", "d2", "P1", "P2", "P3", "P4"];
    let py = args[0].py();
    let objs: Vec<_> = args.iter().copied().zip(NAMES).collect();
    with_matrices::<T, _>(&objs, &mut |m| {
        const GRID: Names = &[(Role::Grid, "c1 (samples N)")];
        let n = m[0].ncols();
        checked(GRID, |cx| cx.check_grid(Role::Grid, n, n))?;
        let b = m.iter().map(bits).max().unwrap_or(0);
        let tb = sample_bits::<T>(n);
        let cost = cagd::coons::coons_point_cost([sampled_cost::<T>(n, b); 4], 3, tb, tb);
        check_work::<T>(GRID, Role::Grid, (n.saturating_mul(n), cost))?;
        let s = py
            .detach(|| compat::krpa_coons(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7]))
            .py()?;
        PyTuple::new(py, [T::from_array(py, s.r)?, T::from_array(py, s.p)?])
    })
}

/// `T, rc, rd, rcd = vrednostCoons(u, v, c1, c2, d1, d2, P1, P2, P3, P4)`: the point of the
/// Coons patch at `(u, v)` from the boundary points `c1 = c_1(u)`, `c2 = c_2(u)`,
/// `d1 = d_1(v)`, `d2 = d_2(v)` and the corners (`d × 1` columns), with its three parts
/// `T = rc + rd − rcd`. All four outputs always come back (Octave's `T = vrednostCoons(...)`
/// is `T, *_ = vrednostCoons(...)` here).
///
/// >>> col = lambda *x: np.array(x, dtype=object).reshape(-1, 1)
/// >>> u, v = Fraction(1, 5), Fraction(1, 2)                    # thesis Primer 4.3
/// >>> c1, c2 = col(u, 0, u - u * u), col(u, 1, u)
/// >>> d1, d2 = col(0, v * v, v - v * v), col(1, v, v)
/// >>> corners = col(0, 0, 0), col(1, 0, 0), col(0, 1, 0), col(1, 1, 1)
/// >>> T, rc, rd, rcd = cagd.octave.vrednostCoons(u, v, c1, c2, d1, d2, *corners)
/// >>> [str(x) for x in T.ravel()], [str(x) for x in rcd.ravel()]
/// (['1/5', '3/10', '19/50'], ['1/5', '1/2', '1/10'])
#[pyfunction]
#[pyo3(name = "vrednostCoons")]
#[allow(clippy::too_many_arguments, non_snake_case)] // the thesis signature, argument for argument
fn vrednost_coons<'py>(
    u: &Bound<'py, PyAny>,
    v: &Bound<'py, PyAny>,
    c1: &Bound<'py, PyAny>,
    c2: &Bound<'py, PyAny>,
    d1: &Bound<'py, PyAny>,
    d2: &Bound<'py, PyAny>,
    P1: &Bound<'py, PyAny>,
    P2: &Bound<'py, PyAny>,
    P3: &Bound<'py, PyAny>,
    P4: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyTuple>> {
    let args = [u, v, c1, c2, d1, d2, P1, P2, P3, P4];
    by_exactness!(
        [u, v, c1, c2, d1, d2, P1, P2, P3, P4],
        vrednost_coons_in(&args)
    )
}

fn vrednost_coons_in<'py, T: Num>(
    args: &[&Bound<'py, PyAny>; 10],
) -> PyResult<Bound<'py, PyTuple>> {
    const NAMES: [&str; 8] = ["c1", "c2", "d1", "d2", "P1", "P2", "P3", "P4"];
    let py = args[0].py();
    let (u, v) = (
        finite_scalar::<T>(args[0], "u")?,
        finite_scalar::<T>(args[1], "v")?,
    );
    let objs: Vec<_> = args[2..].iter().copied().zip(NAMES).collect();
    with_matrices::<T, _>(&objs, &mut |m| {
        let r = compat::vrednost_coons(
            u.clone(),
            v.clone(),
            m[0],
            m[1],
            m[2],
            m[3],
            m[4],
            m[5],
            m[6],
            m[7],
        )
        .py()?;
        let parts = [r.t, r.rc, r.rd, r.rcd].map(|a| T::from_array(py, a));
        PyTuple::new(py, parts.into_iter().collect::<PyResult<Vec<_>>>()?)
    })
}

/// `R, P = krpaGordon(g_u, g_v, g_uv, x_u, x_v, N)`: the Gordon surface of a curve network
/// sampled at `linspace(0, 1, N')` (`g_u = [c_0 … c_n]`, `c_j(u) = g(u, v_j)`;
/// `g_v = [d_0 … d_m]`, `d_i(v) = g(u_i, v)`; the crossings `g_uv` packed `(m+1) × 3(n+1)`,
/// `g_uv[i, 3j:3j+3] = g(u_i, v_j)`; nodes `x_u`, `x_v`) on `linspace(0, 1, N)²`: `R` packed
/// `N × 3N`, `P` `N × N × 3`. Both outputs always come back.
///
/// >>> t, o, z = np.linspace(0, 1, 3), np.ones(3), np.zeros(3)  # the network of (u, v, uv)
/// >>> g_u = np.hstack([np.array([t, z, z]), np.array([t, o, t])])   # g(u, 0), g(u, 1)
/// >>> g_v = np.hstack([np.array([z, t, z]), np.array([o, t, t])])   # g(0, v), g(1, v)
/// >>> g_uv = np.array([[0, 0, 0, 0, 1, 0], [1, 0, 0, 1, 1, 1]])
/// >>> R, P = cagd.octave.krpaGordon(g_u, g_v, g_uv, [0, 1], [0, 1], 3)
/// >>> P.shape, P[1, 2].tolist()                                 # x(1/2, 1)
/// ((3, 3, 3), [0.5, 1.0, 0.5])
#[pyfunction]
#[pyo3(name = "krpaGordon")]
#[allow(non_snake_case)] // the thesis's argument names, for keyword calls
fn krpa_gordon<'py>(
    g_u: &Bound<'py, PyAny>,
    g_v: &Bound<'py, PyAny>,
    g_uv: &Bound<'py, PyAny>,
    x_u: &Bound<'py, PyAny>,
    x_v: &Bound<'py, PyAny>,
    N: usize,
) -> PyResult<Bound<'py, PyTuple>> {
    let args = [g_u, g_v, g_uv, x_u, x_v];
    by_exactness!([g_u, g_v, g_uv, x_u, x_v], krpa_gordon_in(&args, N))
}

fn krpa_gordon_in<'py, T: Num>(
    args: &[&Bound<'py, PyAny>; 5],
    n: usize,
) -> PyResult<Bound<'py, PyTuple>> {
    const NAMES: [&str; 5] = ["g_u", "g_v", "g_uv", "x_u", "x_v"];
    let py = args[0].py();
    checked(GORDON_NAMES, |cx| cx.check_grid(Role::Grid, n, n))?;
    let objs: Vec<_> = args.iter().copied().zip(NAMES).collect();
    with_matrices::<T, _>(&objs, &mut |m| {
        checked(GORDON_NAMES, |cx| {
            cx.check_degree(Role::UNodes, m[3].len().saturating_sub(1))?;
            cx.check_degree(Role::VNodes, m[4].len().saturating_sub(1))
        })?;
        check_gordon_work::<T>(m, n)?;
        let s = py
            .detach(|| compat::krpa_gordon(m[0], m[1], m[2], m[3], m[4], n))
            .py()?;
        PyTuple::new(py, [T::from_array(py, s.r)?, T::from_array(py, s.p)?])
    })
}

/// Refuses a Gordon surface whose set-up and `N × N` points cost more than the limit on work
/// (the core's [`gordon_point_cost`](cagd::gordon::gordon_point_cost) and
/// [`gordon_setup_cost`](cagd::gordon::gordon_setup_cost) of the sampled network).
fn check_gordon_work<T: Num>(m: &[ArrayView2<'_, T>], n: usize) -> PyResult<()> {
    let (k_u, k_v) = (m[3].len(), m[4].len());
    let b = m[..3].iter().map(bits).max().unwrap_or(0);
    let x_bits = bits(&m[3]).max(bits(&m[4]));
    let at_v = sampled_cost::<T>(m[0].ncols() / k_v.max(1), b);
    let at_u = sampled_cost::<T>(m[1].ncols() / k_u.max(1), b);
    let curves = || std::iter::repeat_n(at_u, k_u).chain(std::iter::repeat_n(at_v, k_v));
    let tb = sample_bits::<T>(n);
    let point =
        cagd::gordon::gordon_point_cost(curves(), (k_u, k_v), 3, (tb, x_bits), (tb, x_bits));
    let setup = cagd::gordon::gordon_setup_cost(
        std::iter::repeat_n(at_u, k_u),
        std::iter::repeat_n(at_v, k_v),
        (x_bits, x_bits),
    );
    let work = (n.saturating_mul(n) as u128)
        .saturating_mul(point.weigh(T::EXACT))
        .saturating_add(setup.weigh(T::EXACT));
    checked(GORDON_NAMES, |cx| cx.check_work(Role::Grid, work))
}

/// How `krpaGordon` names the roles of its checks.
const GORDON_NAMES: Names = &[
    (Role::UNodes, "x_u"),
    (Role::VNodes, "x_v"),
    (Role::Grid, "N"),
];

/// `v = Lagrange(x, m, u)`: the `m`-th (from 1) Lagrange basis polynomial of the nodes `x` at
/// every value of `u` (any shape; a number gives a number).
///
/// >>> cagd.octave.Lagrange([0, 1, 2], 2, 0.5)                 # L_1(1/2) = (1/2)(−3/2)/(−1)
/// 0.75
/// >>> cagd.octave.Lagrange([0, 1, 2], 1, [Fraction(1, 2), 3]).tolist()   # exact: L_0
/// [Fraction(3, 8), Fraction(1, 1)]
#[pyfunction]
#[pyo3(name = "Lagrange")]
fn lagrange<'py>(
    x: &Bound<'py, PyAny>,
    m: usize,
    u: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    by_exactness!([x, u], lagrange_in(x, m, u))
}

fn lagrange_in<'py, T: Num>(
    x: &Bound<'py, PyAny>,
    m: usize,
    u: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let py = x.py();
    const NAMES: Names = &[(Role::Nodes, "x"), (Role::T, "u")];
    with_matrices::<T, _>(&[(x, "x")], &mut |nodes| {
        checked(NAMES, |cx| {
            cx.check_degree(Role::Nodes, nodes[0].len().saturating_sub(1))
        })?;
        T::with_values(u, "u", |shape, values| {
            finite("u", values)?;
            let u_bits = values.iter().map(|x| x.bits()).max().unwrap_or(0);
            let (count, x_bits) = (nodes[0].len(), bits(&nodes[0]));
            let cost = cagd::lagrange::Lagrange::<f64>::basis_cost(count, u_bits, x_bits);
            check_work::<T>(NAMES, Role::T, (values.len(), cost))?;
            let view = ArrayViewD::from_shape(IxDyn(shape), values)
                .map_err(|e| crate::error::conversion("u", e.to_string()))?;
            let l = py.detach(|| compat::lagrange(nodes[0], m, view)).py()?;
            if shape.is_empty() {
                return l
                    .iter()
                    .next()
                    .map_or_else(|| Ok(py.None().into_bound(py)), |x| x.to_py(py));
            }
            T::from_array(py, l)
        })
    })
}

/// The variables of an Octave text file (`save -text`) as a dict of `float64` arrays (numbers
/// and matrices as 2-D arrays, N-d arrays with their shape, strings as `str`).
#[pyfunction]
fn load<'py>(py: Python<'py>, path: std::path::PathBuf) -> PyResult<Bound<'py, PyDict>> {
    let ws = cagd_octave::read_text_file(&path)
        .map_err(|e| crate::error::cagd_error("TextFormat", Some("path"), e.to_string()))?;
    let out = PyDict::new(py);
    for (name, value) in ws.iter() {
        if let Some(s) = value.as_str() {
            out.set_item(name, s)?;
        } else if let Some(a) = value.to_array_with(&limits()) {
            out.set_item(name, f64::from_array(py, a)?)?;
        }
    }
    Ok(out)
}

/// Writes the keyword arguments as the variables of an Octave text file (`save -text`; `load`
/// in Octave reads them back): numbers and arrays of real numbers (1-D arrays as rows), every
/// bit of every double kept.
#[pyfunction]
#[pyo3(signature = (path, **variables))]
fn save(path: std::path::PathBuf, variables: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    let mut ws = cagd_octave::Workspace::new();
    for (name, value) in variables.into_iter().flatten() {
        let name: String = name.extract()?;
        let array = f64::with_values(&value, "variables", |shape, v| {
            let shape = match *shape {
                [] => vec![1, 1],
                [n] => vec![1, n],
                _ => shape.to_vec(),
            };
            ndarray::ArrayD::from_shape_vec(IxDyn(&shape), v.to_vec())
                .map_err(|e| crate::error::conversion("variables", e.to_string()))
        })?;
        ws.insert(name, array);
    }
    cagd_octave::write_text_file(&path, &ws)
        .map_err(|e| crate::error::cagd_error("TextFormat", Some("path"), e.to_string()))
}

/// Registers the functions in the module `m` (`cagd._cagd`, re-exported as `cagd.octave`).
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(de_casteljau, m)?)?;
    m.add_function(wrap_pyfunction!(ploskev_b, m)?)?;
    m.add_function(wrap_pyfunction!(bilinearna, m)?)?;
    m.add_function(wrap_pyfunction!(tenzor, m)?)?;
    m.add_function(wrap_pyfunction!(krpa_coons, m)?)?;
    m.add_function(wrap_pyfunction!(vrednost_coons, m)?)?;
    m.add_function(wrap_pyfunction!(krpa_gordon, m)?)?;
    m.add_function(wrap_pyfunction!(lagrange, m)?)?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(save, m)?)?;
    Ok(())
}

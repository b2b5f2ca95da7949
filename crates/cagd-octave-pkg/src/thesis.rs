//! The thesis functions, fixed, under their own names and with their own arguments: the
//! numbers of `octave_ref/fixed/`, with Octave's arrays passed in without a copy and the
//! results written into the arrays Octave returns.
//!
//! | Octave | built on |
//! |---|---|
//! | `T = deCasteljau (kontrolneT, N)` | [`BezierCurve::eval_many_into`] |
//! | `P = ploskevB (kontrolneT, N)` | [`compat::tenzor`], [`BezierPatch::eval_grid_into`] |
//! | `L = bilinearna (B, u, v, N)` | the twin [`compat::bilinearna`] |
//! | `A = tenzor (B)` | the twin [`compat::tenzor`] |
//! | `[R, P] = krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4)` | [`CoonsPatch::with_corners`] of [`SampledCurve`]s, [`CoonsPatch::eval_grid_into`] |
//! | `[T, rc, rd, rcd] = vrednostCoons (u, v, c1, c2, d1, d2, P1, P2, P3, P4)` | the twin [`compat::vrednost_coons`] |
//! | `[R, P] = krpaGordon (g_u, g_v, g_uv, x_u, x_v, N)` | the twin [`compat::krpa_gordon`] |
//! | `v = Lagrange (x, m, u)` | the twin [`compat::lagrange`] |
//!
//! The twins of `cagd_octave::compat` reproduce the fixed Octave code operation by operation
//! (bit for bit on the reference cases) but evaluate point by point. For the three functions
//! that sample whole curves and grids the package calls the core's grid evaluation instead:
//! the same checks and the same constructions, evaluated by Bernstein sums (`deCasteljau`,
//! `ploskevB`) and by the regrouped Coons formula (`krpaCoons`), one to three orders of
//! magnitude faster. The values then agree with the fixed Octave code within a few units of
//! rounding of the scale of the data (4 ULPs or `1e-14` relative to the largest value of the
//! array), which `octave_pkg/tests/` checks on the thesis's examples and on random cases.
//!
//! The drawing the originals did when called without an output is done by the package's `.m`
//! files with Octave's own `plot3` and `surf`.

use cagd::bezier::{BezierCurve, BezierPatch};
use cagd::coons::{CoonsPatch, Tolerance};
use cagd::param::SampledCurve;
use cagd_octave::compat;
use nalgebra::{DMatrix, DVector};
use ndarray::{ArrayView, ArrayView2, Dimension};

use crate::args::Call;
use crate::error::{PkgError, Result};
use crate::value::Sink;

/// The form of a packed control net.
const NET_FORM: &str = "a packed net (m+1) × 3(n+1), B(i+1, 3j+1:3j+3) = b_ij";
/// The form of a sampled curve.
const SAMPLED_FORM: &str = "a 3 × N matrix of samples at linspace (0, 1, N)";
/// The form of a corner or a point.
const POINT_FORM: &str = "a d × 1 column";
/// The form of a node vector.
const NODES_FORM: &str = "a row or column of distinct nodes";

/// A twin's result: its error keeps the library's text without the twin's own name in front
/// (`"de_casteljau: kontrolneT: …"` reads `"kontrolneT: …"` after the Octave name).
fn twin<T>(result: cagd::Result<T>, twin_name: &str) -> Result<T> {
    result.map_err(|e| {
        let mut err = PkgError::from(e);
        let prefix = format!("{twin_name}: ");
        if let Some(rest) = err.message.strip_prefix(&prefix) {
            err.message = rest.to_string();
        }
        err
    })
}

/// Output `index`: the array `a` with Octave size `dims`, written column-major.
pub(crate) fn emit_array<D: Dimension>(
    sink: &mut dyn Sink,
    index: usize,
    dims: &[usize],
    a: ArrayView<'_, f64, D>,
) -> Result<()> {
    let out = sink.real(index, dims)?;
    // The reversed view in logical order visits the array in column-major order.
    for (o, x) in out.iter_mut().zip(a.t().iter()) {
        *o = *x;
    }
    Ok(())
}

/// The shape of an ndarray as Octave's size (at least two entries).
fn octave_dims(shape: &[usize]) -> Vec<usize> {
    let mut dims = shape.to_vec();
    while dims.len() < 2 {
        dims.push(1);
    }
    dims
}

/// Argument `i`: a non-empty matrix view.
fn net<'a>(call: &Call<'_, 'a>, i: usize, what: &str, form: &str) -> Result<ArrayView2<'a, f64>> {
    call.nonempty(i, what, form)?;
    call.view2(i, what, form)
}

/// Degrees `(m, n)` of a packed net with `rows` rows and `cols` columns (`cols / 3` points per
/// row; the twin reports a column count that is not a multiple of 3).
fn net_degrees(b: &ArrayView2<'_, f64>) -> (usize, usize) {
    (
        b.nrows().saturating_sub(1),
        (b.ncols() / 3).saturating_sub(1),
    )
}

/// `T = deCasteljau (kontrolneT, N)`.
pub fn de_casteljau(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "T = deCasteljau (kontrolneT, N)")?;
    call.nargout_max(1)?;
    let form = "a d × (n+1) matrix, one control point per column";
    let p = net(call, 0, "kontrolneT", form)?;
    let n = call.count(1, "N")?;
    call.check_samples("N", n)?;
    let (d, points) = p.dim();
    call.check_degree("kontrolneT (degree)", points - 1)?;
    call.check_work("N", n, points * (points + d))?;
    cagd::error::check_finite("kontrolneT", p.t().iter())?;
    let curve = BezierCurve::new(DMatrix::from_fn(d, points, |i, j| p[[i, j]]))?;
    // `d × N` column-major is the core's `N × d` row-major: written in place.
    let out = sink.real(0, &[d, n])?;
    curve.eval_many_into(&cagd::linspace(0.0, 1.0, n), out)?;
    Ok(())
}

/// Writes a grid held row-major as `(nu, nv, 3)` as Octave's `nu × nv × 3` array (the layout
/// of `P` in `ploskevB`, `krpaCoons`, `krpaGordon`).
fn emit_thesis_grid(
    sink: &mut dyn Sink,
    index: usize,
    (nu, nv): (usize, usize),
    grid: &[f64],
) -> Result<()> {
    let out = sink.real(index, &[nu, nv, 3])?;
    for (k, x) in grid.iter().enumerate() {
        let (point, c) = (k / 3, k % 3);
        let (i, j) = (point / nv, point % nv);
        out[i + nu * (j + nv * c)] = *x;
    }
    Ok(())
}

/// Writes a grid held row-major as `(N, N, 3)` as the packed `N × 3N` matrix `R` of
/// `krpaCoons` and `krpaGordon`: `R(i, 3j+c) = P(i, j, c)`.
fn emit_packed(sink: &mut dyn Sink, index: usize, n: usize, grid: &[f64]) -> Result<()> {
    let out = sink.real(index, &[n, 3 * n])?;
    for (k, x) in grid.iter().enumerate() {
        let (point, c) = (k / 3, k % 3);
        let (i, j) = (point / n, point % n);
        out[i + n * (3 * j + c)] = *x;
    }
    Ok(())
}

/// `P = ploskevB (kontrolneT, N)`.
pub fn ploskev_b(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "P = ploskevB (kontrolneT, N)")?;
    call.nargout_max(1)?;
    let b = net(call, 0, "kontrolneT", NET_FORM)?;
    let n = call.count(1, "N")?;
    call.check_grid("N", n, n)?;
    let (dm, dn) = net_degrees(&b);
    call.check_degree("kontrolneT (degree)", dm.max(dn))?;
    call.check_work("N", n * n, (dm + dn + 2) * 3)?;
    let a = twin(compat::tenzor(b), "tenzor")?;
    let (rows, cols, _) = a.dim();
    let coords = (0..3)
        .map(|c| DMatrix::from_fn(rows, cols, |i, j| a[[i, j, c]]))
        .collect();
    let patch = BezierPatch::new(coords)?;
    let t = cagd::linspace(0.0, 1.0, n);
    let mut grid = vec![0.0; n * n * 3];
    patch.eval_grid_into(&t, &t, &mut grid)?;
    emit_thesis_grid(sink, 0, (n, n), &grid)
}

/// `L = bilinearna (B, u, v, N)`.
pub fn bilinearna(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "L = bilinearna (B, u, v, N)")?;
    call.nargout_max(1)?;
    let b = net(call, 0, "B", NET_FORM)?;
    let u = call.scalar(1, "u")?;
    let v = call.scalar(2, "v")?;
    let n = call.count(3, "N")?;
    let (dm, dn) = net_degrees(&b);
    call.check_degree("B (degree)", dm.max(dn))?;
    call.check_work("B", 1, (dm + 1) * (dn + 1) * (dm.min(dn) + 1) * 3)?;
    let l = twin(compat::bilinearna(b, u, v, n), "bilinearna")?;
    emit_array(sink, 0, &[1, 1, 3], l.view())
}

/// `A = tenzor (B)`.
pub fn tenzor(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(1, 1, "A = tenzor (B)")?;
    call.nargout_max(1)?;
    let b = net(call, 0, "B", NET_FORM)?;
    let a = twin(compat::tenzor(b), "tenzor")?;
    emit_array(sink, 0, &octave_dims(a.shape()), a.view())
}

/// `[R, P] = krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4)`.
pub fn krpa_coons(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(8, 8, "[R, P] = krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4)")?;
    call.nargout_max(2)?;
    const NAMES: [&str; 8] = ["c1", "c2", "d1", "d2", "P1", "P2", "P3", "P4"];
    let mut views = Vec::with_capacity(8);
    for (i, name) in NAMES.iter().enumerate() {
        let form = if i < 4 { SAMPLED_FORM } else { POINT_FORM };
        views.push(net(call, i, name, form)?);
    }
    let n = views[0].ncols();
    for (k, v) in views.iter().enumerate() {
        let want = if k < 4 { (3, n) } else { (3, 1) };
        if v.dim() != want {
            return Err(cagd::Error::ShapeMismatch {
                what: NAMES[k],
                expected: format!("{}×{}", want.0, want.1),
                found: format!("{}×{}", v.nrows(), v.ncols()),
            }
            .into());
        }
        cagd::error::check_finite(NAMES[k], v.t().iter())?;
    }
    if n < 2 {
        return Err(cagd::Error::TooFewPoints {
            what: "c1 (samples N)",
            min: 2,
            found: n,
        }
        .into());
    }
    call.check_grid("c1 (samples N)", n, n)?;
    let t = cagd::linspace(0.0, 1.0, n);
    let curve = |v: &ArrayView2<'_, f64>| {
        SampledCurve::new(t.clone(), DMatrix::from_fn(3, n, |i, j| v[[i, j]]))
    };
    let corner = |v: &ArrayView2<'_, f64>| DVector::from_fn(3, |i, _| v[[i, 0]]);
    let patch = CoonsPatch::with_corners(
        curve(&views[0])?,
        curve(&views[1])?,
        curve(&views[2])?,
        curve(&views[3])?,
        [
            corner(&views[4]),
            corner(&views[5]),
            corner(&views[6]),
            corner(&views[7]),
        ],
        Tolerance::default(),
    )?;
    let mut grid = vec![0.0; n * n * 3];
    patch.eval_grid_into(&t, &t, &mut grid)?;
    emit_packed(sink, 0, n, &grid)?;
    if call.nargout > 1 {
        emit_thesis_grid(sink, 1, (n, n), &grid)?;
    }
    Ok(())
}

/// `[T, rc, rd, rcd] = vrednostCoons (u, v, c1, c2, d1, d2, P1, P2, P3, P4)`.
pub fn vrednost_coons(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        10,
        10,
        "[T, rc, rd, rcd] = vrednostCoons (u, v, c1, c2, d1, d2, P1, P2, P3, P4)",
    )?;
    call.nargout_max(4)?;
    let u = call.scalar(0, "u")?;
    let v = call.scalar(1, "v")?;
    let names = ["c1", "c2", "d1", "d2", "P1", "P2", "P3", "P4"];
    let mut views = Vec::with_capacity(8);
    for (i, name) in names.iter().enumerate() {
        views.push(net(call, i + 2, name, POINT_FORM)?);
    }
    let r = twin(
        compat::vrednost_coons(
            u, v, views[0], views[1], views[2], views[3], views[4], views[5], views[6], views[7],
        ),
        "vrednost_coons",
    )?;
    for (k, part) in [&r.t, &r.rc, &r.rd, &r.rcd]
        .into_iter()
        .enumerate()
        .take(call.nargout)
    {
        emit_array(sink, k, &octave_dims(part.shape()), part.view())?;
    }
    Ok(())
}

/// `[R, P] = krpaGordon (g_u, g_v, g_uv, x_u, x_v, N)`.
pub fn krpa_gordon(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(6, 6, "[R, P] = krpaGordon (g_u, g_v, g_uv, x_u, x_v, N)")?;
    call.nargout_max(2)?;
    let g_u = net(call, 0, "g_u", "a 3 × (n+1)N matrix [c_0 … c_n]")?;
    let g_v = net(call, 1, "g_v", "a 3 × (m+1)N matrix [d_0 … d_m]")?;
    let g_uv = net(call, 2, "g_uv", "an (m+1) × 3(n+1) matrix of crossings")?;
    let x_u = net(call, 3, "x_u", NODES_FORM)?;
    let x_v = net(call, 4, "x_v", NODES_FORM)?;
    let n = call.count(5, "N")?;
    call.check_grid("N", n, n)?;
    call.check_degree("x_u (nodes - 1)", x_u.len().saturating_sub(1))?;
    call.check_degree("x_v (nodes - 1)", x_v.len().saturating_sub(1))?;
    call.check_work("N", n * n, (x_u.len() + x_v.len() + 2) * 3)?;
    let s = twin(
        compat::krpa_gordon(g_u, g_v, g_uv, x_u, x_v, n),
        "krpa_gordon",
    )?;
    emit_array(sink, 0, &octave_dims(s.r.shape()), s.r.view())?;
    if call.nargout > 1 {
        emit_array(sink, 1, &octave_dims(s.p.shape()), s.p.view())?;
    }
    Ok(())
}

/// `v = Lagrange (x, m, u)`.
pub fn lagrange(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(3, 3, "v = Lagrange (x, m, u)")?;
    call.nargout_max(1)?;
    let x = net(call, 0, "x", NODES_FORM)?;
    let m = call.count(1, "m")?;
    let u_dims = call.real(2, "u", "an array of parameters")?.dims;
    let u = call.view_dyn(2, "u", "an array of parameters")?;
    call.check_degree("x (nodes - 1)", x.len().saturating_sub(1))?;
    call.check_work("u", u.len(), x.len())?;
    let v = twin(compat::lagrange(x, m, u), "lagrange")?;
    emit_array(sink, 0, u_dims, v.view())
}

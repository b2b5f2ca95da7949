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
//! | `[R, P] = krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4)` | [`CoonsPatch::with_corners`](cagd::coons::CoonsPatch::with_corners) of [`SampledCurve`](cagd::param::SampledCurve)s, [`CoonsPatch::eval_grid_into`](cagd::coons::CoonsPatch::eval_grid_into) |
//! | `[T, rc, rd, rcd] = vrednostCoons (u, v, c1, c2, d1, d2, P1, P2, P3, P4)` | the twin [`compat::vrednost_coons`] |
//! | `[R, P] = krpaGordon (g_u, g_v, g_uv, x_u, x_v, N)` | the twin's network [`compat::krpa_gordon_surface`], evaluated band by band |
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
//! Each function prices its work with the core's own estimates, as the command line prices
//! the same construction (de Casteljau points, a Bézier patch's grid or scheme, a Coons patch,
//! a Gordon surface, a Lagrange basis), and refuses it above `max_work` with the same words.
//! The grids and lists of points are evaluated in chunks of a few milliseconds between which
//! Octave's Ctrl-C stops the function. A result that overflows the range of doubles
//! (finite arguments, an infinite or NaN value) is refused with `cagd:overflow`, never
//! returned.
//!
//! The drawing the originals did when called without an output is done by the package's `.m`
//! files with Octave's own `plot3` and `surf`.

use cagd::bezier::{BezierCurve, BezierPatch};
use cagd::lagrange::Lagrange;
use cagd_octave::compat;
use nalgebra::DMatrix;
use ndarray::{ArrayView, ArrayView1, ArrayView2, Dimension};

use crate::args::Call;
use crate::error::{PkgError, Result};
use crate::value::Sink;

mod grids;

pub use grids::{krpa_coons, krpa_gordon, ploskev_b};

/// The form of a packed control net.
const NET_FORM: &str = "a packed net (m+1) × 3(n+1), B(i+1, 3j+1:3j+3) = b_ij";
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

/// Refuses a result `values` (output `what`) holding NaN or ±Inf: finite arguments whose
/// result overflows the range of doubles (the core's [`cagd::Error::Overflow`],
/// `cagd:overflow`).
///
/// # Errors
/// [`Kind::Overflow`](crate::Kind::Overflow).
fn finite_result<'a>(what: &'static str, values: impl IntoIterator<Item = &'a f64>) -> Result<()> {
    Ok(cagd::error::check_overflow(what, values)?)
}

/// Output `index`: the array `a` with Octave size `dims`, written column-major, refused if it
/// overflowed ([`finite_result`], `what` its name).
pub(crate) fn emit_array<D: Dimension>(
    sink: &mut dyn Sink,
    (index, what): (usize, &'static str),
    dims: &[usize],
    a: ArrayView<'_, f64, D>,
) -> Result<()> {
    finite_result(what, a.iter())?;
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

/// The Bézier patch of a packed net (through the twin of `tenzor`, which checks it).
fn packed_patch(b: ArrayView2<'_, f64>) -> Result<BezierPatch<f64>> {
    let a = twin(compat::tenzor(b), "tenzor")?;
    let (rows, cols, _) = a.dim();
    let coords = (0..3)
        .map(|c| DMatrix::from_fn(rows, cols, |i, j| a[[i, j, c]]))
        .collect();
    Ok(BezierPatch::new(coords)?)
}

/// `T = deCasteljau (kontrolneT, N)`: priced as de Casteljau's points
/// ([`BezierCurve::eval_cost`], the command line's `decasteljau`).
pub fn de_casteljau(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "T = deCasteljau (kontrolneT, N)")?;
    call.nargout_max(1)?;
    let form = "a d × (n+1) matrix, one control point per column";
    let p = net(call, 0, "kontrolneT", form)?;
    let n = call.count(1, "N")?;
    call.check_samples("N", n)?;
    let (d, points) = p.dim();
    call.check_degree("kontrolneT (degree)", points - 1)?;
    cagd::error::check_finite("kontrolneT", p.t().iter())?;
    let curve = BezierCurve::new(DMatrix::from_fn(d, points, |i, j| p[[i, j]]))?;
    let per_point = curve.eval_cost(0, 0);
    call.check_cost("N", per_point.times(n as u128))?;
    // `d × N` column-major is the core's `N × d` row-major: written in place.
    let t = cagd::linspace(0.0, 1.0, n);
    let out = sink.real(0, &[d, n])?;
    call.in_chunks((&t, per_point), (&mut *out, d), |ts, buffer| {
        Ok(curve.eval_many_into(ts, buffer)?)
    })?;
    finite_result("T", out.iter())
}

/// `L = bilinearna (B, u, v, N)`: priced as one point of a Bézier patch by its scheme
/// ([`BezierPatch::scheme_cost`]).
pub fn bilinearna(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "L = bilinearna (B, u, v, N)")?;
    call.nargout_max(1)?;
    let b = net(call, 0, "B", NET_FORM)?;
    let u = call.scalar(1, "u")?;
    let v = call.scalar(2, "v")?;
    let n = call.count(3, "N")?;
    let (dm, dn) = net_degrees(&b);
    call.check_degree("B (degree)", dm.max(dn))?;
    call.check_cost("B", packed_patch(b)?.scheme_cost(0, 0, 0))?;
    let l = twin(compat::bilinearna(b, u, v, n), "bilinearna")?;
    emit_array(sink, (0, "L"), &[1, 1, 3], l.view())
}

/// `A = tenzor (B)`.
pub fn tenzor(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(1, 1, "A = tenzor (B)")?;
    call.nargout_max(1)?;
    let b = net(call, 0, "B", NET_FORM)?;
    let a = twin(compat::tenzor(b), "tenzor")?;
    emit_array(sink, (0, "A"), &octave_dims(a.shape()), a.view())
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
    let parts = [(&r.t, "T"), (&r.rc, "rc"), (&r.rd, "rd"), (&r.rcd, "rcd")];
    for (part, name) in &parts {
        finite_result(name, part.iter())?;
    }
    for (k, (part, name)) in parts.into_iter().enumerate().take(call.nargout) {
        emit_array(sink, (k, name), &octave_dims(part.shape()), part.view())?;
    }
    Ok(())
}

/// `v = Lagrange (x, m, u)`: priced as the Lagrange basis at every parameter
/// ([`Lagrange::basis_cost`]), evaluated in chunks of `u` (column-major) between which the
/// function may be interrupted.
pub fn lagrange(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(3, 3, "v = Lagrange (x, m, u)")?;
    call.nargout_max(1)?;
    let x = net(call, 0, "x", NODES_FORM)?;
    let m = call.count(1, "m")?;
    let u = call.real(2, "u", "an array of parameters")?;
    call.check_degree("x (nodes - 1)", x.len().saturating_sub(1))?;
    let per_point = Lagrange::<f64>::basis_cost(x.len(), 0, 0);
    call.check_cost("u", per_point.times(u.len() as u128))?;
    let lagrange = |part: &[f64]| twin(compat::lagrange(x, m, ArrayView1::from(part)), "lagrange");
    // The nodes and the index first, then every parameter, as the twin checks them.
    lagrange(&[])?;
    twin(cagd::error::check_finite("lagrange: u", u.data), "lagrange")?;
    let out = sink.real(0, u.dims)?;
    call.in_chunks((u.data, per_point), (&mut *out, 1), |part, buffer| {
        let v = lagrange(part)?;
        buffer.copy_from_slice(v.as_slice().expect("a new 1-D array is contiguous"));
        Ok(())
    })?;
    finite_result("v", out.iter())
}

//! The thesis functions that sample whole grids: `ploskevB`, `krpaCoons`, `krpaGordon`. Each
//! prices its grid as the command line prices the same surface, evaluates it band by band of
//! `u` rows (between which Octave's Ctrl-C stops it) and refuses a grid that overflowed.

use cagd::coons::{coons_point_cost, CoonsPatch, Tolerance};
use cagd::cost::Cost;
use cagd::gordon::{gordon_point_cost, gordon_setup_cost};
use cagd::param::{SampledCurve, Surface};
use cagd_octave::compat;
use nalgebra::{DMatrix, DVector};
use ndarray::ArrayView2;

use super::{
    finite_result, net, net_degrees, packed_patch, twin, NET_FORM, NODES_FORM, POINT_FORM,
};
use crate::args::Call;
use crate::error::Result;
use crate::value::Sink;

/// The form of a sampled curve.
const SAMPLED_FORM: &str = "a 3 × N matrix of samples at linspace (0, 1, N)";

/// The grid `us × vs` of 3-D points, row-major `(nu, nv, 3)`, filled by `fill(band, vs,
/// buffer)` a band of `u` rows at a time (each about a few milliseconds of `per_point` work),
/// between which the call may be interrupted; refused if a value overflowed (`what`).
///
/// # Errors
/// `fill`'s; [`Kind::Interrupted`](crate::Kind::Interrupted); [`Kind::Overflow`](crate::Kind::Overflow).
fn grid_in_bands(
    call: &Call<'_, '_>,
    (us, vs): (&[f64], &[f64]),
    (per_point, what): (Cost, &'static str),
    fill: impl Fn(&[f64], &[f64], &mut [f64]) -> Result<()>,
) -> Result<Vec<f64>> {
    let row = 3 * vs.len();
    let mut grid = vec![0.0; us.len() * row];
    let per_row = per_point.times(vs.len() as u128);
    call.in_chunks((us, per_row), (&mut grid, row), |band, out| {
        fill(band, vs, out)
    })?;
    finite_result(what, &grid)?;
    Ok(grid)
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

/// `R` (packed) and, with two outputs, `P` of an `N × N` grid.
fn emit_r_p(call: &Call<'_, '_>, sink: &mut dyn Sink, n: usize, grid: &[f64]) -> Result<()> {
    emit_packed(sink, 0, n, grid)?;
    if call.nargout > 1 {
        emit_thesis_grid(sink, 1, (n, n), grid)?;
    }
    Ok(())
}

/// `P = ploskevB (kontrolneT, N)`: priced as a Bézier patch on a grid
/// ([`BezierPatch::grid_cost`](cagd::BezierPatch::grid_cost), the command line's
/// `bezier-patch`).
pub fn ploskev_b(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "P = ploskevB (kontrolneT, N)")?;
    call.nargout_max(1)?;
    let b = net(call, 0, "kontrolneT", NET_FORM)?;
    let n = call.count(1, "N")?;
    call.check_grid("N", n, n)?;
    let (dm, dn) = net_degrees(&b);
    call.check_degree("kontrolneT (degree)", dm.max(dn))?;
    let patch = packed_patch(b)?;
    let per_point = patch.grid_cost(0, 0, 0);
    call.check_cost("N", per_point.times((n * n) as u128))?;
    let t = cagd::linspace(0.0, 1.0, n);
    let grid = grid_in_bands(call, (&t, &t), (per_point, "P"), |us, vs, out| {
        Ok(patch.eval_grid_into(us, vs, out)?)
    })?;
    emit_thesis_grid(sink, 0, (n, n), &grid)
}

/// The four boundary curves and four corners of `krpaCoons`, checked: `3 × N` samples
/// (`N ≥ 2`) and `3 × 1` corners, finite.
fn coons_data<'a>(call: &Call<'_, 'a>) -> Result<Vec<ArrayView2<'a, f64>>> {
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
    Ok(views)
}

/// `[R, P] = krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4)`: priced as a Coons patch of sampled
/// curves ([`coons_point_cost`] of [`SampledCurve::eval_cost`]).
pub fn krpa_coons(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(8, 8, "[R, P] = krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4)")?;
    call.nargout_max(2)?;
    let views = coons_data(call)?;
    let n = views[0].ncols();
    call.check_grid("c1 (samples N)", n, n)?;
    let t = cagd::linspace(0.0, 1.0, n);
    let curves = views[..4]
        .iter()
        .map(|v| SampledCurve::new(t.clone(), DMatrix::from_fn(3, n, |i, j| v[[i, j]])))
        .collect::<cagd::Result<Vec<_>>>()?;
    let per_point = coons_point_cost(curves.iter().map(|c| c.eval_cost(0, 0)), 3, 0, 0);
    call.check_cost("c1 (samples N)", per_point.times((n * n) as u128))?;
    let corner = |v: &ArrayView2<'_, f64>| DVector::from_fn(3, |i, _| v[[i, 0]]);
    let [c1, c2, d1, d2]: [SampledCurve<f64>; 4] = curves.try_into().expect("four boundary curves");
    let patch = CoonsPatch::with_corners(
        c1,
        c2,
        d1,
        d2,
        [
            corner(&views[4]),
            corner(&views[5]),
            corner(&views[6]),
            corner(&views[7]),
        ],
        Tolerance::default(),
    )?;
    let grid = grid_in_bands(call, (&t, &t), (per_point, "R"), |us, vs, out| {
        Ok(patch.eval_grid_into(us, vs, out)?)
    })?;
    emit_r_p(call, sink, n, &grid)
}

/// `[R, P] = krpaGordon (g_u, g_v, g_uv, x_u, x_v, N)`: the network unpacked and checked by
/// the twin ([`compat::krpa_gordon_surface`]), priced as a Gordon surface of sampled curves
/// ([`gordon_setup_cost`], [`gordon_point_cost`]), evaluated band by band.
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
    let (surface, t) = twin(
        compat::krpa_gordon_surface(g_u, g_v, g_uv, x_u, x_v, n),
        "krpa_gordon",
    )?;
    let cost = |c: &SampledCurve<f64>| c.eval_cost(0, 0);
    let (at_u, at_v) = (surface.curves_at_u(), surface.curves_at_v());
    let setup = gordon_setup_cost(at_u.iter().map(cost), at_v.iter().map(cost), (0, 0));
    let per_point = gordon_point_cost(
        at_u.iter().chain(at_v).map(cost),
        (x_u.len(), x_v.len()),
        3,
        (0, 0),
        (0, 0),
    );
    call.check_cost("N", setup.and(per_point.times((n * n) as u128)))?;
    let grid = grid_in_bands(call, (&t, &t), (per_point, "R"), |us, vs, out| {
        out.copy_from_slice(surface.eval_grid(us, vs).as_slice());
        Ok(())
    })?;
    emit_r_p(call, sink, n, &grid)
}

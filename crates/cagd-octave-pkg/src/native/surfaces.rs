//! Coons and Gordon patches of Bézier curves, with their parts.

use cagd::bezier::BezierCurve;
use cagd::gordon::GordonSurface;

use cagd_ops::curves::CurveArg;
use cagd_ops::ops::surface::SurfaceParams;
use cagd_ops::ops::Coons;
use cagd_ops::{Params, Role};

use super::{bezier_curve, cost, emit_item, native};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::number::{emit_grid, params, Number};
use crate::ops::{execute, Names};
use crate::value::{Sink, Value};

/// Writes the grid `u × v` of `x` (output 0) and, when asked, of its three parts (outputs 1
/// to 3), each `d × nu × nv`: `parts(u, v)` gives `[x, part1, part2, part3]` at one point.
fn emit_with_parts<T: Number>(
    call: &Call<'_, '_>,
    sink: &mut dyn Sink,
    (u, v, d): (&[T], &[T], usize),
    grid: impl FnOnce(&mut [T]) -> cagd::Result<()>,
    parts: impl Fn(T, T) -> [nalgebra::DVector<T>; 4],
) -> Result<()> {
    let (nu, nv) = (u.len(), v.len());
    if call.nargout == 1 {
        let mut x = vec![T::zero(); nu * nv * d];
        grid(&mut x)?;
        return emit_grid(sink, 0, (nu, nv, d), &x);
    }
    // The point and its parts from one evaluation, so that x = part1 + part2 − part3 holds
    // in the numbers returned.
    let mut out: Vec<Vec<T>> = (0..4).map(|_| Vec::with_capacity(nu * nv * d)).collect();
    for a in u {
        for b in v {
            for (o, p) in out.iter_mut().zip(parts(a.clone(), b.clone())) {
                o.extend(p.iter().cloned());
            }
        }
    }
    for (k, o) in out.iter().enumerate().take(call.nargout) {
        emit_grid(sink, k, (nu, nv, d), o)?;
    }
    Ok(())
}

native!(
    /// `[X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, u, v)`: the bilinearly blended Coons
    /// patch of four Bézier boundary curves on the grid `u × v`, with its parts.
    coons => coons_t
);

fn coons_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        6,
        6,
        "[X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, u, v [, \"exact\"])",
    )?;
    call.nargout_max(4)?;
    let mut boundary = Vec::with_capacity(4);
    for (i, name) in ["c1", "c2", "d1", "d2"].into_iter().enumerate() {
        boundary.push(CurveArg::curve(bezier_curve::<T>(call, call.arg(i), name)?));
    }
    let op =
        Coons {
            at: SurfaceParams {
                u: Params::Given(params::<T>(call, 4, "u")?),
                v: Params::Given(params::<T>(call, 5, "v")?),
                list: false,
            },
            steps: call.nargout > 1,
            ..Coons::new(boundary.try_into().map_err(|_| {
                PkgError::new(Kind::Internal, "cagd_coons: not four boundary curves")
            })?)
        };
    let report = execute(call, COONS_NAMES, &op)?;
    for (k, name) in ["result", "rc", "rd", "rcd"]
        .into_iter()
        .enumerate()
        .take(call.nargout.max(1))
    {
        emit_item(sink, k, &report, name)?;
    }
    Ok(())
}

/// How `cagd_coons` names its arguments.
const COONS_NAMES: Names = &[
    (Role::C1, "c1"),
    (Role::C2, "c2"),
    (Role::D1, "d1"),
    (Role::D2, "d2"),
    (Role::Boundary, "c1/c2/d1/d2"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
    (Role::Result, "X"),
];

/// The Bézier curves held by the cell argument `i` (`what` names it).
fn curve_cell<T: Number>(
    call: &Call<'_, '_>,
    i: usize,
    what: &'static str,
) -> Result<Vec<BezierCurve<T>>> {
    let form = "a cell array of control point matrices (d × (n+1), one per node)";
    match call.arg(i) {
        Value::Cell { items, .. } => items
            .iter()
            .map(|item| bezier_curve::<T>(call, item, what))
            .collect(),
        other => Err(PkgError::arg(
            Kind::Class,
            what,
            format!("{} is not accepted", other.class()),
            form,
        )),
    }
}

native!(
    /// `[X, g1, g2, g12] = cagd_gordon (cu, cv, un, vn, u, v)`: the Gordon surface of a
    /// network of Bézier curves on the grid `u × v`, with its parts.
    gordon => gordon_t
);

fn gordon_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        6,
        6,
        "[X, g1, g2, g12] = cagd_gordon (cu, cv, un, vn, u, v [, \"exact\"])",
    )?;
    call.nargout_max(4)?;
    let at_u = curve_cell::<T>(call, 0, "cu")?;
    let at_v = curve_cell::<T>(call, 1, "cv")?;
    let un = params::<T>(call, 2, "un")?;
    let vn = params::<T>(call, 3, "vn")?;
    call.check_degree("un (nodes - 1)", un.len().saturating_sub(1))?;
    call.check_degree("vn (nodes - 1)", vn.len().saturating_sub(1))?;
    let u = params::<T>(call, 4, "u")?;
    let v = params::<T>(call, 5, "v")?;
    call.check_grid("u, v", u.len(), v.len())?;
    let d = at_u.first().map_or(0, BezierCurve::dim);
    let degree = at_u
        .iter()
        .chain(&at_v)
        .map(|c| c.degree())
        .max()
        .unwrap_or(0);
    call.check_work(
        "u, v",
        u.len() * v.len(),
        cost::<T>(
            (un.len() + vn.len() + 2) * d * (degree + 2),
            degree + un.len() + vn.len(),
        ),
    )?;
    let surface = GordonSurface::new(un, vn, at_u, at_v)?;
    emit_with_parts(
        call,
        sink,
        (&u, &v, d),
        |out| surface.eval_grid_into(&u, &v, out),
        |a, b| {
            let p = surface.eval_parts(a, b);
            [p.g, p.g1, p.g2, p.g12]
        },
    )
}

//! Coons and Gordon patches and ruled surfaces of Bézier or NURBS curves (octave-nurbs
//! structures), with their parts: the operation layer's requests ([`Coons`], [`Gordon`],
//! [`Ruled`]), as the command line runs them.

use cagd_ops::curves::CurveArg;
use cagd_ops::ops::surface::SurfaceParams;
use cagd_ops::ops::{Coons, Gordon, Ruled};
use cagd_ops::{Params, Role};

use super::curve_value::{curve_value, CURVE_FORM};
use super::{emit_item, native};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::number::{params, Number};
use crate::ops::{execute, Names};
use crate::value::{Sink, Value};

native!(
    /// `[X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, u, v)`: the bilinearly blended Coons
    /// patch of four boundary curves (Bézier control points or NURBS structures) on the grid
    /// `u × v`, with its parts.
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
        boundary.push(curve_value::<T>(call, call.arg(i), name)?);
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

native!(
    /// `[X, C1, C2] = cagd_ruled (c1, c2, u, v)`: the ruled surface `x(u, v) = (1 − v) c1(u) +
    /// v c2(u)` between two curves (Bézier control points or NURBS structures) on the grid
    /// `u × v`, with the two curves at `u`.
    ruled => ruled_t
);

fn ruled_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        4,
        4,
        "[X, C1, C2] = cagd_ruled (c1, c2, u, v [, \"exact\"])",
    )?;
    call.nargout_max(3)?;
    let mut op = Ruled::new(
        curve_value::<T>(call, call.arg(0), "c1")?,
        curve_value::<T>(call, call.arg(1), "c2")?,
    );
    op.at = SurfaceParams {
        u: Params::Given(params::<T>(call, 2, "u")?),
        v: Params::Given(params::<T>(call, 3, "v")?),
        list: false,
    };
    op.steps = call.nargout > 1;
    let report = execute(call, RULED_NAMES, &op)?;
    for (k, name) in ["result", "first", "second"]
        .into_iter()
        .enumerate()
        .take(call.nargout.max(1))
    {
        emit_item(sink, k, &report, name)?;
    }
    Ok(())
}

/// How `cagd_ruled` names its arguments.
const RULED_NAMES: Names = &[
    (Role::First, "c1"),
    (Role::Second, "c2"),
    (Role::Boundary, "c1, c2"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
    (Role::Result, "X"),
];

/// The curves held by the cell argument `i` (`what` names it).
fn curve_cell<T: Number>(
    call: &Call<'_, '_>,
    i: usize,
    what: &'static str,
) -> Result<Vec<CurveArg<T>>> {
    match call.arg(i) {
        Value::Cell { items, .. } => items
            .iter()
            .map(|item| curve_value::<T>(call, item, what))
            .collect(),
        other => Err(PkgError::arg(
            Kind::Class,
            what,
            format!("{} is not accepted", other.class()),
            &format!("a cell array of curves, one per node: {CURVE_FORM}"),
        )),
    }
}

native!(
    /// `[X, g1, g2, g12] = cagd_gordon (cu, cv, un, vn, u, v)`: the Gordon surface of a
    /// network of curves (Bézier control points or NURBS structures) on the grid `u × v`, with
    /// its parts.
    gordon => gordon_t
);

fn gordon_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        6,
        6,
        "[X, g1, g2, g12] = cagd_gordon (cu, cv, un, vn, u, v [, \"exact\"])",
    )?;
    call.nargout_max(4)?;
    let mut op = Gordon::new(
        curve_cell::<T>(call, 0, "cu")?,
        curve_cell::<T>(call, 1, "cv")?,
    );
    op.u_nodes = Some(params::<T>(call, 2, "un")?);
    op.v_nodes = Some(params::<T>(call, 3, "vn")?);
    op.at = SurfaceParams {
        u: Params::Given(params::<T>(call, 4, "u")?),
        v: Params::Given(params::<T>(call, 5, "v")?),
        list: false,
    };
    op.steps = call.nargout > 1;
    let report = execute(call, GORDON_NAMES, &op)?;
    for (k, name) in ["result", "g1", "g2", "g12"]
        .into_iter()
        .enumerate()
        .take(call.nargout.max(1))
    {
        emit_item(sink, k, &report, name)?;
    }
    Ok(())
}

/// How `cagd_gordon` names its arguments.
const GORDON_NAMES: Names = &[
    (Role::UCurves, "cu"),
    (Role::VCurves, "cv"),
    (Role::UNodes, "un"),
    (Role::VNodes, "vn"),
    (Role::Network, "cu/cv"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
    (Role::Result, "X"),
];

//! Bézier curves and patches: values, derivatives, subdivision, degree elevation.

use cagd::grid::PointGrid;

use cagd_ops::ops::surface::SurfaceParams;
use cagd_ops::ops::{BezierPatchPoints, DeCasteljau, Derivative, Elevate, Subdivide};
use cagd_ops::{Params, Role};

use super::{emit_item, emit_result, native, CONTROL_FORM};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::number::{matrix, params, scalar, Number};
use crate::ops::{execute, Names};
use crate::value::Sink;

native!(
    /// `X = cagd_bezier (P, t)`: the curve with control points `P` (columns) at `t`.
    bezier => bezier_t
);

fn bezier_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "X = cagd_bezier (P, t [, \"exact\"])")?;
    call.nargout_max(1)?;
    let op = DeCasteljau {
        t: Params::Given(params::<T>(call, 1, "t")?),
        ..DeCasteljau::new(matrix::<T>(call, 0, "P", CONTROL_FORM)?)
    };
    let report = execute(call, NAMES, &op)?;
    emit_result(sink, 0, &report)
}

/// How the Bézier functions name their arguments.
const NAMES: Names = &[(Role::Control, "P"), (Role::T, "t"), (Role::Result, "X")];

native!(
    /// `[X, Q] = cagd_bezier_derivative (P, t, r)`: the `r`-th derivative (default 1) at `t`
    /// and its control points.
    bezier_derivative => bezier_derivative_t
);

fn bezier_derivative_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        2,
        3,
        "[X, Q] = cagd_bezier_derivative (P, t [, r] [, \"exact\"])",
    )?;
    call.nargout_max(2)?;
    let op = Derivative {
        t: Some(Params::Given(params::<T>(call, 1, "t")?)),
        ..Derivative::new(
            matrix::<T>(call, 0, "P", CONTROL_FORM)?,
            if call.has(2) { call.count(2, "r")? } else { 1 },
        )
    };
    let report = execute(call, DERIVATIVE_NAMES, &op)?;
    emit_result(sink, 0, &report)?;
    if call.nargout > 1 {
        emit_item(sink, 1, &report, "control")?;
    }
    Ok(())
}

/// How `cagd_bezier_derivative` names its arguments.
const DERIVATIVE_NAMES: Names = &[
    (Role::Control, "P"),
    (Role::T, "t"),
    (Role::DerivativeOrder, "r"),
    (Role::Result, "X"),
];

native!(
    /// `[L, R] = cagd_bezier_subdivide (P, t)`: the control points of the two pieces of the
    /// curve split at `t` (0 < t < 1).
    bezier_subdivide => bezier_subdivide_t
);

fn bezier_subdivide_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "[L, R] = cagd_bezier_subdivide (P, t [, \"exact\"])")?;
    call.nargout_max(2)?;
    let op = Subdivide {
        t: Some(scalar::<T>(call, 1, "t")?),
        ..Subdivide::new(matrix::<T>(call, 0, "P", CONTROL_FORM)?)
    };
    let report = execute(call, SUBDIVIDE_NAMES, &op)?;
    emit_item(sink, 0, &report, "left")?;
    if call.nargout > 1 {
        emit_item(sink, 1, &report, "right")?;
    }
    Ok(())
}

/// How `cagd_bezier_subdivide` names its arguments.
const SUBDIVIDE_NAMES: Names = &[(Role::Control, "P"), (Role::T, "t"), (Role::Result, "L")];

native!(
    /// `Q = cagd_bezier_elevate (P, r)`: the same curve with its degree raised by `r`
    /// (default 1).
    bezier_elevate => bezier_elevate_t
);

fn bezier_elevate_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(1, 2, "Q = cagd_bezier_elevate (P [, r] [, \"exact\"])")?;
    call.nargout_max(1)?;
    let op = Elevate {
        by: if call.has(1) { call.count(1, "r")? } else { 1 },
        ..Elevate::new(matrix::<T>(call, 0, "P", CONTROL_FORM)?)
    };
    let report = execute(call, ELEVATE_NAMES, &op)?;
    emit_item(sink, 0, &report, "control")
}

/// How `cagd_bezier_elevate` names its arguments.
const ELEVATE_NAMES: Names = &[(Role::Control, "P"), (Role::By, "r"), (Role::Result, "Q")];

/// The form of a patch net.
const PATCH_FORM: &str = "a d × (m+1) × (n+1) array, B(:, i+1, j+1) = b_ij";

native!(
    /// `X = cagd_bezier_patch (B, u, v)`: the patch with net `B` (`d × (m+1) × (n+1)`) on the
    /// grid `u × v`, as `d × numel(u) × numel(v)`.
    bezier_patch => bezier_patch_t
);

fn bezier_patch_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(3, 3, "X = cagd_bezier_patch (B, u, v [, \"exact\"])")?;
    call.nargout_max(1)?;
    let b = call.nonempty(0, "B", PATCH_FORM)?;
    if b.dims.iter().skip(3).any(|&k| k != 1) {
        return Err(PkgError::arg(
            Kind::Shape,
            "B",
            format!("an array of size {}", b.size_str()),
            PATCH_FORM,
        ));
    }
    // As every reader: NaN and ±Inf have no exact value.
    crate::args::finite("B", b.data)?;
    // B(c, i+1, j+1) = b_ij(c) is the net (m+1, n+1, d) of the operation.
    let (d, m1, n1) = (b.dims[0], b.dims[1], b.dims.get(2).copied().unwrap_or(1));
    let net = PointGrid::from_shape_fn((m1, n1, d), |(i, j, c)| {
        T::from_input(b.data[c + d * (i + m1 * j)])
    });
    let op = BezierPatchPoints {
        at: SurfaceParams {
            u: Params::Given(params::<T>(call, 1, "u")?),
            v: Params::Given(params::<T>(call, 2, "v")?),
            list: false,
        },
        ..BezierPatchPoints::new(net)
    };
    let report = execute(call, PATCH_NAMES, &op)?;
    emit_result(sink, 0, &report)
}

/// How `cagd_bezier_patch` names its arguments.
const PATCH_NAMES: Names = &[
    (Role::Net, "B"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
    (Role::Result, "X"),
];

//! B-spline and NURBS curves, interpolating cubic splines, Hermite cubics, the conversions of
//! cubic forms, Bernstein values.

use cagd::conversion::GeometryForm;
use cagd_ops::knots::Degree;
use cagd_ops::ops::spline::{Ends, Knots, Spline};
use cagd_ops::ops::{BSpline, Bernstein, Convert, Hermite, Nurbs};
use cagd_ops::{Params, Role};
use nalgebra::DMatrix;

use super::{emit_item, emit_result, native, CONTROL_FORM};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::number::{emit_matrix, matrix, params, Number};
use crate::ops::{execute, Names};
use crate::value::{Sink, Value};

/// The knots of argument `i`, or none for `[]` (the clamped uniform knots on [0, 1]).
fn knots<T: Number>(call: &Call<'_, '_>, i: usize) -> Result<Option<Vec<T>>> {
    match call.arg(i) {
        Value::Real(r) if r.is_empty() => Ok(None),
        _ => params::<T>(call, i, "U").map(Some),
    }
}

native!(
    /// `X = cagd_bspline (p, P, U, t)`: the B-spline curve of degree `p`, control points `P`
    /// and knots `U` (`[]`: clamped uniform on [0, 1]) at `t`.
    bspline => bspline_t
);

fn bspline_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "X = cagd_bspline (p, P, U, t [, \"exact\"])")?;
    call.nargout_max(1)?;
    let op = BSpline {
        degree: Degree::Degree(call.count(0, "p")?),
        knots: knots::<T>(call, 2)?,
        t: Params::Given(params::<T>(call, 3, "t")?),
        ..BSpline::new(matrix::<T>(call, 1, "P", CONTROL_FORM)?)
    };
    let report = execute(call, SPLINE_NAMES, &op)?;
    emit_result(sink, 0, &report)
}

/// How `cagd_bspline` and `cagd_nurbs` name their arguments.
const SPLINE_NAMES: Names = &[
    (Role::Degree, "p"),
    (Role::Control, "P"),
    (Role::Weights, "w"),
    (Role::Knots, "U"),
    (Role::T, "t"),
    (Role::Result, "X"),
];

native!(
    /// `X = cagd_nurbs (p, P, w, U, t)`: the NURBS curve of degree `p`, control points `P`,
    /// weights `w` and knots `U` (`[]`: clamped uniform on [0, 1]) at `t`.
    nurbs_curve => nurbs_t
);

fn nurbs_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(5, 5, "X = cagd_nurbs (p, P, w, U, t [, \"exact\"])")?;
    call.nargout_max(1)?;
    let control = matrix::<T>(call, 1, "P", CONTROL_FORM)?;
    let op = Nurbs {
        degree: Degree::Degree(call.count(0, "p")?),
        knots: knots::<T>(call, 3)?,
        t: Params::Given(params::<T>(call, 4, "t")?),
        ..Nurbs::new(control, params::<T>(call, 2, "w")?)
    };
    let report = execute(call, SPLINE_NAMES, &op)?;
    emit_result(sink, 0, &report)
}

/// The end conditions a spline takes, in words.
const ENDS_FORM: &str = "\"natural\", \"closed\", or the end tangents as a d × 2 matrix";

native!(
    /// `[X, D] = cagd_spline (Q, t, ends)`: the interpolating cubic spline through the
    /// columns of `Q` at the parameters 0, 1, …, at `t`, and its tangents at the points.
    spline => spline_t
);

fn spline_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 3, "[X, D] = cagd_spline (Q, t [, ends] [, \"exact\"])")?;
    call.nargout_max(2)?;
    let q = matrix::<T>(
        call,
        0,
        "Q",
        "the points to interpolate, d × m (one per column)",
    )?;
    let (ends, tangents) = ends::<T>(call, q.nrows())?;
    let (start_tangent, end_tangent) = match tangents {
        Some(m) => (
            Some(m.columns(0, 1).into_owned()),
            Some(m.columns(1, 1).into_owned()),
        ),
        None => (None, None),
    };
    let op = Spline {
        ends: Some(ends),
        start_tangent,
        end_tangent,
        knots: Knots::Chosen(cagd::spline::Parametrization::Uniform),
        t: Params::Given(params::<T>(call, 1, "t")?),
        ..Spline::new(q)
    };
    let report = execute(call, SPLINE_FN_NAMES, &op)?;
    emit_result(sink, 0, &report)?;
    if call.nargout > 1 {
        emit_item(sink, 1, &report, "tangents")?;
    }
    Ok(())
}

/// How `cagd_spline` names its arguments.
const SPLINE_FN_NAMES: Names = &[
    (Role::Points, "Q"),
    (Role::T, "t"),
    (Role::Ends, "ends"),
    (Role::T0, "ends"),
    (Role::T1, "ends"),
    (Role::Result, "X"),
];

/// The end condition of argument 2 (natural when absent), with the end tangents of a clamped
/// spline as a `d × 2` matrix: the package's layout of the condition.
fn ends<T: Number>(call: &Call<'_, '_>, d: usize) -> Result<(Ends, Option<DMatrix<T>>)> {
    if !call.has(2) {
        return Ok((Ends::Natural, None));
    }
    match call.arg(2).text().as_deref() {
        Some("natural") => Ok((Ends::Natural, None)),
        Some("closed") => Ok((Ends::Closed, None)),
        Some(other) => Err(PkgError::arg(
            Kind::Value,
            "ends",
            format!("'{other}'"),
            ENDS_FORM,
        )),
        None => {
            let tangents = matrix::<T>(call, 2, "ends", ENDS_FORM)?;
            if tangents.shape() != (d, 2) {
                return Err(PkgError::arg(
                    Kind::Shape,
                    "ends",
                    format!("{}×{}", tangents.nrows(), tangents.ncols()),
                    &format!("the end tangents as a {d} × 2 matrix"),
                ));
            }
            Ok((Ends::Clamped, Some(tangents)))
        }
    }
}

native!(
    /// `[X, B] = cagd_hermite (p0, p1, t0, t1, u)`: the Hermite (Ferguson) cubic with
    /// `x(0) = p0`, `x(1) = p1`, `x'(0) = t0`, `x'(1) = t1` at `u`, and its Bézier control
    /// points.
    hermite => hermite_t
);

fn hermite_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        5,
        5,
        "[X, B] = cagd_hermite (p0, p1, t0, t1, u [, \"exact\"])",
    )?;
    call.nargout_max(2)?;
    let form = cagd_ops::ops::hermite::VECTOR_FORM;
    let op = Hermite {
        data: [
            matrix::<T>(call, 0, "p0", form)?,
            matrix::<T>(call, 1, "p1", form)?,
            matrix::<T>(call, 2, "t0", form)?,
            matrix::<T>(call, 3, "t1", form)?,
        ],
        t: Params::Given(params::<T>(call, 4, "u")?),
        steps: call.nargout > 1,
        drawing: false,
    };
    let report = execute(call, HERMITE_NAMES, &op)?;
    emit_result(sink, 0, &report)?;
    if call.nargout > 1 {
        emit_item(sink, 1, &report, "bezier_control")?;
    }
    Ok(())
}

/// How `cagd_hermite` names its arguments.
const HERMITE_NAMES: Names = &[
    (Role::P0, "p0"),
    (Role::P1, "p1"),
    (Role::T0, "t0"),
    (Role::T1, "t1"),
    (Role::Hermite, "p0, p1, t0, t1"),
    (Role::T, "u"),
    (Role::Result, "X"),
];

/// A cubic form by its name.
fn form(call: &Call<'_, '_>, i: usize, what: &str) -> Result<GeometryForm> {
    let words = "\"hermite\", \"bezier\" or \"bspline\"";
    let text = call.text(i, what, words)?;
    match text.to_ascii_lowercase().as_str() {
        "hermite" | "ferguson" => Ok(GeometryForm::Hermite),
        "bezier" => Ok(GeometryForm::Bezier),
        "bspline" => Ok(GeometryForm::BSpline),
        other => Err(PkgError::arg(
            Kind::Value,
            what,
            format!("'{other}'"),
            words,
        )),
    }
}

native!(
    /// `G = cagd_convert (G, from, to)`: the geometry (`d × 4`) of a cubic in one form
    /// ("hermite", "bezier", "bspline") as the geometry of the same cubic in another.
    convert => convert_t
);

fn convert_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(3, 3, "G = cagd_convert (G, from, to [, \"exact\"])")?;
    call.nargout_max(1)?;
    let op = Convert::new(
        matrix::<T>(call, 0, "G", "a d × 4 geometry matrix")?,
        form(call, 1, "from")?,
        form(call, 2, "to")?,
    );
    let report = execute(call, CONVERT_NAMES, &op)?;
    emit_result(sink, 0, &report)
}

/// How `cagd_convert` names its arguments.
const CONVERT_NAMES: Names = &[
    (Role::Control, "G"),
    (Role::From, "from"),
    (Role::To, "to"),
    (Role::Result, "G"),
];

native!(
    /// `B = cagd_bernstein (n, t)`: the Bernstein polynomials of degree `n` at `t`,
    /// `B(i+1, k) = B_i^n(t(k))`.
    bernstein => bernstein_t
);

fn bernstein_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(2, 2, "B = cagd_bernstein (n, t [, \"exact\"])")?;
    call.nargout_max(1)?;
    let op = Bernstein {
        t: Params::Given(params::<T>(call, 1, "t")?),
        ..Bernstein::new(call.count(0, "n")?)
    };
    let report = execute(call, BERNSTEIN_NAMES, &op)?;
    // The operation's rows are the parameters; here B(i+1, k) = B_i^n(t(k)).
    match report.matrix("result") {
        Some(b) => emit_matrix(sink, 0, &b.transpose()),
        None => emit_result(sink, 0, &report),
    }
}

/// How `cagd_bernstein` names its arguments.
const BERNSTEIN_NAMES: Names = &[(Role::Degree, "n"), (Role::T, "t"), (Role::Result, "B")];

//! B-spline and NURBS curves, interpolating cubic splines, Hermite cubics, the conversions of
//! cubic forms, Bernstein values.

use cagd::bspline::{BSplineCurve, KnotVector};
use cagd::conversion::GeometryForm;
use cagd::hermite::HermiteCubic;
use cagd::nurbs::NurbsCurve;
use cagd::spline::{CubicSpline, EndCondition};
use nalgebra::DVector;

use cagd_ops::ops::{Bernstein, Convert};
use cagd_ops::{Params, Role};

use super::{cost, emit_result, native, CONTROL_FORM};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::number::{emit_matrix, matrix, params, Number};
use crate::ops::{execute, Names};
use crate::value::{Sink, Value};

/// Every parameter within `[lo, hi]`, else the core's out-of-domain error.
fn check_domain<T: Number>(what: &'static str, t: &[T], lo: &T, hi: &T) -> Result<()> {
    match t.iter().find(|x| *x < lo || *x > hi) {
        None => Ok(()),
        Some(x) => Err(cagd::Error::ParameterOutOfRange {
            what,
            value: x.to_f64(),
            min: lo.to_f64(),
            max: hi.to_f64(),
        }
        .into()),
    }
}

/// Writes `d × numel(t)` points computed by `fill` (row-major `numel(t) × d`, i.e. Octave's
/// column-major `d × numel(t)`).
fn emit_curve_points<T: Number>(
    call: &Call<'_, '_>,
    sink: &mut dyn Sink,
    (d, t): (usize, &[T]),
    per_point: usize,
    mut fill: impl FnMut(&mut [T]) -> cagd::Result<()>,
) -> Result<()> {
    call.check_samples("t", t.len())?;
    call.check_work("t", t.len(), per_point)?;
    T::emit_with(sink, 0, &[d, t.len()], &mut fill)
}

/// The knots of argument `i`, or for `[]` the clamped uniform knots on `[0, 1]`.
fn knots_or_clamped<T: Number>(
    call: &Call<'_, '_>,
    i: usize,
    p: usize,
    n: usize,
) -> Result<Vec<T>> {
    let given = match call.arg(i) {
        Value::Real(r) => !r.is_empty(),
        _ => true,
    };
    if given {
        return params::<T>(call, i, "U");
    }
    Ok(KnotVector::<T>::clamped_uniform(p, n)?.as_slice().to_vec())
}

native!(
    /// `X = cagd_bspline (p, P, U, t)`: the B-spline curve of degree `p`, control points `P`
    /// and knots `U` (`[]`: clamped uniform on [0, 1]) at `t`.
    bspline => bspline_t
);

fn bspline_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(4, 4, "X = cagd_bspline (p, P, U, t [, \"exact\"])")?;
    call.nargout_max(1)?;
    let p = call.count(0, "p")?;
    call.check_degree("p", p)?;
    let control = matrix::<T>(call, 1, "P", CONTROL_FORM)?;
    let (d, n) = (control.nrows(), control.ncols());
    let knots = knots_or_clamped::<T>(call, 2, p, n)?;
    let t = params::<T>(call, 3, "t")?;
    let curve = BSplineCurve::new(p, knots, control)?;
    let (lo, hi) = curve.domain();
    check_domain("t", &t, &lo, &hi)?;
    emit_curve_points(
        call,
        sink,
        (d, &t),
        cost::<T>((p + 1) * (p + 1 + d), p + 1),
        |out| curve.try_eval_many_into(&t, out),
    )
}

native!(
    /// `X = cagd_nurbs (p, P, w, U, t)`: the NURBS curve of degree `p`, control points `P`,
    /// weights `w` and knots `U` (`[]`: clamped uniform on [0, 1]) at `t`.
    nurbs_curve => nurbs_t
);

fn nurbs_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(5, 5, "X = cagd_nurbs (p, P, w, U, t [, \"exact\"])")?;
    call.nargout_max(1)?;
    let p = call.count(0, "p")?;
    call.check_degree("p", p)?;
    let control = matrix::<T>(call, 1, "P", CONTROL_FORM)?;
    let (d, n) = (control.nrows(), control.ncols());
    let w = params::<T>(call, 2, "w")?;
    let knots = knots_or_clamped::<T>(call, 3, p, n)?;
    let t = params::<T>(call, 4, "t")?;
    let curve = NurbsCurve::new(p, knots, control, w)?;
    let (lo, hi) = curve.domain();
    check_domain("t", &t, &lo, &hi)?;
    emit_curve_points(
        call,
        sink,
        (d, &t),
        cost::<T>((p + 1) * (p + 2 + d), p + 1),
        |out| curve.try_eval_many_into(&t, out),
    )
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
    let d = q.nrows();
    let end = if !call.has(2) {
        EndCondition::Natural
    } else {
        match call.arg(2).text().as_deref() {
            Some("natural") => EndCondition::Natural,
            Some("closed") => EndCondition::Closed,
            Some(other) => {
                return Err(PkgError::arg(
                    Kind::Value,
                    "ends",
                    format!("'{other}'"),
                    ENDS_FORM,
                ));
            }
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
                EndCondition::Clamped {
                    start: tangents.column(0).into_owned(),
                    end: tangents.column(1).into_owned(),
                }
            }
        }
    };
    call.check_degree("Q (points)", q.ncols())?;
    let t = params::<T>(call, 1, "t")?;
    let s = CubicSpline::interpolate(q, end)?;
    let params_ = s.params();
    check_domain("t", &t, &params_[0], &params_[params_.len() - 1])?;
    emit_curve_points(call, sink, (d, &t), cost::<T>(16 * d, 2), |out| {
        s.eval_many_into(&t, out)
    })?;
    if call.nargout > 1 {
        emit_matrix(sink, 1, s.tangents())?;
    }
    Ok(())
}

/// Argument `i` as a column of dimension `d` (any row or column of `d` values).
fn vector<T: Number>(call: &Call<'_, '_>, i: usize, what: &'static str) -> Result<DVector<T>> {
    let m = matrix::<T>(call, i, what, "a point or vector (d values)")?;
    if m.nrows() != 1 && m.ncols() != 1 {
        return Err(PkgError::arg(
            Kind::Shape,
            what,
            format!("a {}×{} matrix", m.nrows(), m.ncols()),
            "a point or vector (d values)",
        ));
    }
    Ok(DVector::from_iterator(m.len(), m.iter().cloned()))
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
    let [p0, p1, t0, t1] = [
        vector::<T>(call, 0, "p0")?,
        vector::<T>(call, 1, "p1")?,
        vector::<T>(call, 2, "t0")?,
        vector::<T>(call, 3, "t1")?,
    ];
    let d = p0.len();
    let h = HermiteCubic::new(p0, p1, t0, t1)?;
    let u = params::<T>(call, 4, "u")?;
    emit_curve_points(call, sink, (d, &u), cost::<T>(8 * d, 2), |out| {
        for (x, t) in out.chunks_exact_mut(d).zip(&u) {
            for (o, v) in x.iter_mut().zip(h.eval(t.clone()).iter()) {
                *o = v.clone();
            }
        }
        Ok(())
    })?;
    if call.nargout > 1 {
        emit_matrix(sink, 1, h.to_bezier()?.control())?;
    }
    Ok(())
}

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

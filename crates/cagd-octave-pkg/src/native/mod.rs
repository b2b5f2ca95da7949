//! The native functions `cagd_*`: the rest of the library in Octave's own terms.
//!
//! | Octave | core |
//! |---|---|
//! | `X = cagd_bezier (P, t)` | [`BezierCurve::eval_many_into`](cagd::BezierCurve::eval_many_into) |
//! | `[X, Q] = cagd_bezier_derivative (P, t, r)` | [`BezierCurve::derivative`](cagd::BezierCurve::derivative) |
//! | `[L, R] = cagd_bezier_subdivide (P, t)` | [`BezierCurve::subdivide`](cagd::BezierCurve::subdivide) |
//! | `Q = cagd_bezier_elevate (P, r)` | [`BezierCurve::elevate`](cagd::BezierCurve::elevate) |
//! | `X = cagd_bezier_patch (B, u, v)` | [`BezierPatch::eval_grid_into`](cagd::BezierPatch::eval_grid_into) |
//! | `[X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, u, v)` | [`cagd_ops::ops::Coons`] of Bézier or NURBS curves |
//! | `[X, g1, g2, g12] = cagd_gordon (cu, cv, un, vn, u, v)` | [`cagd_ops::ops::Gordon`] of Bézier or NURBS curves |
//! | `[X, C1, C2] = cagd_ruled (c1, c2, u, v)` | [`cagd_ops::ops::Ruled`] of Bézier or NURBS curves |
//! | `X = cagd_bspline (p, P, U, t)` | [`BSplineCurve`](cagd::BSplineCurve) |
//! | `X = cagd_nurbs (p, P, w, U, t)` | [`NurbsCurve`](cagd::NurbsCurve) |
//! | `[X, D] = cagd_spline (Q, t, ends)` | [`CubicSpline`](cagd::CubicSpline) |
//! | `[X, B] = cagd_hermite (p0, p1, t0, t1, u)` | [`HermiteCubic`](cagd::HermiteCubic) |
//! | `G = cagd_convert (G, from, to)` | [`cagd::conversion::convert`] |
//! | `B = cagd_bernstein (n, t)` | [`cagd::bernstein::basis_matrix`] |
//!
//! Each takes the option `"exact"` as its last argument (see [`crate::number`]).

mod bezier;
mod curve_value;
mod splines;
mod surfaces;

pub use bezier::{bezier, bezier_derivative, bezier_elevate, bezier_patch, bezier_subdivide};
pub use splines::{bernstein, bspline, convert, hermite, nurbs_curve, spline};
pub use surfaces::{coons, gordon, ruled};

use cagd::bezier::BezierCurve;

use crate::args::Call;
use crate::error::Result;
use crate::number::{matrix_value, Number};
use crate::value::{Sink, Value};

/// A function of one arithmetic.
type Typed = fn(&Call<'_, '_>, &mut dyn Sink) -> Result<()>;

/// Runs `exact` without the trailing option `"exact"` if it is there, else `fast`.
fn with_exact(call: &Call<'_, '_>, sink: &mut dyn Sink, fast: Typed, exact: Typed) -> Result<()> {
    if call.last_is_option("exact") {
        exact(&call.without_last(), sink)
    } else {
        fast(call, sink)
    }
}

/// Defines the public function `$name` running `$typed::<f64>` or, with `"exact"`,
/// `$typed::<BigRational>`.
macro_rules! native {
    ($(#[$doc:meta])* $name:ident => $typed:ident) => {
        $(#[$doc])*
        pub fn $name(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
            super::with_exact(call, sink, $typed::<f64>, $typed::<num_rational::BigRational>)
        }
    };
}
pub(crate) use native;

/// Output `index`: the report's `result` (a matrix, or a grid as `d × nu × nv`).
///
/// # Errors
/// [`Kind::Memory`](crate::Kind::Memory); a report without a result is an internal error.
fn emit_result<T: Number>(
    sink: &mut dyn Sink,
    index: usize,
    report: &cagd_ops::Report<T>,
) -> Result<()> {
    emit_item(sink, index, report, "result")
}

/// Output `index`: the report's item `name` (a matrix, or a grid as `d × nu × nv`).
///
/// # Errors
/// [`Kind::Memory`](crate::Kind::Memory); a report without that item is an internal error.
fn emit_item<T: Number>(
    sink: &mut dyn Sink,
    index: usize,
    report: &cagd_ops::Report<T>,
    name: &str,
) -> Result<()> {
    match report.get(name) {
        Some(cagd_ops::Value::Matrix(m)) => crate::number::emit_matrix(sink, index, m),
        Some(cagd_ops::Value::Grid(g)) => {
            crate::number::emit_grid(sink, index, g.dim(), g.as_slice())
        }
        _ => Err(crate::PkgError::new(
            crate::Kind::Internal,
            format!("the answer has no numeric item `{name}`"),
        )),
    }
}

/// The form of control points.
const CONTROL_FORM: &str = "a d × (n+1) matrix, one control point per column";

/// A Bézier curve from control points given as a value (columns = points).
fn bezier_curve<T: Number>(
    call: &Call<'_, '_>,
    v: &Value<'_>,
    what: &'static str,
) -> Result<BezierCurve<T>> {
    let p = matrix_value::<T>(v, what, CONTROL_FORM, &call.limits)?;
    call.check_degree(what, p.ncols() - 1)?;
    Ok(BezierCurve::new(p)?)
}

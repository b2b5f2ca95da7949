//! A curve argument of the patch functions (`cagd_coons`, `cagd_gordon`): Bézier control
//! points (`d × (n+1)`, one point per column), or a NURBS curve as octave-nurbs builds it
//! (`nrbmak (coefs, knots)`: the fields `coefs`, `4 × n` homogeneous coefficients
//! `(w·x; w·y; w·z; w)`, `knots`, the knot vector, and `order`, the degree + 1). A NURBS keeps
//! its domain `[U(p+1), U(n+1)]`, which the patch maps onto `[0, 1]`; its coefficients are
//! taken as they are (no division by the weights), exactly with `"exact"`.

use cagd::bspline::BSplineCurve;
use cagd::nurbs::NurbsCurve;
use cagd_ops::curves::CurveArg;
use nalgebra::DMatrix;

use super::bezier_curve;
use crate::args::{nonempty_of, scalar_of, Call};
use crate::error::{Kind, PkgError, Result};
use crate::number::Number;
use crate::value::{Real, Value};

/// The form of a curve argument.
pub const CURVE_FORM: &str =
    "Bézier control points (d × (n+1), one per column) or a NURBS curve structure from nrbmak";

/// The form of a NURBS curve structure.
const NURBS_CURVE_FORM: &str =
    "a NURBS curve from nrbmak (fields coefs, 4 × n homogeneous; knots; order)";

/// The curve of the value `v` (`what` names the argument).
///
/// # Errors
/// [`Kind::Struct`] for a structure that is not a NURBS curve, the errors of the control
/// points ([`bezier_curve`]) and of the core's curves (knots, weights).
pub fn curve_value<T: Number>(
    call: &Call<'_, '_>,
    v: &Value<'_>,
    what: &'static str,
) -> Result<CurveArg<T>> {
    match v {
        Value::Struct { .. } => nurbs_curve::<T>(call, v, what).map(CurveArg::curve),
        _ => bezier_curve::<T>(call, v, what).map(CurveArg::curve),
    }
}

/// `nrbmak`'s structure as the core's NURBS curve: `(degree, homogeneous points, knots)`.
fn nurbs_curve<T: Number>(
    call: &Call<'_, '_>,
    v: &Value<'_>,
    what: &'static str,
) -> Result<NurbsCurve<T>> {
    let (order, knots, coefs) = nurbs_fields(v, what)?;
    let degree = order - 1;
    call.check_degree(what, degree)?;
    let library =
        |e: cagd::Error| PkgError::arg(Kind::of(&e), what, e.to_string(), NURBS_CURVE_FORM);
    cagd::error::check_finite("NURBS coefs", coefs.data.iter()).map_err(library)?;
    cagd::error::check_finite("NURBS knots", knots.data.iter()).map_err(library)?;
    let h = DMatrix::from_column_slice(4, coefs.cols(), coefs.data).map(T::from_input);
    let knots: Vec<T> = knots.data.iter().map(|&x| T::from_input(x)).collect();
    BSplineCurve::new(degree, knots, h)
        .and_then(NurbsCurve::from_homogeneous)
        .map_err(library)
}

/// The fields of `nrbmak`'s structure of a curve: `order` (a positive integer), `knots` (a
/// vector, not a cell) and `coefs` (`4 × n`), checked; `form`, if present, `"B-NURBS"`.
///
/// # Errors
/// [`Kind::Struct`] for a missing field, another form or a surface; [`Kind::Value`] for an
/// order that is not a positive integer; [`Kind::Shape`] for coefficients not `4 × n`.
fn nurbs_fields<'a>(v: &Value<'a>, what: &str) -> Result<(usize, Real<'a>, Real<'a>)> {
    let field = |name: &str| {
        v.field(name).ok_or_else(|| {
            PkgError::arg(
                Kind::Struct,
                what,
                format!("the structure has no field '{name}'"),
                NURBS_CURVE_FORM,
            )
        })
    };
    if let Some(form) = v.field("form").and_then(Value::text) {
        if form != "B-NURBS" {
            return Err(PkgError::arg(
                Kind::Struct,
                what,
                format!("'{form}' is not a recognised NURBS representation"),
                NURBS_CURVE_FORM,
            ));
        }
    }
    let order = scalar_of(field("order")?, "order")?;
    if !(order >= 1.0 && order.fract() == 0.0) {
        return Err(PkgError::arg(
            Kind::Value,
            what,
            format!("order {order} is not a positive integer"),
            NURBS_CURVE_FORM,
        ));
    }
    let knots = match field("knots")? {
        Value::Cell { .. } => {
            return Err(PkgError::arg(
                Kind::Struct,
                what,
                "a surface or volume (a cell of knot vectors)",
                NURBS_CURVE_FORM,
            ))
        }
        k => nonempty_of(k, what, NURBS_CURVE_FORM)?,
    };
    let coefs = nonempty_of(field("coefs")?, what, NURBS_CURVE_FORM)?;
    if coefs.rows() != 4 || !coefs.is_matrix() {
        return Err(PkgError::arg(
            Kind::Shape,
            what,
            format!("coefs of size {}", coefs.size_str()),
            NURBS_CURVE_FORM,
        ));
    }
    Ok((order as usize, knots, coefs))
}

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
use crate::value::Value;

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
    let degree = order as usize - 1;
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

#[cfg(test)]
mod tests {
    use crate::value::{Real, Value, VecSink};
    use cagd::Limits;

    /// The homogeneous coefficients of the quarter circle (weights 1, 1, 2) at height `z`:
    /// points (1, 0, z), (1, 1, z), (0, 1, z).
    fn arc_coefs(z: f64) -> Vec<f64> {
        vec![1.0, 0.0, z, 1.0, 1.0, 1.0, z, 1.0, 0.0, 2.0, 2.0 * z, 2.0]
    }

    const KNOTS: [f64; 6] = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];

    /// `nrbmak (coefs, [0 0 0 1 1 1])` as the package receives it.
    fn nurbs(coefs: &[f64]) -> Value<'_> {
        Value::Struct {
            fields: vec![
                (
                    "form",
                    Value::Char {
                        dims: &[1, 7],
                        bytes: b"B-NURBS",
                    },
                ),
                (
                    "coefs",
                    Value::Real(Real {
                        dims: &[4, 3],
                        data: coefs,
                    }),
                ),
                (
                    "knots",
                    Value::Real(Real {
                        dims: &[1, 6],
                        data: &KNOTS,
                    }),
                ),
                (
                    "order",
                    Value::Real(Real {
                        dims: &[1, 1],
                        data: &[3.0],
                    }),
                ),
            ],
        }
    }

    fn real<'a>(dims: &'a [usize], data: &'a [f64]) -> Value<'a> {
        Value::Real(Real { dims, data })
    }

    #[test]
    fn coons_takes_nurbs_boundaries_exactly() {
        // The cylinder over the quarter circle: x(1/2, 1/4) = (3/5, 4/5, 1/4), as
        // (1/4 + 1/2, 1/2 + 2/4) / (1/4 + 1/2 + 2/4) by hand.
        let (a0, a1) = (arc_coefs(0.0), arc_coefs(1.0));
        let d1 = [1.0, 0.0, 0.0, 1.0, 0.0, 1.0];
        let d2 = [0.0, 1.0, 0.0, 0.0, 1.0, 1.0];
        let exact = Value::Char {
            dims: &[1, 5],
            bytes: b"exact",
        };
        let mut args = vec![
            nurbs(&a0),
            nurbs(&a1),
            real(&[3, 2], &d1),
            real(&[3, 2], &d2),
            real(&[1, 1], &[0.5]),
            real(&[1, 1], &[0.25]),
        ];
        let mut out = VecSink::default();
        crate::call("cagd_coons", &args, 1, &mut Limits::default(), &mut out).unwrap();
        let x = out.get(0).data();
        assert!((x[0] - 0.6).abs() < 1e-15 && (x[1] - 0.8).abs() < 1e-15 && x[2] == 0.25);
        args.push(exact);
        crate::call("cagd_coons", &args, 1, &mut Limits::default(), &mut out).unwrap();
        assert_eq!(out.get(0).items(), ["3/5", "4/5", "1/4"]);
    }

    #[test]
    fn gordon_takes_cells_of_nurbs_and_bezier_curves() {
        // Three lines of the cylinder and its two quarter circles: at u = 1/4 the circle is
        // (9/16 + 6/16, 6/16 + 2/16) / (17/16) = (15/17, 8/17).
        let (a0, a1) = (arc_coefs(0.0), arc_coefs(1.0));
        let lines = [
            [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
            [0.6, 0.8, 0.0, 0.6, 0.8, 1.0],
            [0.0, 1.0, 0.0, 0.0, 1.0, 1.0],
        ];
        let cu = Value::Cell {
            dims: &[1, 3],
            items: lines.iter().map(|l| real(&[3, 2], l)).collect(),
        };
        let cv = Value::Cell {
            dims: &[1, 2],
            items: vec![nurbs(&a0), nurbs(&a1)],
        };
        let args = [
            cu,
            cv,
            real(&[1, 3], &[0.0, 0.5, 1.0]),
            real(&[1, 2], &[0.0, 1.0]),
            real(&[1, 1], &[0.25]),
            real(&[1, 1], &[0.75]),
            Value::Char {
                dims: &[1, 5],
                bytes: b"exact",
            },
        ];
        let mut out = VecSink::default();
        crate::call("cagd_gordon", &args, 2, &mut Limits::default(), &mut out).unwrap();
        assert_eq!(out.get(0).items(), ["15/17", "8/17", "3/4"]);
        // The bad input is named as the usage line names it, worded as the command line does.
        let bad = [0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0];
        let mut args = args.to_vec();
        args[1] = Value::Cell {
            dims: &[1, 2],
            items: vec![nurbs(&bad), nurbs(&a1)],
        };
        let e = crate::call("cagd_gordon", &args, 1, &mut Limits::default(), &mut out).unwrap_err();
        assert!(e.to_string().contains("cv: "), "{e}");
        assert_eq!(e.identifier(), "cagd:weights");
    }
}

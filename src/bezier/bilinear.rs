//! Bilinear interpolation and the bilinear patch (thesis §3.1).
//!
//! Four points `b_{0,0}, b_{0,1}, b_{1,0}, b_{1,1}` span the surface (eq. (3.1), (3.2))
//!
//! ```text
//! x(u, v) = Σ_{i,j ∈ {0,1}} b_{i,j} B_i^1(u) B_j^1(v) = [1−u, u] [b_00 b_01; b_10 b_11] [1−v; v],
//! ```
//!
//! a hyperbolic paraboloid when the points are not coplanar (the corners `(0,0,0)`, `(0,1,0)`,
//! `(1,0,0)`, `(1,1,1)` give `z = xy`, thesis Slika 2). One bilinear interpolation is also the
//! step of the tensor de Casteljau algorithm for patches.

use nalgebra::DVector;

use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The four weights of one bilinear interpolation at `(u, v)`.
///
/// The products and the sum are formed in the order of the fixed Octave `bilinearna` (and of
/// the corner term of `krpaCoons`): `(1−u)(1−v) b_{i,j} + u(1−v) b_{i+1,j} + (1−u)v b_{i,j+1} +
/// uv b_{i+1,j+1}`, each weight a product of two scalars, summed left to right, so that `f64`
/// results agree with Octave to the last bit.
pub(crate) struct BilinearWeights<T> {
    w00: T,
    w10: T,
    w01: T,
    w11: T,
}

impl<T: Scalar> BilinearWeights<T> {
    pub(crate) fn new(u: &T, v: &T) -> Self {
        let su = T::one() - u.clone();
        let sv = T::one() - v.clone();
        BilinearWeights {
            w00: su.clone() * sv.clone(),
            w10: u.clone() * sv,
            w01: su * v.clone(),
            w11: u.clone() * v.clone(),
        }
    }

    /// `w00 b00 + w10 b10 + w01 b01 + w11 b11` (that order; note the argument order).
    pub(crate) fn combine(&self, b00: &T, b10: &T, b01: &T, b11: &T) -> T {
        self.w00.clone() * b00.clone()
            + self.w10.clone() * b10.clone()
            + self.w01.clone() * b01.clone()
            + self.w11.clone() * b11.clone()
    }
}

/// The bilinear interpolant of four points at `(u, v)` (thesis eq. (3.2)):
/// `(1−u)(1−v) b_00 + u(1−v) b_10 + (1−u)v b_01 + uv b_11`, computed in that term order.
///
/// # Errors
/// [`Error::ShapeMismatch`] if the points differ in dimension; [`Error::NonFinite`] for a NaN
/// or infinite coordinate or parameter; [`Error::Overflow`] for a point whose double
/// overflows (parameters far outside `[0, 1]`, corners near ±1.7·10³⁰⁸).
///
/// ```
/// use cagd::bezier::bilinear_interpolate;
/// let p = bilinear_interpolate(
///     &[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0], &[1.0, 0.0, 0.0], &[1.0, 1.0, 1.0],
///     0.5, 0.5,
/// )?;
/// assert_eq!(p.as_slice(), &[0.5, 0.5, 0.25]); // on z = xy
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bilinear_interpolate<T: Scalar>(
    b00: &[T],
    b01: &[T],
    b10: &[T],
    b11: &[T],
    u: T,
    v: T,
) -> Result<DVector<T>> {
    check_corners(b00, b01, b10, b11)?;
    super::check_param("bilinear interpolation parameter u", &u)?;
    super::check_param("bilinear interpolation parameter v", &v)?;
    let w = BilinearWeights::new(&u, &v);
    crate::error::finite(
        "bilinear interpolation point",
        DVector::from_fn(b00.len(), |c, _| {
            w.combine(&b00[c], &b10[c], &b01[c], &b11[c])
        }),
    )
}

pub(super) fn check_corners<T: Scalar>(b00: &[T], b01: &[T], b10: &[T], b11: &[T]) -> Result<()> {
    let d = b00.len();
    if d == 0 {
        return Err(Error::ShapeMismatch {
            what: "bilinear corner b00",
            expected: "at least one coordinate".into(),
            found: "0 coordinates".into(),
        });
    }
    for (what, p) in [
        ("bilinear corner b01", b01),
        ("bilinear corner b10", b10),
        ("bilinear corner b11", b11),
    ] {
        if p.len() != d {
            return Err(Error::ShapeMismatch {
                what,
                expected: format!("{d} coordinates (as b00)"),
                found: format!("{} coordinates", p.len()),
            });
        }
    }
    for (what, p) in [
        ("bilinear corner b00", b00),
        ("bilinear corner b01", b01),
        ("bilinear corner b10", b10),
        ("bilinear corner b11", b11),
    ] {
        crate::error::check_finite(what, p.iter())?;
    }
    Ok(())
}

//! `vrednostCoons` (thesis appendix C, Algoritem 6).

use nalgebra::{DMatrix, DVector};
use ndarray::{Array2, ArrayView2};

use super::column_vector;
use cagd::coons::{CoonsPatch, Tolerance};
use cagd::error::{check_finite, Result};
use cagd::param::SampledCurve;
use cagd::Scalar;

/// The point of a Coons patch with its three parts, as returned by [`vrednost_coons`]: the
/// outputs `[T, rc, rd, rcd]` of the fixed `vrednostCoons`, each a `d × 1` column.
#[derive(Debug, Clone, PartialEq)]
pub struct VrednostCoons<T: Scalar = f64> {
    /// `T = rc + rd − rcd`, the point `x(u, v)` (Izrek 4.2).
    pub t: Array2<T>,
    /// `rc = (1−v) c1(u) + v c2(u)`, eq. (4.1).
    pub rc: Array2<T>,
    /// `rd = (1−u) d1(v) + u d2(v)`, eq. (4.2).
    pub rd: Array2<T>,
    /// `rcd = (1−u)(1−v) P1 + u(1−v) P2 + (1−u)v P3 + uv P4`, eq. (4.3).
    pub rcd: Array2<T>,
}

/// The point of the bilinearly blended Coons patch at `(u, v)` from the values of its boundary
/// curves there: the twin of the thesis's `vrednostCoons` (appendix C, Algoritem 6), as fixed in
/// `octave_ref/fixed/vrednostCoons.m`.
///
/// **Original:** `function vrednostCoons(u,v,c1,c2,d1,d2,P1,P2,P3,P4)` — no output; it
/// displays `T`. **Fixed Octave:** `[T, rc, rd, rcd] = vrednostCoons(u,v,c1,c2,d1,d2,P1,P2,P3,P4)`.
///
/// # Layout
/// - `u`, `v`: the parameters (scalars).
/// - `c1`, `c2`: `d × 1` columns, the curves `c1(u) = x(u,0)` and `c2(u) = x(u,1)` at `u`.
/// - `d1`, `d2`: `d × 1` columns, the curves `d1(v) = x(0,v)` and `d2(v) = x(1,v)` at `v`.
/// - `p1 … p4`: `d × 1` columns, the corners `x(0,0), x(1,0), x(0,1), x(1,1)`.
/// - result: `T`, `rc`, `rd`, `rcd`, each `d × 1` (see [`VrednostCoons`]).
///
/// The thesis's data (Primer 4.3) is 3-D; any dimension `d ≥ 1` is accepted, the same for all.
///
/// # Bugs of the original fixed here (`octave_ref/BUGS.md`)
/// - **Returns nothing:** it declared no output and only displayed `T` (line `T = rc+rd-rcd`
///   without a semicolon). The twin returns `T` and its parts.
/// - Its data script uses `u` and `v` without defining them, and `u^2` (a matrix power) where
///   sampled vectors would need `.^`; here the caller passes the curve values.
///
/// # Native function
/// [`CoonsPatch::with_corners`] and [`CoonsPatch::eval_parts`], with the four curves known by
/// their values at `0`, at the parameter and at `1` (the corners) as
/// [`SampledCurve`]s, which return those values exactly; the blend is formed in the term order
/// of the Octave code, so the values agree bit for bit.
///
/// # Errors
/// [`Error::ShapeMismatch`](cagd::Error::ShapeMismatch) for an argument that is not a `d × 1`
/// column of the common dimension (named, e.g. `"vrednost_coons: d2"`);
/// [`Error::NonFinite`](cagd::Error::NonFinite) for a NaN or infinite input;
/// [`Error::CornerMismatch`](cagd::Error::CornerMismatch) when `u` or `v` is 0 or 1 and the
/// curve value given there is not the corner (the original never checks; the patch would not
/// interpolate its boundary).
///
/// ```
/// use cagd_octave::compat::vrednost_coons;
/// use ndarray::{array, Array2};
/// // Thesis Primer 4.3: c1 = (u, 0, u−u²), c2 = (u, 1, u), d1 = (0, v², v−v²), d2 = (1, v, v)
/// // at u = 0.2, v = 0.5; corners (0,0,0), (1,0,0), (0,1,0), (1,1,1).
/// let col = |a: [f64; 3]| Array2::from_shape_vec((3, 1), a.to_vec()).unwrap();
/// let (u, v) = (0.2, 0.5);
/// let r = vrednost_coons(
///     u, v,
///     col([u, 0.0, u - u * u]).view(), col([u, 1.0, u]).view(),
///     col([0.0, v * v, v - v * v]).view(), col([1.0, v, v]).view(),
///     col([0.0, 0.0, 0.0]).view(), col([1.0, 0.0, 0.0]).view(),
///     col([0.0, 1.0, 0.0]).view(), col([1.0, 1.0, 1.0]).view(),
/// )?;
/// assert_eq!(r.t.dim(), (3, 1));
/// let t: Vec<f64> = r.t.iter().copied().collect();
/// assert!((t[0] - 0.2).abs() < 1e-15 && (t[1] - 0.3).abs() < 1e-15 && (t[2] - 0.38).abs() < 1e-15);
/// # Ok::<(), cagd::Error>(())
/// ```
#[allow(clippy::too_many_arguments)] // the thesis signature, argument for argument
pub fn vrednost_coons<T: Scalar>(
    u: T,
    v: T,
    c1: ArrayView2<'_, T>,
    c2: ArrayView2<'_, T>,
    d1: ArrayView2<'_, T>,
    d2: ArrayView2<'_, T>,
    p1: ArrayView2<'_, T>,
    p2: ArrayView2<'_, T>,
    p3: ArrayView2<'_, T>,
    p4: ArrayView2<'_, T>,
) -> Result<VrednostCoons<T>> {
    check_finite("vrednost_coons: u, v", [&u, &v])?;
    let c1 = column_vector("vrednost_coons: c1", &c1, None)?;
    let dim = Some(c1.len());
    let c2 = column_vector("vrednost_coons: c2", &c2, dim)?;
    let d1 = column_vector("vrednost_coons: d1", &d1, dim)?;
    let d2 = column_vector("vrednost_coons: d2", &d2, dim)?;
    let corners = [
        column_vector("vrednost_coons: P1", &p1, dim)?,
        column_vector("vrednost_coons: P2", &p2, dim)?,
        column_vector("vrednost_coons: P3", &p3, dim)?,
        column_vector("vrednost_coons: P4", &p4, dim)?,
    ];
    let [q1, q2, q3, q4] = &corners;
    let patch = CoonsPatch::with_corners(
        through(q1, &u, &c1, q2)?,
        through(q3, &u, &c2, q4)?,
        through(q1, &v, &d1, q3)?,
        through(q2, &v, &d2, q4)?,
        corners.clone(),
        Tolerance::default(),
    )?;
    let point = patch.eval_parts(u, v);
    let column = |x: &DVector<T>| Array2::from_shape_fn((x.len(), 1), |(i, _)| x[i].clone());
    Ok(VrednostCoons {
        t: column(&point.x),
        rc: column(&point.rc),
        rd: column(&point.rd),
        rcd: column(&point.rcd),
    })
}

/// The curve on `[0, 1]` known by its value `at_t` at `t` and its ends `start` (at 0) and `end`
/// (at 1): a [`SampledCurve`] through those points, which returns each of them exactly (its
/// domain stays `[0, 1]` when `t` lies outside). When `t` is 0 or 1 the value given at `t`
/// stands for that end (the corner check then compares it with the corner).
fn through<T: Scalar>(
    start: &DVector<T>,
    t: &T,
    at_t: &DVector<T>,
    end: &DVector<T>,
) -> Result<SampledCurve<T>> {
    let mut points: Vec<(T, &DVector<T>)> = vec![(t.clone(), at_t)];
    if !t.is_zero() {
        points.push((T::zero(), start));
    }
    if !t.is_one() {
        points.push((T::one(), end));
    }
    // The parameters are finite (checked above): they compare.
    points.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
    let params = points.iter().map(|(s, _)| s.clone()).collect();
    let columns: Vec<DVector<T>> = points.iter().map(|(_, p)| (*p).clone()).collect();
    SampledCurve::new(params, DMatrix::from_columns(&columns))?.with_domain(T::zero(), T::one())
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd::Error;
    use ndarray::array;

    fn col(a: &[f64]) -> Array2<f64> {
        Array2::from_shape_vec((a.len(), 1), a.to_vec()).unwrap()
    }

    #[test]
    fn parts_add_up_and_any_dimension_works() {
        let (p1, p2, p3, p4) = (
            col(&[0.0, 0.0]),
            col(&[2.0, 0.0]),
            col(&[0.0, 1.0]),
            col(&[2.0, 1.0]),
        );
        // A plane rectangle with straight sides: x(u, v) = (2u, v), extrapolated at u = 1.5.
        let r = vrednost_coons(
            1.5,
            0.25,
            col(&[3.0, 0.0]).view(),
            col(&[3.0, 1.0]).view(),
            col(&[0.0, 0.25]).view(),
            col(&[2.0, 0.25]).view(),
            p1.view(),
            p2.view(),
            p3.view(),
            p4.view(),
        )
        .unwrap();
        assert_eq!(r.t, array![[3.0], [0.25]]);
        assert_eq!(&r.rc + &r.rd - &r.rcd, r.t);
    }

    #[test]
    fn errors_name_the_argument() {
        let z = col(&[0.0, 0.0, 0.0]);
        let bad = col(&[0.0, 0.0]);
        let e = vrednost_coons(
            0.5,
            0.5,
            z.view(),
            z.view(),
            z.view(),
            bad.view(),
            z.view(),
            z.view(),
            z.view(),
            z.view(),
        )
        .unwrap_err();
        assert!(matches!(
            e,
            Error::ShapeMismatch {
                what: "vrednost_coons: d2",
                ..
            }
        ));
        // At u = 0 the value of c1 must be the corner P1.
        let e = vrednost_coons(
            0.0,
            0.5,
            col(&[1.0, 0.0, 0.0]).view(),
            z.view(),
            z.view(),
            z.view(),
            z.view(),
            z.view(),
            z.view(),
            z.view(),
        )
        .unwrap_err();
        assert!(matches!(e, Error::CornerMismatch { .. }), "{e:?}");
        assert!(matches!(
            vrednost_coons(
                f64::NAN,
                0.5,
                z.view(),
                z.view(),
                z.view(),
                z.view(),
                z.view(),
                z.view(),
                z.view(),
                z.view()
            ),
            Err(Error::NonFinite { .. })
        ));
    }
}

//! `krpaCoons` (thesis appendix C, Algoritem 5).

use ndarray::{Array2, Array3, ArrayView2};

use super::{check_shape, column_vector, samples, to_dmatrix, untenzor};
use crate::literal::LiteralScalar;
use cagd::coons::{CoonsPatch, Tolerance};
use cagd::error::{Error, Result};
use cagd::param::{SampledCurve, Surface};
use cagd::Scalar;

/// A patch sampled on `linspace(0,1,N)²`, as returned by [`krpa_coons`] and
/// [`krpa_gordon`](super::krpa_gordon): the outputs `[R, P]` of the fixed `krpaCoons` and
/// `krpaGordon`.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledPatch<T: Scalar = f64> {
    /// `R`, `N × 3N`, packed: `R(i, 3j-2:3j)` is the point at `(u, v) = (t(i), t(j))`
    /// (Octave indices), the matrix the thesis code fills.
    pub r: Array2<T>,
    /// `P = tenzor(R)`, `N × N × 3`: `P[[i, j, c]]` is coordinate `c` of the point at
    /// `(t(i), t(j))` — the data the original drew with `surf`.
    pub p: Array3<T>,
}

/// The bilinearly blended Coons patch of four sampled boundary curves on `linspace(0,1,N)²`:
/// the twin of the thesis's `krpaCoons` (appendix C, Algoritem 5), as fixed in
/// `octave_ref/fixed/krpaCoons.m`.
///
/// **Original:** `function krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)` — no output; it draws the patch
/// and the four curves. **Fixed Octave:** `[R, P] = krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)`.
///
/// ```text
/// x(u,v) = (1−v) c1(u) + v c2(u) + (1−u) d1(v) + u d2(v)
///          − [(1−u)(1−v) P1 + u(1−v) P2 + (1−u)v P3 + uv P4]        (Izrek 4.2)
/// ```
///
/// # Layout
/// - `c1`, `c2`: `3 × N`, the curves `x(u,0)` and `x(u,1)` sampled at `u = linspace(0,1,N)`.
/// - `d1`, `d2`: `3 × N`, the curves `x(0,v)` and `x(1,v)` sampled at `v = linspace(0,1,N)`.
/// - `p1 … p4`: `3 × 1`, the corners `x(0,0), x(1,0), x(0,1), x(1,1)`.
/// - result: [`SampledPatch`], `R` (`N × 3N`) and `P` (`N × N × 3`). The curves the original
///   drew are the inputs.
///
/// # Bugs of the original fixed here (`octave_ref/BUGS.md`)
/// - **Undefined `N`:** it used `N` without defining it; here (and in the fixed Octave)
///   `N = size(c1, 2)`.
/// - **Missing `P4`:** its data script sets `P3` twice and never `P4`. The twin checks the
///   corners against the curve ends, so passing that data's `P3 = (1,1,1)` is an
///   [`Error::CornerMismatch`] at `x(0,1)`, not a silently wrong patch.
/// - It returned nothing, and grew `R` from `zeros(N,N)`.
///
/// # Native function
/// [`CoonsPatch::with_corners`] over four [`SampledCurve`]s (exact at the samples) and
/// [`Surface::eval_grid`] on `linspace(0,1,N)²`; the blend is formed in the term order of the
/// Octave code (bit for bit equal on the thesis data). `R` is [`untenzor`]`(P)`.
///
/// # Errors
/// [`Error::ShapeMismatch`] for a curve that is not `3 × N` (`N` from `c1`) or a corner that is
/// not `3 × 1`, naming it; [`Error::TooFewPoints`] for `N < 2`; [`Error::NonFinite`] for a NaN
/// or infinite value; [`Error::CornerMismatch`] when the curves do not meet the corners
/// (relative tolerance `1e-10`, see [`Tolerance`]).
///
/// ```
/// use cagd_octave::compat::krpa_coons;
/// use ndarray::{array, Array2};
/// // The unit square with straight sides, N = 3: the patch is x(u,v) = (u, v, 0).
/// let t = [0.0, 0.5, 1.0];
/// let curve = |f: &dyn Fn(f64) -> [f64; 3]| Array2::from_shape_fn((3, 3), |(c, k)| f(t[k])[c]);
/// let c1 = curve(&|u| [u, 0.0, 0.0]);
/// let c2 = curve(&|u| [u, 1.0, 0.0]);
/// let d1 = curve(&|v| [0.0, v, 0.0]);
/// let d2 = curve(&|v| [1.0, v, 0.0]);
/// let (p1, p2, p3, p4) = (array![[0.0], [0.0], [0.0]], array![[1.0], [0.0], [0.0]],
///                         array![[0.0], [1.0], [0.0]], array![[1.0], [1.0], [0.0]]);
/// let s = krpa_coons(c1.view(), c2.view(), d1.view(), d2.view(),
///                    p1.view(), p2.view(), p3.view(), p4.view())?;
/// assert_eq!((s.r.dim(), s.p.dim()), ((3, 9), (3, 3, 3)));
/// assert_eq!(s.r.row(1).to_vec(), vec![0.5, 0.0, 0.0, 0.5, 0.5, 0.0, 0.5, 1.0, 0.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[allow(clippy::too_many_arguments)] // the thesis signature, argument for argument
pub fn krpa_coons<T: LiteralScalar>(
    c1: ArrayView2<'_, T>,
    c2: ArrayView2<'_, T>,
    d1: ArrayView2<'_, T>,
    d2: ArrayView2<'_, T>,
    p1: ArrayView2<'_, T>,
    p2: ArrayView2<'_, T>,
    p3: ArrayView2<'_, T>,
    p4: ArrayView2<'_, T>,
) -> Result<SampledPatch<T>> {
    let n = c1.ncols();
    let curves = [
        ("krpa_coons: c1", c1.view()),
        ("krpa_coons: c2", c2.view()),
        ("krpa_coons: d1", d1.view()),
        ("krpa_coons: d2", d2.view()),
    ];
    for (what, c) in &curves {
        check_shape(what, c, Some(3), Some(n))?;
    }
    if n < 2 {
        return Err(Error::TooFewPoints {
            what: "krpa_coons: c1 (samples N)",
            min: 2,
            found: n,
        });
    }
    let corners = [
        column_vector("krpa_coons: P1", &p1, Some(3))?,
        column_vector("krpa_coons: P2", &p2, Some(3))?,
        column_vector("krpa_coons: P3", &p3, Some(3))?,
        column_vector("krpa_coons: P4", &p4, Some(3))?,
    ];
    let t = samples::<T>(n);
    let [c1, c2, d1, d2] = curves.map(|(_, c)| SampledCurve::new(t.clone(), to_dmatrix(&c)));
    let patch = CoonsPatch::with_corners(c1?, c2?, d1?, d2?, corners, Tolerance::default())?;
    let p = crate::arrays::to_array3(patch.eval_grid(&t, &t));
    let r = untenzor(p.view())?;
    Ok(SampledPatch { r, p })
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::array;

    fn square(n: usize) -> [Array2<f64>; 4] {
        let t = cagd::linspace::linspace(0.0, 1.0, n);
        let curve =
            |f: &dyn Fn(f64) -> [f64; 3]| Array2::from_shape_fn((3, n), |(c, k)| f(t[k])[c]);
        [
            curve(&|u| [u, 0.0, 0.0]),
            curve(&|u| [u, 1.0, 0.0]),
            curve(&|v| [0.0, v, 0.0]),
            curve(&|v| [1.0, v, 0.0]),
        ]
    }

    fn corners() -> [Array2<f64>; 4] {
        [
            array![[0.0], [0.0], [0.0]],
            array![[1.0], [0.0], [0.0]],
            array![[0.0], [1.0], [0.0]],
            array![[1.0], [1.0], [0.0]],
        ]
    }

    #[test]
    fn shapes_are_checked_and_named() {
        let [c1, c2, d1, _] = square(4);
        let [p1, p2, p3, p4] = corners();
        let short = square(3)[3].clone();
        let e = krpa_coons(
            c1.view(),
            c2.view(),
            d1.view(),
            short.view(),
            p1.view(),
            p2.view(),
            p3.view(),
            p4.view(),
        )
        .unwrap_err();
        assert!(
            matches!(
                e,
                Error::ShapeMismatch {
                    what: "krpa_coons: d2",
                    ..
                }
            ),
            "{e:?}"
        );
        let one = Array2::zeros((3, 1));
        let e = krpa_coons(
            one.view(),
            one.view(),
            one.view(),
            one.view(),
            p1.view(),
            p2.view(),
            p3.view(),
            p4.view(),
        )
        .unwrap_err();
        assert!(matches!(e, Error::TooFewPoints { .. }), "{e:?}");
    }

    #[test]
    fn corners_must_meet_the_curves() {
        let [c1, c2, d1, d2] = square(3);
        let [p1, p2, _, p4] = corners();
        let wrong = array![[1.0], [1.0], [1.0]];
        let e = krpa_coons(
            c1.view(),
            c2.view(),
            d1.view(),
            d2.view(),
            p1.view(),
            p2.view(),
            wrong.view(),
            p4.view(),
        )
        .unwrap_err();
        assert!(matches!(e, Error::CornerMismatch { .. }), "{e:?}");
    }
}

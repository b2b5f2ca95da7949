//! `ploskevB` (thesis appendix B, Algoritem 2).

use ndarray::{Array3, ArrayView2};

use super::{samples, tenzor};
use crate::literal::LiteralScalar;
use cagd::error::Result;

/// The Bézier patch with the packed net `kontrolne_t` sampled on `linspace(0,1,N)²`: the twin
/// of the thesis's `ploskevB` (appendix B, Algoritem 2), as fixed in
/// `octave_ref/fixed/ploskevB.m`.
///
/// **Original:** `function ploskevB(kontrolneT,N)` — no output; it draws the patch with
/// `surf(P(:,:,1), P(:,:,2), P(:,:,3))`. **Fixed Octave:** `P = ploskevB(kontrolneT, N)`.
///
/// # Layout
/// - `kontrolne_t`: the packed net `(m+1) × 3(n+1)`, `B(i+1, 3j+1:3j+3) = b_{i,j}` (see
///   [`tenzor`]); `m ≠ n` allowed.
/// - `n`: the number of samples `N` per direction; `u` and `v` both run over
///   `t = linspace(0,1,N)`.
/// - result `P`: `N × N × 3`, `P[[i, j, c]]` = coordinate `c` of `x(t(i), t(j))` — the data
///   `surf` drew.
///
/// # Bugs of the original fixed here (`octave_ref/BUGS.md`)
/// - It evaluated through `bilinearna`, which is wrong for `m ≠ n` (see
///   [`bilinearna`](super::bilinearna)).
/// - It returned nothing (and did not preallocate `P`).
///
/// # Native function
/// [`patch_from_array3`](crate::arrays::patch_from_array3) (after [`tenzor`]) and [`BezierPatch::eval`](cagd::bezier::BezierPatch::eval) at every grid
/// point: the tensor de Casteljau algorithm in the term order of the fixed Octave code, so the
/// values agree bit for bit. (For large grids [`Surface::eval_grid`](cagd::Surface::eval_grid)
/// is faster and agrees to rounding.)
///
/// # Errors
/// As [`tenzor`]; [`Error::TooFewPoints`](cagd::Error::TooFewPoints) for an empty net.
/// `N = 0` gives a `0 × 0 × 3` array, as Octave does.
///
/// ```
/// use cagd_octave::compat::ploskev_b;
/// use ndarray::array;
/// // The bilinear patch b00 = 0, b01 = (0,1,0), b10 = (1,0,0), b11 = (1,1,1): z = uv.
/// let b = array![[0.0, 0.0, 0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 1.0, 1.0, 1.0]];
/// let p = ploskev_b(b.view(), 3)?;
/// assert_eq!(p.dim(), (3, 3, 3));
/// assert_eq!(p[[1, 2, 2]], 0.5); // z(1/2, 1)
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn ploskev_b<T: LiteralScalar>(kontrolne_t: ArrayView2<'_, T>, n: usize) -> Result<Array3<T>> {
    let patch = crate::arrays::patch_from_array3(&tenzor(kontrolne_t)?)?;
    let t = samples::<T>(n);
    let mut p = Array3::from_elem((n, n, patch.dim()), T::zero());
    for (i, u) in t.iter().enumerate() {
        for (j, v) in t.iter().enumerate() {
            for (c, x) in patch.eval(u.clone(), v.clone()).iter().enumerate() {
                p[[i, j, c]] = x.clone();
            }
        }
    }
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::array;

    #[test]
    fn empty_grid() {
        let b = array![[0.0, 0.0, 0.0]];
        assert_eq!(ploskev_b(b.view(), 0).unwrap().dim(), (0, 0, 3));
        // A degree (0, 0) net is one point everywhere.
        let p = ploskev_b(array![[1.0, 2.0, 3.0]].view(), 2).unwrap();
        assert!(p.outer_iter().all(|row| row
            .rows()
            .into_iter()
            .all(|x| x.to_vec() == vec![1.0, 2.0, 3.0])));
    }
}

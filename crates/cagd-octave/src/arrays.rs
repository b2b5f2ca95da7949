//! Octave-shaped arrays and the core's native types: the one place where an `ndarray` array
//! becomes a [`PointGrid`] or a [`BezierPatch`] and back.
//!
//! An Octave array `P(i,j,k)` of size `nu × nv × d` is the [`Array3`] `p[[i-1, j-1, k-1]]` and
//! the [`PointGrid`] entry `[[i-1, j-1, k-1]]`: the same indices, so no conversion reorders.

use cagd::bezier::BezierPatch;
use cagd::error::Result;
use cagd::grid::PointGrid;
use cagd::scalar::Scalar;
use ndarray::Array3;

/// The grid as an array of the same shape `(nu, nv, d)`.
///
/// ```
/// use cagd::grid::PointGrid;
/// let g = PointGrid::from_shape_fn((2, 3, 1), |(a, b, _)| (10 * a + b) as f64);
/// let a = cagd_octave::arrays::to_array3(g.clone());
/// assert_eq!(a[[1, 2, 0]], 12.0);
/// assert_eq!(cagd_octave::arrays::from_array3(&a), g);
/// ```
pub fn to_array3<T>(grid: PointGrid<T>) -> Array3<T> {
    let shape = grid.dim();
    Array3::from_shape_vec(shape, grid.into_vec())
        .expect("a point grid holds nu · nv · d entries in row-major order")
}

/// The array as a grid of the same shape.
pub fn from_array3<T: Clone>(array: &Array3<T>) -> PointGrid<T> {
    PointGrid::from_shape_fn(array.dim(), |(a, b, c)| array[[a, b, c]].clone())
}

/// The Bézier patch of a net of shape `(m + 1, n + 1, d)`, `net[[i, j, k]]` being coordinate
/// `k` of `b_{i,j}` (the layout `tenzor` returns).
///
/// # Errors
/// As [`BezierPatch::from_grid`].
///
/// ```
/// let net = ndarray::Array3::from_shape_fn((2, 2, 1), |(i, j, _)| (i + 2 * j) as f64);
/// let p = cagd_octave::arrays::patch_from_array3(&net)?;
/// assert_eq!(p.eval(0.5, 0.5)[0], 1.5);
/// assert_eq!(cagd_octave::arrays::patch_to_array3(&p), net);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn patch_from_array3<T: Scalar>(net: &Array3<T>) -> Result<BezierPatch<T>> {
    BezierPatch::from_grid(&from_array3(net))
}

/// The control net of a patch as an array of shape `(m + 1, n + 1, d)`.
pub fn patch_to_array3<T: Scalar>(patch: &BezierPatch<T>) -> Array3<T> {
    to_array3(patch.to_grid())
}

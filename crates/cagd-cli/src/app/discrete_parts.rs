//! The three parts of the discrete Coons patch (the CAD notes (6), thesis end of §4.1):
//!
//! ```text
//! b^u_ij  = (1 − i/m) P_0j + (i/m) P_mj,
//! b^v_ij  = (1 − j/n) P_i0 + (j/n) P_in,
//! b^uv_ij = (1 − i/m  i/m) [P_00 P_0n; P_m0 P_mn] (1 − j/n  j/n)ᵀ,
//! P_ij    = b^u_ij + b^v_ij − b^uv_ij,
//! ```
//!
//! the grids `discrete-coons --steps` prints beside the net.

use cagd::grid::PointGrid;
use cagd_octave::literal::LiteralScalar;

/// `[b^u, b^v, b^uv]` of the boundary of `net` (`(m+1) × (n+1) × d`, `m, n ≥ 1`).
pub fn parts<T: LiteralScalar>(net: &PointGrid<T>) -> [PointGrid<T>; 3] {
    let (m1, n1, d) = net.dim();
    let (m, n) = (m1 - 1, n1 - 1);
    let s = |i: usize, m: usize| T::from_ratio(i as i64, m as i64);
    let bu = PointGrid::from_shape_fn((m1, n1, d), |(i, j, k)| {
        (T::one() - s(i, m)) * net[[0, j, k]].clone() + s(i, m) * net[[m, j, k]].clone()
    });
    let bv = PointGrid::from_shape_fn((m1, n1, d), |(i, j, k)| {
        (T::one() - s(j, n)) * net[[i, 0, k]].clone() + s(j, n) * net[[i, n, k]].clone()
    });
    let buv = PointGrid::from_shape_fn((m1, n1, d), |(i, j, k)| {
        let (a, b) = (s(i, m), s(j, n));
        let (a0, b0) = (T::one() - a.clone(), T::one() - b.clone());
        a0.clone() * (b0.clone() * net[[0, 0, k]].clone() + b.clone() * net[[0, n, k]].clone())
            + a * (b0 * net[[m, 0, k]].clone() + b * net[[m, n, k]].clone())
    });
    [bu, bv, buv]
}

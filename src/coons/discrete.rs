//! The discrete Coons patch (thesis end of §4.1; notes (6)).

use nalgebra::DMatrix;

use crate::cost::Cost;
use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// Checks a net given as one `(m+1) × (n+1)` matrix per coordinate (the layout of
/// `BezierPatch`) and returns `(m, n)`.
pub(crate) fn net_degree<T: Scalar>(
    what: &'static str,
    net: &[DMatrix<T>],
) -> Result<(usize, usize)> {
    let first = net.first().ok_or(Error::ShapeMismatch {
        what,
        expected: "at least one coordinate matrix".into(),
        found: "none".into(),
    })?;
    let (rows, cols) = first.shape();
    if rows == 0 || cols == 0 {
        return Err(Error::TooFewPoints {
            what,
            min: 1,
            found: 0,
        });
    }
    for c in net {
        if c.shape() != (rows, cols) {
            return Err(Error::ShapeMismatch {
                what,
                expected: format!("coordinate matrices of one shape {rows}×{cols}"),
                found: format!("{}×{}", c.nrows(), c.ncols()),
            });
        }
        crate::error::check_finite(what, c.iter())?;
    }
    Ok((rows - 1, cols - 1))
}

/// The discrete Coons patch: the interior control points of a Bézier net `b_{i,j}`,
/// `i = 0..=m`, `j = 0..=n`, from its four boundary rows (notes (6)):
///
/// ```text
/// b_ij = (1 − i/m) b_0j + (i/m) b_mj + (1 − j/n) b_i0 + (j/n) b_in
///        − [1 − i/m, i/m] [b_00 b_0n; b_m0 b_mn] [1 − j/n; j/n],   0 < i < m, 0 < j < n.
/// ```
///
/// It is the bilinearly blended Coons construction applied to the control net, with the
/// blending parameters `i/m`, `j/n` at the Greville abscissae.
///
/// `net` holds one `(m+1) × (n+1)` matrix per coordinate (entry `(i, j)` is coordinate `k` of
/// `b_ij`, as `BezierPatch` takes it); only the boundary rows and columns are read, and the
/// returned net has the same boundary with the interior filled in. With `m < 2` or `n < 2`
/// there is no interior and the net is returned unchanged.
///
/// The thesis prints this formula with three slips, corrected here: the ranges of `b^v_ij` are
/// swapped (`i = 1..n−1, j = 1..m−1`; they are `i = 1..m−1, j = 1..n−1`), those of `b^{u,v}_ij`
/// run to `m` and `n` (they are interior, `1..m−1`, `1..n−1`), and its bilinear term
/// `[1 − j/n, j/n] [b_00 b_0n; b_m0 b_mn] [1 − i/m; i/m]` has the two blending vectors swapped,
/// which would give `b_0n` the weight `(1 − j/n) i/m` instead of `(1 − i/m) j/n` (the notes'
/// formula (6) has them right). The left-hand side of its last display should read `b_ij`, not
/// `b^{u,v}_ij`.
///
/// The result satisfies the 3×3 mask equation of [`super::Mask::coons`] at every interior
/// point, so it equals [`super::solve_mask`] with that mask (see there for the proof).
///
/// # Errors
/// [`Error::ShapeMismatch`] for no coordinates or coordinate matrices of different shapes,
/// [`Error::TooFewPoints`] for an empty net, [`Error::NonFinite`] for non-finite entries.
///
/// ```
/// use cagd::coons::discrete_coons;
/// use nalgebra::dmatrix;
/// // A 3×3 net (m = n = 2) of a height field: only the centre is unknown.
/// let z = dmatrix![0.0, 1.0, 0.0;
///                  1.0, 9.0, 3.0;
///                  0.0, 1.0, 2.0];
/// let net = discrete_coons(&[z]).unwrap();
/// // (1 + 1)/2 + (1 + 3)/2 − (0 + 0 + 0 + 2)/4
/// assert_eq!(net[0][(1, 1)], 2.5);
/// ```
pub fn discrete_coons<T: Scalar>(net: &[DMatrix<T>]) -> Result<Vec<DMatrix<T>>> {
    let (m, n) = net_degree("discrete Coons net", net)?;
    let mut out = net.to_vec();
    if m < 2 || n < 2 {
        return Ok(out);
    }
    for (b, o) in net.iter().zip(out.iter_mut()) {
        for i in 1..m {
            let s = T::from_ratio(i as i64, m as i64);
            let s1 = T::one() - s.clone();
            for j in 1..n {
                let t = T::from_ratio(j as i64, n as i64);
                let t1 = T::one() - t.clone();
                let bu = s1.clone() * b[(0, j)].clone() + s.clone() * b[(m, j)].clone();
                let bv = t1.clone() * b[(i, 0)].clone() + t.clone() * b[(i, n)].clone();
                let buv = s1.clone()
                    * (t1.clone() * b[(0, 0)].clone() + t.clone() * b[(0, n)].clone())
                    + s.clone() * (t1.clone() * b[(m, 0)].clone() + t.clone() * b[(m, n)].clone());
                o[(i, j)] = bu + bv - buv;
            }
        }
    }
    Ok(out)
}

/// The cost of [`discrete_coons`] on a net of degree `(m, n)` in `d` coordinates: the
/// `(m−1)(n−1)` interior points, each coordinate `b^u + b^v − b^uv` in 17 operations (4 in each
/// of `b^u`, `b^v`, 9 in `b^uv` with its two weights `1 − i/m`, `1 − j/n`), on numbers as large
/// as the net's grown by the weights: `i/m` and `j/n` multiply numerator and denominator, twice
/// in the corner term, `2(⌈log₂ m⌉ + ⌈log₂ n⌉) + 2` bits (grow it by the size of the net).
///
/// In exact arithmetic an operation took about 300 ns (nets of 401 × 401 single digits, 2.8 s
/// with reading and writing): each weighs a quarter of
/// [`exact_op_cost`](crate::limits::exact_op_cost) ([`Cost::cheaper_when_exact`]).
///
/// ```
/// use cagd::coons::discrete_coons_cost;
/// let c = discrete_coons_cost(4, 3, 3);
/// assert_eq!(c.ops(), 3 * 2 * 3 * 17);
/// assert_eq!(c.bits(), 2 * (2 + 2) + 2);
/// // No interior, no work.
/// assert_eq!(discrete_coons_cost(1, 100, 3).ops(), 0);
/// ```
pub fn discrete_coons_cost(m: usize, n: usize, d: usize) -> Cost {
    let interior = (m.saturating_sub(1) as u128).saturating_mul(n.saturating_sub(1) as u128);
    formula_cost(interior, (m, n), d)
}

/// 17 operations per coordinate at each of `points` points of a net of degree `(m, n)`, on
/// numbers grown by the weights `i/m`, `j/n` (see [`discrete_coons_cost`]).
fn formula_cost(points: u128, (m, n): (usize, usize), d: usize) -> Cost {
    let log2 = |k: usize| u128::from(usize::BITS - k.saturating_sub(1).leading_zeros());
    Cost::new(points.saturating_mul(17 * d as u128), 0)
        .grown(2 * (log2(m) + log2(n)) + 2)
        .cheaper_when_exact(4)
}

/// The three parts of the discrete Coons formula at every point of a net (notes (6)):
///
/// ```text
/// b^u_ij  = (1 − i/m) b_0j + (i/m) b_mj,
/// b^v_ij  = (1 − j/n) b_i0 + (j/n) b_in,
/// b^uv_ij = [1 − i/m, i/m] [b_00 b_0n; b_m0 b_mn] [1 − j/n; j/n],
/// ```
///
/// so that [`discrete_coons`] is `b^u + b^v − b^uv` at the interior points (and at the boundary
/// points too, where the parts reproduce the boundary). `net` is laid out as for
/// [`discrete_coons`]; the result is `[b^u, b^v, b^uv]`, each one matrix per coordinate. A net
/// of one row (`m = 0`) or one column (`n = 0`) has no opposite side: its weight `i/m` (or
/// `j/n`) is taken as 0.
///
/// # Errors
/// As [`discrete_coons`].
///
/// ```
/// use cagd::coons::discrete_coons_parts;
/// use nalgebra::dmatrix;
/// let z = dmatrix![0.0, 1.0, 0.0;
///                  1.0, 9.0, 3.0;
///                  0.0, 1.0, 2.0];
/// let [bu, bv, buv] = discrete_coons_parts(&[z])?;
/// // At the centre: (1 + 1)/2, (1 + 3)/2, (0 + 0 + 0 + 2)/4; the net's 2.5 = 1 + 2 − 0.5.
/// assert_eq!((bu[0][(1, 1)], bv[0][(1, 1)], buv[0][(1, 1)]), (1.0, 2.0, 0.5));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn discrete_coons_parts<T: Scalar>(net: &[DMatrix<T>]) -> Result<[Vec<DMatrix<T>>; 3]> {
    let (m, n) = net_degree("discrete Coons net", net)?;
    let weight = |i: usize, m: usize| {
        if m == 0 {
            T::zero()
        } else {
            T::from_ratio(i as i64, m as i64)
        }
    };
    let mut parts: [Vec<DMatrix<T>>; 3] = std::array::from_fn(|_| Vec::with_capacity(net.len()));
    for b in net {
        let (s, t) = (|i| weight(i, m), |j| weight(j, n));
        let bu = DMatrix::from_fn(m + 1, n + 1, |i, j| {
            (T::one() - s(i)) * b[(0, j)].clone() + s(i) * b[(m, j)].clone()
        });
        let bv = DMatrix::from_fn(m + 1, n + 1, |i, j| {
            (T::one() - t(j)) * b[(i, 0)].clone() + t(j) * b[(i, n)].clone()
        });
        let buv = DMatrix::from_fn(m + 1, n + 1, |i, j| {
            let (s1, t1) = (T::one() - s(i), T::one() - t(j));
            s1 * (t1.clone() * b[(0, 0)].clone() + t(j) * b[(0, n)].clone())
                + s(i) * (t1 * b[(m, 0)].clone() + t(j) * b[(m, n)].clone())
        });
        for (part, value) in parts.iter_mut().zip([bu, bv, buv]) {
            part.push(value);
        }
    }
    Ok(parts)
}

/// The cost of [`discrete_coons_parts`] on a net of degree `(m, n)` in `d` coordinates: the
/// formula's operations (see [`discrete_coons_cost`]) at every one of the `(m+1)(n+1)` points.
///
/// ```
/// use cagd::coons::discrete_coons_parts_cost;
/// assert_eq!(discrete_coons_parts_cost(4, 3, 3).ops(), 5 * 4 * 3 * 17);
/// ```
pub fn discrete_coons_parts_cost(m: usize, n: usize, d: usize) -> Cost {
    let points = (m as u128 + 1).saturating_mul(n as u128 + 1);
    formula_cost(points, (m, n), d)
}

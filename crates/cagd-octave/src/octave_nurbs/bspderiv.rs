//! octave-nurbs' compiled `bspderiv`: the B-spline of the derivative.

use super::basis::truncate;
use super::error::{NurbsError, Result};

/// octave-nurbs' `[dc, dk] = bspderiv (d, c, k)`: the derivative of the B-spline of degree
/// `d` (truncated toward zero) with control points `c` (`rows × cols`) and knots `k`, as the
/// B-spline of degree `d − 1` with control points
/// `dc(:, i) = d / (k(i+d+1) − k(i+1)) · (c(:, i+1) − c(:, i))` (0-based, `i = 0 … cols−2`;
/// Piegl & Tiller A3.3) and knots `dk = k(1 … nk−2)` — in octave-nurbs' operation order, so
/// bit for bit. A zero knot difference gives ±Inf or NaN, as there (the core's
/// [`BSplineCurve::derivative`](cagd::BSplineCurve::derivative) sets such a coefficient to
/// zero instead). The number of knots is not checked: extra knots are kept in `dk`.
///
/// Returns `dc` (`rows × (cols − 1)`, column-major) and `dk`.
///
/// # Errors
/// [`NurbsError::Undefined`] where octave-nurbs reads past its knots (`nk < cols + d`) or
/// sizes arrays negatively (no control point, fewer than 2 knots, a negative degree).
///
/// ```
/// use cagd_octave::octave_nurbs::bspderiv;
/// // octave-nurbs: bspderiv (2, [0 1 2 3], [0 0 0 .5 1 1 1]) = [4 2 4], knots [0 0 .5 1 1].
/// let (dc, dk) = bspderiv(2.0, 1, 4, &[0.0, 1.0, 2.0, 3.0], &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0])?;
/// assert_eq!(dc, vec![4.0, 2.0, 4.0]);
/// assert_eq!(dk, vec![0.0, 0.0, 0.5, 1.0, 1.0]);
/// # Ok::<(), cagd_octave::octave_nurbs::NurbsError>(())
/// ```
pub fn bspderiv(
    d: f64,
    rows: usize,
    cols: usize,
    c: &[f64],
    k: &[f64],
) -> Result<(Vec<f64>, Vec<f64>)> {
    check_bspderiv(d, cols, k.len())?;
    let mut dc = vec![0.0; rows * (cols - 1)];
    bspderiv_into(d, rows, cols, c, k, &mut dc)?;
    Ok((dc, k[1..k.len() - 1].to_vec()))
}

/// `Ok` when octave-nurbs' `bspderiv` reads only inside its arrays for degree `d` (truncated),
/// `cols` control points and `nk` knots: at least one control point and two knots, a degree
/// of at least 0, and the knots `k(i+d+1)` it reads (`nk ≥ cols + d` for two or more points).
///
/// # Errors
/// [`NurbsError::Undefined`].
pub fn check_bspderiv(d: f64, cols: usize, nk: usize) -> Result<()> {
    let dt = truncate(d);
    if dt < 0 || cols == 0 || nk < 2 {
        return Err(NurbsError::undefined(
            "c",
            format!("degree {dt}, {cols} control points, {nk} knots"),
        ));
    }
    if cols >= 2 && (cols - 2) as i64 + dt + 1 >= nk as i64 {
        return Err(NurbsError::undefined(
            "k",
            format!(
                "{nk} knots for degree {dt} and {cols} control points: bspderiv reads k({})",
                cols as i64 - 2 + dt + 2
            ),
        ));
    }
    Ok(())
}

/// The control points `dc` of [`bspderiv`] into `dc` (`rows × (cols − 1)`, Octave's array for
/// them), without allocating; its knots are `k(2:end-1)`.
///
/// # Errors
/// As [`check_bspderiv`].
pub fn bspderiv_into(
    d: f64,
    rows: usize,
    cols: usize,
    c: &[f64],
    k: &[f64],
    dc: &mut [f64],
) -> Result<()> {
    check_bspderiv(d, cols, k.len())?;
    let d = truncate(d) as usize;
    if rows == 0 || cols < 2 {
        return Ok(());
    }
    // Column i: d / (k(i+d+1) − k(i+1)) times c(:, i+1) − c(:, i) (0-based knots `k[i + 1]`
    // and `k[i + d + 1]`, which check_bspderiv has checked exist).
    let (lo, hi) = (&k[1..cols], &k[d + 1..d + cols]);
    let columns = c.chunks_exact(rows).zip(c[rows..].chunks_exact(rows));
    for ((out, (a, b)), (k0, k1)) in dc
        .chunks_exact_mut(rows)
        .zip(columns)
        .zip(lo.iter().zip(hi))
    {
        let tmp = d as f64 / (k1 - k0);
        for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
            *o = tmp * (y - x);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bspderiv_as_octave_nurbs() {
        // octave-nurbs 1.4.3: bspderiv (0, [0 1 2 3], [0 1 2 3 4]) = [NaN NaN NaN]... no:
        // d = 0 gives 0/(k(i+1) − k(i+1)) = NaN times the differences.
        let (dc, dk) =
            bspderiv(0.0, 1, 4, &[0.0, 1.0, 2.0, 3.0], &[0.0, 1.0, 2.0, 3.0, 4.0]).unwrap();
        assert!(dc.iter().all(|x| x.is_nan()));
        assert_eq!(dk, vec![1.0, 2.0, 3.0]);
        // [0 0 0 1 1 1 1] (a knot of multiplicity 4 > 3): [2 2 Inf].
        let (dc, _) = bspderiv(
            2.0,
            1,
            4,
            &[0.0, 1.0, 2.0, 3.0],
            &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        )
        .unwrap();
        assert_eq!(dc, vec![2.0, 2.0, f64::INFINITY]);
        // One control point: an empty derivative.
        let (dc, dk) = bspderiv(2.0, 1, 1, &[0.0], &[0.0, 0.0, 0.0, 1.0]).unwrap();
        assert!(dc.is_empty());
        assert_eq!(dk, vec![0.0, 0.0]);
        assert!(bspderiv(2.0, 1, 4, &[0.0; 4], &[0.0, 0.0, 0.0, 1.0, 1.0]).is_err());
    }
}

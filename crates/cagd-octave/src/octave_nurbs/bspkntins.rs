//! octave-nurbs' `bspkntins`: knot insertion (Piegl & Tiller A5.4, its `.m` file).

use super::error::{NurbsError, Result};
use super::oct::{integer, OctMat, OctVec};
use super::span::findspan;

/// Octave's `sort (u)`: ascending along the first dimension longer than 1, NaN last.
pub(crate) fn octave_sort(u: &[f64], dims: &[usize]) -> Vec<f64> {
    let mut out = u.to_vec();
    let Some(k) = dims.iter().position(|&d| d > 1) else {
        return out;
    };
    let stride: usize = dims[..k].iter().product();
    let len = dims[k];
    let block = stride * len;
    let cmp = |a: &f64, b: &f64| match (a.is_nan(), b.is_nan()) {
        (true, true) => std::cmp::Ordering::Equal,
        (true, false) => std::cmp::Ordering::Greater,
        (false, true) => std::cmp::Ordering::Less,
        _ => a.partial_cmp(b).expect("not NaN"),
    };
    for start in (0..out.len()).step_by(block.max(1)) {
        for s in 0..stride {
            let mut fiber: Vec<f64> = (0..len).map(|i| out[start + s + stride * i]).collect();
            fiber.sort_by(cmp);
            for (i, x) in fiber.into_iter().enumerate() {
                out[start + s + stride * i] = x;
            }
        }
    }
    out
}

/// octave-nurbs' `[ic, ik] = bspkntins (d, c, k, u)`: the control points `ic` and knots `ik`
/// of the B-spline of degree `d` with control points `c` (`rows × cols`, column-major) and
/// knots `k` after inserting the knots `u` (any order, repeats allowed; sorted first, as
/// there), by Piegl & Tiller A5.4 in the operation order of octave-nurbs' `.m` file — its
/// values bit for bit. Nothing is checked that octave-nurbs does not check: knots may be
/// inserted at the ends of the knot range or beyond the multiplicity `d + 1` (zero basis
/// functions, as octave-nurbs' `nrbkntins` notes). Returns `ic` (column-major), its number of
/// columns, and `ik`.
///
/// The core's [`BSplineCurve::insert_knots`](cagd::BSplineCurve::insert_knots) is the same
/// algorithm for knots strictly inside the domain.
///
/// # Errors
/// Where `bspkntins` fails: no knot to insert or a knot outside `[k(1), k(end)]` or NaN
/// (its `findspan`), a non-integer degree, and every index its code would take outside its
/// arrays ([`NurbsError::Index`]).
///
/// ```
/// use cagd_octave::octave_nurbs::bspkntins;
/// // The quadratic [0 1 2 3] on [0 0 0 .5 1 1 1] with the knot 0.25 inserted.
/// let (ic, cols, ik) = bspkntins(2.0, 1, 4, &[0.0, 1.0, 2.0, 3.0],
///     &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], &[0.25], &[1, 1])?;
/// assert_eq!(cols, 5);
/// assert_eq!(ic, vec![0.0, 0.5, 1.25, 2.0, 3.0]);
/// assert_eq!(ik, vec![0.0, 0.0, 0.0, 0.25, 0.5, 1.0, 1.0, 1.0]);
/// # Ok::<(), cagd_octave::octave_nurbs::NurbsError>(())
/// ```
pub fn bspkntins(
    d: f64,
    rows: usize,
    cols: usize,
    c: &[f64],
    k: &[f64],
    u: &[f64],
    u_dims: &[usize],
) -> Result<(Vec<f64>, usize, Vec<f64>)> {
    let d = integer("d", d)?;
    let u = octave_sort(u, u_dims);
    let uv = OctVec::from_data("u", &u);
    let kv = OctVec::from_data("k", k);
    let cm = OctMat::from_data("c", rows, cols, c);
    let (mc, nc, nu, nk) = (rows as i64, cols as i64, u.len() as i64, k.len() as i64);
    let mut ic = OctMat::zeros("ic", mc, nc + nu);
    let mut ik = OctVec::zeros("ik", nk + nu);
    let (n, r) = (nc - 1, nu - 1);
    let m = n + d + 1;
    let a = span(n, uv.get(1)?, k)?;
    let b = span(n, uv.get(r + 1)?, k)? + 1;
    for j in 1..=a - d + 1 {
        ic.set_col(j, &cm.col(j)?)?;
    }
    for j in b..=nc {
        ic.set_col(j + nu, &cm.col(j)?)?;
    }
    for j in 1..=a + 1 {
        ik.set(j, kv.get(j)?)?;
    }
    for j in b + d + 1..=m + 1 {
        ik.set(j + nu, kv.get(j)?)?;
    }
    let mut ii = b + d - 1;
    let mut ss = ii + nu;
    for jj in (0..=r).rev() {
        let x = uv.get(jj + 1)?;
        // ind = (a+1):ii, those with u(jj+1) <= k(ind+1) (all read first, as Octave does).
        let mut ind = Vec::new();
        for i in a + 1..=ii {
            if x <= kv.get(i + 1)? {
                ind.push(i);
            }
        }
        let moved: Vec<Vec<f64>> = ind.iter().map(|&i| cm.col(i - d)).collect::<Result<_>>()?;
        let knots: Vec<f64> = ind.iter().map(|&i| kv.get(i + 1)).collect::<Result<_>>()?;
        for ((&i, col), kn) in ind.iter().zip(&moved).zip(&knots) {
            ic.set_col(i + ss - ii - d, col)?;
            ik.set(i + ss - ii + 1, *kn)?;
        }
        ii -= ind.len() as i64;
        ss -= ind.len() as i64;
        let next = ic.col(ss - d + 1)?;
        ic.set_col(ss - d, &next)?;
        for l in 1..=d {
            let ind = ss - d + l;
            let alfa = ik.get(ss + l + 1)? - x;
            if alfa == 0.0 {
                let next = ic.col(ind + 1)?;
                ic.set_col(ind, &next)?;
            } else {
                let alfa = alfa / (ik.get(ss + l + 1)? - kv.get(ii - d + l + 1)?);
                let next = ic.col(ind + 1)?;
                let this = ic.col(ind)?;
                let blended: Vec<f64> = this
                    .iter()
                    .zip(&next)
                    .map(|(p, q)| {
                        let tmp = (1.0 - alfa) * q;
                        alfa * p + tmp
                    })
                    .collect();
                ic.set_col(ind, &blended)?;
            }
        }
        ik.set(ss + 1, x)?;
        ss -= 1;
    }
    let cols = ic.cols();
    Ok((ic.into_data(), cols, ik.into_data()))
}

/// `findspan (n, d, x, k)` of one parameter as an integer.
fn span(n: i64, x: f64, k: &[f64]) -> Result<i64> {
    let s = findspan(n as f64, &[x], k)?;
    s.first()
        .map(|&s| s as i64)
        .ok_or_else(|| NurbsError::refused("u", "no span"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd::BSplineCurve;
    use nalgebra::DMatrix;

    #[test]
    fn agrees_with_the_core_inside_the_domain() {
        let c = [0.0, 0.0, 1.0, 2.0, 3.0, -1.0, 4.0, 1.0, 5.0, 2.0];
        let k = [0.0, 0.0, 0.0, 0.3, 0.6, 1.0, 1.0, 1.0];
        let u = [0.45, 0.3, 0.8, 0.8];
        let (ic, cols, ik) = bspkntins(2.0, 2, 5, &c, &k, &u, &[1, 4]).unwrap();
        let core = BSplineCurve::new(2, k.to_vec(), DMatrix::from_column_slice(2, 5, &c))
            .unwrap()
            .insert_knots(&u)
            .unwrap();
        assert_eq!(cols, 9);
        assert_eq!(ik, core.knots().as_slice());
        assert_eq!(ic, core.control().as_slice());
    }

    #[test]
    fn ends_and_errors_as_octave_nurbs() {
        // A knot at the end of the range is inserted (octave-nurbs 1.4.3 does it too).
        let c = [0.0, 1.0, 2.0, 3.0];
        let k = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
        let (_, cols, ik) = bspkntins(2.0, 1, 4, &c, &k, &[1.0], &[1, 1]).unwrap();
        assert_eq!((cols, ik.len()), (5, 8));
        assert!(bspkntins(2.0, 1, 4, &c, &k, &[], &[0, 0]).is_err());
        assert!(bspkntins(2.0, 1, 4, &c, &k, &[1.5], &[1, 1]).is_err());
        assert!(bspkntins(2.0, 1, 4, &c, &k, &[f64::NAN], &[1, 1]).is_err());
    }

    #[test]
    fn sort_as_octave() {
        assert_eq!(octave_sort(&[3.0, f64::NAN, 1.0], &[1, 3])[..2], [1.0, 3.0]);
        assert_eq!(
            octave_sort(&[2.0, 1.0, 4.0, 3.0], &[2, 2]),
            vec![1.0, 2.0, 3.0, 4.0]
        );
    }
}

//! The fast paths of [`nrbeval`](super::nrbeval): when every parameter lies in the domain of
//! a well-formed B-spline, the core's batch kernels give `bspeval`'s values to rounding.
//!
//! A curve at a few hundred or more non-decreasing parameters (the usual `linspace`) is
//! evaluated piece by piece: its homogeneous B-spline is cut into Bézier pieces by knot
//! insertion (the core's [`BSplineCurve::insert_knots`], octave-nurbs' `bspkntins`), and each
//! piece is evaluated by the core's Bézier batch ([`BezierCurve::eval_many_into`], Bernstein
//! sums with sizes fixed at compile time for degrees up to 3): the weighted points
//! `(w·x, w·y, w·z)` straight into the output and the weights beside them, in blocks that
//! stay in the cache, then multiplied by `1/w`. This avoids the `p(p+1)/2` divisions per
//! point of the triangular basis; the values agree with `bspeval` to rounding (knot insertion
//! and Bernstein sums are convex combinations). When every weight is exactly 1 (a B-spline
//! written as a NURBS, the usual case) the weights are not evaluated and nothing is divided.

use cagd::bezier::BezierCurve;
use cagd::bspline::{BSplineCurve, BSplineSurface};
use nalgebra::DMatrix;

use super::bspeval::Bsp;
use super::error::Result;

/// Whether `b` is a B-spline the core takes and every parameter lies in its domain
/// `[U(d+1), U(nc+1)]` where `bspeval`'s span is the core's: sorted finite knots, at least
/// `d + 1` control points, a last span of positive length (`bspeval` puts `U(nc+1)` on span
/// `nc − 1`, the core on the last non-empty one), finite parameters.
pub fn regular(b: &Bsp<'_>, params: &[f64]) -> bool {
    let (d, nc, k) = (b.degree, b.cols, b.knots);
    if nc < d + 1 || k.iter().any(|x| !x.is_finite()) || !k.windows(2).all(|w| w[0] <= w[1]) {
        return false;
    }
    let (lo, hi) = (k[d], k[nc]);
    lo < hi && k[nc - 1] < hi && params.iter().all(|&u| (lo..=hi).contains(&u))
}

/// The rows `rows` of the coefficients `c` (`stride × n`, column-major) as a matrix.
pub fn rows_of(c: &[f64], stride: usize, rows: usize, n: usize) -> DMatrix<f64> {
    DMatrix::from_fn(rows, n, |i, j| c[i + stride * j])
}

/// The number of parameters from which a curve is evaluated by its Bézier pieces.
pub const PIECES_FROM: usize = 256;

/// One Bézier piece of a homogeneous curve: its interval, the curve of its weighted points
/// `(w·x, w·y, w·z)` and the curve of its weights as the plane curve `(w, 0)` (plane and
/// space curves of degree up to 3 have the core's fastest kernels); no weight curve when every
/// weight is 1.
pub struct Piece {
    a: f64,
    b: f64,
    weighted: BezierCurve,
    weight: Option<BezierCurve>,
}

/// The Bézier pieces of a homogeneous (4-D) B-spline curve whose domain ends are clamped
/// (the first and last `p + 1` knots of the domain equal): every interior knot raised to
/// multiplicity `p` by knot insertion, then one piece per non-empty span. `None` for other
/// knot vectors. With `unit_weights` the pieces carry no weight curve.
///
/// # Errors
/// The core's, for a curve it does not take.
pub fn bezier_pieces(h: &BSplineCurve, unit_weights: bool) -> Result<Option<Vec<Piece>>> {
    let p = h.degree();
    let knots = h.knots().as_slice();
    let n = h.control().ncols();
    let (lo, hi) = (knots[p], knots[n]);
    let clamped = knots[1..=p].iter().all(|&k| k == lo) && knots[n..n + p].iter().all(|&k| k == hi);
    if !clamped {
        return Ok(None);
    }
    let mut insert = Vec::new();
    let mut k = p + 1;
    while k < n {
        let x = knots[k];
        let mult = knots[k..n].iter().take_while(|&&y| y == x).count();
        if lo < x && x < hi {
            insert.extend(std::iter::repeat_n(x, p.saturating_sub(mult)));
        }
        k += mult;
    }
    let r = h.insert_knots(&insert)?;
    let (rk, rc) = (r.knots().as_slice(), r.control());
    let mut pieces = Vec::new();
    for s in p..rc.ncols() {
        if rk[s] < rk[s + 1] {
            let cols = rc.columns(s - p, p + 1);
            let weighted = DMatrix::from_fn(3, p + 1, |i, j| cols[(i, j)]);
            let weight = DMatrix::from_fn(2, p + 1, |i, j| if i == 0 { cols[(3, j)] } else { 0.0 });
            let weight = if unit_weights {
                None
            } else {
                Some(BezierCurve::new_on_interval(weight, rk[s], rk[s + 1])?)
            };
            pieces.push(Piece {
                a: rk[s],
                b: rk[s + 1],
                weighted: BezierCurve::new_on_interval(weighted, rk[s], rk[s + 1])?,
                weight,
            });
        }
    }
    Ok(Some(pieces))
}

/// Parameters per block of [`eval_pieces`]: the weights of a block (`2 × BLOCK` numbers) and
/// its points stay in the cache between the evaluation and the division.
const BLOCK: usize = 4096;

/// The curve at the non-decreasing parameters `t` (all in the domain) into `out` (`3` numbers
/// per point), piece by piece: a parameter on a breakpoint belongs to the piece on its right
/// (as `findspan`), the right end of the domain to the last piece.
///
/// # Errors
/// The core's (none for parameters in the domain).
pub fn eval_pieces(pieces: &[Piece], t: &[f64], out: &mut [f64]) -> Result<()> {
    if pieces[0].weight.is_none() {
        return Ok(eval_runs(pieces, t, out, &mut [])?);
    }
    let mut w = vec![0.0; 2 * BLOCK.min(t.len())];
    for (ts, out) in t.chunks(BLOCK).zip(out.chunks_mut(3 * BLOCK)) {
        let w = &mut w[..2 * ts.len()];
        eval_runs(pieces, ts, out, w)?;
        for (x, w) in out.chunks_exact_mut(3).zip(w.chunks_exact(2)) {
            let r = 1.0 / w[0];
            for c in x {
                *c *= r;
            }
        }
    }
    Ok(())
}

/// The weighted points (into `out`, 3 per point) and, for pieces with a weight curve, the
/// weights (into `w`, 2 per point) at the non-decreasing parameters `ts`, each run of
/// parameters by the piece holding it.
fn eval_runs(pieces: &[Piece], ts: &[f64], out: &mut [f64], w: &mut [f64]) -> cagd::Result<()> {
    let Some(&t0) = ts.first() else {
        return Ok(());
    };
    let mut start = 0;
    let first = pieces.partition_point(|p| p.a <= t0).saturating_sub(1);
    for (k, piece) in pieces.iter().enumerate().skip(first) {
        if start == ts.len() {
            break;
        }
        let last = k + 1 == pieces.len();
        let len = ts[start..]
            .iter()
            .take_while(|&&x| x < piece.b || (last && x <= piece.b))
            .count();
        let end = start + len;
        if len > 0 {
            piece
                .weighted
                .eval_many_into(&ts[start..end], &mut out[3 * start..3 * end])?;
            if let Some(weight) = &piece.weight {
                weight.eval_many_into(&ts[start..end], &mut w[2 * start..2 * end])?;
            }
        }
        start = end;
    }
    Ok(())
}

/// The `v` rows per band of a surface grid `nu × nv` evaluated by the core's sweep of
/// [`swapped_surface`] (`dh` numbers per control point) a band at a time, so that the
/// evaluation can be stopped between bands: each band costs the sweep of its rows (per row,
/// the `n1` columns of the net collapsed along `v` and the `nu` points summed along `u`) and
/// the set-up every call of the core repeats (the net copied, the `u` basis of every `u`).
/// The band is at least [`CHECK_WORK`](super::CHECK_WORK) and four times that set-up (so
/// that the set-ups add at most a quarter); `None` when such a band would be longer than 16
/// times [`CHECK_WORK`] (a net and degrees so large that only a finer evaluation stops
/// quickly).
pub fn grid_band_rows(bu: &Bsp<'_>, bv: &Bsp<'_>, nu: usize, dh: usize) -> Option<usize> {
    let (p, q) = (bu.degree as u128 + 1, bv.degree as u128 + 1);
    let (n1, n2, nu, dh) = (bu.cols as u128, bv.cols as u128, nu as u128, dh as u128);
    let row = (n1 * q * dh + nu * p * dh + q * q).max(1);
    let setup = n1 * n2 * dh + nu * p * p;
    let rows = (super::CHECK_WORK / row).max(4 * setup / row + 1);
    (rows.saturating_mul(row) <= 16 * super::CHECK_WORK || setup <= super::CHECK_WORK)
        .then_some(rows.min(usize::MAX as u128) as usize)
}

/// The surface `S'(v, u) = S(u, v)` of the rows `0..rows` of 4-row coefficients (`4 × n1 ×
/// n2`), directions swapped: the core's row-major `(nv, nu, rows)` grid of that surface is
/// exactly Octave's `rows × nu × nv`, and its sums run along `v` first, then along `u`, as
/// `nrbeval`'s do.
///
/// # Errors
/// The core's.
pub fn swapped_surface(
    bu: &Bsp<'_>,
    bv: &Bsp<'_>,
    coefs: &[f64],
    n1: usize,
    n2: usize,
    rows: usize,
) -> Result<BSplineSurface> {
    let coords = (0..rows)
        .map(|k| DMatrix::from_fn(n2, n1, |j, i| coefs[k + 4 * (i + n1 * j)]))
        .collect();
    Ok(BSplineSurface::new(
        bv.degree,
        bu.degree,
        bv.knots.to_vec(),
        bu.knots.to_vec(),
        coords,
    )?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd::nurbs::NurbsCurve;

    /// A small deterministic generator (SplitMix64) for the tests.
    struct Rng(u64);

    impl Rng {
        fn unit(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// Clamped knots of degree `p` for `n` points, interior knots repeated up to `p` times.
    fn knots(rng: &mut Rng, p: usize, n: usize) -> Vec<f64> {
        let mut interior = Vec::new();
        while interior.len() < n - p - 1 {
            let x = 0.05 + 0.9 * rng.unit();
            let m = (1 + (rng.unit() * p as f64) as usize).min(n - p - 1 - interior.len());
            interior.extend(std::iter::repeat_n(x, m));
        }
        interior.sort_by(f64::total_cmp);
        let mut k = vec![0.0; p + 1];
        k.extend(interior);
        k.extend(std::iter::repeat_n(1.0, p + 1));
        k
    }

    #[test]
    fn bezier_pieces_give_the_curve() {
        let mut rng = Rng(7);
        for case in 0..60 {
            let p = 1 + case % 5;
            let n = p + 1 + (rng.unit() * 7.0) as usize;
            let unit = case % 3 == 0;
            let h = DMatrix::from_fn(4, n, |r, _| match r {
                3 if unit => 1.0,
                3 => 0.3 + 2.7 * rng.unit(),
                _ => 2.0 * rng.unit() - 1.0,
            });
            let b = BSplineCurve::new(p, knots(&mut rng, p, n), h).unwrap();
            let curve = NurbsCurve::from_homogeneous(b).unwrap();
            let pieces = bezier_pieces(curve.homogeneous(), unit).unwrap().unwrap();
            let t = cagd::linspace(0.0, 1.0, 301);
            let (mut fast, mut slow) = (vec![0.0; 3 * t.len()], vec![0.0; 3 * t.len()]);
            eval_pieces(&pieces, &t, &mut fast).unwrap();
            curve.try_eval_many_into(&t, &mut slow).unwrap();
            let scale = slow.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for (a, b) in fast.iter().zip(&slow) {
                assert!(
                    (a - b).abs() <= 1e-13 * scale,
                    "case {case} (degree {p}): {a} vs {b}"
                );
            }
        }
    }

    #[test]
    fn unclamped_knots_have_no_pieces() {
        let h = DMatrix::from_element(4, 4, 1.0);
        let b = BSplineCurve::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], h).unwrap();
        assert!(bezier_pieces(&b, false).unwrap().is_none());
    }
}

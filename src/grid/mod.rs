//! Evaluation into caller-given buffers: the buffer layouts, their checks, and the row driver
//! that spreads large grids over all cores.
//!
//! **Layouts.** Curves write `k` points of dimension `d` one after the other: `out[p·d + c]` is
//! coordinate `c` of the point at `ts[p]` (a `k × d` row-major array, which is also the
//! column-major storage of nalgebra's `d × k` matrix with one point per column). Surfaces write
//! the grid `us × vs` row by row: `out[(a·nv + b)·d + c]` is coordinate `c` of `x(us[a], vs[b])`
//! (`(nu, nv, d)` row-major, the memory layout of [`PointGrid`], which
//! [`crate::Surface::eval_grid`] returns).
//!
//! **Threads.** With the default feature `parallel`, a grid whose work (points × terms per
//! point) exceeds [`PARALLEL_MIN_WORK`] is cut into a few blocks of whole rows per core and the
//! blocks are evaluated with rayon; each block allocates its scratch once. Smaller grids run on
//! the calling thread and never touch the thread pool.
//!
//! **Vectors.** The row kernels (`contract_row`, `contract_row_planar`, `blend_row`, and the
//! curve kernels that call [`Scalar::vectorized`] themselves) run inside `Scalar::vectorized`:
//! for `f64` with the default feature `simd`, in code compiled for the processor's widest
//! vector instructions, chosen at run time; the results are the same as without it. The
//! dispatch is made per row, around a kernel that is inlined whole (`#[inline(always)]`) into
//! the dispatched code — the closure handed to `vectorized` included: a kernel or closure left
//! as a separate function is compiled for the baseline (SSE2) only.
//!
//! **Exact rationals.** The private module `exact` holds fraction-free kernels that the batch
//! paths take when the scalar is `BigRational` (the same values, a fraction of the gcds).

pub(crate) mod exact;
mod point_grid;

pub use point_grid::PointGrid;

use crate::error::{Error, Result};
use crate::scalar::Scalar;

/// The work (points × multiply-adds per point) above which a grid is split over threads:
/// about 0.1 ms of work, much more than the cost of waking the pool.
pub const PARALLEL_MIN_WORK: usize = 1 << 18;

/// Checks that a buffer has exactly `expected` entries.
pub(crate) fn check_len<T>(what: &'static str, expected: usize, out: &[T]) -> Result<()> {
    if out.len() == expected {
        Ok(())
    } else {
        Err(Error::ShapeMismatch {
            what,
            expected: format!("{expected} entries"),
            found: format!("{} entries", out.len()),
        })
    }
}

/// A vector of `len` copies of `value`, or [`Error::TooLarge`] (counted in
/// [`Limit::Elements`](crate::error::Limit::Elements)) when the memory cannot be reserved: a size
/// beyond what the machine can hold is refused, never a panic or an abort.
pub(crate) fn try_filled<T: Clone>(what: &'static str, len: usize, value: T) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| Error::TooLarge {
        what,
        requested: len as u128,
        limit: (isize::MAX as usize / std::mem::size_of::<T>().max(1)) as u128,
        which: crate::error::Limit::Elements,
    })?;
    v.resize(len, value);
    Ok(v)
}

/// [`try_filled`] for the infallible functions of the crate: a length that cannot be held is a
/// panic naming it (what their `# Panics` sections document), never an abort.
pub(crate) fn filled<T: Clone>(what: &'static str, len: Option<usize>, value: T) -> Vec<T> {
    let len = len.unwrap_or_else(|| panic!("{what}: the number of values overflows usize"));
    try_filled(what, len, value).unwrap_or_else(|e| panic!("{e}"))
}

/// Whether sums `Σ_i w_i x_i` with `Σ_i |w_i| ≤ weight` and `|x_i| ≤ size` are finite doubles
/// whatever the order of the additions: `weight · size ≤ f64::MAX / 4` (a floating-point sum
/// of `k` terms is within a factor `1 + k·ε` of the exact one, far below 2 for any sum that
/// fits in memory). Sums of exact numbers are always finite.
pub(crate) fn bounded_by<T: Scalar>(weight: f64, size: f64) -> bool {
    T::EXACT || weight * size <= f64::MAX / 4.0
}

/// The largest `|x|` of `values` as a double (`∞` if one is not finite).
pub(crate) fn max_abs<'a, T: Scalar>(values: impl IntoIterator<Item = &'a T>) -> f64 {
    values.into_iter().fold(0.0, |m, x| {
        let x = x.to_f64().abs();
        if x.is_nan() {
            f64::INFINITY
        } else {
            m.max(x)
        }
    })
}

/// `rows · row_len` without overflow (an overflowing request is a shape error, not a panic).
pub(crate) fn grid_len(what: &'static str, sizes: &[usize]) -> Result<usize> {
    sizes
        .iter()
        .try_fold(1usize, |acc, &s| acc.checked_mul(s))
        .ok_or_else(|| Error::ShapeMismatch {
            what,
            expected: "a grid whose size fits in memory".into(),
            found: format!("sizes {sizes:?}"),
        })
}

/// Calls `row(scratch, index, chunk)` for every chunk of `out` of length `row_len` (the last
/// one shorter if `out.len()` is not a multiple of `row_len`), with a scratch value made by
/// `init` once per block of rows. Runs on several threads when `work` (an estimate of the
/// multiply-adds) is at least [`PARALLEL_MIN_WORK`] and the feature `parallel` is on.
///
/// Every grid kernel of the crate writes through here, so this is where a non-finite value
/// computed from finite input (a sum that overflowed) is caught: each chunk is scanned right
/// after it is written, while it is in cache (in `f64`; exact numbers are always finite).
///
/// # Errors
/// [`Error::Overflow`] naming `what` and the index in `out` of the first non-finite value
/// (the whole of `out` is written all the same).
pub(crate) fn for_each_row<T, S, I, F>(
    what: &'static str,
    out: &mut [T],
    row_len: usize,
    work: usize,
    init: I,
    row: F,
) -> Result<()>
where
    T: Scalar,
    I: Fn() -> S + Sync,
    F: Fn(&mut S, usize, &mut [T]) + Sync,
{
    for_each_bounded_row(what, out, row_len, work, init, |scratch, r, chunk| {
        row(scratch, r, chunk);
        false
    })
}

/// [`for_each_row`] for kernels that can prove a row finite: `row` returns whether it
/// did (`true`: the row is bounded by a finite number and is not scanned; `false`: it is). A
/// Bézier point is bounded by `Σ |B_i(t)| · max |b_i|`, which the curve and the patch know
/// before they write a row ([`bounded_by`]).
///
/// # Errors
/// As [`for_each_row`].
pub(crate) fn for_each_bounded_row<T, S, I, F>(
    what: &'static str,
    out: &mut [T],
    row_len: usize,
    work: usize,
    init: I,
    row: F,
) -> Result<()>
where
    T: Scalar,
    I: Fn() -> S + Sync,
    F: Fn(&mut S, usize, &mut [T]) -> bool + Sync,
{
    if row_len == 0 || out.is_empty() {
        return Ok(());
    }
    let scan = !T::EXACT;
    let run_block = |first: usize, block: &mut [T]| -> Option<usize> {
        let mut scratch = init();
        let mut bad = None;
        for (r, chunk) in block.chunks_mut(row_len).enumerate() {
            let bounded = row(&mut scratch, first + r, chunk);
            if scan && !bounded && bad.is_none() {
                bad = T::first_non_finite(chunk).map(|k| r * row_len + k);
            }
        }
        bad
    };
    let overflow = |index: usize, out: &[T]| Error::Overflow {
        what,
        index,
        value: out[index].to_f64(),
    };
    #[cfg(feature = "parallel")]
    {
        let threads = rayon::current_num_threads();
        let rows = out.len().div_ceil(row_len);
        if threads > 1 && rows > 1 && work >= PARALLEL_MIN_WORK {
            use rayon::prelude::*;
            // A few blocks per thread, so that a thread slowed by other load can be helped out.
            let rows_per_block = rows.div_ceil(4 * threads).max(1);
            let bad = out
                .par_chunks_mut(rows_per_block * row_len)
                .enumerate()
                .filter_map(|(k, block)| {
                    run_block(k * rows_per_block, block).map(|i| k * rows_per_block * row_len + i)
                })
                .min();
            return match bad {
                Some(index) => Err(overflow(index, out)),
                None => Ok(()),
            };
        }
    }
    let _ = work;
    match run_block(0, out) {
        Some(index) => Err(overflow(index, out)),
        None => Ok(()),
    }
}

/// The rows `f(t)` for every `t` in `ts`, each of length `width`, one after the other
/// (`ts.len() × width`, row-major): one allocation for all of them.
pub(crate) fn rows_of<T: Scalar>(ts: &[T], width: usize, f: impl Fn(&T, &mut [T])) -> Vec<T> {
    let mut rows = vec![T::zero(); ts.len() * width];
    if width > 0 {
        for (t, row) in ts.iter().zip(rows.chunks_exact_mut(width)) {
            f(t, row);
        }
    }
    rows
}

/// `out = Σ_j w[j] · x_j`, where `x_j = xs[j·len .. (j+1)·len]`: a weighted sum of `w.len()`
/// vectors of length `len = out.len()`, accumulated in ascending `j` starting from
/// `w[0] · x_0`.
#[inline(always)]
pub(crate) fn weighted_sum_into<T: Scalar>(w: &[T], xs: &[T], out: &mut [T]) {
    let len = out.len();
    let mut parts = w.iter().zip(xs.chunks_exact(len));
    if let Some((w0, x0)) = parts.next() {
        for (o, x) in out.iter_mut().zip(x0) {
            *o = w0.clone() * x.clone();
        }
    } else {
        out.iter_mut().for_each(|o| *o = T::zero());
    }
    for (wj, xj) in parts {
        for (o, x) in out.iter_mut().zip(xj) {
            *o = o.clone() + wj.clone() * x.clone();
        }
    }
}

/// Writes `Σ_j w_b[j] · c_j` for every point `b` of a grid row: `ws` holds the weights of
/// point `b` at `ws[b·terms ..]`, `coeffs` the `terms` vectors `c_j` of length `d`, `row`
/// receives the points one after the other. Dispatches to a kernel with the dimension fixed
/// at compile time for `d ≤ 4`, so that the sums stay in registers.
#[inline]
pub(crate) fn contract_row<T: Scalar>(ws: &[T], terms: usize, coeffs: &[T], row: &mut [T]) {
    T::vectorized(
        #[inline(always)]
        || contract_row_inline(ws, terms, coeffs, row),
    );
}

/// [`contract_row`] without the dispatch, inlined into its callers' dispatched code.
#[inline(always)]
fn contract_row_inline<T: Scalar>(ws: &[T], terms: usize, coeffs: &[T], row: &mut [T]) {
    let d = coeffs.len() / terms.max(1);
    // Common small cases with both sizes fixed at compile time: the coefficients live in
    // registers and the loops unroll. Same arithmetic (and result) as the general kernels.
    match (terms, d) {
        (2, 2) => contract_row_const::<T, 2, 2>(ws, coeffs, row),
        (2, 3) => contract_row_const::<T, 2, 3>(ws, coeffs, row),
        (3, 2) => contract_row_const::<T, 3, 2>(ws, coeffs, row),
        (3, 3) => contract_row_const::<T, 3, 3>(ws, coeffs, row),
        (4, 2) => contract_row_const::<T, 4, 2>(ws, coeffs, row),
        (4, 3) => contract_row_const::<T, 4, 3>(ws, coeffs, row),
        (5, 3) => contract_row_const::<T, 5, 3>(ws, coeffs, row),
        (6, 3) => contract_row_const::<T, 6, 3>(ws, coeffs, row),
        (_, 1) => contract_row_fixed::<T, 1>(ws, terms, coeffs, row),
        (_, 2) => contract_row_fixed::<T, 2>(ws, terms, coeffs, row),
        (_, 3) => contract_row_fixed::<T, 3>(ws, terms, coeffs, row),
        (_, 4) => contract_row_fixed::<T, 4>(ws, terms, coeffs, row),
        _ => {
            for (w, p) in ws.chunks_exact(terms).zip(row.chunks_exact_mut(d.max(1))) {
                weighted_sum_into(w, coeffs, p);
            }
        }
    }
}

#[inline(always)]
fn contract_row_const<T: Scalar, const L: usize, const D: usize>(
    ws: &[T],
    coeffs: &[T],
    row: &mut [T],
) {
    let c: [[T; D]; L] =
        std::array::from_fn(|j| std::array::from_fn(|k| coeffs[j * D + k].clone()));
    for (w, p) in ws.chunks_exact(L).zip(row.chunks_exact_mut(D)) {
        let mut acc: [T; D] = std::array::from_fn(|k| w[0].clone() * c[0][k].clone());
        for j in 1..L {
            for k in 0..D {
                acc[k] = acc[k].clone() + w[j].clone() * c[j][k].clone();
            }
        }
        for (o, a) in p.iter_mut().zip(acc) {
            *o = a;
        }
    }
}

#[inline(always)]
fn contract_row_fixed<T: Scalar, const D: usize>(
    ws: &[T],
    terms: usize,
    coeffs: &[T],
    row: &mut [T],
) {
    if terms == 0 {
        row.iter_mut().for_each(|o| *o = T::zero());
        return;
    }
    for (w, p) in ws.chunks_exact(terms).zip(row.chunks_exact_mut(D)) {
        let mut acc: [T; D] = std::array::from_fn(|k| w[0].clone() * coeffs[k].clone());
        for (wj, cj) in w[1..].iter().zip(coeffs[D..].chunks_exact(D)) {
            for k in 0..D {
                acc[k] = acc[k].clone() + wj.clone() * cj[k].clone();
            }
        }
        for (o, a) in p.iter_mut().zip(acc) {
            *o = a;
        }
    }
}

/// [`contract_row`] with the weights stored by term ("planar"): the weight `j` of point `b`
/// of the row is `ws[j·stride + first + b]`, for `b` from 0 to `row.len()/d`, `d =
/// coeffs.len()/terms`. Every point is `Σ_j w_b[j] · c_j`, from `w_b[0] · c_0`, `j`
/// ascending — [`contract_row`]'s operations, so its values bit for bit. The weights of
/// consecutive points lie side by side, so they load as vectors without being transposed.
#[inline]
pub(crate) fn contract_row_planar<T: Scalar>(
    ws: &[T],
    stride: usize,
    first: usize,
    terms: usize,
    coeffs: &[T],
    row: &mut [T],
) {
    T::vectorized(
        #[inline(always)]
        || contract_row_planar_inline(ws, stride, first, terms, coeffs, row),
    );
}

#[inline(always)]
fn contract_row_planar_inline<T: Scalar>(
    ws: &[T],
    stride: usize,
    first: usize,
    terms: usize,
    coeffs: &[T],
    row: &mut [T],
) {
    let d = coeffs.len() / terms.max(1);
    if terms == 0 || d == 0 {
        row.iter_mut().for_each(|o| *o = T::zero());
        return;
    }
    let n = row.len() / d;
    macro_rules! fixed {
        ($l:literal, $d:literal) => {
            planar_const::<T, $l, $d>(
                std::array::from_fn(|j| &ws[j * stride + first..][..n]),
                coeffs,
                row,
            )
        };
    }
    match (terms, d) {
        (2, 2) => fixed!(2, 2),
        (2, 3) => fixed!(2, 3),
        (3, 2) => fixed!(3, 2),
        (3, 3) => fixed!(3, 3),
        (4, 2) => fixed!(4, 2),
        (4, 3) => fixed!(4, 3),
        (4, 4) => fixed!(4, 4),
        (5, 3) => fixed!(5, 3),
        (6, 3) => fixed!(6, 3),
        _ => {
            for (b, p) in row.chunks_exact_mut(d).enumerate() {
                for (k, o) in p.iter_mut().enumerate() {
                    let mut acc = ws[first + b].clone() * coeffs[k].clone();
                    for j in 1..terms {
                        acc = acc + ws[j * stride + first + b].clone() * coeffs[j * d + k].clone();
                    }
                    *o = acc;
                }
            }
        }
    }
}

#[inline(always)]
fn planar_const<T: Scalar, const L: usize, const D: usize>(
    planes: [&[T]; L],
    coeffs: &[T],
    row: &mut [T],
) {
    let c: [[T; D]; L] =
        std::array::from_fn(|j| std::array::from_fn(|k| coeffs[j * D + k].clone()));
    for (b, p) in row.chunks_exact_mut(D).enumerate() {
        let mut acc: [T; D] = std::array::from_fn(|k| planes[0][b].clone() * c[0][k].clone());
        for j in 1..L {
            for k in 0..D {
                acc[k] = acc[k].clone() + planes[j][b].clone() * c[j][k].clone();
            }
        }
        for (o, a) in p.iter_mut().zip(acc) {
            *o = a;
        }
    }
}

/// The rows `f(t)` for every `t` in `ts`, each of length `width`, stored by term: entry `j`
/// of the row of `ts[b]` at `j·ts.len() + b` (the layout [`contract_row_planar`] reads, with
/// `stride = ts.len()`). One allocation for all of them and one for a row of scratch.
pub(crate) fn planar_rows_of<T: Scalar>(
    ts: &[T],
    width: usize,
    f: impl Fn(&T, &mut [T]),
) -> Vec<T> {
    let n = ts.len();
    let mut planes = vec![T::zero(); n * width];
    let mut row = vec![T::zero(); width];
    for (b, t) in ts.iter().enumerate() {
        f(t, &mut row);
        for (j, x) in row.iter().enumerate() {
            planes[j * n + b] = x.clone();
        }
    }
    planes
}

/// One grid row of a blended surface: point `b` of `row` (`d` values each) becomes
///
/// ```text
/// Σ_j ws[b][j] · c_j  +  Σ_i w[i] · x_i[b],
/// ```
///
/// with `terms` weights per point `ws[b] = ws[b·terms ..]` on the row's coefficient vectors
/// `c_j = coeffs[j·d ..]` ([`contract_row`]), then the row's weights `w` on whole rows of
/// per-point vectors: `x_i = xs[i·row.len() ..][..row.len()]`, in the layout of `row`. The
/// second part is a sequence of `axpy`s over contiguous memory, which vectorise. The sums run
/// `j` ascending, then `i` ascending. Coons (`terms = 2`, `w = [1 − u, u]`) and Gordon
/// (`terms = n + 1`, `w = L_i(u)`) rows are of this form.
#[inline]
pub(crate) fn blend_row<T: Scalar>(
    ws: &[T],
    terms: usize,
    coeffs: &[T],
    w: &[T],
    xs: &[T],
    row: &mut [T],
) {
    T::vectorized(
        #[inline(always)]
        || blend_row_inline(ws, terms, coeffs, w, xs, row),
    );
}

/// [`blend_row`] without the dispatch.
#[inline(always)]
fn blend_row_inline<T: Scalar>(
    ws: &[T],
    terms: usize,
    coeffs: &[T],
    w: &[T],
    xs: &[T],
    row: &mut [T],
) {
    contract_row_inline(ws, terms, coeffs, row);
    if row.is_empty() {
        return;
    }
    // One pass over the row for all the parts (2 for Coons, up to 6 curves for Gordon).
    let parts = w.len();
    let whole = xs.len() >= parts * row.len();
    match parts {
        2 if whole => add_planes::<T, 2>(w, xs, row),
        3 if whole => add_planes::<T, 3>(w, xs, row),
        4 if whole => add_planes::<T, 4>(w, xs, row),
        5 if whole => add_planes::<T, 5>(w, xs, row),
        6 if whole => add_planes::<T, 6>(w, xs, row),
        _ => {
            for (wi, xi) in w.iter().zip(xs.chunks_exact(row.len())) {
                for (o, x) in row.iter_mut().zip(xi) {
                    *o = o.clone() + wi.clone() * x.clone();
                }
            }
        }
    }
}

/// `row[q] += Σ_i w[i] · xs[i·len + q]` (`i` ascending, `len = row.len()`), in one pass;
/// `xs` must hold `P` whole rows.
#[inline(always)]
fn add_planes<T: Scalar, const P: usize>(w: &[T], xs: &[T], row: &mut [T]) {
    let len = row.len();
    let w: [T; P] = std::array::from_fn(|i| w[i].clone());
    let planes: [&[T]; P] = std::array::from_fn(|i| &xs[i * len..(i + 1) * len]);
    for (q, o) in row.iter_mut().enumerate() {
        let mut acc = o.clone();
        for i in 0..P {
            acc = acc + w[i].clone() * planes[i][q].clone();
        }
        *o = acc;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_visited_once_in_order_both_sequentially_and_in_parallel() {
        for (rows, work) in [(7, 0), (1000, usize::MAX)] {
            let mut out = vec![0.0f64; rows * 3];
            for_each_row(
                "rows",
                &mut out,
                3,
                work,
                || 0usize,
                |seen, r, chunk| {
                    *seen += 1;
                    chunk.fill(r as f64);
                },
            )
            .unwrap();
            for (r, chunk) in out.chunks(3).enumerate() {
                let r = r as f64;
                assert_eq!(chunk, &[r, r, r]);
            }
        }
    }

    #[test]
    fn a_non_finite_value_written_is_reported_with_its_first_index() {
        for (rows, work) in [(7, 0), (1000, usize::MAX)] {
            let mut out = vec![0.0f64; rows * 3];
            let err = for_each_row(
                "rows",
                &mut out,
                3,
                work,
                || (),
                |_, r, chunk| {
                    if r >= 5 {
                        chunk[1] = f64::MAX * 2.0;
                    }
                },
            )
            .unwrap_err();
            assert_eq!(
                err,
                Error::Overflow {
                    what: "rows",
                    index: 16,
                    value: f64::INFINITY
                },
                "{rows} rows"
            );
            // The whole buffer is written all the same.
            assert!(out[3 * rows - 2].is_infinite());
        }
    }

    #[test]
    fn contraction_agrees_for_every_dimension() {
        // Two points, 1..8 terms, dimensions 1..6 (every fixed kernel and the general one).
        for terms in 1..=8 {
            for d in 1..=6 {
                let ws: Vec<f64> = (0..2 * terms).map(|q| 1.0 / (q + 1) as f64).collect();
                let coeffs: Vec<f64> = (0..terms * d).map(|q| q as f64 - 3.0).collect();
                let mut row = vec![f64::NAN; 2 * d];
                contract_row(&ws, terms, &coeffs, &mut row);
                for b in 0..2 {
                    for k in 0..d {
                        let expect = (0..terms)
                            .map(|j| ws[b * terms + j] * coeffs[j * d + k])
                            .fold(None, |acc: Option<f64>, x| Some(acc.map_or(x, |a| a + x)));
                        assert_eq!(Some(row[b * d + k]), expect, "terms {terms}, d = {d}");
                    }
                }
            }
        }
    }

    #[test]
    fn blended_rows_agree_for_every_size() {
        // Three points; sizes covering every fixed kernel and the general one.
        for (terms, parts) in [
            (2, 2),
            (3, 3),
            (4, 4),
            (5, 5),
            (2, 5),
            (6, 1),
            (1, 0),
            (7, 2),
        ] {
            for d in 1..=5 {
                let ws: Vec<f64> = (0..3 * terms).map(|q| 1.0 / (q + 2) as f64).collect();
                let coeffs: Vec<f64> = (0..terms * d).map(|q| q as f64 - 2.5).collect();
                let w: Vec<f64> = (0..parts).map(|i| 0.5 - i as f64).collect();
                // Planar: x_i[b] = xs[(i·3 + b)·d ..].
                let xs: Vec<f64> = (0..3 * parts * d).map(|q| (q % 7) as f64).collect();
                let mut row = vec![f64::NAN; 3 * d];
                blend_row(&ws, terms, &coeffs, &w, &xs, &mut row);
                for b in 0..3 {
                    for k in 0..d {
                        let mut sum = ws[b * terms] * coeffs[k];
                        for j in 1..terms {
                            sum += ws[b * terms + j] * coeffs[j * d + k];
                        }
                        for i in 0..parts {
                            sum += w[i] * xs[(i * 3 + b) * d + k];
                        }
                        assert_eq!(row[b * d + k], sum, "({terms}, {parts}) d = {d}");
                    }
                }
            }
        }
    }

    #[test]
    fn lengths_are_checked() {
        assert!(check_len("out", 3, &[0.0; 3]).is_ok());
        assert!(matches!(
            check_len("out", 3, &[0.0; 2]),
            Err(Error::ShapeMismatch { .. })
        ));
        assert!(grid_len("grid", &[usize::MAX, 2]).is_err());
        assert_eq!(grid_len("grid", &[4, 5, 3]).unwrap(), 60);
    }
}

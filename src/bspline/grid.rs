//! Batch evaluation of B-spline curves and tensor-product surfaces — and, in homogeneous
//! coordinates, of NURBS: the knot span and the `p + 1` non-zero basis values of each
//! parameter are computed once, then every point is a sum of `p + 1` (curves) or `q + 1`
//! (surface rows) terms, with no allocation per point.
//!
//! Layouts are those of [`crate::grid`]. As the per-point [`Curve::eval`](crate::Curve::eval)
//! and [`Surface::eval`](crate::Surface::eval) of these types do, outside the domain the first
//! or last polynomial piece continues and a NaN or infinite parameter gives a point of NaNs
//! (written `t − t`, NaN for both).

use super::basis::{basis_functions_into, last_span};
use crate::error::Result;
use crate::grid::{contract_row_planar, for_each_row, weighted_sum_into};
use crate::scalar::Scalar;

/// Points per block of a curve batch: one scratch (basis and triangle buffers) per block.
const BLOCK: usize = 256;

/// Locates parameters in the knot spans of a degree-`p` spline with `n` control points,
/// giving the span [`find_span`](super::find_span) gives. Consecutive parameters usually fall
/// in the same span or the next one, so the span found last is tried first (`O(1)` per
/// parameter for sorted parameters); otherwise a binary search over the knots.
pub(crate) struct SpanFinder<'a, T> {
    p: usize,
    n: usize,
    knots: &'a [T],
    lo: T,
    hi: T,
    end_span: usize,
}

impl<'a, T: Scalar> SpanFinder<'a, T> {
    /// For valid knots (`n + p + 1` of them, domain `[u_p, u_n]` not a single point).
    pub(crate) fn new(p: usize, n: usize, knots: &'a [T]) -> Self {
        SpanFinder {
            p,
            n,
            knots,
            lo: knots[p].clone(),
            hi: knots[n].clone(),
            end_span: last_span(p, n, knots),
        }
    }

    /// The degree `p`.
    pub(crate) fn degree(&self) -> usize {
        self.p
    }

    /// The span whose polynomial piece gives the point at `t` (the span
    /// [`extended_span`](super::basis::extended_span) gives: outside the domain the first or
    /// the last one), with `t`; `None` for NaN or ±∞. `hint` is the span found last and is
    /// updated.
    #[inline]
    pub(crate) fn locate(&self, t: &T, hint: &mut usize) -> Option<(usize, T)> {
        if !t.is_finite_value() {
            return None;
        }
        let s = if *t < self.lo {
            self.span(&self.lo, *hint)
        } else if *t > self.hi {
            self.end_span
        } else {
            self.span(t, *hint)
        };
        *hint = s;
        Some((s, t.clone()))
    }

    /// The span of `u ∈ [u_p, u_n]`.
    #[inline]
    fn span(&self, u: &T, hint: usize) -> usize {
        if *u == self.hi {
            return self.end_span;
        }
        // For u in [u_p, u_n) find_span's span is the s in [p, n − 1] with u_s ≤ u < u_{s+1}
        // (the largest s with u_s ≤ u).
        let k = self.knots;
        for s in [hint, hint + 1] {
            if s >= self.p && s < self.n && k[s] <= *u && *u < k[s + 1] {
                return s;
            }
        }
        let above = k[..=self.n].partition_point(|x| x <= u);
        (above - 1).clamp(self.p, self.n - 1)
    }
}

/// The spans and the non-zero basis values of all parameters `ts` (end pieces continued):
/// `rows[a·(p+1) ..][..p+1]` holds `N_{s−p,p}(t_a), …, N_{s,p}(t_a)` and `spans[a]` its span
/// `s` (`None`, and a row of zeros, for a NaN or infinite parameter). One allocation each, `O(len·p)`
/// memory, `O(p²)` operations per parameter.
pub(crate) fn basis_rows<T: Scalar>(
    f: &SpanFinder<'_, T>,
    ts: &[T],
) -> (Vec<T>, Vec<Option<usize>>) {
    let w = f.p + 1;
    let mut rows = vec![T::zero(); ts.len() * w];
    let mut spans = Vec::with_capacity(ts.len());
    let (mut left, mut right) = (vec![T::zero(); w], vec![T::zero(); w]);
    let mut hint = f.p;
    for (t, row) in ts.iter().zip(rows.chunks_exact_mut(w)) {
        spans.push(f.locate(t, &mut hint).map(|(s, u)| {
            basis_functions_into(f.p, f.knots, s, &u, row, &mut left, &mut right);
            s
        }));
    }
    (rows, spans)
}

/// [`basis_rows`] stored by term: entry `j` of the row of `ts[a]` at `j·ts.len() + a` (the
/// layout of [`contract_row_planar`]); a NaN parameter has a row of zeros.
pub(crate) fn planar_basis_rows<T: Scalar>(
    f: &SpanFinder<'_, T>,
    ts: &[T],
) -> (Vec<T>, Vec<Option<usize>>) {
    let w = f.p + 1;
    let n = ts.len();
    let mut planes = vec![T::zero(); n * w];
    let mut spans = Vec::with_capacity(n);
    let (mut row, mut left, mut right) =
        (vec![T::zero(); w], vec![T::zero(); w], vec![T::zero(); w]);
    let mut hint = f.p;
    for (a, t) in ts.iter().enumerate() {
        spans.push(f.locate(t, &mut hint).map(|(s, u)| {
            basis_functions_into(f.p, f.knots, s, &u, &mut row, &mut left, &mut right);
            for (j, x) in row.iter().enumerate() {
                planes[j * n + a] = x.clone();
            }
            s
        }));
    }
    (planes, spans)
}

/// Scratch of one block of curve points.
struct CurveScratch<T> {
    basis: Vec<T>,
    left: Vec<T>,
    right: Vec<T>,
    acc: Vec<T>,
    hint: usize,
}

/// The points of a degree-`p` spline curve at all parameters `ts` (end pieces continued; a
/// NaN or infinite parameter gives a point of NaNs), written into `out` one after the other.
///
/// `control` holds the `n` control points one after the other, `dh` numbers each (the
/// column-major storage of a `dh × n` matrix). Each point is `Σ_j N_{s−p+j,p}(t) P_{s−p+j}`,
/// `j` ascending from zero — the operations of `BSplineCurve::try_eval`, so the same values
/// bit for bit. With `project` the last coordinate is a weight and the point written is the
/// others divided by it (a NURBS curve in homogeneous form, as `NurbsCurve::try_eval`); each
/// point then takes `dh − 1` entries of `out`, else `dh`. `out.len()` must be `ts.len()` times
/// that.
///
/// `O(p² + p·dh)` per point, one scratch per block of [`BLOCK`] points; long batches run on
/// several threads.
pub(crate) fn curve_points_into<T: Scalar>(
    p: usize,
    knots: &[T],
    control: &[T],
    dh: usize,
    project: bool,
    ts: &[T],
    out: &mut [T],
) -> Result<()> {
    let n = control.len() / dh;
    let d = dh - usize::from(project);
    let finder = SpanFinder::new(p, n, knots);
    let work = ts.len().saturating_mul((p + 1) * (p + 1 + dh));
    let init = || CurveScratch {
        basis: vec![T::zero(); p + 1],
        left: vec![T::zero(); p + 1],
        right: vec![T::zero(); p + 1],
        acc: vec![T::zero(); dh],
        hint: p,
    };
    let point = |sc: &mut CurveScratch<T>, t: &T, x: &mut [T]| {
        let Some((s, u)) = finder.locate(t, &mut sc.hint) else {
            x.iter_mut().for_each(|o| *o = t.clone() - t.clone());
            return;
        };
        basis_functions_into(p, knots, s, &u, &mut sc.basis, &mut sc.left, &mut sc.right);
        let first = (s - p) * dh;
        let terms = &control[first..first + (p + 1) * dh];
        match dh {
            1 => sum_fixed::<T, 1>(&sc.basis, terms, project, x),
            2 => sum_fixed::<T, 2>(&sc.basis, terms, project, x),
            3 => sum_fixed::<T, 3>(&sc.basis, terms, project, x),
            4 => sum_fixed::<T, 4>(&sc.basis, terms, project, x),
            _ => {
                sc.acc.iter_mut().for_each(|a| *a = T::zero());
                for (w, c) in sc.basis.iter().zip(terms.chunks_exact(dh)) {
                    for (a, ck) in sc.acc.iter_mut().zip(c) {
                        *a = a.clone() + w.clone() * ck.clone();
                    }
                }
                finish(&sc.acc, project, x);
            }
        }
    };
    // Degrees 1…5 with up to 4 numbers per control point: basis, triangle and sums in arrays
    // of sizes fixed at compile time (registers, unrolled loops); the same operations.
    macro_rules! fixed {
        ($n:literal, $dh:literal) => {
            for_each_row(
                "spline curve points",
                out,
                BLOCK * d,
                work,
                || p,
                |hint, block, chunk| {
                    for (t, x) in ts[block * BLOCK..].iter().zip(chunk.chunks_exact_mut(d)) {
                        let Some((s, u)) = finder.locate(t, hint) else {
                            x.iter_mut().for_each(|o| *o = t.clone() - t.clone());
                            continue;
                        };
                        let n = basis_fixed::<T, $n>(knots, s, &u);
                        let first = (s - p) * $dh;
                        let terms = &control[first..first + $n * $dh];
                        sum_fixed::<T, $dh>(&n, terms, project, x);
                    }
                },
            )
        };
    }
    macro_rules! by_dim {
        ($n:literal) => {
            match dh {
                1 => fixed!($n, 1),
                2 => fixed!($n, 2),
                3 => fixed!($n, 3),
                _ => fixed!($n, 4),
            }
        };
    }
    match (p, dh) {
        (1, 1..=4) => by_dim!(2),
        (2, 1..=4) => by_dim!(3),
        (3, 1..=4) => by_dim!(4),
        (4, 1..=4) => by_dim!(5),
        (5, 1..=4) => by_dim!(6),
        _ => for_each_row(
            "spline curve points",
            out,
            BLOCK * d,
            work,
            init,
            |sc, block, chunk| {
                for (t, x) in ts[block * BLOCK..].iter().zip(chunk.chunks_exact_mut(d)) {
                    point(sc, t, x);
                }
            },
        ),
    }
}

/// The `N = p + 1` non-zero basis values on the span `span`: [`basis_functions_into`] with
/// every size fixed at compile time (the same operations, so the same values).
#[inline]
fn basis_fixed<T: Scalar, const N: usize>(knots: &[T], span: usize, u: &T) -> [T; N] {
    let p = N - 1;
    // knots[span + 1 − p ..= span + p]: left[j] = u − k[p − j], right[j] = k[p − 1 + j].
    let k = &knots[span + 1 - p..span + 1 + p];
    let mut n: [T; N] = std::array::from_fn(|_| T::zero());
    let left: [T; N] = std::array::from_fn(|j| {
        if j == 0 {
            T::zero()
        } else {
            u.clone() - k[p - j].clone()
        }
    });
    let right: [T; N] = std::array::from_fn(|j| {
        if j == 0 {
            T::zero()
        } else {
            k[p - 1 + j].clone() - u.clone()
        }
    });
    n[0] = T::one();
    for j in 1..N {
        let mut saved = T::zero();
        for r in 0..j {
            let temp = n[r].clone() / (right[r + 1].clone() + left[j - r].clone());
            n[r] = saved + right[r + 1].clone() * temp.clone();
            saved = left[j - r].clone() * temp;
        }
        n[j] = saved;
    }
    n
}

/// `Σ_j w[j] · c_j` (`D` coordinates each, sum from zero, `j` ascending), then
/// [`finish`]: the sums stay in registers.
#[inline]
fn sum_fixed<T: Scalar, const D: usize>(w: &[T], terms: &[T], project: bool, x: &mut [T]) {
    let mut acc: [T; D] = std::array::from_fn(|_| T::zero());
    for (wj, c) in w.iter().zip(terms.chunks_exact(D)) {
        for k in 0..D {
            acc[k] = acc[k].clone() + wj.clone() * c[k].clone();
        }
    }
    finish(&acc, project, x);
}

/// Writes the sum `acc` (or, with `project`, `acc[k] / acc[last]` for the other `k`) to `x`.
#[inline]
fn finish<T: Scalar>(acc: &[T], project: bool, x: &mut [T]) {
    if project {
        let (coords, w) = acc.split_at(acc.len() - 1);
        for (o, a) in x.iter_mut().zip(coords) {
            *o = a.clone() / w[0].clone();
        }
    } else {
        x.clone_from_slice(acc);
    }
}

/// A tensor-product spline surface in the form the grid evaluation reads it.
pub(crate) struct Net<'a, T> {
    /// Knot spans along `u` (degree `p`, `nu` control points).
    pub(crate) u: SpanFinder<'a, T>,
    /// Knot spans along `v` (degree `q`, `nv` control points).
    pub(crate) v: SpanFinder<'a, T>,
    /// The control points, `net[(i·nv + j)·dh + k]` coordinate `k` of `P_{i,j}`.
    pub(crate) net: Vec<T>,
    /// Numbers per control point.
    pub(crate) dh: usize,
    /// Whether the last coordinate is a weight to divide by (NURBS).
    pub(crate) project: bool,
}

/// The surface on the grid `us × vs` (end pieces continued; a NaN or infinite parameter
/// gives points of NaNs), written row by row into `out` (layout of [`crate::grid`], `dh − 1`
/// numbers per point with `project`, else `dh`; `out.len()` must match).
///
/// The basis rows of every `u` and every `v` are computed once (`O(N·(p+q))` memory for an
/// `N × N` grid). For the row of `u_a` (span `s`) the net is contracted with its `p + 1` basis
/// values, `c_j = Σ_i N_{s−p+i,p}(u_a) P_{s−p+i,j}` for all `j` — the control points of the
/// curve `v ↦ S(u_a, v)`, `(p+1)·nv·dh` operations per row — and then each point of the row is
/// `Σ_l N_{t−q+l,q}(v_b) c_{t−q+l}` ([`contract_row`] over runs of parameters in the same span
/// `t`): `(q+1)·dh` multiply-adds per point, `O(p + q)` per point overall. With `project` the
/// homogeneous row is then divided by its weights. Large grids run on several threads by rows.
///
/// The sums run along `u` first, where `BSplineSurface::try_eval` runs along `v` first: the
/// values agree with it to a few units of `(p + q) ε · max |P_{i,j}|`, and exactly for
/// rationals.
pub(crate) fn surface_grid_into<T: Scalar>(
    s: &Net<'_, T>,
    us: &[T],
    vs: &[T],
    out: &mut [T],
) -> Result<()> {
    let (p, q) = (s.u.degree(), s.v.degree());
    let dh = s.dh;
    let d = dh - usize::from(s.project);
    let nv = s.v.n;
    let (bu, su) = basis_rows(&s.u, us);
    let (bv, sv) = planar_basis_rows(&s.v, vs);
    let nvs = vs.len();
    // Runs of consecutive v in the same span (one run for each span a sorted grid crosses).
    let mut runs: Vec<(usize, usize, Option<usize>)> = Vec::new();
    for (b, span) in sv.iter().enumerate() {
        match runs.last_mut() {
            Some(run) if span.is_some() && run.2 == *span => run.1 = b + 1,
            _ => runs.push((b, b + 1, *span)),
        }
    }
    let fill = |coeffs: &[T], target: &mut [T]| {
        for &(b0, b1, span) in &runs {
            match span {
                Some(t) => contract_row_planar(
                    &bv,
                    nvs,
                    b0,
                    q + 1,
                    &coeffs[(t - q) * dh..(t + 1) * dh],
                    &mut target[b0 * dh..b1 * dh],
                ),
                None => {
                    for (x, v) in target[b0 * dh..b1 * dh].chunks_exact_mut(dh).zip(&vs[b0..]) {
                        x.iter_mut().for_each(|o| *o = v.clone() - v.clone());
                    }
                }
            }
        }
    };
    let no_nan_v = sv.iter().all(Option::is_some);
    let work = us.len().saturating_mul(
        vs.len()
            .saturating_mul((q + 1) * dh)
            .saturating_add((p + 1) * nv * dh),
    );
    let init = || {
        let homogeneous = if s.project { vs.len() * dh } else { 0 };
        (vec![T::zero(); nv * dh], vec![T::zero(); homogeneous])
    };
    // Without weights every point is a sum `Σ_ij N_i(u) N_j(v) P_ij`, bounded by
    // (p+1) max|N_i| · (q+1) max|N_j| · max|P_ij|: when that is finite no row is scanned
    // ([`crate::grid::bounded_by`]). Points of NURBS are divided by their weights: scanned.
    let bounded = T::EXACT
        || !s.project
            && no_nan_v
            && su.iter().all(Option::is_some)
            && crate::grid::bounded_by::<T>(
                crate::grid::max_abs(&bu)
                    * (p + 1) as f64
                    * crate::grid::max_abs(&bv)
                    * (q + 1) as f64,
                crate::grid::max_abs(&s.net),
            );
    crate::grid::for_each_bounded_row(
        "spline surface grid",
        out,
        vs.len() * d,
        work,
        init,
        |(coeffs, hrow), a, row| {
            let Some(span) = su[a] else {
                row.iter_mut()
                    .for_each(|o| *o = us[a].clone() - us[a].clone());
                return false;
            };
            let block = nv * dh;
            weighted_sum_into(
                &bu[a * (p + 1)..(a + 1) * (p + 1)],
                &s.net[(span - p) * block..(span + 1) * block],
                coeffs,
            );
            if !s.project {
                fill(coeffs, row);
            } else if (2..=4).contains(&dh) && no_nan_v {
                // Homogeneous sums kept in registers and projected at once, no second pass.
                for &(b0, b1, span) in &runs {
                    let t = span.unwrap_or(q);
                    let c = &coeffs[(t - q) * dh..];
                    let x = &mut row[b0 * d..b1 * d];
                    match dh {
                        2 => contract_project_row::<T, 2>(&bv, nvs, b0, q + 1, c, x),
                        3 => contract_project_row::<T, 3>(&bv, nvs, b0, q + 1, c, x),
                        _ => contract_project_row::<T, 4>(&bv, nvs, b0, q + 1, c, x),
                    }
                }
            } else {
                fill(coeffs, hrow);
                for (x, h) in row.chunks_exact_mut(d).zip(hrow.chunks_exact(dh)) {
                    finish(h, true, x);
                }
            }
            bounded
        },
    )
}

/// For every point of a run: the homogeneous sum `h = Σ_l w_b[l] · c_l` (`D` numbers,
/// [`contract_row_planar`]'s operations: from `w_b[0] · c_0`, `l` ascending; the weights
/// `w_b[l] = ws[l·stride + first + b]`), then `x_k = h_k · (1/h_{D−1})` into `row` (`D − 1`
/// numbers per point): one division per point, vectorised across points.
#[inline]
fn contract_project_row<T: Scalar, const D: usize>(
    ws: &[T],
    stride: usize,
    first: usize,
    terms: usize,
    coeffs: &[T],
    row: &mut [T],
) {
    T::vectorized(
        #[inline(always)]
        || match terms {
            2 => project_const::<T, 2, D>(ws, stride, first, coeffs, row),
            3 => project_const::<T, 3, D>(ws, stride, first, coeffs, row),
            4 => project_const::<T, 4, D>(ws, stride, first, coeffs, row),
            _ => {
                for (b, x) in row.chunks_exact_mut(D - 1).enumerate() {
                    let w = |l: usize| ws[l * stride + first + b].clone();
                    let mut acc: [T; D] = std::array::from_fn(|k| w(0) * coeffs[k].clone());
                    for l in 1..terms {
                        for k in 0..D {
                            acc[k] = acc[k].clone() + w(l) * coeffs[l * D + k].clone();
                        }
                    }
                    let r = T::one() / acc[D - 1].clone();
                    for k in 0..D - 1 {
                        x[k] = acc[k].clone() * r.clone();
                    }
                }
            }
        },
    );
}

/// [`contract_project_row`] with `L` terms fixed at compile time.
#[inline(always)]
fn project_const<T: Scalar, const L: usize, const D: usize>(
    ws: &[T],
    stride: usize,
    first: usize,
    coeffs: &[T],
    row: &mut [T],
) {
    let n = row.len() / (D - 1);
    let planes: [&[T]; L] = std::array::from_fn(|l| &ws[l * stride + first..][..n]);
    let c: [[T; D]; L] =
        std::array::from_fn(|l| std::array::from_fn(|k| coeffs[l * D + k].clone()));
    for (b, x) in row.chunks_exact_mut(D - 1).enumerate() {
        let mut acc: [T; D] = std::array::from_fn(|k| planes[0][b].clone() * c[0][k].clone());
        for l in 1..L {
            for k in 0..D {
                acc[k] = acc[k].clone() + planes[l][b].clone() * c[l][k].clone();
            }
        }
        let r = T::one() / acc[D - 1].clone();
        for k in 0..D - 1 {
            x[k] = acc[k].clone() * r.clone();
        }
    }
}

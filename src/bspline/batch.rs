//! The fast batch of B-spline and NURBS curves: the triangular scheme of
//! [`basis_functions`](super::basis_functions) with its divisions replaced by products with
//! reciprocals computed once per knot span, the parameters of a span evaluated
//! [`LANES`] at a time.
//!
//! On the span `s` the scheme divides by `N_r / (right_{r+1} + left_{j−r})`, where
//! `right_{r+1} + left_{j−r} = (u_{s+r+1} − u) + (u − u_{s+r+1−j})` is the knot difference
//! `u_{s+r+1} − u_{s+r+1−j}` computed through `u`. Here that difference is taken from the
//! knots, and its reciprocal `ρ_{j,r} = 1/(u_{s+r+1} − u_{s+r+1−j})` (positive: the span is not
//! empty) once per span:
//!
//! ```text
//! N_0 = 1;  for j = 1..p:  t_r = N_r ρ_{j,r},  N_r = s_{r} + right_{r+1} t_r,  s_{r+1} = left_{j−r} t_r,  N_j = s_j
//! C(u) = Σ_{i=0}^{p} N_i P_{s−p+i}    (NURBS: the homogeneous sum times 1/w)
//! ```
//!
//! (`s_0 = 0` is not added). No division per point (NURBS: one, the reciprocal of the
//! weight). The values differ from [`BSplineCurve::try_eval`](super::BSplineCurve::try_eval)
//! by rounding only, and every quantity of the scheme is non-negative, so relative errors add
//! up: each level of the triangle adds at most 6 roundings to every `N_i` (2 in `ρ`, 1 in
//! `u_{s+r+1} − u` or `u − u_{s+1−j}`, 2 products, 1 sum), the sum `p + 1` more, so with the
//! unit roundoff `ε/2`
//!
//! ```text
//! B-spline:  |C_batch(u) − C(u)| ≤ γ_{7p+1} Σ N_i |P_i| ≤ (4p + 1) ε · max_i |P_i|,
//! NURBS:     |C_batch(u) − C(u)| ≤ (γ_{7p+2} + γ_{7p+3}) max_k |P_k| ≤ (7p + 3) ε · max_k |P_k|
//! ```
//!
//! on the domain (NURBS: the numerator also carries the rounding of the stored `w_k P_k`, the
//! weight sum `γ_{7p+1}`, the reciprocal and the product one each; the rational basis is
//! non-negative, so the bound holds in the projected coordinates whatever the weights).
//! Beyond the domain the end piece continues and `u − u_{s+1−j}` or `u_{s+j} − u` changes
//! sign; the same roundings then give the B-spline bound `(4p + 1) ε · max_i |P_i| · Σ Ñ_i`,
//! `Ñ_i` the scheme run on the absolute values of those differences (1 on the domain). A NaN
//! or infinite parameter gives a point of NaNs, as `eval`. The values are exact for
//! rationals. The test `fast_curve_batches_are_within_the_bound_of_exact_rationals`
//! checks both bounds against exact rational arithmetic.
//!
//! The result at a parameter does not depend on the other parameters of the batch (the
//! four-lane and the one-point code do the same operations per point), nor on the threads.

use super::grid::SpanFinder;
use crate::error::Result;
use crate::grid::for_each_row;
use crate::scalar::Scalar;

/// Points per block of the row driver (one span state per block of blocks).
const BLOCK: usize = 1024;

/// The knots, reciprocals and control points of one span, degree `N − 1`, `DH` numbers per
/// control point.
struct Span<T, const N: usize, const DH: usize> {
    /// The span index (`usize::MAX`: none loaded yet).
    s: usize,
    /// `u_s` and `u_{s+1}`: parameters in `[lo, hi)` belong to the span.
    lo: T,
    hi: T,
    /// `kl[j] = u_{s+1−j}`, `kr[j] = u_{s+j}` (`j ≥ 1`).
    kl: [T; N],
    kr: [T; N],
    /// `inv[j][r] = 1/(u_{s+r+1} − u_{s+r+1−j})`, `r < j`.
    inv: [[T; N]; N],
    /// The control points `P_{s−p}, …, P_s`.
    c: [[T; DH]; N],
}

impl<T: Scalar, const N: usize, const DH: usize> Span<T, N, DH> {
    fn empty() -> Self {
        let z = || T::zero();
        Span {
            s: usize::MAX,
            // No parameter satisfies 1 ≤ u < 0.
            lo: T::one(),
            hi: T::zero(),
            kl: std::array::from_fn(|_| z()),
            kr: std::array::from_fn(|_| z()),
            inv: std::array::from_fn(|_| std::array::from_fn(|_| z())),
            c: std::array::from_fn(|_| std::array::from_fn(|_| z())),
        }
    }

    /// How many of `ts`, from the first, lie in `[lo, hi)` (NaN does not): eight at a time
    /// with comparisons that vectorise, then one by one.
    #[inline(always)]
    fn run_length(&self, ts: &[T]) -> usize {
        let inside = |u: &T| (self.lo <= *u) & (*u < self.hi);
        let mut len = 0;
        for c in ts.chunks_exact(8) {
            if !c.iter().fold(true, |all, u| all & inside(u)) {
                break;
            }
            len += 8;
        }
        len + ts[len..].iter().take_while(|u| inside(u)).count()
    }

    #[inline(never)]
    fn load(&mut self, s: usize, knots: &[T], control: &[T]) {
        let p = N - 1;
        self.s = s;
        self.lo = knots[s].clone();
        self.hi = knots[s + 1].clone();
        for j in 1..N {
            self.kl[j] = knots[s + 1 - j].clone();
            self.kr[j] = knots[s + j].clone();
            for r in 0..j {
                self.inv[j][r] =
                    T::one() / (knots[s + r + 1].clone() - knots[s + r + 1 - j].clone());
            }
        }
        for (i, ci) in self.c.iter_mut().enumerate() {
            for (k, x) in ci.iter_mut().enumerate() {
                *x = control[(s - p + i) * DH + k].clone();
            }
        }
    }
}

/// The point at a parameter `u` of the loaded span (`lo ≤ u ≤ hi`), written into `x`
/// (`DH` numbers, `DH − 1` with `PROJECT`).
// Index loops over arrays of compile-time sizes: with iterators (zip, skip) the compiler no
// longer vectorises the loop over points of `run` (four times the instructions).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
fn point<T: Scalar, const N: usize, const DH: usize, const PROJECT: bool>(
    sp: &Span<T, N, DH>,
    u: &T,
    x: &mut [T],
) {
    let left: [T; N] = std::array::from_fn(|j| u.clone() - sp.kl[j].clone());
    let right: [T; N] = std::array::from_fn(|j| sp.kr[j].clone() - u.clone());
    let mut n: [T; N] = std::array::from_fn(|_| T::one());
    for j in 1..N {
        let mut saved = T::zero();
        for r in 0..j {
            let t = n[r].clone() * sp.inv[j][r].clone();
            let a = right[r + 1].clone() * t.clone();
            n[r] = if r == 0 { a } else { saved + a };
            saved = left[j - r].clone() * t;
        }
        n[j] = saved;
    }
    let mut acc: [T; DH] = std::array::from_fn(|k| n[0].clone() * sp.c[0][k].clone());
    for i in 1..N {
        for k in 0..DH {
            acc[k] = acc[k].clone() + n[i].clone() * sp.c[i][k].clone();
        }
    }
    if PROJECT {
        let w = T::one() / acc[DH - 1].clone();
        for k in 0..DH - 1 {
            x[k] = acc[k].clone() * w.clone();
        }
    } else {
        x[..DH].clone_from_slice(&acc);
    }
}

/// [`point`] for a run of parameters of the loaded span: a loop without branches, which
/// the compiler vectorises across points.
#[inline(always)]
fn run<T: Scalar, const N: usize, const DH: usize, const PROJECT: bool>(
    sp: &Span<T, N, DH>,
    ts: &[T],
    out: &mut [T],
) {
    let d = DH - usize::from(PROJECT);
    for (u, x) in ts.iter().zip(out.chunks_exact_mut(d)) {
        point::<T, N, DH, PROJECT>(sp, u, x);
    }
}

/// Everything a block of points needs.
struct Curve<'a, T> {
    finder: SpanFinder<'a, T>,
    knots: &'a [T],
    control: &'a [T],
    project: bool,
    /// The domain `[u_p, u_n]`, on which the basis is positive and sums to 1.
    domain: (&'a T, &'a T),
    /// Whether a point on the domain is bounded by a finite number without weights
    /// ([`crate::grid::bounded_by`]): its blocks of points are then not scanned.
    small: bool,
}

impl<T: Scalar> Curve<'_, T> {
    /// Whether the points at `ts` are finite without looking at them: every parameter on the
    /// domain, no weights, control points below `f64::MAX / 4`.
    #[inline]
    fn bounded(&self, ts: &[T]) -> bool {
        T::EXACT || self.small && T::all_within(ts, self.domain.0, self.domain.1)
    }
}

impl<T: Scalar> Curve<'_, T> {
    /// The points of one block: the longest run of parameters in the loaded span at once
    /// ([`run`]); a parameter outside it is located (outside the domain in the end span, whose
    /// piece continues; NaN or ±∞ gives NaNs), its span
    /// loaded, and the next run starts there.
    #[inline(always)]
    fn block<const N: usize, const DH: usize, const PROJECT: bool>(
        &self,
        sp: &mut Span<T, N, DH>,
        hint: &mut usize,
        ts: &[T],
        out: &mut [T],
    ) {
        let d = DH - usize::from(PROJECT);
        let mut i = 0;
        while i < ts.len() {
            let len = sp.run_length(&ts[i..]);
            run::<T, N, DH, PROJECT>(sp, &ts[i..i + len], &mut out[i * d..(i + len) * d]);
            i += len;
            if i == ts.len() {
                break;
            }
            let (t, x) = (&ts[i], &mut out[i * d..(i + 1) * d]);
            match self.finder.locate(t, hint) {
                // NaN or ±∞: a point of NaNs, as `eval` gives.
                None => x.iter_mut().for_each(|o| *o = t.clone() - t.clone()),
                Some((s, u)) => {
                    if s != sp.s {
                        sp.load(s, self.knots, self.control);
                    }
                    point::<T, N, DH, PROJECT>(sp, &u, x);
                }
            }
            i += 1;
        }
    }

    /// All points, degree `N − 1`, `DH` numbers per control point.
    fn run<const N: usize, const DH: usize>(&self, ts: &[T], out: &mut [T]) -> Result<()> {
        let d = DH - usize::from(self.project);
        let work = ts.len().saturating_mul(N * (N + DH));
        crate::grid::for_each_bounded_row(
            "spline curve points",
            out,
            BLOCK * d,
            work,
            || (Span::<T, N, DH>::empty(), N - 1),
            |(sp, hint), block, chunk| {
                let ts = &ts[block * BLOCK..][..chunk.len() / d];
                if self.project {
                    T::vectorized(
                        #[inline(always)]
                        || self.block::<N, DH, true>(sp, hint, ts, chunk),
                    );
                } else {
                    T::vectorized(
                        #[inline(always)]
                        || self.block::<N, DH, false>(sp, hint, ts, chunk),
                    );
                }
                self.bounded(ts)
            },
        )
    }
}

/// The points of a degree-`p` spline curve at all parameters `ts` by the scheme of the
/// module docs (the end pieces continued outside the domain, as `eval` does; a NaN or
/// infinite parameter gives a point of NaNs), written into
/// `out` one after the other: the fast counterpart of
/// [`curve_points_into`](super::grid::curve_points_into), with the same arguments and
/// layout. Degrees 0…5 with up to 4 numbers per control point run four parameters at a
/// time in registers; the others one at a time with the same operations per point.
pub(crate) fn curve_points_fast_into<T: Scalar>(
    p: usize,
    knots: &[T],
    control: &[T],
    dh: usize,
    project: bool,
    ts: &[T],
    out: &mut [T],
) -> Result<()> {
    let n = control.len() / dh;
    let c = Curve {
        finder: SpanFinder::new(p, n, knots),
        knots,
        control,
        project,
        domain: (
            &knots[p.min(knots.len() - 1)],
            &knots[n.min(knots.len() - 1)],
        ),
        small: !T::EXACT
            && !project
            && crate::grid::bounded_by::<T>(1.0, crate::grid::max_abs(control)),
    };
    macro_rules! by_dim {
        ($n:literal) => {
            match dh {
                1 => c.run::<$n, 1>(ts, out),
                2 => c.run::<$n, 2>(ts, out),
                3 => c.run::<$n, 3>(ts, out),
                _ => c.run::<$n, 4>(ts, out),
            }
        };
    }
    match (p, dh) {
        (0, 1..=4) => by_dim!(1),
        (1, 1..=4) => by_dim!(2),
        (2, 1..=4) => by_dim!(3),
        (3, 1..=4) => by_dim!(4),
        (4, 1..=4) => by_dim!(5),
        (5, 1..=4) => by_dim!(6),
        _ => general(&c, p, dh, ts, out),
    }
}

/// [`curve_points_fast_into`] for any degree and dimension, one point at a time: the
/// operations of [`points`] with sizes known at run time.
fn general<T: Scalar>(
    c: &Curve<'_, T>,
    p: usize,
    dh: usize,
    ts: &[T],
    out: &mut [T],
) -> Result<()> {
    let d = dh - usize::from(c.project);
    let w = p + 1;
    let work = ts.len().saturating_mul(w * (w + dh));
    let init = || GeneralScratch {
        s: usize::MAX,
        hint: p,
        kl: vec![T::zero(); w],
        kr: vec![T::zero(); w],
        inv: vec![T::zero(); w * w],
        n: vec![T::zero(); w],
        left: vec![T::zero(); w],
        right: vec![T::zero(); w],
        acc: vec![T::zero(); dh],
    };
    for_each_row(
        "spline curve points",
        out,
        BLOCK * d,
        work,
        init,
        |sc, block, chunk| {
            for (t, x) in ts[block * BLOCK..].iter().zip(chunk.chunks_exact_mut(d)) {
                let Some((s, u)) = c.finder.locate(t, &mut sc.hint) else {
                    x.iter_mut().for_each(|o| *o = t.clone() - t.clone());
                    continue;
                };
                if s != sc.s {
                    sc.s = s;
                    for j in 1..w {
                        sc.kl[j] = c.knots[s + 1 - j].clone();
                        sc.kr[j] = c.knots[s + j].clone();
                        for r in 0..j {
                            sc.inv[j * w + r] = T::one()
                                / (c.knots[s + r + 1].clone() - c.knots[s + r + 1 - j].clone());
                        }
                    }
                }
                for j in 1..w {
                    sc.left[j] = u.clone() - sc.kl[j].clone();
                    sc.right[j] = sc.kr[j].clone() - u.clone();
                }
                sc.n[0] = T::one();
                for j in 1..w {
                    let mut saved = T::zero();
                    for r in 0..j {
                        let t = sc.n[r].clone() * sc.inv[j * w + r].clone();
                        let a = sc.right[r + 1].clone() * t.clone();
                        sc.n[r] = if r == 0 { a } else { saved + a };
                        saved = sc.left[j - r].clone() * t;
                    }
                    sc.n[j] = saved;
                }
                let terms = &c.control[(s - p) * dh..(s + 1) * dh];
                for (a, c0) in sc.acc.iter_mut().zip(terms) {
                    *a = sc.n[0].clone() * c0.clone();
                }
                for (ni, ci) in sc.n[1..].iter().zip(terms[dh..].chunks_exact(dh)) {
                    for (a, ck) in sc.acc.iter_mut().zip(ci) {
                        *a = a.clone() + ni.clone() * ck.clone();
                    }
                }
                if c.project {
                    let r = T::one() / sc.acc[dh - 1].clone();
                    for (o, a) in x.iter_mut().zip(&sc.acc) {
                        *o = a.clone() * r.clone();
                    }
                } else {
                    x.clone_from_slice(&sc.acc);
                }
            }
        },
    )
}

/// Scratch of [`general`]: the loaded span's knots and reciprocals, the triangle, the sums.
struct GeneralScratch<T> {
    s: usize,
    hint: usize,
    kl: Vec<T>,
    kr: Vec<T>,
    inv: Vec<T>,
    n: Vec<T>,
    left: Vec<T>,
    right: Vec<T>,
    acc: Vec<T>,
}

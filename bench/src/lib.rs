//! Fixtures shared by the cagd benchmarks (`benches/`) and the timing binary used by
//! `compare_octave.sh`: the test geometry (the same numbers the Octave side builds), a
//! hand-specialised `f64` kernel to compare the generic code against, and the accuracy study
//! of de Casteljau vs. the monomial (matrix) form.
//!
//! The geometry is defined by closed formulas so that `compare_octave.sh` can build exactly
//! the same control points in Octave:
//! - patch of degree `(m, n)`: `b_{i,j} = (i/m, j/n, ((7i + 3j) mod 5)/4 − 1/2)` (with `i/0 = 0`);
//! - cubic curve: control points `(0,0,0), (1,2,1), (3,−1,2), (4,1,0)`.

use cagd::bernstein::bernstein_all;
use cagd::bezier::{BezierCurve, BezierPatch, Edge};
use cagd::coons::CoonsPatch;
use cagd::gordon::GordonSurface;
use cagd::Scalar;
use nalgebra::DMatrix;
use num_rational::BigRational;

/// The patch of degree `(m, n)` of the module docs (3-D).
pub fn patch(m: usize, n: usize) -> BezierPatch {
    let frac = |i: usize, k: usize| if k == 0 { 0.0 } else { i as f64 / k as f64 };
    let coords = vec![
        DMatrix::from_fn(m + 1, n + 1, |i, _| frac(i, m)),
        DMatrix::from_fn(m + 1, n + 1, |_, j| frac(j, n)),
        DMatrix::from_fn(m + 1, n + 1, |i, j| {
            ((7 * i + 3 * j) % 5) as f64 / 4.0 - 0.5
        }),
    ];
    BezierPatch::new(coords).expect("valid net")
}

/// The cubic 3-D curve of the module docs.
pub fn cubic_curve() -> BezierCurve {
    BezierCurve::from_points(&[
        [0.0, 0.0, 0.0],
        [1.0, 2.0, 1.0],
        [3.0, -1.0, 2.0],
        [4.0, 1.0, 0.0],
    ])
    .expect("valid control points")
}

/// The Bézier curve of degree `n` through `n + 1` control points on a 3-D spiral.
pub fn curve_of_degree(n: usize) -> BezierCurve {
    let control = DMatrix::from_fn(3, n + 1, |k, i| {
        let a = i as f64 * 0.7;
        [a.cos(), a.sin(), i as f64 / (n.max(1)) as f64][k]
    });
    BezierCurve::new(control).expect("valid control points")
}

/// The bilinear Coons patch of the four boundary curves of `p` (Bézier curves).
pub fn coons_of(p: &BezierPatch) -> CoonsPatch<BezierCurve> {
    CoonsPatch::new(
        p.boundary(Edge::V0),
        p.boundary(Edge::V1),
        p.boundary(Edge::U0),
        p.boundary(Edge::U1),
    )
    .expect("the boundary of a patch is compatible")
}

/// The curve `v ↦ x(u0, v)` of a patch as a Bézier curve.
pub fn curve_at_u(p: &BezierPatch, u0: f64) -> BezierCurve {
    let (m, n) = p.degree();
    let w = bernstein_all(m, u0);
    BezierCurve::new(DMatrix::from_fn(p.dim(), n + 1, |k, j| {
        (0..=m).map(|i| w[i] * p.coordinates()[k][(i, j)]).sum()
    }))
    .expect("valid control points")
}

/// The curve `u ↦ x(u, v0)` of a patch as a Bézier curve.
pub fn curve_at_v(p: &BezierPatch, v0: f64) -> BezierCurve {
    let (m, n) = p.degree();
    let w = bernstein_all(n, v0);
    BezierCurve::new(DMatrix::from_fn(p.dim(), m + 1, |k, i| {
        (0..=n).map(|j| w[j] * p.coordinates()[k][(i, j)]).sum()
    }))
    .expect("valid control points")
}

/// The nodes `0, 1/4, 1/2, 3/4, 1` of the Gordon network.
pub fn gordon_nodes() -> Vec<f64> {
    (0..5).map(|i| i as f64 / 4.0).collect()
}

/// The Gordon surface of the 5 × 5 network of isoparametric curves of `p` (cubic Bézier
/// curves for a bicubic `p`) at [`gordon_nodes`].
pub fn gordon_of(p: &BezierPatch) -> GordonSurface<BezierCurve> {
    let nodes = gordon_nodes();
    GordonSurface::new(
        nodes.clone(),
        nodes.clone(),
        nodes.iter().map(|&u| curve_at_u(p, u)).collect(),
        nodes.iter().map(|&v| curve_at_v(p, v)).collect(),
    )
    .expect("the isoparametric curves of a patch form a compatible network")
}

/// `f(u, v)` at every point of `us × vs` written into `out` ((nu, nv, 3) row-major), one
/// point at a time: the per-point baseline.
pub fn per_point_grid(
    us: &[f64],
    vs: &[f64],
    out: &mut [f64],
    mut f: impl FnMut(f64, f64) -> [f64; 3],
) {
    let mut points = out.chunks_exact_mut(3);
    for &u in us {
        for &v in vs {
            if let Some(p) = points.next() {
                p.copy_from_slice(&f(u, v));
            }
        }
    }
}

/// The cubic Bernstein basis at `t`, written out.
#[inline(always)]
fn cubic_basis(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

/// A hand-specialised bicubic grid kernel in plain `f64`: fixed-size arrays, the same
/// algorithm as `BezierPatch::eval_grid_into` (u-contraction per row, then 4 terms per point),
/// the same rayon split over rows, the same run-time choice of vector instructions
/// ([`f64::vectorized`]). `net[i][j]` is `b_{i,j}`; `out` is (nu, nv, 3) row-major.
pub fn hand_bicubic_grid(net: &[[[f64; 3]; 4]; 4], us: &[f64], vs: &[f64], out: &mut [f64]) {
    use rayon::prelude::*;
    let bv: Vec<[f64; 4]> = vs.iter().map(|&v| cubic_basis(v)).collect();
    let row_len = vs.len() * 3;
    out.par_chunks_mut(row_len)
        .zip(us.par_iter())
        .with_min_len(16)
        .for_each(|(row, &u)| {
            f64::vectorized(|| {
                let wu = cubic_basis(u);
                let mut c = [[0.0; 3]; 4];
                for (j, cj) in c.iter_mut().enumerate() {
                    for (k, x) in cj.iter_mut().enumerate() {
                        *x = wu[0] * net[0][j][k]
                            + wu[1] * net[1][j][k]
                            + wu[2] * net[2][j][k]
                            + wu[3] * net[3][j][k];
                    }
                }
                for (p, w) in row.chunks_exact_mut(3).zip(&bv) {
                    for k in 0..3 {
                        p[k] = w[0] * c[0][k] + w[1] * c[1][k] + w[2] * c[2][k] + w[3] * c[3][k];
                    }
                }
            })
        });
}

/// A hand-specialised cubic 3-D curve kernel in plain `f64` (`ctrl[i]` = `b_i`, `out` is
/// (k, 3) row-major), split over threads like the library, in the same run-time choice of
/// vector instructions ([`f64::vectorized`]).
pub fn hand_cubic_curve(ctrl: &[[f64; 3]; 4], ts: &[f64], out: &mut [f64]) {
    use rayon::prelude::*;
    out.par_chunks_mut(3 * 4096)
        .zip(ts.par_chunks(4096))
        .for_each(|(chunk, ts)| {
            f64::vectorized(|| {
                for (p, &t) in chunk.chunks_exact_mut(3).zip(ts) {
                    let w = cubic_basis(t);
                    for k in 0..3 {
                        p[k] = w[0] * ctrl[0][k]
                            + w[1] * ctrl[1][k]
                            + w[2] * ctrl[2][k]
                            + w[3] * ctrl[3][k];
                    }
                }
            })
        });
}

/// The control net of a bicubic patch as fixed-size arrays, `net[i][j] = b_{i,j}`.
pub fn bicubic_net(p: &BezierPatch) -> [[[f64; 3]; 4]; 4] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| std::array::from_fn(|k| p.coordinates()[k][(i, j)]))
    })
}

/// The control points of a cubic curve as fixed-size arrays.
pub fn cubic_control(c: &BezierCurve) -> [[f64; 3]; 4] {
    std::array::from_fn(|i| std::array::from_fn(|k| c.control()[(k, i)]))
}

/// One line of the accuracy study: the largest error of each evaluation method over random
/// curves and parameters, against exact rational arithmetic, relative to the largest
/// control coordinate (which is 1).
#[derive(Debug, Clone, Copy)]
pub struct AccuracyRow {
    /// The degree.
    pub degree: usize,
    /// De Casteljau in `f64` ([`BezierCurve::eval`]).
    pub de_casteljau: f64,
    /// The Bernstein sum of the grid path ([`BezierCurve::eval_many_into`]).
    pub basis_rows: f64,
    /// The monomial (matrix) form in `f64` ([`BezierCurve::matrix_form`]).
    pub monomial: f64,
}

/// Max errors of de Casteljau, the basis-row path and the monomial form at each degree:
/// `curves` random curves (1-D, control values uniform in `[−1, 1]`, one of them set to ±1),
/// `params` parameters in `[0, 1]` each (including 0 and 1), the exact value from de Casteljau
/// in `BigRational` at the same double parameter.
pub fn accuracy_study(degrees: &[usize], curves: usize, params: usize) -> Vec<AccuracyRow> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let lift = |x: f64| <BigRational as Scalar>::from_f64(x).expect("finite");
    degrees
        .iter()
        .map(|&n| {
            let mut row = AccuracyRow {
                degree: n,
                de_casteljau: 0.0,
                basis_rows: 0.0,
                monomial: 0.0,
            };
            for c in 0..curves {
                let mut values: Vec<f64> = (0..=n).map(|_| 2.0 * next() - 1.0).collect();
                values[c % (n + 1)] = if c % 2 == 0 { 1.0 } else { -1.0 };
                let curve =
                    BezierCurve::new(DMatrix::from_row_slice(1, n + 1, &values)).expect("valid");
                let exact = BezierCurve::new(DMatrix::from_row_slice(
                    1,
                    n + 1,
                    &values.iter().map(|&x| lift(x)).collect::<Vec<_>>(),
                ))
                .expect("valid");
                let form = curve
                    .matrix_form()
                    .expect("degrees up to 40 stay within the range of doubles");
                let ts: Vec<f64> = (0..params)
                    .map(|k| match k {
                        0 => 0.0,
                        1 => 1.0,
                        _ => next(),
                    })
                    .collect();
                let mut batch = vec![0.0; ts.len()];
                curve.eval_many_into(&ts, &mut batch).expect("sizes match");
                for (&t, &b) in ts.iter().zip(&batch) {
                    let truth = exact.eval(lift(t))[0].to_f64();
                    row.de_casteljau = row.de_casteljau.max((curve.eval(t)[0] - truth).abs());
                    row.basis_rows = row.basis_rows.max((b - truth).abs());
                    row.monomial = row.monomial.max((form.eval(t)[0] - truth).abs());
                }
            }
            row
        })
        .collect()
}

/// The B-spline surface of degree `(p, p)` over the `n × n` net
/// `P_{i,j} = (i/(n−1), j/(n−1), ((7i + 3j) mod 5)/4 − 1/2)` (the formula of [`patch`] on a
/// larger net) with clamped uniform knots on `[0, 1]` in both directions (for `p = 3`,
/// `n = 10`: `0 0 0 0 1/7 … 6/7 1 1 1 1`, what `compare_octave.sh` builds for `nrbeval`).
pub fn bspline_surface(p: usize, n: usize) -> cagd::bspline::BSplineSurface {
    let knots = cagd::bspline::KnotVector::<f64>::clamped_uniform(p, n)
        .expect("n ≥ p + 1")
        .as_slice()
        .to_vec();
    let f = |i: usize| i as f64 / (n - 1) as f64;
    let coords = vec![
        DMatrix::from_fn(n, n, |i, _| f(i)),
        DMatrix::from_fn(n, n, |_, j| f(j)),
        DMatrix::from_fn(n, n, |i, j| ((7 * i + 3 * j) % 5) as f64 / 4.0 - 0.5),
    ];
    cagd::bspline::BSplineSurface::new(p, p, knots.clone(), knots, coords).expect("valid surface")
}

/// The cubic 3-D B-spline curve with 10 control points on a spiral (the points of
/// [`curve_of_degree`]`(9)`), clamped uniform knots on `[0, 1]` (7 spans).
pub fn bspline_cubic_curve() -> cagd::bspline::BSplineCurve {
    let control = DMatrix::from_fn(3, 10, |k, i| {
        let a = i as f64 * 0.7;
        [a.cos(), a.sin(), i as f64 / 9.0][k]
    });
    cagd::bspline::BSplineCurve::clamped(3, control).expect("valid curve")
}

/// The NURBS curve of [`bspline_cubic_curve`]'s control points with weights
/// `1 + (i mod 4)/3`.
pub fn nurbs_cubic_curve() -> cagd::nurbs::NurbsCurve {
    let b = bspline_cubic_curve();
    let w: Vec<f64> = (0..10).map(|i| 1.0 + (i % 4) as f64 / 3.0).collect();
    cagd::nurbs::NurbsCurve::new(3, b.knots().as_slice().to_vec(), b.control().clone(), w)
        .expect("valid curve")
}

/// The NURBS surface of [`bspline_surface`]`(p, n)`'s net with weights
/// `1 + ((i + 2j) mod 4)/3`.
pub fn nurbs_surface(p: usize, n: usize) -> cagd::nurbs::NurbsSurface {
    let b = bspline_surface(p, n);
    let w = DMatrix::from_fn(n, n, |i, j| 1.0 + ((i + 2 * j) % 4) as f64 / 3.0);
    let (ku, kv) = b.knots();
    cagd::nurbs::NurbsSurface::new(
        p,
        p,
        ku.as_slice().to_vec(),
        kv.as_slice().to_vec(),
        b.coordinates().to_vec(),
        w,
    )
    .expect("valid surface")
}

/// The arithmetic floor: `MULS` multiplications and `ADDS` additions for each of `points`
/// points, at the machine's vector width (four points per AVX2 vector, in the code
/// [`f64::vectorized`] chooses), spread over twelve independent chains so that the
/// multipliers and adders stay busy, with no memory traffic. Its time is the least any kernel
/// doing those operations per point can take on one core. Returns a value that depends on
/// every operation (so that none is optimised away).
pub fn arithmetic_floor<const MULS: usize, const ADDS: usize>(points: usize) -> f64 {
    f64::vectorized(
        #[inline(always)]
        || {
            let x = std::hint::black_box(0.999_999_999_f64);
            let y = std::hint::black_box(1e-12_f64);
            let mut acc = [[1.0f64; 4]; 12];
            for _ in 0..points.div_ceil(4) {
                for i in 0..MULS.max(ADDS) {
                    let c = &mut acc[i % 12];
                    if i < MULS {
                        for v in c.iter_mut() {
                            *v *= x;
                        }
                    }
                    if i < ADDS {
                        for v in c.iter_mut() {
                            *v += y;
                        }
                    }
                }
            }
            acc.iter().flatten().sum()
        },
    )
}

/// [`arithmetic_floor`] on all threads of the current rayon pool (the points split evenly).
pub fn arithmetic_floor_all<const MULS: usize, const ADDS: usize>(points: usize) -> f64 {
    use rayon::prelude::*;
    let threads = rayon::current_num_threads();
    (0..threads)
        .into_par_iter()
        .map(|_| arithmetic_floor::<MULS, ADDS>(points.div_ceil(threads)))
        .sum()
}

/// The memory floor: the buffer written once (`slice::fill`, which the C library does with
/// streaming or `rep stos` stores that need not read the lines first), on the current thread.
pub fn fill_floor(out: &mut [f64]) {
    std::hint::black_box(out).fill(std::hint::black_box(0.5));
}

/// [`fill_floor`] on all threads of the current rayon pool (a few blocks per thread).
pub fn fill_floor_all(out: &mut [f64]) {
    use rayon::prelude::*;
    let block = out.len().div_ceil(4 * rayon::current_num_threads()).max(1);
    std::hint::black_box(out)
        .par_chunks_mut(block)
        .for_each(|c| c.fill(std::hint::black_box(0.5)));
}

/// The buffer written once with ordinary vector stores (a pattern of twelve values that the
/// compiler cannot turn into `memset`): the stores a kernel in safe Rust makes, which read
/// each cache line before writing it. For comparison with [`fill_floor`].
pub fn store_floor(out: &mut [f64]) {
    let pattern: [f64; 12] = std::hint::black_box(std::array::from_fn(|k| k as f64));
    f64::vectorized(
        #[inline(always)]
        || {
            let out = std::hint::black_box(out);
            let mut chunks = out.chunks_exact_mut(12);
            for c in &mut chunks {
                c.copy_from_slice(&pattern);
            }
            for (o, p) in chunks.into_remainder().iter_mut().zip(pattern) {
                *o = p;
            }
        },
    )
}

/// [`store_floor`] on all threads of the current rayon pool.
pub fn store_floor_all(out: &mut [f64]) {
    use rayon::prelude::*;
    let block = out
        .len()
        .div_ceil(4 * rayon::current_num_threads())
        .div_ceil(12)
        * 12;
    out.par_chunks_mut(block.max(12)).for_each(store_floor);
}

/// The per-point operations of cagd's kernels (multiplications, additions and subtractions),
/// counted from their inner loops, for [`arithmetic_floor`].
pub mod ops {
    /// Bicubic patch grid, 3-D: `Σ_j B_j^3(v) c_j`, 4 terms × 3 coordinates (the row's
    /// `c_j` cost 48 multiply-adds per row of 1000 points, left out).
    pub const BICUBIC: (usize, usize) = (12, 9);
    /// Cubic 3-D curve: the basis as products (`t², t³, s = 1 − t, s², s³` and the four
    /// binomial products: 10 multiplications, 1 subtraction), then 4 terms × 3 coordinates.
    pub const CUBIC_CURVE: (usize, usize) = (22, 10);
}

/// One line of the accuracy study of the B-spline and NURBS curve batches.
#[derive(Debug, Clone, Copy)]
pub struct SplineAccuracyRow {
    /// The degree.
    pub degree: usize,
    /// The fast batch of B-spline curves (`eval_many_into`), in units of `ε · max |P_i|`.
    pub bspline_fast: f64,
    /// The exact-order batch of B-spline curves (`eval_many_exact_order_into`, the values of
    /// `try_eval`), in the same units.
    pub bspline_exact_order: f64,
    /// The fast batch of NURBS curves, in units of `ε · max |P_k|`.
    pub nurbs_fast: f64,
    /// The exact-order batch of NURBS curves.
    pub nurbs_exact_order: f64,
}

/// The largest errors of the B-spline and NURBS curve batches against exact rational
/// arithmetic at the same double parameter, in units of `ε · max |P|`: `curves` random 3-D
/// curves per degree (10 + degree control points in `[−1, 1]³`, clamped knots with random
/// interior knots, weights in `[1/4, 4]`), `params` random parameters each.
pub fn spline_accuracy_study(
    degrees: &[usize],
    curves: usize,
    params: usize,
) -> Vec<SplineAccuracyRow> {
    use cagd::bspline::BSplineCurve;
    use cagd::nurbs::NurbsCurve;
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let lift = |x: f64| <BigRational as Scalar>::from_f64(x).expect("finite");
    let lift_all = |v: &[f64]| v.iter().map(|&x| lift(x)).collect::<Vec<_>>();
    degrees
        .iter()
        .map(|&p| {
            let mut row = SplineAccuracyRow {
                degree: p,
                bspline_fast: 0.0,
                bspline_exact_order: 0.0,
                nurbs_fast: 0.0,
                nurbs_exact_order: 0.0,
            };
            for _ in 0..curves {
                let n = 10 + p;
                let mut inner: Vec<f64> = (0..n - p - 1).map(|_| next()).collect();
                inner.sort_by(f64::total_cmp);
                let mut knots = vec![0.0; p + 1];
                knots.extend(inner);
                knots.extend(vec![1.0; p + 1]);
                let control: Vec<f64> = (0..3 * n).map(|_| 2.0 * next() - 1.0).collect();
                let scale = control.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                let weights: Vec<f64> = (0..n).map(|_| 0.25 + 3.75 * next()).collect();
                let m = DMatrix::from_column_slice(3, n, &control);
                let c = BSplineCurve::new(p, knots.clone(), m.clone()).expect("valid");
                let r = NurbsCurve::new(p, knots.clone(), m, weights.clone()).expect("valid");
                let mq = DMatrix::from_column_slice(3, n, &lift_all(&control));
                let cq = BSplineCurve::new(p, lift_all(&knots), mq.clone()).expect("valid");
                let rq =
                    NurbsCurve::new(p, lift_all(&knots), mq, lift_all(&weights)).expect("valid");
                let ts: Vec<f64> = (0..params).map(|_| next()).collect();
                let mut fast = vec![0.0; 3 * params];
                let mut exact_order = vec![0.0; 3 * params];
                let worst =
                    |fast: &[f64],
                     exact_order: &[f64],
                     eval: &dyn Fn(BigRational) -> Vec<BigRational>| {
                        let (mut a, mut b) = (0.0f64, 0.0f64);
                        for (k, &t) in ts.iter().enumerate() {
                            let e = eval(lift(t));
                            for j in 0..3 {
                                let err = |x: f64| {
                                    (lift(x) - e[j].clone()).to_f64().abs() / (f64::EPSILON * scale)
                                };
                                a = a.max(err(fast[3 * k + j]));
                                b = b.max(err(exact_order[3 * k + j]));
                            }
                        }
                        (a, b)
                    };
                c.eval_many_into(&ts, &mut fast).expect("sizes");
                c.eval_many_exact_order_into(&ts, &mut exact_order)
                    .expect("sizes");
                let (a, b) = worst(&fast, &exact_order, &|t| {
                    cq.try_eval(t).expect("in domain").as_slice().to_vec()
                });
                row.bspline_fast = row.bspline_fast.max(a);
                row.bspline_exact_order = row.bspline_exact_order.max(b);
                r.eval_many_into(&ts, &mut fast).expect("sizes");
                r.eval_many_exact_order_into(&ts, &mut exact_order)
                    .expect("sizes");
                let (a, b) = worst(&fast, &exact_order, &|t| {
                    rq.try_eval(t).expect("in domain").as_slice().to_vec()
                });
                row.nurbs_fast = row.nurbs_fast.max(a);
                row.nurbs_exact_order = row.nurbs_exact_order.max(b);
            }
            row
        })
        .collect()
}

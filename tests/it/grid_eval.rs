//! Evaluation into caller-given buffers (`eval_many_into`, `eval_grid_into`): the fast grid
//! paths agree with per-point de Casteljau (to a few units of ε times the size of the control
//! net in `f64`, exactly in rationals), on both the sequential and the multi-threaded path.

use cagd::bernstein::bernstein_all;
use cagd::bezier::{BezierCurve, BezierPatch};
use cagd::coons::{CoonsPatch, GeneralizedCoonsPatch};
use cagd::gordon::GordonSurface;
use cagd::{Curve, Error, FnCurve, Scalar, Surface};
use nalgebra::{dvector, DMatrix, DVector};
use num_rational::BigRational as Q;

use cagd_test_support as common;
use common::lcg::Lcg;

fn q(n: i64, d: i64) -> Q {
    <Q as Scalar>::from_ratio(n, d)
}

fn random_patch(rng: &mut Lcg, m: usize, n: usize, d: usize) -> BezierPatch {
    let coords = (0..d)
        .map(|_| DMatrix::from_fn(m + 1, n + 1, |_, _| rng.signed()))
        .collect();
    BezierPatch::new(coords).unwrap()
}

fn rational_patch(m: usize, n: usize) -> BezierPatch<Q> {
    let coords = (0..3)
        .map(|k| {
            DMatrix::from_fn(m + 1, n + 1, |i, j| {
                q(((i * 7 + j * 3 + k * 5) % 11) as i64 - 5, 1 + k as i64)
            })
        })
        .collect();
    BezierPatch::new(coords).unwrap()
}

/// The largest |coordinate| of the control net.
fn net_size(p: &BezierPatch) -> f64 {
    p.coordinates().iter().map(|x| x.amax()).fold(0.0, f64::max)
}

/// Checks `out` (layout (nu, nv, d)) against `eval` at every point, within
/// `factor · ε · scale`; returns the worst error in units of `ε · scale`.
fn check_grid_against<S: Surface>(
    s: &S,
    us: &[f64],
    vs: &[f64],
    out: &[f64],
    scale: f64,
    factor: f64,
) -> f64 {
    let d = s.dim();
    let mut worst: f64 = 0.0;
    for (a, u) in us.iter().enumerate() {
        for (b, v) in vs.iter().enumerate() {
            let x = s.eval(*u, *v);
            for k in 0..d {
                let err = (out[(a * vs.len() + b) * d + k] - x[k]).abs() / (f64::EPSILON * scale);
                worst = worst.max(err);
                assert!(
                    err <= factor,
                    "point ({u}, {v}) coordinate {k}: {} vs {} ({err:.1} ε·scale)",
                    out[(a * vs.len() + b) * d + k],
                    x[k]
                );
            }
        }
    }
    worst
}

#[test]
fn patch_grid_agrees_with_de_casteljau_up_to_degree_20() {
    let mut rng = Lcg(7);
    for (m, n) in [
        (0, 0),
        (0, 5),
        (5, 0),
        (1, 1),
        (1, 4),
        (3, 3),
        (2, 7),
        (10, 10),
        (15, 4),
        (20, 20),
    ] {
        for d in [1, 3, 5] {
            let p = random_patch(&mut rng, m, n, d);
            let (us, vs) = (rng.params(9), rng.params(11));
            let mut out = vec![f64::NAN; us.len() * vs.len() * d];
            p.eval_grid_into(&us, &vs, &mut out).unwrap();
            // Both sums run over non-negative weights adding up to one: the error is a few
            // (m + n) ε times the largest control coordinate.
            let bound = 2.0 * (m + n + 2) as f64;
            let worst = check_grid_against(&p, &us, &vs, &out, net_size(&p), bound);
            assert!(worst <= bound, "({m},{n}) d={d}: {worst}");
            // The Array3 path is the same computation, bit for bit.
            let grid = p.try_eval_grid(&us, &vs).unwrap();
            assert_eq!(grid.as_slice(), &out[..]);
        }
    }
}

#[test]
fn patch_grid_is_exact_in_rationals() {
    for (m, n) in [(0, 0), (0, 3), (3, 0), (1, 4), (3, 3), (5, 2), (6, 6)] {
        let p = rational_patch(m, n);
        let us = [q(0, 1), q(1, 3), q(3, 4), q(1, 1), q(-1, 2)];
        let vs = [q(1, 5), q(1, 2), q(7, 5)];
        let mut out = vec![q(0, 1); us.len() * vs.len() * 3];
        p.eval_grid_into(&us, &vs, &mut out).unwrap();
        for (a, u) in us.iter().enumerate() {
            for (b, v) in vs.iter().enumerate() {
                let x = p.eval(u.clone(), v.clone());
                assert_eq!(
                    &out[(a * vs.len() + b) * 3..][..3],
                    x.as_slice(),
                    "({m},{n})"
                );
            }
        }
    }
}

#[test]
fn large_grids_split_over_threads_give_the_rows_of_small_grids() {
    // 400 × 300 bicubic: well above the parallel threshold.
    let mut rng = Lcg(11);
    let p = random_patch(&mut rng, 3, 3, 3);
    let (us, vs) = (rng.params(400), rng.params(300));
    let mut out = vec![0.0; 400 * 300 * 3];
    p.eval_grid_into(&us, &vs, &mut out).unwrap();
    for a in [0, 1, 137, 398, 399] {
        let mut row = vec![0.0; 300 * 3];
        p.eval_grid_into(&us[a..a + 1], &vs, &mut row).unwrap();
        assert_eq!(&out[a * 900..(a + 1) * 900], &row[..], "row {a}");
    }
    let sub: Vec<f64> = us.iter().step_by(37).copied().collect();
    let mut small = vec![0.0; sub.len() * 300 * 3];
    p.eval_grid_into(&sub, &vs, &mut small).unwrap();
    check_grid_against(&p, &sub, &vs, &small, net_size(&p), 16.0);
}

#[test]
fn grid_buffers_of_the_wrong_length_are_errors() {
    let p: BezierPatch = BezierPatch::hyperbolic_paraboloid();
    for len in [0, 5, 7] {
        let mut out = vec![0.0; len];
        assert!(matches!(
            p.eval_grid_into(&[0.0, 1.0], &[0.5], &mut out),
            Err(Error::ShapeMismatch { .. })
        ));
    }
    // Empty grids need an empty buffer.
    assert!(p.eval_grid_into(&[], &[0.5], &mut []).is_ok());
    let c = p.boundary(cagd::Edge::U0);
    assert!(matches!(
        c.eval_many_into(&[0.5], &mut [0.0; 2]),
        Err(Error::ShapeMismatch { .. })
    ));
}

#[test]
fn curve_batches_agree_with_de_casteljau() {
    let mut rng = Lcg(3);
    for n in [0, 1, 2, 3, 5, 10, 20] {
        for d in [1, 2, 3, 4, 7] {
            let control = DMatrix::from_fn(d, n + 1, |_, _| rng.signed());
            let scale = control.amax();
            let c = BezierCurve::new(control).unwrap();
            // 1000 points: several blocks of the sequential path.
            let ts = rng.params(1000);
            let mut out = vec![f64::NAN; ts.len() * d];
            c.eval_many_into(&ts, &mut out).unwrap();
            for (t, p) in ts.iter().zip(out.chunks_exact(d)) {
                let x = c.eval(*t);
                for k in 0..d {
                    let err = (p[k] - x[k]).abs() / (f64::EPSILON * scale);
                    assert!(err <= 2.0 * (n + 1) as f64, "n={n} d={d} t={t}: {err}");
                }
            }
            // The trait method and eval_many use the same layout.
            let mut via_trait = vec![0.0; out.len()];
            Curve::eval_many_into(&c, &ts, &mut via_trait).unwrap();
            assert_eq!(via_trait, out);
            let boxed: Box<dyn Curve> = Box::new(c.clone());
            boxed.eval_many_into(&ts, &mut via_trait).unwrap();
            assert_eq!(via_trait, out);
        }
    }
}

#[test]
fn curve_batches_on_threads_and_intervals() {
    let c = BezierCurve::from_points(&[
        [0.0, 0.0, 0.0],
        [0.0, 2.0, 2.0],
        [8.0, 2.0, 0.0],
        [4.0, 0.0, 0.0],
    ])
    .unwrap();
    let ts = cagd::linspace(0.0, 1.0, 200_001);
    let mut out = vec![0.0; ts.len() * 3];
    c.eval_many_into(&ts, &mut out).unwrap();
    // Primer 2.4: x(1/2) = (3.5, 1.5, 0.75), exactly (dyadic arithmetic).
    assert_eq!(&out[100_000 * 3..100_001 * 3], &[3.5, 1.5, 0.75]);
    for (t, p) in ts.iter().zip(out.chunks_exact(3)).step_by(997) {
        let x = c.eval(*t);
        for k in 0..3 {
            assert!((p[k] - x[k]).abs() <= 16.0 * f64::EPSILON * 8.0);
        }
    }
    let wide = c.clone().with_interval(2.0, 6.0).unwrap();
    let mut w = vec![0.0; 3 * 3];
    wide.eval_many_into(&[2.0, 4.0, 6.0], &mut w).unwrap();
    assert_eq!(w, [0.0, 0.0, 0.0, 3.5, 1.5, 0.75, 4.0, 0.0, 0.0]);
}

#[test]
fn curve_batches_are_exact_in_rationals() {
    let control = DMatrix::from_fn(2, 6, |k, i| q((i * 5 + k * 3) as i64 % 7 - 3, 1 + k as i64));
    let c = BezierCurve::new(control).unwrap();
    let ts = [q(0, 1), q(1, 7), q(1, 2), q(5, 6), q(1, 1), q(3, 2)];
    let mut out = vec![q(0, 1); ts.len() * 2];
    c.eval_many_into(&ts, &mut out).unwrap();
    for (t, p) in ts.iter().zip(out.chunks_exact(2)) {
        assert_eq!(p, c.eval(t.clone()).as_slice());
    }
}

/// The isoparametric curve `v ↦ x(u0, v)` of a patch as a Bézier curve (a function of `v`):
/// control points `Σ_i B_i^m(u0) b_{i,j}`.
fn curve_at_u<T: Scalar>(p: &BezierPatch<T>, u0: T) -> BezierCurve<T> {
    let (m, n) = p.degree();
    let w = bernstein_all(m, u0);
    let control = DMatrix::from_fn(p.dim(), n + 1, |k, j| {
        (0..=m).fold(T::zero(), |acc, i| {
            acc + w[i].clone() * p.coordinates()[k][(i, j)].clone()
        })
    });
    BezierCurve::new(control).unwrap()
}

/// The isoparametric curve `u ↦ x(u, v0)` (a function of `u`).
fn curve_at_v<T: Scalar>(p: &BezierPatch<T>, v0: T) -> BezierCurve<T> {
    let (m, n) = p.degree();
    let w = bernstein_all(n, v0);
    let control = DMatrix::from_fn(p.dim(), m + 1, |k, i| {
        (0..=n).fold(T::zero(), |acc, j| {
            acc + w[j].clone() * p.coordinates()[k][(i, j)].clone()
        })
    });
    BezierCurve::new(control).unwrap()
}

/// The Gordon surface of the 5 × 5 network of isoparametric cubics of a bicubic patch at the
/// nodes 0, 1/4, 1/2, 3/4, 1.
fn gordon_of<T: Scalar>(p: &BezierPatch<T>) -> GordonSurface<BezierCurve<T>, T> {
    let nodes: Vec<T> = (0..5).map(|i| T::from_ratio(i, 4)).collect();
    let at_u = nodes.iter().map(|u| curve_at_u(p, u.clone())).collect();
    let at_v = nodes.iter().map(|v| curve_at_v(p, v.clone())).collect();
    GordonSurface::new(nodes.clone(), nodes, at_u, at_v).unwrap()
}

fn coons_of<T: Scalar>(p: &BezierPatch<T>) -> CoonsPatch<BezierCurve<T>, T> {
    use cagd::Edge;
    CoonsPatch::new(
        p.boundary(Edge::V0),
        p.boundary(Edge::V1),
        p.boundary(Edge::U0),
        p.boundary(Edge::U1),
    )
    .unwrap()
}

#[test]
fn coons_and_gordon_grids_agree_with_per_point_evaluation() {
    let mut rng = Lcg(5);
    let p = random_patch(&mut rng, 3, 3, 3);
    let (us, vs) = (rng.params(23), rng.params(17));
    let mut out = vec![f64::NAN; us.len() * vs.len() * 3];
    let scale = net_size(&p);

    let coons = coons_of(&p);
    coons.eval_grid_into(&us, &vs, &mut out).unwrap();
    check_grid_against(&coons, &us, &vs, &out, scale, 32.0);

    // Gordon reproduces the bicubic patch it was cut from (degree 3 ≤ 4 in both directions).
    let gordon = gordon_of(&p);
    gordon.eval_grid_into(&us, &vs, &mut out).unwrap();
    check_grid_against(&gordon, &us, &vs, &out, scale, 256.0);
    check_grid_against(&p, &us, &vs, &out, scale, 256.0);

    // Large grids (threads) give the rows of small ones.
    let (us, vs) = (rng.params(300), rng.params(400));
    for s in [&coons as &dyn Surface, &gordon] {
        let mut big = vec![0.0; 300 * 400 * 3];
        s.eval_grid_into(&us, &vs, &mut big).unwrap();
        let mut row = vec![0.0; 400 * 3];
        s.eval_grid_into(&us[150..151], &vs, &mut row).unwrap();
        assert_eq!(&big[150 * 1200..151 * 1200], &row[..]);
    }
}

#[test]
fn coons_and_gordon_grids_are_exact_in_rationals() {
    let p = rational_patch(3, 3);
    let us = [q(0, 1), q(1, 3), q(3, 4), q(1, 1)];
    let vs = [q(1, 5), q(1, 2), q(1, 1)];
    let mut out = vec![q(0, 1); us.len() * vs.len() * 3];
    let coons = coons_of(&p);
    let gordon = gordon_of(&p);
    for s in [&coons as &dyn Surface<Q>, &gordon] {
        s.eval_grid_into(&us, &vs, &mut out).unwrap();
        for (a, u) in us.iter().enumerate() {
            for (b, v) in vs.iter().enumerate() {
                let x = s.eval(u.clone(), v.clone());
                assert_eq!(&out[(a * vs.len() + b) * 3..][..3], x.as_slice());
            }
        }
    }
    // Gordon of the bicubic's network is the bicubic, exactly.
    let mut patch_out = vec![q(0, 1); out.len()];
    p.eval_grid_into(&us, &vs, &mut patch_out).unwrap();
    assert_eq!(out, patch_out);
}

#[test]
fn closure_curves_and_other_surfaces_use_the_per_point_defaults() {
    type F = fn(f64) -> DVector<f64>;
    let curves = || {
        let c1: F = |u| dvector![u, 0.0, u - u * u];
        let c2: F = |u| dvector![u, 1.0, u];
        let d1: F = |v| dvector![0.0, v * v, v - v * v];
        let d2: F = |v| dvector![1.0, v, v];
        [c1, c2, d1, d2].map(|f| FnCurve::new(3, f))
    };
    let [c1, c2, d1, d2] = curves();
    let coons = CoonsPatch::new(c1, c2, d1, d2).unwrap();
    let mut out = vec![0.0; 3];
    coons.eval_grid_into(&[0.2], &[0.5], &mut out).unwrap();
    // Thesis Primer 4.3: x(0.2, 0.5) = (0.2, 0.3, 0.38).
    for (x, e) in out.iter().zip([0.2, 0.3, 0.38]) {
        assert!((x - e).abs() < 1e-15);
    }
    let [c1, c2, d1, d2] = curves();
    let partial = GeneralizedCoonsPatch::partially_bicubic(c1, c2, d1, d2).unwrap();
    let (us, vs) = ([0.0, 0.3, 1.0], [0.1, 0.9]);
    let mut out = vec![0.0; 18];
    partial.eval_grid_into(&us, &vs, &mut out).unwrap();
    assert_eq!(
        cagd_octave::arrays::to_array3(partial.eval_grid(&us, &vs))
            .as_slice()
            .unwrap(),
        &out[..],
        "default eval_grid_into is eval point by point"
    );
}

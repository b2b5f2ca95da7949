//! The fraction-free kernels of exact rational arithmetic (Bernstein rows, Bézier curve
//! batches, Gordon's sums over a common denominator) give exactly the values of the generic
//! operations they replace.

use cagd::bernstein::{bernstein, bernstein_all};
use cagd::bezier::BezierCurve;
use cagd::gordon::GordonSurface;
use cagd::lagrange::Lagrange;
use cagd::{Scalar, Surface};
use nalgebra::DMatrix;
use num_rational::BigRational as Q;

use cagd_test_support::lcg::Lcg;

fn q(n: i64, d: i64) -> Q {
    <Q as Scalar>::from_ratio(n, d)
}

fn random_q(rng: &mut Lcg) -> Q {
    q(rng.below(41) as i64 - 20, 1 + rng.below(12) as i64)
}

#[test]
fn bernstein_rows_equal_the_single_polynomials() {
    let mut rng = Lcg(3);
    for n in [0, 1, 2, 3, 7, 20] {
        for _ in 0..6 {
            let t = random_q(&mut rng);
            let row = bernstein_all(n, t.clone());
            for (i, b) in row.iter().enumerate() {
                assert_eq!(*b, bernstein(i, n, t.clone()), "n = {n}, i = {i}, t = {t}");
            }
        }
    }
}

#[test]
fn bezier_batches_equal_de_casteljau() {
    let mut rng = Lcg(8);
    for n in [0, 1, 3, 5, 12] {
        for d in [1, 2, 3] {
            let control = DMatrix::from_fn(d, n + 1, |_, _| random_q(&mut rng));
            for (a, b) in [(q(0, 1), q(1, 1)), (q(-1, 3), q(5, 2))] {
                let c = BezierCurve::new_on_interval(control.clone(), a, b).unwrap();
                let ts: Vec<Q> = (0..7).map(|_| random_q(&mut rng)).collect();
                let many = c.eval_many(&ts).unwrap();
                let mut out = vec![q(0, 1); ts.len() * d];
                c.eval_many_into(&ts, &mut out).unwrap();
                for (k, t) in ts.iter().enumerate() {
                    let e = c.eval(t.clone());
                    assert_eq!(many.column(k), e, "n = {n}, d = {d}, t = {t}");
                    assert_eq!(&out[k * d..(k + 1) * d], e.as_slice());
                }
            }
        }
    }
}

#[test]
fn gordon_parts_equal_the_sums_of_the_formula() {
    // The 3 × 4 network of isoparametric cubics of a bicubic Bézier patch, rational nodes.
    let mut rng = Lcg(21);
    let coords: Vec<DMatrix<Q>> = (0..3)
        .map(|_| DMatrix::from_fn(4, 4, |_, _| random_q(&mut rng)))
        .collect();
    let patch = cagd::bezier::BezierPatch::new(coords).unwrap();
    let (un, vn) = (
        vec![q(0, 1), q(1, 3), q(1, 1)],
        vec![q(0, 1), q(1, 4), q(3, 5), q(1, 1)],
    );
    let at_u: Vec<BezierCurve<Q>> = un.iter().map(|u| iso(&patch, u, true)).collect();
    let at_v: Vec<BezierCurve<Q>> = vn.iter().map(|v| iso(&patch, v, false)).collect();
    let g = GordonSurface::new(un.clone(), vn.clone(), at_u.clone(), at_v.clone()).unwrap();
    let (lu, lv) = (
        Lagrange::new(un.clone()).unwrap(),
        Lagrange::new(vn.clone()).unwrap(),
    );
    for (u, v) in [(q(1, 7), q(2, 9)), (q(0, 1), q(1, 1)), (q(-1, 2), q(3, 2))] {
        let p = g.eval_parts(u.clone(), v.clone());
        let (bu, bv) = (lu.basis(&u), lv.basis(&v));
        for k in 0..3 {
            let mut g1 = q(0, 1);
            for (l, c) in bu.iter().zip(&at_u) {
                g1 += c.eval(v.clone())[k].clone() * l.clone();
            }
            let mut g2 = q(0, 1);
            for (l, c) in bv.iter().zip(&at_v) {
                g2 += c.eval(u.clone())[k].clone() * l.clone();
            }
            let mut g12 = q(0, 1);
            for (li, ui) in bu.iter().zip(&un) {
                for (lj, vj) in bv.iter().zip(&vn) {
                    g12 += patch.eval(ui.clone(), vj.clone())[k].clone() * li * lj;
                }
            }
            assert_eq!((&p.g1[k], &p.g2[k], &p.g12[k]), (&g1, &g2, &g12));
            assert_eq!(p.g[k], &g1 + &g2 - &g12);
        }
        assert_eq!(p.g, g.eval(u, v));
    }
}

/// The isoparametric curve of a patch at `u = s` (`along_v`) or `v = s`, as a Bézier curve.
fn iso(p: &cagd::bezier::BezierPatch<Q>, s: &Q, along_v: bool) -> BezierCurve<Q> {
    let b = bernstein_all(3, s.clone());
    BezierCurve::new(DMatrix::from_fn(3, 4, |k, j| {
        let c = &p.coordinates()[k];
        (0..4).fold(q(0, 1), |acc, i| {
            let x = if along_v {
                c[(i, j)].clone()
            } else {
                c[(j, i)].clone()
            };
            acc + x * b[i].clone()
        })
    }))
    .unwrap()
}

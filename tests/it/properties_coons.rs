//! Property tests of the Coons and Gordon constructions, in exact rationals (so every
//! equality is exact): interpolation, reproduction, discrete Coons = mask, affine invariance,
//! u/v symmetry.

use crate::support;

use cagd::coons::{
    discrete_coons, solve_mask, BicubicCoonsPatch, CoonsBoundary, CoonsPatch, Corner,
    CrossDerivatives, Mask, Tolerance, Twist,
};
use cagd::gordon::GordonSurface;
use cagd::{Curve, Surface};
use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;
use support::{q, Poly, PolySurface, Q};

const DIM: usize = 3;

fn rational() -> impl Strategy<Value = Q> {
    (-64i64..=64).prop_map(|n| q(n, 8))
}

fn point() -> impl Strategy<Value = DVector<Q>> {
    proptest::collection::vec(rational(), DIM).prop_map(DVector::from_vec)
}

fn surface(max_p: usize, max_q: usize) -> impl Strategy<Value = PolySurface<Q>> {
    (0..=max_p, 0..=max_q).prop_flat_map(|(p, qq)| {
        proptest::collection::vec(proptest::collection::vec(point(), qq + 1), p + 1)
            .prop_map(PolySurface::new)
    })
}

/// A curve from `a` (t = 0) to `b` (t = 1): `(1 − t) a + t b + t(1 − t) r(t)`, `r` random of
/// degree ≤ 2.
fn curve_between(a: DVector<Q>, b: DVector<Q>, r: Vec<DVector<Q>>) -> Poly<Q> {
    // (1 − t) a + t b = a + t (b − a); t(1 − t) r(t) = Σ r_k (t^{k+1} − t^{k+2}).
    let zero = DVector::from_element(DIM, q(0, 1));
    let mut coeffs = vec![zero; r.len() + 2];
    coeffs[0] = a.clone();
    coeffs[1] = &b - &a;
    for (k, rk) in r.iter().enumerate() {
        coeffs[k + 1] = &coeffs[k + 1] + rk;
        coeffs[k + 2] = &coeffs[k + 2] - rk;
    }
    Poly::new(coeffs)
}

/// Four compatible boundary curves `[c1, c2, d1, d2]` through random corners.
fn boundary() -> impl Strategy<Value = [Poly<Q>; 4]> {
    (
        proptest::collection::vec(point(), 4),
        proptest::collection::vec(proptest::collection::vec(point(), 0..=2), 4),
    )
        .prop_map(|(p, r)| {
            // P1..P4 = x(0,0), x(1,0), x(0,1), x(1,1)
            [
                curve_between(p[0].clone(), p[1].clone(), r[0].clone()),
                curve_between(p[2].clone(), p[3].clone(), r[1].clone()),
                curve_between(p[0].clone(), p[2].clone(), r[2].clone()),
                curve_between(p[1].clone(), p[3].clone(), r[3].clone()),
            ]
        })
}

fn ts() -> Vec<Q> {
    (0..=4).map(|k| q(k, 4)).chain([q(1, 3), q(5, 7)]).collect()
}

/// `t ↦ A p(t) + b` for a polynomial curve.
fn map_poly(c: &Poly<Q>, a: &DMatrix<Q>, b: &DVector<Q>) -> Poly<Q> {
    Poly::new(
        c.coeffs
            .iter()
            .enumerate()
            .map(|(k, x)| {
                let ax = mat_vec(a, x);
                if k == 0 {
                    &ax + b
                } else {
                    ax
                }
            })
            .collect(),
    )
}

fn mat_vec(a: &DMatrix<Q>, x: &DVector<Q>) -> DVector<Q> {
    DVector::from_fn(a.nrows(), |r, _| {
        (0..a.ncols()).fold(q(0, 1), |acc, c| acc + a[(r, c)].clone() * x[c].clone())
    })
}

fn affine() -> impl Strategy<Value = (DMatrix<Q>, DVector<Q>)> {
    (proptest::collection::vec(rational(), DIM * DIM), point())
        .prop_map(|(a, b)| (DMatrix::from_vec(DIM, DIM, a), b))
}

/// Sorted distinct rational nodes in [−1/2, 3/2], `count` of them.
fn nodes(count: usize) -> impl Strategy<Value = Vec<Q>> {
    proptest::collection::btree_set(-8i64..=24, count)
        .prop_map(|s| s.into_iter().map(|n| q(n, 16)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn coons_interpolates_its_four_curves([c1, c2, d1, d2] in boundary()) {
        let patch = CoonsPatch::with_tolerance(
            c1.clone(), c2.clone(), d1.clone(), d2.clone(), Tolerance::Exact,
        ).unwrap();
        for t in ts() {
            prop_assert_eq!(patch.eval(t.clone(), q(0, 1)), c1.eval(t.clone()));
            prop_assert_eq!(patch.eval(t.clone(), q(1, 1)), c2.eval(t.clone()));
            prop_assert_eq!(patch.eval(q(0, 1), t.clone()), d1.eval(t.clone()));
            prop_assert_eq!(patch.eval(q(1, 1), t.clone()), d2.eval(t.clone()));
        }
    }

    #[test]
    fn coons_reproduces_bilinear_patches(corners in proptest::collection::vec(point(), 4)) {
        // x(u,v) = (1−u)(1−v) P1 + u(1−v) P2 + (1−u)v P3 + uv P4 from its own edges.
        let s = PolySurface::new(vec![
            vec![corners[0].clone(), &corners[2] - &corners[0]],
            vec![&corners[1] - &corners[0], &(&corners[3] - &corners[1]) - &(&corners[2] - &corners[0])],
        ]);
        let (z, o) = (q(0, 1), q(1, 1));
        let patch = CoonsPatch::with_tolerance(
            s.curve_at_v(&z), s.curve_at_v(&o), s.curve_at_u(&z), s.curve_at_u(&o), Tolerance::Exact,
        ).unwrap();
        for u in ts() {
            for v in ts() {
                prop_assert_eq!(patch.eval(u.clone(), v.clone()), s.eval(&u, &v));
            }
        }
    }

    #[test]
    fn bicubic_coons_reproduces_bicubic_patches(s in surface(3, 3)) {
        let (z, o) = (q(0, 1), q(1, 1));
        let boundary = CoonsBoundary::new(
            s.curve_at_v(&z), s.curve_at_v(&o), s.curve_at_u(&z), s.curve_at_u(&o), Tolerance::Exact,
        ).unwrap();
        let (su, sv, suv) = (s.partial(1, 0), s.partial(0, 1), s.partial(1, 1));
        let cross = CrossDerivatives {
            du0: su.curve_at_u(&z), du1: su.curve_at_u(&o),
            dv0: sv.curve_at_v(&z), dv1: sv.curve_at_v(&o),
        };
        let twists = Corner::ALL.map(|c| {
            let (i, j) = c.uv();
            suv.eval(&q(i as i64, 1), &q(j as i64, 1))
        });
        let patch = BicubicCoonsPatch::new(boundary, cross, Twist::Given(twists)).unwrap();
        for u in ts() {
            for v in ts() {
                prop_assert_eq!(patch.eval(u.clone(), v.clone()), s.eval(&u, &v));
            }
        }
    }

    #[test]
    fn gordon_interpolates_every_network_curve(
        s in surface(4, 4),
        un in (2usize..=4).prop_flat_map(nodes),
        vn in (2usize..=4).prop_flat_map(nodes),
    ) {
        let at_u: Vec<_> = un.iter().map(|u| s.curve_at_u(u)).collect();
        let at_v: Vec<_> = vn.iter().map(|v| s.curve_at_v(v)).collect();
        let g = GordonSurface::with_tolerance(un.clone(), vn.clone(), at_u, at_v, Tolerance::Exact).unwrap();
        for t in ts() {
            for (i, u) in un.iter().enumerate() {
                prop_assert_eq!(g.eval(u.clone(), t.clone()), g.curves_at_u()[i].eval(t.clone()));
            }
            for (j, v) in vn.iter().enumerate() {
                prop_assert_eq!(g.eval(t.clone(), v.clone()), g.curves_at_v()[j].eval(t.clone()));
            }
        }
    }

    #[test]
    fn gordon_reproduces_polynomials_of_degree_at_most_m_n(
        (un, vn, s) in (2usize..=4, 2usize..=4).prop_flat_map(|(mu, mv)| {
            (nodes(mu), nodes(mv), surface(mu - 1, mv - 1))
        }),
    ) {
        let at_u: Vec<_> = un.iter().map(|u| s.curve_at_u(u)).collect();
        let at_v: Vec<_> = vn.iter().map(|v| s.curve_at_v(v)).collect();
        let g = GordonSurface::with_tolerance(un, vn, at_u, at_v, Tolerance::Exact).unwrap();
        for u in ts() {
            for v in ts() {
                prop_assert_eq!(g.eval(u.clone(), v.clone()), s.eval(&u, &v));
            }
        }
    }

    #[test]
    fn discrete_coons_is_the_coons_mask_solve(
        net in (2usize..=5, 2usize..=5).prop_flat_map(|(m, n)| {
            proptest::collection::vec(
                proptest::collection::vec(rational(), (m + 1) * (n + 1))
                    .prop_map(move |v| DMatrix::from_vec(m + 1, n + 1, v)),
                2,
            )
        }),
    ) {
        prop_assert_eq!(discrete_coons(&net).unwrap(), solve_mask(&net, &Mask::coons(), &cagd::Limits::default()).unwrap());
    }

    #[test]
    fn coons_is_affinely_invariant([c1, c2, d1, d2] in boundary(), (a, b) in affine()) {
        let patch = CoonsPatch::with_tolerance(
            c1.clone(), c2.clone(), d1.clone(), d2.clone(), Tolerance::Exact,
        ).unwrap();
        let mapped = CoonsPatch::with_tolerance(
            map_poly(&c1, &a, &b), map_poly(&c2, &a, &b), map_poly(&d1, &a, &b), map_poly(&d2, &a, &b),
            Tolerance::Exact,
        ).unwrap();
        for u in ts() {
            for v in ts() {
                let x = patch.eval(u.clone(), v.clone());
                prop_assert_eq!(mapped.eval(u.clone(), v.clone()), &mat_vec(&a, &x) + &b);
            }
        }
    }

    #[test]
    fn gordon_is_affinely_invariant(s in surface(3, 3), (a, b) in affine()) {
        let un = vec![q(0, 1), q(1, 3), q(1, 1)];
        let vn = vec![q(0, 1), q(1, 1)];
        let build = |f: &dyn Fn(&Poly<Q>) -> Poly<Q>| {
            let at_u: Vec<_> = un.iter().map(|u| f(&s.curve_at_u(u))).collect();
            let at_v: Vec<_> = vn.iter().map(|v| f(&s.curve_at_v(v))).collect();
            GordonSurface::with_tolerance(un.clone(), vn.clone(), at_u, at_v, Tolerance::Exact).unwrap()
        };
        let g = build(&|c| c.clone());
        let h = build(&|c| map_poly(c, &a, &b));
        for u in ts() {
            for v in ts() {
                prop_assert_eq!(h.eval(u.clone(), v.clone()), &mat_vec(&a, &g.eval(u.clone(), v.clone())) + &b);
            }
        }
    }

    #[test]
    fn affine_masks_commute_with_affine_maps(
        alpha in (-8i64..=8).prop_map(|n| q(n, 16)),
        net in proptest::collection::vec(rational(), 5 * 4),
        (a, b) in affine(),
    ) {
        // A net of 3-D points (one matrix per coordinate), mapped point by point.
        let coords: Vec<DMatrix<Q>> = (0..DIM)
            .map(|k| DMatrix::from_fn(5, 4, |i, j| net[i * 4 + j].clone() * q(k as i64 + 1, 1) + q((i * j) as i64, k as i64 + 1)))
            .collect();
        let map_net = |c: &[DMatrix<Q>]| -> Vec<DMatrix<Q>> {
            let mut out = c.to_vec();
            for i in 0..5 {
                for j in 0..4 {
                    let p = DVector::from_fn(DIM, |k, _| c[k][(i, j)].clone());
                    let y = &mat_vec(&a, &p) + &b;
                    for k in 0..DIM {
                        out[k][(i, j)] = y[k].clone();
                    }
                }
            }
            out
        };
        let mask = Mask::from_alpha(alpha).unwrap();
        match solve_mask(&coords, &mask, &cagd::Limits::default()) {
            Ok(solved) => prop_assert_eq!(solve_mask(&map_net(&coords), &mask, &cagd::Limits::default()).unwrap(), map_net(&solved)),
            Err(e) => {
                let singular = matches!(e, cagd::Error::SingularMask { .. });
                prop_assert!(singular, "unexpected error {:?}", e);
            }
        }
    }

    #[test]
    fn coons_is_symmetric_in_u_and_v([c1, c2, d1, d2] in boundary()) {
        // Swapping the roles of the c and d curves transposes the patch.
        let patch = CoonsPatch::with_tolerance(
            c1.clone(), c2.clone(), d1.clone(), d2.clone(), Tolerance::Exact,
        ).unwrap();
        let swapped = CoonsPatch::with_tolerance(d1, d2, c1, c2, Tolerance::Exact).unwrap();
        for u in ts() {
            for v in ts() {
                prop_assert_eq!(swapped.eval(v.clone(), u.clone()), patch.eval(u.clone(), v.clone()));
            }
        }
    }

    #[test]
    fn gordon_and_discrete_coons_are_symmetric_in_u_and_v(
        s in surface(3, 3),
        net in proptest::collection::vec(rational(), 4 * 6),
    ) {
        let un = vec![q(0, 1), q(1, 2), q(1, 1)];
        let vn = vec![q(-1, 4), q(1, 1)];
        let at_u: Vec<_> = un.iter().map(|u| s.curve_at_u(u)).collect();
        let at_v: Vec<_> = vn.iter().map(|v| s.curve_at_v(v)).collect();
        let g = GordonSurface::new(un.clone(), vn.clone(), at_u.clone(), at_v.clone()).unwrap();
        let t = GordonSurface::new(vn, un, at_v, at_u).unwrap();
        for u in ts() {
            for v in ts() {
                prop_assert_eq!(t.eval(v.clone(), u.clone()), g.eval(u.clone(), v.clone()));
            }
        }
        let m = DMatrix::from_vec(4, 6, net);
        prop_assert_eq!(
            discrete_coons(&[m.transpose()]).unwrap()[0].clone(),
            discrete_coons(&[m]).unwrap()[0].transpose()
        );
    }
}

//! Gordon surfaces and the Lagrange basis: appendix D's network, separate node vectors,
//! exactness in rationals, conditioning, and every bad-input error.

#[path = "support/coons.rs"]
mod support;

use cagd::coons::{CoonsPatch, Tolerance};
use cagd::gordon::GordonSurface;
use cagd::lagrange::{
    basis_product, chebyshev_nodes, check_nodes, Lagrange, LagrangeInterpolant, NodePlacement,
};
use cagd::{Curve, Error, FnCurve, Scalar, Surface};
use nalgebra::{dvector, DMatrix, DVector};
use support::{q, qv, random_surface, Poly, Q};

type QF = fn(Q) -> DVector<Q>;
type QCurves = Vec<FnCurve<QF, QF>>;

/// Appendix D: `d_i = g(u_i, v)` (functions of v) and `c_j = g(u, v_j)` (functions of u).
fn appendix_d() -> (QCurves, QCurves) {
    let d: [QF; 3] = [
        |v| dvector![q(0, 1), v.clone(), v],
        |v| dvector![q(1, 2), v.clone(), q(1, 4) + v],
        |v| dvector![q(1, 1), v.clone(), v],
    ];
    let c: [QF; 3] = [
        |u| dvector![u.clone(), q(0, 1), u.clone() - u.clone() * u],
        |u| dvector![u.clone(), q(1, 2), q(1, 2) + u.clone() - u.clone() * u],
        |u| dvector![u.clone(), q(1, 1), q(1, 1) + u.clone() - u.clone() * u],
    ];
    (
        Vec::from(d.map(|f| FnCurve::new(3, f))),
        Vec::from(c.map(|f| FnCurve::new(3, f))),
    )
}

fn thesis_nodes() -> Vec<Q> {
    vec![q(0, 1), q(1, 2), q(1, 1)]
}

fn params() -> Vec<Q> {
    (0..=8).map(|k| q(k, 8)).collect()
}

#[test]
fn appendix_d_network_is_compatible_and_interpolated() {
    let (d, c) = appendix_d();
    let g = GordonSurface::with_tolerance(thesis_nodes(), thesis_nodes(), d, c, Tolerance::Exact)
        .unwrap();
    let nodes = thesis_nodes();
    for t in params() {
        for (i, ui) in nodes.iter().enumerate() {
            assert_eq!(
                g.eval(ui.clone(), t.clone()),
                g.curves_at_u()[i].eval(t.clone())
            );
        }
        for (j, vj) in nodes.iter().enumerate() {
            assert_eq!(
                g.eval(t.clone(), vj.clone()),
                g.curves_at_v()[j].eval(t.clone())
            );
        }
    }
    // The network lies on (u, v, v + u − u²), of degree (2, 1): Gordon reproduces it.
    for u in params() {
        for v in params() {
            let z = v.clone() + u.clone() - u.clone() * u.clone();
            assert_eq!(
                g.eval(u.clone(), v.clone()),
                dvector![u.clone(), v.clone(), z]
            );
        }
    }
}

#[test]
fn appendix_d_printed_crossings_are_g_of_u_b_v_a() {
    // The thesis's g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22] must hold g(u_i, v_j) in
    // row i, block j; so its printed g_ab is g(u_b, v_a).
    let printed: [[(i64, i64); 3]; 9] = [
        [(0, 1), (0, 1), (0, 1)], // g00
        [(1, 2), (0, 1), (1, 4)], // g01
        [(1, 1), (0, 1), (0, 1)], // g02
        [(0, 1), (1, 2), (1, 2)], // g10
        [(1, 2), (1, 2), (3, 4)], // g11
        [(1, 1), (1, 2), (1, 2)], // g12
        [(0, 1), (1, 1), (1, 1)], // g20
        [(1, 2), (1, 1), (5, 4)], // g21
        [(1, 1), (1, 1), (1, 1)], // g22
    ];
    let g = |a: usize, b: usize| qv(&printed[3 * a + b]);
    let g_uv: Vec<Vec<DVector<Q>>> = vec![
        vec![g(0, 0), g(1, 0), g(2, 0)],
        vec![g(0, 1), g(1, 1), g(2, 1)],
        vec![g(0, 2), g(1, 2), g(2, 2)],
    ];
    let (d, c) = appendix_d();
    let nodes = thesis_nodes();
    for i in 0..3 {
        for j in 0..3 {
            assert_eq!(g_uv[i][j], d[i].eval(nodes[j].clone()), "d_{i}(v_{j})");
            assert_eq!(g_uv[i][j], c[j].eval(nodes[i].clone()), "c_{j}(u_{i})");
        }
    }
    let surface =
        GordonSurface::with_points(nodes.clone(), nodes, d, c, g_uv.clone(), Tolerance::Exact)
            .unwrap();
    assert_eq!(surface.points(), &g_uv[..]);
    // The other reading (row = v index) is not a compatible network.
    let transposed: Vec<Vec<DVector<Q>>> = (0..3)
        .map(|i| (0..3).map(|j| g_uv[j][i].clone()).collect())
        .collect();
    let (d, c) = appendix_d();
    let err = GordonSurface::with_points(
        thesis_nodes(),
        thesis_nodes(),
        d,
        c,
        transposed,
        Tolerance::Exact,
    )
    .err()
    .unwrap();
    assert!(matches!(err, Error::NetworkMismatch { .. }));
}

#[test]
fn gordon_parts_add_up() {
    let (d, c) = appendix_d();
    let g = GordonSurface::new(thesis_nodes(), thesis_nodes(), d, c).unwrap();
    let p = g.eval_parts(q(1, 3), q(2, 7));
    assert_eq!(p.g, &p.g1 + &p.g2 - &p.g12);
    // g1 interpolates in u the curves g(u_i, v): here exact, as the surface is quadratic in u.
    assert_eq!(p.g1, p.g);
}

#[test]
fn separate_node_vectors_and_counts() {
    // A surface of degree (5, 4) cut into 4 curves at uneven u nodes and 3 at v nodes.
    let mut seed = 99;
    let s = random_surface(&mut seed, 5, 4, 3);
    let un = vec![q(0, 1), q(1, 5), q(2, 3), q(1, 1)];
    let vn = vec![q(-1, 4), q(1, 2), q(9, 8)];
    let at_u: Vec<Poly<Q>> = un.iter().map(|u| s.curve_at_u(u)).collect();
    let at_v: Vec<Poly<Q>> = vn.iter().map(|v| s.curve_at_v(v)).collect();
    let g = GordonSurface::with_tolerance(un.clone(), vn.clone(), at_u, at_v, Tolerance::Exact)
        .unwrap();
    for t in params() {
        for u in &un {
            assert_eq!(g.eval(u.clone(), t.clone()), s.eval(u, &t));
        }
        for v in &vn {
            assert_eq!(g.eval(t.clone(), v.clone()), s.eval(&t, v));
        }
    }
    // Inside, the error is (I − P_u)(I − P_v) S, not zero for this degree.
    assert_ne!(g.eval(q(1, 3), q(1, 3)), s.eval(&q(1, 3), &q(1, 3)));
    // The grid agrees with pointwise evaluation.
    let ts: Vec<Q> = (0..5).map(|k| q(k, 4)).collect();
    let grid = g.eval_grid(&ts, &ts[1..]);
    assert_eq!(grid.shape(), &[5, 4, 3]);
    for (i, u) in ts.iter().enumerate() {
        for (j, v) in ts[1..].iter().enumerate() {
            let p = g.eval(u.clone(), v.clone());
            for k in 0..3 {
                assert_eq!(grid[[i, j, k]], p[k]);
            }
        }
    }
}

#[test]
fn gordon_reproduces_surfaces_of_degree_at_most_m_in_u_or_n_in_v() {
    let mut seed = 5;
    let un = vec![q(0, 1), q(1, 3), q(1, 1)];
    let vn = vec![q(0, 1), q(1, 4), q(3, 5), q(1, 1)];
    // Degree (2, 7): at most m = 2 in u.
    for (p, qq) in [(2, 7), (6, 3), (2, 3)] {
        let s = random_surface(&mut seed, p, qq, 2);
        let at_u: Vec<Poly<Q>> = un.iter().map(|u| s.curve_at_u(u)).collect();
        let at_v: Vec<Poly<Q>> = vn.iter().map(|v| s.curve_at_v(v)).collect();
        let g = GordonSurface::new(un.clone(), vn.clone(), at_u, at_v).unwrap();
        for u in params() {
            for v in params() {
                assert_eq!(
                    g.eval(u.clone(), v.clone()),
                    s.eval(&u, &v),
                    "degree ({p}, {qq})"
                );
            }
        }
    }
}

#[test]
fn coons_is_gordon_with_two_curves_each_way() {
    let mut seed = 12;
    let s = random_surface(&mut seed, 4, 4, 3);
    let (zero, one) = (q(0, 1), q(1, 1));
    let c1 = s.curve_at_v(&zero);
    let c2 = s.curve_at_v(&one);
    let d1 = s.curve_at_u(&zero);
    let d2 = s.curve_at_u(&one);
    let coons = CoonsPatch::new(c1.clone(), c2.clone(), d1.clone(), d2.clone()).unwrap();
    let gordon = GordonSurface::new(
        vec![zero.clone(), one.clone()],
        vec![zero, one],
        vec![d1, d2],
        vec![c1, c2],
    )
    .unwrap();
    for u in params() {
        for v in params() {
            assert_eq!(
                gordon.eval(u.clone(), v.clone()),
                coons.eval(u.clone(), v.clone())
            );
        }
    }
}

type F = fn(f64) -> DVector<f64>;
type FCurves = Vec<FnCurve<F, F>>;

fn f64_network() -> (FCurves, FCurves) {
    let d: [F; 3] = [
        |v| dvector![0.0, v, v],
        |v| dvector![0.5, v, 0.25 + v],
        |v| dvector![1.0, v, v],
    ];
    let c: [F; 3] = [
        |u| dvector![u, 0.0, u - u * u],
        |u| dvector![u, 0.5, 0.5 + u - u * u],
        |u| dvector![u, 1.0, 1.0 + u - u * u],
    ];
    (
        Vec::from(d.map(|f| FnCurve::new(3, f))),
        Vec::from(c.map(|f| FnCurve::new(3, f))),
    )
}

#[test]
fn incompatible_network_names_the_pair_gap_and_tolerance() {
    let (mut d, c) = f64_network();
    // Move d1 = g(0.5, v) up by 1e-3 where v = 1: it crosses c2 = g(u, 1) at u = 0.5.
    d[1] = FnCurve::new(3, |v| dvector![0.5, v, 0.25 + v + 1e-3 * v * v]);
    let nodes = vec![0.0, 0.5, 1.0];
    let err = GordonSurface::new(nodes.clone(), nodes, d, c)
        .err()
        .unwrap();
    match err {
        Error::NetworkMismatch {
            u_curve,
            v_curve,
            u,
            v,
            gap,
            allowed,
            tolerance,
            count,
        } => {
            assert_eq!((u_curve, v_curve, u, v), (1, 2, 0.5, 1.0));
            assert!((gap - 1e-3).abs() < 1e-15);
            assert!((allowed - 1.251e-10).abs() < 1e-20); // relative to the largest |coordinate|, 1.251
            assert_eq!(tolerance, Tolerance::Relative(1e-10));
            assert_eq!(count, 2); // also (1, 1): 1e-3/4
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn explicit_crossings_are_checked_against_both_curves() {
    let (d, c) = f64_network();
    let nodes = vec![0.0, 0.5, 1.0];
    let mut points: Vec<Vec<DVector<f64>>> = (0..3)
        .map(|i| (0..3).map(|j| d[i].eval(nodes[j])).collect())
        .collect();
    points[2][0][2] += 0.5;
    let err = GordonSurface::with_points(
        nodes.clone(),
        nodes.clone(),
        d,
        c,
        points,
        Tolerance::default(),
    )
    .err()
    .unwrap();
    assert!(
        matches!(err, Error::NetworkMismatch { u_curve: 2, v_curve: 0, count: 2, gap, .. } if gap == 0.5)
    );
    let (d, c) = f64_network();
    let err = GordonSurface::with_points(
        nodes.clone(),
        nodes,
        d,
        c,
        vec![vec![]],
        Tolerance::default(),
    )
    .err()
    .unwrap();
    assert!(matches!(
        err,
        Error::ShapeMismatch {
            what: "Gordon crossing points g(u_i, v_j)",
            ..
        }
    ));
}

#[test]
fn bad_nodes_and_too_few_curves() {
    let build = |un: Vec<f64>, vn: Vec<f64>, keep_u: usize, keep_v: usize| {
        let (mut d, mut c) = f64_network();
        d.truncate(keep_u);
        c.truncate(keep_v);
        GordonSurface::new(un, vn, d, c).err().unwrap()
    };
    let ok = vec![0.0, 0.5, 1.0];
    assert_eq!(
        build(vec![0.0, 0.5, 0.5], ok.clone(), 3, 3),
        Error::DuplicateNodes {
            what: "Gordon nodes u_i",
            first: 1,
            second: 2,
            value: 0.5
        }
    );
    assert_eq!(
        build(ok.clone(), vec![0.0, 1.0, 0.5], 3, 3),
        Error::UnsortedNodes {
            what: "Gordon nodes v_j",
            index: 1,
            value: 1.0,
            next: 0.5
        }
    );
    assert_eq!(
        build(vec![0.0], ok.clone(), 1, 3),
        Error::TooFewCurves {
            what: "Gordon curves g(u_i, v)",
            min: 2,
            found: 1
        }
    );
    assert_eq!(
        build(ok.clone(), vec![], 3, 0),
        Error::TooFewCurves {
            what: "Gordon curves g(u, v_j)",
            min: 2,
            found: 0
        }
    );
    assert!(matches!(
        build(vec![0.0, 1.0], ok.clone(), 3, 3),
        Error::ShapeMismatch {
            what: "Gordon nodes u_i",
            ..
        }
    ));
    assert!(matches!(
        build(vec![0.0, f64::NAN, 1.0], ok, 3, 3),
        Error::NonFinite {
            what: "Gordon nodes u_i",
            index: 1,
            ..
        }
    ));
    // Curves of different dimensions.
    let (mut d, c) = f64_network();
    d[0] = FnCurve::new(2, |v| dvector![0.0, v]);
    let nodes = vec![0.0, 0.5, 1.0];
    assert!(matches!(
        GordonSurface::new(nodes.clone(), nodes, d, c)
            .err()
            .unwrap(),
        Error::ShapeMismatch {
            what: "Gordon network curves",
            ..
        }
    ));
}

#[test]
fn conditioning_report_and_chebyshev_nodes() {
    // The same smooth surface sampled at 11 uniform vs 11 Chebyshev nodes per direction.
    // Runge's function in both directions: neither direction is reproduced exactly.
    let runge = |t: f64| 1.0 / (1.0 + 25.0 * (t - 0.5) * (t - 0.5));
    let surface = move |u: f64, v: f64| dvector![u, v, runge(u) * runge(v)];
    let build = |placement: NodePlacement| {
        let nodes: Vec<f64> = placement.nodes(11);
        type Boxed = Box<dyn Curve<f64>>;
        let at_u: Vec<Boxed> = nodes
            .iter()
            .map(|&u| Box::new(FnCurve::new(3, move |v: f64| surface(u, v))) as Boxed)
            .collect();
        let at_v: Vec<Boxed> = nodes
            .iter()
            .map(|&v| Box::new(FnCurve::new(3, move |u: f64| surface(u, v))) as Boxed)
            .collect();
        GordonSurface::new(nodes.clone(), nodes, at_u, at_v).unwrap()
    };
    let uniform = build(NodePlacement::Uniform);
    let chebyshev = build(NodePlacement::Chebyshev);
    let (ku, kc) = (uniform.conditioning(), chebyshev.conditioning());
    assert!(ku.u.value > 29.0 && ku.u.value < 30.0, "{:?}", ku.u);
    assert!(kc.u.value < 2.5, "{:?}", kc.u);
    assert!(ku.amplification() > 10.0 * kc.amplification());
    // Runge: on the line v = 0.95 (between the nodes of both sets), uniform nodes err far more.
    let err = |g: &GordonSurface<Box<dyn Curve<f64>>, f64>| {
        (0..=200)
            .map(|k| {
                let u = k as f64 / 200.0;
                (g.eval(u, 0.95) - surface(u, 0.95)).amax()
            })
            .fold(0.0, f64::max)
    };
    assert!(
        err(&uniform) > 10.0 * err(&chebyshev),
        "{} vs {}",
        err(&uniform),
        err(&chebyshev)
    );
}

// ---------------------------------------------------------------- Lagrange

#[test]
fn lagrange_basis_is_exact_and_matches_the_product_form() {
    let nodes = vec![q(-1, 3), q(0, 1), q(2, 7), q(1, 2), q(1, 1)];
    let l = Lagrange::new(nodes.clone()).unwrap();
    for t in (0..=20).map(|k| q(k - 4, 12)) {
        let b = l.basis(&t);
        assert_eq!(b.iter().fold(q(0, 1), |a, x| a + x.clone()), q(1, 1));
        for (i, bi) in b.iter().enumerate() {
            assert_eq!(*bi, basis_product(&nodes, i, &t));
        }
    }
    for (k, x) in nodes.iter().enumerate() {
        let b = l.basis(x);
        for (i, bi) in b.iter().enumerate() {
            assert_eq!(*bi, if i == k { q(1, 1) } else { q(0, 1) });
        }
    }
    assert_eq!(l.degree(), 4);
}

#[test]
fn lagrange_interpolant_reproduces_polynomials_and_their_derivatives() {
    let mut seed = 8;
    let p = Poly::new(
        (0..4)
            .map(|_| DVector::from_fn(2, |_, _| support::lcg_rational(&mut seed, 3)))
            .collect(),
    );
    let nodes = vec![q(0, 1), q(1, 5), q(1, 2), q(3, 4), q(1, 1)];
    let values =
        DMatrix::from_columns(&nodes.iter().map(|t| p.eval(t.clone())).collect::<Vec<_>>());
    let interp = LagrangeInterpolant::new(Lagrange::new(nodes.clone()).unwrap(), values).unwrap();
    for t in (0..=10).map(|k| q(k, 10)).chain(nodes.iter().cloned()) {
        assert_eq!(interp.eval(t.clone()), p.eval(t.clone()));
        assert_eq!(
            interp.eval_derivative(t.clone()),
            p.eval_derivative(t.clone())
        );
    }
    assert!(matches!(
        LagrangeInterpolant::new(Lagrange::new(nodes).unwrap(), DMatrix::<Q>::zeros(2, 3)),
        Err(Error::ShapeMismatch { .. })
    ));
}

#[test]
fn node_checks() {
    assert_eq!(
        check_nodes("x", &[0.0, 0.2, 0.2], 1),
        Err(Error::DuplicateNodes {
            what: "x",
            first: 1,
            second: 2,
            value: 0.2
        })
    );
    assert_eq!(
        check_nodes("x", &[0.3, 0.2], 1),
        Err(Error::UnsortedNodes {
            what: "x",
            index: 0,
            value: 0.3,
            next: 0.2
        })
    );
    assert_eq!(
        Lagrange::<f64>::new(vec![]).err(),
        Some(Error::TooFewPoints {
            what: "Lagrange nodes",
            min: 1,
            found: 0
        })
    );
    assert!(check_nodes("x", &[0.0, 1.0], 2).is_ok());
}

#[test]
fn chebyshev_nodes_are_symmetric_and_sorted() {
    for count in 2..30 {
        let t = chebyshev_nodes(count);
        assert_eq!((t[0], t[count - 1]), (0.0, 1.0));
        assert!(t.windows(2).all(|w| w[0] < w[1]));
        for k in 0..count {
            assert!((t[k] + t[count - 1 - k] - 1.0).abs() < 1e-15);
            let want = (1.0 - (std::f64::consts::PI * k as f64 / (count - 1) as f64).cos()) / 2.0;
            assert!((t[k] - want).abs() < 1e-15);
        }
    }
    let exact: Vec<Q> = NodePlacement::Uniform.nodes(4);
    assert_eq!(exact, vec![q(0, 1), q(1, 3), q(2, 3), q(1, 1)]);
    assert_eq!(
        <Q as Scalar>::to_f64(&NodePlacement::Chebyshev.nodes::<Q>(3)[1]),
        0.5
    );
}

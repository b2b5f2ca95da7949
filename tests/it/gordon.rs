//! Gordon surfaces and the Lagrange basis: appendix D's network, separate node vectors,
//! exactness in rationals, conditioning, and every bad-input error.

use crate::support;

use cagd::coons::{CoonsPatch, Tolerance};
use cagd::gordon::GordonSurface;
use cagd::lagrange::{
    basis_product, chebyshev_nodes, check_nodes, Lagrange, LagrangeInterpolant, NodePlacement,
};
use cagd::{Curve, Error, FnCurve, Scalar, Surface};
use nalgebra::{dvector, DMatrix, DVector};
use support::{q, qv, random_surface, Poly, Q};

type QF = fn(Q) -> DVector<Q>;
type QCurves = Vec<FnCurve<QF, cagd::NoDerivative, Q>>;

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
    let grid = cagd_octave::arrays::to_array3(g.eval_grid(&ts, &ts[1..]));
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
type FCurves = Vec<FnCurve<F>>;

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
    // A negative tolerance.
    let (d, c) = f64_network();
    let nodes = vec![0.0, 0.5, 1.0];
    assert!(matches!(
        GordonSurface::with_tolerance(nodes.clone(), nodes, d, c, Tolerance::Absolute(-1.0))
            .err()
            .unwrap(),
        Error::InvalidArgument {
            what: "tolerance",
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
            assert_eq!(*bi, basis_product(&nodes, i, &t).unwrap());
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
            cagd::CurveDeriv::eval_derivative(&interp, t.clone()),
            cagd::CurveDeriv::eval_derivative(&p, t.clone())
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

// ---------------------------------------------------------------- against GNU Octave

use cagd_test_support as common;

use cagd::bezier::BezierCurve;
use cagd::SampledCurve;
use common::{array3, expected, matrix, row};
use ndarray::{Array, Dimension};

/// `common::assert_close` for arrays of any fixed dimension.
fn assert_close<D: Dimension>(name: &str, ours: &Array<f64, D>, octave: &Array<f64, D>) {
    common::assert_close(name, ours.view().into_dyn(), octave.view().into_dyn());
}

/// `common::assert_identical` for arrays of any fixed dimension.
fn assert_identical<D: Dimension>(name: &str, ours: &Array<f64, D>, octave: &Array<f64, D>) {
    common::assert_identical(name, ours.view().into_dyn(), octave.view().into_dyn());
}
use ndarray::Array2;

/// Curve `k` of a family sampled side by side: columns `k·N .. (k+1)·N` of `family` (3 × K·N).
fn sampled_curve(t: &[f64], family: &Array2<f64>, k: usize) -> SampledCurve<f64> {
    let n = t.len();
    SampledCurve::new(
        t.to_vec(),
        DMatrix::from_fn(family.nrows(), n, |i, j| family[[i, k * n + j]]),
    )
    .unwrap()
}

/// `points[i][j] = g(u_i, v_j)` from the packed `(m+1) × 3(n+1)` matrix.
fn crossings(g_uv: &Array2<f64>) -> Vec<Vec<DVector<f64>>> {
    (0..g_uv.nrows())
        .map(|i| {
            (0..g_uv.ncols() / 3)
                .map(|j| DVector::from_fn(3, |k, _| g_uv[[i, 3 * j + k]]))
                .collect()
        })
        .collect()
}

#[test]
fn octave_appendix_d_krpa_gordon() {
    let ws = expected("gordon_thesis");
    let x = row(&ws, "x");
    let points = crossings(&matrix(&ws, "g_uv"));
    for n in [3, 10, 101] {
        let t = row(&ws, &format!("t_N{n}"));
        assert_eq!(t, cagd::linspace(0.0, 1.0, n));
        let g_u = matrix(&ws, &format!("g_u_N{n}")); // [c0 c1 c2]: g(u, v_j)
        let g_v = matrix(&ws, &format!("g_v_N{n}")); // [d0 d1 d2]: g(u_i, v)
        let at_u: Vec<_> = (0..3).map(|i| sampled_curve(&t, &g_v, i)).collect();
        let at_v: Vec<_> = (0..3).map(|j| sampled_curve(&t, &g_u, j)).collect();
        // With N = 10 the node 0.5 is not a sample: the polylines through the samples miss
        // the quadratic curves c_j there by up to h²/4 = 0.003, so the network of polylines is
        // compatible only to 1e-2. (N = 3 and 101 sample the nodes exactly.)
        let tolerance = if n == 10 {
            Tolerance::Absolute(1e-2)
        } else {
            Tolerance::default()
        };
        let g =
            GordonSurface::with_points(x.clone(), x.clone(), at_u, at_v, points.clone(), tolerance)
                .unwrap();
        let grid = cagd_octave::arrays::to_array3(g.eval_grid(&t, &t));
        assert_close(&format!("P_N{n}"), &grid, &array3(&ws, &format!("P_N{n}")));
    }
    common::report_worst("gordon_thesis");
}

/// `S(u, v) = Σ_k A(:,k) U[ea_k] V[eb_k]`, `U = cumprod([1 u u u u])`, `V = cumprod([1 v v v])`,
/// in the operation order of `octave_ref/cases/gordon_random.m`.
fn random_surface_f64(
    a: DMatrix<f64>,
    ea: Vec<usize>,
    eb: Vec<usize>,
) -> impl Fn(f64, f64) -> DVector<f64> + Clone {
    move |u: f64, v: f64| {
        let mut us = [1.0; 5];
        let mut vs = [1.0; 4];
        for k in 1..5 {
            us[k] = us[k - 1] * u;
        }
        for k in 1..4 {
            vs[k] = vs[k - 1] * v;
        }
        DVector::from_fn(3, |r, _| {
            (0..ea.len()).fold(0.0, |acc, k| acc + a[(r, k)] * (us[ea[k]] * vs[eb[k]]))
        })
    }
}

/// The Gordon surface of a sampled network on its sampling grid, in exact rationals from the
/// given doubles (on the grid only samples are used).
fn exact_gordon_grid(
    xu: &[f64],
    xv: &[f64],
    t: &[f64],
    g_u: &Array2<f64>,
    g_v: &Array2<f64>,
    g_uv: &Array2<f64>,
) -> ndarray::Array3<f64> {
    let lift = |x: f64| <Q as Scalar>::from_f64(x).unwrap();
    let n = t.len();
    let tq: Vec<Q> = t.iter().map(|&x| lift(x)).collect();
    let family = |m: &Array2<f64>, k: usize| {
        SampledCurve::new(
            tq.clone(),
            DMatrix::from_fn(3, n, |i, j| lift(m[[i, k * n + j]])),
        )
        .unwrap()
    };
    let at_u: Vec<_> = (0..xu.len()).map(|i| family(g_v, i)).collect();
    let at_v: Vec<_> = (0..xv.len()).map(|j| family(g_u, j)).collect();
    let points: Vec<Vec<DVector<Q>>> = crossings(g_uv)
        .iter()
        .map(|r| r.iter().map(|p| p.map(lift)).collect())
        .collect();
    // Between the samples the polylines are not the network: no compatibility to check.
    let g = GordonSurface::with_points(
        xu.iter().map(|&x| lift(x)).collect(),
        xv.iter().map(|&x| lift(x)).collect(),
        at_u,
        at_v,
        points,
        Tolerance::Absolute(1e3),
    )
    .unwrap();
    cagd_octave::arrays::to_array3(g.eval_grid(&tq, &tq)).map(|x| x.to_f64())
}

#[test]
fn octave_random_gordon_networks() {
    let ws = expected("gordon_random");
    for r in 1..=3 {
        let get = |name: &str| matrix(&ws, &format!("r{r}_{name}"));
        let a = DMatrix::from_fn(3, get("A").ncols(), |i, j| get("A")[[i, j]]);
        let ea: Vec<usize> = row(&ws, &format!("r{r}_ea"))
            .iter()
            .map(|&e| e as usize)
            .collect();
        let eb: Vec<usize> = row(&ws, &format!("r{r}_eb"))
            .iter()
            .map(|&e| e as usize)
            .collect();
        let (xu, xv, t) = (
            row(&ws, &format!("r{r}_xu")),
            row(&ws, &format!("r{r}_xv")),
            row(&ws, &format!("r{r}_t")),
        );
        let s = random_surface_f64(a, ea, eb);
        // The network as closures on the surface; their samples are Octave's, bit for bit.
        type Boxed = Box<dyn Curve<f64>>;
        let at_u: Vec<Boxed> = xu
            .iter()
            .map(|&u| {
                let s = s.clone();
                Box::new(FnCurve::new(3, move |v: f64| s(u, v))) as Boxed
            })
            .collect();
        let at_v: Vec<Boxed> = xv
            .iter()
            .map(|&v| {
                let s = s.clone();
                Box::new(FnCurve::new(3, move |u: f64| s(u, v))) as Boxed
            })
            .collect();
        let n = t.len();
        let g_u = Array2::from_shape_fn((3, xv.len() * n), |(k, c)| at_v[c / n].eval(t[c % n])[k]);
        let g_v = Array2::from_shape_fn((3, xu.len() * n), |(k, c)| at_u[c / n].eval(t[c % n])[k]);
        assert_identical(&format!("r{r}_g_u"), &g_u, &get("g_u"));
        assert_identical(&format!("r{r}_g_v"), &g_v, &get("g_v"));
        let g = GordonSurface::new(xu.clone(), xv.clone(), at_u, at_v).unwrap();
        let points = crossings(&get("g_uv"));
        assert_eq!(g.points(), &points[..]);
        let ours = cagd_octave::arrays::to_array3(g.eval_grid(&t, &t));
        let octave = array3(&ws, &format!("r{r}_P"));
        let kappa = g.conditioning().amplification();
        if kappa < 10.0 {
            assert_close(&format!("r{r}_P"), &ours, &octave);
            continue;
        }
        // Clustered random nodes make the blending ill-conditioned (κ = Λ_u + Λ_v + Λ_u Λ_v
        // is 1810 for r1 and 175 for r2): any two operation orders then differ by up to
        // κ·ε relative, more than 1e-14. Both are checked against the exact (rational) Gordon
        // surface of the same doubles, and against each other within κ·ε.
        let exact = exact_gordon_grid(&xu, &xv, &t, &get("g_u"), &get("g_v"), &get("g_uv"));
        let scale = octave.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let bound = kappa * f64::EPSILON * scale;
        let max_diff = |a: &ndarray::Array3<f64>, b: &ndarray::Array3<f64>| {
            a.iter()
                .zip(b.iter())
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        };
        let (ours_err, octave_err, diff) = (
            max_diff(&ours, &exact),
            max_diff(&octave, &exact),
            max_diff(&ours, &octave),
        );
        eprintln!(
            "[gordon_random r{r}] κ = {kappa:.1}: |ours − exact| = {ours_err:.2e}, |Octave − exact| = {octave_err:.2e}, |ours − Octave| = {diff:.2e} = {:.2e} of the scale {scale:.3}",
            diff / scale
        );
        assert!(
            ours_err <= bound,
            "r{r}: ours {ours_err:e} from exact, bound {bound:e}"
        );
        assert!(
            octave_err <= bound,
            "r{r}: Octave {octave_err:e} from exact, bound {bound:e}"
        );
        assert!(
            diff <= bound.max(1e-14 * scale),
            "r{r}: {diff:e} apart, bound {bound:e}"
        );
    }
    common::report_worst("gordon_random");
}

#[test]
fn octave_lagrange_basis() {
    let ws = expected("lagrange_basis");
    for k in 1..=3 {
        let x = row(&ws, &format!("x{k}"));
        let t = row(&ws, &format!("t{k}"));
        let octave = matrix(&ws, &format!("L{k}"));
        let basis = Lagrange::new(x.clone()).unwrap();
        let barycentric = Array2::from_shape_fn((x.len(), t.len()), |(i, j)| basis.basis(&t[j])[i]);
        let product = Array2::from_shape_fn((x.len(), t.len()), |(i, j)| {
            basis_product(&x, i, &t[j]).unwrap()
        });
        assert_identical(&format!("L{k} (product form)"), &product, &octave);
        assert_close(&format!("L{k} (barycentric)"), &barycentric, &octave);
    }
    common::report_worst("lagrange_basis");
}

#[test]
fn gordon_of_bezier_curves_as_one_bezier_patch_is_exact() {
    let mut seed = 71;
    let s = random_surface(&mut seed, 5, 3, 3);
    let un = vec![q(0, 1), q(1, 4), q(2, 3), q(1, 1)];
    let vn = vec![q(0, 1), q(1, 2), q(1, 1)];
    // Each network curve of the polynomial surface as a Bézier curve (monomial → Bernstein:
    // b_k = Σ_{i≤k} C(k,i)/C(n,i) a_i).
    let to_bezier = |p: &Poly<Q>| {
        let n = p.coeffs.len() - 1;
        let binom = |n: usize, k: usize| {
            (0..k).fold(q(1, 1), |acc, i| acc * q((n - i) as i64, (i + 1) as i64))
        };
        let control = DMatrix::from_fn(3, n + 1, |d, k| {
            (0..=k).fold(q(0, 1), |acc, i| {
                acc + binom(k, i) / binom(n, i) * p.coeffs[i][d].clone()
            })
        });
        BezierCurve::new(control).unwrap()
    };
    let at_u: Vec<_> = un.iter().map(|u| to_bezier(&s.curve_at_u(u))).collect();
    let at_v: Vec<_> = vn.iter().map(|v| to_bezier(&s.curve_at_v(v))).collect();
    for (c, u) in at_u.iter().zip(&un) {
        assert_eq!(c.eval(q(1, 3)), s.eval(u, &q(1, 3)));
    }
    let g = GordonSurface::with_tolerance(un, vn, at_u, at_v, Tolerance::Exact).unwrap();
    let patch = g.to_bezier().unwrap();
    assert_eq!(patch.degree(), (5, 3));
    for u in params() {
        for v in params() {
            assert_eq!(
                patch.eval(u.clone(), v.clone()),
                g.eval(u.clone(), v.clone())
            );
        }
    }
    // A curve over another interval enters reparametrised onto [0, 1], which keeps its
    // control points: the exact form exists too.
    let shifted =
        BezierCurve::new_on_interval(DMatrix::from_element(3, 2, q(0, 1)), q(0, 1), q(2, 1))
            .unwrap();
    let line = BezierCurve::new(DMatrix::from_element(3, 2, q(0, 1))).unwrap();
    let z = vec![q(0, 1), q(1, 1)];
    let g = GordonSurface::new(
        z.clone(),
        z,
        vec![shifted, line.clone()],
        vec![line.clone(), line],
    )
    .unwrap();
    let patch = g.to_bezier().unwrap();
    for u in params() {
        for v in params() {
            assert_eq!(
                patch.eval(u.clone(), v.clone()),
                g.eval(u.clone(), v.clone())
            );
        }
    }
}

//! The programs in `examples/`, recomputed: each test builds what its example builds and pins
//! the lines the example prints against values computed independently (closed forms, exact
//! rationals, GNU Octave's saved values). CI runs the examples themselves
//! (`cargo run --example …`).

use crate::support::{q, Q};

use cagd::bspline::BSplineCurve;
use cagd::coons::CoonsPatch;
use cagd::gordon::GordonSurface;
use cagd::nurbs::NurbsCurve;
use cagd::{BezierCurve, Surface};
use nalgebra::{dvector, DMatrix};

fn points(p: &[[f64; 3]]) -> DMatrix<f64> {
    DMatrix::from_fn(3, p.len(), |r, c| p[c][r])
}

/// `examples/coons_bspline_boundaries.rs`.
#[test]
fn coons_bspline_boundaries() {
    let c1 = BSplineCurve::uniform_cubic(
        &points(&[[0.0, 0.0, 0.0], [1.0, 0.0, 2.0], [2.0, 0.0, 0.0]]),
        true,
    )
    .unwrap();
    let c2 = BSplineCurve::clamped(
        2,
        points(&[[0.0, 2.0, 0.0], [1.0, 2.0, 1.0], [2.0, 2.0, 0.0]]),
    )
    .unwrap();
    let d1 = BSplineCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
        points(&[
            [0.0, 0.0, 0.0],
            [0.0, 1.0, -1.0],
            [0.0, 1.5, 0.5],
            [0.0, 2.0, 0.0],
        ]),
    )
    .unwrap();
    let d2 = BSplineCurve::clamped(1, points(&[[2.0, 0.0, 0.0], [2.0, 2.0, 0.0]])).unwrap();
    let domains: Vec<_> = [&c1, &c2, &d1, &d2].iter().map(|c| c.domain()).collect();
    assert_eq!(domains, [(0.0, 4.0), (0.0, 1.0), (0.0, 2.0), (0.0, 1.0)]);
    let patch = CoonsPatch::new(c1, c2, d1, d2).unwrap();
    let x = patch.eval(0.375, 0.25);
    // (37/64, 89/128, 31/64) from the closed forms (tests/it/domain.rs).
    assert!((&x - dvector![37.0 / 64.0, 89.0 / 128.0, 31.0 / 64.0]).amax() <= 4.0 * f64::EPSILON);
    assert_eq!(
        format!("x(3/8, 1/4) = ({:.7}, {:.7}, {:.7})", x[0], x[1], x[2]),
        "x(3/8, 1/4) = (0.5781250, 0.6953125, 0.4843750)"
    );
}

/// `examples/gordon_nurbs_network.rs`.
#[test]
fn gordon_nurbs_network() {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let arc = |r: f64, z: f64| {
        let points = DMatrix::from_column_slice(3, 3, &[r, 0.0, z, r, r, z, 0.0, r, z]);
        NurbsCurve::new(
            2,
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            points,
            vec![1.0, h, 1.0],
        )
        .unwrap()
    };
    let profile = |phi: f64| {
        let (c, s) = (phi.cos(), phi.sin());
        let points = DMatrix::from_fn(3, 3, |row, k| {
            let (r, z) = ([1.0, 2.0, 1.0][k], [0.0, 0.5, 1.0][k]);
            [r * c, r * s, z][row]
        });
        NurbsCurve::new(2, vec![0.0, 0.0, 0.0, 2.0, 2.0, 2.0], points, vec![1.0; 3]).unwrap()
    };
    let nodes = vec![0.0, 0.5, 1.0];
    let quarter = std::f64::consts::FRAC_PI_2;
    let g = GordonSurface::new(
        nodes.clone(),
        nodes,
        vec![arc(1.0, 0.0), arc(1.5, 0.5), arc(1.0, 1.0)],
        vec![profile(0.0), profile(0.5 * quarter), profile(quarter)],
    )
    .unwrap();
    // The surface of revolution the network is cut from: radius r(u) = 1 + 2u(1 − u), height
    // u, and the unit rational quarter circle ((1−v)² + √2 v(1−v), √2 v(1−v) + v²)/w(v),
    // w(v) = (1−v)² + √2 v(1−v) + v².
    let surface = |u: f64, v: f64| {
        let r = 1.0 + 2.0 * u * (1.0 - u);
        let (a, m, b) = ((1.0 - v) * (1.0 - v), 2.0 * h * v * (1.0 - v), v * v);
        let w = a + m + b;
        dvector![r * (a + m) / w, r * (m + b) / w, u]
    };
    let lines = [
        "g(0.25, 0.5) = (0.972271824132, 0.972271824132, 0.250000000000), 1.375000000000 from the z axis",
        "g(0.25, 0.25) = (1.278458913961, 0.506130225648, 0.250000000000), 1.375000000000 from the z axis",
    ];
    for ((u, v), line) in [(0.25, 0.5), (0.25, 0.25)].into_iter().zip(lines) {
        let x = g.eval(u, v);
        assert!((&x - surface(u, v)).amax() < 1e-14, "({u}, {v}): {x}");
        let text = format!(
            "g({u}, {v}) = ({:.12}, {:.12}, {:.12}), {:.12} from the z axis",
            x[0],
            x[1],
            x[2],
            x[0].hypot(x[1])
        );
        assert_eq!(text, line);
    }
}

/// `examples/octave_text_file.rs`: the B-spline of Octave's file agrees with Octave's own
/// `bspeval` values bit for bit.
#[test]
fn octave_text_file() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/octave_ref/expected/bspline_curves.txt"
    );
    let file = cagd_octave::text_format::read_text_file(path).unwrap();
    let matrix = |name: &str| {
        let a = file.matrix(name).unwrap();
        DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[[i, j]])
    };
    let degree = file.scalar("deg_p3_uniform").unwrap() as usize;
    let knots: Vec<f64> = matrix("knots_p3_uniform").iter().copied().collect();
    let curve = BSplineCurve::new(degree, knots, matrix("C_p3_uniform")).unwrap();
    assert_eq!(curve.domain(), (0.0, 2.0));
    let (us, octave) = (matrix("u_p3_uniform"), matrix("P_p3_uniform"));
    for (k, u) in us.iter().enumerate() {
        assert_eq!(curve.try_eval(*u).unwrap(), octave.column(k), "u = {u}");
    }
    // u = 1 is Octave's 12th parameter.
    assert_eq!(us[11], 1.0);
    let x = curve.try_eval(1.0).unwrap();
    assert_eq!(x, octave.column(11));
    assert_eq!(
        format!("C(1) = ({}, {})", x[0], x[1]),
        "C(1) = (-2.060143520962414, 5.648655513712225)"
    );
}

/// `examples/primer_2_4_exact.rs`: every point of the scheme by hand (midpoints, t = 1/2).
#[test]
fn primer_2_4_exact() {
    let int = |n: i64| q(n, 1);
    let control = DMatrix::from_row_slice(3, 4, &[0, 0, 8, 4, 0, 2, 2, 0, 0, 2, 0, 0]).map(int);
    let curve = BezierCurve::new(control).unwrap();
    let scheme = curve.scheme(q(1, 2));
    let col = |m: &DMatrix<Q>| -> Vec<Vec<Q>> {
        m.column_iter()
            .map(|c| c.iter().cloned().collect())
            .collect()
    };
    let v = |p: [(i64, i64); 3]| p.iter().map(|&(n, d)| q(n, d)).collect::<Vec<Q>>();
    assert_eq!(
        col(scheme.level(1).unwrap()),
        [
            v([(0, 1), (1, 1), (1, 1)]),
            v([(4, 1), (2, 1), (1, 1)]),
            v([(6, 1), (1, 1), (0, 1)])
        ]
    );
    assert_eq!(
        col(scheme.level(2).unwrap()),
        [v([(2, 1), (3, 2), (1, 1)]), v([(5, 1), (3, 2), (1, 2)])]
    );
    let b = scheme.point_on_curve();
    assert_eq!(b.as_slice(), v([(7, 2), (3, 2), (3, 4)]).as_slice());
    assert_eq!(
        format!("{scheme}b(1/2) = ({}, {}, {})", b[0], b[1], b[2]),
        "de Casteljau scheme, degree 3, t = 1/2\n\
         r = 0       r = 1       r = 2           r = 3\n\
         (0, 0, 0)\n\
         (0, 2, 2)   (0, 1, 1)\n\
         (8, 2, 0)   (4, 2, 1)   (2, 3/2, 1)\n\
         (4, 0, 0)   (6, 1, 0)   (5, 3/2, 1/2)   (7/2, 3/2, 3/4)\n\
         b(1/2) = (7/2, 3/2, 3/4)"
    );
}

//! Property tests for the Bernstein basis, Bézier curves and Bézier patches: the properties
//! the thesis proves (§2.2–2.4, §3.4–3.5), checked in `f64` with tolerances scaled to the data
//! and exactly in `BigRational`.

use cagd::bernstein::{bernstein, bernstein_all, bernstein_derivative_all};
use cagd::bezier::{BezierCurve, BezierPatch, Edge};
use cagd::Scalar;
use nalgebra::{DMatrix, DVector};
use num_rational::BigRational;
use proptest::prelude::*;

// ---------------------------------------------------------------------------------------------
// Strategies and helpers
// ---------------------------------------------------------------------------------------------

fn q(n: i64, d: i64) -> BigRational {
    <BigRational as Scalar>::from_ratio(n, d)
}

/// A curve of degree `0..=max_degree` in dimension `dims`, coordinates in [-10, 10].
fn curve(
    dims: std::ops::RangeInclusive<usize>,
    max_degree: usize,
) -> impl Strategy<Value = BezierCurve<f64>> {
    (dims, 0..=max_degree).prop_flat_map(|(d, n)| {
        prop::collection::vec(-10.0..10.0f64, d * (n + 1))
            .prop_map(move |v| BezierCurve::new(DMatrix::from_column_slice(d, n + 1, &v)).unwrap())
    })
}

/// A 3-D patch of degree `(0..=max, 0..=max)`, coordinates in [-10, 10].
fn patch(max: usize) -> impl Strategy<Value = BezierPatch<f64>> {
    (0..=max, 0..=max).prop_flat_map(|(m, n)| {
        prop::collection::vec(-10.0..10.0f64, 3 * (m + 1) * (n + 1)).prop_map(move |v| {
            let coords = v
                .chunks((m + 1) * (n + 1))
                .map(|c| DMatrix::from_row_slice(m + 1, n + 1, c))
                .collect();
            BezierPatch::new(coords).unwrap()
        })
    })
}

fn rational() -> impl Strategy<Value = BigRational> {
    (-20i64..=20, 1i64..=9).prop_map(|(n, d)| q(n, d))
}

/// A rational parameter in [0, 1].
fn unit_rational() -> impl Strategy<Value = BigRational> {
    (1i64..=12).prop_flat_map(|d| (0..=d).prop_map(move |k| q(k, d)))
}

fn rational_curve(max_degree: usize) -> impl Strategy<Value = BezierCurve<BigRational>> {
    (1usize..=3, 0..=max_degree).prop_flat_map(|(d, n)| {
        prop::collection::vec(rational(), d * (n + 1))
            .prop_map(move |v| BezierCurve::new(DMatrix::from_column_slice(d, n + 1, &v)).unwrap())
    })
}

fn rational_patch(max: usize) -> impl Strategy<Value = BezierPatch<BigRational>> {
    (0..=max, 0..=max, 1usize..=3).prop_flat_map(|(m, n, d)| {
        prop::collection::vec(rational(), d * (m + 1) * (n + 1)).prop_map(move |v| {
            let coords = v
                .chunks((m + 1) * (n + 1))
                .map(|c| DMatrix::from_row_slice(m + 1, n + 1, c))
                .collect();
            BezierPatch::new(coords).unwrap()
        })
    })
}

/// 1 + the largest absolute control coordinate: the size rounding errors scale with.
fn scale(control: &DMatrix<f64>) -> f64 {
    1.0 + control.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

fn patch_scale(p: &BezierPatch<f64>) -> f64 {
    1.0 + p
        .coordinates()
        .iter()
        .flat_map(|x| x.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

fn max_diff(a: &DVector<f64>, b: &DVector<f64>) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b.iter())
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

fn cross(o: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// Convex hull of 2-D points, counter-clockwise, without collinear points (Andrew's monotone
/// chain). One point for a single (or repeated) point, two for collinear input.
fn convex_hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut pts = points.to_vec();
    pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let mut lower: Vec<[f64; 2]> = Vec::new();
    for &p in &pts {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0.0 {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<[f64; 2]> = Vec::new();
    for &p in pts.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0.0 {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// Whether `x` lies in the axis-aligned box of `points` and on the inner side of every edge of
/// their convex hull, with tolerance `eps` (distances) — the check used for the convex hull
/// property.
fn in_convex_hull(points: &[[f64; 2]], x: [f64; 2], eps: f64) -> bool {
    for k in 0..2 {
        let lo = points.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
        let hi = points
            .iter()
            .map(|p| p[k])
            .fold(f64::NEG_INFINITY, f64::max);
        if x[k] < lo - eps || x[k] > hi + eps {
            return false;
        }
    }
    let hull = convex_hull(points);
    if hull.len() == 1 {
        return (x[0] - hull[0][0]).hypot(x[1] - hull[0][1]) <= eps;
    }
    // For two hull points both directed edges are checked: x must be on the segment's line.
    (0..hull.len()).all(|k| {
        let (a, b) = (hull[k], hull[(k + 1) % hull.len()]);
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        cross(a, b, x) >= -eps * len
    })
}

#[test]
fn hull_check_rejects_outside_points() {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]];
    assert_eq!(convex_hull(&square).len(), 4);
    assert!(in_convex_hull(&square, [0.5, 0.9], 1e-12));
    assert!(!in_convex_hull(&square, [1.1, 0.5], 1e-12));
    // Inside the box, outside the hull (a triangle).
    let triangle = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    assert!(!in_convex_hull(&triangle, [0.9, 0.9], 1e-12));
    assert!(in_convex_hull(&triangle, [0.4, 0.4], 1e-12));
    // Collinear: only the segment.
    let line = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
    assert!(in_convex_hull(&line, [1.5, 1.5], 1e-12));
    assert!(!in_convex_hull(&line, [1.5, 1.4], 1e-12));
}

// ---------------------------------------------------------------------------------------------
// Bernstein polynomials
// ---------------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Izrek 2.7 (partition of unity) and non-negativity on [0, 1].
    #[test]
    fn bernstein_partition_of_unity_and_non_negative(n in 0usize..60, t in 0.0..=1.0f64) {
        let b = bernstein_all(n, t);
        prop_assert_eq!(b.len(), n + 1);
        prop_assert!(b.iter().all(|&x| x >= 0.0));
        let sum: f64 = b.iter().sum();
        prop_assert!((sum - 1.0).abs() <= 1e-13, "sum = {}", sum);
    }

    /// The direct formula and the recurrence agree; symmetry B_i^n(t) = B_{n−i}^n(1−t) (Izrek 2.8).
    #[test]
    fn bernstein_direct_formula_and_symmetry(n in 0usize..40, t in 0.0..=1.0f64) {
        let all = bernstein_all(n, t);
        let mirrored = bernstein_all(n, 1.0 - t);
        for i in 0..=n {
            let direct = bernstein(i, n, t);
            prop_assert!((direct - all[i]).abs() <= 1e-13 * all[i] + 1e-300,
                "B_{}^{}({}) = {} vs {}", i, n, t, direct, all[i]);
            prop_assert!((all[i] - mirrored[n - i]).abs() <= 1e-13);
        }
    }

    /// Exactly in rationals: the sum is 1 and every derivative order r ≥ 1 sums to 0.
    #[test]
    fn bernstein_exact_sums(n in 0usize..25, t in unit_rational(), r in 1usize..4) {
        let sum = bernstein_all(n, t.clone()).into_iter().fold(q(0, 1), |a, b| a + b);
        prop_assert_eq!(sum, q(1, 1));
        let dsum = bernstein_derivative_all(n, r, t).into_iter().fold(q(0, 1), |a, b| a + b);
        prop_assert_eq!(dsum, q(0, 1));
    }
}

// ---------------------------------------------------------------------------------------------
// Curves in f64
// ---------------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// §2.3 property 4: b(0) = b_0 and b(1) = b_n, exactly.
    #[test]
    fn endpoint_interpolation(c in curve(1..=4, 10)) {
        let n = c.degree();
        prop_assert_eq!(c.eval(0.0), c.control_point(0).unwrap());
        prop_assert_eq!(c.eval(1.0), c.control_point(n).unwrap());
    }

    /// §2.3 property 5: the reversed polygon traces the curve backwards.
    #[test]
    fn symmetry(c in curve(1..=4, 10), t in 0.0..=1.0f64) {
        let tol = 1e-12 * scale(c.control());
        prop_assert!(max_diff(&c.reversed().eval(1.0 - t), &c.eval(t)) <= tol);
    }

    /// §2.3 property 1: mapping the control points by x ↦ A x + c maps the curve.
    #[test]
    fn affine_invariance(
        c in curve(3..=3, 8),
        a in prop::collection::vec(-2.0..2.0f64, 9),
        shift in prop::collection::vec(-5.0..5.0f64, 3),
        t in 0.0..=1.0f64,
    ) {
        let a = DMatrix::from_row_slice(3, 3, &a);
        let shift = DVector::from_vec(shift);
        let mut mapped = &a * c.control();
        for mut col in mapped.column_iter_mut() {
            col += &shift;
        }
        let image = BezierCurve::new(mapped).unwrap();
        let expected = &a * c.eval(t) + &shift;
        let tol = 1e-11 * (6.0 * scale(c.control()) + 5.0);
        prop_assert!(max_diff(&image.eval(t), &expected) <= tol);
    }

    /// Izrek 2.12: for t ∈ [0, 1] the point lies in the convex hull of the control points
    /// (checked as: inside the bounding box and inside every half-plane of the hull).
    #[test]
    fn convex_hull_property(c in curve(2..=2, 9), t in 0.0..=1.0f64) {
        let points: Vec<[f64; 2]> =
            c.control().column_iter().map(|p| [p[0], p[1]]).collect();
        let x = c.eval(t);
        prop_assert!(in_convex_hull(&points, [x[0], x[1]], 1e-11 * scale(c.control())),
            "b({}) = {:?} outside the hull of {:?}", t, x, points);
    }

    /// Izrek 2.9: de Casteljau = Bernstein form, and for cubics also = the matrix form of
    /// the matrix-form notes.
    #[test]
    fn de_casteljau_equals_bernstein_and_matrix_form(
        c in curve(1..=4, 10),
        cubic in curve(1..=3, 3).prop_filter("cubic", |c| c.degree() == 3),
        t in 0.0..=1.0f64,
    ) {
        let tol = 1e-12 * scale(c.control());
        prop_assert!(max_diff(&c.eval(t), &c.eval_bernstein(t)) <= tol);
        let tol = 1e-12 * scale(cubic.control());
        let x = cubic.eval(t);
        prop_assert!(max_diff(&x, &cubic.eval_bernstein(t)) <= tol);
        prop_assert!(max_diff(&x, &cubic.eval_matrix_form(t)) <= tol);
        // And the scheme's last point is the same computation, bit for bit.
        prop_assert_eq!(c.scheme(t).point_on_curve(), c.eval(t));
    }

    /// §2.4: the derivative curve matches a central difference, and `Curve::eval_derivative`
    /// matches the hodograph.
    #[test]
    fn derivative_matches_central_difference(c in curve(1..=3, 8), t in 0.01..0.99f64) {
        let n = c.degree();
        prop_assume!(n >= 1);
        let h = 1e-5;
        let fd = (c.eval(t + h) - c.eval(t - h)) / (2.0 * h);
        let hodograph = c.hodograph().unwrap();
        prop_assert_eq!(hodograph.degree(), n - 1);
        let d = hodograph.eval(t);
        let bound = 1e-9 * (1.0 + (n * n * n) as f64 * 8.0 * scale(c.control()));
        prop_assert!(max_diff(&fd, &d) <= bound, "fd {:?} vs {:?}", fd, d);
        let from_trait = cagd::CurveDeriv::eval_derivative(&c, t);
        prop_assert!(max_diff(&from_trait, &d) <= 1e-11 * n as f64 * scale(c.control()));
        // Second derivative against a central difference of the first.
        if n >= 2 {
            let d2 = c.derivative(2).unwrap();
            prop_assert_eq!(d2.degree(), n - 2);
            let fd2 = (hodograph.eval(t + h) - hodograph.eval(t - h)) / (2.0 * h);
            let bound = 1e-9 * (1.0 + (n * n * n * n) as f64 * 16.0 * scale(c.control()));
            prop_assert!(max_diff(&fd2, &d2.eval(t)) <= bound);
        }
    }

    /// Subdivision at u: the halves over [0, u] and [u, 1] reproduce the curve, and meet at
    /// b(u).
    #[test]
    fn subdivision_reproduces_the_curve(
        c in curve(1..=3, 9),
        u in 0.05..0.95f64,
        s in 0.0..=1.0f64,
    ) {
        let (left, right) = c.subdivide(u).unwrap();
        let tol = 1e-11 * scale(c.control());
        let n = c.degree();
        prop_assert_eq!(left.control_point(n).unwrap(), c.eval(u));
        prop_assert_eq!(right.control_point(0).unwrap(), c.eval(u));
        let x = u * s;
        prop_assert!(max_diff(&left.eval(x), &c.eval(x)) <= tol);
        let y = u + (1.0 - u) * s;
        prop_assert!(max_diff(&right.eval(y), &c.eval(y)) <= tol);
    }

    /// Degree elevation leaves the curve unchanged.
    #[test]
    fn degree_elevation_keeps_the_curve(c in curve(1..=3, 9), t in 0.0..=1.0f64) {
        let e = c.elevate();
        prop_assert_eq!(e.degree(), c.degree() + 1);
        let ee = e.elevate();
        let tol = 1e-12 * scale(c.control());
        prop_assert!(max_diff(&e.eval(t), &c.eval(t)) <= tol);
        prop_assert!(max_diff(&ee.eval(t), &c.eval(t)) <= tol);
    }

    /// A curve over [a, b] at u is the unit curve at (u − a)/(b − a) (§2.3 property 2).
    #[test]
    fn interval_reparametrisation(
        c in curve(1..=3, 7),
        a in -5.0..5.0f64,
        len in 0.5..4.0f64,
        t in 0.0..=1.0f64,
    ) {
        let wide = c.clone().with_interval(a, a + len).unwrap();
        let u = a + t * len;
        let tol = 1e-10 * scale(c.control());
        prop_assert!(max_diff(&wide.eval(u), &c.eval(wide.local_parameter(u))) <= tol);
        prop_assert!(max_diff(&wide.eval(u), &c.eval(t)) <= tol * 10.0);
    }

    /// `eval_many` is column-wise `eval`, bit for bit.
    #[test]
    fn eval_many_is_eval_per_column(c in curve(1..=3, 6), ts in prop::collection::vec(0.0..=1.0f64, 1..8)) {
        let all = c.eval_many(&ts).unwrap();
        prop_assert_eq!(all.shape(), (c.dim(), ts.len()));
        for (k, &t) in ts.iter().enumerate() {
            prop_assert_eq!(all.column(k).into_owned(), c.eval(t));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Patches in f64
// ---------------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// §3.4 property 5: the boundary curves are the Bézier curves of the boundary rows and
    /// columns of the net — bit for bit, since the bilinear step at u ∈ {0, 1} or v ∈ {0, 1}
    /// reduces to the curve's linear step.
    #[test]
    fn boundary_curves_are_boundary_row_curves(p in patch(5), s in 0.0..=1.0f64) {
        prop_assert_eq!(p.boundary(Edge::U0).eval(s), p.eval(0.0, s));
        prop_assert_eq!(p.boundary(Edge::U1).eval(s), p.eval(1.0, s));
        prop_assert_eq!(p.boundary(Edge::V0).eval(s), p.eval(s, 0.0));
        prop_assert_eq!(p.boundary(Edge::V1).eval(s), p.eval(s, 1.0));
        // §3.4 property 1: the corners are interpolated.
        let (m, n) = p.degree();
        prop_assert_eq!(p.eval(0.0, 0.0), p.control_point(0, 0).unwrap());
        prop_assert_eq!(p.eval(0.0, 1.0), p.control_point(0, n).unwrap());
        prop_assert_eq!(p.eval(1.0, 0.0), p.control_point(m, 0).unwrap());
        prop_assert_eq!(p.eval(1.0, 1.0), p.control_point(m, n).unwrap());
    }

    /// Grid evaluation through basis matrices = per-point tensor de Casteljau = Bernstein form.
    #[test]
    fn grid_equals_per_point_de_casteljau(
        p in patch(6),
        us in prop::collection::vec(0.0..=1.0f64, 1..6),
        vs in prop::collection::vec(0.0..=1.0f64, 1..6),
    ) {
        let grid = p.try_eval_grid(&us, &vs).unwrap();
        prop_assert_eq!(grid.dim(), (us.len(), vs.len(), 3));
        let tol = 1e-12 * patch_scale(&p);
        for (a, &u) in us.iter().enumerate() {
            for (b, &v) in vs.iter().enumerate() {
                let x = p.eval(u, v);
                prop_assert_eq!(&p.scheme(u, v).point_on_surface(), &x);
                prop_assert!(max_diff(&x, &p.eval_bernstein(u, v)) <= tol);
                for k in 0..3 {
                    prop_assert!((grid[[a, b, k]] - x[k]).abs() <= tol,
                        "grid[{}, {}, {}] = {} vs {}", a, b, k, grid[[a, b, k]], x[k]);
                }
            }
        }
    }

    /// Trditev 3.3: ∂u, ∂v and the twist ∂²/∂u∂v match central differences.
    #[test]
    fn patch_partials_match_central_differences(p in patch(4), u in 0.05..0.95f64, v in 0.05..0.95f64) {
        let (m, n) = p.degree();
        prop_assume!(m >= 1 && n >= 1);
        let sc = patch_scale(&p);
        let h = 1e-5;
        let xu = (p.eval(u + h, v) - p.eval(u - h, v)) / (2.0 * h);
        let xv = (p.eval(u, v + h) - p.eval(u, v - h)) / (2.0 * h);
        let bound = 1e-9 * (1.0 + 8.0 * (m.max(n).pow(3)) as f64 * sc);
        prop_assert!(max_diff(&xu, &p.derivative(1, 0).unwrap().eval(u, v)) <= bound);
        prop_assert!(max_diff(&xv, &p.derivative(0, 1).unwrap().eval(u, v)) <= bound);
        let h = 1e-4;
        let xuv = (p.eval(u + h, v + h) - p.eval(u + h, v - h) - p.eval(u - h, v + h)
            + p.eval(u - h, v - h)) / (4.0 * h * h);
        let twist = p.twist().unwrap();
        prop_assert_eq!(twist.degree(), (m - 1, n - 1));
        prop_assert!(max_diff(&xuv, &twist.eval(u, v)) <= 1e-5 * (1.0 + 16.0 * (m * n).pow(2) as f64 * sc));
    }

    /// Higher orders: ∂u^r∂v^s is the r-fold u-derivative of the s-fold v-derivative.
    #[test]
    fn higher_partials_compose(p in patch(5), u in 0.0..=1.0f64, v in 0.0..=1.0f64) {
        let (m, n) = p.degree();
        let (r, s) = (m.min(2), n.min(2));
        let direct = p.derivative(r, s).unwrap();
        let mut composed = p.clone();
        for _ in 0..s { composed = composed.derivative(0, 1).unwrap(); }
        for _ in 0..r { composed = composed.derivative(1, 0).unwrap(); }
        prop_assert_eq!(direct.degree(), (m - r, n - s));
        let tol = 1e-11 * 16.0 * (m * n + 1).pow(2) as f64 * patch_scale(&p);
        prop_assert!(max_diff(&direct.eval(u, v), &composed.eval(u, v)) <= tol);
    }
}

// ---------------------------------------------------------------------------------------------
// Exact rational versions
// ---------------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// de Casteljau = Bernstein = matrix form, exactly.
    #[test]
    fn exact_de_casteljau_bernstein_matrix_form(c in rational_curve(6), t in unit_rational()) {
        let x = c.eval(t.clone());
        prop_assert_eq!(&x, &c.eval_bernstein(t.clone()));
        prop_assert_eq!(&x, &c.eval_matrix_form(t.clone()));
        prop_assert_eq!(&x, &c.matrix_form().to_bezier().eval(t));
    }

    /// Subdivision, elevation, symmetry and reparametrisation, exactly.
    #[test]
    fn exact_subdivision_elevation_symmetry(
        c in rational_curve(6),
        u in (1i64..=8).prop_map(|k| q(k, 9)),
        s in unit_rational(),
    ) {
        let (left, right) = c.subdivide(u.clone()).unwrap();
        let x = u.clone() * s.clone();
        prop_assert_eq!(left.eval(x.clone()), c.eval(x));
        let y = u.clone() + (q(1, 1) - u) * s.clone();
        prop_assert_eq!(right.eval(y.clone()), c.eval(y));
        prop_assert_eq!(c.elevate().eval(s.clone()), c.eval(s.clone()));
        prop_assert_eq!(c.reversed().eval(q(1, 1) - s.clone()), c.eval(s.clone()));
        let wide = c.clone().with_interval(q(-3, 2), q(5, 2)).unwrap();
        prop_assert_eq!(wide.eval(q(-3, 2) + q(4, 1) * s.clone()), c.eval(s));
    }

    /// Derivatives compose exactly: d²b = d(db), and the scheme's derivative is the hodograph.
    #[test]
    fn exact_derivatives(c in rational_curve(6), t in unit_rational()) {
        let n = c.degree();
        prop_assume!(n >= 2);
        let d1 = c.derivative(1).unwrap();
        prop_assert_eq!(c.derivative(2).unwrap(), d1.derivative(1).unwrap());
        prop_assert_eq!(c.eval_derivative(t.clone()), d1.eval(t));
    }

    /// Patches: grid = de Casteljau = Bernstein, boundary curves, derivative composition.
    #[test]
    fn exact_patch_evaluations(
        p in rational_patch(4),
        us in prop::collection::vec(unit_rational(), 1..4),
        vs in prop::collection::vec(unit_rational(), 1..4),
    ) {
        let grid = p.try_eval_grid(&us, &vs).unwrap();
        for (a, u) in us.iter().enumerate() {
            for (b, v) in vs.iter().enumerate() {
                let x = p.eval(u.clone(), v.clone());
                prop_assert_eq!(&x, &p.eval_bernstein(u.clone(), v.clone()));
                for k in 0..p.dim() {
                    prop_assert_eq!(&grid[[a, b, k]], &x[k]);
                }
            }
        }
        let s = us[0].clone();
        prop_assert_eq!(p.boundary(Edge::U0).eval(s.clone()), p.eval(q(0, 1), s.clone()));
        prop_assert_eq!(p.boundary(Edge::V1).eval(s.clone()), p.eval(s.clone(), q(1, 1)));
        let (m, n) = p.degree();
        if m >= 1 && n >= 1 {
            let twist = p.twist().unwrap();
            let composed = p.derivative(1, 0).unwrap().derivative(0, 1).unwrap();
            prop_assert_eq!(twist, composed);
        }
    }
}

//! Hostile arguments to the public functions of the core: no function that returns `Result`
//! panics, whatever it is given (sizes up to `usize::MAX`, indices out of range, knot vectors
//! too short, magnitudes near the `f64` range, NaN and ±∞); index arguments are checked and
//! sizes that overflow are [`Error::TooLarge`]. The regressions first (each an input reported
//! from outside, with the error it now gives), then a property test that calls the
//! constructors and evaluators with arbitrary arguments under `catch_unwind`.

use std::panic::{catch_unwind, AssertUnwindSafe};

use cagd::bspline::{basis_all, cox_de_boor, find_span, BSplineCurve, BSplineSurface, KnotVector};
use cagd::conversion::{convert, CubicForm};
use cagd::lagrange::{basis_product, try_chebyshev_nodes, Lagrange};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::spline::{solve_tridiagonal, CubicSpline, EndCondition};
use cagd::{
    BezierCurve, BezierPatch, Curve, Error, GordonSurface, HermiteCubic, Surface, Tolerance,
};
use nalgebra::{DMatrix, DVector};

fn too_large<T: std::fmt::Debug>(r: cagd::Result<T>) -> bool {
    matches!(r, Err(Error::TooLarge { .. }))
}

#[test]
fn tridiagonal_right_hand_sides_of_different_lengths_are_a_shape_error() {
    let rhs = [DVector::from_element(2, 5.0), DVector::from_element(1, 5.0)];
    let r = solve_tridiagonal(&[0.0, 1.0], &[4.0, 4.0], &[1.0, 0.0], &rhs);
    assert!(matches!(r, Err(Error::ShapeMismatch { .. })), "{r:?}");
}

#[test]
fn spans_and_bases_of_short_knot_vectors_are_knot_count_errors() {
    // Four control points of degree 3 need eight knots.
    for knots in [
        &[][..],
        &[0.0][..],
        &[0.0, 1.0][..],
        &[0.0, 0.0, 1.0, 1.0][..],
    ] {
        let r = find_span(3, 4, knots, &0.5);
        assert!(
            matches!(r, Err(Error::KnotCount { .. })),
            "{knots:?}: {r:?}"
        );
        let r = basis_all(3, 4, knots, &0.5);
        assert!(
            matches!(r, Err(Error::KnotCount { .. })),
            "{knots:?}: {r:?}"
        );
    }
    // Fewer control points than the degree needs, and degrees that overflow.
    let r = find_span(3, 2, &[0.0, 0.0, 1.0, 1.0, 1.0, 1.0], &0.5);
    assert!(matches!(r, Err(Error::TooFewControlPoints { .. })), "{r:?}");
    let r = find_span(usize::MAX, 2, &[0.0, 1.0], &0.5);
    assert!(r.is_err(), "{r:?}");
    let r = basis_all(1, usize::MAX, &[0.0, 1.0], &0.5);
    assert!(r.is_err(), "{r:?}");
    // A domain of one point.
    let r = find_span(1, 2, &[0.0, 1.0, 1.0, 2.0], &1.0);
    assert!(matches!(r, Err(Error::EmptyInterval { .. })), "{r:?}");
}

#[test]
fn knot_vectors_and_clamped_curves_of_absurd_sizes_are_too_large() {
    let control = DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 2.0]);
    let r = BSplineCurve::clamped(usize::MAX, control.clone());
    assert!(matches!(r, Err(Error::TooFewControlPoints { .. })), "{r:?}");
    assert!(too_large(KnotVector::<f64>::clamped_uniform(2, usize::MAX)));
    assert!(too_large(KnotVector::<f64>::uniform(2, usize::MAX)));
    assert!(too_large(KnotVector::<f64>::clamped_uniform(
        1,
        usize::MAX / 2
    )));
    assert!(too_large(KnotVector::<f64>::uniform(
        usize::MAX - 1,
        usize::MAX
    )));
    let r = KnotVector::<f64>::clamped_uniform(usize::MAX, 3);
    assert!(matches!(r, Err(Error::TooFewControlPoints { .. })), "{r:?}");
    // Ordinary sizes still work.
    assert_eq!(KnotVector::<f64>::clamped_uniform(1, 2).unwrap().len(), 4);
}

#[test]
fn cox_de_boor_checks_its_index() {
    let knots = [0.0, 1.0, 2.0, 3.0];
    assert_eq!(cox_de_boor(0, 2, &knots, &1.5).unwrap(), 0.75);
    for (i, p) in [(1, 2), (3, 0), (0, 3), (usize::MAX, 0), (0, usize::MAX)] {
        let r = cox_de_boor(i, p, &knots, &1.5);
        assert!(
            matches!(r, Err(Error::InvalidArgument { .. })),
            "{i}, {p}: {r:?}"
        );
    }
}

#[test]
fn conversion_checks_the_shape_of_the_geometry() {
    for (rows, cols) in [(2, 3), (2, 5), (0, 4), (3, 0)] {
        let g = DMatrix::<f64>::zeros(rows, cols);
        let r = convert(&g, CubicForm::Hermite, CubicForm::Bezier);
        if cols == 4 {
            assert!(r.is_ok(), "{rows}x{cols}");
        } else {
            assert!(
                matches!(r, Err(Error::ShapeMismatch { .. })),
                "{rows}x{cols}: {r:?}"
            );
        }
    }
}

#[test]
fn node_and_sample_counts_that_cannot_be_held_are_too_large() {
    assert!(too_large(cagd::linspace::try_linspace(
        0.0,
        1.0,
        usize::MAX
    )));
    assert!(too_large(try_chebyshev_nodes(usize::MAX)));
    assert_eq!(
        cagd::linspace::try_linspace(0.0, 1.0, 3).unwrap(),
        vec![0.0, 0.5, 1.0]
    );
    assert_eq!(try_chebyshev_nodes(3).unwrap(), vec![0.0, 0.5, 1.0]);
}

/// A random stream behind a shared reference, so that arguments can be drawn inside the
/// argument lists of other draws (the 64-bit LCG of the other tests).
struct Rng(std::cell::Cell<u64>);

impl Rng {
    fn next(&self) -> f64 {
        let x = self
            .0
            .get()
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0.set(x);
        (x >> 11) as f64 / (1u64 << 53) as f64
    }
    fn signed(&self) -> f64 {
        2.0 * self.next() - 1.0
    }
    fn below(&self, n: usize) -> usize {
        ((self.next() * n as f64) as usize).min(n - 1)
    }
}

/// A value for an argument: ordinary, tiny, huge, non-finite.
fn value(rng: &Rng) -> f64 {
    match rng.below(12) {
        0 => f64::NAN,
        1 => f64::INFINITY,
        2 => f64::NEG_INFINITY,
        3 => f64::MAX,
        4 => -1.5e308,
        5 => 5e-324,
        6 => 0.0,
        7 => 1e154,
        _ => 10.0 * rng.signed(),
    }
}

/// A size or index: mostly small, sometimes at or near `usize::MAX`.
fn size(rng: &Rng) -> usize {
    match rng.below(10) {
        0 => usize::MAX,
        1 => usize::MAX / 2 + 1,
        2 => 1 << 40,
        _ => rng.below(6),
    }
}

/// A small size, for arguments that are allocated by the test itself.
fn small(rng: &Rng) -> usize {
    rng.below(6)
}

fn values(rng: &Rng, n: usize) -> Vec<f64> {
    (0..n).map(|_| value(rng)).collect()
}

fn matrix(rng: &Rng, rows: usize, cols: usize) -> DMatrix<f64> {
    DMatrix::from_fn(rows, cols, |_, _| value(rng))
}

/// Sorted knots, with repeats, or unsorted and non-finite ones.
fn knots(rng: &Rng, n: usize) -> Vec<f64> {
    let mut k = values(rng, n);
    if rng.below(3) > 0 {
        k.retain(|x| x.is_finite());
        k.sort_by(|a, b| a.partial_cmp(b).unwrap());
    }
    k
}

/// One call with arbitrary arguments: the index picks the function.
fn call(op: usize, rng: &Rng) {
    let t = value(rng);
    match op {
        0 => {
            let c = BezierCurve::new(matrix(rng, small(rng), small(rng)));
            if let Ok(c) = c {
                let _ = c.eval(t);
                let _ = c.try_eval(t);
                let _ = c.eval_many(&values(rng, 3));
                let _ = c.derivative(size(rng));
                let _ = c.subdivide(t);
                let _ = c.scheme(t);
                let _ = c.with_interval(value(rng), value(rng));
            }
        }
        1 => {
            let (d, m, n) = (small(rng), small(rng), small(rng));
            let coords = (0..d).map(|_| matrix(rng, m, n)).collect();
            if let Ok(p) = BezierPatch::new(coords) {
                let _ = p.eval(t, value(rng));
                let _ = p.try_eval(t, value(rng));
                let _ = p.try_eval_grid(&values(rng, 2), &values(rng, 2));
                let _ = p.derivative(size(rng), size(rng));
                let _ = p.control_point(size(rng), size(rng));
            }
        }
        2 => {
            let (p, n, d) = (size(rng), small(rng), small(rng));
            let k = knots(rng, small(rng) + small(rng));
            let _ = find_span(p, n, &k, &t);
            let _ = basis_all(p, n, &k, &t);
            let _ = cox_de_boor(size(rng), p, &k, &t);
            if let Ok(c) = BSplineCurve::new(p, k.clone(), matrix(rng, d, n)) {
                let _ = c.eval(t);
                let _ = c.try_eval(t);
                let _ = c.de_boor(t);
                let _ = c.basis(&t);
                let _ = c.eval_many(&values(rng, 4));
                let _ = c.derivative();
                let _ = c.insert_knot(value(rng));
                let _ = c.insert_knots(&values(rng, 2));
                let _ = cagd::integral::bspline_integral(&c);
            }
            let _ = BSplineCurve::clamped(p, matrix(rng, d, n));
            let _ = BSplineCurve::uniform_cubic(&matrix(rng, d, n), rng.below(2) == 0);
        }
        3 => {
            let (p, n) = (size(rng), size(rng));
            let _ = KnotVector::<f64>::clamped_uniform(p, n);
            let _ = KnotVector::<f64>::uniform(p, n);
            let _ = KnotVector::new(knots(rng, small(rng)));
        }
        4 => {
            let (p, n, d) = (size(rng), small(rng), small(rng));
            let k = knots(rng, small(rng) + small(rng));
            let w = values(rng, n);
            if let Ok(c) = NurbsCurve::new(p, k, matrix(rng, d, n), w) {
                let _ = c.eval(t);
                let _ = c.try_eval(t);
                let _ = c.basis(&t);
                let _ = c.try_eval_derivative(t);
                let _ = c.insert_knots(&values(rng, 2));
                let mut out = vec![0.0; 2 * d];
                let _ = c.eval_many_into(&values(rng, 2), &mut out);
            }
            let _ = NurbsCurve::circle(value(rng), &values(rng, small(rng)));
            let _ = NurbsCurve::arc(value(rng), &values(rng, small(rng)), t, value(rng));
        }
        5 => {
            let (p, q, d) = (size(rng), size(rng), small(rng));
            let (m, n) = (small(rng), small(rng));
            let coords: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
            if let Ok(s) = BSplineSurface::clamped(p, q, coords.clone()) {
                let _ = s.eval(t, value(rng));
                let _ = s.try_eval(t, value(rng));
                let mut out = vec![0.0; 4 * d];
                let _ = s.eval_grid_into(&values(rng, 2), &values(rng, 2), &mut out);
                let weights = matrix(rng, m, n);
                let (ku, kv) = s.knots();
                let _ = NurbsSurface::new(
                    p,
                    q,
                    ku.as_slice().to_vec(),
                    kv.as_slice().to_vec(),
                    coords,
                    weights,
                );
            }
        }
        6 => {
            let n = small(rng);
            let xs = values(rng, n);
            let ys = matrix(rng, small(rng), n);
            let end = match rng.below(3) {
                0 => EndCondition::Natural,
                1 => EndCondition::Closed,
                _ => EndCondition::Clamped {
                    start: DVector::from_vec(values(rng, small(rng))),
                    end: DVector::from_vec(values(rng, small(rng))),
                },
            };
            if let Ok(s) = CubicSpline::interpolate_with_params(ys, xs, end) {
                let _ = s.eval(t);
                let _ = s.try_eval(t);
            }
            let k = small(rng);
            let rhs: Vec<DVector<f64>> = (0..k)
                .map(|_| DVector::from_vec(values(rng, small(rng))))
                .collect();
            let _ = solve_tridiagonal(
                &values(rng, small(rng)),
                &values(rng, k),
                &values(rng, small(rng)),
                &rhs,
            );
        }
        7 => {
            let nodes = values(rng, small(rng));
            let _ = basis_product(&nodes, size(rng), &t);
            if let Ok(l) = Lagrange::new(nodes) {
                let _ = l.basis(&t);
                let mut out = vec![0.0; small(rng)];
                let _ = l.basis_into(&t, &mut out);
                let _ = l.interpolate(&matrix(rng, small(rng), small(rng)), &t);
            }
            let _ = try_chebyshev_nodes(size(rng));
            let _ = cagd::linspace::try_linspace(t, value(rng), size(rng));
        }
        8 => {
            let v = |rng: &Rng, d: usize| DVector::from_vec(values(rng, d));
            let d = small(rng);
            if let Ok(h) = HermiteCubic::new(v(rng, d), v(rng, d), v(rng, d), v(rng, small(rng))) {
                let _ = h.eval(t);
                let _ = h.to_bezier();
            }
            let _ = HermiteCubic::from_geometry(matrix(rng, small(rng), small(rng)));
            let forms = [CubicForm::Hermite, CubicForm::Bezier, CubicForm::BSpline];
            let g = matrix(rng, small(rng), small(rng) + 2);
            let _ = convert(&g, forms[rng.below(3)], forms[rng.below(3)]);
        }
        9 => {
            let (m, n, d) = (small(rng), small(rng), small(rng));
            let net: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
            let _ = cagd::coons::discrete_coons(&net);
            if let Ok(mask) = cagd::coons::Mask::new(value(rng), value(rng)) {
                let _ = cagd::coons::solve_mask(&net, &mask, &cagd::Limits::default());
            }
        }
        10 => {
            // Coons and Gordon over Bézier boundaries of arbitrary values.
            let d = 1 + small(rng) % 3;
            let curve = |rng: &Rng| BezierCurve::new(matrix(rng, d, 1 + small(rng))).ok();
            let (Some(c1), Some(c2), Some(d1), Some(d2)) =
                (curve(rng), curve(rng), curve(rng), curve(rng))
            else {
                return;
            };
            if let Ok(p) = cagd::CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::default()) {
                let _ = p.eval(t, value(rng));
                let _ = p.try_eval(t, value(rng));
            }
            let (Some(us), Some(vs)) = (
                (0..small(rng))
                    .map(|_| curve(rng))
                    .collect::<Option<Vec<_>>>(),
                (0..small(rng))
                    .map(|_| curve(rng))
                    .collect::<Option<Vec<_>>>(),
            ) else {
                return;
            };
            let (un, vn) = (values(rng, us.len()), values(rng, vs.len()));
            if let Ok(g) = GordonSurface::new(un, vn, us, vs) {
                let _ = g.eval(t, value(rng));
                let _ = g.try_eval(t, value(rng));
                let _ = g.eval_parts(t, value(rng));
            }
        }
        _ => {
            let d = small(rng);
            let v = |rng: &Rng| DVector::from_vec(values(rng, d));
            let _ = cagd::continuity::joint((&v(rng), &v(rng)), (&v(rng), &v(rng)), value(rng));
            let _ = cagd::continuity::c1_free_point(&v(rng), &v(rng));
            let _ = cagd::bernstein::binomial_f64(size(rng), size(rng));
        }
    }
}

const OPS: usize = 12;

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(3000))]

    /// Every call returns (an `Err` is fine); none panics.
    #[test]
    fn no_public_function_panics_on_any_argument(
        op in 0..OPS,
        seed in proptest::prelude::any::<u64>(),
    ) {
        if std::env::var_os("CAGD_HOSTILE_TRACE").is_some() {
            eprintln!("op {op} seed {seed}");
        }
        let rng = Rng(std::cell::Cell::new(seed | 1));
        let outcome = catch_unwind(AssertUnwindSafe(|| call(op, &rng)));
        proptest::prop_assert!(outcome.is_ok(), "operation {} with seed {} panicked", op, seed);
    }
}

//! Hostile arguments to the public functions of the core: no function that returns `Result`
//! panics, whatever it is given (sizes up to `usize::MAX`, indices out of range, knot vectors
//! too short, magnitudes near the `f64` range, NaN and ±∞); index arguments are checked and
//! sizes that overflow are [`Error::TooLarge`]. The regressions first (each an input reported
//! from outside, with the error it now gives), then a property test that calls the
//! constructors and evaluators with arbitrary arguments under `catch_unwind`.

use std::panic::{catch_unwind, AssertUnwindSafe};

use cagd::bspline::{basis_all, cox_de_boor, find_span, BSplineCurve, KnotVector};
use cagd::conversion::{convert, CubicForm};
use cagd::lagrange::try_chebyshev_nodes;
use cagd::spline::solve_tridiagonal;
use cagd::Error;
use cagd_test_support::hostile_calls::{call, Draws, GROUPS, OPS};
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

// ------------------------------------------------------------------------------------------
// The calls reported from outside (issue 23), each with what it gives now.

fn overflow<T: std::fmt::Debug>(r: cagd::Result<T>) -> bool {
    matches!(r, Err(Error::Overflow { .. }))
}

fn non_finite<T: std::fmt::Debug>(r: cagd::Result<T>) -> bool {
    matches!(r, Err(Error::NonFinite { .. }))
}

#[test]
fn nan_and_infinite_arguments_are_refused() {
    let l = cagd::lagrange::Lagrange::new(vec![0.0, 0.5, 1.0]).unwrap();
    assert!(non_finite(l.interpolate(
        &DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 0.0]),
        &f64::NAN
    )));
    let nan = DMatrix::from_row_slice(2, 2, &[1.0, f64::NAN, 0.0, 1.0]);
    assert!(non_finite(cagd::conversion::invert(&nan)));
    let g = DMatrix::from_row_slice(1, 4, &[0.0, f64::NAN, 1.0, 2.0]);
    assert!(non_finite(convert(
        &g,
        CubicForm::Hermite,
        CubicForm::Bezier
    )));
    let v = DVector::from_vec(vec![1.0, f64::NAN]);
    assert!(non_finite(cagd::continuity::c1_free_point(&v, &v)));
    assert!(non_finite(cagd::linspace::try_linspace(f64::NAN, 1.0, 5)));
    assert!(non_finite(cagd::coons::Mask::from_alpha(f64::NAN)));
    assert!(non_finite(cagd::bspline::basis_functions(
        1,
        &[0.0, 0.0, 1.0, 1.0],
        1,
        &f64::NAN
    )));
}

#[test]
fn finite_input_never_gives_an_ok_holding_inf_or_nan() {
    use cagd::{BezierCurve, CubicSpline, EndCondition, GordonSurface, NurbsCurve, SampledCurve};
    // An interval whose width overflows: refused where the width first appears.
    let control = DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 0.0]);
    assert!(overflow(BezierCurve::new_on_interval(
        control, -1e308, 1e308
    )));
    // The derivative of control points ±1.7·10³⁰⁸.
    let c = BezierCurve::new(DMatrix::from_row_slice(1, 3, &[1.7e308, -1.7e308, 1.7e308])).unwrap();
    assert!(overflow(c.derivative(1)));
    assert!(overflow(c.hodograph()));
    // Knots a few subnormals apart.
    let knots = vec![0.0, 0.0, 0.0, 5e-324, 1e-320, 1.0, 1.0, 1.0];
    assert!(overflow(BSplineCurve::new(2, knots, DMatrix::zeros(1, 5))));
    // NURBS weights all 10³⁰⁸ or all 5·10⁻³²⁴: the curve of weights all 1 (scaled by a power
    // of two into [1, 2): exactly 1 for 5·10⁻³²⁴ = 2⁻¹⁰⁷⁴, 1.113… for 10³⁰⁸, a few ULPs off).
    let points = DMatrix::from_row_slice(2, 3, &[1.0, 0.0, 1.0, 1.0, 0.0, 1.0]);
    let k = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    let unit = NurbsCurve::new(2, k.clone(), points.clone(), vec![1.0; 3]).unwrap();
    for w in [1e308, 5e-324] {
        let c = NurbsCurve::new(2, k.clone(), points.clone(), vec![w; 3]).unwrap();
        for t in [0.0, 0.3, 0.5, 1.0] {
            let (a, b) = (c.try_eval(t).unwrap(), unit.try_eval(t).unwrap());
            assert!((a - b).amax() <= 4.0 * f64::EPSILON, "weights {w}, t = {t}");
        }
    }
    // Weights spanning more than the range of doubles: named.
    assert!(overflow(NurbsCurve::new(
        2,
        k,
        points,
        vec![1e308, 5e-324, 1.0]
    )));
    // Spline parameters 5·10⁻³²⁴ apart.
    let pts = DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 0.0]);
    let r =
        CubicSpline::interpolate_with_params(pts, vec![0.0, 5e-324, 1e-323], EndCondition::Natural);
    assert!(overflow(r));
    // 1001 equally spaced Lagrange nodes; a Gordon surface of 1001 curves.
    let nodes = cagd::linspace(0.0, 1.0, 1001);
    assert!(overflow(cagd::lagrange::Lagrange::new(nodes.clone())));
    let line = |a: [f64; 2], b: [f64; 2]| {
        SampledCurve::new(
            vec![0.0, 1.0],
            DMatrix::from_column_slice(2, 2, &[a[0], a[1], b[0], b[1]]),
        )
        .unwrap()
    };
    let at_u: Vec<_> = nodes.iter().map(|&u| line([u, 0.0], [u, 1.0])).collect();
    let at_v = vec![line([0.0, 0.0], [1.0, 0.0]), line([0.0, 1.0], [1.0, 1.0])];
    let r = GordonSurface::new(nodes, vec![0.0, 1.0], at_u, at_v);
    assert!(matches!(
        r,
        Err(Error::Overflow {
            what: "Lagrange barycentric weights",
            ..
        })
    ));
}

#[test]
fn result_functions_do_not_panic_on_the_reported_calls() {
    use cagd::{CoonsPatch, FnCurve, Surface};
    let c = BSplineCurve::clamped(2, DMatrix::from_row_slice(1, 4, &[0.0, 1.0, 2.0, 3.0])).unwrap();
    assert!(too_large(c.elevate(usize::MAX)));
    // A boundary curve that returns a point of the wrong dimension inside its domain.
    type F = fn(f64) -> DVector<f64>;
    let edges: [F; 4] = [
        |u| DVector::from_vec(vec![u, 0.0]),
        |u| DVector::from_vec(vec![u, 1.0]),
        |v| DVector::from_vec(vec![0.0, v]),
        |v| {
            if v > 0.0 && v < 1.0 {
                DVector::from_vec(vec![1.0, v, 7.0])
            } else {
                DVector::from_vec(vec![1.0, v])
            }
        },
    ];
    let [c1, c2, d1, d2] = edges.map(|f| FnCurve::new(2, f));
    let patch = CoonsPatch::new(c1, c2, d1, d2).unwrap();
    let r = patch.try_eval(0.5, 0.5);
    assert!(
        matches!(
            r,
            Err(Error::ShapeMismatch {
                what: "Coons boundary curve d2",
                ..
            })
        ),
        "{r:?}"
    );
    // eval is total: the point is NaN, never an index past the short vector.
    assert!(patch.eval(0.5, 0.5).iter().all(|x| x.is_nan()));
}

#[test]
fn work_unbounded_in_the_arguments_is_refused_before_it_starts() {
    let start = std::time::Instant::now();
    let long = cagd::BezierCurve::new(DMatrix::<f64>::zeros(1, 100_001)).unwrap();
    assert!(too_large(long.try_eval(0.5)));
    assert!(too_large(long.eval_many(&[0.5])));
    let c = BSplineCurve::clamped(2, DMatrix::from_row_slice(1, 4, &[0.0, 1.0, 2.0, 3.0])).unwrap();
    assert!(too_large(c.elevate(1_000_000)));
    assert!(too_large(cagd::exact::rational_from_decimal("1e999999999")));
    assert!(too_large(cagd::exact::rational_from_decimal(
        "1e-999999999"
    )));
    assert!(too_large(
        cagd::conversion::bezier_to_monomial_matrix::<f64>(1100)
    ));
    assert!(too_large(cagd::bernstein::elevate(&[1.0], 1_000_000)));
    // The Cox–de Boor recursion makes 2^(p+1) calls.
    let knots: Vec<f64> = (0..64).map(f64::from).collect();
    assert!(too_large(cox_de_boor(0, 60, &knots, &30.5)));
    assert!(start.elapsed() < std::time::Duration::from_secs(10));
}

#[test]
fn infallible_functions_have_fallible_twins_and_documented_panics() {
    use cagd::grid::PointGrid;
    assert!(matches!(
        cagd::bspline::basis_functions(2, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 9, &0.5),
        Err(Error::InvalidArgument { .. })
    ));
    assert!(matches!(
        cagd::lagrange::power_coefficients(&[0.0, 1.0], 5),
        Err(Error::InvalidArgument { .. })
    ));
    let l = cagd::lagrange::Lagrange::new(vec![0.0, 1.0]).unwrap();
    assert!(too_large(l.lebesgue_constant(0.0, 1.0, usize::MAX)));
    assert!(matches!(
        cagd::bspline::try_cox_de_boor_triangle(3, &[0.0, 1.0], &0.5),
        Err(Error::InvalidArgument { .. })
    ));
    assert!(too_large(cagd::linspace::try_linspace(0.0, 1.0, 1 << 40)));
    assert!(too_large(PointGrid::try_from_elem(
        (1 << 20, 1 << 20, 1),
        0.0
    )));
    // The infallible ones panic, naming the size, instead of aborting.
    for (what, f) in [
        (
            "linspace",
            Box::new(|| drop(cagd::linspace(0.0, 1.0, 1 << 40))) as Box<dyn Fn()>,
        ),
        (
            "from_elem",
            Box::new(|| drop(PointGrid::from_elem((1 << 20, 1 << 20, 1), 0.0))),
        ),
        (
            "triangle",
            Box::new(|| drop(cagd::bspline::cox_de_boor_triangle(3, &[0.0, 1.0], &0.5))),
        ),
        (
            "bernstein_all",
            Box::new(|| drop(cagd::bernstein::bernstein_all(usize::MAX, 0.5))),
        ),
        (
            "bernstein of a coefficient beyond doubles, 2^41 + 1 values",
            Box::new(|| {
                std::hint::black_box(cagd::bernstein::bernstein(1 << 40, 1 << 41, 0.5));
            }),
        ),
        (
            "bernstein_derivative",
            Box::new(|| {
                std::hint::black_box(cagd::bernstein::bernstein_derivative(0, 1 << 40, 1, 0.5));
            }),
        ),
        (
            "bernstein_derivative_all, r > n",
            Box::new(|| {
                drop(cagd::bernstein::bernstein_derivative_all(
                    1 << 40,
                    usize::MAX,
                    0.5,
                ))
            }),
        ),
        (
            "basis_matrix",
            Box::new(|| drop(cagd::bernstein::basis_matrix(usize::MAX, &[0.5]))),
        ),
        (
            "basis_derivative_matrix",
            Box::new(|| drop(cagd::bernstein::basis_derivative_matrix(1 << 40, 1, &[0.5]))),
        ),
        (
            "bernstein_antiderivative",
            Box::new(|| {
                drop(cagd::integral::bernstein_antiderivative::<f64>(
                    usize::MAX,
                    0,
                ))
            }),
        ),
    ] {
        assert!(catch_unwind(AssertUnwindSafe(f)).is_err(), "{what}");
    }
}

#[test]
fn gregory_twists_of_different_dimensions_or_not_finite_are_refused() {
    use cagd::coons::GregoryTwist;
    let v = |x: &[f64]| DVector::from_vec(x.to_vec());
    let a = [
        v(&[1.0, 0.0]),
        v(&[1.0, 0.0]),
        v(&[1.0, 0.0]),
        v(&[1.0, 0.0]),
    ];
    // b at P3 of dimension 3: the blend used to panic in eval (zip_map of 2 and 3 entries).
    let b = [
        v(&[0.0, 1.0]),
        v(&[0.0, 1.0]),
        v(&[0.0, 1.0, 2.0]),
        v(&[0.0, 1.0]),
    ];
    let r = GregoryTwist::new(a.clone(), b);
    assert!(
        matches!(&r, Err(Error::ShapeMismatch { what: "Gregory twists", found, .. })
            if found == "dimension 3 for b at P3"),
        "{r:?}"
    );
    let b = [
        v(&[0.0, 1.0]),
        v(&[0.0, f64::NAN]),
        v(&[0.0, 1.0]),
        v(&[0.0, 1.0]),
    ];
    assert!(non_finite(GregoryTwist::new(a.clone(), b)));
    let g = GregoryTwist::new(a.clone(), a).unwrap();
    assert_eq!(
        g.eval(cagd::coons::Corner::U0V0, &0.5, &0.5),
        v(&[1.0, 0.0])
    );
}

#[test]
fn an_integral_over_an_interval_whose_width_overflows_is_an_error() {
    // `cagd integrate "[0 0; 1 2; 2 0]" --rows --interval=-1e308,1e308` panicked in
    // integral.rs (an `expect` on the antiderivative's control points).
    let control = DMatrix::from_column_slice(2, 3, &[0.0, 0.0, 1.0, 2.0, 2.0, 0.0]);
    assert!(overflow(cagd::BezierCurve::new_on_interval(
        control.clone(),
        -1e308,
        1e308
    )));
    let wide =
        cagd::BezierCurve::new_on_interval(control.map(|x| x * 1e307), -1e307, 1e307).unwrap();
    assert!(overflow(cagd::integral::bezier_antiderivative(&wide)));
    assert!(overflow(cagd::integral::bezier_integral(&wide)));
}

/// The longest one call of the property test may take in a test build (the workspace's crates
/// unoptimised): every refusal happens before the work, and what is allowed is small, so the
/// slowest calls take a fraction of a second; a call that ran away would take minutes.
const CALL_TIME_LIMIT: std::time::Duration = std::time::Duration::from_secs(10);

/// One call again, outside `catch_unwind` (so that a panic shows where it happened):
/// `CAGD_HOSTILE_REPLAY=GROUP,SEED cargo test -p cagd --test it replay_one_call`.
#[test]
fn replay_one_call() {
    let Ok(spec) = std::env::var("CAGD_HOSTILE_REPLAY") else {
        return;
    };
    let (op, seed) = spec.split_once(',').expect("GROUP,SEED");
    let (op, seed): (usize, u64) = (op.parse().expect("group"), seed.parse().expect("seed"));
    let start = std::time::Instant::now();
    call(op, &Draws::seeded(seed));
    eprintln!(
        "group {op} ({}) seed {seed}: {:?}",
        GROUPS[op].0,
        start.elapsed()
    );
}

/// Many calls of every group (or of one: `SEEDS,GROUP`), reporting each failure (group, seed,
/// message) and the slowest call of each group instead of stopping at the first:
/// `CAGD_HOSTILE_SCAN=SEEDS cargo test -p cagd --test it scan_every_group -- --nocapture`.
#[test]
fn scan_every_group() {
    let Ok(spec) = std::env::var("CAGD_HOSTILE_SCAN") else {
        return;
    };
    let (seeds, only) = match spec.split_once(',') {
        Some((s, g)) => (s, Some(g.parse::<usize>().expect("GROUP"))),
        None => (spec.as_str(), None),
    };
    let seeds: u64 = seeds.parse().expect("SEEDS");
    std::panic::set_hook(Box::new(|_| {}));
    let mut failures = 0;
    for (op, (name, _)) in GROUPS.iter().enumerate() {
        if only.is_some_and(|g| g != op) {
            continue;
        }
        let mut slowest = (std::time::Duration::ZERO, 0);
        let mut seen = std::collections::BTreeSet::new();
        for seed in 0..seeds {
            let seed = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ (op as u64);
            let start = std::time::Instant::now();
            let outcome = catch_unwind(AssertUnwindSafe(|| call(op, &Draws::seeded(seed))));
            let elapsed = start.elapsed();
            if elapsed > slowest.0 {
                slowest = (elapsed, seed);
            }
            if let Err(panic) = outcome {
                let message = panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                let key: String = message.chars().take(60).collect();
                if seen.insert(key) {
                    failures += 1;
                    eprintln!("FAIL group {op} ({name}) seed {seed}: {message}");
                }
            }
        }
        eprintln!(
            "group {op} ({name}): slowest {:?} (seed {})",
            slowest.0, slowest.1
        );
    }
    let _ = std::panic::take_hook();
    assert_eq!(failures, 0);
}

/// The number of cases of the property test below: 3000, or `CAGD_HOSTILE_CASES` (a longer
/// local run: `CAGD_HOSTILE_CASES=200000 cargo test -p cagd --test it no_public_function`).
fn hostile_cases() -> u32 {
    std::env::var("CAGD_HOSTILE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3000)
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(hostile_cases()))]

    /// Every call returns (an `Err` is fine) within a bounded time; none panics, and no `Ok`
    /// holds a non-finite number (`hostile_calls::check::ok` panics on one). The calls are those
    /// of the `library` fuzz target (`cagd_test_support::hostile_calls`), here from a seeded
    /// stream.
    #[test]
    fn no_public_function_panics_or_returns_a_non_finite_value(
        op in 0..OPS,
        seed in proptest::prelude::any::<u64>(),
    ) {
        if std::env::var_os("CAGD_HOSTILE_TRACE").is_some() {
            eprintln!("op {op} seed {seed}");
        }
        let draws = Draws::seeded(seed);
        let start = std::time::Instant::now();
        let outcome = catch_unwind(AssertUnwindSafe(|| call(op, &draws)));
        let elapsed = start.elapsed();
        if let Err(panic) = &outcome {
            let message = panic
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| panic.downcast_ref::<&str>().copied())
                .unwrap_or("(no message)");
            proptest::prop_assert!(false, "group {} ({}) with seed {} panicked: {}", op, GROUPS[op].0, seed, message);
        }
        proptest::prop_assert!(
            elapsed < CALL_TIME_LIMIT,
            "group {} ({}) with seed {} took {:?}", op, GROUPS[op].0, seed, elapsed
        );
    }
}

#[test]
fn periodic_wrapping_of_a_far_parameter_ends() {
    // 10³⁰⁰ / 2: a double where k + 1 = k; the floor used to count up to it one by one.
    let w = cagd::bspline::wrap_periodic(1e300, &1.0, &3.0);
    assert!((1.0..3.0).contains(&w), "{w}");
    let c = BSplineCurve::clamped(1, DMatrix::from_row_slice(1, 2, &[0.0, 1.0])).unwrap();
    let mut out = [0.0];
    let r =
        c.eval_many_extrapolated_into(&[1e300], &mut out, &cagd::bspline::Extrapolation::Periodic);
    assert!(r.is_ok() && out[0].is_finite(), "{r:?} {out:?}");
}

#[test]
fn curvature_of_overflowing_or_non_finite_derivatives_is_an_error() {
    use cagd::curvature::curvature_squared;
    let big = DVector::from_vec(vec![1e200, 0.0]);
    let r = curvature_squared(&big, &DVector::from_vec(vec![0.0, 1.0]));
    assert!(matches!(r, Err(Error::Overflow { .. })), "{r:?}");
    let nan = DVector::from_vec(vec![f64::NAN, 1.0]);
    let r = curvature_squared(&nan, &DVector::from_vec(vec![0.0, 1.0]));
    assert!(matches!(r, Err(Error::NonFinite { .. })), "{r:?}");
}

#[test]
fn bernstein_integrals_of_any_degree_and_values_of_bad_indices() {
    assert!(cagd::integral::bernstein_integral::<f64>(usize::MAX) > 0.0);
    let r = cagd::integral::bernstein_antiderivative_values::<f64>(2, &[3], &[0.5]);
    assert!(matches!(r, Err(Error::InvalidArgument { .. })), "{r:?}");
    let r = cagd::integral::bernstein_antiderivative_values::<f64>(usize::MAX, &[0], &[0.5]);
    assert!(too_large(r));
}

#[test]
fn end_knots_beyond_degree_plus_one_are_named_before_elevation_or_merging() {
    use cagd::bspline::make_compatible;
    // Degree 1 with the last knot three times: control point 2 has no non-empty span.
    let over = BSplineCurve::new(
        1,
        vec![0.0, 0.0, 1.0, 1.0, 1.0],
        DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 2.0]),
    )
    .unwrap();
    let line = BSplineCurve::new(
        1,
        vec![0.0, 0.0, 1.0, 1.0],
        DMatrix::from_row_slice(1, 2, &[0.0, 1.0]),
    )
    .unwrap();
    let more_than = |r: Option<&Error>| {
        matches!(r, Some(Error::InvalidArgument { message, .. })
            if message.contains("occurs 2 times and the last 3, more than degree + 1 = 2"))
    };
    let r = over.elevate(1);
    assert!(more_than(r.as_ref().err()), "{r:?}");
    let r = make_compatible(&[line.clone(), over]);
    assert!(more_than(r.as_ref().err()), "{r:?}");
    // Too few end knots: not clamped, with the counts.
    let open = BSplineCurve::new(1, vec![-1.0, 0.0, 1.0, 2.0], DMatrix::zeros(1, 2)).unwrap();
    let r = make_compatible(&[line, open]);
    assert!(
        matches!(&r, Err(Error::InvalidArgument { message, .. })
            if message.contains("curve 1: the knot vector must be clamped") && message.contains("occur 1 and 1 times")),
        "{r:?}"
    );
}

#[test]
fn coons_patch_in_bspline_form_refuses_knots_that_collapse_or_overflow() {
    use cagd::coons::{coons_bspline_net, CoonsPatch};
    let line = |a: [f64; 2], b: [f64; 2]| {
        BSplineCurve::new(
            1,
            vec![0.0, 0.0, 1.0, 1.0],
            DMatrix::from_column_slice(2, 2, &[a[0], a[1], b[0], b[1]]),
        )
        .unwrap()
    };
    // d1 on [−1.5·10³⁰⁸, 3] with an interior knot at 1: on [0, 1] it becomes 1.0, the end.
    let d1 = BSplineCurve::new(
        1,
        vec![-1.5e308, -1.5e308, 1.0, 3.0, 3.0],
        DMatrix::from_column_slice(2, 3, &[0.0, 0.0, 0.0, 0.5, 0.0, 1.0]),
    )
    .unwrap();
    let patch = CoonsPatch::new(
        line([0.0, 0.0], [1.0, 0.0]),
        line([0.0, 1.0], [1.0, 1.0]),
        d1,
        line([1.0, 0.0], [1.0, 1.0]),
    )
    .unwrap();
    let r = patch.to_bspline();
    assert!(
        matches!(&r, Err(Error::InvalidArgument { what: "Coons patch in B-spline form", message })
            if message.starts_with("boundary d1: the knots 1.0 and 3.0 become the same double 1.0")),
        "{r:?}"
    );
    // Corners ±1.7·10³⁰⁸: each part is finite, their sum r_c + r_d overflows before − r_cd.
    let big = 1.7e308;
    let corners = [
        DVector::from_vec(vec![big, 0.0]),
        DVector::from_vec(vec![-big, 0.0]),
        DVector::from_vec(vec![-big, 1.0]),
        DVector::from_vec(vec![big, 1.0]),
    ];
    let edge = |a: &DVector<f64>, b: &DVector<f64>| line([a[0], a[1]], [b[0], b[1]]);
    let [p00, p10, p01, p11] = &corners;
    let r = coons_bspline_net(
        &edge(p00, p10),
        &edge(p01, p11),
        &edge(p00, p01),
        &edge(p10, p11),
        &corners,
    );
    assert!(
        matches!(
            r,
            Err(Error::Overflow {
                what: "Coons patch in B-spline form control points",
                ..
            })
        ),
        "{r:?}"
    );
}

#[test]
fn geometry_form_matrices_beyond_the_degree_limit_are_refused_before_they_are_built() {
    use cagd::conversion::{form_conversion, GeometryForm};
    // The Bézier form's identity of k × k was built for any k: 10⁷ + 1 columns asked for
    // 800 TB (an abort), usize::MAX overflowed.
    for k in [1002, 10_000_001, 1 << 40, usize::MAX] {
        assert!(too_large(GeometryForm::Bezier.to_bezier::<f64>(k)), "{k}");
        assert!(
            too_large(GeometryForm::Algebraic.from_bezier::<f64>(k)),
            "{k}"
        );
        assert!(
            too_large(form_conversion::<f64>(
                GeometryForm::Bezier,
                GeometryForm::Bezier,
                k
            )),
            "{k}"
        );
    }
    assert_eq!(
        GeometryForm::Bezier.to_bezier::<f64>(1001).unwrap().nrows(),
        1001
    );
}

#[test]
fn design_matrices_of_any_degree_are_knot_count_errors() {
    // p + 1 and 2p + 2 overflowed (a panic in a test build) for p near usize::MAX.
    for p in [usize::MAX, usize::MAX / 2 + 1, 1 << 40] {
        let r = cagd::bspline::design_matrix(p, &[0.0, 0.0, 1.0, 1.0], &[0.5], false);
        assert!(matches!(r, Err(Error::KnotCount { .. })), "{p}: {r:?}");
    }
}

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

/// Many calls of every group, reporting each failure (group, seed, message) and the slowest
/// call of each group instead of stopping at the first: `CAGD_HOSTILE_SCAN=SEEDS cargo test -p
/// cagd --test it scan_every_group -- --nocapture`.
#[test]
fn scan_every_group() {
    let Some(seeds) = std::env::var("CAGD_HOSTILE_SCAN")
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
    else {
        return;
    };
    std::panic::set_hook(Box::new(|_| {}));
    let mut failures = 0;
    for (op, (name, _)) in GROUPS.iter().enumerate() {
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

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(3000))]

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

//! Coons patches: the thesis's worked example, interpolation, the bicubic and Gregory
//! constructions, discrete Coons and masks, and every bad-input error.

use crate::support;

use std::cell::Cell;
use std::rc::Rc;

use cagd::coons::{
    discrete_coons, solve_mask, BicubicCoonsPatch, BlendingPair, CoonsBoundary, CoonsPatch, Corner,
    CrossDerivatives, GeneralizedCoonsPatch, Mask, Tolerance, Twist,
};
use cagd::{Curve, Error, FnCurve, SampledCurve, Scalar, Surface};
use nalgebra::{dmatrix, dvector, DMatrix, DVector};
use support::{q, qv, random_surface, Poly, PolySurface, Q};

type QF = fn(Q) -> DVector<Q>;
type PolyBoundary = CoonsBoundary<Poly<Q>, Q>;
type PolyCross = CrossDerivatives<Poly<Q>>;

/// Primer 4.3's curves: c1 = (u, 0, u − u²), c2 = (u, 1, u), d1 = (0, v², v − v²), d2 = (1, v, v).
fn primer_4_3() -> [FnCurve<QF, cagd::NoDerivative, Q>; 4] {
    let c1: QF = |u| dvector![u.clone(), q(0, 1), u.clone() - u.clone() * u];
    let c2: QF = |u| dvector![u.clone(), q(1, 1), u];
    let d1: QF = |v| dvector![q(0, 1), v.clone() * v.clone(), v.clone() - v.clone() * v];
    let d2: QF = |v| dvector![q(1, 1), v.clone(), v];
    [c1, c2, d1, d2].map(|f| FnCurve::new(3, f))
}

#[test]
fn primer_4_3_exactly() {
    let [c1, c2, d1, d2] = primer_4_3();
    let patch = CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::Exact).unwrap();
    let p = patch.eval_parts(q(1, 5), q(1, 2));
    assert_eq!(p.rc, qv(&[(1, 5), (1, 2), (9, 50)]));
    assert_eq!(p.rd, qv(&[(1, 5), (3, 10), (3, 10)]));
    assert_eq!(p.rcd, qv(&[(1, 5), (1, 2), (1, 10)]));
    assert_eq!(p.x, qv(&[(1, 5), (3, 10), (19, 50)]));
}

#[test]
fn primer_4_3_corners_are_those_of_the_thesis_code() {
    // P1..P4 of appendix C = x(0,0), x(1,0), x(0,1), x(1,1); the curves meet there exactly
    // (c2(0) = d1(1) = (0,1,0), c1(1) = d2(0) = (1,0,0)).
    let [c1, c2, d1, d2] = primer_4_3();
    let corners = [
        qv(&[(0, 1), (0, 1), (0, 1)]),
        qv(&[(1, 1), (0, 1), (0, 1)]),
        qv(&[(0, 1), (1, 1), (0, 1)]),
        qv(&[(1, 1), (1, 1), (1, 1)]),
    ];
    let patch =
        CoonsPatch::with_corners(c1, c2, d1, d2, corners.clone(), Tolerance::Exact).unwrap();
    assert_eq!(patch.corners(), &corners);
    assert_eq!(
        patch.eval(q(1, 5), q(1, 2)),
        qv(&[(1, 5), (3, 10), (19, 50)])
    );
}

#[test]
fn appendix_c_data_script_as_printed_is_rejected() {
    // The data script sets "P3 = [1;1;1]" where it means P4: x(0,1) is then off by (1, 0, 1)
    // from both c2(0) and d1(1).
    let [c1, c2, d1, d2] = primer_4_3();
    let corners = [
        qv(&[(0, 1), (0, 1), (0, 1)]),
        qv(&[(1, 1), (0, 1), (0, 1)]),
        qv(&[(1, 1), (1, 1), (1, 1)]),
        qv(&[(1, 1), (1, 1), (1, 1)]),
    ];
    match CoonsPatch::with_corners(c1, c2, d1, d2, corners, Tolerance::Exact) {
        Err(Error::CornerMismatch { gaps, tolerance }) => {
            assert_eq!(tolerance, Tolerance::Exact);
            assert_eq!(gaps.len(), 2);
            for g in &gaps {
                assert_eq!(g.corner, Corner::U0V1);
                assert_eq!(g.first, "P3");
                assert_eq!(g.gap, 1.0);
                assert_eq!(g.allowed, 0.0);
            }
            assert_eq!((gaps[0].second, gaps[1].second), ("c2(0)", "d1(1)"));
        }
        Err(other) => panic!("expected CornerMismatch, got {other:?}"),
        Ok(_) => panic!("expected CornerMismatch, got a patch"),
    }
}

#[test]
fn primer_4_3_in_f64_matches_the_decimal_values() {
    type F = fn(f64) -> DVector<f64>;
    let c: [F; 4] = [
        |u| dvector![u, 0.0, u - u * u],
        |u| dvector![u, 1.0, u],
        |v| dvector![0.0, v * v, v - v * v],
        |v| dvector![1.0, v, v],
    ];
    let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(3, f));
    let p = CoonsPatch::new(c1, c2, d1, d2)
        .unwrap()
        .eval_parts(0.2, 0.5);
    for (got, want) in [
        (&p.rc, [0.2, 0.5, 0.18]),
        (&p.rd, [0.2, 0.3, 0.3]),
        (&p.rcd, [0.2, 0.5, 0.1]),
        (&p.x, [0.2, 0.3, 0.38]),
    ] {
        for k in 0..3 {
            assert!((got[k] - want[k]).abs() < 1e-15, "{got} vs {want:?}");
        }
    }
}

/// A boundary cut from a polynomial surface, as four `Poly` curves.
fn boundary_of(s: &PolySurface<Q>) -> [Poly<Q>; 4] {
    [
        s.curve_at_v(&q(0, 1)),
        s.curve_at_v(&q(1, 1)),
        s.curve_at_u(&q(0, 1)),
        s.curve_at_u(&q(1, 1)),
    ]
}

fn params() -> Vec<Q> {
    (0..=6).map(|k| q(k, 6)).collect()
}

#[test]
fn bilinear_coons_interpolates_its_boundary_exactly() {
    let mut seed = 7;
    let s = random_surface(&mut seed, 4, 3, 3);
    let [c1, c2, d1, d2] = boundary_of(&s);
    let patch = CoonsPatch::with_tolerance(
        c1.clone(),
        c2.clone(),
        d1.clone(),
        d2.clone(),
        Tolerance::Exact,
    )
    .unwrap();
    for t in params() {
        assert_eq!(patch.eval(t.clone(), q(0, 1)), c1.eval(t.clone()));
        assert_eq!(patch.eval(t.clone(), q(1, 1)), c2.eval(t.clone()));
        assert_eq!(patch.eval(q(0, 1), t.clone()), d1.eval(t.clone()));
        assert_eq!(patch.eval(q(1, 1), t.clone()), d2.eval(t.clone()));
    }
    // Not the surface itself inside (it is of degree (4, 3)).
    assert_ne!(patch.eval(q(1, 3), q(1, 3)), s.eval(&q(1, 3), &q(1, 3)));
}

#[test]
fn bilinear_coons_reproduces_a_surface_linear_in_one_direction() {
    // x = r_c + r_d − r_cd reproduces any surface of degree ≤ 1 in u or in v (its boolean-sum
    // error (I − P_u)(I − P_v) S vanishes).
    let mut seed = 11;
    let s = random_surface(&mut seed, 1, 5, 3);
    let [c1, c2, d1, d2] = boundary_of(&s);
    let patch = CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::Exact).unwrap();
    for u in params() {
        for v in params() {
            assert_eq!(patch.eval(u.clone(), v.clone()), s.eval(&u, &v));
        }
    }
}

#[test]
fn grid_evaluation_agrees_with_pointwise_evaluation_bit_for_bit() {
    type F = fn(f64) -> DVector<f64>;
    let c: [F; 4] = [
        |u| dvector![u, (3.0 * u).sin() * 0.1 * (1.0 - u), u * u],
        |u| dvector![u, 1.0 + u * (1.0 - u), 1.0 - u],
        |v| dvector![0.0, v, v * v * v],
        |v| dvector![1.0 + 0.2 * v * (1.0 - v), v, 1.0 - v * v],
    ];
    let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(3, f));
    let patch = CoonsPatch::new(c1, c2, d1, d2).unwrap();
    let us = cagd::linspace(0.0, 1.0, 13);
    let vs = cagd::linspace(0.0, 1.0, 8);
    let grid = cagd_octave::arrays::to_array3(patch.eval_grid(&us, &vs));
    assert_eq!(grid.shape(), &[13, 8, 3]);
    for (i, u) in us.iter().enumerate() {
        for (j, v) in vs.iter().enumerate() {
            let p = patch.eval(*u, *v);
            for k in 0..3 {
                assert_eq!(grid[[i, j, k]].to_bits(), p[k].to_bits());
            }
        }
    }
}

/// A curve that counts its evaluations.
struct Counting {
    inner: SampledCurve<f64>,
    calls: Rc<Cell<usize>>,
}

impl Curve<f64> for Counting {
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn domain(&self) -> (f64, f64) {
        self.inner.domain()
    }
    fn eval(&self, t: f64) -> DVector<f64> {
        self.calls.set(self.calls.get() + 1);
        self.inner.eval(t)
    }
    fn point_cost(&self, param_bits: u128) -> cagd::cost::Cost {
        self.inner.point_cost(param_bits)
    }
}

#[test]
fn grid_evaluation_evaluates_each_curve_once_per_grid_line() {
    let calls = Rc::new(Cell::new(0));
    let line = |a: [f64; 2], b: [f64; 2]| Counting {
        inner: SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]]).unwrap(),
        calls: calls.clone(),
    };
    let patch = CoonsPatch::new(
        line([0.0, 0.0], [1.0, 0.0]),
        line([0.0, 1.0], [1.0, 1.0]),
        line([0.0, 0.0], [0.0, 1.0]),
        line([1.0, 0.0], [1.0, 1.0]),
    )
    .unwrap();
    calls.set(0);
    let grid = cagd_octave::arrays::to_array3(
        patch.eval_grid(&cagd::linspace(0.0, 1.0, 20), &cagd::linspace(0.0, 1.0, 30)),
    );
    // c1, c2 once per u (20 each), d1, d2 once per v (30 each).
    assert_eq!(calls.get(), 2 * 20 + 2 * 30);
    assert_eq!(grid[[19, 29, 0]], 1.0);
}

#[test]
fn corner_mismatch_names_corners_gaps_and_tolerance() {
    let line = |a: [f64; 2], b: [f64; 2]| {
        SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]]).unwrap()
    };
    let c1 = line([0.0, 0.0], [1.0, 0.0]);
    let c2 = line([0.0, 1.0], [1.0, 1.0]);
    let d1 = line([0.0, 0.0], [0.0, 1.0 + 3e-10]);
    let d2 = line([1.0, 0.0], [1.0, 1.0]);
    let err = CoonsPatch::new(c1.clone(), c2.clone(), d1.clone(), d2.clone()).unwrap_err();
    match &err {
        Error::CornerMismatch { gaps, tolerance } => {
            assert_eq!(*tolerance, Tolerance::Relative(1e-10));
            assert_eq!(gaps.len(), 1);
            assert_eq!(gaps[0].corner, Corner::U0V1);
            assert_eq!((gaps[0].first, gaps[0].second), ("c2(0)", "d1(1)"));
            assert!((gaps[0].gap - 3e-10).abs() < 1e-16);
            // relative: 1e-10 · max(1, 1 + 3e-10)
            assert!((gaps[0].allowed - 1e-10).abs() < 1e-18);
        }
        other => panic!("expected CornerMismatch, got {other:?}"),
    }
    let message = err.to_string();
    assert!(
        message.contains("x(0,1) (P3)") && message.contains("c2(0)") && message.contains("d1(1)"),
        "{message}"
    );
    // A looser tolerance accepts it; the corners are then taken from c1, c2.
    let patch = CoonsPatch::with_tolerance(c1, c2, d1, d2, Tolerance::Absolute(1e-9)).unwrap();
    assert_eq!(patch.corners()[2], dvector![0.0, 1.0]);
}

#[test]
fn relative_tolerance_scales_with_the_data() {
    let line = |a: [f64; 2], b: [f64; 2]| {
        SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]]).unwrap()
    };
    // Coordinates of size 1e6: a gap of 1e-5 is 1e-11 relative, within 1e-10.
    let big = 1e6;
    let ok = CoonsPatch::new(
        line([0.0, 0.0], [big, 0.0]),
        line([0.0, big], [big, big]),
        line([0.0, 0.0], [0.0, big + 1e-5]),
        line([big, 0.0], [big, big]),
    );
    assert!(ok.is_ok());
    let err = CoonsPatch::with_tolerance(
        line([0.0, 0.0], [big, 0.0]),
        line([0.0, big], [big, big]),
        line([0.0, 0.0], [0.0, big + 1e-5]),
        line([big, 0.0], [big, big]),
        Tolerance::Absolute(1e-10),
    )
    .unwrap_err();
    assert!(matches!(err, Error::CornerMismatch { ref gaps, .. } if gaps.len() == 1));
    let err = CoonsPatch::with_tolerance(
        line([0.0, 0.0], [1.0, 0.0]),
        line([0.0, 1.0], [1.0, 1.0]),
        line([0.0, 0.0], [0.0, 1.0]),
        line([1.0, 0.0], [1.0, 1.0]),
        Tolerance::Relative(-1.0),
    )
    .unwrap_err();
    assert!(matches!(
        err,
        Error::InvalidArgument {
            what: "tolerance",
            ..
        }
    ));
}

#[test]
fn curves_of_different_dimensions_are_rejected() {
    let c2d = SampledCurve::new(vec![0.0, 1.0], dmatrix![0.0, 1.0; 0.0, 0.0]).unwrap();
    let c3d = SampledCurve::new(vec![0.0, 1.0], dmatrix![0.0, 1.0; 0.0, 0.0; 0.0, 0.0]).unwrap();
    let err = CoonsPatch::new(c2d.clone(), c2d.clone(), c3d, c2d).unwrap_err();
    assert!(
        matches!(err, Error::ShapeMismatch { what: "Coons boundary curves", ref found, .. } if found.contains("d1"))
    );
}

#[test]
fn non_finite_corners_are_rejected() {
    type F = fn(f64) -> DVector<f64>;
    let bad: F = |u| dvector![u, if u == 1.0 { f64::NAN } else { 0.0 }];
    let c: [F; 4] = [
        bad,
        |u| dvector![u, 1.0],
        |v| dvector![0.0, v],
        |v| dvector![1.0, v],
    ];
    let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(2, f));
    assert!(matches!(
        CoonsPatch::new(c1, c2, d1, d2),
        Err(Error::NonFinite { .. })
    ));
}

#[test]
fn coons_patch_of_sampled_curves_is_the_thesis_grid() {
    // On the sampling grid a Coons patch of SampledCurves uses exactly the samples, as krpaCoons.
    let n = 5;
    let t = cagd::linspace(0.0, 1.0, n);
    let sample = |f: &dyn Fn(f64) -> [f64; 3]| {
        SampledCurve::new(t.clone(), DMatrix::from_fn(3, n, |k, i| f(t[i])[k])).unwrap()
    };
    let c1 = sample(&|u| [u, 0.0, u - u * u]);
    let c2 = sample(&|u| [u, 1.0, u]);
    let d1 = sample(&|v| [0.0, v * v, v - v * v]);
    let d2 = sample(&|v| [1.0, v, v]);
    let patch = CoonsPatch::new(c1, c2, d1, d2).unwrap();
    let grid = cagd_octave::arrays::to_array3(patch.eval_grid(&t, &t));
    // The boundary rows of the grid are the samples (to round-off: x = (r_c + r_d) − r_cd).
    for i in 0..n {
        assert_eq!(grid[[i, 0, 2]], t[i] - t[i] * t[i]);
        assert!((grid[[0, i, 1]] - t[i] * t[i]).abs() < 1e-16);
    }
}

// ---------------------------------------------------------------- generalized and partially bicubic

#[test]
fn generalized_with_linear_blending_is_the_bilinear_patch_bit_for_bit() {
    type F = fn(f64) -> DVector<f64>;
    let c: [F; 4] = [
        |u| dvector![u, 0.3 * u * (1.0 - u), u - u * u],
        |u| dvector![u, 1.0, u],
        |v| dvector![0.0, v * v, v - v * v],
        |v| dvector![1.0, v, v + 0.3 * v * (v - 1.0)],
    ];
    let bilinear = {
        let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(3, f));
        CoonsPatch::new(c1, c2, d1, d2).unwrap()
    };
    let general = {
        let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(3, f));
        GeneralizedCoonsPatch::new(
            c1,
            c2,
            d1,
            d2,
            BlendingPair::linear(),
            BlendingPair::linear(),
        )
        .unwrap()
    };
    let ts = cagd::linspace(0.0, 1.0, 9);
    let a = cagd_octave::arrays::to_array3(bilinear.eval_grid(&ts, &ts));
    let b = cagd_octave::arrays::to_array3(general.eval_grid(&ts, &ts));
    assert!(a
        .iter()
        .zip(b.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    assert_eq!(bilinear.eval_parts(0.3, 0.7), general.eval_parts(0.3, 0.7));
}

#[test]
fn partially_bicubic_interpolates_and_flattens_the_cross_derivatives() {
    let mut seed = 23;
    let s = random_surface(&mut seed, 3, 3, 3);
    let [c1, c2, d1, d2] = boundary_of(&s);
    let boundary = CoonsBoundary::new(
        c1.clone(),
        c2.clone(),
        d1.clone(),
        d2.clone(),
        Tolerance::Exact,
    )
    .unwrap();
    let patch = GeneralizedCoonsPatch::from_boundary(
        boundary,
        BlendingPair::hermite_cubic(),
        BlendingPair::hermite_cubic(),
        0.0,
    )
    .unwrap();
    for t in params() {
        assert_eq!(patch.eval(t.clone(), q(0, 1)), c1.eval(t.clone()));
        assert_eq!(patch.eval(t.clone(), q(1, 1)), c2.eval(t.clone()));
        assert_eq!(patch.eval(q(0, 1), t.clone()), d1.eval(t.clone()));
        assert_eq!(patch.eval(q(1, 1), t.clone()), d2.eval(t.clone()));
    }
}

#[test]
fn partially_bicubic_cross_derivative_depends_only_on_the_corner_tangents() {
    // Numerically: x_u(0, v) of the partially bicubic patch equals H0(v) c1'(0) + H3(v) c2'(0).
    type F = fn(f64) -> DVector<f64>;
    let c: [F; 4] = [
        |u| dvector![u, 0.0, (2.0 * u).sin() * 0.3],
        |u| dvector![u, 1.0, u * u],
        |v| dvector![0.0, v, 0.7 * v * (1.0 - v)],
        |v| {
            dvector![
                1.0,
                v,
                (2.0f64).sin() * 0.3 * (1.0 - v) + v + 0.5 * v * (1.0 - v) * v
            ]
        },
    ];
    let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(3, f));
    let patch = GeneralizedCoonsPatch::partially_bicubic(c1, c2, d1, d2).unwrap();
    let tangent0 = dvector![1.0, 0.0, 0.6]; // c1'(0)
    let tangent1 = dvector![1.0, 0.0, 0.0]; // c2'(0)
    let h = 1e-6;
    for v in cagd::linspace(0.0, 1.0, 11) {
        let fd = (patch.eval(h, v) - patch.eval(0.0, v)) / h;
        let [h0, h3, _, _] = cagd::hermite::hermite_basis(v);
        let want = &tangent0 * h0 + &tangent1 * h3;
        assert!((fd - want).amax() < 1e-5);
    }
}

#[test]
fn blending_functions_breaking_the_conditions_are_named() {
    let line = |a: [f64; 2], b: [f64; 2]| {
        SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]]).unwrap()
    };
    let build = |f: BlendingPair<f64>, g: BlendingPair<f64>| {
        GeneralizedCoonsPatch::new(
            line([0.0, 0.0], [1.0, 0.0]),
            line([0.0, 1.0], [1.0, 1.0]),
            line([0.0, 0.0], [0.0, 1.0]),
            line([1.0, 0.0], [1.0, 1.0]),
            f,
            g,
        )
    };
    // f1(0) = 0.9.
    let err = build(
        BlendingPair::new("shifted", |t: f64| 0.9 - t, |t: f64| 0.1 + t),
        BlendingPair::linear(),
    )
    .unwrap_err();
    assert_eq!(
        err,
        Error::BlendingCondition {
            function: "f1",
            condition: "first function is 1 at 0",
            t: 0.0,
            value: 0.9,
            expected: 1.0,
            tolerance: 1e-12
        }
    );
    // g1(1) = 0.5.
    let err = build(
        BlendingPair::linear(),
        BlendingPair::new("half", |t: f64| 1.0 - t / 2.0, |t: f64| t / 2.0),
    )
    .unwrap_err();
    assert!(
        matches!(err, Error::BlendingCondition { function: "g1", t, value, .. } if t == 1.0 && value == 0.5)
    );
    // f1 + f2 = 1 fails between the ends: (1 − t)² + t² = 1 − 2t(1 − t).
    let err = build(
        BlendingPair::new("squares", |t: f64| (1.0 - t) * (1.0 - t), |t: f64| t * t),
        BlendingPair::linear(),
    )
    .unwrap_err();
    match err {
        Error::BlendingCondition {
            function,
            condition,
            t,
            value,
            expected,
            ..
        } => {
            assert_eq!((function, condition), ("f1 + f2", "partition of unity"));
            assert_eq!(t, 1.0 / 32.0);
            assert_eq!(expected, 1.0);
            assert!((value - (1.0 - 2.0 * t * (1.0 - t))).abs() < 1e-15);
        }
        other => panic!("{other:?}"),
    }
    // NaN from a blending function is a failure, not a pass.
    let err = build(
        BlendingPair::new(
            "nan",
            |t: f64| if t == 0.5 { f64::NAN } else { 1.0 - t },
            |t: f64| t,
        ),
        BlendingPair::linear(),
    )
    .unwrap_err();
    assert!(matches!(err, Error::BlendingCondition { t, .. } if t == 0.5));
}

// ---------------------------------------------------------------- bicubic

/// The boundary, cross-boundary derivatives and corner twists of a polynomial surface.
fn bicubic_data(s: &PolySurface<Q>) -> (PolyBoundary, PolyCross, [DVector<Q>; 4]) {
    let [c1, c2, d1, d2] = boundary_of(s);
    let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::Exact).unwrap();
    let su = s.partial(1, 0);
    let sv = s.partial(0, 1);
    let cross = CrossDerivatives {
        du0: su.curve_at_u(&q(0, 1)),
        du1: su.curve_at_u(&q(1, 1)),
        dv0: sv.curve_at_v(&q(0, 1)),
        dv1: sv.curve_at_v(&q(1, 1)),
    };
    let suv = s.partial(1, 1);
    let twists = Corner::ALL.map(|c| {
        let (i, j) = c.uv();
        suv.eval(&q(i as i64, 1), &q(j as i64, 1))
    });
    (boundary, cross, twists)
}

/// Checks positions and cross-boundary derivatives on all four edges against the data.
fn assert_interpolates_edges(patch: &BicubicCoonsPatch<Poly<Q>, Poly<Q>, Q>, s: &PolySurface<Q>) {
    let su = s.partial(1, 0);
    let sv = s.partial(0, 1);
    for t in params() {
        for (u, v, across_u) in [
            (q(0, 1), t.clone(), true),
            (q(1, 1), t.clone(), true),
            (t.clone(), q(0, 1), false),
            (t.clone(), q(1, 1), false),
        ] {
            let p = patch.eval_partials(u.clone(), v.clone()).unwrap();
            assert_eq!(p.x, s.eval(&u, &v), "position at ({u}, {v})");
            if across_u {
                assert_eq!(p.xu, su.eval(&u, &v), "x_u at ({u}, {v})");
            } else {
                assert_eq!(p.xv, sv.eval(&u, &v), "x_v at ({u}, {v})");
            }
        }
    }
}

#[test]
fn bicubic_coons_interpolates_positions_and_cross_derivatives_with_compatible_data() {
    // A surface of degree (5, 4): not bicubic, so nothing is reproduced by accident inside.
    let mut seed = 101;
    let s = random_surface(&mut seed, 5, 4, 3);
    let (boundary, cross, twists) = bicubic_data(&s);
    let patch = BicubicCoonsPatch::new(boundary, cross, Twist::Given(twists)).unwrap();
    assert_interpolates_edges(&patch, &s);
    assert_ne!(patch.eval(q(1, 3), q(1, 2)), s.eval(&q(1, 3), &q(1, 2)));
    // Gregory's square with compatible twists is the same patch.
    let (boundary, cross, _) = bicubic_data(&s);
    let gregory = BicubicCoonsPatch::new(boundary, cross, Twist::Gregory).unwrap();
    for u in params() {
        for v in params() {
            assert_eq!(
                gregory.eval(u.clone(), v.clone()),
                patch.eval(u.clone(), v.clone())
            );
        }
    }
}

#[test]
fn bicubic_coons_reproduces_a_bicubic_patch() {
    let mut seed = 5;
    let s = random_surface(&mut seed, 3, 3, 2);
    let (boundary, cross, twists) = bicubic_data(&s);
    let patch = BicubicCoonsPatch::new(boundary, cross, Twist::Given(twists)).unwrap();
    for u in params() {
        for v in params() {
            assert_eq!(patch.eval(u.clone(), v.clone()), s.eval(&u, &v));
        }
    }
}

#[test]
fn zero_twist_misses_the_cross_derivatives_where_the_data_twist() {
    let mut seed = 77;
    let s = random_surface(&mut seed, 3, 3, 3);
    let (boundary, cross, twists) = bicubic_data(&s);
    assert!(twists.iter().any(|t| t.iter().any(|x| *x != q(0, 1))));
    let patch = BicubicCoonsPatch::new(boundary, cross, Twist::Zero).unwrap();
    // Positions are still interpolated …
    for t in params() {
        assert_eq!(patch.eval(q(0, 1), t.clone()), s.eval(&q(0, 1), &t));
    }
    // … but not x_u along u = 0.
    let su = s.partial(1, 0);
    let v = q(1, 2);
    let p = patch.eval_partials(q(0, 1), v.clone()).unwrap();
    assert_ne!(p.xu, su.eval(&q(0, 1), &v));
}

/// Data whose twists disagree: x_u(0, v) gets an extra `v(1 − v) e`, which changes
/// ∂/∂v x_u at (0,0) and (0,1) but no value of x_u at the corners.
fn incompatible_twist_data(
    s: &PolySurface<Q>,
    e: DVector<Q>,
) -> (PolyBoundary, PolyCross, Poly<Q>) {
    let (boundary, mut cross, _) = bicubic_data(s);
    let mut coeffs = cross.du0.coeffs.clone();
    while coeffs.len() < 3 {
        coeffs.push(DVector::from_element(s.dim(), q(0, 1)));
    }
    coeffs[1] = coeffs[1].zip_map(&e, |a, b| a + b);
    coeffs[2] = coeffs[2].zip_map(&e, |a, b| a - b);
    cross.du0 = Poly::new(coeffs);
    let du0 = cross.du0.clone();
    (boundary, cross, du0)
}

#[test]
fn gregory_twist_interpolates_incompatible_twist_data_edge_by_edge() {
    let mut seed = 3;
    let s = random_surface(&mut seed, 4, 4, 3);
    let e = qv(&[(1, 1), (-2, 1), (3, 2)]);
    let (boundary, cross, du0) = incompatible_twist_data(&s, e);
    let patch = BicubicCoonsPatch::new(boundary, cross, Twist::Gregory).unwrap();
    let g = patch.gregory_twist().unwrap();
    assert_ne!(g.along_v()[0], g.along_u()[0]); // (0,0): incompatible
    assert_ne!(g.along_v()[2], g.along_u()[2]); // (0,1): incompatible
    assert_eq!(g.along_v()[1], g.along_u()[1]); // (1,0): compatible
    let su = s.partial(1, 0);
    let sv = s.partial(0, 1);
    for t in params() {
        // Positions on all four edges.
        for (u, v) in [
            (q(0, 1), t.clone()),
            (q(1, 1), t.clone()),
            (t.clone(), q(0, 1)),
            (t.clone(), q(1, 1)),
        ] {
            let p = patch.eval_partials(u.clone(), v.clone()).unwrap();
            assert_eq!(p.x, s.eval(&u, &v));
        }
        // Cross-boundary derivatives: the modified data on u = 0, the surface's elsewhere.
        let p = patch.eval_partials(q(0, 1), t.clone()).unwrap();
        assert_eq!(p.xu, du0.eval(t.clone()), "x_u(0, {t})");
        let p = patch.eval_partials(q(1, 1), t.clone()).unwrap();
        assert_eq!(p.xu, su.eval(&q(1, 1), &t));
        let p = patch.eval_partials(t.clone(), q(0, 1)).unwrap();
        assert_eq!(p.xv, sv.eval(&t, &q(0, 1)), "x_v({t}, 0)");
        let p = patch.eval_partials(t.clone(), q(1, 1)).unwrap();
        assert_eq!(p.xv, sv.eval(&t, &q(1, 1)));
    }
}

#[test]
fn constant_twists_cannot_serve_both_edges_of_an_incompatible_corner() {
    let mut seed = 3;
    let s = random_surface(&mut seed, 4, 4, 3);
    let e = qv(&[(1, 1), (-2, 1), (3, 2)]);
    let (_, _, twists) = bicubic_data(&s);
    let (boundary, cross, du0) = incompatible_twist_data(&s, e);
    let patch = BicubicCoonsPatch::new(boundary, cross, Twist::Given(twists)).unwrap();
    // The surface's own twist at (0,0) is b = ∂/∂u x_v, what the edge u = 0 needs: x_u along
    // u = 0 is the (modified) data. The edge v = 0 needs a = ∂/∂v x_u (modified), so x_v along
    // v = 0 misses the data there.
    let t = q(1, 3);
    let p = patch.eval_partials(q(0, 1), t.clone()).unwrap();
    assert_eq!(p.xu, du0.eval(t.clone()));
    let p = patch.eval_partials(t.clone(), q(0, 1)).unwrap();
    assert_ne!(p.xv, s.partial(0, 1).eval(&t, &q(0, 1)));
}

#[test]
fn bicubic_partials_agree_with_finite_differences_inside() {
    // Gregory's twist makes the patch rational; check x_u, x_v inside against differences.
    let mut seed = 9;
    let s = random_surface(&mut seed, 4, 4, 2);
    let (boundary, cross, _) = incompatible_twist_data(&s, qv(&[(2, 1), (-1, 1)]));
    let patch = BicubicCoonsPatch::new(boundary, cross, Twist::Gregory).unwrap();
    let h = q(1, 1_000_000);
    for (u, v) in [(q(1, 10), q(1, 5)), (q(1, 2), q(1, 3)), (q(9, 10), q(4, 5))] {
        let p = patch.eval_partials(u.clone(), v.clone()).unwrap();
        let du = (patch.eval(u.clone() + h.clone(), v.clone())
            - patch.eval(u.clone() - h.clone(), v.clone()))
        .map(|x| x / (q(2, 1) * h.clone()));
        let dv = (patch.eval(u.clone(), v.clone() + h.clone())
            - patch.eval(u.clone(), v.clone() - h.clone()))
        .map(|x| x / (q(2, 1) * h.clone()));
        assert!((du - &p.xu).iter().all(|d| d.to_f64().abs() < 1e-8));
        assert!((dv - &p.xv).iter().all(|d| d.to_f64().abs() < 1e-8));
    }
}

#[test]
fn bicubic_errors() {
    let mut seed = 1;
    let s = random_surface(&mut seed, 3, 3, 2);
    // A cross-boundary derivative that disagrees with a boundary tangent.
    let (boundary, mut cross, _) = bicubic_data(&s);
    let mut c = cross.du0.coeffs.clone();
    c[0] = c[0].map(|x| x + q(1, 8));
    cross.du0 = Poly::new(c);
    match BicubicCoonsPatch::new(boundary, cross, Twist::Zero) {
        Err(Error::CornerMismatch { gaps, .. }) => {
            assert_eq!(gaps.len(), 2);
            assert_eq!(
                (gaps[0].corner, gaps[0].first, gaps[0].second),
                (Corner::U0V0, "c1'(0)", "x_u(0,v) at v=0")
            );
            assert_eq!((gaps[1].corner, gaps[1].first), (Corner::U0V1, "c2'(0)"));
            assert_eq!(gaps[0].gap, 0.125);
        }
        other => panic!("{other:?}"),
    }
    // Gregory needs derivatives of the cross-boundary curves: they are in the type
    // (`CurveDeriv`), so a closure curve without one does not compile (docs/ERRORS.md); with
    // them (constant cross derivatives: zero) the twist is computed and the patch is flat.
    type F = fn(f64) -> DVector<f64>;
    let line = |a: [f64; 2], b: [f64; 2]| {
        SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]]).unwrap()
    };
    let boundary = CoonsBoundary::new(
        line([0.0, 0.0], [1.0, 0.0]),
        line([0.0, 1.0], [1.0, 1.0]),
        line([0.0, 0.0], [0.0, 1.0]),
        line([1.0, 0.0], [1.0, 1.0]),
        Tolerance::default(),
    )
    .unwrap();
    let ex: F = |_| dvector![1.0, 0.0];
    let ey: F = |_| dvector![0.0, 1.0];
    let zero: F = |_| dvector![0.0, 0.0];
    let cross = || CrossDerivatives {
        du0: FnCurve::with_derivative(2, ex, zero),
        du1: FnCurve::with_derivative(2, ex, zero),
        dv0: FnCurve::with_derivative(2, ey, zero),
        dv1: FnCurve::with_derivative(2, ey, zero),
    };
    let gregory = BicubicCoonsPatch::new(boundary.clone(), cross(), Twist::Gregory).unwrap();
    assert!((gregory.eval(0.25, 0.75) - dvector![0.25, 0.75]).amax() < 1e-16);
    let patch = BicubicCoonsPatch::new(boundary.clone(), cross(), Twist::Zero)
        .ok()
        .unwrap();
    assert!((patch.eval(0.25, 0.75) - dvector![0.25, 0.75]).amax() < 1e-16);
    let partials = patch.eval_partials(0.5, 0.5).unwrap();
    assert!(
        (partials.xu.clone() - dvector![1.0, 0.0]).amax() < 1e-15,
        "{partials:?}"
    );
    // Given twists of the wrong dimension.
    let err = BicubicCoonsPatch::new(
        boundary,
        cross(),
        Twist::Given([dvector![0.0], dvector![0.0], dvector![0.0], dvector![0.0]]),
    )
    .err()
    .unwrap();
    assert!(matches!(
        err,
        Error::ShapeMismatch {
            what: "given twists",
            ..
        }
    ));
}

// ---------------------------------------------------------------- discrete Coons and masks

/// A net whose boundary is random and whose interior is garbage (the constructions must not
/// read it).
fn random_net(seed: &mut u64, m: usize, n: usize, d: usize) -> Vec<DMatrix<Q>> {
    (0..d)
        .map(|_| DMatrix::from_fn(m + 1, n + 1, |_, _| support::lcg_rational(seed, 3)))
        .collect()
}

#[test]
fn discrete_coons_worked_example() {
    // m = 2, n = 3; by formula (6) with exact fractions:
    // b_11 = ½ b01 + ½ b21 + ⅔ b10 + ⅓ b13 − (½·⅔ b00 + ½·⅓ b03 + ½·⅔ b20 + ½·⅓ b23).
    let z = DMatrix::from_row_slice(
        3,
        4,
        &[
            q(0, 1),
            q(1, 1),
            q(2, 1),
            q(3, 1),
            q(4, 1),
            q(99, 1),
            q(99, 1),
            q(5, 1),
            q(6, 1),
            q(7, 1),
            q(8, 1),
            q(9, 1),
        ],
    );
    let net = discrete_coons(&[z]).unwrap();
    let b11 = q(1, 2) * q(1, 1) + q(1, 2) * q(7, 1) + q(2, 3) * q(4, 1) + q(1, 3) * q(5, 1)
        - (q(1, 3) * q(0, 1) + q(1, 6) * q(3, 1) + q(1, 3) * q(6, 1) + q(1, 6) * q(9, 1));
    assert_eq!(net[0][(1, 1)], b11);
    assert_eq!(b11, q(13, 3));
    // The boundary is untouched.
    assert_eq!(net[0][(0, 2)], q(2, 1));
    assert_eq!(net[0][(1, 3)], q(5, 1));
}

#[test]
fn discrete_coons_equals_the_mask_solve_exactly() {
    let mut seed = 17;
    for (m, n) in [(2, 2), (3, 5), (6, 2), (4, 4), (7, 3)] {
        let net = random_net(&mut seed, m, n, 3);
        let a = discrete_coons(&net).unwrap();
        let b = solve_mask(&net, &Mask::coons(), &cagd::Limits::default()).unwrap();
        assert_eq!(a, b, "degree ({m}, {n})");
    }
}

#[test]
fn the_thesis_bilinear_term_with_swapped_vectors_differs() {
    // The thesis prints the corner term as [1 − j/n, j/n] B [1 − i/m; i/m]; on a net with
    // m ≠ n … and b_0n ≠ b_m0 that is not the Coons net (notes (6) is).
    let mut seed = 29;
    let net = random_net(&mut seed, 3, 4, 1);
    let good = discrete_coons(&net).unwrap();
    let b = &net[0];
    let (m, n) = (3i64, 4i64);
    let (i, j) = (1usize, 1usize);
    let (s, t) = (q(i as i64, m), q(j as i64, n));
    let one = q(1, 1);
    let swapped = (one.clone() - s.clone()) * b[(0, j)].clone()
        + s.clone() * b[(3, j)].clone()
        + (one.clone() - t.clone()) * b[(i, 0)].clone()
        + t.clone() * b[(i, 4)].clone()
        - ((one.clone() - t.clone())
            * ((one.clone() - s.clone()) * b[(0, 0)].clone() + s.clone() * b[(0, 4)].clone())
            + t.clone()
                * ((one.clone() - s.clone()) * b[(3, 0)].clone() + s.clone() * b[(3, 4)].clone()));
    assert_ne!(good[0][(i, j)], swapped);
}

#[test]
fn masks_with_four_alpha_plus_four_beta_one_reproduce_bilinear_nets() {
    let bilinear = |m: usize, n: usize| {
        vec![DMatrix::from_fn(m + 1, n + 1, |i, j| {
            q(3, 1)
                + q(-2, 1) * q(i as i64, 1)
                + q(5, 7) * q(j as i64, 1)
                + q(1, 3) * q((i * j) as i64, 1)
        })]
    };
    for alpha in [q(-1, 4), q(0, 1), q(1, 8), q(-1, 10)] {
        let mask = Mask::from_alpha(alpha.clone());
        assert_eq!(Mask::new(alpha.clone(), mask.beta()).unwrap(), mask);
        for (m, n) in [(3, 3), (5, 2), (2, 6)] {
            let net = bilinear(m, n);
            let mut garbled = net.clone();
            garbled[0][(1, 1)] = q(1000, 1);
            assert_eq!(
                solve_mask(&garbled, &mask, &cagd::Limits::default()).unwrap(),
                net,
                "alpha = {alpha}"
            );
        }
    }
}

#[test]
fn mask_solution_satisfies_the_mask_at_every_interior_point() {
    let mut seed = 31;
    let mask = Mask::new(q(1, 10), q(3, 20)).unwrap();
    for (m, n) in [(4, 3), (3, 6)] {
        let net = random_net(&mut seed, m, n, 2);
        let out = solve_mask(&net, &mask, &cagd::Limits::default()).unwrap();
        for b in &out {
            for i in 1..m {
                for j in 1..n {
                    let corners = b[(i - 1, j - 1)].clone()
                        + b[(i - 1, j + 1)].clone()
                        + b[(i + 1, j - 1)].clone()
                        + b[(i + 1, j + 1)].clone();
                    let edges = b[(i - 1, j)].clone()
                        + b[(i + 1, j)].clone()
                        + b[(i, j - 1)].clone()
                        + b[(i, j + 1)].clone();
                    assert_eq!(b[(i, j)], mask.alpha() * corners + mask.beta() * edges);
                }
            }
        }
    }
}

#[test]
fn banded_solver_agrees_with_nalgebra_dense_lu() {
    // f64: a mask that needs pivoting (indefinite system) on nets of both orientations.
    let mask = Mask::from_alpha(0.4);
    for (m, n) in [(7usize, 4usize), (4, 9), (12, 12)] {
        let z = DMatrix::from_fn(m + 1, n + 1, |i, j| ((i * 7 + j * 3) as f64).sin());
        let banded = solve_mask(std::slice::from_ref(&z), &mask, &cagd::Limits::default()).unwrap();
        // Dense system in the natural numbering.
        let idx = |i: usize, j: usize| (i - 1) * (n - 1) + (j - 1);
        let size = (m - 1) * (n - 1);
        let mut a = DMatrix::<f64>::identity(size, size);
        let mut r = DVector::<f64>::zeros(size);
        for i in 1..m {
            for j in 1..n {
                for (di, dj) in [
                    (-1i64, -1i64),
                    (-1, 0),
                    (-1, 1),
                    (0, -1),
                    (0, 1),
                    (1, -1),
                    (1, 0),
                    (1, 1),
                ] {
                    let w = if di != 0 && dj != 0 {
                        mask.alpha()
                    } else {
                        mask.beta()
                    };
                    let (ni, nj) = ((i as i64 + di) as usize, (j as i64 + dj) as usize);
                    if ni == 0 || ni == m || nj == 0 || nj == n {
                        r[idx(i, j)] += w * z[(ni, nj)];
                    } else {
                        a[(idx(i, j), idx(ni, nj))] -= w;
                    }
                }
            }
        }
        let x = a.lu().solve(&r).unwrap();
        let mut worst: f64 = 0.0;
        for i in 1..m {
            for j in 1..n {
                worst = worst.max((banded[0][(i, j)] - x[idx(i, j)]).abs());
            }
        }
        assert!(worst < 1e-12, "({m}, {n}): {worst}");
    }
}

#[test]
fn a_large_net_is_solved_by_the_band_solver() {
    // Degree 60 × 80: 4661 unknowns; a dense matrix would hold 21.7 million entries. The
    // system's condition number is λ_max/λ_min ≈ 4 / ((1 − cos π/60)(1 − cos π/80)) ≈ 4·10⁶,
    // which bounds the agreement in f64.
    let (m, n) = (60, 80);
    let z = DMatrix::from_fn(m + 1, n + 1, |i, j| {
        let (s, t) = (i as f64 / m as f64, j as f64 / n as f64);
        (3.0 * s).sin() + t * t + s * t
    });
    let a = solve_mask(
        std::slice::from_ref(&z),
        &Mask::coons(),
        &cagd::Limits::default(),
    )
    .unwrap();
    let b = discrete_coons(&[z]).unwrap();
    assert!((&a[0] - &b[0]).amax() < 1e-9, "{}", (&a[0] - &b[0]).amax());
}

#[test]
fn mask_errors() {
    // Not affine.
    assert_eq!(
        Mask::new(0.1, 0.2).unwrap_err(),
        Error::MaskNotAffine {
            alpha: 0.1,
            beta: 0.2,
            sum: 4.0 * 0.1 + 4.0 * 0.2
        }
    );
    assert!(matches!(
        Mask::new(q(1, 10), q(3, 20) + q(1, 1_000_000_000)),
        Err(Error::MaskNotAffine { .. })
    ));
    assert!(Mask::new(0.05, 0.2).is_ok());
    assert!(matches!(
        Mask::new(f64::NAN, 0.25),
        Err(Error::NonFinite { .. })
    ));
    // Singular: α = −1/2, β = 3/4 on a 4×4 net (λ_11 = 1/2 + α = 0), exactly and in f64.
    let mut seed = 41;
    let net = random_net(&mut seed, 3, 3, 3);
    let err = solve_mask(
        &net,
        &Mask::new(q(-1, 2), q(3, 4)).unwrap(),
        &cagd::Limits::default(),
    )
    .unwrap_err();
    match err {
        Error::SingularMask {
            alpha,
            beta,
            m,
            n,
            p,
            q: qq,
            eigenvalue,
        } => {
            assert_eq!((alpha, beta, m, n, p, qq), (-0.5, 0.75, 3, 3, 1, 1));
            assert!(eigenvalue.abs() < 1e-15);
        }
        other => panic!("{other:?}"),
    }
    let netf: Vec<DMatrix<f64>> = net.iter().map(|b| b.map(|x| x.to_f64())).collect();
    assert!(matches!(
        solve_mask(&netf, &Mask::from_alpha(0.5), &cagd::Limits::default()),
        Err(Error::SingularMask { p: 2, q: 2, .. })
    ));
    // The same mask is fine on a net where no mode vanishes.
    let net5 = random_net(&mut seed, 5, 4, 1);
    assert!(solve_mask(
        &net5,
        &Mask::new(q(-1, 2), q(3, 4)).unwrap(),
        &cagd::Limits::default()
    )
    .is_ok());
    // Bad nets.
    assert!(matches!(
        solve_mask::<f64>(&[], &Mask::coons(), &cagd::Limits::default()),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(matches!(
        discrete_coons(&[DMatrix::<f64>::zeros(3, 3), DMatrix::zeros(3, 4)]),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(matches!(
        discrete_coons(&[DMatrix::<f64>::zeros(0, 3)]),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        discrete_coons(&[dmatrix![0.0, f64::INFINITY; 1.0, 2.0]]),
        Err(Error::NonFinite { .. })
    ));
    // No interior: returned unchanged.
    let thin = vec![dmatrix![1.0, 2.0, 3.0; 4.0, 5.0, 6.0]];
    assert_eq!(discrete_coons(&thin).unwrap(), thin);
    assert_eq!(
        solve_mask(&thin, &Mask::coons(), &cagd::Limits::default()).unwrap(),
        thin
    );
}

#[test]
fn coons_mask_eigenvalues_are_positive() {
    // λ_pq = (1 − cos θ_p)(1 − cos φ_q) for Coons.
    for (m, n) in [(2, 2), (3, 7), (10, 4)] {
        let (p, qq, l) = Mask::<f64>::coons().smallest_eigenvalue(m, n).unwrap();
        let want = (1.0 - (std::f64::consts::PI / m as f64).cos())
            * (1.0 - (std::f64::consts::PI / n as f64).cos());
        assert_eq!((p, qq), (1, 1));
        assert!((l - want).abs() < 1e-15);
    }
}

// ---------------------------------------------------------------- against GNU Octave

use cagd_test_support as common;

use cagd::bezier::BezierCurve;
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
use ndarray::{Array2, Array3};

fn to_dmatrix(a: &Array2<f64>) -> DMatrix<f64> {
    DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[[i, j]])
}

fn column(a: &Array2<f64>) -> DVector<f64> {
    assert_eq!(a.ncols(), 1);
    DVector::from_iterator(a.nrows(), a.column(0).iter().copied())
}

fn as_array2(v: &DVector<f64>) -> Array2<f64> {
    Array2::from_shape_fn((v.len(), 1), |(i, _)| v[i])
}

fn sampled(t: &[f64], samples: &Array2<f64>) -> SampledCurve<f64> {
    SampledCurve::new(t.to_vec(), to_dmatrix(samples)).unwrap()
}

/// The grid packed as the thesis's R: `R(i, 3j−2:3j) = x(u_i, v_j)`.
fn packed(grid: &Array3<f64>) -> Array2<f64> {
    let (nu, nv, d) = grid.dim();
    Array2::from_shape_fn((nu, d * nv), |(i, c)| grid[[i, c / d, c % d]])
}

#[test]
fn octave_primer_4_3_vrednost_coons() {
    let ws = expected("coons_thesis");
    type F = fn(f64) -> DVector<f64>;
    let c: [F; 4] = [
        |u| dvector![u, 0.0, u - u * u],
        |u| dvector![u, 1.0, u],
        |v| dvector![0.0, v * v, v - v * v],
        |v| dvector![1.0, v, v],
    ];
    let [c1, c2, d1, d2] = c.map(|f| FnCurve::new(3, f));
    let (u, v) = (ws.scalar("ex_u").unwrap(), ws.scalar("ex_v").unwrap());
    // The inputs are the curve values Octave computed (u^2 there, u*u here: the same double).
    for (name, curve, t) in [
        ("ex_c1", &c1, u),
        ("ex_c2", &c2, u),
        ("ex_d1", &d1, v),
        ("ex_d2", &d2, v),
    ] {
        assert_identical(name, &as_array2(&curve.eval(t)), &matrix(&ws, name));
    }
    let corners = ["P1", "P2", "P3", "P4"].map(|p| column(&matrix(&ws, p)));
    let patch = CoonsPatch::with_corners(c1, c2, d1, d2, corners, Tolerance::default()).unwrap();
    let p = patch.eval_parts(u, v);
    for (name, ours) in [
        ("ex_T", &p.x),
        ("ex_rc", &p.rc),
        ("ex_rd", &p.rd),
        ("ex_rcd", &p.rcd),
    ] {
        assert_identical(name, &as_array2(ours), &matrix(&ws, name));
    }
}

#[test]
fn octave_appendix_c_krpa_coons() {
    let ws = expected("coons_thesis");
    let corners = ["P1", "P2", "P3", "P4"].map(|p| column(&matrix(&ws, p)));
    for n in [2, 3, 10, 101] {
        let t = row(&ws, &format!("t_N{n}"));
        assert_eq!(t, cagd::linspace(0.0, 1.0, n));
        let [c1, c2, d1, d2] =
            ["c1", "c2", "d1", "d2"].map(|c| sampled(&t, &matrix(&ws, &format!("{c}_N{n}"))));
        let patch = CoonsPatch::with_corners(c1, c2, d1, d2, corners.clone(), Tolerance::default())
            .unwrap();
        let grid = cagd_octave::arrays::to_array3(patch.eval_grid(&t, &t));
        // Same curve values, same term order: bit for bit.
        assert_identical(&format!("P_N{n}"), &grid, &array3(&ws, &format!("P_N{n}")));
        assert_close(&format!("P_N{n}"), &grid, &array3(&ws, &format!("P_N{n}")));
        if n <= 3 {
            assert_identical(
                &format!("R_N{n}"),
                &packed(&grid),
                &matrix(&ws, &format!("R_N{n}")),
            );
        }
    }
    common::report_worst("coons_thesis");
}

/// `(1−t) a + t b + (t(1−t)) (α + β t)`, coordinate by coordinate, in the operation order of
/// `octave_ref/cases/coons_random.m`.
fn random_edge(
    a: DVector<f64>,
    b: DVector<f64>,
    alpha: DVector<f64>,
    beta: DVector<f64>,
) -> Box<dyn Curve<f64>> {
    Box::new(FnCurve::new(3, move |t: f64| {
        DVector::from_fn(3, |k, _| {
            (1.0 - t) * a[k] + t * b[k] + (t * (1.0 - t)) * (alpha[k] + beta[k] * t)
        })
    }))
}

#[test]
fn octave_random_coons_patches() {
    let ws = expected("coons_random");
    for r in 1..=3 {
        let get = |name: &str| matrix(&ws, &format!("r{r}_{name}"));
        let (q, a, b) = (
            to_dmatrix(&get("Q")),
            to_dmatrix(&get("A")),
            to_dmatrix(&get("B")),
        );
        let col = |m: &DMatrix<f64>, k: usize| m.column(k).into_owned();
        // c1: P1 → P2, c2: P3 → P4, d1: P1 → P3, d2: P2 → P4.
        let ends = [(0, 1), (2, 3), (0, 2), (1, 3)];
        let curves: Vec<Box<dyn Curve<f64>>> = ends
            .iter()
            .enumerate()
            .map(|(k, &(s, e))| random_edge(col(&q, s), col(&q, e), col(&a, k), col(&b, k)))
            .collect();
        let t = row(&ws, &format!("r{r}_t"));
        for (k, name) in ["c1", "c2", "d1", "d2"].iter().enumerate() {
            let ours = Array2::from_shape_fn((3, t.len()), |(i, j)| curves[k].eval(t[j])[i]);
            assert_identical(&format!("r{r}_{name}"), &ours, &get(name));
        }
        let [c1, c2, d1, d2]: [Box<dyn Curve<f64>>; 4] = curves.try_into().ok().unwrap();
        let corners = [0, 1, 2, 3].map(|k| col(&q, k));
        let patch =
            CoonsPatch::with_corners(c1, c2, d1, d2, corners, Tolerance::default()).unwrap();
        let grid = cagd_octave::arrays::to_array3(patch.eval_grid(&t, &t));
        assert_close(&format!("r{r}_P"), &grid, &array3(&ws, &format!("r{r}_P")));
        assert_identical(&format!("r{r}_P"), &grid, &array3(&ws, &format!("r{r}_P")));
        let uv = get("uv");
        let names = ["T", "rc", "rd", "rcd"];
        let mut ours: Vec<Array2<f64>> = names
            .iter()
            .map(|_| Array2::zeros((3, uv.ncols())))
            .collect();
        for k in 0..uv.ncols() {
            let p = patch.eval_parts(uv[[0, k]], uv[[1, k]]);
            for (o, part) in ours.iter_mut().zip([&p.x, &p.rc, &p.rd, &p.rcd]) {
                for i in 0..3 {
                    o[[i, k]] = part[i];
                }
            }
        }
        for (name, o) in names.iter().zip(&ours) {
            assert_close(&format!("r{r}_{name}"), o, &get(name));
        }
    }
    common::report_worst("coons_random");
}

#[test]
fn octave_nurbs_nrbcoons_of_bezier_boundaries() {
    // octave-nurbs builds the Coons patch as a NURBS surface (ruled surfaces and a bilinear
    // patch, degree-elevated, knots merged) and evaluates it by de Boor: another operation
    // order, so agreement is to round-off relative to the size of the data, not bit for bit.
    let ws = expected("nrbcoons_bezier");
    for r in 1..=2 {
        let get = |name: &str| matrix(&ws, &format!("r{r}_{name}"));
        let [c1, c2, d1, d2] =
            ["c1", "c2", "d1", "d2"].map(|c| BezierCurve::new(to_dmatrix(&get(c))).unwrap());
        let patch = CoonsPatch::new(c1, c2, d1, d2).unwrap();
        let (tu, tv) = (row(&ws, &format!("r{r}_tu")), row(&ws, &format!("r{r}_tv")));
        let octave = array3(&ws, &format!("r{r}_P"));
        assert_close(
            &format!("r{r}_P (CoonsPatch)"),
            &cagd_octave::arrays::to_array3(patch.eval_grid(&tu, &tv)),
            &octave,
        );
        let bezier = patch.to_bezier().unwrap();
        assert_close(
            &format!("r{r}_P (as one Bézier patch)"),
            &cagd_octave::arrays::to_array3(bezier.eval_grid(&tu, &tv)),
            &octave,
        );
    }
    common::report_worst("nrbcoons_bezier");
}

#[test]
fn coons_of_bezier_curves_as_one_bezier_patch_is_exact() {
    let mut seed = 61;
    let mut curve = |a: &DVector<Q>, b: &DVector<Q>, deg: usize| {
        let mut c = DMatrix::from_fn(3, deg + 1, |_, _| support::lcg_rational(&mut seed, 2));
        c.set_column(0, a);
        c.set_column(deg, b);
        BezierCurve::new(c).unwrap()
    };
    let p: Vec<DVector<Q>> = (0..4)
        .map(|k| qv(&[(k, 1), (k * k, 3), (1 - k, 2)]))
        .collect();
    let patch = CoonsPatch::with_tolerance(
        curve(&p[0], &p[1], 4),
        curve(&p[2], &p[3], 2),
        curve(&p[0], &p[2], 3),
        curve(&p[1], &p[3], 1),
        Tolerance::Exact,
    )
    .unwrap();
    let bezier = patch.to_bezier().unwrap();
    assert_eq!(bezier.degree(), (4, 3));
    for u in params() {
        for v in params() {
            assert_eq!(
                bezier.eval(u.clone(), v.clone()),
                patch.eval(u.clone(), v.clone())
            );
        }
    }
}

/// Validation arithmetic cannot be bypassed by overflow: with α = 1e308, `4α` is infinite and
/// `4α + 4β` NaN, which compared as "not too far from 1" before.
#[test]
fn mask_weights_that_overflow_are_not_affine() {
    for (alpha, beta) in [(1e308, -1e308 + 0.25), (-1e308, 1e308), (1e308, 0.25)] {
        let err = Mask::new(alpha, beta).unwrap_err();
        assert!(
            matches!(err, cagd::Error::MaskNotAffine { .. }),
            "{alpha}, {beta}: {err:?}"
        );
    }
    assert!(Mask::new(-0.25, 0.5).is_ok());
}

//! Knot vectors and parameters: the same wrong knots get the same words whatever else is
//! wrong, and parameters outside a spline's domain are refused.

use cagd_ops::knots::{
    check_knots, knots_or_clamped, params_within, CURVE, DOMAIN_FORM, SURFACE_U,
};
use cagd_ops::{Context, Kind, Params, Role};

#[test]
fn the_same_wrong_knots_get_the_same_words_in_every_order() {
    // Decreasing first, then the count against the control points, then the domain.
    let e = check_knots(&[0.0, 1.0, 0.5, 1.0, 1.0], 1, 3, CURVE).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::Knots, Kind::Knots));
    assert!(
        e.problem.starts_with("knot vector: knot 3 (0.5) is below"),
        "{e}"
    );
    let e = check_knots(&[0.0, 0.0, 1.0, 1.0], 3, 2, CURVE).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::Control, Kind::Shape));
    assert_eq!(
        e.problem,
        "control points: degree 3 needs at least 4 control point(s), got 2"
    );
    let e = check_knots(&[0.0, 0.0, 0.0, 0.0, 1.0, 1.0], 2, 3, SURFACE_U).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::UKnots, Kind::Value));
    let e = check_knots(&[0.0, 1.0, f64::NAN], 0, 2, CURVE).unwrap_err();
    assert_eq!(e.kind, Kind::NonFinite);
    assert_eq!(
        knots_or_clamped::<f64>(None, 3, 2, CURVE),
        Err(check_knots(&[0.0; 6], 3, 2, CURVE).unwrap_err())
    );
}

#[test]
fn parameters_outside_a_spline_are_refused() {
    let mut cx = Context::new(cagd::Limits::default());
    let t = Params::Given(vec![0.5, 2.0]);
    let e = params_within(
        &t,
        Role::T,
        (&0.0, &1.0),
        ("B-spline", DOMAIN_FORM),
        &mut cx,
    )
    .unwrap_err();
    assert_eq!(e.kind, Kind::Domain);
    assert_eq!(
        e.problem,
        "B-spline: parameter 2 is outside the domain [0, 1]"
    );
    let s = params_within(
        &Params::Samples(3),
        Role::T,
        (&1.0, &2.0),
        ("B-spline", DOMAIN_FORM),
        &mut cx,
    );
    assert_eq!(s, Ok(vec![1.0, 1.5, 2.0]));
}

//! B-splines, NURBS, interpolating splines and Hermite cubics: the operation layer's words for
//! a refusal, the clamped uniform knots for `[]`, end segments continued.

use cagd::limits::Limits;
use cagd_octave_pkg::args::Call;
use cagd_octave_pkg::native::{bspline, hermite, nurbs_curve, spline};
use cagd_octave_pkg::{Real, Value, VecSink};
use cagd_ops::knots::Degree;
use cagd_ops::ops::BSpline;
use cagd_ops::{execute as run_op, Context, Params};
use nalgebra::DMatrix;

fn real<'a>(dims: &'a [usize], data: &'a [f64]) -> Value<'a> {
    Value::Real(Real { dims, data })
}

fn chars<'a>(dims: &'a [usize], text: &'a str) -> Value<'a> {
    Value::Char {
        dims,
        bytes: text.as_bytes(),
    }
}

/// The words of an operation's error, as every front end prints them after its name.
fn words<O: cagd_ops::Operation<f64>>(op: &O) -> String {
    run_op(op, &mut Context::new(Limits::default()))
        .unwrap_err()
        .to_string()
}

#[test]
fn bspline_and_nurbs_answer_with_the_operations_words() {
    let (one, row4, row6) = ([1usize, 1], [1usize, 4], [1usize, 6]);
    let p = [0.0, 1.0, 2.0, 3.0];
    let args = [
        real(&one, &[2.0]),
        real(&row4, &p),
        real(&row6, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
        real(&one, &[0.5]),
    ];
    let call = Call::new("cagd_bspline", &args, 1, Limits::default());
    let e = bspline(&call, &mut VecSink::default()).unwrap_err();
    let op = BSpline {
        degree: Degree::Degree(2),
        knots: Some(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
        t: Params::Given(vec![0.5]),
        ..BSpline::new(DMatrix::from_row_slice(1, 4, &p))
    };
    assert_eq!(e.message, format!("U: {}", words(&op)));
    assert_eq!(e.identifier(), "cagd:knots");
    // [] is the clamped uniform vector: 0,0,0,½,1,1,1, so X(½) = 3/2.
    let empty = [0usize, 0];
    let three = [1usize, 3];
    let args = [
        real(&one, &[2.0]),
        real(&row4, &p),
        real(&empty, &[]),
        real(&three, &[0.0, 0.5, 1.0]),
    ];
    let mut sink = VecSink::default();
    bspline(
        &Call::new("cagd_bspline", &args, 1, Limits::default()),
        &mut sink,
    )
    .unwrap();
    assert_eq!(sink.get(0).data(), &[0.0, 1.5, 3.0]);
    // A zero weight: the weights are checked first, with the request's words.
    let args = [
        real(&one, &[2.0]),
        real(&three, &[0.0, 1.0, 2.0]),
        real(&three, &[1.0, 0.0, 1.0]),
        real(&empty, &[]),
        real(&one, &[0.5]),
    ];
    let e = nurbs_curve(
        &Call::new("cagd_nurbs", &args, 1, Limits::default()),
        &mut VecSink::default(),
    )
    .unwrap_err();
    assert_eq!(e.identifier(), "cagd:weights");
    assert!(
        e.message.starts_with("w: NURBS weights: weight 2 is 0"),
        "{e}"
    );
}

#[test]
fn splines_continue_their_end_segments_and_hermite_gives_its_bezier_points() {
    // The natural spline through 0, 1, 0 at t = 5/2: its last segment continued, -11/16.
    let (one, three) = ([1usize, 1], [1usize, 3]);
    let args = [
        real(&three, &[0.0, 1.0, 0.0]),
        real(&one, &[2.5]),
        chars(&[1, 7], "natural"),
    ];
    let mut sink = VecSink::default();
    spline(
        &Call::new("cagd_spline", &args, 2, Limits::default()),
        &mut sink,
    )
    .unwrap();
    assert_eq!(sink.get(0).data(), &[-0.6875]);
    assert_eq!(sink.get(1).data(), &[1.5, 0.0, -1.5]);
    let col = [2usize, 1];
    let args = [
        real(&col, &[0.0, 0.0]),
        real(&col, &[1.0, 0.0]),
        real(&col, &[1.0, 1.0]),
        real(&col, &[1.0, -1.0]),
        real(&one, &[0.5]),
    ];
    let mut sink = VecSink::default();
    hermite(
        &Call::new("cagd_hermite", &args, 2, Limits::default()),
        &mut sink,
    )
    .unwrap();
    assert_eq!(sink.get(0).data(), &[0.5, 0.25]);
    let third = 1.0 / 3.0;
    assert_eq!(
        sink.get(1).data(),
        &[0.0, 0.0, third, third, 1.0 - third, third, 1.0, 0.0]
    );
    // Vectors of different sizes: the four together.
    let (col3, d3) = ([3usize, 1], [1.0, 0.0, 0.0]);
    let args = [
        real(&col, &[0.0, 0.0]),
        real(&col3, &d3),
        real(&col, &[1.0, 1.0]),
        real(&col, &[1.0, 1.0]),
        real(&one, &[0.5]),
    ];
    let e = hermite(
        &Call::new("cagd_hermite", &args, 1, Limits::default()),
        &mut VecSink::default(),
    )
    .unwrap_err();
    assert!(
        e.message
            .starts_with("p0, p1, t0, t1: Hermite cubic: expected four vectors"),
        "{e}"
    );
}

//! The octave-nurbs twins: the layouts of `cagd_nrbeval`, the classes each argument takes, no
//! knot count check in `cagd_findspan`, the fields of `cagd_nrbkntins`' structure.

use cagd::Limits;
use cagd_octave_pkg::{native, nurbs, Output, Real, Value, VecSink};

use crate::values::{nrbmak, real};

/// `nrbmak ([0 1 3 4; 0 2 -1 1; 0 1 2 0; 1 1 1 1], [0 0 0 0 1 1 1 1])` as Octave passes it.
fn cubic<'a>(coefs: &'a [f64], knots: &'a [f64]) -> Value<'a> {
    nrbmak([
        ("coefs", real(&[4, 4], coefs)),
        ("knots", real(&[1, 8], knots)),
        ("order", real(&[1, 1], &[4.0])),
    ])
}

const COEFS: [f64; 16] = [
    0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 1.0, 1.0, 3.0, -1.0, 2.0, 1.0, 4.0, 1.0, 0.0, 1.0,
];
const KNOTS: [f64; 8] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];

/// Calls the function `name` as the package's table does.
fn run(name: &'static str, args: &[Value<'_>], nargout: usize) -> cagd_octave_pkg::Result<VecSink> {
    type Function = fn(
        &cagd_octave_pkg::args::Call<'_, '_>,
        &mut dyn cagd_octave_pkg::Sink,
    ) -> cagd_octave_pkg::Result<()>;
    let function: Function = match name {
        "cagd_nrbeval" => nurbs::nrbeval,
        "cagd_bspeval" => nurbs::bspeval,
        "cagd_findspan" => nurbs::findspan,
        "cagd_nrbkntins" => nurbs::nrbkntins,
        "cagd_bezier" => native::bezier,
        _ => unreachable!("no test of {name}"),
    };
    let mut out = VecSink::default();
    let call = cagd_octave_pkg::args::Call::new(name, args, nargout, Limits::default());
    function(&call, &mut out).map_err(|e| e.prefixed(name))?;
    Ok(out)
}

#[test]
fn nrbeval_layouts() {
    let t: Vec<f64> = cagd::linspace(0.0, 1.0, 600);
    let at = |dims: &'static [usize], nargout| {
        run(
            "cagd_nrbeval",
            &[cubic(&COEFS, &KNOTS), Value::Real(Real { dims, data: &t })],
            nargout,
        )
        .unwrap()
    };
    // A row: 3 × n; a column: [3, n, 1]; two outputs: homogeneous points and weights.
    let row = at(&[1, 600], 1);
    assert_eq!(row.get(0).dims(), &[3, 600]);
    let col = at(&[600, 1], 1);
    assert_eq!(col.get(0).dims(), &[3, 600, 1]);
    assert_eq!(row.get(0).data(), col.get(0).data());
    let two = at(&[1, 600], 2);
    assert!(
        matches!(two.get(1), Output::Real(d, w) if d == &[1, 600] && w.iter().all(|&x| (x - 1.0).abs() < 1e-15))
    );
    // The Bézier-piece path (600 sorted parameters) is the cubic b(t): check t = 1/2.
    let mid = &row.get(0).data()[3 * 299..3 * 300];
    let b = cagd::BezierCurve::new(nalgebra::DMatrix::from_column_slice(
        3,
        4,
        &[0.0, 0.0, 0.0, 1.0, 2.0, 1.0, 3.0, -1.0, 2.0, 4.0, 1.0, 0.0],
    ))
    .unwrap();
    let want = b.eval(t[299]);
    for c in 0..3 {
        assert!((mid[c] - want[c]).abs() < 1e-15);
    }
}

#[test]
fn classes_as_octave_nurbs_takes_them() {
    let k = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    let c = [0.0, 1.0, 2.0, 3.0];
    let real = |dims: &'static [usize], data: &'static [f64]| Value::Real(Real { dims, data });
    let numeric =
        |class: &'static str, dims: &'static [usize], data: &'static [f64]| Value::Numeric {
            class,
            real: Real { dims, data },
        };
    let kv = Value::Real(Real {
        dims: &[1, 7],
        data: &k,
    });
    // Integer parameters and degree are taken (bspeval converts them), integer control
    // points refused (bspeval: "the control net should be a matrix of doubles").
    let args = [
        numeric("int8", &[1, 1], &[2.0]),
        real(&[1, 4], &[0.0, 1.0, 2.0, 3.0]),
        kv.clone(),
        numeric("uint8", &[1, 1], &[1.0]),
    ];
    assert_eq!(run("cagd_bspeval", &args, 1).unwrap().get(0).data(), &[3.0]);
    let args = [
        real(&[1, 1], &[2.0]),
        numeric("int32", &[1, 4], &[0.0, 1.0, 2.0, 3.0]),
        kv.clone(),
        real(&[1, 1], &[0.5]),
    ];
    assert_eq!(
        run("cagd_bspeval", &args, 1).unwrap_err().identifier(),
        "cagd:class"
    );
    let args = [
        real(&[1, 1], &[2.0]),
        numeric("single", &[1, 4], &[0.0, 1.0, 2.0, 3.0]),
        kv.clone(),
        real(&[1, 1], &[0.5]),
    ];
    assert!(run("cagd_bspeval", &args, 1).is_ok());
    // The native functions refuse every class but double, as before.
    let args = [
        numeric("single", &[1, 2], &[0.0, 1.0]),
        real(&[1, 1], &[0.5]),
    ];
    assert_eq!(
        run("cagd_bezier", &args, 1).unwrap_err().identifier(),
        "cagd:class"
    );
    let _ = c;
}

#[test]
fn findspan_without_the_knot_count_check() {
    // cagd_findspan (4, 2, 0.5, [0 0 0 .5 1 1 1]) = 3, as findspan (bspinterpcrv relies on it).
    let k = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    let args = [
        Value::Real(Real {
            dims: &[1, 1],
            data: &[4.0],
        }),
        Value::Real(Real {
            dims: &[1, 1],
            data: &[2.0],
        }),
        Value::Real(Real {
            dims: &[1, 1],
            data: &[0.5],
        }),
        Value::Real(Real {
            dims: &[1, 7],
            data: &k,
        }),
    ];
    assert_eq!(
        run("cagd_findspan", &args, 1).unwrap().get(0).data(),
        &[3.0]
    );
}

#[test]
fn nrbkntins_returns_the_fields_of_its_structure() {
    let args = [
        cubic(&COEFS, &KNOTS),
        Value::Real(Real {
            dims: &[1, 1],
            data: &[0.5],
        }),
    ];
    let out = run("cagd_nrbkntins", &args, 6).unwrap();
    assert_eq!(out.get(0).dims(), &[4, 5]);
    assert_eq!(out.get(1).data(), &[4.0]);
    assert_eq!(out.get(2).data(), &[5.0]);
    assert_eq!(
        out.get(3).data(),
        &[0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]
    );
    assert_eq!(out.get(4).dims(), &[0, 0]);
}

//! Coons and Gordon patches of octave-nurbs structures: exact results, bad inputs named as the
//! usage line names them.

use cagd::Limits;
use cagd_octave_pkg::args::Call;
use cagd_octave_pkg::native::{coons, gordon};
use cagd_octave_pkg::{Value, VecSink};

use crate::values::{nrbmak, real};

/// Calls `f` as Octave would with `args` and `nargout` outputs.
fn call(
    f: fn(&Call<'_, '_>, &mut dyn cagd_octave_pkg::Sink) -> cagd_octave_pkg::Result<()>,
    args: &[Value<'_>],
    nargout: usize,
    out: &mut VecSink,
) -> cagd_octave_pkg::Result<()> {
    f(
        &Call::new("cagd_test", args, nargout, Limits::default()),
        out,
    )
}

/// The homogeneous coefficients of the quarter circle (weights 1, 1, 2) at height `z`:
/// points (1, 0, z), (1, 1, z), (0, 1, z).
fn arc_coefs(z: f64) -> Vec<f64> {
    vec![1.0, 0.0, z, 1.0, 1.0, 1.0, z, 1.0, 0.0, 2.0, 2.0 * z, 2.0]
}

const KNOTS: [f64; 6] = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];

/// `nrbmak (coefs, [0 0 0 1 1 1])` as the package receives it.
fn nurbs(coefs: &[f64]) -> Value<'_> {
    nrbmak([
        ("coefs", real(&[4, 3], coefs)),
        ("knots", real(&[1, 6], &KNOTS)),
        ("order", real(&[1, 1], &[3.0])),
    ])
}

#[test]
fn coons_takes_nurbs_boundaries_exactly() {
    // The cylinder over the quarter circle: x(1/2, 1/4) = (3/5, 4/5, 1/4), as
    // (1/4 + 1/2, 1/2 + 2/4) / (1/4 + 1/2 + 2/4) by hand.
    let (a0, a1) = (arc_coefs(0.0), arc_coefs(1.0));
    let d1 = [1.0, 0.0, 0.0, 1.0, 0.0, 1.0];
    let d2 = [0.0, 1.0, 0.0, 0.0, 1.0, 1.0];
    let exact = Value::Char {
        dims: &[1, 5],
        bytes: b"exact",
    };
    let mut args = vec![
        nurbs(&a0),
        nurbs(&a1),
        real(&[3, 2], &d1),
        real(&[3, 2], &d2),
        real(&[1, 1], &[0.5]),
        real(&[1, 1], &[0.25]),
    ];
    let mut out = VecSink::default();
    call(coons, &args, 1, &mut out).unwrap();
    let x = out.get(0).data();
    assert!((x[0] - 0.6).abs() < 1e-15 && (x[1] - 0.8).abs() < 1e-15 && x[2] == 0.25);
    args.push(exact);
    call(coons, &args, 1, &mut out).unwrap();
    assert_eq!(out.get(0).items(), ["3/5", "4/5", "1/4"]);
}

#[test]
fn gordon_takes_cells_of_nurbs_and_bezier_curves() {
    // Three lines of the cylinder and its two quarter circles: at u = 1/4 the circle is
    // (9/16 + 6/16, 6/16 + 2/16) / (17/16) = (15/17, 8/17).
    let (a0, a1) = (arc_coefs(0.0), arc_coefs(1.0));
    let lines = [
        [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [0.6, 0.8, 0.0, 0.6, 0.8, 1.0],
        [0.0, 1.0, 0.0, 0.0, 1.0, 1.0],
    ];
    let cu = Value::Cell {
        dims: &[1, 3],
        items: lines.iter().map(|l| real(&[3, 2], l)).collect(),
    };
    let cv = Value::Cell {
        dims: &[1, 2],
        items: vec![nurbs(&a0), nurbs(&a1)],
    };
    let args = [
        cu,
        cv,
        real(&[1, 3], &[0.0, 0.5, 1.0]),
        real(&[1, 2], &[0.0, 1.0]),
        real(&[1, 1], &[0.25]),
        real(&[1, 1], &[0.75]),
        Value::Char {
            dims: &[1, 5],
            bytes: b"exact",
        },
    ];
    let mut out = VecSink::default();
    call(gordon, &args, 2, &mut out).unwrap();
    assert_eq!(out.get(0).items(), ["15/17", "8/17", "3/4"]);
    // The bad input is named as the usage line names it, worded as the command line does.
    let bad = [0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0];
    let mut args = args.to_vec();
    args[1] = Value::Cell {
        dims: &[1, 2],
        items: vec![nurbs(&bad), nurbs(&a1)],
    };
    let e = call(gordon, &args, 1, &mut out).unwrap_err();
    assert!(e.to_string().contains("cv: "), "{e}");
    assert_eq!(e.identifier(), "cagd:weights");
}

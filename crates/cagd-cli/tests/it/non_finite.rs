//! The NaN/Inf policy (README "NaN and infinity", crate docs): non-finite numbers are
//! rejected with a typed error at every entry point — every public constructor, every
//! evaluation that takes parameters, every parser, every command-line input.

use cagd::coons::{CoonsBoundary, Mask};
use cagd::interpolation::{LagrangePolynomial, ParametricInterpolant, PiecewiseLinear};
use cagd::lagrange::Lagrange;
use cagd::surfaces::FergusonPatch;
use cagd::{
    BSplineCurve, BSplineSurface, BezierCurve, BezierPatch, CoonsPatch, CubicSpline, EndCondition,
    Error, GordonSurface, HermiteCubic, KnotVector, NurbsCurve, NurbsSurface, SampledCurve,
    Tolerance,
};
use nalgebra::{dmatrix, dvector, DMatrix, DVector};

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

fn non_finite<T: std::fmt::Debug>(r: Result<T, Error>) -> bool {
    matches!(r, Err(Error::NonFinite { .. }))
}

/// `n` points in 2-D with entry `k` replaced by `x`.
fn pts_with(n: usize, k: usize, x: f64) -> DMatrix<f64> {
    let mut m = DMatrix::from_fn(2, n, |i, j| (i + 2 * j) as f64);
    m[k] = x;
    m
}

#[test]
fn bezier_curves_and_patches() {
    for x in BAD {
        assert!(non_finite(BezierCurve::new(pts_with(3, 4, x))), "{x}");
        assert!(non_finite(BezierCurve::from_points(&[[0.0, x]])), "{x}");
        assert!(non_finite(BezierCurve::new_on_interval(
            pts_with(3, 0, 0.0),
            x,
            1.0
        )));
        let c = BezierCurve::new(pts_with(3, 0, 0.0)).unwrap();
        assert!(non_finite(c.try_eval(x)), "{x}");
        assert!(non_finite(c.eval_many(&[0.5, x])), "{x}");
        let mut z = DMatrix::from_element(2, 2, 1.0);
        z[(1, 1)] = x;
        assert!(non_finite(BezierPatch::new(vec![z])), "{x}");
        let p = BezierPatch::new(vec![DMatrix::from_element(2, 2, 1.0)]).unwrap();
        assert!(non_finite(p.try_eval(0.5, x)), "{x}");
        assert!(non_finite(p.try_eval_grid(&[x], &[0.5])), "{x}");
    }
}

#[test]
fn splines_and_nurbs() {
    for x in BAD {
        let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        assert!(non_finite(BSplineCurve::new(
            2,
            knots.clone(),
            pts_with(3, 1, x)
        )));
        let mut bad_knots = knots.clone();
        bad_knots[3] = x;
        assert!(BSplineCurve::new(2, bad_knots.clone(), pts_with(3, 0, 0.0)).is_err());
        assert!(KnotVector::new(vec![0.0, x]).is_err());
        assert!(non_finite(BSplineCurve::clamped(2, pts_with(3, 2, x))));
        let w = vec![1.0, x, 1.0];
        assert!(NurbsCurve::new(2, knots.clone(), pts_with(3, 0, 0.0), w).is_err());
        assert!(non_finite(NurbsCurve::new(
            2,
            knots.clone(),
            pts_with(3, 5, x),
            vec![1.0; 3]
        )));
        let mut z = DMatrix::from_element(3, 3, 1.0);
        z[4] = x;
        assert!(non_finite(BSplineSurface::clamped(2, 2, vec![z.clone()])));
        assert!(non_finite(NurbsSurface::new(
            2,
            2,
            knots.clone(),
            knots.clone(),
            vec![z],
            DMatrix::from_element(3, 3, 1.0)
        )));
        let c = BSplineCurve::clamped(2, pts_with(3, 0, 0.0)).unwrap();
        assert!(c.try_eval(x).is_err());
    }
}

#[test]
fn interpolation_hermite_and_cubic_splines() {
    for x in BAD {
        assert!(non_finite(LagrangePolynomial::new(
            vec![0.0, 1.0],
            vec![0.0, x]
        )));
        assert!(non_finite(PiecewiseLinear::new(
            vec![0.0, x],
            vec![0.0, 1.0]
        )));
        assert!(non_finite(ParametricInterpolant::new(
            pts_with(2, 3, x),
            vec![0.0, 1.0]
        )));
        assert!(Lagrange::new(vec![0.0, x]).is_err());
        let e = dvector![1.0, 0.0];
        assert!(non_finite(HermiteCubic::new(
            dvector![0.0, x],
            e.clone(),
            e.clone(),
            e.clone()
        )));
        assert!(non_finite(CubicSpline::interpolate(
            pts_with(4, 6, x),
            EndCondition::Natural
        )));
        assert!(non_finite(CubicSpline::interpolate(
            pts_with(4, 0, 0.0),
            EndCondition::Clamped {
                start: dvector![x, 0.0],
                end: e.clone()
            }
        )));
        let v = |a: f64| DVector::from_vec(vec![a, 0.0]);
        let corners = |a: f64| [[v(a), v(1.0)], [v(0.0), v(1.0)]];
        assert!(non_finite(FergusonPatch::new(
            &corners(x),
            &corners(0.0),
            &corners(0.0),
            &corners(0.0)
        )));
    }
}

#[test]
fn coons_gordon_and_masks() {
    let line = |a: [f64; 2], b: [f64; 2]| {
        SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]])
    };
    for x in BAD {
        assert!(non_finite(line([0.0, x], [1.0, 0.0])));
        assert!(non_finite(SampledCurve::new(
            vec![0.0, x],
            DMatrix::zeros(2, 2)
        )));
        // Closure curves are checked where the construction evaluates them.
        let bad = cagd::FnCurve::new(2, move |t: f64| dvector![t, x]);
        let ok = |a: [f64; 2], b: [f64; 2]| -> Box<dyn cagd::Curve<f64>> {
            Box::new(line(a, b).unwrap())
        };
        let r = CoonsPatch::new(
            Box::new(bad) as Box<dyn cagd::Curve<f64>>,
            ok([0.0, 1.0], [1.0, 1.0]),
            ok([0.0, 0.0], [0.0, 1.0]),
            ok([1.0, 0.0], [1.0, 1.0]),
        );
        assert!(r.is_err(), "{x}");
        let r = CoonsBoundary::new(
            line([0.0, 0.0], [1.0, 0.0]).unwrap(),
            line([0.0, 1.0], [1.0, 1.0]).unwrap(),
            line([0.0, 0.0], [0.0, 1.0]).unwrap(),
            line([1.0, 0.0], [1.0, 1.0]).unwrap(),
            Tolerance::Absolute(x),
        );
        assert!(r.is_err(), "tolerance {x}");
        let at_u = vec![
            line([0.0, 0.0], [0.0, 1.0]).unwrap(),
            line([1.0, 0.0], [1.0, 1.0]).unwrap(),
        ];
        let at_v = vec![
            line([0.0, 0.0], [1.0, 0.0]).unwrap(),
            line([0.0, 1.0], [1.0, 1.0]).unwrap(),
        ];
        assert!(non_finite(
            GordonSurface::new(vec![0.0, x], vec![0.0, 1.0], at_u, at_v).map(|_| ())
        ));
        assert!(Mask::new(x, 0.25).is_err());
        let mut net = DMatrix::from_element(3, 3, 1.0);
        net[0] = x;
        assert!(non_finite(cagd::coons::discrete_coons(&[net.clone()])));
        assert!(non_finite(cagd::coons::solve_mask(
            &[net],
            &Mask::coons(),
            &cagd::Limits::default()
        )));
    }
}

#[test]
fn parsers_and_readers() {
    use cagd_octave::literal::{parse_matrix, parse_params, LiteralError};
    for text in ["[1 NaN]", "Inf", "[0 -Inf]", "1e308*10", "0/0", "nan", "NA"] {
        assert!(
            matches!(
                parse_matrix::<f64>(text),
                Err(LiteralError::NonFinite { .. } | LiteralError::UnknownVariable { .. })
            ),
            "{text}"
        );
        assert!(parse_params::<f64>(text).is_err(), "{text}");
    }
    let r = cagd_octave::script::run::<f64>("x = Inf;", Default::default());
    assert!(matches!(r, Err(LiteralError::NonFinite { .. })));
    // The Octave text reader keeps what Octave wrote (Inf, NaN, NA are values in a file);
    // the command line refuses them as input (see below).
    let ws = cagd_octave::text_format::read_text("# name: x\n# type: scalar\nNaN\n").unwrap();
    assert!(ws.scalar("x").unwrap().is_nan());
}

/// Every command-line input path that takes numbers refuses NaN and Inf with exit code 2.
#[test]
fn command_line_inputs() {
    use cagd_cli::{run, ErrorKind};
    let dir = tempfile::tempdir().unwrap();
    let octave = dir.path().join("inf.txt");
    std::fs::write(
        &octave,
        "# name: A\n# type: matrix\n# rows: 2\n# columns: 2\n 0 Inf\n 1 2\n",
    )
    .unwrap();
    let numeric = dir.path().join("nan.csv");
    std::fs::write(&numeric, "0,1,NaN\n0,1,2\n").unwrap();
    let script = dir.path().join("s.m");
    std::fs::write(&script, "c1 = [u;0;Inf*u];\n").unwrap();
    let o = octave.to_str().unwrap();
    let n = numeric.to_str().unwrap();
    let s = script.to_str().unwrap();
    let cases: Vec<Vec<&str>> = vec![
        vec!["decasteljau", "[0 NaN 1]"],
        vec!["decasteljau", o],
        vec!["decasteljau", n],
        vec!["decasteljau", "[0 1]", "--t", "Inf"],
        vec!["bezier-patch", o, "--n", "3"],
        vec!["bezier-patch", "[0 0 0 0 1 0; 1 0 0 1 1 NaN]", "--n", "3"],
        vec!["bernstein", "--degree", "2", "--t", "[0 NaN]"],
        vec!["derivative", "[0 1 Inf]"],
        vec!["lagrange", "--nodes", "[0 Inf]"],
        vec!["lagrange", "--nodes", "[0 1]", "--points", "[0 NaN]"],
        vec!["spline", "[0 0; 1 Inf; 2 0]'"],
        vec![
            "hermite", "--p0", "[0;NaN]", "--p1", "[1;0]", "--t0", "[1;1]", "--t1", "[1;1]",
        ],
        vec!["bspline", "[0 0; 1 2; 3 Inf]'", "--degree", "2"],
        vec![
            "nurbs",
            "[1 0; 1 1; 0 1]'",
            "--weights",
            "[1 Inf 1]",
            "--degree",
            "2",
        ],
        vec!["curve", "[u; Inf*u]"],
        vec!["curve", "[u; exp(1000*u)]", "--t", "1"],
        vec!["surface", "[u; v; u/0]", "--n", "2"],
        vec![
            "coons",
            "--c1",
            "[u;0;NaN]",
            "--c2",
            "[u;1;0]",
            "--d1",
            "[0;v;0]",
            "--d2",
            "[1;v;0]",
        ],
        vec![
            "coons", "--script", s, "--c2", "[u;1;0]", "--d1", "[0;v;0]", "--d2", "[1;v;0]",
        ],
        vec![
            "gordon",
            "--v-curve",
            "[u;0;0]",
            "--v-curve",
            "[u;1;0]",
            "--u-curve",
            "[0;v;0]",
            "--u-curve",
            "[1;v;0]",
            "--u-nodes",
            "[0 Inf]",
        ],
        vec![
            "discrete-coons",
            "[0 0 0 0 1 0 0 2 0; 1 0 0 0 0 0 1 2 1; 2 0 0 2 1 1 2 2 NaN]",
        ],
        vec!["script", s],
    ];
    for case in cases {
        let mut args = vec!["cagd"];
        args.extend(&case);
        let err = run(&args).expect_err(&format!("{case:?} must fail"));
        assert_eq!(err.exit_code(), 2, "{case:?}");
        let msg = err.to_string();
        assert!(
            msg.contains("finite") || msg.contains("NaN") || msg.contains("Inf"),
            "{case:?}: {msg}"
        );
        assert!(!matches!(err.kind, ErrorKind::Internal), "{case:?}");
    }
}

/// `--exact --format octave`: an exact result is finite, but its double may not be. Octave's
/// format stores doubles, so such a value is refused, naming the entry and the exact value,
/// instead of being written as Inf — for every subcommand, by the one renderer. The exact
/// formats still print it.
#[test]
fn exact_results_beyond_the_doubles_are_refused_in_octave_format() {
    use cagd_cli::{run, ErrorKind};
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("big.m");
    std::fs::write(&script, "x = [1 2];\nbig = [1e308 -1e308] * 5;\n").unwrap();
    let s = script.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["decasteljau", "[1e308 -1e308; 0 1]", "--t", "5"],
            "result(1,1) is the exact value `-9",
        ),
        (vec!["curve", "[1e308*u; u]", "--t", "5"], "result(1,1)"),
        (
            vec!["surface", "[1e308*u; v; u]", "--u", "5", "--v", "0"],
            "result(1,1,1) is",
        ),
        (
            vec![
                "lagrange",
                "--nodes",
                "[0 1]",
                "--points",
                "[0 1e308]",
                "--t",
                "5",
            ],
            "result(1,1)",
        ),
        (
            vec!["bernstein", "--degree", "2", "--t", "1e200"],
            "result(1,1)",
        ),
        (vec!["script", s], "big(1,1) is the exact value `500"),
        (
            vec!["decasteljau", "[1e308 -1e308; 0 1]", "--t", "5", "--steps"],
            "-Inf",
        ),
    ];
    for (case, named) in cases {
        let mut args = vec!["cagd"];
        args.extend(&case);
        args.extend(["--exact", "--format", "octave"]);
        let err = run(&args).expect_err(&format!("{case:?} must be refused"));
        let msg = err.to_string();
        assert_eq!(err.argument, "--format octave", "{case:?}: {msg}");
        assert!(msg.contains(named), "{case:?}: {msg}");
        assert!(msg.contains("beyond the range of doubles"), "{msg}");
        assert!(
            matches!(&err.kind, ErrorKind::Library(e) if matches!(**e, cagd::Error::NonFinite { .. })),
            "{case:?}"
        );
        assert_eq!(err.exit_code(), 2);
        // The exact formats write the same value as a fraction.
        let mut exact = args.clone();
        exact.truncate(args.len() - 1);
        exact.push("json");
        let out = run(&exact).unwrap_or_else(|e| panic!("{case:?} in json: {e}"));
        assert!(
            out.stdout.contains("0000000000\""),
            "{case:?}: {}",
            out.stdout
        );
    }
    // Within the doubles, Octave's format is written as before.
    let out = run([
        "cagd",
        "decasteljau",
        "[1e300 -1e300; 0 1]",
        "--t",
        "5",
        "--exact",
        "--format",
        "octave",
    ])
    .unwrap();
    assert!(out.stdout.contains("# name: result"), "{}", out.stdout);
}

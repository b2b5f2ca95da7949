//! Any curve of the library as a boundary, network curve or ruling on the command line:
//! `bezier(P)`, `bspline(P, U)` and `nurbs(P, W, U)` in `gordon`, `ruled`, `coons`,
//! `coons-bicubic` and `ferguson`, exact where rational. The expected values are computed independently of the
//! library, with Python's `fractions` from the textbook formulas (Cox–de Boor for the
//! B-splines, the rational Bézier form for the NURBS, thesis (4.1) for the bilinear patch,
//! thesis (4.5) and Gregory's square for the bicubic patch); the derivations are in the comments, the computation in
//! `any_curve_oracle.py` beside this file.

use cagd_cli::run;
use serde_json::Value as J;

/// The JSON answer of `cagd args… --format json` (in-process).
fn json(args: &[&str]) -> J {
    let mut full: Vec<String> = std::iter::once("cagd")
        .chain(args.iter().copied())
        .map(String::from)
        .collect();
    full.extend(["--format".into(), "json".into()]);
    let out = run(&full).unwrap_or_else(|e| panic!("cagd {args:?} failed: {e}"));
    serde_json::from_str(&out.stdout).unwrap()
}

/// An exact column (`d × 1`, `--exact`) as its strings.
fn column(v: &J) -> Vec<String> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|r| r[0].as_str().unwrap().to_string())
        .collect()
}

/// The error line of a command that must fail with exit 2.
fn error(args: &[&str]) -> String {
    let full: Vec<String> = std::iter::once("cagd")
        .chain(args.iter().copied())
        .map(String::from)
        .collect();
    let e = run(&full).expect_err("must fail");
    assert_eq!(e.exit_code(), 2, "{e}");
    e.to_string()
}

/// The knots of the quadratic B-splines in `t ∈ [0, 2]` below (one interior knot at 1).
const K: &str = "[0 0 0 1 2 2 2]";

#[test]
fn gordon_surface_of_b_spline_curves_is_exact() {
    // The biquadratic surface S(u, t) = Σ_i Σ_j B_i²(u) N_j(t) P_ij, Bernstein in u, the
    // quadratic B-spline basis of knots [0 0 0 1 2 2 2] in t = 2v, P_ij = (i/2, j, z_ij) with
    // z = [0 1 1 0; 1 2 3 1; 0 1 2 4]. Its curves g(u_i, ·) at u_i = 0, 1/2, 1 are B-splines
    // in v with the control points Σ_i B_i²(u_i) P_ij; its curves g(·, v_j) at t = 0, 1, 2 are
    // quadratics in u with the control points Σ_j N_j(t) P_ij (N(1) = (0, 1/2, 1/2, 0)).
    // S is quadratic in u, so g1 = S and g12 = g2: the Gordon surface is S itself, and
    // S(1/4, 3/2) = (1/4, 17/8, 187/128).
    let u_curve = |p: &str| format!("bspline({p}, {K})");
    let v_curve = |p: &str| format!("bspline({p}, [0 0 0 1 1 1])");
    let curves = [
        ("--u-curve", u_curve("[0 0 0 0; 0 1 2 3; 0 1 1 0]")),
        (
            "--u-curve",
            u_curve("[1/2 1/2 1/2 1/2; 0 1 2 3; 1/2 3/2 9/4 3/2]"),
        ),
        ("--u-curve", u_curve("[1 1 1 1; 0 1 2 3; 0 1 2 4]")),
        ("--v-curve", v_curve("[0 1/2 1; 0 0 0; 0 1 0]")),
        ("--v-curve", v_curve("[0 1/2 1; 3/2 3/2 3/2; 1 5/2 3/2]")),
        ("--v-curve", v_curve("[0 1/2 1; 3 3 3; 0 1 4]")),
    ];
    let mut args = vec!["gordon"];
    for (flag, curve) in &curves {
        args.extend([*flag, curve.as_str()]);
    }
    let exact = [
        args.clone(),
        vec!["--u", "0.25", "--v", "0.75", "--steps", "--exact"],
    ]
    .concat();
    let out = json(&exact);
    assert_eq!(column(&out["result"]), ["1/4", "17/8", "187/128"]);
    assert_eq!(column(&out["g1"]), ["1/4", "17/8", "187/128"]);
    assert_eq!(column(&out["g2"]), column(&out["g12"]));
    // In doubles, the same to rounding.
    let out = json(&[args, vec!["--u", "0.25", "--v", "0.75"]].concat());
    let x: Vec<f64> = (0..3)
        .map(|k| out["result"][k][0].as_f64().unwrap())
        .collect();
    for (got, want) in x.iter().zip([0.25, 17.0 / 8.0, 187.0 / 128.0]) {
        assert!((got - want).abs() < 1e-14, "{x:?}");
    }
}

#[test]
fn ruled_surface_between_two_nurbs_curves_is_exact() {
    // The quarter circle of radius 1 at z = 0 (points (1,0), (1,1), (0,1), weights 1, 1, 2):
    // at its parameter 1/2, ((1/4 + 1/2)/(5/4), (1/2 + 2/4)/(5/4)) = (3/5, 4/5). The second
    // curve is the circle of radius 2 at z = 1 on the knots [0 0 0 2 2 2] (domain [0, 2],
    // mapped onto u ∈ [0, 1]): (6/5, 8/5, 1) at u = 1/2. So
    // x(1/2, 1/4) = 3/4 (3/5, 4/5, 0) + 1/4 (6/5, 8/5, 1) = (3/4, 1, 1/4).
    let first = "nurbs([1 1 0; 0 1 1; 0 0 0], [1 1 2], [0 0 0 1 1 1])";
    let second = "nurbs([2 2 0; 0 2 2; 1 1 1], [1 1 2], [0 0 0 2 2 2])";
    let args = ["ruled", "--first", first, "--second", second];
    let out = json(&[&args[..], &["--u", "0.5", "--v", "0.25", "--exact"]].concat());
    assert_eq!(column(&out["result"]), ["3/4", "1", "1/4"]);
    // The steps show each curve as the surface uses it, at the u's.
    let out = json(
        &[
            &args[..],
            &["--u", "[0 0.5 1]", "--v", "0", "--steps", "--exact"],
        ]
        .concat(),
    );
    let at_half: Vec<&str> = (0..3)
        .map(|k| out["second"][k][1].as_str().unwrap())
        .collect();
    assert_eq!(at_half, ["6/5", "8/5", "1"]);
    let first_end: Vec<&str> = (0..3)
        .map(|k| out["first"][k][2].as_str().unwrap())
        .collect();
    assert_eq!(first_end, ["0", "1", "0"]);
}

/// The boundary data of the bicubic test: `c1` a quadratic B-spline bump on [0, 2]
/// (x = u, z = 0 → 1 → 0; its unit tangents (1, 0, ±4) at the ends), `c2`, `d1`, `d2` lines,
/// the cross-boundary curves meeting those tangents at the corners, `x_v(u, 0)` a quadratic
/// bump (0, 1, 2·2u(1 − u)). The twist data disagree: at (0, 0) `∂/∂v x_u = (0, 0, −4)` but
/// `∂/∂u x_v = (0, 0, 4)`.
fn bicubic_data() -> Vec<String> {
    [
        "coons-bicubic",
        "--c1",
        &format!("bspline([0 1/4 3/4 1; 0 0 0 0; 0 1 1 0], {K})"),
        "--c2",
        "bspline([0 1; 1 1; 0 0], [0 0 1 1])",
        "--d1",
        "bezier([0 0; 0 1; 0 0])",
        "--d2",
        "bezier([1 1; 0 1; 0 0])",
        "--d1u",
        "bezier([1 1; 0 0; 4 0])",
        "--d2u",
        "bezier([1 1; 0 0; -4 0])",
        "--c1v",
        "bezier([0 0 0; 1 1 1; 0 2 0])",
        "--c2v",
        "bezier([0 0; 1 1; 0 0])",
        "--exact",
    ]
    .map(String::from)
    .to_vec()
}

#[test]
fn coons_bicubic_with_b_spline_boundaries_and_gregory_twists_is_exact() {
    // Thesis (4.5) with H0..H3 = 2t³−3t²+1, t³−2t²+t, t³−t², −2t³+3t² and Gregory's
    // T_ij = (|u−i| a + |v−j| b)/(|u−i| + |v−j|), evaluated by hand in fractions:
    // at (1/2, 1/4): h_c = (1/2, 1/4, 3/4), h_d = (1/2, 1/4, 63/64),
    // h_cd = (1/2, 1/4, 261/320), x = (1/2, 1/4, 147/160); at (1/4, 3/4): z = 615/4096.
    // With zero twists instead: z(1/2, 1/4) = 57/64.
    let data = bicubic_data();
    let base: Vec<&str> = data.iter().map(String::as_str).collect();
    let gregory = [&base[..], &["--twist", "gregory"]].concat();
    let out = json(&[&gregory[..], &["--u", "0.5", "--v", "0.25", "--steps"]].concat());
    assert_eq!(column(&out["hc"]), ["1/2", "1/4", "3/4"]);
    assert_eq!(column(&out["hd"]), ["1/2", "1/4", "63/64"]);
    assert_eq!(column(&out["hcd"]), ["1/2", "1/4", "261/320"]);
    assert_eq!(column(&out["result"]), ["1/2", "1/4", "147/160"]);
    let out = json(&[&gregory[..], &["--u", "0.25", "--v", "0.75"]].concat());
    assert_eq!(column(&out["result"]), ["1/4", "3/4", "615/4096"]);
    let out = json(&[&base[..], &["--u", "0.5", "--v", "0.25"]].concat());
    assert_eq!(column(&out["result"]), ["1/2", "1/4", "57/64"]);
    // A cross-boundary curve that misses a boundary tangent is named with the others.
    let mut bad = gregory.clone();
    let k = bad.iter().position(|a| *a == "--d1u").unwrap();
    bad[k + 1] = "bezier([1 1; 0 0; 3 0])";
    let e = error(&bad);
    assert!(
        e.starts_with("--c1v/--c2v/--d1u/--d2u: ") && e.contains("c1'(0)"),
        "{e}"
    );
}

#[test]
fn ferguson_patch_of_boundary_curves_takes_their_corner_data() {
    // The edges of z = uv as Bézier lines, twists 1: the hyperbolic paraboloid, as with the
    // corner matrices (course.rs): x(1/2, 1/4) = (1/2, 1/4, 1/8).
    let twists = "[0 0 1; 0 0 1; 0 0 1; 0 0 1]'";
    let at = ["--u", "0.5", "--v", "0.25", "--exact"];
    let curves = json(
        &[
            &[
                "ferguson",
                "--c1",
                "bezier([0 1; 0 0; 0 0])",
                "--c2",
                "bezier([0 1; 1 1; 0 1])",
                "--d1",
                "bezier([0 0; 0 1; 0 0])",
                "--d2",
                "bezier([1 1; 0 1; 0 1])",
                "--twists",
                twists,
            ][..],
            &at,
        ]
        .concat(),
    );
    assert_eq!(column(&curves["result"]), ["1/2", "1/4", "1/8"]);
    let corners = json(
        &[
            &[
                "ferguson",
                "--points",
                "[0 0 0; 1 0 0; 0 1 0; 1 1 1]'",
                "--du",
                "[1 0 0; 1 0 0; 1 0 1; 1 0 1]'",
                "--dv",
                "[0 1 0; 0 1 1; 0 1 0; 0 1 1]'",
                "--twists",
                twists,
            ][..],
            &at,
        ]
        .concat(),
    );
    assert_eq!(curves, corners);
    // The B-spline bump of the bicubic test as c1: its ends (0,0,0), (1,0,0) and unit
    // tangents (1,0,4), (1,0,−4) give the Hermite edge z(1/2) = 4/8 + 4/8 = 1.
    let out = json(&[
        "ferguson",
        "--c1",
        &format!("bspline([0 1/4 3/4 1; 0 0 0 0; 0 1 1 0], {K})"),
        "--c2",
        "bezier([0 1; 1 1; 0 0])",
        "--d1",
        "bezier([0 0; 0 1; 0 0])",
        "--d2",
        "bezier([1 1; 0 1; 0 0])",
        "--u",
        "0.5",
        "--v",
        "0",
        "--exact",
    ]);
    assert_eq!(column(&out["result"]), ["1/2", "0", "1"]);
    let e = error(&[
        "ferguson",
        "--points",
        "zeros(3,4)",
        "--c1",
        "bezier([0 1; 0 0; 0 0])",
    ]);
    assert!(
        e.starts_with("--points: has no effect with boundary curves"),
        "{e}"
    );
}

#[test]
fn plane_boundaries_give_a_plane_patch_on_a_grid() {
    // Boundary expressions in 2-D (a patch of the plane): on a grid the patch has two
    // coordinates, x(1/2, 1/2) = rc + rd − rcd = (1/2, 5/8) + (1/2, 1/2) − (1/2, 1/2). The
    // grid once assumed three coordinates and stopped with an internal error.
    let args = [
        "coons",
        "--c1",
        "[u;0]",
        "--c2",
        "[u;1+u-u^2]",
        "--d1",
        "[0;v]",
        "--d2",
        "[1;v]",
    ];
    let out = json(&[&args[..], &["--n", "3", "--exact"]].concat());
    let result = out["result"].as_array().unwrap();
    assert_eq!(result.len(), 3, "u");
    assert_eq!(result[1][1].as_array().unwrap().len(), 2, "two coordinates");
    assert_eq!(result[1][1], serde_json::json!(["1/2", "5/8"]));
    // With the parts: each is a plane grid too.
    let out = json(&[&args[..], &["--n", "3", "--steps", "--exact"]].concat());
    assert_eq!(out["rc"][1][1], serde_json::json!(["1/2", "5/8"]));
}

/// The issue's Coons example: `c1` the quadratic B-spline of the points (0,0,0), (1,0,1),
/// (2,0,0), (3,0,1), (4,0,0) on the knots [0 0 0 1 2 3 3 3] (degree 8 − 5 − 1 = 2, domain
/// [0, 3] mapped onto u ∈ [0, 1]), the other sides lines meeting it at the corners.
const ISSUE_COONS: [&str; 9] = [
    "coons",
    "--c1",
    "bspline([0 1 2 3 4; 0 0 0 0 0; 0 1 0 1 0], [0 0 0 1 2 3 3 3])",
    "--c2",
    "[4*u; 1; 0]",
    "--d1",
    "[0; v; 0]",
    "--d2",
    "[4; v; 0]",
];

#[test]
fn coons_with_a_b_spline_boundary_prints_the_issues_value() {
    // On the side v = 0 the patch is c1: u = 1/2 is t = 3/2 in [1, 2), where de Boor (Cox–de
    // Boor by hand) gives the weights 1/8, 3/4, 1/8 of (1,0,1), (2,0,0), (3,0,1):
    // x(1/2, 0) = (1/8 + 3/2 + 3/8, 0, 1/8 + 1/8) = (2, 0, 1/4).
    let args = [&ISSUE_COONS[..], &["--u", "0.5", "--v", "0", "--exact"]].concat();
    let full: Vec<String> = std::iter::once("cagd")
        .chain(args.iter().copied())
        .map(String::from)
        .collect();
    let out = run(&full).unwrap();
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
    assert!(
        out.stdout
            .ends_with("result =\n\n      2\n      0\n    1/4\n\n"),
        "{}",
        out.stdout
    );
    assert_eq!(column(&json(&args)["result"]), ["2", "0", "1/4"]);
    // Inside: rc = ((2,0,1/4) + (2,1,0))/2, and rd = rcd = (4u, v, 0) (the sides are the
    // bilinear patch of the corners), so x(1/2, 1/2) = (2, 1/2, 1/8).
    let inside = [&ISSUE_COONS[..], &["--u", "0.5", "--v", "0.5", "--exact"]].concat();
    assert_eq!(column(&json(&inside)["result"]), ["2", "1/2", "1/8"]);
}

#[test]
fn coons_with_b_spline_boundaries_on_a_grid_is_exact() {
    // Every side a B-spline: c1 as in the issue; c2 the linear B-spline of (0,1,0), (2,1,0),
    // (4,1,0) on [0 0 1 2 2] = (4u, 1, 0); d1, d2 linear on [0 0 1 1] = (0, v, 0), (4, v, 0).
    // rd = rcd, so x = (1 − v) c1(u) + v c2(u): with c1(0), c1(1/2), c1(1) = (0,0,0),
    // (2,0,1/4), (4,0,0), on the grid u, v ∈ {0, 1/2, 1} (the oracle's table).
    let out = json(&[
        "coons",
        "--c1",
        ISSUE_COONS[2],
        "--c2",
        "bspline([0 2 4; 1 1 1; 0 0 0], [0 0 1 2 2])",
        "--d1",
        "bspline([0 0; 0 1; 0 0], [0 0 1 1])",
        "--d2",
        "bspline([4 4; 0 1; 0 0], [0 0 1 1])",
        "--u",
        "[0 0.5 1]",
        "--v",
        "[0 0.5 1]",
        "--exact",
    ]);
    let expected = [
        [["0", "0", "0"], ["0", "1/2", "0"], ["0", "1", "0"]],
        [["2", "0", "1/4"], ["2", "1/2", "1/8"], ["2", "1", "0"]],
        [["4", "0", "0"], ["4", "1/2", "0"], ["4", "1", "0"]],
    ];
    assert_eq!(out["result"], serde_json::json!(expected));
}

#[test]
fn coons_with_nurbs_boundaries_reproduces_the_cylinder() {
    // c1 the quarter circle (1,0,0) → (0,1,0) with weights 1, 1, 2 (w1²/(w0 w2) = 1/2: a
    // circular arc), c2 the same at z = 1, d1, d2 the vertical lines between their ends. The
    // Coons patch is the piece of the unit cylinder they bound: at u = 1/2 the rational
    // Bézier form gives ((1/4 + 1/2)/(5/4), (1/2 + 1/2)/(5/4)) = (3/5, 4/5); at u = 1/4,
    // (15/17, 8/17); and rd = rcd, so x(u, v) = (c1(u)_x, c1(u)_y, v).
    let args = [
        "coons",
        "--c1",
        "nurbs([1 1 0; 0 1 1; 0 0 0], [1 1 2], [0 0 0 1 1 1])",
        "--c2",
        "nurbs([1 1 0; 0 1 1; 1 1 1], [1 1 2], [0 0 0 1 1 1])",
        "--d1",
        "[1; 0; v]",
        "--d2",
        "[0; 1; v]",
    ];
    for (u, v, want) in [
        ("0.5", "0.25", ["3/5", "4/5", "1/4"]),
        ("0.25", "0.75", ["15/17", "8/17", "3/4"]),
    ] {
        let out = json(&[&args[..], &["--u", u, "--v", v, "--exact"]].concat());
        assert_eq!(column(&out["result"]), want, "({u}, {v})");
    }
    // In doubles, every grid point on the cylinder x² + y² = 1.
    let out = json(&[&args[..], &["--n", "5"]].concat());
    for row in out["result"].as_array().unwrap() {
        for p in row.as_array().unwrap() {
            let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
            assert!((x.hypot(y) - 1.0).abs() < 1e-14, "{p}");
        }
    }
}

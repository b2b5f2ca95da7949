//! `cagd curvature`: κ and the Frenet frame of Bézier, B-spline and NURBS curves, against
//! values worked out by hand (derivatives of the curves' polynomial and rational forms).

use serde_json::Value as J;

fn json(args: &[&str]) -> J {
    let mut argv = vec!["cagd", "curvature"];
    argv.extend_from_slice(args);
    argv.extend_from_slice(&["--format", "json"]);
    let out = cagd_cli::run(argv.iter().copied()).unwrap_or_else(|e| panic!("{args:?}: {e}"));
    serde_json::from_str(&out.stdout).unwrap()
}

fn row(v: &J) -> Vec<String> {
    v[0].as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_string))
        .collect()
}

#[test]
fn the_parabola_as_bezier_bspline_and_nurbs_has_kappa_squared_4_over_1_plus_4t2_cubed() {
    // x(t) = (t, t²): x′ = (1, 2t), x″ = (0, 2), κ² = 4 / (1 + 4t²)³: at t = 0 it is 4; at
    // t = 1/4, 1 + 4t² = 5/4, so 4 · 64/125 = 256/125; at t = 1/2, 4/8 = 1/2.
    let expected = ["4", "256/125", "1/2"];
    for curve in [
        "[0 0.5 1; 0 0 1]",
        "bezier([0 0.5 1; 0 0 1])",
        "bspline([0 0.5 1; 0 0 1], [0 0 0 1 1 1])",
        "nurbs([0 0.5 1; 0 0 1], [1 1 1], [0 0 0 1 1 1])",
    ] {
        let v = json(&[curve, "--t", "[0 1/4 1/2]", "--exact"]);
        assert_eq!(row(&v["result"]), expected, "{curve}");
    }
    // In doubles: κ = 2/(1+4t²)^{3/2}, the frame turns left (signed κ > 0).
    let v = json(&["[0 0.5 1; 0 0 1]", "--t", "0.5"]);
    let kappa = v["result"][0][0].as_f64().unwrap();
    assert!((kappa - 2.0 / 2f64.powf(1.5)).abs() < 1e-15, "{kappa}");
    let t: Vec<f64> = [0, 1]
        .map(|r| v["tangent"][r][0].as_f64().unwrap())
        .to_vec();
    let s = 0.5f64.sqrt();
    assert!(
        (t[0] - s).abs() < 1e-15 && (t[1] - s).abs() < 1e-15,
        "{t:?}"
    );
}

#[test]
fn the_nurbs_quarter_circle_has_curvature_one_and_its_normal_points_to_the_centre() {
    // (1,0), (1,1), (0,1) with weights 1, 1, 2: the unit circle; (3/5, 4/5) at t = 1/2.
    let v = json(&[
        "nurbs([1 1 0; 0 1 1], [1 1 2], [0 0 0 1 1 1])",
        "--t",
        "[0 0.5 1]",
        "--steps",
    ]);
    for k in 0..3 {
        assert!((v["result"][0][k].as_f64().unwrap() - 1.0).abs() < 1e-14);
    }
    // At t = 1/2 the point is (3/5, 4/5): N = −(3/5, 4/5), T = (−4/5, 3/5).
    let n = [
        v["normal"][0][1].as_f64().unwrap(),
        v["normal"][1][1].as_f64().unwrap(),
    ];
    let t = [
        v["tangent"][0][1].as_f64().unwrap(),
        v["tangent"][1][1].as_f64().unwrap(),
    ];
    assert!(
        (n[0] + 0.6).abs() < 1e-15 && (n[1] + 0.8).abs() < 1e-15,
        "{n:?}"
    );
    assert!(
        (t[0] + 0.8).abs() < 1e-15 && (t[1] - 0.6).abs() < 1e-15,
        "{t:?}"
    );
    // Exact: κ² = 1 at every parameter.
    let v = json(&[
        "nurbs([1 1 0; 0 1 1], [1 1 2], [0 0 0 1 1 1])",
        "--t",
        "[0 1/3 1/2 1]",
        "--exact",
    ]);
    assert_eq!(row(&v["result"]), ["1", "1", "1", "1"]);
}

#[test]
fn a_space_curve_has_its_binormal_and_a_straight_one_a_warning() {
    // The twisted cubic (t, t², t³) as a cubic Bézier curve: at t = 0, x′ = (1, 0, 0),
    // x″ = (0, 2, 0): κ = 2, T = e1, N = e2, B = e3.
    let v = json(&["[0 1/3 2/3 1; 0 0 1/3 1; 0 0 0 1]", "--t", "0"]);
    assert!((v["result"][0][0].as_f64().unwrap() - 2.0).abs() < 1e-14);
    let col = |name: &str| [0, 1, 2].map(|r| v[name][r][0].as_f64().unwrap());
    assert_eq!(col("tangent"), [1.0, 0.0, 0.0]);
    assert_eq!(col("normal"), [0.0, 1.0, 0.0]);
    assert_eq!(col("binormal"), [0.0, 0.0, 1.0]);
    // A straight space curve: κ = 0, and N, B undefined (warned, given as 0).
    let out = cagd_cli::run(["cagd", "curvature", "[0 1 2; 0 1 2; 0 1 2]", "--t", "0.5"]).unwrap();
    assert!(out.stdout.contains("result = 0"), "{}", out.stdout);
    assert!(
        out.warnings
            .iter()
            .any(|(a, w)| a == "--t" && w.message.contains("straight")),
        "{:?}",
        out.warnings
    );
}

#[test]
fn a_singular_point_and_bad_curves_are_refused_naming_the_argument() {
    // All control points equal: x′ = 0.
    let e = cagd_cli::run(["cagd", "curvature", "[1 1 1; 2 2 2]", "--t", "0.5"]).unwrap_err();
    assert_eq!(e.argument, "--t");
    assert!(e.problem.contains("tangent x′(t) is zero"), "{e}");
    let e = cagd_cli::run(["cagd", "curvature", "bspline([0 1; 0 1], [0 1])"]).unwrap_err();
    assert_eq!(e.argument, "CURVE", "{e}");
    let e = cagd_cli::run([
        "cagd",
        "curvature",
        "[0 1 2 3; 0 1 0 1; 0 0 1 1; 1 1 1 1]",
        "--t",
        "0.5",
    ])
    .unwrap_err();
    assert_eq!(e.argument, "CURVE", "{e}");
    assert!(e.problem.contains("4 coordinates"), "{e}");
}

/// The columns `k` of a JSON matrix as doubles.
fn column(v: &J, k: usize) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|r| r[k].as_f64().unwrap())
        .collect()
}

/// `v / |v|`.
fn unit(v: [f64; 3]) -> Vec<f64> {
    let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    v.iter().map(|x| x / n).collect()
}

fn close(got: &[f64], want: &[f64]) -> bool {
    got.len() == want.len() && got.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-14)
}

#[test]
fn a_space_b_spline_with_interior_knots_at_a_parameter_of_its_own_domain() {
    // The quadratic B-spline of (0,0,0), (1,1,0), (2,0,1), (3,1,1), (4,0,0) on the knots
    // [0 0 0 1 2 3 3 3] (domain [0, 3]; t is not mapped onto [0, 1]). On the span [1, 2) it is
    // one quadratic; Cox–de Boor gives x(1) = (3/2, 1/2, 1/2), x(3/2) = (2, 1/4, 7/8),
    // x(2) = (5/2, 1/2, 1), so with h = 1/2: x′(3/2) = (x(2) − x(1))/(2h) = (1, 0, 1/2) and
    // x″ = (x(1) − 2 x(3/2) + x(2))/h² = (0, 2, −1). Then x′ × x″ = (−1, 1, 2), |x′|² = 5/4 and
    // κ² = 6/(5/4)³ = 384/125; T = (2, 0, 1)/√5, B = (−1, 1, 2)/√6, N = B × T = (1, 5, −2)/√30.
    let curve = "bspline([0 1 2 3 4; 0 1 0 1 0; 0 0 1 1 0], [0 0 0 1 2 3 3 3])";
    let v = json(&[curve, "--t", "1.5", "--steps", "--exact"]);
    assert_eq!(row(&v["result"]), ["384/125"]);
    let exact_column = |name: &str| -> Vec<String> {
        v[name]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r[0].as_str().unwrap().to_string())
            .collect()
    };
    assert_eq!(exact_column("d1"), ["1", "0", "1/2"]);
    assert_eq!(exact_column("d2"), ["0", "2", "-1"]);
    let v = json(&[curve, "--t", "1.5"]);
    let kappa = v["result"][0][0].as_f64().unwrap();
    assert!((kappa - (384.0f64 / 125.0).sqrt()).abs() < 1e-14, "{kappa}");
    assert!(close(&column(&v["tangent"], 0), &unit([2.0, 0.0, 1.0])));
    assert!(close(&column(&v["binormal"], 0), &unit([-1.0, 1.0, 2.0])));
    assert!(close(&column(&v["normal"], 0), &unit([1.0, 5.0, -2.0])));
}

#[test]
fn a_nurbs_half_circle_of_two_arcs_has_kappa_one_half_and_normals_to_the_centre() {
    // Radius 2, two rational quadratic arcs meeting at a double knot: (2,0), (2,2), (0,2) with
    // weights 1, 1, 2 and (0,2), (−2,2), (−2,0) with weights 2, 1, 1 (w1²/(w0 w2) = 1/2: arcs
    // of a circle). κ = 1/2 everywhere, κ² = 1/4. At t = 1/2 the rational Bézier form gives
    // ((1/4·2 + 1/2·2)/(5/4), (1/2·2)/(5/4)) = (6/5, 8/5), at t = 3/2 (−6/5, 8/5): the normal
    // is −x/2 there, the tangent (counter-clockwise) the normal turned right, and κ > 0.
    let curve = "nurbs([2 2 0 -2 -2; 0 2 2 2 0], [1 1 2 1 1], [0 0 0 1 1 2 2 2])";
    let v = json(&[curve, "--t", "[0 1/2 1 3/2 2]", "--exact"]);
    assert_eq!(row(&v["result"]), ["1/4"; 5]);
    let v = json(&[curve, "--t", "[0.5 1.5]"]);
    for k in 0..2 {
        assert!((v["result"][0][k].as_f64().unwrap() - 0.5).abs() < 1e-14);
    }
    assert!(close(&column(&v["normal"], 0), &[-0.6, -0.8]));
    assert!(close(&column(&v["tangent"], 0), &[-0.8, 0.6]));
    assert!(close(&column(&v["normal"], 1), &[0.6, -0.8]));
    assert!(close(&column(&v["tangent"], 1), &[-0.8, -0.6]));
}

#[test]
fn the_twisted_cubic_as_a_bezier_curve_at_one_half() {
    // (t, t², t³): x′(1/2) = (1, 1, 3/4), x″(1/2) = (0, 2, 3); x′ × x″ = (3/2, −3, 2) of
    // squared length 61/4, |x′|² = 41/16: κ² = (61/4)/(41/16)³ = 62464/68921.
    // T = (4, 4, 3)/√41, B = (3, −6, 4)/√61, N = B × T = (−34, 7, 36)/√2501.
    let curve = "[0 1/3 2/3 1; 0 0 1/3 1; 0 0 0 1]";
    let v = json(&[curve, "--t", "0.5", "--exact"]);
    assert_eq!(row(&v["result"]), ["62464/68921"]);
    let v = json(&[curve, "--t", "0.5"]);
    let kappa = v["result"][0][0].as_f64().unwrap();
    assert!((kappa - (62464.0f64 / 68921.0).sqrt()).abs() < 1e-14);
    assert!(close(&column(&v["tangent"], 0), &unit([4.0, 4.0, 3.0])));
    assert!(close(&column(&v["binormal"], 0), &unit([3.0, -6.0, 4.0])));
    assert!(close(&column(&v["normal"], 0), &unit([-34.0, 7.0, 36.0])));
}

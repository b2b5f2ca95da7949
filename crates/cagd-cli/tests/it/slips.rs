//! Issue 24: no silent wrong answer — points as the notes write them, decimal commas wherever
//! numbers are read, one convention per word, messages that point to the fix, pictures that
//! show the answer. Each slip gives its note, warning or error; the explicit, correct readings
//! of the same data stay silent. Expected values are exact fractions worked out by hand from
//! the textbook formulas (de Casteljau, Lagrange), never the program's own output.

use std::path::Path;

use assert_cmd::Command;
use cagd_test_support::thesis_args::PRIMER_4_3;
use serde_json::Value as J;

use super::course::{error, run_ok, silent};

/// Runs the `cagd` binary (which writes its pictures), requiring success.
pub(super) fn binary(args: &[&str]) {
    let out = Command::cargo_bin("cagd")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "cagd {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The exact `result` of a command (`--exact --format json`), row by row.
fn exact_result(args: &[&str]) -> Vec<Vec<String>> {
    exact_named(args, "result")
}

/// The exact output `name` of a command (`--exact --format json`), row by row.
fn exact_named(args: &[&str], name: &str) -> Vec<Vec<String>> {
    let mut a = args.to_vec();
    a.extend(["--exact", "--format", "json"]);
    let (out, _) = run_ok(&a);
    let v: J = serde_json::from_str(&out).unwrap();
    assert!(!v[name].is_null(), "{args:?}: no {name} in {v}");
    rows(&v[name])
}

fn rows(v: &J) -> Vec<Vec<String>> {
    let cell = |x: &J| x.as_str().map_or_else(|| x.to_string(), str::to_string);
    match v {
        J::Array(r) if r.iter().all(J::is_array) => r
            .iter()
            .map(|row| row.as_array().unwrap().iter().map(cell).collect())
            .collect(),
        J::Array(r) => vec![r.iter().map(cell).collect()],
        x => vec![vec![cell(x)]],
    }
}

fn col(values: &[&str]) -> Vec<Vec<String>> {
    values.iter().map(|v| vec![v.to_string()]).collect()
}

const NOTE_3X3: &str =
    "CONTROL: read as 3 points in 3-D, one per column; --rows if each row is a point";

// ---------------------------------------------------------------------------------------
// 1. Orientation never guessed in silence

#[test]
fn square_and_wide_point_matrices_get_the_orientation_note() {
    // The issue's 3×3: the rows mean b0 = (0,0,0), b1 = (1,2,0), b2 = (2,0,1); by hand
    // b(1/2) = (b0 + 2 b1 + b2)/4 = (1, 1, 1/4). Read as columns: (0, 5/4, 3/4), with the note.
    let m = "[0 0 0; 1 2 0; 2 0 1]";
    let (_, warnings) = run_ok(&["decasteljau", m, "--t", "0.5"]);
    assert_eq!(warnings, vec![NOTE_3X3.to_string()]);
    assert_eq!(
        exact_result(&["decasteljau", m, "--t", "0.5", "--columns"]),
        col(&["0", "5/4", "3/4"])
    );
    assert_eq!(
        exact_result(&["decasteljau", m, "--t", "0.5", "--rows"]),
        col(&["1", "1", "1/4"])
    );
    // "[0 0; 4 2]": rows (0,0), (4,2) at t = 1/4 → (1, 1/2); columns (0,4), (0,2) → (0, 7/2).
    let (_, warnings) = run_ok(&["decasteljau", "[0 0; 4 2]", "--t", "1/4"]);
    assert_eq!(
        warnings,
        vec!["CONTROL: read as 2 points in 2-D, one per column; --rows if each row is a point"]
    );
    assert_eq!(
        exact_result(&["decasteljau", "[0 0; 4 2]", "--t", "1/4", "--rows"]),
        col(&["1", "1/2"])
    );
    // Every command that reads points: elevate, subdivide, spline, bspline, nurbs, convert,
    // integrate, lagrange --points, continuity.
    for args in [
        vec!["elevate", m, "--by", "1"],
        vec!["subdivide", m],
        vec!["integrate", m],
        vec!["convert", m, "--from", "bezier", "--to", "monomial"],
        vec!["bspline", m, "--degree", "2"],
        vec!["nurbs", m, "--degree", "2", "--weights", "[1 1 1]"],
    ] {
        let (_, warnings) = run_ok(&args);
        assert!(
            warnings.iter().any(|w| w.ends_with(
                "read as 3 points in 3-D, one per column; --rows if each row is a point"
            )),
            "{args:?}: {warnings:?}"
        );
        for stated in ["--rows", "--columns"] {
            let mut a = args.clone();
            a.push(stated);
            silent(&a);
        }
    }
}

#[test]
fn shapes_only_one_reading_makes_valid_stay_silent() {
    // 2×4: four points in the plane (as rows they would be 2 points in 4-D).
    silent(&["decasteljau", "[0 1 3 4; 0 2 2 0]", "--t", "0.5"]);
    // 4×2 with --rows: four points in the plane.
    silent(&[
        "decasteljau",
        "[0 0; 1 2; 3 2; 4 0]",
        "--rows",
        "--t",
        "0.5",
    ]);
    // A row of numbers: points in 1-D (a function's Bézier ordinates).
    silent(&["decasteljau", "[1 2 3]", "--t", "0.5"]);
    silent(&[
        "lagrange",
        "--nodes",
        "1:5",
        "--points",
        "[1 2 3 2 1]",
        "--t",
        "2.5",
    ]);
    // 4×2 as columns gives points in 4-D: a warning naming --rows, not a note.
    let (_, warnings) = run_ok(&["decasteljau", "[0 0; 1 2; 3 2; 4 0]", "--t", "0.5"]);
    assert_eq!(
        warnings,
        vec!["CONTROL: read as 2 points in 4-D, one per column; --rows if each row is a point"]
    );
}

#[test]
fn every_error_about_points_names_the_orientation_and_the_flip() {
    // lagrange --points as rows: 3 points in the plane read as 2 points in 3-D.
    let e = error(&["lagrange", "--nodes", "1:3", "--points", "[0 0; 1 1; 2 0]"]);
    assert!(
        e.contains("read as 2 points in 3-D, one per column; --rows if each row is a point"),
        "{e}"
    );
    // With --rows stated the error still says how the points were read.
    let e = error(&[
        "lagrange",
        "--nodes",
        "1:2",
        "--points",
        "[0 0; 1 1; 2 0]",
        "--rows",
    ]);
    assert!(
        e.contains("read as 3 points in 2-D, one per row (--rows); leave out --rows if each column is a point"),
        "{e}"
    );
    // convert: the B-spline form is cubic, 4 points typed as rows read as 2 in 4-D.
    let e = error(&[
        "convert",
        "[0 0; 1 1; 2 0; 3 1]",
        "--from",
        "bezier",
        "--to",
        "bspline",
    ]);
    assert!(
        e.contains("(read as 2 points in 4-D, one per column; --rows if each row is a point)"),
        "{e}"
    );
    // continuity --free-point with the points as rows but read as columns.
    let e = error(&[
        "continuity",
        "[2 3 4; 3 1 5]",
        "[3 4 3; 2 6 0; 5 7 5; 5 2 3]",
        "--free-point",
    ]);
    assert!(e.contains("--rows"), "{e}");
    // The help of each names --rows and --columns.
    for command in ["convert", "continuity", "lagrange", "decasteljau"] {
        let help = silent(&[command, "--help"]);
        assert!(
            help.contains("--rows") && help.contains("--columns"),
            "{command}"
        );
    }
}

// ---------------------------------------------------------------------------------------
// 2. Decimal commas wherever numbers are read

const COMMA_05: &str = "`0,5` read as two numbers 0 and 5; a decimal point is `0.5`";

#[test]
fn decimal_commas_in_control_points_lists_and_files_warn() {
    // The issue's control points: meant (0.5, 1.5), (1, 2.5), (2, 0.5); at t = 1/2 by hand
    // (b0 + 2 b1 + b2)/4 = (1.125, 1.75).
    let (_, warnings) = run_ok(&["decasteljau", "[0,5 1,0 2,0; 1,5 2,5 0,5]", "--t", "0.5"]);
    assert_eq!(warnings, vec![format!("CONTROL: {COMMA_05}")]);
    assert_eq!(
        exact_result(&["decasteljau", "[0.5 1.0 2.0; 1.5 2.5 0.5]", "--t", "0.5"]),
        col(&["9/8", "7/4"])
    );
    // A list whose pieces fall inside the domain: p(5/2) = 87/32 is meant.
    let args = ["lagrange", "--nodes", "1:5", "--points", "[1 2 3 2 1]"];
    let mut a = args.to_vec();
    a.extend(["--t", "[2,5]"]);
    let (_, warnings) = run_ok(&a);
    assert_eq!(
        warnings,
        vec!["--t: `2,5` read as two numbers 2 and 5; a decimal point is `2.5`"]
    );
    let mut a = args.to_vec();
    a.extend(["--t", "2.5"]);
    assert_eq!(exact_result(&a), vec![vec!["87/32".to_string()]]);
    // A numeric file with decimal commas.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("points.txt");
    std::fs::write(&file, "0,5 1,5\n1,0 2,5\n2,0 0,5\n").unwrap();
    let (_, warnings) = run_ok(&[
        "decasteljau",
        file.to_str().unwrap(),
        "--rows",
        "--t",
        "0.5",
    ]);
    assert_eq!(warnings[0], format!("CONTROL: {COMMA_05}"));
    // Rows that are each one pair d,d, typed without a space or as the lines of a file: a
    // column of decimals (0.5, 1.5) read as the 2×2 matrix [0 5; 1 5]. Both readings are
    // plausible, so the warning also names the other.
    let pairs =
        format!("CONTROL: {COMMA_05}; `0, 5` (a space after the comma) if two numbers are meant");
    let (_, warnings) = run_ok(&["decasteljau", "[0,5;1,5]", "--t", "0.5"]);
    assert!(warnings.contains(&pairs), "{warnings:?}");
    std::fs::write(&file, "0,5\n1,5\n2,5\n").unwrap();
    for rows in [true, false] {
        let mut a = vec!["decasteljau", file.to_str().unwrap(), "--t", "0.5"];
        if rows {
            a.push("--rows");
        }
        let (_, warnings) = run_ok(&a);
        assert!(warnings.contains(&pairs), "{a:?}: {warnings:?}");
    }
    // A CSV file of x,y rows of whole numbers is such a file too: read as written (by hand,
    // b(1/2) of (0,1), (1,2), (2,0) is (1, 5/4)), with the warning naming the space.
    std::fs::write(&file, "0,1\n1,2\n2,0\n").unwrap();
    let csv = [
        "decasteljau",
        file.to_str().unwrap(),
        "--rows",
        "--t",
        "0.5",
    ];
    let (_, warnings) = run_ok(&csv);
    assert_eq!(
        warnings,
        vec![
            "CONTROL: `0,1` read as two numbers 0 and 1; a decimal point is `0.1`; `0, 1` (a \
              space after the comma) if two numbers are meant"
        ]
    );
    assert_eq!(exact_result(&csv), col(&["1", "5/4"]));
    // A CSV file with a space after each comma, three numbers a line or a decimal point reads
    // as written, silently.
    for text in [
        "0, 1\n1, 2\n2, 0\n",
        "0,1,0\n1,2,0\n2,0,0\n",
        "0,1\n1,2.5\n2,0\n",
    ] {
        std::fs::write(&file, text).unwrap();
        silent(&csv);
    }
}

#[test]
fn errors_caused_by_decimal_commas_say_so() {
    let cases: [(&[&str], &str); 4] = [
        (&["decasteljau", "[0 1 2; 0 1 0]", "--t", "0,5"], "--t: "),
        (
            &[
                "bspline",
                "[0 1 2 3; 0 1 0 1]",
                "--degree",
                "3",
                "--knots",
                "[0 0 0 0 0,5 1 1 1 1]",
            ],
            "--knots: ",
        ),
        (
            &[
                "nurbs",
                "[0 1 2; 0 1 0]",
                "--columns",
                "--degree",
                "2",
                "--weights",
                "[1 0,5 1]",
            ],
            "--weights: ",
        ),
        (
            &["lagrange", "--nodes", "[0 0,5 1]", "--points", "[1 2 3]"],
            "--nodes: ",
        ),
    ];
    for (args, start) in cases {
        let e = error(args);
        assert!(
            e.starts_with(start) && e.contains(COMMA_05),
            "{args:?}: {e}"
        );
    }
}

#[test]
fn decimal_points_and_comma_separated_lists_stay_silent() {
    for t in [
        "[0.2 0.4]",
        "0:0.2:1",
        "[0, 0.5, 1]",
        "[0;0.5]",
        "[0,0.5,1]",
        "0.5",
    ] {
        silent(&["decasteljau", "[0 1 3 4; 0 2 2 0]", "--t", t]);
    }
    silent(&[
        "bspline",
        "[0 1 3 4; 0 2 2 0]",
        "--degree",
        "2",
        "--knots",
        "[0,0,0,0.5,1,1,1]",
    ]);
    silent(&["decasteljau", "[0,1,3,4;0,2,2,0]", "--t", "0.5"]);
    silent(&["decasteljau", "[0, 5; 1, 5]", "--columns", "--t", "0.5"]);
    // The issue's control points written with decimal points: (0.5, 1.5), (1, 2.5), (2, 0.5);
    // by hand b(1/2) = (b0 + 2 b1 + b2)/4 = (1.125, 1.75), silently.
    let out = silent(&[
        "decasteljau",
        "[0.5 1 2; 1.5 2.5 0.5]",
        "--columns",
        "--t",
        "0.5",
        "--format",
        "json",
    ]);
    let v: J = serde_json::from_str(&out).unwrap();
    assert_eq!(v["result"], serde_json::json!([[1.125], [1.75]]));
}

// ---------------------------------------------------------------------------------------
// 3. One convention per word

#[test]
fn convention_elevate_degree_is_the_degree_after_elevation() {
    // A quadratic raised to degree 4 = raised by 2: the same control points.
    let q = "[0 1 2; 0 1 0]";
    let elevate = |extra: &[&str]| {
        let mut a = vec!["elevate", q, "--columns"];
        a.extend(extra);
        exact_named(&a, "control")
    };
    let by = elevate(&["--by", "2"]);
    assert_eq!(elevate(&["--degree", "4"]), by);
    assert_eq!(elevate(&["--order", "5"]), by);
    assert_eq!(elevate(&["--degree", "4", "--by", "2"]), by);
    // By hand (degree 2 → 4): b'_i = Σ C(2,j) C(2,i−j)/C(4,i) b_j: x = 0, 1/2, 1, 3/2, 2;
    // y = 0, 1/2, 2/3, 1/2, 0.
    assert_eq!(
        by,
        vec![
            vec!["0", "1/2", "1", "3/2", "2"],
            vec!["0", "1/2", "2/3", "1/2", "0"]
        ]
        .into_iter()
        .map(|r| r.into_iter().map(String::from).collect::<Vec<_>>())
        .collect::<Vec<_>>()
    );
    let e = error(&["elevate", q, "--columns", "--degree", "4", "--by", "1"]);
    assert!(
        e.starts_with("--degree: the degree after elevation 4 contradicts --by 1"),
        "{e}"
    );
    let e = error(&["elevate", q, "--columns", "--degree", "1"]);
    assert!(
        e.starts_with("--degree: the degree after elevation 1 is below"),
        "{e}"
    );
    // A B-spline: its degree comes from its knots (7 knots, 4 points: degree 2).
    let b = [
        "elevate",
        "[0 1 3 4; 0 2 2 0]",
        "--knots",
        "[0 0 0 0.5 1 1 1]",
    ];
    let mut by1 = b.to_vec();
    by1.extend(["--by", "1"]);
    let mut to3 = b.to_vec();
    to3.extend(["--degree", "3"]);
    assert_eq!(exact_named(&by1, "control"), exact_named(&to3, "control"));
    assert_eq!(exact_named(&by1, "knots"), exact_named(&to3, "knots"));
}

#[test]
fn elevate_to_the_curves_own_degree_warns_and_names_by() {
    // `--degree 2` on a quadratic (meant: by 2) raises nothing: the same points, a warning
    // naming the reading and --by.
    let q = "[0 1 2; 0 1 0]";
    let same = vec![
        vec!["0".to_string(), "1".into(), "2".into()],
        vec!["0".to_string(), "1".into(), "0".into()],
    ];
    for (option, value, word) in [("--degree", "2", "degree"), ("--order", "3", "order")] {
        let args = ["elevate", q, "--columns", option, value];
        let (_, warnings) = run_ok(&args);
        assert_eq!(
            warnings,
            vec![format!(
                "{option}: the {word} after elevation {value} is the curve's {word}: nothing is \
                 raised (R = 0); --by {value} raises the degree by {value}"
            )]
        );
        assert_eq!(exact_named(&args, "control"), same);
    }
    // The fix it names: by hand (degree 2 → 4), x = 0, 1/2, 1, 3/2, 2; y = 0, 1/2, 2/3, 1/2, 0.
    let by = silent(&["elevate", q, "--columns", "--by", "2", "--exact"]);
    assert!(by.contains("1/2  2/3  1/2"), "{by}");
    // A B-spline of degree 2 (7 knots, 4 points) asked for degree 2: the same warning.
    let (_, warnings) = run_ok(&[
        "elevate",
        "[0 1 3 4; 0 2 2 0]",
        "--knots",
        "[0 0 0 0.5 1 1 1]",
        "--degree",
        "2",
    ]);
    assert!(
        warnings.len() == 1 && warnings[0].contains("--by 2 raises the degree by 2"),
        "{warnings:?}"
    );
    // Stated: R = 0 typed as such is silent; a target below the degree is an error.
    silent(&["elevate", q, "--columns", "--by", "0"]);
    silent(&["elevate", q, "--columns", "--by", "0", "--degree", "2"]);
    let e = error(&["elevate", q, "--columns", "--degree", "1"]);
    assert!(
        e.starts_with("--degree: the degree after elevation 1 is below"),
        "{e}"
    );
}

#[test]
fn convention_order_is_a_bsplines_order_in_every_command() {
    let p = "[0 1 3 4; 0 2 2 0]";
    let u = "[0 0 0 0.5 1 1 1]";
    for (command, extra) in [
        ("bspline", vec!["--t", "0.25"]),
        ("integrate", vec![]),
        ("insert-knot", vec!["--insert", "0.25"]),
        ("nurbs", vec!["--weights", "[1 2 1 1]", "--t", "0.25"]),
    ] {
        let mut by_degree = vec![command, p, "--knots", u, "--degree", "2"];
        by_degree.extend(&extra);
        let mut by_order = vec![command, p, "--knots", u, "--order", "3"];
        by_order.extend(&extra);
        let name = match command {
            "integrate" => "integral",
            "insert-knot" => "control",
            _ => "result",
        };
        assert_eq!(
            exact_named(&by_degree, name),
            exact_named(&by_order, name),
            "{command}"
        );
    }
    let basis =
        |w: &str, v: &str| exact_result(&["bspline-basis", "--knots", u, w, v, "--t", "0.25"]);
    assert_eq!(basis("--degree", "2"), basis("--order", "3"));
    // The derivative's order is -r; --order there is refused, naming -r.
    let e = error(&["derivative", "[0 1 2; 0 1 0]", "--order", "1"]);
    assert!(e.starts_with("--order: ") && e.contains("-r"), "{e}");
    let d = exact_named(
        &["derivative", "[0 1 2; 0 1 0]", "--columns", "-r", "1"],
        "control",
    );
    assert_eq!(
        d,
        vec![vec!["2", "2"], vec!["2", "-2"]]
            .into_iter()
            .map(|r| r.into_iter().map(String::from).collect::<Vec<_>>())
            .collect::<Vec<_>>()
    );
}

/// A 4×4 control net packed as `bezier-patch` reads it (one bump at P_22).
const NET_4X4: &str = "[0 0 0 1 0 0 2 0 0 3 0 0; 0 1 0 1 1 0 2 1 0 3 1 0; \
    0 2 0 1 2 0 2 2 1 3 2 0; 0 3 0 1 3 0 2 3 0 3 3 0]";

#[test]
fn convention_default_degree_is_cubic_in_every_command_with_one() {
    let p = "[0 1 2 3 4; 0 2 0 2 0]";
    // (command and arguments, the output compared): without --degree, as with --degree 3,
    // and not as with --degree 2 (so that the default is seen to matter).
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["bspline", p, "--t", "0.3"], "result"),
        (
            vec!["nurbs", p, "--weights", "[1 2 1 2 1]", "--t", "0.3"],
            "result",
        ),
        (vec!["insert-knot", p, "--insert", "0.3"], "control"),
        (
            vec![
                "bspline-basis",
                "--knots",
                "[0 0 0 0 1 2 2 2 2]",
                "--t",
                "0.3",
            ],
            "result",
        ),
        (
            vec!["bspline-surface", NET_4X4, "--u", "0.3", "--v", "0.6"],
            "result",
        ),
        (
            vec![
                "nurbs-surface",
                NET_4X4,
                "--weights",
                "[1 1 1 1; 1 2 2 1; 1 2 2 1; 1 1 1 1]",
                "--u",
                "0.3",
                "--v",
                "0.6",
            ],
            "result",
        ),
        (vec!["integrate", p, "--knots", "0:8"], "integral"),
    ];
    for (args, name) in cases {
        let with = |degree: &'static str| {
            let mut a = args.clone();
            a.extend(["--degree", degree]);
            a
        };
        let default = exact_named(&args, name);
        assert_eq!(default, exact_named(&with("3"), name), "{args:?}");
        if args[0] == "integrate" {
            // 9 knots for 5 points fit the cubic only.
            let e = error(&with("2"));
            assert!(e.contains("expected 8 knots"), "{e}");
        } else {
            assert_ne!(default, exact_named(&with("2"), name), "{args:?}");
        }
    }
    // Without --knots, --degree or --order, integrate's CONTROL is a Bézier curve (degree 4
    // for 5 points): ∫₀¹ = mean of the points = (2, 4/5).
    assert_eq!(
        exact_named(&["integrate", p], "integral"),
        vec![vec!["2".to_string()], vec!["4/5".to_string()]]
    );
}

/// The knot rule's form, the same for every command with control points and knots.
const KNOTS_FORM: &str = "expected n + p + 1 non-decreasing knots for n control points of \
    degree p (n ≥ p + 1), with u_(p+1) < u_(n+1)";

#[test]
fn convention_one_knot_count_rule_and_wording() {
    let p = "[0 1 3 4; 0 2 2 0]";
    // The count: 6 knots where the quadratic on 4 points has 7.
    let wrong = "[0 0 0 1 1 1]";
    let count = format!(
        "--knots: knot vector: expected 7 knots (control points + degree + 1), got 6; {KNOTS_FORM}"
    );
    for command in ["bspline", "nurbs", "insert-knot", "integrate"] {
        let mut a = vec![command, p, "--degree", "2", "--knots", wrong, "--columns"];
        match command {
            "insert-knot" => a.extend(["--insert", "0.5"]),
            "nurbs" => a.extend(["--weights", "[1 1 1 1]"]),
            _ => {}
        }
        assert_eq!(error(&a), count, "{command}");
    }
    // Decreasing knots: knot 5 (counted from 1) falls below knot 4, in every command that
    // takes knots, the call forms of the curve arguments among them.
    let decreasing = "[0 0 0 0.5 0.25 1 1]";
    let problem = "knot 5 (0.25) is below the knot before it (0.5); knots must be non-decreasing";
    let curve = format!("bspline({p}, {decreasing})");
    let rational = format!("nurbs({p}, [1 1 1 1], {decreasing})");
    let commands: Vec<(Vec<&str>, &str)> = vec![
        (vec!["bspline", p], "--knots"),
        (vec!["nurbs", p, "--weights", "[1 1 1 1]"], "--knots"),
        (vec!["insert-knot", p, "--insert", "0.5"], "--knots"),
        (vec!["integrate", p], "--knots"),
        (vec!["elevate", p], "--knots"),
        (vec!["curvature", &curve, "--t", "0.5"], "CURVE"),
        (
            vec!["ruled", "--first", &rational, "--second", "[0 4; 1 1]"],
            "--first",
        ),
    ];
    for (args, argument) in commands {
        let mut a = args.clone();
        if argument == "--knots" {
            a.extend(["--knots", decreasing]);
        }
        a.push("--columns");
        let e = error(&a);
        let start = format!("{argument}: knot vector: {problem}");
        assert!(e.starts_with(&start), "{args:?}: {e}");
        assert!(e.ends_with(KNOTS_FORM), "{args:?}: {e}");
    }
    // The basis (no control points) and the surfaces: the same problem in the same words.
    let e = error(&["bspline-basis", "--knots", decreasing, "--degree", "2"]);
    assert!(
        e.starts_with(&format!("--knots: knot vector: {problem}")),
        "{e}"
    );
    for surface in ["bspline-surface", "nurbs-surface"] {
        let mut a = vec![surface, NET_4X4, "--degree", "2", "--uknots", decreasing];
        if surface == "nurbs-surface" {
            a.extend(["--weights", "ones(4, 4)"]);
        }
        let e = error(&a);
        let start = format!("--uknots: knot vector along u: {problem}");
        assert!(e.starts_with(&start) && e.ends_with(KNOTS_FORM), "{e}");
    }
}

#[test]
fn convention_default_samples_cover_the_data() {
    // Lagrange samples its nodes' range: no value extrapolated, no warning.
    let out = silent(&[
        "lagrange",
        "--nodes",
        "1:5",
        "--points",
        "[1 2 3 2 1]",
        "--format",
        "json",
    ]);
    let v: J = serde_json::from_str(&out).unwrap();
    let t: Vec<f64> = rows(&v["t"])[0]
        .iter()
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!((t[0], *t.last().unwrap()), (1.0, 5.0));
}

#[test]
fn convention_parameter_vectors_are_rows() {
    for args in [
        vec!["decasteljau", "[0 1 3 4; 0 2 2 0]", "--t", "[0 0.5 1]"],
        vec!["bernstein", "--degree", "2", "--t", "[0 0.5 1]"],
        vec![
            "bspline-basis",
            "--knots",
            "[0 0 0 1 1 1]",
            "--degree",
            "2",
            "--t",
            "[0 0.5 1]",
        ],
        vec![
            "bspline",
            "[0 1 3 4; 0 2 2 0]",
            "--degree",
            "2",
            "--t",
            "[0 0.5 1]",
        ],
        vec!["lagrange", "--nodes", "[0 0.5 1]", "--t", "[0 0.5 1]"],
        vec!["integrate", "--bernstein", "2", "--t", "[0 0.5 1]"],
    ] {
        let mut a = args.clone();
        a.extend(["--format", "json"]);
        let (out, _) = run_ok(&a);
        let v: J = serde_json::from_str(&out).unwrap();
        let t: Vec<Vec<f64>> = rows(&v["t"])
            .iter()
            .map(|r| r.iter().map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(t, vec![vec![0.0, 0.5, 1.0]], "{args:?}: {}", v["t"]);
    }
}

#[test]
fn convention_de_boor_span_counts_knots_from_one() {
    // Knots u_1..u_7 = 0 0 0 ½ 1 1 1 (the notes count from 1): t = 1/4 lies in [u_3, u_4).
    let out = run_ok(&[
        "bspline",
        "[0 1 3 4; 0 2 2 0]",
        "--degree",
        "2",
        "--knots",
        "[0 0 0 0.5 1 1 1]",
        "--t",
        "0.25",
        "--steps",
        "--format",
        "json",
    ])
    .0;
    let v: J = serde_json::from_str(&out).unwrap();
    assert_eq!(
        rows(&v["de_boor"]["span"]),
        vec![vec!["3.0"]],
        "{}",
        v["de_boor"]
    );
    let out = run_ok(&[
        "insert-knot",
        "[0 1 3 4; 0 2 2 0]",
        "--degree",
        "2",
        "--knots",
        "[0 0 0 0.5 1 1 1]",
        "--insert",
        "0.25",
        "--steps",
        "--format",
        "json",
    ])
    .0;
    let v: J = serde_json::from_str(&out).unwrap();
    let span = &v["insert_1"]["span"];
    assert_eq!(rows(span), vec![vec!["3.0"]], "{v}");
}

/// The conventions of docs/COURSE.md ("Conventions: one word, one meaning") that a text shown
/// to a user breaks, one line each (empty when it keeps them all): parameter vectors are rows
/// (`t is 1×k`); one knot-count rule (`n + p + 1`, for `n` control points of degree `p`);
/// `--order` is a B-spline's order `k = p + 1`; knots are numbered from 1 (`u_1`, the domain
/// `[u_(p+1), u_(n+1)]`, the functions `N_1,p … N_n,p`).
fn conventions_broken(text: &str) -> Vec<String> {
    let text = &text.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut broken = Vec::new();
    for name in ["t", "u", "v"] {
        let says = format!(" {name} is ");
        for (at, _) in text.match_indices(&says) {
            let shape = text[at + says.len()..]
                .split_whitespace()
                .next()
                .unwrap_or("");
            let is_shape = shape.contains('×') || shape.contains("x1");
            if is_shape && !shape.starts_with("1×") {
                broken.push(format!(
                    "`{name} is {shape}`: parameter vectors are rows, 1×k"
                ));
            }
        }
    }
    for plus in ["+ p + ", "+ q + "] {
        for (at, _) in text.match_indices(plus) {
            if !text[at + plus.len()..].starts_with('1') {
                broken.push(format!(
                    "`{}`: knots are n + p + 1",
                    &text[at..at + plus.len() + 1]
                ));
            }
        }
    }
    // The last knot's subscript u_(n+p+1) is the one place the rule is written tight.
    let plain = text.replace("u_(n+p+1)", "u_last");
    for other in [
        "n+p+",
        "n+q+",
        "nu + p",
        "nv + q",
        "m − p",
        "m - p",
        "m + 1 knots",
    ] {
        if plain.contains(other) {
            broken.push(format!("`{other}`: one knot-count rule, written n + p + 1"));
        }
    }
    let order_defined = ["k = p + 1", "K = P + 1", "(degree + 1)"];
    if text.contains("--order") && !order_defined.iter().any(|d| text.contains(d)) {
        broken.push("--order without `k = p + 1`: the order is a B-spline's".into());
    }
    for zero in [
        "u_0",
        "u_p",
        "u_n",
        "u_m",
        "v_q",
        "v_n",
        "N_0,",
        "N_(n-1)",
        "N_(n−1)",
        "u_{",
    ] {
        if text.contains(zero) {
            broken.push(format!(
                "`{zero}`: knots and basis functions are numbered from 1"
            ));
        }
    }
    let subscript = ["u_1", "u_(", "u_s", "u_k"]
        .iter()
        .any(|k| text.contains(k));
    if subscript && !text.contains("numbered from 1") {
        broken.push("knot subscripts without `numbered from 1`".into());
    }
    if text.contains("domain [u_") && !text.contains("domain [u_(p+1), u_(n+1)]") {
        broken.push("a B-spline domain other than [u_(p+1), u_(n+1)]".into());
    }
    broken
}

#[test]
fn convention_checks_catch_each_broken_convention() {
    let kept = "Input: --knots: n + p + 1 non-decreasing values u_1..u_(n+p+1), numbered from 1, \
        --order k = p + 1; the domain [u_(p+1), u_(n+1)].\nLayout: t is 1×k, result k×n.";
    assert_eq!(conventions_broken(kept), Vec::<String>::new());
    // The texts the help had before, each caught.
    for (planted, rule) in [
        ("Layout: t is k×1, result k×(n+1)", "rows"),
        (
            "The knot vector: n + p + 2 non-decreasing values",
            "n + p + 1",
        ),
        ("Layout: knots 1×(n+p+1+r)", "n + p + 1"),
        ("--uknots and --vknots (nu + p + 1", "n + p + 1"),
        ("--order K: the order of the derivative", "order"),
        ("Sample the knot domain [u_p, u_n]", "numbered from 1"),
        ("column = N_0,p..N_(n-1),p", "numbered from 1"),
        ("The span is k with u_k ≤ t < u_(k+1).", "numbered from 1"),
        ("--knots u_0..u_m, numbered from 1", "numbered from 1"),
    ] {
        let found = conventions_broken(planted);
        assert!(
            found.iter().any(|b| b.contains(rule)),
            "{planted}: {found:?}"
        );
    }
}

#[test]
fn convention_help_texts_agree_with_the_conventions() {
    let all = cagd_cli::subcommands();
    let mut takes_knots = 0;
    for sub in all.iter().map(String::as_str) {
        let help = silent(&[sub, "--help"]);
        let broken = conventions_broken(&help);
        assert!(broken.is_empty(), "cagd {sub} --help: {broken:?}");
        // Every command that takes knots states the one rule in the same words.
        if help.contains("--knots <") || help.contains("--uknots <") {
            takes_knots += 1;
            assert!(
                help.contains("n + p + 1 non-decreasing"),
                "cagd {sub} --help states no knot count"
            );
        }
    }
    assert!(takes_knots >= 8, "{takes_knots} commands take knots");
    // The readable steps' labels, in every language (the words "numbered from 1" in English).
    for (name, words) in cagd_cli::lang::STEP_LABELS {
        for lang in cagd_cli::lang::Lang::ALL {
            let broken: Vec<_> = conventions_broken(words.get(lang))
                .into_iter()
                .filter(|b| lang == cagd_cli::lang::Lang::En || !b.starts_with("knot subscripts"))
                .collect();
            assert!(
                broken.is_empty(),
                "step label {name} ({lang:?}): {broken:?}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// 4. Messages that point to the fix

#[test]
fn messages_name_what_was_typed_and_what_was_meant() {
    let e = error(&["integrate", "--bernstien", "3"]);
    assert!(
        e.starts_with("--bernstien: unknown option; expected --bernstein perhaps"),
        "{e}"
    );
    let e = error(&[
        "bspline-surface",
        "[0 0 0 1 0 0; 0 1 0 1 1 0]",
        "--knots",
        "[0 0 1 1]",
    ]);
    assert!(
        e.starts_with("--knots: unknown option; expected --uknots and --vknots"),
        "{e}"
    );
    let e = error(&["decastljau", "[0 1]"]);
    assert!(
        e.starts_with("decastljau: unknown subcommand; expected decasteljau perhaps"),
        "{e}"
    );
    for surface in [
        vec![
            "coons", "--c1", "[u;0;0]", "--c2", "[u;1;0]", "--d1", "[0;v;0]", "--d2", "[1;v;0]",
        ],
        vec!["bezier-patch", "[0 0 0 1 0 0; 0 1 0 1 1 1]"],
    ] {
        let mut a = surface.clone();
        a.extend(["--t", "0.5"]);
        let e = error(&a);
        assert!(
            e.starts_with("--t: unknown option; expected --u and --v"),
            "{e}"
        );
    }
    let e = error(&[
        "decasteljau",
        "/nonexistent/dir/nonexist.txt:B",
        "--t",
        "0.5",
    ]);
    assert!(e.contains("no such file"), "{e}");
    let e = error(&["decasteljau", "nonexist.txt:B", "--t", "0.5"]);
    assert!(e.starts_with("CONTROL nonexist.txt: no such file"), "{e}");
}

// ---------------------------------------------------------------------------------------
// 5. Pictures that show the answer

/// The canvas units of an SVG to a pixel of its picture: its viewBox's width over its width
/// (the picture is drawn on a finer canvas than its pixels).
pub(super) fn canvas_per_pixel(svg: &str) -> f64 {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let root = doc.root_element();
    let width: f64 = root.attribute("width").unwrap().parse().unwrap();
    let view: Vec<f64> = root
        .attribute("viewBox")
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(view[0], 0.0, "the viewBox starts at the origin");
    view[2] / width
}

/// The circles of an SVG, in pixels of the picture: (cx, cy, r, the element's text).
pub(super) fn circles(svg: &str) -> Vec<(f64, f64, f64, String)> {
    let scale = canvas_per_pixel(svg);
    svg.split("<circle")
        .skip(1)
        .map(|c| {
            let end = c.find("/>").unwrap_or(c.len());
            let el = &c[..end];
            let attr = |name: &str| -> f64 {
                let at = el.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
                el[at..].split('"').next().unwrap().parse::<f64>().unwrap() / scale
            };
            (attr("cx"), attr("cy"), attr("r"), el.to_string())
        })
        .collect()
}

/// Checks that the SVG of `decasteljau P --t ts --plot` marks each point b(t) (`expected`,
/// worked out by hand) where the control points' own circles put it.
fn marker_at(dir: &Path, ts: &str, expected: &[(f64, f64)]) {
    let svg = dir.join(format!("m{}.svg", expected.len()));
    let svg = svg.to_str().unwrap();
    // b0 = (0,0), b1 = (1,2), b2 = (3,2), b3 = (4,0).
    binary(&[
        "decasteljau",
        "[0 1 3 4; 0 2 2 0]",
        "--t",
        ts,
        "--plot",
        svg,
    ]);
    let text = std::fs::read_to_string(svg).unwrap();
    let all = circles(&text);
    // The control points: red circles of radius 5 (not the legend's radius 4).
    let control: Vec<_> = all
        .iter()
        .filter(|c| c.2 == 5.0 && c.3.contains("fill=\"none\""))
        .collect();
    assert_eq!(control.len(), 4, "{all:?}");
    // Pixel = a + b·coordinate, from b0 and b3 (x) and b0 and b1 (y).
    let bx = (control[3].0 - control[0].0) / 4.0;
    let by = (control[1].1 - control[0].1) / 2.0;
    let pixel = |(x, y): (f64, f64)| (control[0].0 + bx * x, control[0].1 + by * y);
    let markers: Vec<_> = all.iter().filter(|c| c.2 == 6.0).collect();
    assert_eq!(markers.len(), expected.len(), "{all:?}");
    for (m, p) in markers.iter().zip(expected) {
        let (px, py) = pixel(*p);
        assert!(
            (m.0 - px).abs() <= 1.0 && (m.1 - py).abs() <= 1.0,
            "marker at ({}, {}), b = {p:?} at ({px}, {py})",
            m.0,
            m.1
        );
    }
    // Labelled with its parameter.
    assert!(
        text.contains("t = 0.5") || text.contains("t = 1/2"),
        "labels"
    );
}

#[test]
fn the_plot_marks_each_evaluated_point_where_it_is() {
    let dir = tempfile::tempdir().unwrap();
    // By hand: x(t) = 3t(1−t)² + 9t²(1−t) + 4t³, y(t) = 6t(1−t)² + 6t²(1−t) = 6t(1−t).
    let b = |t: f64| {
        let s = 1.0 - t;
        (
            3.0 * t * s * s + 9.0 * t * t * s + 4.0 * t * t * t,
            6.0 * t * s,
        )
    };
    marker_at(dir.path(), "0.5", &[(2.0, 1.5)]);
    marker_at(dir.path(), "[0.25 0.5 0.75]", &[b(0.25), b(0.5), b(0.75)]);
}

#[test]
fn every_plotting_command_marks_its_evaluated_points() {
    let dir = tempfile::tempdir().unwrap();
    let svg = |name: &str| {
        dir.path()
            .join(format!("{name}.svg"))
            .to_str()
            .unwrap()
            .to_string()
    };
    let p = "[0 1 3 4; 0 2 2 0]";
    let cases: Vec<(&str, Vec<&str>)> = vec![
        ("bezier", vec!["decasteljau", p, "--t", "0.5"]),
        ("bspline", vec!["bspline", p, "--degree", "2", "--t", "0.5"]),
        (
            "nurbs",
            vec![
                "nurbs",
                p,
                "--degree",
                "2",
                "--weights",
                "[1 2 2 1]",
                "--t",
                "0.5",
            ],
        ),
        ("spline", vec!["spline", p, "--t", "0.5"]),
        (
            "coons",
            [&["coons"][..], &PRIMER_4_3, &["--u", "0.2", "--v", "0.5"]].concat(),
        ),
        (
            "gordon",
            vec![
                "gordon",
                "--u-curve",
                "[u;0;0]",
                "--u-curve",
                "[u;1;u]",
                "--v-curve",
                "[0;v;0]",
                "--v-curve",
                "[1;v;v]",
                "--u",
                "0.2",
                "--v",
                "0.5",
            ],
        ),
    ];
    for (name, args) in cases {
        let path = svg(name);
        let mut a = args.clone();
        a.extend(["--plot", &path]);
        binary(&a);
        let text = std::fs::read_to_string(&path).unwrap();
        let markers = circles(&text).into_iter().filter(|c| c.2 == 6.0).count();
        assert_eq!(markers, 1, "{name}: the evaluated point is marked once");
    }
}

#[test]
fn the_thesis_picture_of_primer_2_4_marks_b_one_half_where_it_is() {
    // Primer 2.4: b0 = (0,0,0), b1 = (0,2,2), b2 = (8,2,0), b3 = (4,0,0); at t = 1/2 the
    // Bernstein weights are (1, 3, 3, 1)/8. The picture is a 3-D view, an affine map of the
    // points to pixels, which keeps affine combinations: the mark of b(1/2) lies at
    // (p0 + 3 p1 + 3 p2 + p3)/8 of the control points' pixels p0..p3.
    // The picture that `cagd thesis --out` writes (run once for this test and the command
    // line's test of every thesis file).
    let (_, out) = super::cli::thesis_out();
    let text = std::fs::read_to_string(out.join("primer_2_4.svg")).unwrap();
    let all = circles(&text);
    let control: Vec<_> = all
        .iter()
        .filter(|c| c.2 == 5.0 && c.3.contains("fill=\"none\""))
        .collect();
    assert_eq!(control.len(), 4, "{all:?}");
    let weights = [1.0, 3.0, 3.0, 1.0];
    let at = |k: usize| -> f64 {
        control
            .iter()
            .zip(weights)
            .map(|(c, w)| w * if k == 0 { c.0 } else { c.1 })
            .sum::<f64>()
            / 8.0
    };
    let markers: Vec<_> = all.iter().filter(|c| c.2 == 6.0).collect();
    assert_eq!(markers.len(), 1, "one mark for the one point: {all:?}");
    let (x, y) = (at(0), at(1));
    // Each pixel is rounded to a whole pixel: half a pixel for the mark, at most half a pixel
    // for the weighted mean of the control points.
    assert!(
        (markers[0].0 - x).abs() <= 1.0 && (markers[0].1 - y).abs() <= 1.0,
        "mark at ({}, {}), b(1/2) at ({x}, {y})",
        markers[0].0,
        markers[0].1
    );
}

/// The pixels of a PNG file (RGB, 8 bits), with its width.
fn png_pixels(path: &Path) -> (Vec<[u8; 3]>, usize) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut buf).unwrap();
    assert_eq!(frame.color_type, png::ColorType::Rgb);
    let pixels = buf[..frame.buffer_size()]
        .chunks_exact(3)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    (pixels, frame.width as usize)
}

/// The share `a` of `colour` in `pixel` if the pixel is `colour` laid over white with
/// coverage `a` (`pixel = white + a (colour − white)` in each channel, within 4 levels).
fn coverage(pixel: [u8; 3], colour: [u8; 3]) -> Option<f64> {
    let shares: Vec<f64> = (0..3)
        .filter(|&k| colour[k] < 200)
        .map(|k| (255.0 - pixel[k] as f64) / (255.0 - colour[k] as f64))
        .collect();
    let a = shares.iter().sum::<f64>() / shares.len() as f64;
    (0..3)
        .all(|k| {
            let expected = 255.0 - a * (255.0 - colour[k] as f64);
            (pixel[k] as f64 - expected).abs() <= 4.0
        })
        .then_some(a)
}

#[test]
fn png_pictures_are_anti_aliased() {
    // The curve is drawn in the blue (0, 114, 189) on white. A rasterizer without
    // anti-aliasing gives each pixel the line's colour or the background's; an anti-aliased
    // one gives the pixels a line partly covers the tones between, all along the curve.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("c.png");
    binary(&[
        "decasteljau",
        "[0 1 3 4; 0 2 2 0]",
        "--plot",
        path.to_str().unwrap(),
    ]);
    let (pixels, width) = png_pixels(&path);
    let blue = [0, 114, 189];
    let partly: Vec<usize> = (0..pixels.len())
        .filter(|&k| coverage(pixels[k], blue).is_some_and(|a| (0.15..=0.85).contains(&a)))
        .collect();
    let full = pixels
        .iter()
        .filter(|&&p| coverage(p, blue).is_some_and(|a| a > 0.95))
        .count();
    assert!(full > 100, "the curve is drawn in blue ({full} pixels)");
    assert!(
        partly.len() > 200,
        "{} pixels of intermediate blue tones: no anti-aliasing",
        partly.len()
    );
    // All along the curve, not in one spot: partly covered pixels in most of the columns
    // the curve crosses (where it runs level along a pixel row a stretch may be covered
    // whole).
    let columns = |ks: &[usize]| {
        let mut c: Vec<usize> = ks.iter().map(|k| k % width).collect();
        c.sort_unstable();
        c.dedup();
        c.len()
    };
    let crossed: Vec<usize> = (0..pixels.len())
        .filter(|&k| coverage(pixels[k], blue).is_some_and(|a| a > 0.15))
        .collect();
    assert!(
        columns(&partly) * 2 >= columns(&crossed),
        "intermediate tones in {} of the {} columns the curve crosses",
        columns(&partly),
        columns(&crossed)
    );
}

/// The text elements of an SVG, in pixels of the picture: (x, y, text).
pub(super) fn svg_texts(svg: &str) -> Vec<(f64, f64, String)> {
    let scale = canvas_per_pixel(svg);
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| {
            let at = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap() / scale;
            let text: String = n
                .descendants()
                .filter(|d| d.is_text())
                .filter_map(|d| d.text())
                .collect();
            (at("x"), at("y"), text.trim().to_string())
        })
        .collect()
}

/// The axis names and the tick values of a 2-D chart's SVG: (x name, y name, x ticks, y
/// ticks). Ticks are the numbers in a row under the chart (one y) and in a column left of it
/// (one x); the names are the texts beside them.
pub(super) fn axes(svg: &str) -> (String, String, Vec<f64>, Vec<f64>) {
    let texts = svg_texts(svg);
    let numbers: Vec<(f64, f64, f64)> = texts
        .iter()
        .filter_map(|(x, y, t)| t.parse::<f64>().ok().map(|v| (*x, *y, v)))
        .collect();
    let most = |key: &dyn Fn(&(f64, f64, f64)) -> f64| {
        let keys: Vec<f64> = numbers.iter().map(key).collect();
        *keys
            .iter()
            .max_by_key(|k| keys.iter().filter(|j| j == k).count())
            .unwrap()
    };
    let column = most(&|n| n.0);
    let row = most(&|n| n.1);
    let y_ticks: Vec<f64> = numbers
        .iter()
        .filter(|n| n.0 == column)
        .map(|n| n.2)
        .collect();
    let x_ticks: Vec<f64> = numbers.iter().filter(|n| n.1 == row).map(|n| n.2).collect();
    // The names: the text below the x ticks, and the text left of the y ticks.
    let x_name = texts
        .iter()
        .filter(|(_, y, _)| *y > row)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap()
        .2
        .clone();
    let y_name = texts
        .iter()
        .filter(|(x, _, _)| *x < column)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap()
        .2
        .clone();
    (x_name, y_name, x_ticks, y_ticks)
}

#[test]
fn basis_plots_name_their_axes_and_fit_their_data() {
    let dir = tempfile::tempdir().unwrap();
    let svg = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    // (command, its picture, the y axis's name, the knot range t covers)
    let basis = svg("basis.svg");
    let bernstein = svg("bernstein.svg");
    type Case<'a> = (Vec<&'a str>, &'a str, &'a str, (f64, f64));
    let cases: [Case; 2] = [
        (
            vec![
                "bspline-basis",
                "--knots",
                "[0 0 0 1 2 3 3 3]",
                "--degree",
                "2",
                "--t",
                "1.5",
                "--plot",
                &basis,
            ],
            &basis,
            "N_i,2(t)",
            (0.0, 3.0),
        ),
        (
            vec!["bernstein", "--degree", "3", "--plot", &bernstein],
            &bernstein,
            "B_i^3(t)",
            (0.0, 1.0),
        ),
    ];
    for (args, path, y_name, (a, b)) in cases {
        binary(&args);
        let (x_name, name, x_ticks, y_ticks) = axes(&std::fs::read_to_string(path).unwrap());
        assert_eq!((x_name.as_str(), name.as_str()), ("t", y_name), "{args:?}");
        let range = |v: &[f64]| {
            (
                v.iter().copied().fold(f64::INFINITY, f64::min),
                v.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            )
        };
        // t over the knot range (padded by 5 %, so no tick beyond its ends).
        assert_eq!(range(&x_ticks), (a, b), "{args:?}: t ticks {x_ticks:?}");
        // Basis values over [0, 1]: no tick beyond.
        assert_eq!(
            range(&y_ticks),
            (0.0, 1.0),
            "{args:?}: value ticks {y_ticks:?}"
        );
    }
}

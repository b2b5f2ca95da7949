//! The slips of a student typing into the page's command box, as the command line has them
//! (crates/cagd-cli/tests/it/slips.rs has the same cases through the program): each slip gives
//! its note, warning or error, worded as the program words it, and the correct, explicit
//! reading of the same data stays silent and gives the meant value. The values are worked out
//! by hand from the textbook formulas (de Casteljau, Lagrange, degree elevation), never taken
//! from the program's output.

use serde_json::Value;

use super::run;

/// The page's answer to `cagd ARGS` typed into the command box.
fn answer(args: &[&str]) -> Value {
    let argv = std::iter::once("cagd")
        .chain(args.iter().copied())
        .map(String::from)
        .collect();
    serde_json::from_str(&run(argv, vec![], vec![])).unwrap()
}

/// The warnings shown under the answer of a command that must succeed, without the page's
/// `cagd: warning: ` (so that they read as the program's test has them).
fn warnings(args: &[&str]) -> Vec<String> {
    let v = answer(args);
    assert_eq!(v["ok"], true, "{args:?}: {v}");
    v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| {
            let w = w.as_str().unwrap();
            w.strip_prefix("cagd: warning: ")
                .unwrap_or_else(|| panic!("{w}"))
                .to_string()
        })
        .collect()
}

/// A command that must succeed without a warning.
fn silent(args: &[&str]) {
    assert_eq!(warnings(args), Vec::<String>::new(), "{args:?}");
}

/// The error line of a command that must fail, without the page's `cagd: error: `.
fn error(args: &[&str]) -> String {
    let v = answer(args);
    assert_eq!(v["ok"], false, "{args:?} succeeded: {v}");
    assert_eq!(v["code"], 2, "{v}");
    let e = v["error"].as_str().unwrap();
    assert_eq!(e.lines().count(), 1, "{e}");
    e.strip_prefix("cagd: error: ").unwrap().to_string()
}

/// The exact item `name` of a command that must run silently (`--exact --format json`), row
/// by row, each number as printed.
fn exact(args: &[&str], name: &str) -> Vec<Vec<String>> {
    let mut a = args.to_vec();
    a.extend(["--exact", "--format", "json"]);
    silent(&a);
    let v = answer(&a);
    let data: Value = serde_json::from_str(v["stdout"].as_str().unwrap()).unwrap();
    let cell = |x: &Value| x.as_str().map_or_else(|| x.to_string(), str::to_string);
    match &data[name] {
        Value::Array(r) if r.iter().all(Value::is_array) => r
            .iter()
            .map(|row| row.as_array().unwrap().iter().map(cell).collect())
            .collect(),
        Value::Array(r) => vec![r.iter().map(cell).collect()],
        x => vec![vec![cell(x)]],
    }
}

/// A column of numbers as printed.
fn col(values: &[&str]) -> Vec<Vec<String>> {
    values.iter().map(|v| vec![(*v).to_string()]).collect()
}

/// Rows of numbers as printed.
fn rows(values: &[&[&str]]) -> Vec<Vec<String>> {
    values
        .iter()
        .map(|r| r.iter().map(|v| (*v).to_string()).collect())
        .collect()
}

const NOTE_3X3: &str =
    "CONTROL: read as 3 points in 3-D, one per column; --rows if each row is a point";
const NOTE_2X2: &str =
    "CONTROL: read as 2 points in 2-D, one per column; --rows if each row is a point";
const COMMA_05: &str = "`0,5` read as two numbers 0 and 5; a decimal point is `0.5`";

#[test]
fn square_point_matrices_get_the_orientation_note_and_stated_readings_are_silent() {
    // The rows mean b0 = (0,0,0), b1 = (1,2,0), b2 = (2,0,1): b(1/2) = (b0 + 2 b1 + b2)/4 =
    // (1, 1, 1/4); as columns (0,1,2), (0,2,0), (0,0,1): (0, 5/4, 3/4).
    let m = "[0 0 0; 1 2 0; 2 0 1]";
    assert_eq!(warnings(&["decasteljau", m, "--t", "0.5"]), [NOTE_3X3]);
    let at = |stated: &str| exact(&["decasteljau", m, "--t", "0.5", stated], "result");
    assert_eq!(at("--columns"), col(&["0", "5/4", "3/4"]));
    assert_eq!(at("--rows"), col(&["1", "1", "1/4"]));
    // "[0 0; 4 2]" at t = 1/4: the rows (0,0), (4,2) give 3/4 (0,0) + 1/4 (4,2) = (1, 1/2).
    assert_eq!(
        warnings(&["decasteljau", "[0 0; 4 2]", "--t", "1/4"]),
        [NOTE_2X2]
    );
    assert_eq!(
        exact(
            &["decasteljau", "[0 0; 4 2]", "--t", "1/4", "--rows"],
            "result"
        ),
        col(&["1", "1/2"])
    );
}

#[test]
fn every_command_reading_a_square_net_notes_it_elevate_too() {
    let m = "[0 0 0; 1 2 0; 2 0 1]";
    for args in [
        vec!["elevate", m, "--by", "1"],
        vec!["subdivide", m],
        vec!["integrate", m],
        vec!["convert", m, "--from", "bezier", "--to", "monomial"],
        vec!["bspline", m, "--degree", "2"],
        vec!["nurbs", m, "--degree", "2", "--weights", "[1 1 1]"],
    ] {
        // (convert calls its points GEOMETRY, the others CONTROL.)
        let w = warnings(&args);
        let reading = "read as 3 points in 3-D, one per column; --rows if each row is a point";
        assert!(w.len() == 1 && w[0].ends_with(reading), "{args:?}: {w:?}");
        for stated in ["--rows", "--columns"] {
            let mut a = args.clone();
            a.push(stated);
            silent(&a);
        }
    }
    // The elevated rows b0, b1, b2 (degree 2 → 3): b0, (b0 + 2 b1)/3, (2 b1 + b2)/3, b2.
    assert_eq!(
        exact(&["elevate", m, "--by", "1", "--rows"], "control"),
        rows(&[
            &["0", "2/3", "4/3", "2"],
            &["0", "4/3", "4/3", "0"],
            &["0", "0", "1/3", "1"]
        ])
    );
}

#[test]
fn shapes_only_one_reading_makes_valid_stay_silent() {
    silent(&["decasteljau", "[0 1 3 4; 0 2 2 0]", "--t", "0.5"]);
    silent(&[
        "decasteljau",
        "[0 0; 1 2; 3 2; 4 0]",
        "--rows",
        "--t",
        "0.5",
    ]);
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
    // 4×2 as columns: points in 4-D, a warning naming --rows.
    assert_eq!(
        warnings(&["decasteljau", "[0 0; 1 2; 3 2; 4 0]", "--t", "0.5"]),
        ["CONTROL: read as 2 points in 4-D, one per column; --rows if each row is a point"]
    );
}

#[test]
fn errors_about_points_name_the_reading_and_rows() {
    let e = error(&["lagrange", "--nodes", "1:3", "--points", "[0 0; 1 1; 2 0]"]);
    assert!(
        e.starts_with("--points: ")
            && e.contains("read as 2 points in 3-D, one per column; --rows if each row is a point"),
        "{e}"
    );
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
    let e = error(&[
        "continuity",
        "[2 3 4; 3 1 5]",
        "[3 4 3; 2 6 0; 5 7 5; 5 2 3]",
        "--free-point",
    ]);
    assert!(e.contains("--rows"), "{e}");
}

#[test]
fn decimal_commas_in_points_and_lists_warn_and_decimal_points_are_silent() {
    // Meant (0.5, 1.5), (1, 2.5), (2, 0.5): at t = 1/2, (b0 + 2 b1 + b2)/4 = (9/8, 7/4).
    assert_eq!(
        warnings(&["decasteljau", "[0,5 1,0 2,0; 1,5 2,5 0,5]", "--t", "0.5"]),
        [format!("CONTROL: {COMMA_05}")]
    );
    let meant = [
        "decasteljau",
        "[0.5 1 2; 1.5 2.5 0.5]",
        "--columns",
        "--t",
        "0.5",
    ];
    assert_eq!(exact(&meant, "result"), col(&["9/8", "7/4"]));
    // The list [2,5] lies inside the nodes' range, yet 2.5 is meant: by Lagrange's formula
    // through (1,1), (2,2), (3,3), (4,2), (5,1), p(5/2) = 87/32.
    let lagrange = [
        "lagrange",
        "--nodes",
        "1:5",
        "--points",
        "[1 2 3 2 1]",
        "--t",
    ];
    assert_eq!(
        warnings(&[&lagrange[..], &["[2,5]"]].concat()),
        ["--t: `2,5` read as two numbers 2 and 5; a decimal point is `2.5`"]
    );
    assert_eq!(
        exact(&[&lagrange[..], &["2.5"]].concat(), "result"),
        col(&["87/32"])
    );
    for t in ["[0.2 0.4]", "0:0.2:1", "[0, 0.5, 1]", "[0,0.5,1]", "0.5"] {
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
fn the_same_lists_with_decimal_points_are_silent() {
    // With decimal points: silent (five points for the nine knots of a cubic), and the NURBS
    // quadratic on [0 0 0 1 1 1] with weights 1, 1/2, 1 at t = 1/2: the weighted Bernstein
    // values 1/4·1, 1/2·1/2, 1/4·1 sum to 3/4, so x = (0 + 1/4 + 2/4)/(3/4) = 1 and
    // y = (1/4)/(3/4) = 1/3.
    silent(&[
        "bspline",
        "[0 1 2 3 4; 0 1 0 1 0]",
        "--degree",
        "3",
        "--knots",
        "[0 0 0 0 0.5 1 1 1 1]",
    ]);
    let nurbs = [
        "nurbs",
        "[0 1 2; 0 1 0]",
        "--columns",
        "--degree",
        "2",
        "--weights",
        "[1 0.5 1]",
        "--t",
        "0.5",
    ];
    assert_eq!(exact(&nurbs, "result"), col(&["1", "1/3"]));
    silent(&["lagrange", "--nodes", "[0 0.5 1]", "--points", "[1 2 3]"]);
}

#[test]
fn elevate_degree_is_the_degree_after_elevation() {
    // A quadratic raised to degree 4 (by 2), by hand: b'_i = Σ C(2,j) C(2,i−j)/C(4,i) b_j.
    let q = "[0 1 2; 0 1 0]";
    let elevated = |extra: &[&str]| {
        exact(
            &[&["elevate", q, "--columns"][..], extra].concat(),
            "control",
        )
    };
    let by = rows(&[
        &["0", "1/2", "1", "3/2", "2"],
        &["0", "1/2", "2/3", "1/2", "0"],
    ]);
    assert_eq!(elevated(&["--by", "2"]), by);
    assert_eq!(elevated(&["--degree", "4"]), by);
    assert_eq!(elevated(&["--order", "5"]), by);
    assert_eq!(elevated(&["--degree", "4", "--by", "2"]), by);
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
}

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
        let e = error(&[&surface[..], &["--t", "0.5"]].concat());
        assert!(
            e.starts_with("--t: unknown option; expected --u and --v"),
            "{e}"
        );
        // Where --u and --v are what was meant: silent.
        silent(&[&surface[..], &["--u", "0.5", "--v", "0.5"]].concat());
    }
    // A file the page was not given: named as missing, not as a matrix that does not parse.
    let e = error(&["decasteljau", "nonexist.txt:B", "--t", "0.5"]);
    assert!(e.starts_with("CONTROL nonexist.txt: no such file"), "{e}");
    // The intended spellings work and say nothing.
    silent(&["integrate", "--bernstein", "3"]);
    silent(&["decasteljau", "[0 1]", "--t", "0.5"]);
}

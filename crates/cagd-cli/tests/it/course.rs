//! The course from the command line: the subcommands of the course notes against their oracles
//! (the sources' worked examples, exact rational arithmetic, octave-nurbs and octave-splines
//! through `octave_ref/cases/{course_cli,nurbs,bspline_curves}.m`), the slips that must not
//! give a silent wrong answer (and the correct readings that must stay silent), readable
//! output, and `cagd course`.

use std::path::Path;

use assert_cmd::Command;
use cagd_cli::run;
use ndarray::{Array2, ArrayD, IxDyn};
use serde_json::Value as J;

use cagd_test_support as common;

// ---------------------------------------------------------------------------------------
// Helpers

/// Runs `cagd args…` in-process; the standard output and the warnings as
/// `ARGUMENT: MESSAGE` (file arguments must be absolute paths: tests run in parallel).
pub(super) fn run_ok(args: &[&str]) -> (String, Vec<String>) {
    let mut full = vec!["cagd".to_string()];
    full.extend(args.iter().map(|s| s.to_string()));
    let out = run(&full).unwrap_or_else(|e| panic!("cagd {args:?} failed: {e}"));
    let warnings = out
        .warnings
        .iter()
        .map(|(a, w)| format!("{a}: {w}"))
        .collect();
    (out.stdout, warnings)
}

/// The standard output of a command that must run without a warning.
pub(super) fn silent(args: &[&str]) -> String {
    let (out, warnings) = run_ok(args);
    assert!(warnings.is_empty(), "cagd {args:?} warned: {warnings:?}");
    out
}

/// The JSON result of a command that must run without a warning.
fn json(args: &[&str]) -> J {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    serde_json::from_str(&silent(&a)).unwrap()
}

/// The error line of a command that must fail (in-process): `ARGUMENT: PROBLEM; expected …`.
pub(super) fn error(args: &[&str]) -> String {
    let mut full = vec!["cagd".to_string()];
    full.extend(args.iter().map(|s| s.to_string()));
    match run(&full) {
        Ok(_) => panic!("cagd {args:?} succeeded"),
        Err(e) => {
            assert_eq!(e.exit_code(), 2, "{e}");
            e.to_string()
        }
    }
}

/// A JSON matrix (array of rows) as an ndarray.
fn mat(v: &J) -> Array2<f64> {
    let rows: Vec<Vec<f64>> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        })
        .collect();
    let (r, c) = (rows.len(), rows.first().map_or(0, Vec::len));
    Array2::from_shape_fn((r, c), |(i, j)| rows[i][j])
}

/// A JSON grid `[i][j][k]` as an `nu × nv × d` array.
fn grid(v: &J) -> ArrayD<f64> {
    let g = v.as_array().unwrap();
    let (nu, nv, d) = (
        g.len(),
        g[0].as_array().unwrap().len(),
        g[0][0].as_array().unwrap().len(),
    );
    ArrayD::from_shape_fn(IxDyn(&[nu, nv, d]), |i| {
        g[i[0]][i[1]][i[2]].as_f64().unwrap()
    })
}

/// Exact JSON values (`--exact`): the strings of a matrix.
fn exact(v: &J) -> Vec<Vec<String>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_str().unwrap().to_string())
                .collect()
        })
        .collect()
}

fn strs(rows: &[&[&str]]) -> Vec<Vec<String>> {
    rows.iter()
        .map(|r| r.iter().map(|s| s.to_string()).collect())
        .collect()
}

/// An Octave literal of a matrix with every bit (shortest round-trip decimals).
fn lit(m: &Array2<f64>) -> String {
    let rows: Vec<String> = m
        .rows()
        .into_iter()
        .map(|r| {
            r.iter()
                .map(|x| format!("{x:?}"))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    format!("[{}]", rows.join("; "))
}

fn row_lit(v: &[f64]) -> String {
    format!(
        "[{}]",
        v.iter()
            .map(|x| format!("{x:?}"))
            .collect::<Vec<_>>()
            .join(" ")
    )
}

/// Octave's `c × nu × nv` array as our `nu × nv × c` grid.
fn octave_grid(a: &ArrayD<f64>) -> ArrayD<f64> {
    let s = a.shape();
    ArrayD::from_shape_fn(IxDyn(&[s[1], s[2], s[0]]), |i| a[[i[2], i[0], i[1]]])
}

/// The packed `(m+1) × 3(n+1)` net of an Octave `3 × (m+1) × (n+1)` array.
fn packed(a: &ArrayD<f64>) -> Array2<f64> {
    let s = a.shape();
    Array2::from_shape_fn((s[1], 3 * s[2]), |(i, c)| a[[c % 3, i, c / 3]])
}

// ---------------------------------------------------------------------------------------
// The four slips of the issue, and the correct readings that stay silent

#[test]
fn slip_points_typed_as_rows_warn_and_both_right_readings_are_silent() {
    // The matrix-form and lecture notes write points as rows: 4 points in the plane read as
    // columns would be 2 points in R⁴.
    let (out, warnings) = run_ok(&["decasteljau", "[0 0; 1 2; 3 3; 4 0]", "--t", "1/3"]);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(
        warnings[0],
        "CONTROL: read as 2 points in 4-D, one per column; --rows if each row is a point"
    );
    assert!(out.contains("result ="), "{out}");
    // The right readings: --rows, or the transpose.
    let rows = silent(&[
        "decasteljau",
        "[0 0; 1 2; 3 3; 4 0]",
        "--rows",
        "--t",
        "1/3",
        "--exact",
    ]);
    let cols = silent(&[
        "decasteljau",
        "[0 0; 1 2; 3 3; 4 0]'",
        "--t",
        "1/3",
        "--exact",
    ]);
    assert_eq!(rows, cols);
    // b(1/3) = (8·0 + 12·1 + 6·3 + 4)/27, (12·2 + 6·3)/27 = (34/27, 14/9).
    assert!(
        rows.contains("34/27\n") && rows.contains("14/9\n"),
        "{rows}"
    );
    // Points of dimension 4 with --rows get the warning the other way round.
    let (_, warnings) = run_ok(&["decasteljau", "[0 0 0 0; 1 1 1 1]", "--rows", "--t", "0.5"]);
    assert!(
        warnings.len() == 1
            && warnings[0].ends_with(
                "read as 2 points in 4-D, one per row (--rows); leave out --rows if each column is a point"
            ),
        "{warnings:?}"
    );
    // The same check guards every command that takes points.
    let (_, warnings) = run_ok(&["spline", "[0 0; 2 1; 4 4; 6 0]", "--t", "0.5"]);
    assert!(
        warnings[0].starts_with("POINTS: read as 2 points in 4-D"),
        "{warnings:?}"
    );
    let (_, warnings) = run_ok(&["elevate", "[0 0; 1 2; 3 2]", "--by", "1"]);
    assert!(
        warnings[0]
            == "CONTROL: read as 2 points in 3-D, one per column; --rows if each row is a point",
        "{warnings:?}"
    );
}

#[test]
fn slip_decimal_commas_warn_and_decimal_points_run_silently() {
    let (out, warnings) = run_ok(&[
        "decasteljau",
        "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'",
        "--t",
        "[0,2 0,4]",
    ]);
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    assert_eq!(
        warnings[0],
        "--t: `0,2` read as two numbers 0 and 2; a decimal point is `0.2`"
    );
    assert_eq!(
        warnings[1],
        "--t: 2 values lie (the first t = 2) outside [0, 1]; the curve is extrapolated there"
    );
    assert!(out.contains("t =\n\n    0  2  0  4\n"), "{out}");
    // Without brackets a decimal comma is a syntax error, not a silent reading.
    let e = error(&["bernstein", "--degree", "2", "--t", "0,5"]);
    assert!(e.starts_with("--t: "), "{e}");
    for good in [
        "[0.2 0.4]",
        "0:0.2:1",
        "[0, 0.5, 1]",
        "[0;0.5]",
        "[0,0.5,1]",
    ] {
        silent(&["decasteljau", "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", "--t", good]);
    }
}

#[test]
fn slip_script_samples_read_as_control_points_warn_and_samples_reads_them_as_samples() {
    let script = common::data_file("appendix_c.m");
    let script = script.to_str().unwrap();
    let names = ["--c1", "c1", "--c2", "c2", "--d1", "d1", "--d2", "d2"];
    let at = ["--u", "0.5", "--v", "0.25"];
    let args = |extra: &[&'static str]| {
        let mut a = vec!["coons", "--script", script];
        a.extend(names);
        a.extend(extra);
        a.extend(at);
        a
    };
    let (out, warnings) = run_ok(&args(&["--format", "json"]));
    assert_eq!(warnings.len(), 4, "{warnings:?}");
    assert_eq!(
        warnings[0],
        "--c1: `c1` is a 3×10 matrix of the script, read as the control points of a Bézier curve of degree 9; if its columns are samples of the curve (as in the thesis's data scripts), add --samples"
    );
    let as_control = mat(&serde_json::from_str::<J>(&out).unwrap()["result"]);
    // With --samples: the columns are samples at the script's u and v, as appendix C means,
    // and the result is the script's own run (curves and corners from the script).
    let as_samples = mat(&json(&args(&["--samples"]))["result"]);
    let default = mat(&json(&["coons", "--script", script, "--u", "0.5", "--v", "0.25"])["result"]);
    assert_eq!(as_samples, default);
    // The boundary d1 = (0, v², v − v²) is different read as control points: at v = 1/4 the
    // Bézier curve of its 10 samples is not the polyline through them.
    let d1_samples = mat(&json(&[
        "coons",
        "--script",
        script,
        "--c1",
        "c1",
        "--c2",
        "c2",
        "--d1",
        "d1",
        "--d2",
        "d2",
        "--samples",
        "--u",
        "0",
        "--v",
        "0.25",
    ])["result"]);
    let (out, _) = run_ok(&[
        "coons", "--script", script, "--c1", "c1", "--c2", "c2", "--d1", "d1", "--d2", "d2", "--u",
        "0", "--v", "0.25", "--format", "json",
    ]);
    let d1_control = mat(&serde_json::from_str::<J>(&out).unwrap()["result"]);
    assert!((d1_samples[[1, 0]] - d1_control[[1, 0]]).abs() > 1e-3);
    assert_ne!(as_control, as_samples);
    // --samples without data to read is an option without effect.
    let e = error(&[
        "coons",
        "--c1",
        "[u;0;0]",
        "--c2",
        "[u;1;0]",
        "--d1",
        "[0;v;0]",
        "--d2",
        "[1;v;0]",
        "--samples",
    ]);
    assert!(e.starts_with("--samples: has no effect"), "{e}");
}

#[test]
fn slip_spline_tangents_need_clamped_ends_and_the_clamped_spline_runs_silently() {
    let pts = "[0 0; 2 1; 4 4; 6 0]'";
    for end in ["natural", "closed"] {
        let e = error(&["spline", pts, "--end", end, "--start-tangent", "[1;1]"]);
        assert!(
            e.starts_with(&format!("--start-tangent: has no effect with {end} ends")),
            "{e}"
        );
        let e = error(&["spline", pts, "--end", end, "--end-tangent", "[1;1]"]);
        assert!(e.starts_with("--end-tangent: has no effect"), "{e}");
    }
    // Both tangents without --end: the clamped spline of the lecture notes, silently.
    let out = json(&[
        "spline",
        pts,
        "--start-tangent",
        "[1;1]",
        "--end-tangent",
        "[-1;1]",
        "--exact",
        "--t",
        "1",
    ]);
    assert_eq!(
        exact(&out["tangents"]),
        strs(&[&["1", "31/15", "41/15", "-1"], &["1", "16/5", "-9/5", "1"]])
    );
    let with_end = json(&[
        "spline",
        pts,
        "--end",
        "clamped",
        "--start-tangent",
        "[1;1]",
        "--end-tangent",
        "[-1;1]",
        "--exact",
        "--t",
        "1",
    ]);
    assert_eq!(out, with_end);
    // One tangent alone cannot clamp.
    let e = error(&["spline", pts, "--start-tangent", "[1;1]"]);
    assert!(
        e.starts_with("--end-tangent: missing with clamped ends"),
        "{e}"
    );
}

#[test]
fn every_warning_is_printed_once() {
    // Appendix D's data script through gordon: the script's lenient evaluations were reported
    // by the script and again by the evaluation environment.
    let out = Command::cargo_bin("cagd")
        .unwrap()
        .current_dir(common::WORKSPACE)
        .args([
            "gordon",
            "--script",
            "tests/data/appendix_d_odd.m",
            "--u",
            "0.5",
            "--v",
            "0.5",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let stderr = String::from_utf8(out.stderr).unwrap();
    // Each message once, whatever argument it is reported about.
    let messages: Vec<&str> = stderr
        .lines()
        .map(|l| l.split_once(": line ").map_or(l, |(_, m)| m))
        .collect();
    let distinct: std::collections::BTreeSet<&&str> = messages.iter().collect();
    assert_eq!(messages.len(), 9, "{stderr}");
    assert_eq!(messages.len(), distinct.len(), "{stderr}");
    assert!(
        stderr
            .lines()
            .all(|l| l.starts_with("cagd: warning: --script ")),
        "{stderr}"
    );
    // Two slips in one argument: each warning once, in order.
    let out = Command::cargo_bin("cagd")
        .unwrap()
        .args(["bernstein", "--degree", "2", "--t", "[0,5 0,5]"])
        .output()
        .unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        stderr,
        "cagd: warning: --t: `0,5` read as two numbers 0 and 5; a decimal point is `0.5`\n\
         cagd: warning: --t: 2 values lie (the first t = 5) outside [0, 1]; the polynomials are extrapolated there\n"
    );
}

#[test]
fn parameters_outside_the_domain_warn_or_fail_where_undefined() {
    let cases: [(&[&str], &str); 6] = [
        (
            &["bernstein", "--degree", "3", "--t", "1.5"],
            "--t: t = 1.5 lies outside [0, 1]",
        ),
        (
            &[
                "hermite", "--p0", "[0;0]", "--p1", "[1;0]", "--t0", "[1;1]", "--t1", "[1;-1]",
                "--t", "-1",
            ],
            "--t: t = -1 lies outside [0, 1]",
        ),
        (
            &["lagrange", "--nodes", "[0 0.5 1]", "--t", "2"],
            "--t: t = 2 lies outside [0, 1]",
        ),
        (
            &[
                "bezier-patch",
                common::thesis_args::NET_3X3,
                "--u",
                "2",
                "--v",
                "0.5",
            ],
            "--u: u = 2 lies outside [0, 1]",
        ),
        (
            &["spline", "[0 0; 1 1; 2 0]'", "--t", "3"],
            "--t: t = 3 lies outside [0, 2]; the end segments are extended there",
        ),
        (
            &["decasteljau", "[0 1 3]", "--interval", "2,5", "--t", "1"],
            "--t: t = 1 lies outside [2, 5]",
        ),
    ];
    for (args, warning) in cases {
        let (_, w) = run_ok(args);
        assert!(w.len() == 1 && w[0].starts_with(warning), "{args:?}: {w:?}");
    }
    // A closed spline is periodic: every parameter is on the curve, silently.
    silent(&[
        "spline",
        "[0 0; 1 1; 2 0]'",
        "--end",
        "closed",
        "--t",
        "[-7 3 10]",
    ]);
    // B-spline surfaces are not defined outside their domain.
    let e = error(&[
        "bspline-surface",
        common::thesis_args::NET_3X3,
        "--degree",
        "2",
        "--u",
        "1.5",
        "--v",
        "0",
    ]);
    assert!(
        e.starts_with("--u: B-spline surface: parameter 1.5 is outside the domain [0, 1]"),
        "{e}"
    );
}

#[test]
fn options_without_effect_are_errors_naming_them() {
    let odd = common::data_file("appendix_d_odd.m");
    let odd = odd.to_str().unwrap();
    let cases: [(&[&str], &str); 6] = [
        (
            &["integrate", "[0 1 2]", "--i", "1"],
            "--i: has no effect without the Bernstein polynomials",
        ),
        (
            &["integrate", "--bernstein", "2", "[0 1]"],
            "CONTROL: has no effect with the Bernstein polynomials",
        ),
        (
            &["continuity", "[0 1]", "[1 2]", "--k", "2"],
            "--k: has no effect without the free point",
        ),
        (
            &[
                "discrete-coons",
                common::thesis_args::NET_3X3,
                "--mask=0,0.25",
                "--steps",
            ],
            "--steps: has no effect with a mask",
        ),
        (
            &["gordon", "--script", odd, "--u-nodes", "[0 0.5 1]"],
            "--u-nodes: has no effect with the script's packed network",
        ),
        (
            &["integrate", "[0 1 2]", "--degree", "1", "--interval", "0,2"],
            "--interval: has no effect on a B-spline",
        ),
    ];
    for (args, start) in cases {
        let e = error(args);
        assert!(e.starts_with(start), "{args:?}: {e}");
    }
}

// ---------------------------------------------------------------------------------------
// Output people can read

#[test]
fn text_hides_round_off_while_machine_formats_keep_every_bit() {
    let args = ["curve", "[t; t/3]", "--t", "[0.1 0.2 0.3]"];
    let out = silent(&args);
    assert!(out.contains("0.1  0.2  0.3\n"), "{out}");
    // 15 significant digits of the matrix's largest entry (0.3): 15 decimals.
    assert!(
        out.contains("0.033333333333333  0.066666666666667  0.1\n"),
        "{out}"
    );
    // Round-off below the matrix's last digit does not show (a spline's samples): the
    // natural spline through (0,0), (2,1), (4,4), (6,0) at its default samples.
    let out = silent(&["spline", "[0 0; 2 1; 4 4; 6 0]", "--rows"]);
    assert!(
        !out.contains("99999999") && !out.contains("00000000"),
        "{out}"
    );
    let out = silent(&["curve", "t+0.2", "--t", "0.1"]);
    assert!(out.contains("result = 0.3\n"), "{out}");
    let mut a = vec!["curve", "t+0.2", "--t", "0.1"];
    a.extend(["--format", "csv"]);
    assert!(silent(&a).contains("0.30000000000000004"));
    let mut a = vec!["curve", "t+0.2", "--t", "0.1"];
    a.extend(["--digits", "17"]);
    assert!(silent(&a).contains("result = 0.30000000000000004"));
    // Round-off of a zero beside numbers of size 1 is 0 in text (cos(π/2) = 6.1e-17).
    let out = silent(&["curve", "[cos(pi*t); sin(pi*t)]", "--t", "[0 0.5]"]);
    assert!(out.contains("    1  0\n    0  1\n"), "{out}");
}

#[test]
fn steps_in_json_are_structured_data() {
    let out = json(&[
        "decasteljau",
        common::thesis_args::PRIMER_2_4,
        "--t",
        "0.5",
        "--steps",
        "--exact",
    ]);
    let scheme = &out["scheme"];
    assert_eq!(exact(&scheme["r3"]), strs(&[&["7/2"], &["3/2"], &["3/4"]]));
    assert_eq!(
        exact(&scheme["r2"]),
        strs(&[&["2", "5"], &["3/2", "3/2"], &["1", "1/2"]])
    );
    let keys: Vec<&String> = scheme.as_object().unwrap().keys().collect();
    assert_eq!(keys.len(), 4);
    let out = json(&[
        "bspline-basis",
        "--knots",
        "[0 0 0 1 2 3 3 3]",
        "--degree",
        "2",
        "--t",
        "1.5",
        "--steps",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["triangle"]["p2"]),
        strs(&[&["0", "1/8", "3/4", "1/8", "0"]])
    );
    // The text format keeps the triangle of the thesis.
    let text = silent(&[
        "decasteljau",
        common::thesis_args::PRIMER_2_4,
        "--t",
        "0.5",
        "--steps",
        "--exact",
    ]);
    assert!(text.contains("(4, 0, 0)   (6, 1, 0)   (5, 3/2, 1/2)   (7/2, 3/2, 3/4)"));
}

#[test]
fn surfaces_list_one_point_per_line() {
    let out = silent(&[
        "surface",
        "[u; v; u.*v]",
        "--u",
        "[0 1]",
        "--v",
        "[0 0.5]",
        "--list",
        "--exact",
    ]);
    assert!(
        out.contains("result =\n\n    0    0  0    0    0\n    0  1/2  0  1/2    0\n    1    0  1    0    0\n    1  1/2  1  1/2  1/2\n"),
        "{out}"
    );
    let j = json(&[
        "coons",
        "--c1",
        "[u;0;u-u^2]",
        "--c2",
        "[u;1;u]",
        "--d1",
        "[0;v^2;v-v^2]",
        "--d2",
        "[1;v;v]",
        "--u",
        "0.2",
        "--v",
        "0.5",
        "--list",
        "--exact",
    ]);
    assert_eq!(
        exact(&j["result"]),
        strs(&[&["1/5", "1/2", "1/5", "3/10", "19/50"]])
    );
}

// ---------------------------------------------------------------------------------------
// The new commands against their oracles

#[test]
fn convert_reproduces_the_matrix_form_notes_and_the_lecture_notes_table() {
    // The matrix-form notes: P·M = [0 3 0 0; 0 3 −6 4].
    let out = json(&[
        "convert",
        "[0 0; 1 1; 2 0; 3 1]",
        "--rows",
        "--from",
        "bezier",
        "--to",
        "monomial",
        "--steps",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["result"]),
        strs(&[&["0", "3", "0", "0"], &["0", "3", "-6", "4"]])
    );
    assert_eq!(
        exact(&out["T"]),
        strs(&[
            &["1", "-3", "3", "-1"],
            &["0", "3", "-6", "3"],
            &["0", "0", "3", "-3"],
            &["0", "0", "0", "1"]
        ])
    );
    // The lecture notes' table, X_to = X_from · T, every printed matrix.
    let table: [(&str, &str, &[&[&str]]); 6] = [
        (
            "bezier",
            "hermite",
            &[
                &["1", "0", "-3", "0"],
                &["0", "0", "3", "0"],
                &["0", "0", "0", "-3"],
                &["0", "1", "0", "3"],
            ],
        ),
        (
            "hermite",
            "bezier",
            &[
                &["1", "1", "0", "0"],
                &["0", "0", "1", "1"],
                &["0", "1/3", "0", "0"],
                &["0", "0", "-1/3", "0"],
            ],
        ),
        (
            "bspline",
            "hermite",
            &[
                &["1/6", "0", "-1/2", "0"],
                &["2/3", "1/6", "0", "-1/2"],
                &["1/6", "2/3", "1/2", "0"],
                &["0", "1/6", "0", "1/2"],
            ],
        ),
        (
            "bspline",
            "bezier",
            &[
                &["1/6", "0", "0", "0"],
                &["2/3", "2/3", "1/3", "1/6"],
                &["1/6", "1/3", "2/3", "2/3"],
                &["0", "0", "0", "1/6"],
            ],
        ),
        (
            "hermite",
            "bspline",
            &[
                &["-1", "2", "-1", "2"],
                &["2", "-1", "2", "-1"],
                &["-7/3", "2/3", "-1/3", "2/3"],
                &["-2/3", "1/3", "-2/3", "7/3"],
            ],
        ),
        (
            "bezier",
            "bspline",
            &[
                &["6", "0", "0", "0"],
                &["-7", "2", "-1", "2"],
                &["2", "-1", "2", "-7"],
                &["0", "0", "0", "6"],
            ],
        ),
    ];
    for (from, to, t) in table {
        // Row i of T is e_i · T: the conversion of the 1-D geometry e_i.
        let rows: Vec<Vec<String>> = ["[1 0 0 0]", "[0 1 0 0]", "[0 0 1 0]", "[0 0 0 1]"]
            .iter()
            .map(|e| {
                let out = json(&["convert", e, "--from", from, "--to", to, "--exact"]);
                exact(&out["result"]).remove(0)
            })
            .collect();
        assert_eq!(rows, strs(t), "{from} → {to}");
    }
    // The lecture notes' Bézier example in Hermite form: x'(0) = 3(x1 − x0), x'(1) = 3(x3 − x2).
    let out = json(&[
        "convert",
        "[2 3; 3 5; 4 7; 5 3]",
        "--rows",
        "--from",
        "bezier",
        "--to",
        "hermite",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["result"]),
        strs(&[&["2", "5", "3", "3"], &["3", "3", "6", "-12"]])
    );
    // Any degree: a quintic to monomial and back is the identity, exactly.
    let q = "[1 -2 0.5 3 0 7; 2 2 -1 0 4 1]";
    let mono = json(&[
        "convert", q, "--from", "bezier", "--to", "monomial", "--exact",
    ]);
    let text: Vec<String> = exact(&mono["result"])
        .iter()
        .map(|r| format!("[{}]", r.join(" ")))
        .collect();
    let back = json(&[
        "convert",
        &format!(
            "[{}; {}]",
            &text[0][1..text[0].len() - 1],
            &text[1][1..text[1].len() - 1]
        ),
        "--from",
        "monomial",
        "--to",
        "bezier",
        "--exact",
    ]);
    assert_eq!(
        exact(&back["result"]),
        strs(&[
            &["1", "-2", "1/2", "3", "0", "7"],
            &["2", "2", "-1", "0", "4", "1"]
        ])
    );
    // The algebraic form A of the lecture notes is the monomial form reversed.
    let alg = json(&[
        "convert",
        "[0 0; 1 1; 2 0; 3 1]",
        "--rows",
        "--from",
        "bezier",
        "--to",
        "algebraic",
        "--exact",
    ]);
    assert_eq!(
        exact(&alg["result"]),
        strs(&[&["0", "0", "3", "0"], &["4", "-6", "3", "0"]])
    );
}

#[test]
fn elevation_matches_nrbdegelev() {
    let ws = common::expected("course_cli");
    let c = common::matrix(&ws, "el_bez_C");
    for (r, name) in [("1", "el_bez_E1"), ("2", "el_bez_E2")] {
        let out = json(&["elevate", &lit(&c), "--by", r]);
        common::assert_close(
            name,
            &mat(&out["control"]).into_dyn(),
            &common::matrix(&ws, name).into_dyn(),
        );
    }
    let c = common::matrix(&ws, "el_bsp_C");
    let k = common::row(&ws, "el_bsp_K");
    for (r, cn, kn) in [
        ("1", "el_bsp_C1", "el_bsp_K1"),
        ("2", "el_bsp_C2", "el_bsp_K2"),
    ] {
        // The degree before (2) comes from the knots: numel(K) − columns(C) − 1.
        let out = json(&["elevate", &lit(&c), "--knots", &row_lit(&k), "--by", r]);
        common::assert_close(
            kn,
            &mat(&out["knots"]).into_dyn(),
            &common::matrix(&ws, kn).into_dyn(),
        );
        common::assert_close(
            cn,
            &mat(&out["control"]).into_dyn(),
            &common::matrix(&ws, cn).into_dyn(),
        );
    }
    // Exactly by hand: the segment 0 → 3 as a quadratic and a cubic; --degree and --order
    // name the curve after elevation (the order k = p + 1).
    let out = json(&["elevate", "[0 3]", "--by", "2", "--steps", "--exact"]);
    assert_eq!(exact(&out["degree_2"]), strs(&[&["0", "3/2", "3"]]));
    assert_eq!(exact(&out["control"]), strs(&[&["0", "1", "2", "3"]]));
    let by_order = json(&["elevate", &lit(&c), "--order", "4", "--knots", &row_lit(&k)]);
    let by_degree = json(&[
        "elevate",
        &lit(&c),
        "--degree",
        "3",
        "--knots",
        &row_lit(&k),
    ]);
    assert_eq!(by_order, by_degree);
    let by_one = json(&["elevate", &lit(&c), "--by", "1", "--knots", &row_lit(&k)]);
    assert_eq!(by_one, by_degree);
}

#[test]
fn subdivision_gives_primer_2_4s_two_polygons() {
    let out = json(&[
        "subdivide",
        common::thesis_args::PRIMER_2_4,
        "--t",
        "0.5",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["left"]),
        strs(&[
            &["0", "0", "2", "7/2"],
            &["0", "1", "3/2", "3/2"],
            &["0", "1", "1", "3/4"]
        ])
    );
    assert_eq!(
        exact(&out["right"]),
        strs(&[
            &["7/2", "5", "6", "4"],
            &["3/2", "3/2", "1", "0"],
            &["3/4", "1/2", "0", "0"]
        ])
    );
    let text = silent(&[
        "subdivide",
        common::thesis_args::PRIMER_2_4,
        "--steps",
        "--exact",
    ]);
    assert!(
        text.contains("R(4, 0, 0)   R(6, 1, 0)   R(5, 3/2, 1/2)   LR(7/2, 3/2, 3/4)"),
        "{text}"
    );
    assert!(
        text.contains("L(0, 0, 0)\n(0, 2, 2)    L(0, 1, 1)\n"),
        "{text}"
    );
    let e = error(&["subdivide", common::thesis_args::PRIMER_2_4, "--t", "1"]);
    assert!(e.starts_with("--t: "), "{e}");
}

#[test]
fn knot_insertion_matches_bspkntins_and_nrbkntins() {
    let ws = common::expected("bspline_curves");
    for key in [
        "p2_clamped",
        "p3_clamped",
        "p3_repeated",
        "p3_uniform",
        "p4_nonunif",
    ] {
        let c = common::matrix(&ws, &format!("C_{key}"));
        let k = common::row(&ws, &format!("knots_{key}"));
        let p = common::row(&ws, &format!("deg_{key}"))[0];
        let ins = common::row(&ws, &format!("ins_{key}"));
        let out = json(&[
            "insert-knot",
            &lit(&c),
            "--degree",
            &format!("{p}"),
            "--knots",
            &row_lit(&k),
            "--insert",
            &row_lit(&ins),
        ]);
        common::assert_close(
            &format!("IK_{key}"),
            &mat(&out["knots"]).into_dyn(),
            &common::matrix(&ws, &format!("IK_{key}")).into_dyn(),
        );
        common::assert_close(
            &format!("IC_{key}"),
            &mat(&out["control"]).into_dyn(),
            &common::matrix(&ws, &format!("IC_{key}")).into_dyn(),
        );
    }
    let ws = common::expected("nurbs");
    for key in ["p2", "p3"] {
        let h = common::matrix(&ws, &format!("H_{key}"));
        let w: Vec<f64> = h.row(3).to_vec();
        let pts = Array2::from_shape_fn((3, h.ncols()), |(r, c)| h[[r, c]] / w[c]);
        let out = json(&[
            "insert-knot",
            &lit(&pts),
            "--weights",
            &row_lit(&w),
            "--degree",
            &format!("{}", common::row(&ws, &format!("deg_{key}"))[0]),
            "--knots",
            &row_lit(&common::row(&ws, &format!("knots_{key}"))),
            "--insert",
            &row_lit(&common::row(&ws, &format!("ins_{key}"))),
        ]);
        let ih = common::matrix(&ws, &format!("IH_{key}"));
        let ours_w = mat(&out["weights"]);
        common::assert_close(
            &format!("IH_{key} weights"),
            &ours_w.clone().into_dyn(),
            &ih.slice(ndarray::s![3..4, ..]).to_owned().into_dyn(),
        );
        let ours_pts = mat(&out["control"]);
        let octave_pts = Array2::from_shape_fn((3, ih.ncols()), |(r, c)| ih[[r, c]] / ih[[3, c]]);
        common::assert_close(
            &format!("IH_{key} points"),
            &ours_pts.into_dyn(),
            &octave_pts.into_dyn(),
        );
    }
    // Boehm's α by hand: u = 1/4 into u_1..u_7 = 0,0,0,½,1,1,1 (span 3, u_3 ≤ u < u_4):
    // α_i = (u − u_i)/(u_(i+2) − u_i), i = 2, 3: 1/2, 1/4.
    let out = json(&[
        "insert-knot",
        "[0 0; 1 2; 3 2; 4 0]",
        "--rows",
        "--degree",
        "2",
        "--knots",
        "[0 0 0 0.5 1 1 1]",
        "--insert",
        "0.25",
        "--steps",
        "--exact",
    ]);
    assert_eq!(exact(&out["insert_1"]["alpha"]), strs(&[&["1/2", "1/4"]]));
    assert_eq!(
        exact(&out["control"]),
        strs(&[&["0", "1/2", "3/2", "3", "4"], &["0", "1", "2", "2", "0"]])
    );
}

#[test]
fn bspline_basis_matches_basisfun_and_the_lecture_notes() {
    let ws = common::expected("bspline_curves");
    for key in ["p2_clamped", "p3_repeated", "p3_uniform", "p4_nonunif"] {
        let k = common::row(&ws, &format!("knots_{key}"));
        let p = common::row(&ws, &format!("deg_{key}"))[0] as usize;
        let u = common::row(&ws, &format!("u_{key}"));
        let spans = common::row(&ws, &format!("S_{key}"));
        let b = common::matrix(&ws, &format!("B_{key}"));
        let out = json(&[
            "bspline-basis",
            "--knots",
            &row_lit(&k),
            "--degree",
            &format!("{p}"),
            "--t",
            &row_lit(&u),
        ]);
        let ours = mat(&out["result"]);
        // basisfun gives the p+1 non-zero functions of its span s (octave-nurbs counts from 0):
        // our columns s − p … s from 0, N_(s−p+1)…N_(s+1) as the help numbers them.
        let picked = Array2::from_shape_fn((u.len(), p + 1), |(i, j)| {
            ours[[i, spans[i] as usize - p + j]]
        });
        common::assert_close(&format!("B_{key}"), &picked.into_dyn(), &b.into_dyn());
    }
    // The lecture notes' uniform quadratic N_i,3 (order 3): ½u² on the first span, peak 3/4.
    let out = json(&[
        "bspline-basis",
        "--knots",
        "[0 1 2 3]",
        "--order",
        "3",
        "--t",
        "[0.5 1.5 2.5]",
        "--exact",
    ]);
    assert_eq!(exact(&out["result"]), strs(&[&["1/8"], &["3/4"], &["1/8"]]));
    // The uniform cubic pieces of the lecture notes' M_C: at the start of a span 1/6, 2/3, 1/6.
    let out = json(&[
        "bspline-basis",
        "--knots",
        "0:7",
        "--order",
        "4",
        "--t",
        "4",
        "--exact",
    ]);
    assert_eq!(exact(&out["result"]), strs(&[&["0", "1/6", "2/3", "1/6"]]));
}

#[test]
fn continuity_reproduces_the_lecture_notes_free_point() {
    let out = json(&[
        "continuity",
        "[2 3 4; 3 1 5; 3 4 3]",
        "[3 4 3; 2 6 0; 5 7 5; 5 2 3]",
        "--rows",
        "--free-point",
        "--exact",
    ]);
    assert_eq!(exact(&out["free_base"]), strs(&[&["3"], &["4"], &["3"]]));
    assert_eq!(
        exact(&out["free_direction"]),
        strs(&[&["1"], &["-2"], &["3"]])
    );
    assert!(out["free_point"]
        .as_str()
        .unwrap()
        .contains("x = 3 + k, y = 4 - 2k, z = 3 + 3k"));
    assert_eq!(exact(&out["point"]), strs(&[&["4"], &["2"], &["6"]]));
    assert_eq!(
        [
            &out["continuity"]["C0"],
            &out["continuity"]["C1"],
            &out["continuity"]["G1"],
            &out["continuity"]["C2"]
        ]
        .map(exact),
        [
            strs(&[&["1"]]),
            strs(&[&["1"]]),
            strs(&[&["1"]]),
            strs(&[&["0"]])
        ]
    );
    // k = 2: G1, which the notes call C1, but not C1.
    let out = json(&[
        "continuity",
        "[2 3 4; 3 1 5; 3 4 3]",
        "[3 4 3; 2 6 0; 5 7 5; 5 2 3]",
        "--rows",
        "--free-point",
        "--k",
        "2",
        "--exact",
    ]);
    assert_eq!(exact(&out["point"]), strs(&[&["5"], &["0"], &["9"]]));
    assert_eq!(exact(&out["k"]), strs(&[&["2"]]));
    assert_eq!(exact(&out["continuity"]["C1"]), strs(&[&["0"]]));
    assert_eq!(exact(&out["continuity"]["G1"]), strs(&[&["1"]]));
    // Tangents (2, 0) and (4, 0): G1, not C1; then a C2 joint (second derivatives (0, −4)).
    let out = json(&[
        "continuity",
        "[0 0; 1 1; 2 1]",
        "[2 1; 4 1; 5 0]",
        "--rows",
        "--exact",
    ]);
    assert_eq!(exact(&out["continuity"]["C1"]), strs(&[&["0"]]));
    assert_eq!(exact(&out["continuity"]["G1"]), strs(&[&["1"]]));
    assert_eq!(exact(&out["k"]), strs(&[&["1/2"]]));
    let out = json(&[
        "continuity",
        "[0 0; 1 2; 2 2]",
        "[2 2; 3 2; 4 0]",
        "--rows",
        "--steps",
        "--exact",
    ]);
    assert_eq!(exact(&out["continuity"]["C2"]), strs(&[&["1"]]));
    // The derivative polygons 2Δb_i and 2Δ²b_i whose ends are compared.
    assert_eq!(
        exact(&out["first"]["d1"]),
        strs(&[&["2", "2"], &["4", "0"]])
    );
    assert_eq!(exact(&out["first"]["d2"]), strs(&[&["0"], &["-4"]]));
    assert_eq!(exact(&out["second"]["d2"]), strs(&[&["0"], &["-4"]]));
}

#[test]
fn integrals_are_exact() {
    // ∫₀¹ B_i^n = 1/(n+1); ∫₀^(1/2) B_0^3 = 15/64 (1 − (1 − t)⁴ at t = 1/2, over 4).
    let out = json(&["integrate", "--bernstein", "3", "--t", "0.5", "--exact"]);
    assert_eq!(
        exact(&out["integral"]),
        strs(&[&["1/4"], &["1/4"], &["1/4"], &["1/4"]])
    );
    assert_eq!(
        exact(&out["result"]),
        strs(&[&["15/64", "11/64", "5/64", "1/64"]])
    );
    // The parabola (t·2, 4t(1−t)·… ): control (0,0), (1,2), (2,0): ∫ = (1, 2/3).
    let out = json(&["integrate", "[0 0; 1 2; 2 0]", "--rows", "--exact"]);
    assert_eq!(exact(&out["integral"]), strs(&[&["1"], &["2/3"]]));
    assert_eq!(
        exact(&out["antiderivative"]),
        strs(&[&["0", "0", "1/3", "1"], &["0", "0", "2/3", "2/3"]])
    );
    // Over [1, 4]: three times as much.
    let out = json(&[
        "integrate",
        "[0 0; 1 2; 2 0]",
        "--rows",
        "--interval",
        "1,4",
        "--exact",
    ]);
    assert_eq!(exact(&out["integral"]), strs(&[&["3"], &["2"]]));
    // B-splines: ∫ N_i,p = (u_(i+p+1) − u_i)/(p+1): 1/6, 1/3, 1/3, 1/6 on 0,0,0,½,1,1,1.
    let out = json(&[
        "integrate",
        "[6 3 3 6]",
        "--degree",
        "2",
        "--knots",
        "[0 0 0 0.5 1 1 1]",
        "--steps",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["basis_integrals"]),
        strs(&[&["1/6", "1/3", "1/3", "1/6"]])
    );
    assert_eq!(exact(&out["integral"]), strs(&[&["4"]]));
    // An unclamped uniform cubic: over the domain [0, 1] the four pieces of the span integrate
    // to 1/24, 11/24, 11/24, 1/24 (∫₀¹ of the rows of the lecture notes' M_C).
    for (control, integral) in [
        ("[1 0 0 0]", "1/24"),
        ("[0 1 0 0]", "11/24"),
        ("[0 0 1 0]", "11/24"),
        ("[0 0 0 1]", "1/24"),
    ] {
        let out = json(&[
            "integrate",
            control,
            "--degree",
            "3",
            "--knots",
            "[-3 -2 -1 0 1 2 3 4]",
            "--exact",
        ]);
        assert_eq!(exact(&out["integral"]), strs(&[&[integral]]));
    }
}

#[test]
fn ruled_surface_matches_nrbruled() {
    let ws = common::expected("course_cli");
    let out = json(&[
        "ruled",
        "--first",
        &lit(&common::matrix(&ws, "ru_C1")),
        "--second",
        &lit(&common::matrix(&ws, "ru_C2")),
        "--u",
        &row_lit(&common::row(&ws, "ru_gu")),
        "--v",
        &row_lit(&common::row(&ws, "ru_gv")),
        "--columns",
    ]);
    common::assert_close(
        "ru_S",
        &grid(&out["result"]),
        &octave_grid(&common::array(&ws, "ru_S")),
    );
    // The lecture notes' form (1 − v) ¹x(u) + v ²x(u), exactly.
    let out = json(&[
        "ruled",
        "--first",
        "[u;0;0]",
        "--second",
        "[u;1;u-u^2]",
        "--u",
        "0.5",
        "--v",
        "0.25",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["result"]),
        strs(&[&["1/2"], &["1/4"], &["1/16"]])
    );
}

#[test]
fn ferguson_patch_reproduces_the_hyperbolic_paraboloid() {
    // z = uv: corner points, u-tangents (1, 0, v), v-tangents (0, 1, u), twist 1.
    let args = [
        "ferguson",
        "--points",
        "[0 0 0; 1 0 0; 0 1 0; 1 1 1]'",
        "--du",
        "[1 0 0; 1 0 0; 1 0 1; 1 0 1]'",
        "--dv",
        "[0 1 0; 0 1 1; 0 1 0; 0 1 1]'",
        "--twists",
        "[0 0 1; 0 0 1; 0 0 1; 0 0 1]'",
        "--u",
        "[0 0.25 1]",
        "--v",
        "[0.5 1]",
        "--list",
        "--exact",
    ];
    let out = json(&args);
    let rows = exact(&out["result"]);
    for r in &rows {
        let q = |s: &str| -> (i64, i64) {
            match s.split_once('/') {
                Some((a, b)) => (a.parse().unwrap(), b.parse().unwrap()),
                None => (s.parse().unwrap(), 1),
            }
        };
        let (u, v, z) = (q(&r[0]), q(&r[1]), q(&r[4]));
        assert_eq!(z.0 * u.1 * v.1, u.0 * v.0 * z.1, "z = uv at {r:?}");
        assert_eq!((&r[2], &r[3]), (&r[0], &r[1]));
    }
    // Zero twists (the notes' F-patch): at (1/4, 1/4) the twist term
    // (f3 + f4)(1/4)² = (9/64 − 3/64)² = 9/1024 is missing from uv = 1/16.
    let out = json(&[
        "ferguson",
        "--points",
        "[0 0 0; 1 0 0; 0 1 0; 1 1 1]'",
        "--du",
        "[1 0 0; 1 0 0; 1 0 1; 1 0 1]'",
        "--dv",
        "[0 1 0; 0 1 1; 0 1 0; 0 1 1]'",
        "--u",
        "0.25",
        "--v",
        "0.25",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["result"]),
        strs(&[&["1/4"], &["1/4"], &["55/1024"]])
    );
}

#[test]
fn spline_surfaces_read_nrbmak_structs_and_match_nrbeval() {
    let file = common::octave_ref_dir()
        .join("expected")
        .join("course_cli.txt");
    let file = file.to_str().unwrap();
    let ws = common::expected("course_cli");
    let out = json(&[
        "nurbs-surface",
        &format!("{file}:srf"),
        "--u",
        &row_lit(&common::row(&ws, "srf_gu")),
        "--v",
        &row_lit(&common::row(&ws, "srf_gv")),
    ]);
    common::assert_close(
        "srf_S",
        &grid(&out["result"]),
        &octave_grid(&common::array(&ws, "srf_S")),
    );
    let out = json(&[
        "bspline-surface",
        &format!("{file}:bsrf"),
        "--u",
        &row_lit(&common::row(&ws, "bsrf_gu")),
        "--v",
        &row_lit(&common::row(&ws, "bsrf_gv")),
    ]);
    common::assert_close(
        "bsrf_S",
        &grid(&out["result"]),
        &octave_grid(&common::array(&ws, "bsrf_S")),
    );
    // The rational struct is refused as a B-spline surface, naming the right command.
    let e = error(&["bspline-surface", &format!("{file}:srf")]);
    assert!(e.contains("nurbs-surface"), "{e}");
    // A packed net with --degree: bspline_surfaces' p2q2 through the command line.
    let ws = common::expected("bspline_surfaces");
    let names: Vec<String> = ws.names().map(str::to_string).collect();
    for key in names.iter().filter_map(|n| n.strip_prefix("X_")) {
        let (x, y, z) = (
            common::matrix(&ws, &format!("X_{key}")),
            common::matrix(&ws, &format!("Y_{key}")),
            common::matrix(&ws, &format!("Z_{key}")),
        );
        let (p, q) = (
            common::row(&ws, &format!("degu_{key}"))[0],
            common::row(&ws, &format!("degv_{key}"))[0],
        );
        let out = json(&[
            "bspline-surface",
            "--x",
            &lit(&x),
            "--y",
            &lit(&y),
            "--z",
            &lit(&z),
            "--degree",
            &format!("{p},{q}"),
            "--uknots",
            &row_lit(&common::row(&ws, &format!("ku_{key}"))),
            "--vknots",
            &row_lit(&common::row(&ws, &format!("kv_{key}"))),
            "--u",
            &row_lit(&common::row(&ws, &format!("gu_{key}"))),
            "--v",
            &row_lit(&common::row(&ws, &format!("gv_{key}"))),
        ]);
        common::assert_close(
            &format!("S_{key}"),
            &grid(&out["result"]),
            &octave_grid(&common::array(&ws, &format!("S_{key}"))),
        );
    }
}

#[test]
fn circles_and_arcs_match_nrbcirc() {
    let ws = common::expected("nurbs");
    for k in 1..=6 {
        let a = common::row(&ws, &format!("circ_{k}_args"));
        let center = if a[3] == 0.0 {
            row_lit(&a[1..3])
        } else {
            row_lit(&a[1..4])
        };
        let u = common::row(&ws, &format!("circ_{k}_u"));
        let out = json(&[
            "arc",
            "--radius",
            &format!("{:?}", a[0]),
            "--center",
            &center,
            "--start",
            &format!("{:?}", a[4]),
            "--end",
            &format!("{:?}", a[5]),
            "--t",
            &row_lit(&u),
        ]);
        let p = common::matrix(&ws, &format!("circ_{k}_P"));
        let ours = mat(&out["result"]);
        let octave = p.slice(ndarray::s![0..ours.nrows(), ..]).to_owned();
        common::assert_close(&format!("circ_{k}_P"), &ours.into_dyn(), &octave.into_dyn());
        common::assert_close(
            &format!("circ_{k}_knots"),
            &mat(&out["knots"]).into_dyn(),
            &common::matrix(&ws, &format!("circ_{k}_knots")).into_dyn(),
        );
    }
    let e = error(&["circle", "--exact"]);
    assert!(e.starts_with("--exact: "), "{e}");
}

#[test]
fn bezier_patch_derivatives_match_nrbdeval() {
    let ws = common::expected("course_cli");
    let b = common::array(&ws, "dp_B");
    let net = lit(&packed(&b));
    let (gu, gv) = (
        row_lit(&common::row(&ws, "dp_gu")),
        row_lit(&common::row(&ws, "dp_gv")),
    );
    for (du, dv, name) in [
        ("0", "0", "dp_P"),
        ("1", "0", "dp_Du"),
        ("0", "1", "dp_Dv"),
        ("2", "0", "dp_Duu"),
        ("1", "1", "dp_Duv"),
        ("0", "2", "dp_Dvv"),
    ] {
        let out = json(&[
            "bezier-patch",
            &net,
            "--du",
            du,
            "--dv",
            dv,
            "--u",
            &gu,
            "--v",
            &gv,
        ]);
        common::assert_close(
            name,
            &grid(&out["result"]),
            &octave_grid(&common::array(&ws, name)),
        );
    }
    // The twist net m·n·Δ^(1,1) b_ij of thesis Trditev 3.3, exactly, on the 3×3 example net.
    let out = json(&[
        "bezier-patch",
        common::thesis_args::NET_3X3,
        "--du",
        "1",
        "--dv",
        "1",
        "--u",
        "0",
        "--v",
        "0",
        "--exact",
    ]);
    // z = [0 1 0; 1 4 1; 0 1 0]: 4·(4 − 1 − 1 + 0) = 8 at (0,0); x, y have no twist.
    let net = &out["net"];
    assert_eq!(net[0][0][2].as_str(), Some("8"));
    assert_eq!(net[1][1][2].as_str(), Some("8"));
    assert_eq!(net[0][1][2].as_str(), Some("-8"));
    assert_eq!(exact(&out["result"]), strs(&[&["0"], &["0"], &["8"]]));
    // --x/--y/--z: the same patch from its coordinate matrices.
    let by_net = json(&[
        "bezier-patch",
        common::thesis_args::NET_3X3,
        "--u",
        "0.25",
        "--v",
        "0.5",
        "--exact",
    ]);
    let by_xyz = json(&[
        "bezier-patch",
        "--x",
        "[0 0 0; 2 2 2; 4 4 4]",
        "--y",
        "[0 2 4; 0 2 4; 0 2 4]",
        "--z",
        "[0 1 0; 1 4 1; 0 1 0]",
        "--u",
        "0.25",
        "--v",
        "0.5",
        "--exact",
    ]);
    assert_eq!(by_net, by_xyz);
}

#[test]
fn coons_blend_is_thesis_4_4_with_its_checks() {
    let curves = common::thesis_args::PRIMER_4_3;
    let mut args: Vec<&str> = vec!["coons"];
    args.extend(curves);
    args.extend(["--u", "0.2", "--v", "0.5", "--exact", "--steps"]);
    // linear: the bilinear patch, Primer 4.3's (1/5, 3/10, 19/50).
    let mut a = args.clone();
    a.extend(["--blend", "linear"]);
    assert_eq!(
        exact(&json(&a)["result"]),
        strs(&[&["1/5"], &["3/10"], &["19/50"]])
    );
    // hermite: f1 = H0³ = 1 − 3u² + 2u³ (f1(1/5) = 112/125, f2 = 13/125; g = (1/2, 1/2)).
    // r_c = ½c1(1/5) + ½c2(1/5) = (1/5, 1/2, 9/50); r_d = f1 d1(½) + f2 d2(½)
    //     = (13/125, 112/500 + 13/250, 112/500 + 13/250);
    // r_cd = f1 g1 P1 + f2 g1 P2 + f1 g2 P3 + f2 g2 P4 = (13/125, 1/2, 13/250).
    let mut a = args.clone();
    a.extend(["--blend", "hermite"]);
    let out = json(&a);
    assert_eq!(exact(&out["rc"]), strs(&[&["1/5"], &["1/2"], &["9/50"]]));
    assert_eq!(
        exact(&out["rd"]),
        strs(&[&["13/125"], &["69/250"], &["69/250"]])
    );
    assert_eq!(
        exact(&out["rcd"]),
        strs(&[&["13/125"], &["1/2"], &["13/250"]])
    );
    assert_eq!(
        exact(&out["result"]),
        strs(&[&["1/5"], &["69/250"], &["101/250"]])
    );
    // The same pair as an expression, and as [f1; f2].
    let mut a = args.clone();
    a.extend(["--blend", "1-3*t^2+2*t^3"]);
    assert_eq!(json(&a)["result"], out["result"]);
    let mut a = args.clone();
    a.extend(["--blend", "[1-3*t^2+2*t^3; 3*t^2-2*t^3]"]);
    assert_eq!(json(&a)["result"], out["result"]);
    // The checks of (4.4): f1(0) = 1, f1(1) = 0, f1 + f2 = 1.
    let mut a = args.clone();
    a.extend(["--blend", "1-t^2/2"]);
    let e = error(&a);
    assert!(
        e.starts_with("--blend: ") && e.contains("first function is 0 at 1"),
        "{e}"
    );
    let mut a = args.clone();
    a.extend(["--blend", "[1-t; t^2]"]);
    let e = error(&a);
    assert!(
        e.starts_with("--blend: ") && e.contains("partition of unity"),
        "{e}"
    );
}

#[test]
fn decasteljau_on_an_interval() {
    // Primer 2.4 over [2, 6]: u = 4 is t = 1/2 (thesis §2.3.2).
    let out = json(&[
        "decasteljau",
        common::thesis_args::PRIMER_2_4,
        "--interval",
        "2,6",
        "--t",
        "4",
        "--exact",
    ]);
    assert_eq!(exact(&out["result"]), strs(&[&["7/2"], &["3/2"], &["3/4"]]));
    let out = json(&[
        "decasteljau",
        "[0 4]",
        "--interval",
        "2,6",
        "--n",
        "3",
        "--exact",
    ]);
    assert_eq!(exact(&out["t"]), strs(&[&["2", "4", "6"]]));
    assert_eq!(exact(&out["result"]), strs(&[&["0", "2", "4"]]));
}

#[test]
fn lagrange_coefficients_and_nodes_in_any_order() {
    // The lecture notes' example: x⁴/6 − 2x³ + 47x²/6 − 11x + 6.
    let out = json(&[
        "lagrange",
        "--nodes",
        "1:5",
        "--points",
        "[1 2 3 2 1]",
        "--coefficients",
        "--t",
        "2.5",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["polynomial"]),
        strs(&[&["1/6", "-2", "47/6", "-11", "6"]])
    );
    assert_eq!(exact(&out["result"]), strs(&[&["87/32"]]));
    // The notes' blending matrix G for (0, 1/3, 2/3, 1).
    let out = json(&[
        "lagrange",
        "--nodes",
        "[0 1/3 2/3 1]",
        "--coefficients",
        "--t",
        "0",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["coefficients"]),
        strs(&[
            &["-9/2", "9", "-11/2", "1"],
            &["27/2", "-45/2", "9", "0"],
            &["-27/2", "18", "-9/2", "0"],
            &["9/2", "-9/2", "1", "0"]
        ])
    );
    // Příklad 1: (0, 1/2, 1/4, 1) is allowed; the basis is still the identity at the nodes,
    // in the order given.
    let out = json(&[
        "lagrange",
        "--nodes",
        "[0 0.5 0.25 1]",
        "--t",
        "[0 0.5 0.25 1]",
        "--exact",
    ]);
    assert_eq!(
        exact(&out["result"]),
        strs(&[
            &["1", "0", "0", "0"],
            &["0", "1", "0", "0"],
            &["0", "0", "1", "0"],
            &["0", "0", "0", "1"]
        ])
    );
    // Points on a line visited out of order get a note.
    let (_, w) = run_ok(&[
        "lagrange",
        "--nodes",
        "[0 0.5 0.25 1]",
        "--points",
        "[0 1 2 3; 0 1 2 3]",
        "--t",
        "0.5",
    ]);
    assert!(
        w.len() == 1 && w[0].starts_with("--nodes: the nodes do not increase"),
        "{w:?}"
    );
    let e = error(&["lagrange", "--nodes", "[0 0.5 0]"]);
    assert!(e.starts_with("--nodes: "), "{e}");
    // The lecture notes' linear interpolation of the same points: 5/2 at x = 5/2, 3/2 at 4.5.
    let out = json(&[
        "lagrange",
        "--nodes",
        "1:5",
        "--points",
        "[1 2 3 2 1]",
        "--linear",
        "--t",
        "[2.5 4.5]",
        "--exact",
    ]);
    assert_eq!(exact(&out["result"]), strs(&[&["5/2", "3/2"]]));
    let e = error(&[
        "lagrange",
        "--nodes",
        "[0 1 0.5]",
        "--points",
        "[1 2 3]",
        "--linear",
    ]);
    assert!(e.starts_with("--nodes: "), "{e}");
}

#[test]
fn bspline_order_and_the_de_boor_scheme() {
    let base = [
        "bspline",
        "[0 0; 1 2; 3 2; 4 0]'",
        "--knots",
        "[0 0 0 0.5 1 1 1]",
        "--t",
        "0.25",
        "--steps",
        "--exact",
    ];
    let mut by_degree = base.to_vec();
    by_degree.extend(["--degree", "2"]);
    let mut by_order = base.to_vec();
    by_order.extend(["--order", "3"]);
    let out = json(&by_degree);
    assert_eq!(out, json(&by_order));
    // de Boor by hand: span 3 (u_3 ≤ 1/4 < u_4), α = 1/2, 1/4, then 1/2; the point (1, 3/2).
    assert_eq!(exact(&out["de_boor"]["alpha1"]), strs(&[&["1/2", "1/4"]]));
    assert_eq!(
        exact(&out["de_boor"]["d1"]),
        strs(&[&["1/2", "3/2"], &["1", "2"]])
    );
    assert_eq!(exact(&out["de_boor"]["d2"]), strs(&[&["1"], &["3/2"]]));
    let help = silent(&["bspline", "--help"]);
    assert!(
        help.contains("Sample the knot domain [u_(p+1), u_(n+1)] (not [0, 1])"),
        "{help}"
    );
}

#[test]
fn spline_steps_params_and_periodic_closed_splines() {
    // The lecture notes' system for case a: rows [1 4 1], right-hand sides 3(x_(k+1) − x_(k−1)).
    let out = json(&[
        "spline",
        "[0 0; 2 1; 4 4; 6 0]'",
        "--start-tangent",
        "[1;1]",
        "--end-tangent",
        "[-1;1]",
        "--steps",
        "--exact",
        "--t",
        "0",
    ]);
    assert_eq!(
        exact(&out["system"]),
        strs(&[
            &["1", "0", "0", "0"],
            &["1", "4", "1", "0"],
            &["0", "1", "4", "1"],
            &["0", "0", "0", "1"]
        ])
    );
    assert_eq!(
        exact(&out["rhs"]),
        strs(&[&["1", "12", "12", "-1"], &["1", "12", "-3", "1"]])
    );
    assert_eq!(
        exact(&out["segment_2"]["bezier"]),
        strs(&[
            &["2", "121/45", "139/45", "4"],
            &["1", "31/15", "23/5", "4"]
        ])
    );
    // Chord-length parameters and a closed spline against Octave's spline and csape.
    let ws = common::expected("course_cli");
    let y = common::matrix(&ws, "sp_Y");
    let s0 = common::matrix(&ws, "sp_s0");
    let sn = common::matrix(&ws, "sp_sn");
    let out = json(&[
        "spline",
        &lit(&y),
        "--steps",
        "--params",
        "chord",
        "--start-tangent",
        &lit(&s0),
        "--end-tangent",
        &lit(&sn),
        "--t",
        &row_lit(&common::row(&ws, "sp_e")),
    ]);
    common::assert_close(
        "sp_t",
        &mat(&out["params"]).into_dyn(),
        &common::matrix(&ws, "sp_t").into_dyn(),
    );
    common::assert_close(
        "sp_V",
        &mat(&out["result"]).into_dyn(),
        &common::matrix(&ws, "sp_V").into_dyn(),
    );
    let out = json(&[
        "spline",
        &lit(&y),
        "--end",
        "closed",
        "--params",
        &row_lit(&common::row(&ws, "sp_tc")),
        "--t",
        &row_lit(&common::row(&ws, "sp_ec")),
    ]);
    common::assert_close(
        "sp_Vc",
        &mat(&out["result"]).into_dyn(),
        &common::matrix(&ws, "sp_Vc").into_dyn(),
    );
    let e = error(&["spline", "[0 0; 1 1; 2 0]'", "--params", "chord", "--exact"]);
    assert!(e.starts_with("--params: "), "{e}");
}

#[test]
fn coons_bicubic_and_discrete_coons_print_their_parts() {
    let mut args: Vec<&str> = vec!["coons-bicubic"];
    args.extend(common::thesis_args::FLAT_SQUARE);
    args.extend(common::thesis_args::FLAT_SQUARE_CROSS);
    args.extend(["--u", "0.25", "--v", "0.5", "--steps", "--exact"]);
    let out = json(&args);
    // The flat square: h_c = (u, v, 0) from x(0,v), x(1,v) and x_u = (1,0,0); h_d = (u, v, 0);
    // h_cd = (u, v, 0); x = (u, v, 0).
    for name in ["hc", "hd", "hcd", "result"] {
        assert_eq!(
            exact(&out[name]),
            strs(&[&["1/4"], &["1/2"], &["0"]]),
            "{name}"
        );
    }
    let net = "[0 0 0 0 1 0 0 2 0; 1 0 0 0 0 0 1 2 1; 2 0 0 2 1 1 2 2 0]";
    let out = json(&["discrete-coons", net, "--steps", "--exact"]);
    // Centre (i, j) = (1, 1): b^u = ½P01 + ½P21 = (1, 1, 1/2), b^v = ½P10 + ½P12 = (1, 1, 1/2),
    // b^uv = ¼(P00 + P02 + P20 + P22) = (1, 1, 0); the net's centre (1, 1, 1).
    let at = |name: &str| -> Vec<String> {
        (0..3)
            .map(|k| out[name][1][1][k].as_str().unwrap().to_string())
            .collect()
    };
    assert_eq!(at("bu"), ["1", "1", "1/2"]);
    assert_eq!(at("bv"), ["1", "1", "1/2"]);
    assert_eq!(at("buv"), ["1", "1", "0"]);
    assert_eq!(at("result"), ["1", "1", "1"]);
    let help = silent(&["discrete-coons", "--help"]);
    assert!(
        help.contains("α = 0, β = 1/4 is the discrete Laplace mask")
            && help.contains("α = −1/4, β = 1/2 is the mask the permanence principle gives"),
        "{help}"
    );
}

// ---------------------------------------------------------------------------------------
// Pictures and `cagd course`

/// A valid SVG and a decodable, non-blank PNG of 900×700.
fn check_picture(dir: &Path, name: &str) {
    let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    assert!(
        !svg.contains(">-0<") && !svg.contains(">-0.0<"),
        "{name}.svg has a -0 tick"
    );
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(dir.join(format!("{name}.png"))).unwrap(),
    ));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut buf).unwrap();
    assert_eq!((frame.width, frame.height), (900, 700), "{name}.png");
    let distinct: std::collections::HashSet<&[u8]> = buf[..frame.buffer_size()].chunks(3).collect();
    assert!(distinct.len() > 20, "{name}.png looks blank");
}

#[test]
fn new_commands_draw_valid_pictures() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let commands: Vec<(Vec<String>, &str)> = vec![
        (
            vec!["bernstein".into(), "--degree".into(), "3".into()],
            "bernstein",
        ),
        (
            vec![
                "bspline-basis".into(),
                "--knots".into(),
                "0:7".into(),
                "--order".into(),
                "4".into(),
            ],
            "basis",
        ),
        (
            vec!["subdivide".into(), common::thesis_args::PRIMER_2_4.into()],
            "subdivide",
        ),
        (
            vec![
                "elevate".into(),
                "[0 0; 1 2; 3 2; 4 0]'".into(),
                "--by".into(),
                "2".into(),
            ],
            "elevate",
        ),
        (
            vec![
                "convert".into(),
                "[2 3; 3 5; 4 7; 5 3]".into(),
                "--rows".into(),
                "--from".into(),
                "bezier".into(),
                "--to".into(),
                "bspline".into(),
            ],
            "convert",
        ),
        (vec!["circle".into()], "circle"),
        (
            vec![
                "nurbs".into(),
                "[1 0; 1 1; 0 1]'".into(),
                "--weights".into(),
                "[1 0.7071067811865476 1]".into(),
                "--degree".into(),
                "2".into(),
            ],
            "quarter",
        ),
        (
            vec![
                "ruled".into(),
                "--first".into(),
                "[u;0;0]".into(),
                "--second".into(),
                "[u;1;u-u^2]".into(),
            ],
            "ruled",
        ),
    ];
    for (args, name) in commands {
        let mut full = vec!["cagd".to_string()];
        full.extend(args);
        for ext in ["svg", "png"] {
            let mut a = full.clone();
            a.extend(["--plot".to_string(), p(&format!("{name}.{ext}"))]);
            run(&a).unwrap().files.commit().unwrap();
        }
        check_picture(dir.path(), name);
    }
}

#[test]
fn course_prints_every_example_and_writes_valid_pictures() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("pictures");
    let out = Command::cargo_bin("cagd")
        .unwrap()
        .args(["course", "--out", out_dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    for expected in [
        "P·M =\n\n    0  3   0  0\n    0  3  -6  4\n",
        "0     3/5     6/5     9/5    12/5  3\n    0  49/125  62/125  63/125  76/125  1\n",
        "T(bezier → hermite) =\n\n    1  0  -3   0\n    0  0   3   0\n    0  0   0  -3\n    0  1   0   3\n",
        "tangents (rows x', y') =\n\n    1  31/15  41/15  -1\n    1   16/5   -9/5   1\n",
        "the third is wrong, it is -27/15",
        "coefficients of x⁴ … 1 =\n\n    1/6  -2  47/6  -11  6\n",
        "x = 3 + k, y = 4 − 2k, z = 3 + 3k, as the notes print",
        "C0 true, C1 true, G1 true",
        // √2/2 to 15 digits of the matrix's largest entry, 1.
        "weights =\n\n    1  0.70710678118655  1",
        "Formula and Coons mask agree: yes, exactly",
        "z by the mask α = 0, β = 1/4 =\n\n    0     1     2  0\n    1   9/8   9/8  0\n",
    ] {
        assert!(text.contains(expected), "missing {expected:?}");
    }
    let pictures = [
        "matrix_form",
        "conversion",
        "splines",
        "lagrange",
        "c1_joint",
        "nurbs_circle",
        "discrete_coons",
    ];
    for name in pictures {
        check_picture(&out_dir, name);
    }
    assert_eq!(
        std::fs::read_dir(&out_dir).unwrap().count(),
        2 * pictures.len()
    );
}

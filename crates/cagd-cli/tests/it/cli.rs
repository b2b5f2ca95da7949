//! The `cagd` binary: output snapshots (insta) for the working subcommands, pictures and
//! meshes it writes, and the contract for bad input — one line on standard error, exit code
//! 2, nothing on standard output and no output file.

use std::path::{Path, PathBuf};

use assert_cmd::Command;

use cagd_test_support as common;

use common::bad_input::{check_all, mentions, refused};

fn cagd() -> Command {
    let mut c = Command::cargo_bin("cagd").unwrap();
    c.current_dir(common::WORKSPACE);
    c
}

/// Runs `cagd args…`, expects success, returns standard output.
fn ok(args: &[&str]) -> String {
    let out = cagd().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "cagd {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// Runs `cagd args…` and checks the error contract; returns the one error line.
fn fails(args: &[&str]) -> String {
    refused(cagd().args(args), None).unwrap_or_else(|e| panic!("cagd {args:?}: {e}"))
}

// ---------------------------------------------------------------------------------------
// Results

#[test]
fn curve_text() {
    insta::assert_snapshot!(ok(&["curve", "[u; 0; u-u^2]", "--n", "5"]));
}

#[test]
fn curve_exact_fractions() {
    // Appendix D's c1 at u = 0, 1/4, 1/2: exactly (u, 1/2, 1/2 + u − u²).
    insta::assert_snapshot!(ok(&[
        "curve",
        "[u; 0.5; 0.5+u-u^2]",
        "--t",
        "[0 0.25 0.5]",
        "--exact"
    ]));
}

#[test]
fn curve_csv_and_json() {
    insta::assert_snapshot!(
        "curve_csv",
        ok(&["curve", "[t; t^2]", "--t", "0:0.5:1", "--format", "csv"])
    );
    insta::assert_snapshot!(
        "curve_json",
        ok(&["curve", "[t; t^2]", "--t", "0:0.5:1", "--format", "json"])
    );
    insta::assert_snapshot!(
        "curve_json_exact",
        ok(&["curve", "[t; t/3]", "--t", "[0.1 1]", "--format", "json", "--exact"])
    );
}

#[test]
fn ranges_print_octaves_doubles() {
    // Octave: disp(num2str(0:0.1:0.3, 17)) gives 0 0.10000000000000001 0.20000000000000001
    // 0.29999999999999999; the shortest round-trip forms of those doubles are below.
    let out = ok(&["curve", "t", "--t", "0:0.1:0.3", "--format", "csv"]);
    assert_eq!(out, "# t\n0,0.1,0.2,0.3\n\n# result\n0,0.1,0.2,0.3\n\n");
}

#[test]
fn surface_text_and_csv() {
    insta::assert_snapshot!("surface_text", ok(&["surface", "[u; v; u.*v]", "--n", "3"]));
    insta::assert_snapshot!(
        "surface_csv",
        ok(&[
            "surface",
            "[u; v; u.*v]",
            "--u",
            "[0 1]",
            "--v",
            "0:0.5:1",
            "--format",
            "csv"
        ])
    );
}

#[test]
fn script_appendix_c_point() {
    insta::assert_snapshot!(ok(&["script", "tests/data/appendix_c_point.m"]));
}

#[test]
fn script_appendix_c_with_n_from_the_command_line() {
    // The printed appendix C script uses N without defining it: --n binds it.
    let text = std::fs::read_to_string(cagd_test_support::data_file("appendix_c.m"))
        .unwrap()
        .replace("N = 10;", "");
    let out = cagd()
        .args(["script", "-", "--n", "4", "--format", "json"])
        .write_stdin(text)
        .output()
        .unwrap();
    assert!(out.status.success());
    insta::assert_snapshot!(String::from_utf8(out.stdout).unwrap());
}

#[test]
fn script_appendix_d_warns_once_per_lenient_evaluation() {
    let out = cagd()
        .args(["script", "tests/data/appendix_d.m", "--format", "csv"])
        .output()
        .unwrap();
    assert!(out.status.success());
    insta::assert_snapshot!(String::from_utf8(out.stderr).unwrap());
}

#[test]
fn curve_from_a_script_curve() {
    let out = ok(&[
        "curve",
        "d1",
        "--script",
        "tests/data/appendix_c_point.m",
        "--t",
        "[0 0.5 1]",
        "--exact",
    ]);
    assert!(
        out.contains("result =\n\n    0    0  0\n    0  1/4  1\n    0  1/4  0\n"),
        "{out}"
    );
}

#[test]
fn help_and_version() {
    let out = ok(&["--help"]);
    for sub in ["curve", "surface", "script"] {
        assert!(out.contains(sub));
    }
    let out = ok(&["curve", "--help"]);
    assert!(out.contains("--plot <FILE>") && out.contains("--exact") && out.contains("Examples:"));
    assert!(ok(&["--version"]).starts_with("cagd "));
}

// ---------------------------------------------------------------------------------------
// Files

#[test]
fn plot_mesh_and_output_files() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let stdout = ok(&[
        "surface",
        "[u; v; u-u^2+v]",
        "--n",
        "6",
        "--plot",
        &p("s.svg"),
        "--mesh",
        &p("s.stl"),
        "-o",
        &p("s.json"),
        "--format",
        "json",
    ]);
    assert!(stdout.is_empty(), "the result went to -o");
    let svg = std::fs::read_to_string(p("s.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    let stl = stl_io::read_stl(&mut std::fs::File::open(p("s.stl")).unwrap()).unwrap();
    assert_eq!(stl.faces.len(), 2 * 5 * 5);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p("s.json")).unwrap()).unwrap();
    assert_eq!(json["result"][5][5][2], serde_json::json!(1.0));
    ok(&[
        "curve",
        "[cos(2*pi*t); sin(2*pi*t); t]",
        "--n",
        "30",
        "--plot",
        &p("c.png"),
    ]);
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(p("c.png")).unwrap(),
    ));
    let info = decoder.read_info().unwrap();
    assert_eq!(info.info().width, 900);
    for name in ["s.obj", "s.ply"] {
        ok(&["surface", "[u; v; u.*v]", "--n", "4", "--mesh", &p(name)]);
    }
    let obj = std::fs::read_to_string(p("s.obj")).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), 16);
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), 18);
    // No temporary files are left in the directory.
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(
        names,
        ["c.png", "s.json", "s.obj", "s.ply", "s.stl", "s.svg"]
    );
}

// ---------------------------------------------------------------------------------------
// Bad input

/// Output options pointing into `dir`, appended to every bad command to prove that nothing is
/// written when the command fails.
fn outputs(dir: &Path, surface: bool) -> Vec<String> {
    let mut v = vec![
        "--plot".to_string(),
        dir.join("out.svg").to_str().unwrap().to_string(),
        "-o".to_string(),
        dir.join("out.txt").to_str().unwrap().to_string(),
    ];
    if surface {
        v.push("--mesh".into());
        v.push(dir.join("out.stl").to_str().unwrap().to_string());
    }
    v
}

#[test]
fn bad_inputs_exit_2_with_one_line_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let missing_dir: PathBuf = d.join("no/such/dir/out.svg");
    let missing = missing_dir.to_str().unwrap();
    let cases: Vec<(Vec<&str>, bool, &str)> = vec![
        (
            vec!["curve", "[1 2; 3]"],
            false,
            "row 2 has 1 column(s), expected 2",
        ),
        (vec!["curve", "[u; w]"], false, "unknown variable `w`"),
        (
            vec!["curve", "[u; foo(u)]"],
            false,
            "unknown function `foo`",
        ),
        (
            vec!["curve", "[u; v]"],
            false,
            "uses the parameters u and v",
        ),
        (
            vec!["curve", "[u; sin(u)]", "--exact"],
            false,
            "no exact rational value",
        ),
        (
            vec!["curve", "[u; 1/(u-u)]"],
            false,
            "not a finite real number",
        ),
        (vec!["curve", "[u; Inf]"], false, "`Inf` is not accepted"),
        (vec!["curve", "[u; 'a']"], false, "character strings"),
        (vec!["curve", "[u; u", "--n", "3"], false, "expected `]`"),
        (vec!["curve", "u", "--n", "1"], false, "N = 1 is too small"),
        (
            vec!["curve", "u", "--n", "abc"],
            false,
            "invalid value 'abc'",
        ),
        (
            vec!["curve", "u", "--t", "[0 1; 2 3]"],
            false,
            "got a 2×2 matrix",
        ),
        (vec!["curve", "u", "--t", "1:0"], false, "has no values"),
        (
            vec!["curve", "u", "--t", "0:1e-9:1"],
            false,
            "more than the limit",
        ),
        (
            vec!["curve", "u", "--t", "0.5", "--n", "3"],
            false,
            "cannot be used together",
        ),
        (
            vec!["curve", "u", "--format", "xml"],
            false,
            "invalid value 'xml'",
        ),
        (
            vec!["curve", "u", "--script", "tests/data/nope.m"],
            false,
            "no such file",
        ),
        (
            vec!["curve", "[u; u]", "--plot", "out.gif"],
            false,
            "unknown picture format",
        ),
        (
            vec!["curve", "[u; u; u; u]"],
            false,
            "expected curves and surfaces of 2-D or 3-D points",
        ),
        (vec!["curve", "[u; u]", "--bogus"], false, "unknown option"),
        (
            vec!["surface", "[u; v; u]", "--u", "0.5"],
            true,
            "grid has shape (1, 11, 3)",
        ),
        (
            vec!["surface", "[u; v; u]", "--n", "0"],
            true,
            "N = 0 is too small",
        ),
        (vec!["surface", "[u; v; t]"], true, "unknown variable `t`"),
        (
            vec!["surface", "[u; v; u]", "--mesh", "x.vtk"],
            false,
            "unknown mesh format",
        ),
        (
            vec!["surface", "[u; v; u]", "--n", "3000"],
            true,
            "more than the limit",
        ),
        (
            vec!["script", "tests/data/nope.m"],
            false,
            "no such file or directory",
        ),
        (vec!["script", "-"], false, "found `;`"),
        (vec!["frobnicate"], false, "unknown subcommand"),
        (vec![], false, "no subcommand given"),
    ];
    check_all(cases, |(args, surface, message)| {
        let mut cmd = cagd();
        cmd.args(args);
        let takes_outputs = !args.is_empty() && args[0] != "frobnicate" && args[0] != "script";
        if takes_outputs && !args.contains(&"--plot") && !args.contains(&"--mesh") {
            cmd.args(outputs(d, *surface));
        }
        if args.first() == Some(&"script") && args.get(1) == Some(&"-") {
            cmd.write_stdin("x = ;");
        }
        mentions(&refused(&mut cmd, Some(d))?, message)
    });
    // An output in a missing folder: one line, and none of the other outputs is written.
    let line = fails(&[
        "surface",
        "[u; v; u]",
        "--n",
        "3",
        "--mesh",
        d.join("ok.stl").to_str().unwrap(),
        "--plot",
        missing,
    ]);
    assert!(line.contains("does not exist"), "{line}");
    assert!(common::bad_input::files_in(d).is_empty());
}

#[test]
fn a_failed_command_keeps_the_previous_output_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("result.txt");
    std::fs::write(&out, "previous\n").unwrap();
    fails(&["curve", "[1 2; 3]", "-o", out.to_str().unwrap()]);
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "previous\n");
    ok(&["curve", "[u; 1]", "--n", "2", "-o", out.to_str().unwrap()]);
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "u =\n\n    0  1\n\nresult =\n\n    0  1\n    1  1\n\n"
    );
}

#[test]
fn error_lines_read_well() {
    insta::assert_snapshot!([
        fails(&["curve", "[1 2; 3]"]),
        fails(&["curve", "[u; w]"]),
        fails(&["curve", "u", "--n", "1"]),
        fails(&["curve", "u", "--format", "xml"]),
        fails(&["script", "tests/data/nope.m"]),
        fails(&[
            "curve",
            "u",
            "--script",
            "tests/data/appendix_c.m",
            "--exact",
            "--t",
            "[1 2"
        ]),
    ]
    .join("\n"));
}

// ---------------------------------------------------------------------------------------
// The library behind the binary: matrix arguments

mod matrix_arguments {
    use cagd_cli::{load_matrix, ErrorKind};
    use cagd_octave::literal::{Env, LiteralError};
    use nalgebra::DMatrix;
    use num_rational::BigRational;

    fn data(file: &str) -> String {
        format!("{}/tests/data/{file}", cagd_test_support::WORKSPACE)
    }

    fn b() -> DMatrix<f64> {
        DMatrix::from_row_slice(4, 3, &[0., 0., 0., 0., 2., 2., 8., 2., 0., 4., 0., 0.1])
    }

    #[test]
    fn literal_and_octave_written_text_files_agree() {
        let literal = load_matrix::<f64>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            "[0 0 0; 0 2 2; 8 2 0; 4 0 0.1]",
            None,
        );
        assert_eq!(literal.unwrap(), b());
        for file in ["octave_save_ascii.txt", "octave_dlmwrite.csv"] {
            let m = load_matrix::<f64>(
                &cagd_cli::Cx::new(cagd::Limits::default()),
                "--control",
                &data(file),
                None,
            )
            .unwrap();
            assert_eq!(m, b(), "{file}");
        }
        // Exact: 1.00000000e-01 is exactly 1/10.
        let m = load_matrix::<BigRational>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            &data("octave_save_ascii.txt"),
            None,
        )
        .unwrap();
        assert_eq!(m[(3, 2)], BigRational::new(1.into(), 10.into()));
    }

    #[test]
    fn octave_text_format_is_read() {
        // The first numeric variable, or the one named after a colon.
        let file = data("octave_save_text.txt");
        assert_eq!(
            load_matrix::<f64>(
                &cagd_cli::Cx::new(cagd::Limits::default()),
                "--control",
                &file,
                None
            )
            .unwrap(),
            b()
        );
        let named = load_matrix::<f64>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            &format!("{file}:B"),
            None,
        )
        .unwrap();
        assert_eq!(named, b());
        // Exact: Octave's 0.10000000000000001 is read as the decimal it stands for, 1/10.
        let m = load_matrix::<BigRational>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            &file,
            None,
        )
        .unwrap();
        assert_eq!(m[(3, 2)], BigRational::new(1.into(), 10.into()));
        let e = load_matrix::<f64>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            &format!("{file}:C"),
            None,
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::Data);
        assert!(
            e.to_string().contains("one of the numeric variables B"),
            "{e}"
        );
    }

    #[test]
    fn missing_files_and_bad_files() {
        let e = load_matrix::<f64>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            "no/such/points.csv",
            None,
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io(std::io::ErrorKind::NotFound));
        assert_eq!(
            e.to_string(),
            "--control no/such/points.csv: no such file or directory; expected an Octave matrix literal such as \"[0 0 0; 1 2 0]'\", a numeric text or CSV file, or - for standard input"
        );
        let dir = tempfile::tempdir().unwrap();
        let ragged = dir.path().join("ragged.txt");
        std::fs::write(&ragged, "1 2 3\n# comment\n4 5\n").unwrap();
        let e = load_matrix::<f64>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            ragged.to_str().unwrap(),
            None,
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::Data);
        assert!(e
            .problem
            .starts_with("line 3: the row has 2 value(s), the first row 3"));
        let nan = dir.path().join("nan.csv");
        std::fs::write(&nan, "1,NaN\n").unwrap();
        let e = load_matrix::<f64>(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            nan.to_str().unwrap(),
            None,
        )
        .unwrap_err();
        assert!(e
            .problem
            .contains("value 2 (`NaN`) is not a finite decimal number"));
    }

    #[test]
    fn literals_may_use_script_variables() {
        let script = cagd_octave::script::run::<f64>(
            "P1 = [0;0;0]; P2 = [1;0;0]; c1 = [u;0;u-u^2];",
            Env::new(),
        )
        .unwrap();
        let m = load_matrix(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            "[P1 P2]",
            Some(&script),
        )
        .unwrap();
        assert_eq!(m.shape(), (3, 2));
        let e = load_matrix(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            "[P1 c1]",
            Some(&script),
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::Shape);
        let e = load_matrix(
            &cagd_cli::Cx::new(cagd::Limits::default()),
            "--control",
            "[P1 P9]",
            Some(&script),
        )
        .unwrap_err();
        assert!(matches!(
            e.kind,
            ErrorKind::Literal(ref l) if matches!(**l, LiteralError::UnknownVariable { .. })
        ));
    }
}

// ---------------------------------------------------------------------------------------
// The subcommands of the thesis and the course, on the thesis data

use common::thesis_args::{
    with, FLAT_SQUARE, FLAT_SQUARE_CROSS, GORDON_D, NET_3X3, PRIMER_2_4, PRIMER_4_3,
};

#[test]
fn decasteljau_primer_2_4_exact_scheme() {
    let out = ok(&[
        "decasteljau",
        PRIMER_2_4,
        "--t",
        "0.5",
        "--steps",
        "--exact",
    ]);
    assert!(out.contains("(7/2, 3/2, 3/4)"), "{out}");
    assert!(
        out.contains("result =\n\n    7/2\n    3/2\n    3/4\n"),
        "{out}"
    );
    insta::assert_snapshot!(out);
}

#[test]
fn decasteljau_rows_and_curve() {
    insta::assert_snapshot!(ok(&[
        "decasteljau",
        "[0 0 0; 0 2 2; 8 2 0; 4 0 0]",
        "--rows",
        "--n",
        "5"
    ]));
}

#[test]
fn bezier_patch_scheme_and_grid() {
    insta::assert_snapshot!(
        "bezier_patch_point",
        ok(&[
            "bezier-patch",
            NET_3X3,
            "--u",
            "0.5",
            "--v",
            "0.5",
            "--steps",
            "--exact"
        ])
    );
    insta::assert_snapshot!(
        "bezier_patch_grid",
        ok(&["bezier-patch", NET_3X3, "--n", "3"])
    );
}

#[test]
fn coons_primer_4_3_exact() {
    let out = ok(&with(
        &["coons"],
        &with(
            &PRIMER_4_3,
            &["--u", "0.2", "--v", "0.5", "--steps", "--exact"],
        ),
    ));
    assert!(
        out.contains("result =\n\n      1/5\n     3/10\n    19/50\n"),
        "{out}"
    );
    insta::assert_snapshot!(out);
}

#[test]
fn coons_appendix_c_script_grid() {
    insta::assert_snapshot!(ok(&[
        "coons",
        "--script",
        "tests/data/appendix_c.m",
        "--format",
        "csv"
    ]));
}

#[test]
fn coons_point_script_and_bezier_boundaries() {
    // Algorithm 6's data script: the same point as Primer 4.3.
    let out = ok(&[
        "coons",
        "--script",
        "tests/data/appendix_c_point.m",
        "--u",
        "0.2",
        "--v",
        "0.5",
        "--exact",
    ]);
    assert!(
        out.ends_with("result =\n\n      1/5\n     3/10\n    19/50\n\n"),
        "{out}"
    );
    // Bézier boundaries of the bilinear patch: the Coons patch is that patch.
    let out = ok(&[
        "coons",
        "--c1",
        "[0 0 0; 1 0 0]'",
        "--c2",
        "[0 1 0; 1 1 1]'",
        "--d1",
        "[0 0 0; 0 1 0]'",
        "--d2",
        "[1 0 0; 1 1 1]'",
        "--u",
        "0.5",
        "--v",
        "0.5",
        "--exact",
    ]);
    assert!(
        out.ends_with("result =\n\n    1/2\n    1/2\n    1/4\n\n"),
        "{out}"
    );
}

#[test]
fn coons_expression_boundaries_keep_their_domain_beyond_the_unit_square() {
    // Primer 4.3's expressions at u = 3/2: the samples reach 3/2, but the expressions' domain
    // stays [0, 1] (a sampled expression is not reparametrised onto its sample range). From the
    // closed forms: r_c = (3/2, 1/2, 3/8), r_d = (3/2, 5/8, 5/8), r_cd = (3/2, 1/2, 3/4).
    let out = ok(&[
        "coons",
        "--script",
        "tests/data/appendix_c_point.m",
        "--u",
        "1.5",
        "--v",
        "0.5",
        "--exact",
    ]);
    assert!(
        out.ends_with("result =\n\n    3/2\n    5/8\n    1/4\n\n"),
        "{out}"
    );
}

#[test]
fn coons_bicubic_flat_square() {
    let args = [&["coons-bicubic"][..], &FLAT_SQUARE, &FLAT_SQUARE_CROSS].concat();
    insta::assert_snapshot!(ok(&with(&args, &["--n", "3", "--exact"])));
}

#[test]
fn discrete_coons_and_mask() {
    let net = "[0 0 0 0 1 0 0 2 0; 1 0 0 0 0 0 1 2 1; 2 0 0 2 1 1 2 2 0]";
    insta::assert_snapshot!("discrete_coons", ok(&["discrete-coons", net, "--exact"]));
    let out = ok(&["discrete-coons", net, "--mask=0,0.25", "--format", "csv"]);
    assert!(out.contains("2,2,1,1,0.5\n"), "{out}");
}

#[test]
fn gordon_appendix_d_network_exact() {
    let out = ok(&with(
        &["gordon"],
        &with(
            &GORDON_D,
            &["--u", "0.25", "--v", "0.75", "--steps", "--exact"],
        ),
    ));
    assert!(
        out.contains("result =\n\n      1/4\n      3/4\n    15/16\n"),
        "{out}"
    );
    insta::assert_snapshot!(out);
}

#[test]
fn gordon_appendix_d_script() {
    insta::assert_snapshot!(ok(&[
        "gordon",
        "--script",
        "tests/data/appendix_d_odd.m",
        "--u",
        "[0 0.5 1]",
        "--v",
        "[0 0.25]",
        "--steps"
    ]));
}

#[test]
fn lagrange_bernstein_derivative() {
    insta::assert_snapshot!(
        "lagrange_basis",
        ok(&[
            "lagrange",
            "--nodes",
            "[0 0.5 1]",
            "--t",
            "[0.25 2]",
            "--exact"
        ])
    );
    // The lecture notes: the polynomial through (1,1),(2,2),(3,3),(4,2),(5,1).
    insta::assert_snapshot!(
        "lagrange_points",
        ok(&[
            "lagrange",
            "--nodes",
            "1:5",
            "--points",
            "[1 2 3 2 1]",
            "--t",
            "1:0.5:5",
            "--exact"
        ])
    );
    insta::assert_snapshot!(
        "bernstein",
        ok(&["bernstein", "--degree", "3", "--t", "[0 0.5 1]", "--exact"])
    );
    insta::assert_snapshot!(
        "derivative",
        ok(&["derivative", PRIMER_2_4, "-r", "1", "--t", "0.5", "--exact"])
    );
}

#[test]
fn course_subcommands() {
    let out = ok(&[
        "spline",
        "[0 0; 2 1; 4 4; 6 0]'",
        "--end",
        "clamped",
        "--start-tangent",
        "[1;1]",
        "--end-tangent",
        "[-1;1]",
        "--t",
        "[0 1.5 3]",
        "--exact",
    ]);
    // The lecture notes: x-tangents 1, 31/15, 41/15, -1; y-tangents 1, 48/15, -27/15, 1.
    assert!(
        out.contains("1  31/15  41/15  -1\n    1   16/5   -9/5   1\n"),
        "{out}"
    );
    insta::assert_snapshot!("spline_004", out);
    insta::assert_snapshot!(
        "hermite",
        ok(&[
            "hermite", "--p0", "[0;0]", "--p1", "[1;0]", "--t0", "[1;1]", "--t1", "[1;-1]", "--t",
            "0.5", "--steps", "--exact"
        ])
    );
    insta::assert_snapshot!(
        "bspline",
        ok(&[
            "bspline",
            "[0 0; 1 2; 3 2; 4 0]'",
            "--degree",
            "2",
            "--knots",
            "[0 0 0 0.5 1 1 1]",
            "--t",
            "[0.25 0.5]",
            "--steps",
            "--exact"
        ])
    );
    let out = ok(&[
        "nurbs",
        "[1 0; 1 1; 0 1]'",
        "--weights",
        "[1 0.7071067811865476 1]",
        "--degree",
        "2",
        "--n",
        "5",
        "--format",
        "json",
    ]);
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    for k in 0..5 {
        let (x, y) = (
            json["result"][0][k].as_f64().unwrap(),
            json["result"][1][k].as_f64().unwrap(),
        );
        assert!((x.hypot(y) - 1.0).abs() < 1e-12, "point {k} off the circle");
    }
}

#[test]
fn subcommand_help_documents_layout_and_example() {
    let all = cagd_cli::subcommands();
    assert!(all.len() >= 31, "{all:?}");
    for sub in all.iter().map(String::as_str) {
        let out = ok(&[sub, "--help"]);
        assert!(out.contains("Example"), "{sub} --help has no example");
        assert!(out.contains("cagd "), "{sub} --help");
        // Those that read data describe its layout; these read none (or only a script).
        if !matches!(sub, "thesis" | "course" | "script" | "serve") {
            assert!(
                out.contains("Layout"),
                "{sub} --help says nothing of the layout"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// The main job: `cagd thesis`

/// `cagd thesis --out DIR`, run once for the tests that read what it writes (the one below
/// and [`super::slips::the_thesis_picture_of_primer_2_4_marks_b_one_half_where_it_is`]): its
/// standard output and `DIR`, a fresh folder in cargo's folder for the tests' files.
pub(super) fn thesis_out() -> &'static (String, PathBuf) {
    static OUT: std::sync::OnceLock<(String, PathBuf)> = std::sync::OnceLock::new();
    OUT.get_or_init(|| {
        let out_dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli-thesis-pictures");
        match std::fs::remove_dir_all(&out_dir) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => panic!("{out_dir:?}: {e}"),
            _ => {}
        }
        let out = ok(&["thesis", "--out", out_dir.to_str().unwrap()]);
        (out, out_dir)
    })
}

#[test]
fn thesis_prints_every_example_and_writes_valid_files() {
    let (out, out_dir) = thesis_out();
    for expected in [
        "(4, 0, 0)   (6, 1, 0)   (5, 3/2, 1/2)   (7/2, 3/2, 3/4)",
        "b(1/2) =\n\n    7/2\n    3/2\n    3/4\n",
        "Primer 3.2's control net is garbled",
        "rcd =\n\n     1/5\n     1/2\n    1/10\n",
        "x = rc + rd - rcd =\n\n      1/5\n     3/10\n    19/50\n",
        "the last line sets P4",
        "g = g1 + g2 - g12 =\n\n      1/4\n      3/4\n    15/16\n",
        "conditioning: Lebesgue constants",
    ] {
        assert!(out.contains(expected), "missing {expected:?}");
    }
    // Every picture parses (SVG as XML, PNG decodes to its full size).
    let pictures = [
        "primer_2_4",
        "patch_example",
        "primer_4_3",
        "appendix_c",
        "appendix_d",
    ];
    for name in pictures {
        let svg = std::fs::read_to_string(out_dir.join(format!("{name}.svg"))).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        assert_eq!(doc.root_element().tag_name().name(), "svg");
        assert!(
            doc.descendants().count() > 100,
            "{name}.svg is nearly empty"
        );
        let decoder = png::Decoder::new(std::io::BufReader::new(
            std::fs::File::open(out_dir.join(format!("{name}.png"))).unwrap(),
        ));
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let frame = reader.next_frame(&mut buf).unwrap();
        assert_eq!((frame.width, frame.height), (900, 700), "{name}.png");
        // Not a blank image: many distinct colours.
        let distinct: std::collections::HashSet<&[u8]> =
            buf[..frame.buffer_size()].chunks(3).collect();
        assert!(distinct.len() > 50, "{name}.png looks blank");
    }
    // Meshes parse with real readers: grids of N × N vertices, 2 (N−1)² triangles.
    for (name, n) in [
        ("patch_example", 21usize),
        ("primer_4_3", 21),
        ("appendix_c", 10),
        ("appendix_d", 21),
    ] {
        let faces = 2 * (n - 1) * (n - 1);
        let stl = stl_io::read_stl(
            &mut std::fs::File::open(out_dir.join(format!("{name}.stl"))).unwrap(),
        )
        .unwrap();
        assert_eq!(
            (stl.vertices.len(), stl.faces.len()),
            (n * n, faces),
            "{name}.stl"
        );
        let (models, _) = tobj::load_obj(
            out_dir.join(format!("{name}.obj")),
            &tobj::LoadOptions {
                triangulate: true,
                ..Default::default()
            },
        )
        .unwrap();
        let mesh = &models[0].mesh;
        assert_eq!(mesh.positions.len(), 3 * n * n, "{name}.obj");
        assert_eq!(mesh.indices.len(), 3 * faces, "{name}.obj");
        let parser = ply_rs_bw::parser::Parser::<ply_rs_bw::ply::DefaultElement>::new();
        let ply = parser
            .read_ply(&mut std::fs::File::open(out_dir.join(format!("{name}.ply"))).unwrap())
            .unwrap();
        assert_eq!(ply.payload["vertex"].len(), n * n, "{name}.ply");
        assert_eq!(ply.payload["face"].len(), faces, "{name}.ply");
    }
    // Only the listed files, no temporary leftovers.
    assert_eq!(std::fs::read_dir(out_dir).unwrap().count(), 5 * 2 + 4 * 3);
}

#[test]
fn thesis_into_an_unwritable_place_fails_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let blocker = dir.path().join("file");
    std::fs::write(&blocker, "x").unwrap();
    let line = fails(&["thesis", "--out", blocker.join("sub").to_str().unwrap()]);
    assert!(line.starts_with("cagd: error: --out "), "{line}");
}

// ---------------------------------------------------------------------------------------
// Octave text format: output that live Octave loads, and input Octave wrote

/// Whether Octave can be used; without it the test is skipped locally but fails under CI.
fn octave_available() -> bool {
    let found = std::process::Command::new("octave")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI is set but GNU Octave is not installed"
        );
        eprintln!("SKIPPED: GNU Octave is not installed (set CI to make this a failure)");
    }
    found
}

#[test]
fn format_octave_loads_in_live_octave() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    ok(&with(
        &["coons"],
        &with(
            &PRIMER_4_3,
            &[
                "--u",
                "0.2",
                "--v",
                "0.5",
                "--steps",
                "--format",
                "octave",
                "-o",
                &p("coons.txt"),
            ],
        ),
    ));
    ok(&[
        "decasteljau",
        PRIMER_2_4,
        "--n",
        "3",
        "--steps",
        "--format",
        "octave",
        "-o",
        &p("curve.txt"),
    ]);
    ok(&[
        "bezier-patch",
        NET_3X3,
        "--n",
        "3",
        "--format",
        "octave",
        "-o",
        &p("patch.txt"),
    ]);
    // Our own reader reads what we wrote (also without Octave).
    let m = cagd_cli::load_matrix::<f64>(
        &cagd_cli::Cx::new(cagd::Limits::default()),
        "x",
        &format!("{}:result", p("curve.txt")),
        None,
    )
    .unwrap();
    assert_eq!(m.shape(), (3, 3));
    assert_eq!(m.column(1).as_slice(), &[3.5, 1.5, 0.75]);
    if !octave_available() {
        return;
    }
    let script = format!(
        "c = load('{}'); d = load('{}'); s = load('{}');\n\
         assert(c.result, [0.2; 0.3; 0.38], 1e-15);\n\
         assert(c.rc, [0.2; 0.5; 0.18], 1e-15);\n\
         assert(c.rd, [0.2; 0.3; 0.3], 1e-15);\n\
         assert(c.rcd, [0.2; 0.5; 0.1], 1e-15);\n\
         assert(d.result, [0 3.5 4; 0 1.5 0; 0 0.75 0]);\n\
         assert(d.t, [0 0.5 1]);\n\
         assert(isstruct(d.scheme_2) && isequal(fieldnames(d.scheme_2), {{'r0'; 'r1'; 'r2'; 'r3'}}));\n\
         assert(d.scheme_2.r0, [0 0 8 4; 0 2 2 0; 0 2 0 0]);\n\
         assert(d.scheme_2.r1, [0 4 6; 1 2 1; 1 1 0]);\n\
         assert(d.scheme_2.r3, [3.5; 1.5; 0.75]);\n\
         assert(size(s.result), [3 3 3]);\n\
         assert(squeeze(s.result(2,2,:)), [2; 2; 1.5]);\n\
         assert(s.result(:,:,1), [0 0 0; 2 2 2; 4 4 4]);\n\
         printf('loaded\\n');\n",
        p("coons.txt"),
        p("curve.txt"),
        p("patch.txt")
    );
    let out = std::process::Command::new("octave")
        .args([
            "--no-gui",
            "--quiet",
            "--no-window-system",
            "--eval",
            &script,
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success() && String::from_utf8_lossy(&out.stdout).contains("loaded"),
        "Octave: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn octave_array_file_as_a_bezier_net() {
    // An (m+1)×(n+1)×3 array written in Octave's text format is a net like the packed one.
    let dir = tempfile::tempdir().unwrap();
    let net = dir.path().join("net.txt");
    ok(&[
        "discrete-coons",
        NET_3X3,
        "--format",
        "octave",
        "-o",
        net.to_str().unwrap(),
    ]);
    let from_file = ok(&[
        "bezier-patch",
        &format!("{}:result", net.display()),
        "--u",
        "0.5",
        "--v",
        "0.5",
    ]);
    let from_literal = ok(&[
        "bezier-patch",
        "[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 2 2 4 1; 4 0 0 4 2 1 4 4 0]",
        "--u",
        "0.5",
        "--v",
        "0.5",
    ]);
    assert_eq!(from_file, from_literal);
}

#[test]
fn new_subcommands_reject_bad_input_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let o = |name: &str| d.join(name).to_str().unwrap().to_string();
    let (svg, stl, txt) = (o("x.svg"), o("x.stl"), o("x.txt"));
    // A packed network whose crossings g_uv have one row instead of one per node (in a
    // directory of its own: `d` must stay empty).
    let scripts = tempfile::tempdir().unwrap();
    let bad_network = scripts.path().join("bad_network.m");
    let bad_network = bad_network.to_str().unwrap().to_string();
    std::fs::write(
        &bad_network,
        "x = [0 1];\ng_u = [0 1 0 1; 0 0 1 1; 0 1 1 2];\ng_v = [0 0 1 1; 0 1 0 1; 0 1 1 2];\ng_uv = [0 0 0 0 1 1];\n",
    )
    .unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["decasteljau", "[1 2; 3]", "--plot", &svg], "CONTROL: "),
        (
            vec!["decasteljau", "nope/points.csv", "-o", &txt],
            "no such file",
        ),
        (
            vec!["decasteljau", PRIMER_2_4, "--n", "1", "--plot", &svg],
            "N = 1 is too small",
        ),
        (
            vec!["bezier-patch", "[1 2 3 4]", "--mesh", &stl],
            "the net is 1×4",
        ),
        (
            vec!["bezier-patch", NET_3X3, "--n", "1", "--mesh", &stl],
            "--n: N = 1",
        ),
        (
            vec![
                "coons", "--c1", "[u;0;w]", "--c2", "[u;1;u]", "--d1", "[0;v;0]", "--d2",
                "[1;v;v]", "--plot", &svg,
            ],
            "unknown variable `w`",
        ),
        (
            with(&["coons", "--n", "1", "--mesh", &stl], &PRIMER_4_3),
            "N = 1 is too small",
        ),
        (
            vec![
                "coons",
                "--c1",
                "[u;0;u-u^2]",
                "--c2",
                "[u;1;u]",
                "--d1",
                "[0;v;v]",
                "--d2",
                "[1;v;v]",
                "-o",
                &txt,
            ],
            "do not meet at the corners",
        ),
        (vec!["coons", "--c1", "[u;0;u-u^2]"], "--c2: missing"),
        (
            vec![
                "coons", "--c1", "[u;v;0]", "--c2", "[u;1;u]", "--d1", "[0;v;0]", "--d2", "[1;v;v]",
            ],
            "uses the parameters u and v",
        ),
        (
            vec![
                "coons-bicubic",
                "--c1",
                "[u;0;0]",
                "--c2",
                "[u;1;0]",
                "--d1",
                "[0;v;0]",
                "--d2",
                "[1;v;0]",
                "--n",
                "3",
            ],
            "--d1u: missing",
        ),
        (
            vec!["discrete-coons", NET_3X3, "--mask=1,1", "-o", &txt],
            "--mask",
        ),
        (
            vec![
                "gordon",
                "--u-curve",
                "[0;v;v]",
                "--v-curve",
                "[u;0;u]",
                "--plot",
                &svg,
            ],
            "at least 2 curves",
        ),
        (
            vec!["gordon", "--script", &bad_network, "-o", &txt],
            "--script: `g_uv` is 1×6 for 2 × 2 nodes",
        ),
        (
            vec!["lagrange", "--nodes", "[0 0 1]", "-o", &txt],
            "--nodes",
        ),
        (
            vec!["bernstein", "--degree", "3", "--i", "4"],
            "--i: i = 4 exceeds the degree 3",
        ),
        (vec!["derivative", PRIMER_2_4, "-r", "4", "-o", &txt], "-r"),
        (
            vec!["spline", "[0 0; 1 1]'", "--end", "clamped"],
            "--start-tangent: missing",
        ),
        (vec!["spline", "[0; 0]", "--plot", &svg], "POINTS"),
        (
            vec![
                "hermite", "--p0", "[0;0]", "--p1", "[1;0;0]", "--t0", "[1;1]", "--t1", "[1;1]",
            ],
            "--p0/--p1/--t0/--t1",
        ),
        (
            vec!["bspline", "[0 0; 1 1]'", "--degree", "3", "--plot", &svg],
            "CONTROL: control points: degree 3 needs at least 4 control point(s), got 2",
        ),
        (
            vec![
                "bspline",
                "[0 0; 1 1; 2 0]'",
                "--degree",
                "2",
                "--knots",
                "[0 0 0 1 0.5 1]",
            ],
            "--knots",
        ),
        (
            vec![
                "nurbs",
                "[1 0; 1 1; 0 1]'",
                "--weights",
                "[1 0 1]",
                "-o",
                &txt,
            ],
            "weight",
        ),
    ];
    check_all(cases, |(args, message)| {
        mentions(&refused(cagd().args(args), Some(d))?, message)
    });
}

//! Resource limits on the command line: defaults, environment variables, flags (the flag
//! wins), each refusal a one-line error with exit code 2 that names the setting.

use assert_cmd::Command;

use cagd_test_support as common;

use common::thesis_args::{with, FLAT_SQUARE, FLAT_SQUARE_CROSS, GORDON_D, PRIMER_4_3};

fn cagd() -> Command {
    let mut c = Command::cargo_bin("cagd").unwrap();
    for (_, var, _) in cagd_cli::limits::SETTINGS {
        c.env_remove(var);
    }
    c
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Runs `cmd`, which must succeed; returns its standard output.
fn succeeds(cmd: &mut Command) -> String {
    let out = cmd.output().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn environment_and_flags_set_the_limits() {
    let surface = ["surface", "[u; v; u.*v]", "--n", "4"];
    // Default: 16 points are fine.
    assert!(cagd().args(surface).output().unwrap().status.success());
    // The environment lowers the limit.
    let out = cagd()
        .env("CAGD_MAX_GRID_POINTS", "10")
        .args(surface)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let e = stderr(&out);
    assert_eq!(e.lines().count(), 1);
    assert!(
        e.contains("16 exceeds the limit of 10")
            && e.contains("--max-grid-points")
            && e.contains("CAGD_MAX_GRID_POINTS"),
        "{e}"
    );
    // The flag wins over the environment, before or after the subcommand.
    succeeds(
        cagd()
            .env("CAGD_MAX_GRID_POINTS", "10")
            .args(surface)
            .args(["--max-grid-points", "16"]),
    );
    let out = cagd()
        .args(["--max-degree", "2", "decasteljau", "[0 1 2 3]"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("degree: 3 exceeds the limit of 2"));
    // A malformed variable is an error naming it.
    let out = cagd()
        .env("CAGD_MAX_DEPTH", "deep")
        .args(surface)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("CAGD_MAX_DEPTH"), "{}", stderr(&out));
}

#[test]
fn parser_limits_follow_the_settings() {
    let deep = format!("[u; {}u{}]", "(".repeat(10), ")".repeat(10));
    assert!(cagd()
        .args(["curve", &deep, "--n", "2"])
        .output()
        .unwrap()
        .status
        .success());
    let out = cagd()
        .args(["curve", &deep, "--n", "2", "--max-depth", "5"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("nested more than 5 levels"),
        "{}",
        stderr(&out)
    );
    let out = cagd()
        .env("CAGD_MAX_ELEMENTS", "100")
        .args(["decasteljau", "[0 1]", "--t", "0:0.001:1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("limit of 100"), "{}", stderr(&out));
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.txt");
    std::fs::write(&big, "0 1\n".repeat(1000)).unwrap();
    let out = cagd()
        .args([
            "decasteljau",
            big.to_str().unwrap(),
            "--max-input-bytes",
            "1000",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("larger than 1000 bytes"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_mask_system_is_refused_before_it_is_allocated() {
    let net = format!(
        "[{}]",
        (0..60)
            .map(|i| (0..60 * 3)
                .map(|j| ((i + j) % 7).to_string())
                .collect::<Vec<_>>()
                .join(" "))
            .collect::<Vec<_>>()
            .join("; ")
    );
    let out = cagd()
        .args([
            "discrete-coons",
            &net,
            "--mask=0,0.25",
            "--max-system-entries",
            "1000",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("--max-system-entries"),
        "{}",
        stderr(&out)
    );
}

/// `u+u+…+u` with `terms` terms: an expression of `terms + 1` nodes (the sum and its
/// operands).
fn long_sum(terms: usize) -> String {
    vec!["u"; terms].join("+")
}

/// Runs `cmd` and checks that it is refused up front by the work estimate of the expressions
/// it would sample, naming `argument`; returns the error line.
fn refused_by_work(cmd: &mut Command, argument: &str) -> String {
    let start = std::time::Instant::now();
    let out = cmd.output().unwrap();
    let elapsed = start.elapsed();
    let e = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{e}");
    assert!(out.stdout.is_empty());
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(
        e.starts_with(&format!(
            "cagd: error: {argument}: estimated operations (samples × expression nodes): "
        )) && e.contains("(raise it with --max-work or CAGD_MAX_WORK)"),
        "{e}"
    );
    // Sampling would take hours; the refusal comes before it.
    assert!(elapsed.as_secs() < 20, "took {elapsed:?}");
    e
}

#[test]
fn large_expressions_at_many_samples_are_refused_before_sampling() {
    // 50 001 nodes in the third coordinate (about 100 KB of text).
    let big = long_sum(50_000);
    let curve = format!("[u; 0; {big}]");
    let e = refused_by_work(cagd().args(["curve", &curve, "--n", "1000000"]), "EXPR");
    // 10⁶ samples × (the matrix, its three elements, the sum's 50 000 operands).
    assert!(
        e.contains("50004000000 exceeds the limit of 2000000000"),
        "{e}"
    );
    let surface = format!("[u; v; {big}]");
    let e = refused_by_work(cagd().args(["surface", &surface, "--n", "1000"]), "EXPR");
    assert!(e.contains("50004000000 exceeds"), "{e}");
    // Boundary and network curves: the argument with the largest share is named.
    let many_u = ["--u", "0:2e-6:1", "--v", "0.5"];
    let mut coons = with(&["coons"], &PRIMER_4_3);
    coons[2] = &curve;
    refused_by_work(cagd().args(coons).args(many_u), "--c1");
    let mut bicubic = [&["coons-bicubic"][..], &FLAT_SQUARE, &FLAT_SQUARE_CROSS].concat();
    bicubic[10] = &curve;
    refused_by_work(cagd().args(bicubic).args(many_u), "--c1v");
    let mut gordon = with(&["gordon"], &GORDON_D);
    gordon[4] = &curve;
    refused_by_work(cagd().args(gordon).args(many_u), "--v-curve");
    // A curve of a data script counts with everything it is computed from.
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("big.m");
    std::fs::write(
        &script,
        format!("w = {};\nc1 = [u; 0; w];\n", long_sum(400_000)),
    )
    .unwrap();
    let script = script.to_str().unwrap();
    let e = refused_by_work(
        cagd().args(["curve", "c1", "--script", script, "--n", "1000000"]),
        "EXPR",
    );
    assert!(e.contains("exceeds the limit of 2000000000"), "{e}");
}

#[test]
fn a_higher_max_work_lets_the_same_command_run() {
    let curve = format!("[u; 0; {}]", long_sum(1000));
    let args = ["curve", curve.as_str(), "--n", "2000", "--format", "csv"];
    // 2000 samples × 1004 nodes, refused by a lower flag or environment variable.
    let e = refused_by_work(cagd().args(args).args(["--max-work", "2000000"]), "EXPR");
    assert!(e.contains(": 2008000 exceeds the limit of 2000000 "), "{e}");
    refused_by_work(cagd().env("CAGD_MAX_WORK", "2007999").args(args), "EXPR");
    // Past the node count, one evaluation is measured: 2005 element results (1000 loads of
    // u, 999 sums, the matrix and its elements) at each of the 2000 samples.
    let measured = |limit: &str| {
        let out = cagd()
            .args(args)
            .args(["--max-work", limit])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        stderr(&out)
    };
    let e = measured("2008000");
    assert!(
        e.starts_with("cagd: error: EXPR: estimated operations (samples × work of one sample): 4010000 exceeds the limit of 2008000 "),
        "{e}"
    );
    let text = succeeds(
        cagd()
            .env("CAGD_MAX_WORK", "2000000")
            .args(args)
            .args(["--max-work", "4010000"]),
    );
    // The last point is (1, 0, 1000): a thousand times u = 1.
    let last: Vec<f64> = text
        .lines()
        .filter_map(|l| l.rsplit(',').next()?.trim().parse().ok())
        .collect();
    assert_eq!(last[last.len() - 3..], [1.0, 0.0, 1000.0], "{text}");
}

#[test]
fn typical_thesis_commands_stay_far_below_the_work_limit() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("thesis");
    let coons = with(&["coons"], &PRIMER_4_3);
    let gordon = with(&["gordon"], &GORDON_D);
    let commands: Vec<Vec<&str>> = vec![
        vec!["thesis", "--out", out_dir.to_str().unwrap()],
        with(&coons, &["--u", "0.2", "--v", "0.5", "--exact"]),
        with(&coons, &["--n", "100"]),
        vec!["coons", "--script", "tests/data/appendix_c.m", "--n", "10"],
        with(&gordon, &["--n", "100", "--steps"]),
        vec!["gordon", "--script", "tests/data/appendix_d_odd.m"],
        vec!["curve", "[u; 0.5; 0.5+u-u^2]", "--n", "1000"],
        vec!["surface", "[u; v; u-u^2+v]", "--n", "100"],
    ];
    for args in &commands {
        // With a limit five hundred times lower than the default (2·10⁹): far below it.
        let mut c = cagd();
        c.current_dir(common::WORKSPACE)
            .args(args)
            .args(["--max-work", "4000000"]);
        assert!(!succeeds(&mut c).is_empty(), "{args:?}");
    }
}

/// Random digits `0..=9` as a 1×n row literal (a fixed sequence).
fn digits(n: usize) -> String {
    let mut lcg = common::lcg::Lcg(7);
    let values: Vec<String> = (0..n).map(|_| lcg.below(10).to_string()).collect();
    format!("[{}]", values.join(" "))
}

/// Exact arithmetic is weighed by the size its numbers reach (`cagd::limits::exact_op_cost`):
/// each of these commands runs in about 2–10 s in a release build with `--exact` (measured by
/// bench/exact_work.sh), and is refused up front at the default limits, naming its
/// argument; the same command in doubles, where shown, still runs. Curves here, surfaces in
/// [`exact_surface_work_is_weighed_by_the_size_of_the_numbers`].
#[test]
fn exact_curve_work_is_weighed_by_the_size_of_the_numbers() {
    let row60 = digits(60);
    let row1000 = digits(1000);
    let weights: String = format!(
        "[{}]",
        (0..60)
            .map(|i| (1 + i % 3).to_string())
            .collect::<Vec<_>>()
            .join(" ")
    );
    // (arguments, the argument named, whether the command also runs in doubles here)
    let cases: Vec<(Vec<&str>, &str, bool)> = vec![
        (vec!["bernstein", "--degree", "200"], "--t", true),
        (
            vec![
                "decasteljau",
                common::thesis_args::PRIMER_2_4,
                "--n",
                "100000",
            ],
            "--t",
            false,
        ),
        (vec!["derivative", &row60, "--t", "0:0.005:1"], "--t", true),
        (
            vec!["bezier-patch", common::thesis_args::NET_3X3, "--n", "300"],
            "--u/--v",
            true,
        ),
        (
            vec!["lagrange", "--nodes", "0:0.01:1", "--n", "1001"],
            "--t",
            true,
        ),
        (
            vec![
                "hermite", "--p0", "[0;0]", "--p1", "[1;0]", "--t0", "[1;1]", "--t1", "[1;-1]",
                "--n", "100000",
            ],
            "--t",
            false,
        ),
        (vec!["spline", &row1000], "POINTS", true),
        (
            vec!["bspline", &row60, "--degree", "10", "--n", "10001"],
            "--t",
            true,
        ),
        (
            vec![
                "nurbs",
                &row60,
                "--weights",
                &weights,
                "--degree",
                "10",
                "--n",
                "10001",
            ],
            "--t",
            true,
        ),
        (
            vec!["curve", "[u^20; u^19]", "--n", "1000000"],
            "EXPR",
            false,
        ),
        (
            vec!["surface", "[u; v; u.*v]", "--n", "1000"],
            "EXPR",
            false,
        ),
    ];
    refused_exact_but_run_in_doubles(&cases);
}

/// As [`exact_curve_work_is_weighed_by_the_size_of_the_numbers`], for surfaces. The two
/// largest (an 80 × 80 net with a mask, a network of 200 × 200 lines) are not also run in
/// doubles here: each takes 5–7 s in an unoptimised test build, and the refusal in exact
/// arithmetic is what this test is about.
#[test]
fn exact_surface_work_is_weighed_by_the_size_of_the_numbers() {
    let net80: String = {
        let mut lcg = common::lcg::Lcg(11);
        let rows: Vec<String> = (0..80)
            .map(|i| {
                (0..80)
                    .map(|j| format!("{i} {j} {}", lcg.below(10)))
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .collect();
        format!("[{}]", rows.join("; "))
    };
    let coons = with(&["coons"], &PRIMER_4_3);
    let gordon = with(&["gordon"], &GORDON_D);
    let bicubic = [&["coons-bicubic"][..], &FLAT_SQUARE, &FLAT_SQUARE_CROSS].concat();
    // A plane as a network of 200 × 200 lines: at 400 × 400 its exact Lagrange weights alone
    // took 17 s, before the estimate of the points was made; the estimate now comes first.
    let lines: Vec<String> = (0..200)
        .flat_map(|i| ["--u-curve".into(), format!("[{i}/199; v; 0]")])
        .chain((0..200).flat_map(|j| ["--v-curve".into(), format!("[u; {j}/199; 0]")]))
        .collect();
    let network: Vec<&str> = ["gordon", "--u", "0.5", "--v", "0.5"]
        .into_iter()
        .chain(lines.iter().map(String::as_str))
        .collect();
    let cases: Vec<(Vec<&str>, &str, bool)> = vec![
        (with(&coons, &["--n", "300"]), "--u/--v", true),
        (with(&bicubic, &["--n", "200"]), "--u/--v", true),
        (with(&gordon, &["--n", "200"]), "--u/--v", true),
        (
            vec!["discrete-coons", &net80, "--mask=-0.25,0.5"],
            "NET",
            false,
        ),
        // The formula on a 501 × 501 net (a 1001 × 1001 one ran 20–74 s unchecked).
        (vec!["discrete-coons", "zeros(501,1503)"], "NET", true),
        (network, "--u-curve/--v-curve", false),
    ];
    refused_exact_but_run_in_doubles(&cases);
}

/// Each command of `cases` is refused with `--exact` at the default limits, naming the
/// argument, and (where marked) runs in doubles.
fn refused_exact_but_run_in_doubles(cases: &[(Vec<&str>, &str, bool)]) {
    for (args, argument, in_doubles) in cases {
        let out = cagd().args(args).arg("--exact").output().unwrap();
        let e = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {e}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(
            e.starts_with(&format!("cagd: error: {argument}: estimated operations"))
                && e.contains("exceeds the limit of 2000000000 (raise it with --max-work"),
            "{args:?}: {e}"
        );
        if *in_doubles {
            succeeds(cagd().args(args).args(["--format", "csv"]));
        }
    }
}

/// Small exact problems, as students give them, stay well within the default limit: each
/// runs at a quarter of it.
#[test]
fn small_exact_problems_run() {
    let coons = with(&["coons"], &PRIMER_4_3);
    let gordon = with(&["gordon"], &GORDON_D);
    let commands: Vec<Vec<&str>> = vec![
        vec!["bernstein", "--degree", "20", "--n", "101"],
        vec![
            "decasteljau",
            common::thesis_args::PRIMER_2_4,
            "--n",
            "101",
            "--steps",
        ],
        vec!["bezier-patch", common::thesis_args::NET_3X3, "--n", "21"],
        vec!["lagrange", "--nodes", "0:0.1:1", "--n", "101"],
        vec!["spline", "[0 0; 2 1; 4 4; 6 0]'", "--end", "closed"],
        vec!["curve", "[u; u^2; u^3]", "--n", "1001"],
        with(&coons, &["--n", "21", "--steps"]),
        with(&gordon, &["--n", "21", "--steps"]),
        vec!["discrete-coons", "zeros(41,123)", "--steps"],
    ];
    for args in &commands {
        succeeds(
            cagd()
                .args(args)
                .args(["--exact", "--max-work", "500000000"]),
        );
    }
}

/// `--steps` writes a de Casteljau scheme per point, about as many numbers as operations: a
/// grid whose schemes would fill gigabytes (666 bytes of text per point for a 3×3 net) is
/// refused up front, though the same grid without schemes runs.
#[test]
fn schemes_that_would_fill_memory_are_refused() {
    let net = common::thesis_args::NET_3X3;
    let args = ["bezier-patch", net, "--n", "700"];
    let out = cagd().args(args).arg("--steps").output().unwrap();
    let e = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{e}");
    assert!(
        e.starts_with("cagd: error: --u/--v: estimated operations: ")
            && e.contains("exceeds the limit of 2000000000"),
        "{e}"
    );
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("grid.txt");
    succeeds(cagd().args(args).arg("-o").arg(&file));
    assert!(std::fs::metadata(&file).unwrap().len() > 1_000_000);
    // The curve's schemes likewise: 10⁶ parameters of the cubic of Primer 2.4.
    let curve = [
        "decasteljau",
        common::thesis_args::PRIMER_2_4,
        "--n",
        "1000000",
    ];
    let out = cagd().args(curve).arg("--steps").output().unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).starts_with("cagd: error: --t: estimated operations: "));
}

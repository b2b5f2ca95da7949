//! Regression tests: inputs found by fuzzing (fuzz/) and by the reliability review, each of
//! which once crashed, hung, or ran out of memory, and now gives a typed error or a value.
//! Also: every recursive path of the expression parser is bounded by the depth limit.

use cagd_octave::literal::{parse_matrix, Env, Expr, LiteralError, ParamExpr};

/// The stack of the threads that check recursion bounds: 4 MiB. An unoptimised test build
/// uses about 10 KB per nesting level of the parser, so the 64 levels the depth limit allows
/// fit, while the 20 000 levels below would need hundreds of megabytes at any optimisation
/// level (an optimised build needs a few hundred bytes per level: 20 000 of them overflowed
/// 512 KiB before the fix of the transpose run).
const SMALL_STACK: usize = 4 << 20;

/// Nestings through every recursive rule of the grammar, far past the limit: each must be a
/// `TooDeep` error (no stack overflow), in a thread with a small stack.
#[test]
fn every_recursive_path_is_bounded_by_the_depth_limit() {
    let n = 20_000;
    let cases: Vec<(&str, String)> = vec![
        (
            "parentheses",
            format!("{}1{}", "(".repeat(n), ")".repeat(n)),
        ),
        ("brackets", format!("{}1{}", "[".repeat(n), "]".repeat(n))),
        ("unary minus", format!("{}1", "-".repeat(n))),
        ("unary plus and not", format!("{}1", "+-".repeat(n))),
        (
            "call arguments",
            format!("{}1{}", "sin(".repeat(n), ")".repeat(n)),
        ),
        (
            "power operands",
            format!("2{}", "^-(2".repeat(n)) + &")".repeat(n),
        ),
        (
            "transpose of groups",
            format!("{}1{}", "(".repeat(n), ")'".repeat(n)),
        ),
        (
            "index arguments",
            format!("x{}1{}", "(x(".repeat(n), "))".repeat(n)),
        ),
        (
            "matrix rows",
            format!("{}1{}", "[1;".repeat(n), "]".repeat(n)),
        ),
    ];
    let handle = std::thread::Builder::new()
        .stack_size(SMALL_STACK)
        .spawn(move || {
            for (what, text) in &cases {
                let err = Expr::parse(text).expect_err(what);
                assert!(
                    matches!(err, LiteralError::TooDeep { limit: 64, .. }),
                    "{what}: {err}"
                );
                assert!(parse_matrix::<f64>(text).is_err(), "{what}");
                assert!(ParamExpr::parse(text).is_err(), "{what}");
            }
            // Data scripts: nested loops and deep expressions in statements.
            let loops = format!(
                "{}x = 1;\n{}",
                "for i = 1:1\n".repeat(100),
                "end\n".repeat(100)
            );
            assert!(cagd_octave::script::run::<f64>(&loops, Env::new()).is_err());
            let deep = format!("y = {}1{};\n", "(".repeat(n), ")".repeat(n));
            assert!(matches!(
                cagd_octave::script::run::<f64>(&deep, Env::new()),
                Err(LiteralError::TooDeep { .. })
            ));
            // Just inside the limit: parses and evaluates.
            let ok = format!("{}1{}", "(".repeat(60), ")".repeat(60));
            assert_eq!(parse_matrix::<f64>(&ok).unwrap()[(0, 0)], 1.0);
        })
        .unwrap();
    handle.join().expect("no stack overflow");
}

/// Curves defined from curves in a script are evaluated once each, in order (not inlined):
/// a chain of doublings stays linear in time.
#[test]
fn chained_script_curves_stay_linear() {
    let mut source = String::from("c0 = [u; u];\n");
    for k in 1..200 {
        source.push_str(&format!("c{k} = c{} + c{};\n", k - 1, k - 1));
    }
    let script = cagd_octave::script::run::<f64>(&source, Env::new()).unwrap();
    let c = script.resolve("c199").unwrap();
    let p = c
        .sample_curve(&mut script.env().clone(), "u", &[1.0])
        .unwrap();
    assert_eq!(p[(0, 0)], 2f64.powi(199));
}

/// `x(i) = ...` in a loop used to copy `x` at every assignment (quadratic: 10⁵ elements took
/// 16 s); now the vector is updated in place and grows at its end. Same values as Octave.
#[test]
fn indexed_assignment_in_a_loop_is_linear() {
    let start = std::time::Instant::now();
    let s = cagd_octave::script::run::<f64>(
        "for i = 1:200000\n  x(i) = i;\nend\ny = [1;2]; y(4) = 3;\nz = zeros(1,3); z(5) = 7;\nw(2,3) = 1; w(3,1) = 2;\n",
        Env::new(),
    )
    .unwrap();
    assert!(start.elapsed().as_secs() < 20, "{:?}", start.elapsed());
    let x = s.value("x").unwrap();
    assert_eq!(
        (x.nrows(), x.ncols(), x[(0, 199_999)]),
        (1, 200_000, 200_000.0)
    );
    assert_eq!(s.value("y").unwrap().as_slice(), &[1.0, 2.0, 0.0, 3.0]);
    assert_eq!(s.value("z").unwrap().as_slice(), &[0.0, 0.0, 0.0, 0.0, 7.0]);
    let w = s.value("w").unwrap();
    assert_eq!(
        (w.nrows(), w.ncols(), w[(1, 2)], w[(2, 0)]),
        (3, 3, 1.0, 2.0)
    );
}

/// A loop that rebuilds a growing matrix (`x = [x i]`) is quadratic in Octave too; the total
/// work of a script is bounded (25 × max_elements elements assigned), so it stops with an
/// error instead of running for hours.
#[test]
fn scripts_have_a_work_budget() {
    use cagd::limits::Limits;
    let limits = Limits {
        max_elements: 10_000,
        ..Limits::default()
    };
    let err = cagd_octave::script::run::<f64>(
        "x = [];\nfor i = 1:5000\n  x = [x i];\nend\n",
        Env::with_limits(limits),
    )
    .unwrap_err();
    assert!(matches!(err, LiteralError::TooLarge { .. }), "{err}");
    assert!(err.to_string().contains("all together"), "{err}");
}

/// One evaluation is bounded in work (64 × max_elements element operations), so a short text
/// cannot run for minutes: chains of large products or sums stop with `TooLarge`. (Shown at
/// 10⁵ elements, a budget of 6.4·10⁶ operations that each chain exceeds after a few links;
/// at the default 4·10⁶ the same chains, 40 times larger, stop alike.)
#[test]
fn one_evaluation_has_a_work_budget() {
    let limits = cagd::limits::Limits {
        max_elements: 100_000,
        ..cagd::limits::Limits::default()
    };
    let parse = |text: &str| cagd_octave::literal::parse_matrix_with::<f64>(text, &limits);
    // Each product 100·128·100 = 1.28·10⁶ multiply-adds: the budget ends after about five.
    let products = format!("ones(100,128){}", "*ones(128,100)*ones(100,128)".repeat(40));
    let start = std::time::Instant::now();
    let result = parse(&products).map(|m| m.shape());
    assert!(
        matches!(result, Err(LiteralError::TooLarge { .. })),
        "{result:?}"
    );
    // Each sum 9·10⁴ additions: the budget ends after about seventy of the 2000.
    let sums = format!("ones(300,300){}", "+1".repeat(2000));
    let result = parse(&sums).map(|m| m.shape());
    assert!(
        matches!(result, Err(LiteralError::TooLarge { .. })),
        "{result:?}"
    );
    // Within the budget the same chains run.
    let short = parse(&format!("ones(300,300){}", "+1".repeat(60))).unwrap();
    assert_eq!(short[(299, 299)], 61.0);
    let short = parse("ones(100,128)*ones(128,100)*ones(100,128)").unwrap();
    assert_eq!(short[(0, 0)], 128.0 * 100.0);
    assert!(start.elapsed().as_secs() < 60, "{:?}", start.elapsed());
    // Ordinary work is far inside the budget.
    let m = parse_matrix::<f64>("ones(1000,1000)*ones(1000,1)+1").unwrap();
    assert_eq!((m.nrows(), m[(999, 0)]), (1000, 1001.0));
}

/// Fuzzing (`text_format`, out-of-memory after 4.9 million runs): a `range` variable whose
/// base, limit and increment ask for 2·10⁹ elements made `to_array` allocate 16 GB. Ranges
/// are now expanded only up to the element limit; beyond it the accessors give a typed error.
#[test]
fn fuzz_text_format_oom_huge_range() {
    use cagd_octave::text_format::{read_text, TextFormatError};
    // The input as libFuzzer minimised it (artifacts/text_format/oom-24c6a13e…).
    let bytes = b"#name:\xf3\x96\x91\x91#namer\n# type: range\n#nt\n1 16666666666.00 8";
    let text = std::str::from_utf8(bytes).unwrap();
    let ws = read_text(text).unwrap();
    let name = ws.names().next().unwrap().to_string();
    assert!(matches!(
        ws.array(&name),
        Err(TextFormatError::WrongType { .. })
    ));
    assert!(ws.matrix(&name).is_err());
    // A range within the limit still expands.
    let ws = read_text("# name: r\n# type: range\n# base, limit, increment\n1 9 2\n").unwrap();
    assert_eq!(
        ws.matrix("r").unwrap().row(0).to_vec(),
        vec![1.0, 3.0, 5.0, 7.0, 9.0]
    );
}

/// Fuzzing (`literal`, timeout in the instrumented build at the default limits): the exact
/// range `1e-3:1e-3:2e2-2` has 198 000 elements. Linear work within the limits, not a hang
/// (about a second in a debug build); the fuzz targets now run with limits of 10⁴ elements.
/// The range must be exact and complete.
#[test]
fn fuzz_literal_timeout_long_exact_range() {
    use num_rational::BigRational;
    let start = std::time::Instant::now();
    let r = cagd_octave::literal::parse_params::<BigRational>("1e-3:1e-3:2e2-2").unwrap();
    assert_eq!(r.len(), 198_000);
    assert_eq!(r[197_999], BigRational::new(198.into(), 1.into()));
    assert_eq!(r[0], BigRational::new(1.into(), 1000.into()));
    assert!(start.elapsed().as_secs() < 30, "{:?}", start.elapsed());
    // Third finding: a step of 1e-5828 − 2 (a 19 000-bit denominator): the literal is now
    // out of range for exact evaluation.
    let r = cagd_octave::literal::parse_params::<BigRational>("1:1e-5828-2:1e0-5828-2");
    assert!(
        matches!(r, Err(LiteralError::NumberOutOfRange { .. })),
        "{:?}",
        r.map(|v| v.len())
    );
    // Second finding of the same kind: 61 401 elements with a 10⁻³³ offset (110-bit
    // denominators).
    let r = cagd_octave::literal::parse_params::<BigRational>("1e-33-612e2-1:2e2").unwrap();
    // Exactly (200 − base) = 61401 − 10⁻³³, so 61 401 elements (in doubles the offset vanishes
    // and Octave counts 61 402).
    assert_eq!(r.len(), 61_401);
    assert!(start.elapsed().as_secs() < 30, "{:?}", start.elapsed());
    // Above the element limit it is an error, not an allocation.
    let over = cagd_octave::literal::parse_params::<BigRational>("1e-9:1e-9:1");
    assert!(matches!(over, Err(LiteralError::TooLarge { .. })));
}

/// Fuzzing (`literal`, timeout at 30 s per input at the default limits, after 99 012 runs):
/// `[1.7918485:1206315]*3` builds an exact range of 1.2·10⁶ elements (denominator 10⁷), about
/// a second in a release build, and the target builds it four times. Linear work the limits
/// allow (the target now has 180 s per input); what must hold is that the work meter refuses
/// the multiplication after the range, and a range it cannot pay for before it is built.
#[test]
fn fuzz_literal_timeout_exact_range_at_the_default_limits() {
    use num_rational::BigRational;
    let work_refused = |text: &str| {
        let r = cagd_octave::literal::parse_matrix::<BigRational>(text);
        match r {
            Err(LiteralError::TooLarge {
                what, count, limit, ..
            }) => {
                assert!(what.contains("work"), "{text}: {what}");
                assert_eq!(limit, 256_000_000, "{text}");
                count
            }
            other => panic!("{text}: {:?}", other.map(|m| m.len())),
        }
    };
    // Past the meter: refused before a single element is built (the count is the range's
    // charge, 128 per element for one-word bounds).
    let charged = work_refused("[1.7918485:2100000]");
    assert!(
        (2_099_999 * 128..2_099_999 * 128 + 16).contains(&charged),
        "{charged}"
    );
    // In doubles the same range is cheap and allowed.
    let r = cagd_octave::literal::parse_matrix::<f64>("[1.7918485:2100000]").unwrap();
    assert_eq!(r.len(), 2_099_999);
}

/// Fuzzing (`literal`, timeout): the exact power `-(24.445^46913)` built a 985 000-bit
/// rational by repeated squaring with a gcd at every step (minutes). Exact numbers are now
/// limited to 2¹² bits of numerator and denominator, and powers skip the gcd.
#[test]
fn fuzz_literal_timeout_huge_exact_power() {
    use num_rational::BigRational;
    let start = std::time::Instant::now();
    let r = cagd_octave::literal::parse_matrix::<BigRational>("-(24.445^46913) ");
    assert!(
        matches!(r, Err(LiteralError::NumberOutOfRange { .. })),
        "{:?}",
        r.map(|m| m.shape())
    );
    // Products of large exact numbers stop at the size limit too.
    let r = cagd_octave::literal::parse_matrix::<BigRational>("3^1000 * 3^1000 * 3^1000");
    assert!(
        matches!(r, Err(LiteralError::TooLarge { .. })),
        "{:?}",
        r.map(|m| m.shape())
    );
    assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
    // Ordinary exact powers are exact.
    let p = cagd_octave::literal::parse_matrix::<BigRational>("(-2/3)^-3").unwrap();
    assert_eq!(p[(0, 0)], BigRational::new((-27).into(), 8.into()));
    let p = cagd_octave::literal::parse_matrix::<BigRational>("2^100").unwrap();
    assert_eq!(
        p[(0, 0)],
        BigRational::from_integer(num_bigint::BigInt::from(2).pow(100))
    );
    // f64 is unaffected: the double overflows and is refused as non-finite.
    assert!(matches!(
        cagd_octave::literal::parse_matrix::<f64>("24.445^46913"),
        Err(LiteralError::NonFinite { .. })
    ));
}

/// Fuzzing (`script`, timeout and slow unit): the same exact-power growth through a data
/// script, with negative and tower exponents. Both now stop at once with a typed error.
#[test]
fn fuzz_script_timeout_exact_power_towers() {
    use num_rational::BigRational;
    let start = std::time::Instant::now();
    for source in ["03333333^-33333", "033093333306;366063333^33166^33333"] {
        let mut env = Env::<BigRational>::new();
        env.bind_scalar("N", BigRational::from_integer(4.into()));
        let r = cagd_octave::script::run::<BigRational>(source, env);
        assert!(
            matches!(
                r,
                Err(LiteralError::NumberOutOfRange { .. } | LiteralError::TooLarge { .. })
            ),
            "{source}"
        );
        // In doubles the same scripts run (the values are finite or refused as non-finite).
        let _ = cagd_octave::script::run::<f64>(source, Env::new());
    }
    assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
}

/// Fuzzing (`text_format`, timeout after 3.8 million runs): a 218-byte file declaring a
/// `20002114 × 0` matrix. It has no elements, so it passed every size check, but Octave's
/// layout gives an R×0 matrix one blank line per row: writing it back made a 20 MB text and
/// reading that again took seconds. Every length of an array read is now bounded by the
/// element limit, even when the array is empty; within the limit R×0 matrices still read and
/// round-trip as Octave writes them.
#[test]
fn fuzz_text_format_timeout_empty_matrix_with_huge_row_count() {
    use cagd_octave::text_format::{read_text, write_text, TextFormatError};
    let start = std::time::Instant::now();
    // The decisive variable of the artifact (timeout-aaea22b1…).
    let text = "# Created by Octa columns: 0\n\n\n\n# name:_a0_n0\n# type: matrix\n# rows: 20002114\n# columns: 0\n\n\n\n# name: _n0a_lb1_b\n# type: scalar\n1\n";
    let err = read_text(text).unwrap_err();
    assert!(
        matches!(err, TextFormatError::BadHeader { line: 8, ref found, .. } if found.contains("20002114")),
        "{err:?}"
    );
    assert!(start.elapsed().as_secs() < 5, "{:?}", start.elapsed());
    // A 5×0 matrix as Octave 7.3 writes it (`A = zeros(5, 0); save -text`): five blank lines.
    let octave = "# name: A\n# type: matrix\n# rows: 5\n# columns: 0\n\n\n\n\n\n\n\n";
    let ws = read_text(octave).unwrap();
    assert_eq!(ws.matrix("A").unwrap().shape(), &[5, 0]);
    let again = read_text(&write_text(&ws).unwrap()).unwrap();
    assert_eq!(again.matrix("A").unwrap().shape(), &[5, 0]);
}

/// Fuzzing (`literal`, timeout after 0.64 million runs): 121 bytes of exact arithmetic on
/// 1000-bit rationals over a range of a few hundred elements took a third of a second in a
/// release build (over 10 s instrumented), while the work meter charged one unit per
/// element. Exact operations are now charged `(a + b)²` for operands of `a` and `b` 64-bit
/// words (the gcd behind every exact result) times 32, before they are computed, and exact
/// ranges are charged per element the same way. The second finding (`1e-85*9-3e-31:3555*2`,
/// after 3·10⁵ runs with the unweighted `(a + b)²`) set the weight.
#[test]
fn fuzz_literal_timeout_large_exact_operands() {
    use num_rational::BigRational;
    let artifact = "1e-310-3-310--[77777.7777777-754./ 1.7777777-7777-777./ 1.77777:777./ 1.777777-7777:52-1e-10--2-1e7-777751]-310-310--2-A2";
    // At the fuzzing limits (10⁴ elements: a budget of 640 000 operations) the work limit
    // stops it at once.
    let small = cagd::limits::Limits {
        max_elements: 10_000,
        ..cagd::limits::Limits::default()
    };
    let mut env = Env::<BigRational>::with_limits(small);
    let start = std::time::Instant::now();
    let r = cagd_octave::literal::Expr::parse(artifact)
        .unwrap()
        .eval(&mut env);
    assert!(
        matches!(r, Err(LiteralError::TooLarge { ref what, .. }) if what.contains("work")),
        "{:?}",
        r.map(|m| m.shape())
    );
    assert!(start.elapsed().as_secs() < 5, "{:?}", start.elapsed());
    // The second artifact: 7 111 exact elements with 283-bit denominators, 48 ms in a release
    // build per evaluation, is refused at the fuzzing limits and still exact at the defaults.
    let second = "1e-85*9-3e-31:3555*2";
    let r = cagd_octave::literal::Expr::parse(second)
        .unwrap()
        .eval(&mut Env::<BigRational>::with_limits(small));
    assert!(
        matches!(r, Err(LiteralError::TooLarge { ref what, .. }) if what.contains("work")),
        "{:?}",
        r.map(|m| m.shape())
    );
    let r = cagd_octave::literal::parse_params::<BigRational>(second).unwrap();
    assert_eq!(r.len(), 7_111);
    // At the default limits a range of 10⁶ elements of 1000-bit numbers is refused before it
    // is built (it would cost about 4·10⁹ units, 16 times the budget) ...
    let start = std::time::Instant::now();
    let r = cagd_octave::literal::parse_params::<BigRational>(
        "(1e-300:1e-300+1/7:1e-300+1000000/7) + 1e-301",
    );
    assert!(
        matches!(r, Err(LiteralError::TooLarge { ref what, .. }) if what.contains("work")),
        "{:?}",
        r.map(|m| m.len())
    );
    assert!(start.elapsed().as_secs() < 5, "{:?}", start.elapsed());
    // ... while short-word exact ranges of the same length stay within it and are exact.
    let r = cagd_octave::literal::parse_params::<BigRational>("(1/3:1/7:100000/7) + 1/9").unwrap();
    assert_eq!(r.len(), 99_998);
    assert_eq!(r[0], BigRational::new(4.into(), 9.into()));
    // f64 evaluation of the artifact is unaffected (an unknown variable at its end).
    assert!(matches!(
        cagd_octave::literal::parse_matrix::<f64>(artifact),
        Err(LiteralError::UnknownVariable { .. })
    ));
}

/// Fuzzing (`script`, stack overflow after 10⁶ runs): `.5555` followed by 1 300 transposes
/// built a 1 300-deep tree of transpose nodes (postfix operators did not pass the depth
/// check), and evaluating it overflowed the stack. Two transposes cancel on real matrices,
/// so a run of them is now one node or none; the values are Octave's (`x''` is `x`).
#[test]
fn fuzz_script_stack_overflow_long_transpose_run() {
    let handle = std::thread::Builder::new()
        .stack_size(SMALL_STACK)
        .spawn(|| {
            let artifact = format!(".5555{}#", "'".repeat(1300));
            let r = cagd_octave::script::run::<f64>(&artifact, Env::new());
            assert!(r.is_ok(), "{:?}", r.err());
            for (quotes, odd) in [(20_000, false), (20_001, true)] {
                let text = format!("[1 2 3]{}", "'".repeat(quotes));
                let m = parse_matrix::<f64>(&text).unwrap();
                let expect = if odd { (3, 1) } else { (1, 3) };
                assert_eq!(m.shape(), expect, "{quotes} quotes");
                assert_eq!(m[(if odd { 2 } else { 0 }, if odd { 0 } else { 2 })], 3.0);
            }
            // Mixed `'` and `.'` count alike.
            let m = parse_matrix::<f64>("[1 2; 3 4].''.'").unwrap();
            assert_eq!(m, parse_matrix::<f64>("[1 3; 2 4]").unwrap());
        })
        .unwrap();
    handle.join().expect("no stack overflow");
}

/// The smaller limits the `cli` fuzz target ran at when it found the findings below (it now
/// runs at the defaults).
const FUZZ_CLI_LIMITS: [(&str, &str); 6] = [
    ("CAGD_MAX_ELEMENTS", "10000"),
    ("CAGD_MAX_ITERATIONS", "10000"),
    ("CAGD_MAX_SAMPLES", "1000"),
    ("CAGD_MAX_GRID_POINTS", "10000"),
    ("CAGD_MAX_WORK", "5000000"),
    ("CAGD_MAX_SYSTEM_ENTRIES", "100000"),
];

/// The command line as the `cli` fuzz target ran it for the findings below: its smaller limits
/// ([`FUZZ_CLI_LIMITS`]) in the environment, the others removed.
fn fuzz_cli(args: &[&str]) -> std::process::Output {
    let mut c = assert_cmd::Command::cargo_bin("cagd").unwrap();
    for (_, var, _) in cagd_cli::limits::SETTINGS {
        c.env_remove(var);
    }
    for (var, value) in FUZZ_CLI_LIMITS {
        c.env(var, value);
    }
    c.args(args).output().unwrap()
}

fn refused_by_work(out: &std::process::Output, argument: &str, limit: &str) {
    let e = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{e}");
    assert!(out.stdout.is_empty());
    assert!(
        e.starts_with(&format!("cagd: error: {argument}: estimated operations: "))
            && e.contains(&format!("exceeds the limit of {limit} ")),
        "{e}"
    );
}

/// `cli` fuzz target, timeout after 708 882 runs: an exact interpolating spline through the
/// 2 223 points of `0:2222` (the first number is `0222222222222-222222222222`, zero). The
/// spline command had no work estimate; its tridiagonal solve builds continuants of about
/// 4 bits per point: 1.8 s in a release build, over 10 s instrumented, and 6 s through 1 000
/// random digits. Now refused before the solve, at the fuzz target's limits and at the
/// defaults; fewer points in doubles, and a short exact spline, still run.
#[test]
fn fuzz_cli_timeout_exact_spline_through_many_points() {
    let points = "[ ; 0222222222222-222222222222:2222]";
    refused_by_work(
        &fuzz_cli(&["spline", points, "--exact"]),
        "POINTS",
        "5000000",
    );
    let mut c = assert_cmd::Command::cargo_bin("cagd").unwrap();
    for (_, var, _) in cagd_cli::limits::SETTINGS {
        c.env_remove(var);
    }
    let out = c.args(["spline", points, "--exact"]).output().unwrap();
    refused_by_work(&out, "POINTS", "2000000000");
    let out = fuzz_cli(&["spline", "[ ; 0:50]", "--format", "csv"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // 10 samples per segment: 200 segments are 2001 samples, above the target's 1000, and
    // the error names the points (spline has no --n).
    let out = fuzz_cli(&["spline", "[ ; 0:200]"]);
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(
        e.starts_with(
            "cagd: error: POINTS: samples (10 per segment): 2001 exceeds the limit of 1000 "
        ),
        "{e}"
    );
    // A short exact spline still runs: the natural spline through 0, 1, 0 has tangents
    // 3/2, 0, −3/2.
    let out = fuzz_cli(&["spline", "[0 1 0]", "--exact"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("3/2") && text.contains("-3/2"), "{text}");
}

/// `cli` fuzz target, slow unit (11 s instrumented) before that timeout: Bernstein values of
/// degree 95 at 11 parameters, exactly (0.6 s in a release build; degree 200 takes 5 s,
/// degree 1000 — within the degree limit — minutes). The estimate counted (n+1)² operations
/// per parameter as if each cost one `f64` operation; each now weighs
/// `exact_op_cost(n · (bits(t) + 1))`.
#[test]
fn fuzz_cli_slow_exact_bernstein_of_high_degree() {
    refused_by_work(
        &fuzz_cli(&["bernstein", "--degree", "95", "--exact"]),
        "--t",
        "5000000",
    );
    refused_by_work(
        &fuzz_cli(&[
            "bernstein",
            "--degree",
            "1000",
            "--exact",
            "--max-work",
            "2000000000",
        ]),
        "--t",
        "2000000000",
    );
    // In doubles, and exactly at a low degree, the same command runs: B_1^3(1/2) = 3/8.
    assert!(fuzz_cli(&["bernstein", "--degree", "95"]).status.success());
    let out = fuzz_cli(&["bernstein", "--degree", "3", "--t", "0.5", "--exact"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("3/8"), "{text}");
}

/// `script` fuzz target, timeout (after 5.4·10⁵ runs, on a machine busy compiling): a mutated
/// appendix C script whose unclosed `for` made two loops of N element assignments run N
/// times, in exact arithmetic. At N = 86 it took 1.2 s instrumented; at N = 860 (740 000
/// iterations, within the iteration limit) 20 s in a release build, because indexing `v(i)`
/// copied all of `v` and the script's total budget counted only the values assigned. Now
/// indexing reads in place and every evaluation's work counts against the script's budget,
/// so N = 860 stops with `TooLarge` (about 1 s in a release build) while N = 86 still runs.
/// Here with a tenth of the default elements (a budget of 10⁷), N = 300 stops.
#[test]
fn fuzz_script_timeout_nested_exact_element_loops() {
    let limits = cagd::limits::Limits {
        max_elements: 400_000,
        ..Default::default()
    };
    let script = |n: usize| {
        format!(
            "N = {n};\nv = linspace(0,1,N);\nfor j = 1:N\n  c = zeros(1,N);\n  for i = 1:N\n    c(i) = v(i)-(v(i))^2;\n  end;\n  d = [v; c];\nend;\n"
        )
    };
    use num_rational::BigRational;
    let s = cagd_octave::script::run::<BigRational>(&script(86), Env::with_limits(limits)).unwrap();
    let c = s.value("c").unwrap();
    // c(i) = t − t² at t = (i−1)/85: at i = 2, 1/85 − 1/7225 = 84/7225.
    assert_eq!(c[(0, 1)], BigRational::new(84.into(), 7225.into()));
    let err = cagd_octave::script::run::<BigRational>(&script(300), Env::with_limits(limits))
        .unwrap_err();
    assert!(
        matches!(err, LiteralError::TooLarge { ref what, .. } if what.contains("work of the script")),
        "{err}"
    );
    // In doubles the same loops stay well within the budget.
    assert!(cagd_octave::script::run::<f64>(&script(300), Env::with_limits(limits)).is_ok());
}

//! Hostile input across every subcommand, drawn from the classes an outside attack found:
//! extreme magnitudes (near the range of doubles, subnormal), deep nesting, odd file types
//! (FIFOs, devices, folders, `/dev/stdin`) as inputs and outputs, and pictures and meshes of
//! all of them. Every case must end in under 5 s with either exit 0 and finite output, or
//! exit 2 and one error line; never a signal, a panic, NaN/Inf in the output, a file left
//! behind by a refused command, or a non-regular file replaced.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use cagd_test_support as common;

use common::thesis_args::{GORDON_D, NET_3X3, PRIMER_2_4, PRIMER_4_3};

/// Matrices near the limits of doubles, and nesting near and past the depth limit.
fn hostile_matrices() -> Vec<String> {
    vec![
        "[1e308 -1e308; 1 2]".into(),
        "[1.7e308 -1.7e308 1.7e308]".into(),
        "[-1e308 1e308; 0 1]".into(),
        "[0 1e-310 1; 1e-320 0 5e-324]".into(),
        "[1e200 1e200; 1e200 1e200]*1e200".into(),
        "[0 0 0; 1e308 1e308 1e308]'".into(),
        format!("[{}1{} 2]", "(".repeat(60), ")".repeat(60)),
        format!("[{}1{} 2]", "(".repeat(5000), ")".repeat(5000)),
        format!("[{}1 2]", "-".repeat(5000)),
        format!("[1{} 2]", "'".repeat(5000)),
    ]
}

/// Parameter lists near the limits of doubles.
fn hostile_params() -> Vec<String> {
    vec![
        "1e308".into(),
        "[-1e308 0 1e308]".into(),
        "[0 1e-320 1]".into(),
        "-1.7e308:1e307:1.7e308".into(),
    ]
}

/// Four corner vectors of zeros, for the tangents and twists of a Ferguson patch.
const FLAT_TANGENTS: &str = "[0 0 0; 0 0 0; 0 0 0; 0 0 0]'";

/// The commands, each with its matrix argument replaced by `M` and a parameter list by `T`.
fn templates() -> Vec<Vec<String>> {
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    let mut t = vec![
        s(&["decasteljau", "M", "--t", "T"]),
        s(&["decasteljau", "M", "--n", "3", "--steps"]),
        s(&["bezier-patch", "M", "--u", "T", "--v", "0.5"]),
        s(&["bezier-patch", NET_3X3, "--u", "T", "--v", "T"]),
        s(&["discrete-coons", "M"]),
        s(&["discrete-coons", "M", "--mask=0,0.25"]),
        s(&["lagrange", "--nodes", "M", "--t", "T"]),
        s(&[
            "lagrange", "--nodes", "[0 1 2]", "--points", "M", "--t", "T",
        ]),
        s(&["bernstein", "--degree", "3", "--t", "T"]),
        s(&["derivative", "M", "-r", "1"]),
        s(&["derivative", PRIMER_2_4, "-r", "2", "--t", "T"]),
        s(&["spline", "M"]),
        s(&["spline", "M", "--t", "T"]),
        s(&[
            "hermite", "--p0", "M", "--p1", "[0;0]", "--t0", "[1;0]", "--t1", "[0;1]", "--t", "T",
        ]),
        s(&[
            "hermite",
            "--p0",
            "[1.5e308;0]",
            "--p1",
            "[0;0]",
            "--t0",
            "M",
            "--t1",
            "[0;0]",
            "--t",
            "T",
        ]),
        s(&["bspline", "M", "--degree", "1", "--t", "T"]),
        s(&[
            "nurbs",
            "M",
            "--degree",
            "1",
            "--weights",
            "[1 1 1]",
            "--t",
            "T",
        ]),
        s(&["curve", "[u; u^2]*1e300", "--t", "T"]),
        s(&["curve", "M", "--n", "3"]),
        s(&["surface", "[1e308*(2*u-1); v; u]", "--n", "3"]),
        s(&["surface", "[u; v; M(1)*u]", "--u", "T", "--v", "0:0.5:1"]),
        // The constructions of the course.
        s(&["convert", "M", "--from", "bezier", "--to", "bspline"]),
        s(&["elevate", "M", "--by", "2"]),
        s(&["subdivide", "M", "--t", "T"]),
        s(&["insert-knot", "M", "--degree", "1", "--insert", "T"]),
        s(&["bspline-basis", "--knots", "M", "--degree", "1", "--t", "T"]),
        s(&["continuity", PRIMER_2_4, "M", "--free-point"]),
        s(&["integrate", "M"]),
        s(&[
            "ruled",
            "--first",
            "M",
            "--second",
            "[0 1 2; 1 1 1]",
            "--u",
            "T",
            "--v",
            "0.5",
        ]),
        s(&[
            "ruled",
            "--first",
            "[1e308*u; 0]",
            "--second",
            "[u; 1]",
            "--n",
            "3",
        ]),
        s(&[
            "ferguson",
            "--points",
            "M",
            "--du",
            FLAT_TANGENTS,
            "--dv",
            FLAT_TANGENTS,
            "--twists",
            FLAT_TANGENTS,
            "--u",
            "T",
        ]),
        s(&["circle", "--radius", "M(1)", "--t", "T"]),
        s(&[
            "arc", "--radius", "1", "--center", "M", "--start", "0", "--end", "T",
        ]),
    ];
    for surface in ["bspline-surface", "nurbs-surface"] {
        t.push(s(&[
            surface, "M", "--degree", "1", "--u", "T", "--v", "0.5",
        ]));
    }
    let mut coons = s(&["coons"]);
    coons.extend(s(&PRIMER_4_3));
    coons.extend(s(&["--u", "T", "--v", "0.5"]));
    t.push(coons);
    let mut coons_m = s(&["coons", "--c1", "M", "--c2", "M", "--d1", "M", "--d2", "M"]);
    coons_m.extend(s(&["--n", "3"]));
    t.push(coons_m);
    let mut gordon = s(&["gordon"]);
    gordon.extend(s(&GORDON_D));
    gordon.extend(s(&["--u", "T", "--v", "0.5"]));
    t.push(gordon);
    t
}

/// Every case: the templates filled with every hostile value, with and without a picture.
fn cases() -> Vec<Vec<String>> {
    let mut out = Vec::new();
    for template in templates() {
        let fill = |m: &str, t: &str| -> Vec<String> {
            template
                .iter()
                .map(|a| match a.as_str() {
                    "M" => m.to_string(),
                    "T" => t.to_string(),
                    other => other.replace("M(1)", &format!("({m})(1)")),
                })
                .collect()
        };
        let has_m = template.iter().any(|a| a == "M" || a.contains("M(1)"));
        let has_t = template.iter().any(|a| a == "T");
        let ms: Vec<String> = if has_m {
            hostile_matrices()
        } else {
            vec!["[0 1 2; 0 1 0]".into()]
        };
        let ts: Vec<String> = if has_t {
            hostile_params()
        } else {
            vec!["0.5".into()]
        };
        for m in &ms {
            out.push(fill(m, "0.5"));
            out.push(
                fill(m, "0.5")
                    .into_iter()
                    .chain(["--plot".into(), "p.svg".into()])
                    .collect(),
            );
        }
        for t in &ts {
            out.push(fill(&ms[0], t));
        }
    }
    out
}

/// What one run did.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    elapsed: Duration,
}

/// Runs the `cagd` binary in `dir` with `stdin` as standard input, killing it after 20 s.
fn run(dir: &Path, args: &[String], stdin: Option<&Path>) -> Run {
    let start = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .current_dir(dir)
        .stdin(match stdin {
            Some(p) => Stdio::from(std::fs::File::open(p).unwrap()),
            None => Stdio::null(),
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let deadline = start + Duration::from_secs(20);
    loop {
        if child.try_wait().unwrap().is_some() || Instant::now() > deadline {
            break;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let _ = child.kill();
    let out = child.wait_with_output().unwrap();
    Run {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        elapsed: start.elapsed(),
    }
}

/// The contract of one run: `None` if it holds, else what broke.
fn broken(r: &Run, dir: &Path) -> Option<String> {
    // An unoptimised build is several times slower than the release binary users run.
    if r.elapsed > Duration::from_secs(5) {
        return Some(format!("took {:?}", r.elapsed));
    }
    let has_non_finite = |text: &str| {
        text.split(|c: char| !c.is_ascii_alphanumeric())
            .any(|w| w.eq_ignore_ascii_case("inf") || w.eq_ignore_ascii_case("nan"))
    };
    let error_lines: Vec<&str> = r
        .stderr
        .lines()
        .filter(|l| !l.starts_with("cagd: warning:"))
        .collect();
    match r.code {
        None => Some("killed by a signal".into()),
        Some(0) if has_non_finite(&r.stdout) => Some("printed a non-finite number".into()),
        Some(0) if !error_lines.is_empty() => Some("exit 0 with an error line".into()),
        Some(0) => None,
        Some(2) if error_lines.len() != 1 || !error_lines[0].starts_with("cagd: error: ") => {
            Some("exit 2 without exactly one error line".into())
        }
        Some(2) if !r.stdout.is_empty() => Some("exit 2 with output".into()),
        Some(2) => {
            let left: Vec<_> = std::fs::read_dir(dir)
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .filter(|f| f != "inputs")
                .collect();
            (!left.is_empty()).then(|| format!("left files behind: {left:?}"))
        }
        Some(c) => Some(format!("exit code {c}")),
    }
}

fn check_all(cases: &[(Vec<String>, Option<PathBuf>)]) {
    let failures = std::sync::Mutex::new(Vec::new());
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| loop {
                let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some((args, stdin)) = cases.get(k) else {
                    break;
                };
                let dir = common::TempDir::new("hostile");
                let r = run(dir.path(), args, stdin.as_deref());
                if let Some(problem) = broken(&r, dir.path()) {
                    let shown: Vec<String> = args
                        .iter()
                        .map(|a| {
                            if a.len() > 60 {
                                format!("{}…", &a[..40])
                            } else {
                                a.clone()
                            }
                        })
                        .collect();
                    failures.lock().unwrap().push(format!(
                        "cagd {}: {problem}\n  stderr: {}",
                        shown.join(" "),
                        r.stderr.lines().next().unwrap_or("")
                    ));
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    assert!(
        failures.is_empty(),
        "{} case(s) broke the contract:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn extreme_magnitudes_and_deep_nesting_across_every_subcommand() {
    let cases: Vec<(Vec<String>, Option<PathBuf>)> =
        cases().into_iter().map(|c| (c, None)).collect();
    assert!(cases.len() > 300, "{} cases", cases.len());
    check_all(&cases);
}

#[cfg(unix)]
#[test]
fn odd_file_types_as_inputs_and_outputs() {
    let dir = common::TempDir::new("hostile-files");
    let fifo = dir.path().join("fifo");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let folder = dir.path().join("folder");
    std::fs::create_dir(&folder).unwrap();
    let empty = dir.path().join("empty.txt");
    std::fs::write(&empty, "").unwrap();
    let numbers = dir.path().join("numbers.txt");
    std::fs::write(&numbers, "0 1 2\n0 1 0\n").unwrap();
    let p = |path: &Path| path.to_str().unwrap().to_string();
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    let mut cases: Vec<(Vec<String>, Option<PathBuf>)> = Vec::new();
    // Outputs onto things that are not regular files: refused, never replaced.
    for target in [p(&fifo), p(&folder), "/dev/null".into(), "/dev/full".into()] {
        for flag in ["-o", "--plot", "--mesh"] {
            let mut args = s(&["surface", "[u;v;u*v]", "--n", "3"]);
            args.extend([flag.to_string(), target.clone()]);
            cases.push((args, None));
        }
    }
    // Inputs that are not regular files: read (standard input, a file read through
    // /dev/stdin) or refused with the right name (a folder, an empty device).
    for (input, stdin) in [
        ("/dev/stdin".to_string(), Some(numbers.clone())),
        ("-".to_string(), Some(numbers.clone())),
        ("-".to_string(), Some(empty.clone())),
        (p(&folder), None),
        ("/dev/null".to_string(), None),
        (p(&empty), None),
    ] {
        cases.push((s(&["decasteljau", &input, "--t", "0.5"]), stdin.clone()));
        cases.push((s(&["discrete-coons", &input]), stdin.clone()));
        cases.push((s(&["script", &input]), stdin));
    }
    // Two outputs on one path.
    cases.push((
        s(&[
            "decasteljau",
            "[0 1 2; 0 1 0]",
            "--n",
            "3",
            "--plot",
            "a.svg",
            "-o",
            "./a.svg",
        ]),
        None,
    ));
    check_all(&cases);
    let kind = std::fs::metadata(&fifo).unwrap().file_type();
    use std::os::unix::fs::FileTypeExt;
    assert!(kind.is_fifo(), "the FIFO was replaced");
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    assert!(folder.is_dir() && std::fs::read_dir(&folder).unwrap().next().is_none());
}

//! The output files follow the shell's `>`, atomically: a failed command (standard output
//! included) replaces no file; a symbolic link is followed and its target written; an output
//! that is also an input is refused before any work; a read-only file is refused; Ctrl-C
//! leaves no temporary file; a closed or full standard output is an error. Messages quote
//! every path escaped, on one line.

use std::path::Path;
use std::process::{Command, Output, Stdio};

use cagd_test_support::bad_input::files_in;

fn cagd(dir: &Path, args: &[&str]) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_cagd"));
    cmd.current_dir(dir).args(args);
    cmd
}

/// Exit 2, one line on standard error naming `needle`; returns the line.
fn refused(out: &Output, needle: &str) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr:?}");
    assert!(stderr.starts_with("cagd: error: "), "{stderr}");
    assert!(stderr.contains(needle), "{needle:?} not in {stderr}");
    stderr
}

/// No `.cagd-*` file left in `dir`.
fn no_temporaries(dir: &Path) {
    let left: Vec<String> = files_in(dir)
        .into_iter()
        .filter(|f| f.starts_with(".cagd-"))
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
}

const CURVE: &str = "[0 1;0 1]'";

#[test]
fn a_failed_write_to_standard_output_replaces_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("keep.txt"), "old").unwrap();
    let full = || Stdio::from(std::fs::File::create("/dev/full").unwrap());
    // The picture to a full standard output, the result to keep.txt.
    let out = cagd(
        d,
        &[
            "decasteljau",
            CURVE,
            "--t",
            "0:0.5:1",
            "--plot",
            "-",
            "-o",
            "keep.txt",
        ],
    )
    .stdout(full())
    .output()
    .unwrap();
    refused(
        &out,
        "no space left on the device; no output file was replaced",
    );
    assert_eq!(std::fs::read_to_string(d.join("keep.txt")).unwrap(), "old");
    // The result to a full standard output, the picture to a file that exists.
    std::fs::write(d.join("p.svg"), "old picture").unwrap();
    let out = cagd(d, &["decasteljau", CURVE, "--t", "0.5", "--plot", "p.svg"])
        .stdout(full())
        .output()
        .unwrap();
    refused(&out, "standard output: cannot write");
    assert_eq!(
        std::fs::read_to_string(d.join("p.svg")).unwrap(),
        "old picture"
    );
    no_temporaries(d);
    // And a command that fails in its work keeps the file too.
    let out = cagd(d, &["decasteljau", "[0 1; 2]", "-o", "keep.txt"])
        .output()
        .unwrap();
    refused(&out, "CONTROL");
    assert_eq!(std::fs::read_to_string(d.join("keep.txt")).unwrap(), "old");
}

/// Started as the shell starts `cagd … >&-`.
fn with_stdout_closed(dir: &Path, args: &[&str]) -> Output {
    Command::new("sh")
        .current_dir(dir)
        .arg("-c")
        .arg("exec \"$0\" \"$@\" >&-")
        .arg(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn a_closed_standard_output_is_an_error_and_replaces_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let out = with_stdout_closed(d, &["bernstein", "--degree", "1", "--t", "0.5"]);
    refused(&out, "standard output: cannot write: it is closed");
    let out = with_stdout_closed(d, &["decasteljau", CURVE, "--plot", "p.svg", "--t", "1"]);
    refused(&out, "no output file was replaced");
    assert!(!d.join("p.svg").exists());
    no_temporaries(d);
    // Nothing for standard output: the command succeeds.
    let out = with_stdout_closed(
        d,
        &["bernstein", "--degree", "1", "--t", "0.5", "-o", "r.txt"],
    );
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    assert!(std::fs::read_to_string(d.join("r.txt"))
        .unwrap()
        .contains("0.5"));
    // A standard output sent to /dev/null is not closed.
    let out = cagd(d, &["bernstein", "--degree", "1", "--t", "0.5"])
        .stdout(Stdio::null())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
}

#[cfg(unix)]
#[test]
fn symbolic_links_are_followed_and_stay_links() {
    use std::os::unix::fs::symlink;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir(d.join("elsewhere")).unwrap();
    for name in ["r.txt", "p.svg", "m.obj"] {
        std::fs::write(d.join("elsewhere").join(name), "old").unwrap();
        symlink(format!("elsewhere/{name}"), d.join(format!("link-{name}"))).unwrap();
    }
    symlink("link-r.txt", d.join("chain.txt")).unwrap();
    let args = [
        "surface",
        "[u; v; u.*v]",
        "--n",
        "3",
        "-o",
        "link-r.txt",
        "--plot",
        "link-p.svg",
        "--mesh",
        "link-m.obj",
    ];
    let out = cagd(d, &args).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    for (name, part) in [
        ("r.txt", "result(:,:,3)"),
        ("p.svg", "<svg"),
        ("m.obj", "\nf "),
    ] {
        let link = d.join(format!("link-{name}"));
        assert!(link.symlink_metadata().unwrap().file_type().is_symlink());
        let text = std::fs::read_to_string(d.join("elsewhere").join(name)).unwrap();
        assert!(text.contains(part), "{name}: {text:.40}");
    }
    no_temporaries(d);
    no_temporaries(&d.join("elsewhere"));
    // A chain of links; a dangling link creates its target.
    let out = cagd(
        d,
        &[
            "bernstein",
            "--degree",
            "1",
            "--t",
            "0.5",
            "-o",
            "chain.txt",
        ],
    )
    .output()
    .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(d.join("chain.txt").symlink_metadata().unwrap().is_symlink());
    assert!(std::fs::read_to_string(d.join("elsewhere/r.txt"))
        .unwrap()
        .contains("0.5"));
    symlink("elsewhere/new.txt", d.join("dangling.txt")).unwrap();
    let out = cagd(
        d,
        &[
            "bernstein",
            "--degree",
            "1",
            "--t",
            "0.5",
            "-o",
            "dangling.txt",
        ],
    )
    .output()
    .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(d.join("elsewhere/new.txt").is_file());
    // A loop of links, and a link into a missing folder, are refused before any work.
    symlink("loop-b", d.join("loop-a")).unwrap();
    symlink("loop-a", d.join("loop-b")).unwrap();
    symlink("nowhere/x.svg", d.join("astray.svg")).unwrap();
    let out = cagd(d, &["decasteljau", CURVE, "--plot", "loop-a", "--t", "1"])
        .output()
        .unwrap();
    refused(&out, "--plot loop-a: is a loop of symbolic links");
    let out = cagd(
        d,
        &["decasteljau", CURVE, "--plot", "astray.svg", "--t", "1"],
    )
    .output()
    .unwrap();
    refused(
        &out,
        "the folder nowhere does not exist (the link's target nowhere/x.svg)",
    );
    assert!(d.join("astray.svg").is_symlink());
}

#[cfg(unix)]
#[test]
fn an_output_that_is_an_input_is_refused_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::create_dir(d.join("sub")).unwrap();
    let points = "0 1 3\n0 2 0\n";
    std::fs::write(d.join("pts.txt"), points).unwrap();
    std::fs::hard_link(d.join("pts.txt"), d.join("hard.txt")).unwrap();
    std::os::unix::fs::symlink("pts.txt", d.join("soft.txt")).unwrap();
    std::fs::write(
        d.join("net.txt"),
        "# name: B\n# type: matrix\n# rows: 2\n# columns: 3\n 0 1 3\n 0 2 0\n",
    )
    .unwrap();
    let absolute = d.join("pts.txt").to_str().unwrap().to_string();
    // The work would fail on --t: the refusal of -o comes first, before any work.
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["decasteljau", "pts.txt", "--t", "[0.5", "-o", "pts.txt"],
            "-o pts.txt",
        ),
        (
            vec!["decasteljau", "pts.txt", "--t", "[0.5", "-o", "./pts.txt"],
            "-o ./pts.txt",
        ),
        (
            vec![
                "decasteljau",
                "pts.txt",
                "--t",
                "[0.5",
                "-o",
                "sub/../pts.txt",
            ],
            "-o sub/",
        ),
        (
            vec!["decasteljau", &absolute, "--t", "[0.5", "-o", "pts.txt"],
            "-o pts.txt",
        ),
        (
            vec!["decasteljau", "pts.txt", "--t", "[0.5", "-o", "hard.txt"],
            "-o hard.txt",
        ),
        (
            vec!["decasteljau", "soft.txt", "--t", "[0.5", "-o", "pts.txt"],
            "-o pts.txt",
        ),
        (
            vec![
                "decasteljau",
                "pts.txt",
                "--t",
                "[0.5",
                "--plot",
                "soft.txt",
            ],
            "--plot soft.txt",
        ),
        (
            vec!["decasteljau", "net.txt:B", "--t", "[0.5", "-o", "net.txt"],
            "-o net.txt",
        ),
        (
            vec![
                "coons", "--c1", "pts.txt", "--c2", "[u;1]", "--d1", "[0;v]", "--d2", "[1;v]",
                "-o", "pts.txt",
            ],
            "-o pts.txt",
        ),
    ];
    for (args, named) in cases {
        let out = cagd(d, &args).output().unwrap();
        let line = refused(&out, named);
        assert!(line.contains("is also an input"), "{args:?}: {line}");
        assert_eq!(std::fs::read_to_string(d.join("pts.txt")).unwrap(), points);
    }
    // In-process (`cagd_cli::run`), the same refusal.
    let p = |name: &str| d.join(name).to_str().unwrap().to_string();
    let (input, output) = (p("pts.txt"), p("hard.txt"));
    let err =
        cagd_cli::run(["cagd", "decasteljau", &input, "--t", "[0.5", "-o", &output]).unwrap_err();
    assert_eq!(err.kind, cagd_cli::ErrorKind::Usage);
    assert!(err.problem.starts_with("is also an input"), "{err}");
    // Standard input redirected from the output file.
    let out = cagd(d, &["decasteljau", "-", "--t", "0.5", "-o", "pts.txt"])
        .stdin(std::fs::File::open(d.join("pts.txt")).unwrap())
        .output()
        .unwrap();
    refused(&out, "is also an input (`-`)");
    assert_eq!(std::fs::read_to_string(d.join("pts.txt")).unwrap(), points);
    // A different file is fine.
    let out = cagd(
        d,
        &["decasteljau", "pts.txt", "--t", "0.5", "-o", "out.txt"],
    )
    .output()
    .unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
}

#[cfg(unix)]
#[test]
fn read_only_outputs_are_refused_and_permissions_kept() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    std::fs::write(d.join("ro.txt"), "old").unwrap();
    std::fs::set_permissions(d.join("ro.txt"), std::fs::Permissions::from_mode(0o444)).unwrap();
    std::os::unix::fs::symlink("ro.txt", d.join("ro-link.txt")).unwrap();
    for target in ["ro.txt", "ro-link.txt"] {
        let out = cagd(
            d,
            &["bernstein", "--degree", "1", "--t", "0.5", "-o", target],
        )
        .output()
        .unwrap();
        refused(&out, "is read-only (mode 0444)");
        assert_eq!(std::fs::read_to_string(d.join("ro.txt")).unwrap(), "old");
    }
    let out = cagd(d, &["decasteljau", CURVE, "--t", "1", "--plot", "ro.txt"])
        .output()
        .unwrap();
    refused(&out, "--plot ro.txt: is read-only");
    // A writable file keeps its mode when it is replaced.
    std::fs::write(d.join("rw.txt"), "old").unwrap();
    std::fs::set_permissions(d.join("rw.txt"), std::fs::Permissions::from_mode(0o640)).unwrap();
    let out = cagd(
        d,
        &["bernstein", "--degree", "1", "--t", "0.5", "-o", "rw.txt"],
    )
    .output()
    .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(mode(&d.join("rw.txt")), 0o640);
    assert_eq!(mode(&d.join("ro.txt")), 0o444);
    no_temporaries(d);
}

/// Ctrl-C (SIGINT) or SIGTERM while a large output is being written: the process ends by the
/// signal, and neither the temporary file nor a partial output is left.
#[cfg(unix)]
#[test]
fn a_signal_during_a_write_leaves_no_temporary_file() {
    for signal in ["INT", "TERM"] {
        // On a busy machine the write may end before the signal lands: then the same command
        // with a longer output is tried again (the rule is checked only on a write that was
        // really interrupted).
        let interrupted = [400_000, 1_000_000, 2_000_000]
            .into_iter()
            .any(|samples| interrupt_a_write(signal, samples));
        assert!(
            interrupted,
            "SIG{signal}: every write ended before the signal"
        );
    }
}

/// Starts `bernstein --n SAMPLES -o big.csv` over an old `big.csv`, sends `SIGNAL` once the
/// temporary file is there, and checks what an interrupted write must leave: the old file and
/// no temporary. False when the command finished before the signal arrived.
fn interrupt_a_write(signal: &str, samples: usize) -> bool {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("big.csv"), "old").unwrap();
    let n = samples.to_string();
    let args = [
        "bernstein",
        "--degree",
        "3",
        "--n",
        &n,
        "--format",
        "csv",
        "-o",
        "big.csv",
    ];
    let mut child = cagd(d, &args)
        .env("CAGD_MAX_SAMPLES", "2000000")
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Wait for the temporary file to appear, then interrupt.
    let started = std::time::Instant::now();
    while !files_in(d).iter().any(|f| f.starts_with(".cagd-")) {
        if child.try_wait().unwrap().is_some() {
            panic!("the command ended before its temporary file was seen");
        }
        assert!(started.elapsed().as_secs() < 120, "no temporary file");
        std::thread::sleep(std::time::Duration::from_micros(200));
    }
    let kill = Command::new("kill")
        .args([format!("-{signal}"), child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let status = child.wait().unwrap();
    no_temporaries(d);
    if status.success() {
        assert_ne!(std::fs::read_to_string(d.join("big.csv")).unwrap(), "old");
        return false;
    }
    let expected = if signal == "INT" { 2 } else { 15 };
    assert_eq!(status.signal(), Some(expected), "{status:?}");
    assert_eq!(std::fs::read_to_string(d.join("big.csv")).unwrap(), "old");
    true
}

#[test]
fn messages_quote_paths_escaped_on_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (path, shown) in [
        ("no\x1b]0;T\x07dir/x", "no\\u{1b}]0;T\\u{7}dir/x"),
        ("two\nlines/x.txt", "two\\nlines/x.txt"),
        ("tab\there/x.txt", "tab\\there/x.txt"),
    ] {
        let out = cagd(d, &["bernstein", "--degree", "1", "--t", "0.5", "-o", path])
            .output()
            .unwrap();
        let line = refused(&out, shown);
        assert!(
            !line.trim_end().contains(|c: char| c.is_control()),
            "{line:?}"
        );
        // The same text as an input (a literal that does not parse, or a missing file).
        let out = cagd(d, &["decasteljau", path]).output().unwrap();
        let line = refused(&out, "CONTROL");
        assert!(
            !line.trim_end().contains(|c: char| c.is_control()),
            "{line:?}"
        );
    }
    let out = cagd(d, &["decasteljau", "in\x1bdir/x.txt"])
        .output()
        .unwrap();
    refused(
        &out,
        "CONTROL in\\u{1b}dir/x.txt: no such file or directory",
    );
    // An empty path, and a folder given as an input file.
    let out = cagd(d, &["bernstein", "--degree", "1", "-o", ""])
        .output()
        .unwrap();
    let line = refused(
        &out,
        "--output: invalid value '' (an empty path names no file)",
    );
    assert!(!line.contains("one of"), "{line}");
    std::fs::create_dir(d.join("points")).unwrap();
    let out = cagd(d, &["decasteljau", "/etc"]).output().unwrap();
    refused(&out, "CONTROL /etc: is a folder, not a file");
    let out = cagd(d, &["decasteljau", "points/"]).output().unwrap();
    refused(&out, "is a folder, not a file");
}

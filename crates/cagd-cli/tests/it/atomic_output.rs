//! Every file the command line writes (`-o`, `--plot`, `--mesh`, `thesis --out`) is staged in
//! memory by `cagd_cli::run` and written by `PendingWrites::commit`: all files go to
//! temporary names first and are renamed only when every one of them was written, so a
//! failure on any output leaves none.

use std::path::Path;

use assert_cmd::Command;
use cagd_cli::{run, PendingWrites};

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn run_stages_every_output_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let (out, plot, mesh) = (p("r.txt"), p("s.svg"), p("s.stl"));
    let outcome = run([
        "cagd",
        "surface",
        "[u; v; u.*v]",
        "--n",
        "3",
        "-o",
        &out,
        "--plot",
        &plot,
        "--mesh",
        &mesh,
    ])
    .unwrap();
    let staged: Vec<_> = outcome.files.paths().map(|p| p.to_owned()).collect();
    assert_eq!(staged.len(), 3);
    assert!(files_in(dir.path()).is_empty(), "run wrote files");
    assert!(outcome.stdout.is_empty(), "the result went to -o");
    let text = outcome.files.contents(Path::new(&out)).unwrap().to_vec();
    assert!(String::from_utf8(text).unwrap().contains("result(:,:,3)"));
    outcome.files.commit().unwrap();
    assert_eq!(files_in(dir.path()), ["r.txt", "s.stl", "s.svg"]);

    // thesis --out: the folder is created only at commit.
    let out_dir = dir.path().join("thesis-out");
    let outcome = run(["cagd", "thesis", "--out", out_dir.to_str().unwrap()]).unwrap();
    assert!(!out_dir.exists());
    let n = outcome.files.paths().count();
    assert!(n >= 10, "{n} thesis files");
    outcome.files.commit().unwrap();
    assert_eq!(files_in(&out_dir).len(), n);
}

#[test]
fn a_failing_second_output_leaves_no_first_output() {
    let dir = tempfile::tempdir().unwrap();
    let mut files = PendingWrites::new();
    files.add("-o", dir.path().join("first.txt"), b"first".to_vec());
    files.add(
        "--plot",
        dir.path().join("missing/second.svg"),
        b"<svg/>".to_vec(),
    );
    let err = files.commit().unwrap_err();
    assert!(err.argument.starts_with("--plot "), "{err}");
    assert!(err.problem.contains("does not exist"), "{err}");
    assert_eq!(err.exit_code(), 2);
    assert!(
        files_in(dir.path()).is_empty(),
        "{:?}",
        files_in(dir.path())
    );
}

/// Through the binary: -o, --plot and --mesh, with the last one unwritable (its folder does
/// not exist, or it is a folder): exit 2, and neither of the others exists, nor any temporary.
#[test]
fn the_binary_writes_all_outputs_or_none() {
    for (bad_plot, bad_mesh) in [(false, true), (true, false)] {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir(dir.path().join("a-folder.stl")).unwrap();
        let plot = if bad_plot { "nowhere/p.svg" } else { "p.svg" };
        let mesh = if bad_mesh { "a-folder.stl" } else { "m.stl" };
        let out = Command::cargo_bin("cagd")
            .unwrap()
            .current_dir(dir.path())
            .args([
                "surface",
                "[u; v; u.*v]",
                "--n",
                "3",
                "-o",
                "r.txt",
                "--plot",
                plot,
            ])
            .args(["--mesh", mesh])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{plot} {mesh}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert_eq!(files_in(dir.path()), ["a-folder.stl"], "{plot} {mesh}");
        assert!(files_in(&dir.path().join("a-folder.stl")).is_empty());
    }
    // The same command with writable outputs writes all three.
    let dir = tempfile::tempdir().unwrap();
    let ok = Command::cargo_bin("cagd")
        .unwrap()
        .current_dir(dir.path())
        .args([
            "surface",
            "[u; v; u.*v]",
            "--n",
            "3",
            "-o",
            "r.txt",
            "--plot",
            "p.svg",
        ])
        .args(["--mesh", "m.stl"])
        .output()
        .unwrap();
    assert_eq!(ok.status.code(), Some(0));
    assert_eq!(files_in(dir.path()), ["m.stl", "p.svg", "r.txt"]);
}

#[test]
fn octave_text_files_are_written_atomically() {
    use cagd_octave::text_format::{write_text_file, Workspace};
    let dir = tempfile::tempdir().unwrap();
    let mut ws = Workspace::new();
    ws.insert("x", 2.5);
    write_text_file(dir.path().join("x.txt"), &ws).unwrap();
    assert!(write_text_file(dir.path().join("no/x.txt"), &ws).is_err());
    let mut bad = Workspace::new();
    bad.insert("not a name", 1.0);
    assert!(write_text_file(dir.path().join("bad.txt"), &bad).is_err());
    assert_eq!(files_in(dir.path()), ["x.txt"]);
}

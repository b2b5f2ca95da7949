//! The command line's contract for bad input, shared by the tables of bad inputs
//! (`crates/cagd-cli/tests/it/cli.rs`, `crates/cagd-cli/tests/it/bad_inputs.rs`): exit code 2, nothing on standard output, one line
//! on standard error of the form `cagd: error: ARGUMENT: PROBLEM; expected FORM`, no panic,
//! and no file left behind.

use std::fmt::Debug;
use std::path::Path;

use assert_cmd::Command;

/// Runs `cmd`, which must refuse its input, and checks the contract (and, with `dir`, that
/// `dir` is still empty afterwards). Returns the error line, or what broke the contract.
pub fn refused(cmd: &mut Command, dir: Option<&Path>) -> Result<String, String> {
    let out = cmd.output().map_err(|e| format!("cannot run cagd: {e}"))?;
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let lines: Vec<&str> = stderr.lines().collect();
    let broken = if out.status.code() != Some(2) {
        Some(format!("exit code {:?}", out.status.code()))
    } else if !out.stdout.is_empty() {
        Some("printed a result".to_string())
    } else if lines.len() != 1 {
        Some("not one line on standard error".to_string())
    } else if !lines[0].starts_with("cagd: error: ") || !lines[0].contains("; expected ") {
        Some("not of the form `cagd: error: ARGUMENT: PROBLEM; expected FORM`".to_string())
    } else if stderr.contains("panicked") || stderr.contains("RUST_BACKTRACE") {
        Some("panicked".to_string())
    } else {
        dir.map(files_in)
            .filter(|files| !files.is_empty())
            .map(|files| format!("left files behind: {files:?}"))
    };
    match broken {
        Some(problem) => Err(format!("{problem}; stderr {stderr:?}")),
        None => Ok(lines[0].to_string()),
    }
}

/// The names of the files in `dir`.
pub fn files_in(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

/// Checks that the error line names what it should.
pub fn mentions(line: &str, message: &str) -> Result<(), String> {
    if line.contains(message) {
        Ok(())
    } else {
        Err(format!(
            "the error line does not contain {message:?}: {line}"
        ))
    }
}

/// Runs `check` on every case of a table and fails the test once, listing every case that
/// failed and why.
pub fn check_all<C: Debug>(
    cases: impl IntoIterator<Item = C>,
    mut check: impl FnMut(&C) -> Result<(), String>,
) {
    let failures: Vec<String> = cases
        .into_iter()
        .filter_map(|case| check(&case).err().map(|e| format!("{case:?}: {e}")))
        .collect();
    assert!(
        failures.is_empty(),
        "{} case(s) failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

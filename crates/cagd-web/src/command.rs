//! A whole command line in the browser: [`cagd_cli::run`] with input files from the page.

use std::cell::RefCell;

use serde_json::json;
use wasm_bindgen::prelude::wasm_bindgen;

thread_local! {
    /// The files of the last [`run`], for [`file_bytes`].
    static LAST_FILES: RefCell<Vec<Vec<u8>>> = const { RefCell::new(Vec::new()) };
}

/// Runs the command line `argv` (the program name first, as the shell would pass it) with the
/// input files `names[i]` holding `texts[i]` (a data script typed into the page), and answers
/// in JSON:
///
/// - `{"ok": true, "stdout": TEXT, "warnings": [LINE…], "files": [{"path": P, "size": N}…]}`,
///   the warnings as the program prints them (`cagd: warning: …`), the files staged (read each
///   with [`file_bytes`]);
/// - `{"ok": false, "error": "cagd: error: ARG: PROBLEM; expected FORM", "code": 2, "limit": L}`,
///   `L` the resource limit that refused the request (e.g. `"max_work"`), else `null`.
///
/// ```
/// let answer = cagd_web::run(
///     ["cagd", "bernstein", "--degree", "2", "--t", "0.5", "--exact"].map(String::from).to_vec(),
///     vec![],
///     vec![],
/// );
/// let v: serde_json::Value = serde_json::from_str(&answer).unwrap();
/// assert_eq!(v["ok"], true);
/// assert!(v["stdout"].as_str().unwrap().contains("1/4  1/2  1/4"));
/// ```
#[wasm_bindgen]
pub fn run(argv: Vec<String>, names: Vec<String>, texts: Vec<String>) -> String {
    let files: Vec<(String, String)> = names.into_iter().zip(texts).collect();
    let answer = match cagd_cli::run_with_files(argv, files) {
        Ok(outcome) => {
            let paths: Vec<_> = outcome.files.paths().map(|p| p.to_path_buf()).collect();
            let staged: Vec<serde_json::Value> = paths
                .iter()
                .map(|p| {
                    let size = outcome.files.contents(p).map_or(0, <[u8]>::len);
                    json!({ "path": p.display().to_string(), "size": size })
                })
                .collect();
            let bytes = paths
                .iter()
                .map(|p| outcome.files.contents(p).unwrap_or_default().to_vec())
                .collect();
            LAST_FILES.with(|f| *f.borrow_mut() = bytes);
            let warnings: Vec<String> = outcome
                .warnings
                .iter()
                .map(|(argument, w)| format!("cagd: warning: {argument}: {w}"))
                .collect();
            json!({
                "ok": true,
                "stdout": outcome.stdout,
                "warnings": warnings,
                "files": staged,
            })
        }
        Err(e) => {
            LAST_FILES.with(|f| f.borrow_mut().clear());
            json!({
                "ok": false,
                "error": format!("cagd: error: {e}"),
                "code": e.exit_code(),
                "limit": e.limit().map(|l| l.field()),
            })
        }
    };
    answer.to_string()
}

/// The contents of file `index` of the last [`run`] (empty if there is no such file).
#[wasm_bindgen]
pub fn file_bytes(index: usize) -> Vec<u8> {
    LAST_FILES.with(|f| f.borrow().get(index).cloned().unwrap_or_default())
}

#[cfg(test)]
mod slips;

#[cfg(test)]
mod tests {
    use super::*;

    fn answer(args: &[&str]) -> serde_json::Value {
        let argv = std::iter::once("cagd")
            .chain(args.iter().copied())
            .map(String::from)
            .collect();
        serde_json::from_str(&run(argv, vec![], vec![])).unwrap()
    }

    #[test]
    fn primer_2_4_with_its_picture() {
        let v = answer(&[
            "decasteljau",
            "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'",
            "--t",
            "0.5",
            "--steps",
            "--exact",
            "--plot",
            "curve.svg",
        ]);
        assert_eq!(v["ok"], true);
        let stdout = v["stdout"].as_str().unwrap();
        for value in ["7/2", "3/2", "3/4"] {
            assert!(stdout.contains(value), "{stdout}");
        }
        assert_eq!(v["files"][0]["path"], "curve.svg");
        let svg = String::from_utf8(file_bytes(0)).unwrap();
        assert!(svg.starts_with("<svg"));
        assert_eq!(svg.len() as u64, v["files"][0]["size"].as_u64().unwrap());
    }

    #[test]
    fn errors_read_as_the_program_prints_them() {
        let v = answer(&["decasteljau", "[1 2; 3]"]);
        assert_eq!(v["ok"], false);
        assert_eq!(v["code"], 2);
        let e = v["error"].as_str().unwrap();
        assert!(e.starts_with("cagd: error: CONTROL: "), "{e}");
        assert!(v["limit"].is_null());
        assert!(file_bytes(0).is_empty());
        // A limit names itself, so that the page can run a command on its main thread under a
        // small work limit and hand the ones above it to a worker.
        let v = answer(&[
            "bernstein",
            "--degree",
            "3",
            "--n",
            "101",
            "--max-work",
            "10",
        ]);
        assert_eq!(v["limit"], "max_work");
        assert!(v["error"].as_str().unwrap().contains("--max-work"));
        let v = answer(&["serve"]);
        assert!(v["error"]
            .as_str()
            .unwrap()
            .starts_with("cagd: error: serve: "));
    }

    #[test]
    fn scripts_come_from_the_page() {
        let argv = ["cagd", "script", "data.m"].map(String::from).to_vec();
        let v: serde_json::Value = serde_json::from_str(&run(
            argv,
            vec!["data.m".into()],
            vec!["x = 1:3; c = [u; 0; u-u^2];".into()],
        ))
        .unwrap();
        assert_eq!(v["ok"], true, "{v}");
        assert!(v["stdout"].as_str().unwrap().contains("x ="));
    }

    /// Issue 24 through the page's command box: each slip gives its note, warning or error,
    /// worded as on the command line, and the explicit readings stay silent.
    #[test]
    fn slips_are_named_in_the_command_box_and_explicit_readings_are_silent() {
        let note = "cagd: warning: CONTROL: read as 3 points in 3-D, one per column; --rows if each row is a point";
        let v = answer(&["decasteljau", "[0 0 0; 1 2 0; 2 0 1]", "--t", "0.5"]);
        assert_eq!(v["warnings"], serde_json::json!([note]));
        for stated in ["--rows", "--columns"] {
            let v = answer(&["decasteljau", "[0 0 0; 1 2 0; 2 0 1]", "--t", "0.5", stated]);
            assert_eq!(v["warnings"], serde_json::json!([]), "{stated}");
        }
        let v = answer(&["decasteljau", "[0,5 1,0 2,0; 1,5 2,5 0,5]", "--t", "0.5"]);
        assert_eq!(
            v["warnings"][0],
            "cagd: warning: CONTROL: `0,5` read as two numbers 0 and 5; a decimal point is `0.5`"
        );
        let v = answer(&["lagrange", "--nodes", "[0 0,5 1]", "--points", "[1 2 3]"]);
        let e = v["error"].as_str().unwrap();
        assert!(
            e.starts_with("cagd: error: --nodes: ") && e.contains("`0,5` read as two numbers"),
            "{e}"
        );
        let v = answer(&["decastljau", "[0 1]"]);
        assert!(
            v["error"].as_str().unwrap().contains("decasteljau perhaps"),
            "{v}"
        );
        let v = answer(&["decasteljau", "[0.5 1 2; 1.5 2.5 0.5]'", "--t", "0.5"]);
        assert_eq!(v["warnings"], serde_json::json!([]));
    }
}

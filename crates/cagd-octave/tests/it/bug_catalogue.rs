//! The catalogue of the printed code's bugs (`octave_ref/BUGS.md`) against live GNU Octave.
//!
//! - [`originals_behave_as_catalogued`] runs every bug script of `octave_ref/bugs/` (the
//!   ORIGINAL thesis code) under live Octave through `octave_ref/bugs/run_bugs.sh` and fails if
//!   any output differs from the one captured in `octave_ref/bugs/captured/` — an original that
//!   starts behaving differently (a new Octave, a changed transcription) must be looked at and
//!   the catalogue updated. Without Octave it prints `skipped: octave not found` and passes,
//!   unless the environment variable `CI` is set.
//! - [`catalogue_entries_are_complete_and_pinned`] reads `BUGS.md` and checks every entry: the
//!   original files it names exist, its script and captured output exist, the Octave output it
//!   quotes occurs verbatim in the captured output, and every test it names as pinning the fix
//!   exists (`#[test] fn <name>` in the named file); and every bug script has an entry.

use cagd_test_support as common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use common::{octave_available, octave_ref_dir, TempDir};

fn crate_dir() -> PathBuf {
    PathBuf::from(common::WORKSPACE)
}

fn bugs_dir() -> PathBuf {
    octave_ref_dir().join("bugs")
}

/// The bug scripts (every `octave_ref/bugs/*.m` but the helper `bug_setup.m`), by name.
fn bug_scripts() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(bugs_dir())
        .expect("octave_ref/bugs")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter_map(|f| f.strip_suffix(".m").map(str::to_string))
        .filter(|n| n != "bug_setup")
        .collect();
    names.sort();
    names
}

/// One `### B<k>.` entry of the catalogue.
#[derive(Debug, Default)]
struct Entry {
    id: String,
    title: String,
    originals: Vec<String>,
    script: Option<String>,
    pinned_by: Vec<String>,
    quoted: Vec<String>,
    has_cause: bool,
    has_fix: bool,
}

/// The items in backticks of a line.
fn backticked(line: &str) -> Vec<String> {
    line.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

fn parse_catalogue(text: &str) -> Vec<Entry> {
    let mut entries: Vec<Entry> = Vec::new();
    let mut lines = text.lines().peekable();
    let mut in_list_item = "";
    while let Some(line) = lines.next() {
        if let Some(head) = line.strip_prefix("### ") {
            if head.starts_with('B') {
                let (id, title) = head.split_once(". ").expect("### B<k>. title");
                entries.push(Entry {
                    id: id.to_string(),
                    title: title.to_string(),
                    ..Entry::default()
                });
            }
            in_list_item = "";
            continue;
        }
        if line.starts_with("## ") {
            in_list_item = "";
            continue;
        }
        let Some(entry) = entries.last_mut() else {
            continue;
        };
        if let Some(rest) = line.strip_prefix("- Original: ") {
            entry.originals.extend(backticked(rest));
            in_list_item = "original";
        } else if let Some(rest) = line.strip_prefix("- Script: ") {
            entry.script = backticked(rest).into_iter().next();
            in_list_item = "";
        } else if let Some(rest) = line.strip_prefix("- Pinned by: ") {
            entry.pinned_by.extend(backticked(rest));
            in_list_item = "";
        } else if line.starts_with("  ") && in_list_item == "original" {
            entry.originals.extend(backticked(line));
        } else if line.starts_with("Octave 7 writes") {
            in_list_item = "";
            // Skip to the fenced block and take its lines.
            for l in lines.by_ref() {
                if l == "```text" {
                    break;
                }
            }
            for l in lines.by_ref() {
                if l == "```" {
                    break;
                }
                entry.quoted.push(l.to_string());
            }
        } else if line.starts_with("**Cause.**") {
            entry.has_cause = true;
        } else if line.starts_with("**Fix.**") {
            entry.has_fix = true;
        }
    }
    entries
}

fn catalogue() -> Vec<Entry> {
    let path = octave_ref_dir().join("BUGS.md");
    let text = std::fs::read_to_string(&path).expect("octave_ref/BUGS.md");
    parse_catalogue(&text)
}

/// Whether `file` (relative to the crate) holds `#[test]` directly above `fn name(`.
fn test_exists(file: &Path, name: &str) -> bool {
    let Ok(text) = std::fs::read_to_string(crate_dir().join(file)) else {
        return false;
    };
    let lines: Vec<&str> = text.lines().map(str::trim).collect();
    lines.windows(2).any(|w| {
        w[0] == "#[test]"
            && (w[1].starts_with(&format!("fn {name}("))
                || w[1].starts_with(&format!("fn {name}<")))
    })
}

#[test]
fn catalogue_entries_are_complete_and_pinned() {
    let entries = catalogue();
    assert!(entries.len() >= 19, "{} entries in BUGS.md", entries.len());
    let mut scripts_seen: BTreeMap<String, String> = BTreeMap::new();
    for (k, e) in entries.iter().enumerate() {
        let ctx = format!("BUGS.md {} ({})", e.id, e.title);
        assert_eq!(
            e.id,
            format!("B{}", k + 1),
            "{ctx}: entries must be numbered B1, B2, …"
        );
        assert!(
            e.has_cause && e.has_fix,
            "{ctx}: needs **Cause.** and **Fix.**"
        );
        assert!(!e.originals.is_empty(), "{ctx}: names no original file");
        for o in &e.originals {
            assert!(
                o.starts_with("original/") && octave_ref_dir().join(o).is_file(),
                "{ctx}: original `{o}` is not a file under octave_ref/original/"
            );
        }
        let script = e
            .script
            .as_deref()
            .unwrap_or_else(|| panic!("{ctx}: no `- Script:` line"));
        let name = script
            .strip_prefix("bugs/")
            .and_then(|s| s.strip_suffix(".m"))
            .unwrap_or_else(|| panic!("{ctx}: script `{script}` is not bugs/<name>.m"));
        assert!(
            bugs_dir().join(format!("{name}.m")).is_file(),
            "{ctx}: octave_ref/{script} does not exist"
        );
        if let Some(other) = scripts_seen.insert(name.to_string(), e.id.clone()) {
            panic!("{ctx}: script {script} is also the script of {other}");
        }
        let captured_path = bugs_dir().join("captured").join(format!("{name}.txt"));
        let captured = std::fs::read_to_string(&captured_path).unwrap_or_else(|_| {
            panic!(
                "{ctx}: {} missing (run bash octave_ref/bugs/run_bugs.sh)",
                captured_path.display()
            )
        });
        assert!(!e.quoted.is_empty(), "{ctx}: quotes no Octave output");
        let captured_lines: Vec<&str> = captured.lines().collect();
        let quoted: Vec<&str> = e.quoted.iter().map(String::as_str).collect();
        assert!(
            captured_lines
                .windows(quoted.len())
                .any(|w| w == quoted.as_slice()),
            "{ctx}: the quoted Octave output does not occur in captured/{name}.txt\n--- quoted\n{}\n--- captured\n{captured}",
            quoted.join("\n")
        );
        assert!(!e.pinned_by.is_empty(), "{ctx}: no pinning test");
        for pin in &e.pinned_by {
            let (file, test) = pin
                .split_once("::")
                .unwrap_or_else(|| panic!("{ctx}: `{pin}` is not <file>::<test>"));
            assert!(
                test_exists(Path::new(file), test),
                "{ctx}: pinning test `{pin}` does not exist (no `#[test] fn {test}` in {file})"
            );
        }
    }
    for script in bug_scripts() {
        assert!(
            scripts_seen.contains_key(&script),
            "octave_ref/bugs/{script}.m has no entry in BUGS.md"
        );
    }
    let captured: Vec<String> = std::fs::read_dir(bugs_dir().join("captured"))
        .expect("captured/")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    for f in captured {
        let name = f.strip_suffix(".txt").unwrap_or(&f);
        assert!(
            scripts_seen.contains_key(name),
            "octave_ref/bugs/captured/{f} belongs to no bug script"
        );
    }
}

#[test]
fn originals_behave_as_catalogued() {
    if !octave_available("originals_behave_as_catalogued") {
        return;
    }
    let out = TempDir::new("bugs");
    let run = Command::new("bash")
        .arg(bugs_dir().join("run_bugs.sh"))
        .arg(out.path())
        .output()
        .expect("run bash octave_ref/bugs/run_bugs.sh");
    assert!(
        run.status.success(),
        "run_bugs.sh failed\n--- stdout\n{}\n--- stderr\n{}",
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr)
    );
    let by_script: BTreeMap<String, String> = catalogue()
        .into_iter()
        .filter_map(|e| {
            let s = e.script?;
            let name = s.strip_prefix("bugs/")?.strip_suffix(".m")?.to_string();
            Some((name, format!("{}. {}", e.id, e.title)))
        })
        .collect();
    let mut failures = Vec::new();
    let scripts = bug_scripts();
    for name in &scripts {
        let live = std::fs::read_to_string(out.path().join(format!("{name}.txt")))
            .unwrap_or_else(|e| panic!("{name}: no output from run_bugs.sh: {e}"));
        let captured =
            std::fs::read_to_string(bugs_dir().join("captured").join(format!("{name}.txt")))
                .unwrap_or_else(|e| panic!("{name}: captured output missing: {e}"));
        if live != captured {
            let entry = by_script.get(name).map_or("no entry", String::as_str);
            let first = live
                .lines()
                .zip(captured.lines())
                .position(|(a, b)| a != b)
                .unwrap_or(live.lines().count().min(captured.lines().count()));
            failures.push(format!(
                "{name} (BUGS.md {entry}): live Octave differs from captured/{name}.txt from \
                 line {}\n--- captured\n{captured}--- live\n{live}",
                first + 1
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} original(s) behave differently from the catalogue (if on purpose: bash \
         octave_ref/bugs/run_bugs.sh, review, update BUGS.md, commit):\n\n{}",
        failures.len(),
        scripts.len(),
        failures.join("\n")
    );
    eprintln!(
        "[bug catalogue] {} bug script(s) behave under live Octave exactly as captured",
        scripts.len()
    );
}

/// The parser finds what an entry holds (so a malformed entry cannot pass by being skipped).
#[test]
fn catalogue_parser_reads_an_entry() {
    let text = "## X\n\n### B1. Title here\n\n- Original: `original/a.m` line 3,\n  `original/b.m` line 4\n- Script: `bugs/x.m`\n- Pinned by: `tests/t.rs::one`, `tests/t.rs::two`\n\nOctave 7 writes:\n\n```text\nerror: boom\nsecond\n```\n\n**Cause.** c\n\n**Fix.** f\n";
    let e = parse_catalogue(text);
    assert_eq!(e.len(), 1);
    assert_eq!(e[0].id, "B1");
    assert_eq!(e[0].title, "Title here");
    assert_eq!(e[0].originals, ["original/a.m", "original/b.m"]);
    assert_eq!(e[0].script.as_deref(), Some("bugs/x.m"));
    assert_eq!(e[0].pinned_by, ["tests/t.rs::one", "tests/t.rs::two"]);
    assert_eq!(e[0].quoted, ["error: boom", "second"]);
    assert!(e[0].has_cause && e[0].has_fix);
    assert!(test_exists(
        Path::new("crates/cagd-octave/tests/it/bug_catalogue.rs"),
        "catalogue_parser_reads_an_entry"
    ));
    assert!(!test_exists(
        Path::new("crates/cagd-octave/tests/it/bug_catalogue.rs"),
        "no_such_test"
    ));
}

//! Helpers shared by the integration tests of every package of the workspace: the Octave reference files under
//! `octave_ref/expected/`, error measures against them, and running live GNU Octave.
//!
//! # Reference files
//! Each `octave_ref/cases/<case>.m` makes Octave write `octave_ref/expected/<case>.txt`, holding
//! the inputs and the outputs of the case. [`expected`] loads one by case name; [`matrix`],
//! [`array()`] and [`array3`] fetch a variable (failing the test, with the file and name, when it
//! is missing or has another shape).
//!
//! # Tolerance
//! A value agrees with Octave when it is within [`MAX_ULPS`] ULPs of Octave's, or within
//! [`MAX_REL`] relative, whichever is looser. "Relative" is measured against the scale of the
//! compared array: `|ours − octave| / max_k |octave_k|` (the normwise relative error). The
//! scale matters for values near zero: a curve point is a convex combination of control points,
//! so every algorithm's rounding error is proportional to the size of the control points, not
//! to the size of the point. Non-finite values must be identical.
//!
//! [`assert_close`] checks this for a whole array, panics naming the variable, the index and
//! both values of the first offending element, and records the worst error; [`report_worst`]
//! prints the worst error seen by the test binary so far (to stderr: run with `--nocapture`).
//!
//! # Bad input
//! [`bad_input`] checks the command line's contract for bad input, for the tables of bad
//! inputs; [`thesis_args`] holds the command-line arguments of the thesis's examples.
//!
//! # Hostile calls
//! [`hostile_calls`] calls the core's public functions with arbitrary arguments, for the
//! property test that none panics and for the `library` fuzz target.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;

use cagd_octave::text_format::{read_text_file, Workspace};
use ndarray::{Array2, Array3, ArrayD, ArrayViewD, Dimension, Ix3};

pub mod bad_input;
pub mod hostile_calls;
pub mod lcg;
pub mod thesis_args;

/// Largest accepted distance in units in the last place.
pub const MAX_ULPS: u64 = 4;
/// Largest accepted error relative to the scale of the compared array.
pub const MAX_REL: f64 = 1e-14;

/// The root of the workspace (where `octave_ref/` and `tests/data/` are).
pub const WORKSPACE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// The root of the workspace as a path.
pub fn workspace() -> PathBuf {
    Path::new(WORKSPACE).to_path_buf()
}

/// `octave_ref/` of the workspace.
pub fn octave_ref_dir() -> PathBuf {
    workspace().join("octave_ref")
}

/// A file of `tests/data/`.
pub fn data_file(name: &str) -> PathBuf {
    workspace().join("tests").join("data").join(name)
}

/// Loads `octave_ref/expected/<case>.txt`; panics (failing the test) if it is missing or
/// malformed.
pub fn expected(case: &str) -> Workspace {
    let path = octave_ref_dir()
        .join("expected")
        .join(format!("{case}.txt"));
    read_text_file(&path).unwrap_or_else(|e| {
        panic!(
            "cannot load reference file {}: {e} (run bash octave_ref/regenerate.sh)",
            path.display()
        )
    })
}

/// A 2-D numeric variable of a reference file.
pub fn matrix(ws: &Workspace, name: &str) -> Array2<f64> {
    ws.matrix(name)
        .unwrap_or_else(|e| panic!("reference variable: {e}"))
}

/// A numeric variable of any dimension.
pub fn array(ws: &Workspace, name: &str) -> ArrayD<f64> {
    ws.array(name)
        .unwrap_or_else(|e| panic!("reference variable: {e}"))
}

/// A numeric variable as an `a × b × c` array. Octave drops trailing singleton dimensions, so
/// a `2×3×1` array is stored as `2×3`; it is given back as `2×3×1`.
pub fn array3(ws: &Workspace, name: &str) -> Array3<f64> {
    let a = array(ws, name);
    let a = if a.ndim() == 2 {
        let s = a.shape().to_vec();
        a.into_shape_with_order(vec![s[0], s[1], 1])
            .expect("same size")
    } else {
        a
    };
    let shape = a.shape().to_vec();
    a.into_dimensionality::<Ix3>()
        .unwrap_or_else(|_| panic!("reference variable `{name}` is {shape:?}, expected 3-D"))
}

/// A row vector variable (1×n) as a `Vec`.
pub fn row(ws: &Workspace, name: &str) -> Vec<f64> {
    let m = matrix(ws, name);
    assert!(
        m.nrows() == 1 || m.is_empty(),
        "reference variable `{name}` is {:?}, expected a row",
        m.dim()
    );
    m.iter().copied().collect()
}

/// Distance between two finite doubles in units in the last place (0 for `0.0` vs `-0.0`).
pub fn ulp_distance(a: f64, b: f64) -> u64 {
    fn ordered(x: f64) -> i128 {
        let bits = x.to_bits() as i64;
        if bits < 0 {
            -((bits & i64::MAX) as i128)
        } else {
            bits as i128
        }
    }
    (ordered(a) - ordered(b)).unsigned_abs() as u64
}

/// The worst disagreement found in one or more comparisons.
#[derive(Debug, Clone, Default)]
pub struct ErrorStats {
    /// Number of values compared.
    pub compared: usize,
    /// Largest distance in ULPs.
    pub max_ulps: u64,
    /// Where it occurred, with both values (empty while every value is identical).
    pub max_ulps_at: String,
    /// Largest error relative to the scale of its array.
    pub max_rel: f64,
    /// Where it occurred, with both values (empty while every value is identical).
    pub max_rel_at: String,
}

impl ErrorStats {
    /// Merges another comparison into this one.
    pub fn merge(&mut self, other: &ErrorStats) {
        self.compared += other.compared;
        if other.max_ulps > self.max_ulps {
            self.max_ulps = other.max_ulps;
            self.max_ulps_at = other.max_ulps_at.clone();
        }
        if other.max_rel > self.max_rel {
            self.max_rel = other.max_rel;
            self.max_rel_at = other.max_rel_at.clone();
        }
    }
}

impl std::fmt::Display for ErrorStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let at = |s: &str| {
            if s.is_empty() {
                String::new()
            } else {
                format!(" [{s}]")
            }
        };
        write!(
            f,
            "{} value(s) compared; worst {} ULP(s){}; worst relative error {:.3e}{}",
            self.compared,
            self.max_ulps,
            at(&self.max_ulps_at),
            self.max_rel,
            at(&self.max_rel_at)
        )
    }
}

/// Octave-style 1-based subscript `(i,j,k)` of a 0-based index.
fn subscript(index: &[usize]) -> String {
    let parts: Vec<String> = index.iter().map(|i| (i + 1).to_string()).collect();
    format!("({})", parts.join(","))
}

/// Compares `ours` with Octave's array of the same shape, element by element; panics naming
/// `name`, the Octave subscript and both values of the first element outside the tolerance
/// (and on a shape mismatch). Records and returns the errors.
pub fn assert_close<'a, 'b>(
    name: &str,
    ours: impl Into<ArrayViewD<'a, f64>>,
    octave: impl Into<ArrayViewD<'b, f64>>,
) -> ErrorStats {
    let ours = ours.into();
    let octave = octave.into();
    assert_eq!(
        ours.shape(),
        octave.shape(),
        "{name}: shape of ours {:?} differs from Octave's {:?}",
        ours.shape(),
        octave.shape()
    );
    let scale = octave
        .iter()
        .filter(|x| x.is_finite())
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    let mut stats = ErrorStats {
        compared: ours.len(),
        ..ErrorStats::default()
    };
    for ((idx, &a), &b) in ours.indexed_iter().zip(octave.iter()) {
        let at = || format!("{name}{}", subscript(idx.slice()));
        if !(a.is_finite() && b.is_finite()) {
            assert!(
                a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                "{}: ours {a:e}, Octave {b:e}",
                at()
            );
            continue;
        }
        let ulps = ulp_distance(a, b);
        let rel = if scale > 0.0 {
            (a - b).abs() / scale
        } else {
            0.0
        };
        assert!(
            ulps <= MAX_ULPS || rel <= MAX_REL,
            "{}: ours {a:e} ({a:?}), Octave {b:e} ({b:?}): {ulps} ULPs, {rel:.3e} relative to \
             the array scale {scale:e}; allowed {MAX_ULPS} ULPs or {MAX_REL:e} relative",
            at()
        );
        if ulps > stats.max_ulps {
            stats.max_ulps = ulps;
            stats.max_ulps_at = format!("{}: ours {a:?}, Octave {b:?}", at());
        }
        if rel > stats.max_rel {
            stats.max_rel = rel;
            stats.max_rel_at = format!("{}: ours {a:?}, Octave {b:?}", at());
        }
    }
    record(&stats);
    stats
}

/// Asserts that two arrays are identical bit for bit (for linspace, tenzor, inputs).
pub fn assert_identical<'a, 'b>(
    name: &str,
    ours: impl Into<ArrayViewD<'a, f64>>,
    octave: impl Into<ArrayViewD<'b, f64>>,
) {
    let ours = ours.into();
    let octave = octave.into();
    assert_eq!(ours.shape(), octave.shape(), "{name}: shapes differ");
    for ((idx, &a), &b) in ours.indexed_iter().zip(octave.iter()) {
        assert!(
            a.to_bits() == b.to_bits(),
            "{name}{}: ours {a:?}, Octave {b:?} (not bit for bit)",
            subscript(idx.slice())
        );
    }
}

static WORST: Mutex<Option<ErrorStats>> = Mutex::new(None);

/// Adds a comparison to the worst-error record of this test binary.
pub fn record(stats: &ErrorStats) {
    let mut w = WORST.lock().unwrap_or_else(|p| p.into_inner());
    match w.as_mut() {
        Some(all) => all.merge(stats),
        None => *w = Some(stats.clone()),
    }
}

/// The worst error recorded so far by this test binary.
pub fn worst() -> Option<ErrorStats> {
    WORST.lock().unwrap_or_else(|p| p.into_inner()).clone()
}

/// Prints the worst error recorded so far to stderr, with a label.
pub fn report_worst(label: &str) {
    if let Some(w) = worst() {
        eprintln!("[{label}] worst error versus Octave so far: {w}");
    }
}

// ---------------------------------------------------------------------------------------------
// Live Octave

/// Whether GNU Octave can be run. When it cannot: prints `skipped: octave not found` and
/// returns `false` (the caller returns, so the test passes) — unless the environment variable
/// `CI` is set, where a missing Octave fails the test.
pub fn octave_available(test: &str) -> bool {
    let found = Command::new("octave")
        .args(["--no-gui", "--version"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    if !found {
        if std::env::var_os("CI").is_some() {
            panic!("{test}: octave not found, and CI is set: CI must have GNU Octave");
        }
        // Written to the stream directly, not with eprintln!, so that the test harness does not
        // capture it: the skip must be visible in a plain `cargo test`.
        use std::io::Write;
        let _ = writeln!(std::io::stderr(), "{test}: skipped: octave not found");
    }
    found
}

/// A fresh empty directory under the system's temporary directory, removed when dropped.
pub struct TempDir(PathBuf);

impl TempDir {
    /// Creates `<tmp>/cagd-<label>-<pid>-<n>`.
    pub fn new(label: &str) -> TempDir {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static N: AtomicUsize = AtomicUsize::new(0);
        let dir = std::env::temp_dir().join(format!(
            "cagd-{label}-{}-{}",
            std::process::id(),
            N.fetch_add(1, Ordering::Relaxed)
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create temporary directory");
        TempDir(dir)
    }

    /// The directory.
    pub fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs an Octave script (written to `dir/<name>.m`, run with `dir` as the working directory)
/// in one Octave process and returns what it printed to stdout. Panics with Octave's output if
/// the script does not print `DONE` as its last step: Octave 7 may print `error: ignoring const
/// execution_exception& while preparing to exit` and its exit status is not a reliable signal,
/// so scripts end with `disp('DONE')`.
pub fn run_octave(dir: &Path, name: &str, script: &str) -> String {
    let file = dir.join(format!("{name}.m"));
    std::fs::write(&file, script).expect("write Octave script");
    let out = Command::new("octave")
        .args(["--no-gui", "--no-window-system", "--quiet", "--norc"])
        .arg(format!("{name}.m"))
        .current_dir(dir)
        .output()
        .expect("run octave");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(
        stdout.lines().any(|l| l.trim() == "DONE"),
        "Octave script {name}.m did not finish (exit status {:?})\n--- stdout\n{stdout}\n--- stderr\n{stderr}",
        out.status.code()
    );
    stdout
}

//! The crate against GNU Octave: every file under `octave_ref/expected/` was written by Octave
//! (`octave_ref/cases/*.m` running the fixed thesis functions in `octave_ref/fixed/`), holds
//! the inputs and the outputs of its case, and is compared here with the crate's results.
//!
//! Naming conventions the tests below rely on (so a new case following them needs no new Rust):
//! - `linspace_samples`: `lin_<key>_a`, `lin_<key>_b` (the interval) and `lin_<key>_n<n>`
//!   (Octave's `linspace(a, b, n)`), compared bit for bit;
//! - curve files (`curves`, `primer_2_4`): `P_<key>` (d × (n+1) control points, one per
//!   column), `t_N<N>` (`linspace(0,1,N)`), `T_<key>_N<N>` (d × N, the fixed `deCasteljau`);
//! - patch files (`patches`): `B_<key>` ((m+1) × 3(n+1) packed net), `A_<key>`
//!   (`tenzor(B)`, (m+1) × (n+1) × 3), `t_N<N>`, `P_<key>_N<N>` (N × N × 3, the fixed
//!   `ploskevB`).
//!
//! Tolerance: 4 ULPs or 1e-14 relative, whichever is looser (see `crates/cagd-test-support/src/lib.rs`). Run
//! with `--nocapture` to see the worst error observed.

use cagd_test_support as common;

use cagd::bezier::BezierCurve;
use cagd::Surface;
use cagd_octave::Workspace;
use common::{assert_close, assert_identical, expected, matrix, row, ErrorStats};
use nalgebra::DMatrix;
use ndarray::{Array2, Array3};

/// The interval keys of `linspace_samples`, from the `lin_<key>_a` variables.
fn linspace_keys(ws: &cagd_octave::Workspace) -> Vec<String> {
    ws.names()
        .filter_map(|n| n.strip_prefix("lin_")?.strip_suffix("_a"))
        .map(str::to_string)
        .collect()
}

/// Every file Octave wrote under `octave_ref/expected/` reads without error.
#[test]
fn every_reference_file_reads() {
    let dir = common::octave_ref_dir().join("expected");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("octave_ref/expected")
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "txt"))
        .collect();
    files.sort();
    assert!(files.len() >= 4, "reference files in {}", dir.display());
    for f in &files {
        let ws = cagd_octave::read_text_file(f).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        assert!(!ws.is_empty(), "{}: no variables", f.display());
    }
}

#[test]
fn linspace_matches_octave_bit_for_bit() {
    let ws = expected("linspace_samples");
    let keys = linspace_keys(&ws);
    assert_eq!(
        keys,
        ["a0_b1", "am1_b1", "a0p3_b7p1", "a1_b0", "am3p7_b1000"],
        "the intervals of octave_ref/cases/linspace_samples.m"
    );
    let mut compared = 0;
    for key in &keys {
        let a = ws.scalar(&format!("lin_{key}_a")).unwrap();
        let b = ws.scalar(&format!("lin_{key}_b")).unwrap();
        for n in 0..=200 {
            let name = format!("lin_{key}_n{n}");
            let octave = row(&ws, &name);
            assert_eq!(octave.len(), n, "{name}");
            let ours = cagd::linspace(a, b, n);
            for (i, (x, y)) in ours.iter().zip(&octave).enumerate() {
                assert!(
                    x.to_bits() == y.to_bits(),
                    "{name}({}): ours {x:?}, Octave {y:?} (linspace must be bit for bit)",
                    i + 1
                );
            }
            compared += n;
        }
    }
    eprintln!("[linspace] {compared} values identical to Octave's, bit for bit");
}

/// The reference files themselves against the thesis: Primer 2.4 gives b(0.5) = (3.5, 1.5,
/// 0.75), and the fixed `deCasteljau` must reproduce it (a second oracle for the Octave side).
#[test]
fn primer_2_4_reference_agrees_with_the_thesis() {
    let ws = expected("primer_2_4");
    assert_eq!(
        matrix(&ws, "P_primer_2_4"),
        ndarray::array![
            [0.0, 0.0, 8.0, 4.0],
            [0.0, 2.0, 2.0, 0.0],
            [0.0, 2.0, 0.0, 0.0]
        ]
    );
    assert_eq!(row(&ws, "t_N3"), [0.0, 0.5, 1.0]);
    let t = matrix(&ws, "T_primer_2_4_N3");
    assert_eq!(t.column(1).to_vec(), [3.5, 1.5, 0.75]);
    // End-point interpolation.
    assert_eq!(t.column(0).to_vec(), [0.0, 0.0, 0.0]);
    assert_eq!(t.column(2).to_vec(), [4.0, 0.0, 0.0]);
}

/// Every `t_N<N>` in the curve and patch files is `linspace(0,1,N)` bit for bit, so the
/// parameters the crate evaluates at are the ones Octave used.
#[test]
fn sample_parameters_are_octave_linspace() {
    for case in ["curves", "patches", "primer_2_4"] {
        let ws = expected(case);
        let mut found = 0;
        for name in ws.names().filter(|n| n.starts_with("t_N")) {
            let n: usize = name["t_N".len()..].parse().expect("t_N<N>");
            let t = Array2::from_shape_vec((1, n), cagd::linspace(0.0, 1.0, n)).unwrap();
            assert_identical(
                &format!("{case}: {name}"),
                &t.into_dyn(),
                &matrix(&ws, name).into_dyn(),
            );
            found += 1;
        }
        assert_eq!(found, 4, "{case}: expected t_N2, t_N3, t_N10, t_N101");
    }
}

/// `A_<key> = tenzor(B_<key>)`: the packed layout is `B(i, 3j+c) = A(i, j, c)` (0-based).
#[test]
fn tenzor_reference_matches_the_packed_layout() {
    let ws = expected("patches");
    let mut found = 0;
    for name in ws.names().filter(|n| n.starts_with("B_deg")) {
        let key = &name[2..];
        let b = matrix(&ws, name);
        let a = common::array3(&ws, &format!("A_{key}"));
        let (m1, n1) = (b.nrows(), b.ncols() / 3);
        let unpacked = Array3::from_shape_fn((m1, n1, 3), |(i, j, c)| b[[i, 3 * j + c]]);
        assert_identical(&format!("A_{key}"), &unpacked.into_dyn(), &a.into_dyn());
        found += 1;
    }
    assert_eq!(found, 9, "patch degrees in octave_ref/cases/patches.m");
}

/// `ndarray` matrix → `nalgebra` matrix (same logical layout).
fn to_dmatrix(a: &Array2<f64>) -> DMatrix<f64> {
    DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[[i, j]])
}

/// `nalgebra` matrix → `ndarray` matrix, for comparison.
fn to_array2(m: &DMatrix<f64>) -> Array2<f64> {
    Array2::from_shape_fn(m.shape(), |(i, j)| m[(i, j)])
}

/// Splits `<prefix><key>_N<N>` into `(key, N)`.
fn key_and_count<'a>(name: &'a str, prefix: &str) -> Option<(&'a str, usize)> {
    let (key, n) = name.strip_prefix(prefix)?.rsplit_once("_N")?;
    Some((key, n.parse().ok()?))
}

/// Every curve case of a file: `T_<key>_N<N>` against `BezierCurve::eval_many` and the
/// per-point `eval` of `P_<key>` at `t_N<N>`. Returns the errors and the number of cases.
fn compare_curves(case: &str, ws: &Workspace) -> (ErrorStats, usize) {
    let mut stats = ErrorStats::default();
    let mut cases = 0;
    for name in ws.names().filter(|n| n.starts_with("T_")) {
        let (key, n) = key_and_count(name, "T_").unwrap_or_else(|| panic!("{case}: {name}"));
        let control = to_dmatrix(&matrix(ws, &format!("P_{key}")));
        let t = row(ws, &format!("t_N{n}"));
        let octave = matrix(ws, name);
        let curve = BezierCurve::new(control).expect("control points from the reference file");
        let many = to_array2(&curve.eval_many(&t).expect("eval_many"));
        stats.merge(&assert_close(
            &format!("{case}: {name} (eval_many)"),
            &many.into_dyn(),
            octave.view().into_dyn(),
        ));
        let per_point = Array2::from_shape_fn(octave.dim(), |(c, k)| curve.eval(t[k])[c]);
        stats.merge(&assert_close(
            &format!("{case}: {name} (eval)"),
            &per_point.into_dyn(),
            octave.view().into_dyn(),
        ));
        cases += 1;
    }
    (stats, cases)
}

/// Errors of the two patch evaluations.
#[derive(Default)]
struct PatchStats {
    /// `eval_grid`: basis matrices, `B_u · P · B_vᵀ` (a different operation order from Octave's).
    grid: ErrorStats,
    /// `eval`: tensor de Casteljau in the fixed `bilinearna`'s operation order.
    point: ErrorStats,
}

/// Every patch case: `P_<key>_N<N>` (the fixed `ploskevB`) against `BezierPatch::eval_grid`
/// (basis matrices) and the per-point tensor de Casteljau `eval`, the patch built from
/// `A_<key>` (the `tenzor` layout).
fn compare_patches(ws: &Workspace) -> (PatchStats, usize) {
    let mut stats = PatchStats::default();
    let mut cases = 0;
    for name in ws.names().filter(|n| n.starts_with("P_")) {
        let (key, n) = key_and_count(name, "P_").unwrap_or_else(|| panic!("patches: {name}"));
        let net = common::array3(ws, &format!("A_{key}"));
        let t = row(ws, &format!("t_N{n}"));
        let octave = common::array3(ws, name);
        let patch =
            cagd_octave::arrays::patch_from_array3(&net).expect("net from the reference file");
        let grid = cagd_octave::arrays::to_array3(patch.eval_grid(&t, &t));
        stats.grid.merge(&assert_close(
            &format!("patches: {name} (eval_grid)"),
            &grid.into_dyn(),
            octave.view().into_dyn(),
        ));
        let checked = patch.try_eval_grid(&t, &t).expect("try_eval_grid");
        assert_identical(
            &format!("patches: {name} (try_eval_grid = eval_grid)"),
            &cagd_octave::arrays::to_array3(checked).into_dyn(),
            &cagd_octave::arrays::to_array3(patch.eval_grid(&t, &t)).into_dyn(),
        );
        let per_point = Array3::from_shape_fn(octave.dim(), |(i, j, c)| patch.eval(t[i], t[j])[c]);
        stats.point.merge(&assert_close(
            &format!("patches: {name} (eval)"),
            &per_point.into_dyn(),
            octave.view().into_dyn(),
        ));
        cases += 1;
    }
    (stats, cases)
}

#[test]
fn primer_2_4_curve_matches_octave() {
    let (stats, cases) = compare_curves("primer_2_4", &expected("primer_2_4"));
    assert_eq!(cases, 4);
    eprintln!("[primer_2_4] {cases} cases: {stats}");
}

#[test]
fn random_curves_match_octave() {
    let (stats, cases) = compare_curves("curves", &expected("curves"));
    // degrees 0,1,2,3,7,20 in 2-D and 3-D (and degree 3 in 1-D): 13 curves; N = 2,3,10 for
    // all and 101 for degrees 3 and 20.
    assert_eq!(cases, 13 * 3 + 5);
    eprintln!("[curves] {cases} cases: {stats}");
}

#[test]
fn random_patches_match_octave() {
    let (stats, cases) = compare_patches(&expected("patches"));
    assert_eq!(cases, 9 * 3 + 2);
    eprintln!("[patches] {cases} cases, eval_grid: {}", stats.grid);
    eprintln!("[patches] {cases} cases, eval (per point): {}", stats.point);
}

/// All curve and patch comparisons once more, to print the single worst error of the suite.
#[test]
fn worst_error_over_all_bezier_cases() {
    let mut all = ErrorStats::default();
    let mut cases = 0;
    for case in ["primer_2_4", "curves"] {
        let (s, c) = compare_curves(case, &expected(case));
        all.merge(&s);
        cases += c;
    }
    let (s, c) = compare_patches(&expected("patches"));
    all.merge(&s.grid);
    all.merge(&s.point);
    cases += c;
    eprintln!("[octave_reference] worst error versus Octave over {cases} Bézier cases: {all}");
}

/// The comparison can fail: 100 ULPs (2.2e-14 relative) on the value that sets the scale of
/// its array is outside both 4 ULPs and 1e-14 relative.
#[test]
#[should_panic(expected = "100 ULPs")]
fn assert_close_rejects_100_ulps_at_full_scale() {
    let octave = ndarray::array![[1.0, 2.0]].into_dyn();
    let mut ours = octave.clone();
    ours[[0, 1]] = f64::from_bits(2.0f64.to_bits() + 100);
    assert_close("probe", &ours, &octave);
}

/// … and accepts 4 ULPs, or any error within 1e-14 of the array's scale.
#[test]
fn assert_close_accepts_four_ulps_or_1e14_of_the_scale() {
    let octave = ndarray::array![[1.0, 1e-6]].into_dyn();
    let mut ours = octave.clone();
    ours[[0, 0]] = f64::from_bits(1.0f64.to_bits() + 4);
    ours[[0, 1]] = 1e-6 + 0.9e-14;
    let s = assert_close("probe", &ours, &octave);
    assert_eq!(s.compared, 2);
    assert!(s.max_ulps > 4 && s.max_rel < 1e-14);
}

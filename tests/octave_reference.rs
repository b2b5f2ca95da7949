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
//! Tolerance: 4 ULPs or 1e-14 relative, whichever is looser (see `tests/common/mod.rs`). Run
//! with `--nocapture` to see the worst error observed.

mod common;

use common::{assert_identical, expected, matrix, row};
use ndarray::{Array2, Array3};

/// The interval keys of `linspace_samples`, from the `lin_<key>_a` variables.
fn linspace_keys(ws: &cagd::octave::Workspace) -> Vec<String> {
    ws.names()
        .filter_map(|n| n.strip_prefix("lin_")?.strip_suffix("_a"))
        .map(str::to_string)
        .collect()
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

//! The Octave-compatible layer (`cagd::octave::compat`) against GNU Octave.
//!
//! 1. Every twin on the reference cases of `octave_ref/expected/` (written by Octave running
//!    the fixed thesis functions of `octave_ref/fixed/`), within 4 ULPs or 1e-14 relative to
//!    the array scale (`tests/common`). Several tests pin a bug of the printed original (see
//!    `octave_ref/BUGS.md`, which names them).
//! 2. Insta snapshots (`tests/snapshots/octave_compat__*.snap`) of the human-readable output of
//!    each twin on the thesis data, in an Octave-like display with every number written in full
//!    (the shortest decimal that reads back as the same double).
//! 3. A cross-check that parses every number back out of every committed snapshot file and
//!    compares it with the Octave-written reference variable it shows, so that a snapshot can
//!    never drift from Octave silently (accepting a changed snapshot with wrong numbers fails
//!    this test).
//!
//! Run with `--nocapture` to see the worst error observed.

mod common;

use std::collections::BTreeMap;
use std::path::PathBuf;

use cagd::octave::compat;
use cagd::Error;
use common::{assert_close, assert_identical, expected, matrix, ErrorStats};
use ndarray::{array, Array2, Array3, ArrayD, ArrayViewD, Axis, IxDyn};

// ---------------------------------------------------------------------------------------------
// Twins against the reference cases

/// The `(P, T, N)` triples of a curve file: `P_<key>`, `T_<key>_N<N>`.
fn curve_cases(case: &str) -> Vec<(String, String, usize)> {
    let ws = expected(case);
    let mut out = Vec::new();
    for name in ws.names().filter(|n| n.starts_with("T_")) {
        let (key, n) = name[2..].rsplit_once("_N").expect("T_<key>_N<N>");
        out.push((format!("P_{key}"), name.to_string(), n.parse().expect("N")));
    }
    assert!(!out.is_empty(), "{case}: no T_<key>_N<N> variables");
    out
}

fn check_de_casteljau(case: &str) -> usize {
    let ws = expected(case);
    let mut stats = ErrorStats::default();
    let cases = curve_cases(case);
    for (p, t, n) in &cases {
        let ours = compat::de_casteljau(matrix(&ws, p).view(), *n).unwrap();
        stats.merge(&assert_close(
            &format!("{case}: de_casteljau({p}, {n}) vs {t}"),
            &ours.into_dyn(),
            &matrix(&ws, t).into_dyn(),
        ));
    }
    eprintln!("[de_casteljau {case}] {stats}");
    cases.len()
}

/// Thesis Primer 2.4 — four control points in 3-D, the data on which the original stops with
/// `kontrolneT(4,_): out of bound 3` — at N = 2, 3, 10, 101.
#[test]
fn de_casteljau_primer_2_4_matches_octave() {
    assert_eq!(check_de_casteljau("primer_2_4"), 4);
}

/// Curves of degree 0…20 in 1-D, 2-D and 3-D (the original allocated `zeros(3,N)`).
#[test]
fn de_casteljau_any_dimension_matches_octave() {
    let n = check_de_casteljau("curves");
    assert!(n >= 30, "{n} curve cases");
    let ws = expected("curves");
    let dims: std::collections::BTreeSet<usize> = curve_cases("curves")
        .iter()
        .map(|(p, _, _)| matrix(&ws, p).nrows())
        .collect();
    assert_eq!(dims.into_iter().collect::<Vec<_>>(), [1, 2, 3]);
}

/// The columns are the points: the data of `octave_ref/bugs/decasteljau_rows_for_points.m`,
/// where the original (interpolating rows) draws a curve that depends on `b0` only. The
/// Bézier curve of the columns, at t = 0, 1/4, 1/2, 3/4, 1, is exact in binary.
#[test]
fn de_casteljau_control_points_are_columns() {
    let p = array![[1.0, 0.0, 2.0], [2.0, 2.0, 0.0], [3.0, 0.0, 3.0]];
    let t = compat::de_casteljau(p.view(), 5).unwrap();
    assert_eq!(
        t,
        array![
            [1.0, 0.6875, 0.75, 1.1875, 2.0],
            [2.0, 1.875, 1.5, 0.875, 0.0],
            [3.0, 1.875, 1.5, 1.875, 3.0]
        ]
    );
}

/// Each parameter starts from the control points: the point at t = 1/2 is the same whether it
/// is sample 2 of 3 or sample 3 of 5 (the original, overwriting its input, drew
/// (2.375, 2.875, 3) and (2.68359…, 2.94727…, 3)); the input is left as it was.
#[test]
fn de_casteljau_samples_do_not_depend_on_n() {
    let p = array![[1.0, 0.0, 2.0], [2.0, 2.0, 0.0], [3.0, 0.0, 3.0]];
    let copy = p.clone();
    let t3 = compat::de_casteljau(p.view(), 3).unwrap();
    let t5 = compat::de_casteljau(p.view(), 5).unwrap();
    assert_eq!(t3.column(1), t5.column(2));
    assert_eq!(t3.column(1).to_vec(), [0.75, 1.5, 1.5]);
    assert_eq!(p, copy);
}

/// `(B, A, [(P, N)])` of the patch file.
fn patch_cases() -> Vec<(String, String, Vec<(String, usize)>)> {
    let ws = expected("patches");
    let mut out = Vec::new();
    for b in ws.names().filter(|n| n.starts_with("B_")) {
        let key = &b[2..];
        let grids = ws
            .names()
            .filter_map(|n| {
                let n_str = n.strip_prefix(&format!("P_{key}_N"))?;
                Some((n.to_string(), n_str.parse().expect("N")))
            })
            .collect();
        out.push((b.to_string(), format!("A_{key}"), grids));
    }
    out
}

/// Every patch of the `patches` case, `m ≠ n` and degree 0 in a direction included, through
/// `ploskev_b` (whole grids) and `bilinearna` (point by point): the original `bilinearna` is
/// wrong for all of (0,3), (4,0), (2,5), (5,2), (1,4).
#[test]
fn bilinearna_and_ploskev_b_m_ne_n_match_octave() {
    let ws = expected("patches");
    let mut stats = ErrorStats::default();
    let mut degrees = Vec::new();
    for (b, _, grids) in patch_cases() {
        let net = matrix(&ws, &b);
        degrees.push((net.nrows() - 1, net.ncols() / 3 - 1));
        for (p, n) in grids {
            let octave = common::array3(&ws, &p);
            let ours = compat::ploskev_b(net.view(), n).unwrap();
            stats.merge(&assert_close(
                &format!("ploskev_b({b}, {n}) vs {p}"),
                &ours.clone().into_dyn(),
                &octave.clone().into_dyn(),
            ));
            if n > 10 {
                continue;
            }
            let t = cagd::linspace(0.0, 1.0, n);
            let mut pointwise = Array3::zeros((n, n, 3));
            for (i, &u) in t.iter().enumerate() {
                for (j, &v) in t.iter().enumerate() {
                    let l = compat::bilinearna(net.view(), u, v, n).unwrap();
                    assert_eq!(l.dim(), (1, 1, 3));
                    for c in 0..3 {
                        pointwise[[i, j, c]] = l[[0, 0, c]];
                    }
                }
            }
            stats.merge(&assert_close(
                &format!("bilinearna({b}, t(i), t(j), {n}) vs {p}"),
                &pointwise.into_dyn(),
                &octave.into_dyn(),
            ));
        }
    }
    for d in [(0, 3), (4, 0), (2, 5), (5, 2), (1, 4), (3, 3)] {
        assert!(degrees.contains(&d), "patch of degree {d:?} missing");
    }
    eprintln!("[ploskev_b, bilinearna] {stats}");
}

/// The nets of `octave_ref/bugs/bilinearna_m_ne_n.m` at (u, v) = (0.5, 0.25): the patch values
/// (exact in binary) where the original returned (0.75, 0.75, 1.625) or zeros.
#[test]
fn bilinearna_bug_script_nets_give_the_patch() {
    let cases: [(Array2<f64>, [f64; 3]); 5] = [
        (
            array![[1., 0., 0., 2., 1., 0.], [0., 1., 3., 1., 2., 4.]],
            [0.75, 0.75, 1.625],
        ),
        (
            array![
                [1., 0., 0., 2., 1., 0., 4., 0., 1.],
                [0., 1., 3., 1., 2., 4., 2., 2., 0.]
            ],
            [1.03125, 0.90625, 1.625],
        ),
        (
            array![
                [1., 0., 0., 2., 1., 0.],
                [0., 1., 3., 1., 2., 4.],
                [3., 3., 1., 0., 0., 2.]
            ],
            [1.0, 1.25, 1.9375],
        ),
        (
            array![[1., 2., 3., 4., 5., 6., 7., 8., 9.]],
            [2.5, 3.5, 4.5],
        ),
        (
            array![[1., 2., 3.], [4., 5., 6.], [7., 8., 9.]],
            [4.0, 5.0, 6.0],
        ),
    ];
    for (net, want) in cases {
        let l = compat::bilinearna(net.view(), 0.5, 0.25, 5).unwrap();
        assert_eq!(l.iter().copied().collect::<Vec<_>>(), want, "net {net}");
    }
}

/// `tenzor` copies bit for bit, and `untenzor` inverts it.
#[test]
fn tenzor_matches_octave_bit_for_bit() {
    let ws = expected("patches");
    let cases = patch_cases();
    assert_eq!(cases.len(), 9);
    for (b, a, _) in cases {
        let net = matrix(&ws, &b);
        let ours = compat::tenzor(net.view()).unwrap();
        assert_identical(
            &format!("tenzor({b}) vs {a}"),
            &ours.clone().into_dyn(),
            &common::array3(&ws, &a).into_dyn(),
        );
        assert_eq!(compat::untenzor(ours.view()).unwrap(), net);
    }
}

/// A packed net whose width is not a multiple of 3 is an error (the original dropped the
/// trailing columns silently, see `octave_ref/bugs/tenzor_drops_columns.m`).
#[test]
fn tenzor_rejects_partial_points() {
    for cols in [1, 2, 4, 5, 7, 13] {
        let b = Array2::<f64>::zeros((2, cols));
        match compat::tenzor(b.view()) {
            Err(Error::ShapeMismatch { what, found, .. }) => {
                assert_eq!(what, "tenzor: B");
                assert_eq!(found, format!("2×{cols}"));
            }
            other => panic!("2×{cols}: expected ShapeMismatch, got {other:?}"),
        }
        assert!(compat::ploskev_b(b.view(), 3).is_err());
        assert!(compat::bilinearna(b.view(), 0.5, 0.5, 3).is_err());
    }
}

/// `compat::linspace` is Octave's `linspace(a, b, n)`, bit for bit, as a 1 × n row.
#[test]
fn linspace_twin_matches_octave_bit_for_bit() {
    let ws = expected("linspace_samples");
    let mut compared = 0;
    for name in ws
        .names()
        .filter(|n| n.starts_with("lin_") && n.ends_with("_a"))
    {
        let key = &name[4..name.len() - 2];
        let a = ws.scalar(name).unwrap();
        let b = ws.scalar(&format!("lin_{key}_b")).unwrap();
        for n in 0..=200 {
            let var = format!("lin_{key}_n{n}");
            let ours = compat::linspace(a, b, n).unwrap();
            assert_eq!(ours.dim(), (1, n));
            if n > 0 {
                assert_identical(&var, &ours.into_dyn(), &matrix(&ws, &var).into_dyn());
            }
            compared += 1;
        }
    }
    assert_eq!(compared, 5 * 201);
}

/// Bad input to the Bézier twins is a typed error naming the argument, never a panic.
#[test]
fn bezier_twins_reject_bad_input() {
    let nan = array![[0.0, 1.0], [f64::NAN, 2.0]];
    assert!(matches!(
        compat::de_casteljau(nan.view(), 3),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        compat::de_casteljau(Array2::zeros((0, 3)).view(), 3),
        Err(Error::ShapeMismatch { .. })
    ));
    let inf = array![[0.0, 1.0, f64::INFINITY]];
    assert!(matches!(
        compat::ploskev_b(inf.view(), 3),
        Err(Error::NonFinite { index: 2, .. })
    ));
    assert!(matches!(
        compat::bilinearna(array![[0.0, 1.0, 2.0]].view(), 0.5, f64::INFINITY, 3),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        compat::untenzor(Array3::zeros((2, 2, 4)).view()),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(compat::linspace(0.0, f64::NAN, 4).is_err());
}

// ---------------------------------------------------------------------------------------------
// Human-readable display

/// A number in full: the shortest decimal that reads back as the same double (plain notation
/// for 1e-5 ≤ |x| < 1e15, scientific otherwise).
fn number(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || (1e-5..1e15).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// One 2-D page, columns right-aligned, two spaces apart (Octave's display, every digit kept).
fn page(a: &ArrayViewD<'_, f64>) -> String {
    let (rows, cols) = (a.shape()[0], a.shape()[1]);
    let cells: Vec<Vec<String>> = (0..rows)
        .map(|i| (0..cols).map(|j| number(a[[i, j]])).collect())
        .collect();
    let widths: Vec<usize> = (0..cols)
        .map(|j| cells.iter().map(|r| r[j].len()).max().unwrap_or(0))
        .collect();
    let mut out = String::new();
    for r in &cells {
        let line: Vec<String> = r
            .iter()
            .zip(&widths)
            .map(|(c, w)| format!("{c:>w$}"))
            .collect();
        out.push_str("  ");
        out.push_str(&line.join("  "));
        out.push('\n');
    }
    out
}

/// `name = …` as Octave displays a variable: a matrix as one page, a 3-D array page by page
/// (`name(:,:,k) = …`).
fn show(name: &str, a: &ArrayViewD<'_, f64>) -> String {
    match a.ndim() {
        2 => format!("{name} =\n\n{}\n", page(a)),
        3 => (0..a.shape()[2])
            .map(|k| {
                let p = a.index_axis(Axis(2), k);
                format!("{name}(:,:,{}) =\n\n{}\n", k + 1, page(&p))
            })
            .collect(),
        d => panic!("{name}: cannot display a {d}-D array"),
    }
}

// ---------------------------------------------------------------------------------------------
// Snapshots

/// One variable of a snapshot and the Octave reference (case file, variable) it must equal.
struct Shown {
    name: &'static str,
    value: ArrayD<f64>,
    case: &'static str,
    var: &'static str,
}

fn shown(name: &'static str, value: ArrayD<f64>, case: &'static str, var: &'static str) -> Shown {
    Shown {
        name,
        value,
        case,
        var,
    }
}

/// The snapshots: name, a title saying what is shown, and the variables.
fn snapshots() -> Vec<(&'static str, &'static str, Vec<Shown>)> {
    let snap = expected("compat_snapshots");
    let p = matrix(&snap, "snap_P_primer_2_4");
    let b = matrix(&snap, "snap_B");
    vec![
        (
            "de_casteljau_primer_2_4",
            "T = de_casteljau(P, 5): thesis Primer 2.4 (appendix A, Algoritem 1); the columns \
             of T are the curve at t = linspace(0,1,5)",
            vec![
                shown(
                    "P",
                    p.clone().into_dyn(),
                    "compat_snapshots",
                    "snap_P_primer_2_4",
                ),
                shown(
                    "t",
                    compat::linspace(0.0, 1.0, 5).unwrap().into_dyn(),
                    "compat_snapshots",
                    "snap_t_N5",
                ),
                shown(
                    "T",
                    compat::de_casteljau(p.view(), 5).unwrap().into_dyn(),
                    "compat_snapshots",
                    "snap_T_primer_2_4_N5",
                ),
            ],
        ),
        (
            "tenzor_degree_2x3",
            "A = tenzor(B): a degree (2,3) net, b(i,j) = (i, j, z(i,j)), packed 3×12 -> 3×4×3 \
             (appendix B, Algoritem 4)",
            vec![
                shown("B", b.clone().into_dyn(), "compat_snapshots", "snap_B"),
                shown(
                    "A",
                    compat::tenzor(b.view()).unwrap().into_dyn(),
                    "compat_snapshots",
                    "snap_A",
                ),
            ],
        ),
        (
            "ploskev_b_degree_2x3",
            "P = ploskev_b(B, 5) and L = bilinearna(B, 0.5, 0.25, 5): the degree (2,3) patch \
             of snapshot tenzor_degree_2x3 on linspace(0,1,5)² and at one point (appendix B, \
             Algoritmi 2 and 3)",
            vec![
                shown(
                    "P",
                    compat::ploskev_b(b.view(), 5).unwrap().into_dyn(),
                    "compat_snapshots",
                    "snap_P_B_N5",
                ),
                shown(
                    "L",
                    compat::bilinearna(b.view(), 0.5, 0.25, 5)
                        .unwrap()
                        .into_dyn(),
                    "compat_snapshots",
                    "snap_L_B",
                ),
            ],
        ),
    ]
}

fn render(title: &str, vars: &[Shown]) -> String {
    let mut out = format!("% {title}\n\n");
    for v in vars {
        out.push_str(&show(v.name, &v.value.view()));
    }
    out
}

#[test]
fn snapshots_of_the_twins_on_the_thesis_data() {
    for (name, title, vars) in snapshots() {
        insta::assert_snapshot!(name, render(title, &vars));
    }
}

fn snapshot_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots")
}

/// The content of an insta snapshot file (after its `---` header).
fn snapshot_body(text: &str) -> &str {
    let rest = text.strip_prefix("---\n").expect("insta header");
    let end = rest.find("\n---\n").expect("end of insta header");
    &rest[end + 5..]
}

/// Parses the variables back out of a rendered snapshot: `name = …` pages and `name(:,:,k) =`
/// pages, every number as a double. Panics (failing the test) on anything it cannot read.
fn parse_display(body: &str) -> BTreeMap<String, ArrayD<f64>> {
    let mut pages: BTreeMap<String, Vec<(usize, Vec<Vec<f64>>)>> = BTreeMap::new();
    let mut lines = body.lines().peekable();
    while let Some(line) = lines.next() {
        if line.is_empty() || line.starts_with('%') {
            continue;
        }
        let head = line
            .strip_suffix(" =")
            .unwrap_or_else(|| panic!("unexpected line in snapshot: {line:?}"));
        let (name, k) = match head.split_once("(:,:,") {
            Some((n, k)) => (n, k.trim_end_matches(')').parse().expect("page number")),
            None => (head, 0),
        };
        assert_eq!(lines.next(), Some(""), "blank line after `{line}`");
        let mut rows = Vec::new();
        while let Some(l) = lines.next_if(|l| !l.is_empty()) {
            let row: Vec<f64> = l
                .split_whitespace()
                .map(|tok| {
                    tok.parse()
                        .unwrap_or_else(|_| panic!("`{name}`: not a number: {tok:?}"))
                })
                .collect();
            rows.push(row);
        }
        pages.entry(name.to_string()).or_default().push((k, rows));
    }
    pages
        .into_iter()
        .map(|(name, mut p)| {
            p.sort_by_key(|(k, _)| *k);
            let rows = p[0].1.len();
            let cols = p[0].1.first().map_or(0, Vec::len);
            let mut a = if p[0].0 == 0 {
                ArrayD::zeros(IxDyn(&[rows, cols]))
            } else {
                ArrayD::zeros(IxDyn(&[rows, cols, p.len()]))
            };
            for (idx, (k, page)) in p.iter().enumerate() {
                assert!(*k == 0 || *k == idx + 1, "`{name}`: pages out of order");
                assert_eq!(page.len(), rows, "`{name}`: ragged pages");
                for (i, r) in page.iter().enumerate() {
                    assert_eq!(r.len(), cols, "`{name}`: ragged rows");
                    for (j, x) in r.iter().enumerate() {
                        if *k == 0 {
                            a[[i, j]] = *x;
                        } else {
                            a[[i, j, idx]] = *x;
                        }
                    }
                }
            }
            (name, a)
        })
        .collect()
}

/// Every number of every committed snapshot equals Octave's (4 ULPs or 1e-14 relative), and
/// every snapshot file of this test binary is one of the snapshots above: a snapshot accepted
/// with numbers Octave does not write fails here.
#[test]
fn snapshots_agree_with_octave() {
    let table = snapshots();
    let mut stats = ErrorStats::default();
    let mut checked = 0;
    for (name, _, vars) in &table {
        let path = snapshot_dir().join(format!("octave_compat__{name}.snap"));
        let text = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (run the snapshot test first)", path.display()));
        let parsed = parse_display(snapshot_body(&text));
        let names: Vec<&str> = vars.iter().map(|v| v.name).collect();
        assert_eq!(
            parsed.keys().map(String::as_str).collect::<Vec<_>>(),
            {
                let mut n = names.clone();
                n.sort();
                n
            },
            "{name}: variables shown"
        );
        for v in vars {
            let ws = expected(v.case);
            let octave = common::array(&ws, v.var);
            let ours = &parsed[v.name];
            // Octave drops trailing singleton dimensions (1×1×3 stays 3-D, N×1 is 2-D).
            stats.merge(&assert_close(
                &format!("snapshot {name}: {} vs {}.txt {}", v.name, v.case, v.var),
                ours,
                &octave,
            ));
            checked += ours.len();
        }
    }
    let files: Vec<String> = std::fs::read_dir(snapshot_dir())
        .expect("tests/snapshots")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|f| f.starts_with("octave_compat__") && f.ends_with(".snap"))
        .collect();
    for f in &files {
        let name = &f["octave_compat__".len()..f.len() - ".snap".len()];
        assert!(
            table.iter().any(|(n, _, _)| *n == name),
            "tests/snapshots/{f} is not a snapshot of this test (stale file?)"
        );
    }
    assert_eq!(files.len(), table.len());
    eprintln!("[snapshots vs Octave] {checked} numbers parsed back; {stats}");
}

/// The display round-trips every double exactly, so the cross-check compares Octave with the
/// very numbers the twins returned.
#[test]
fn display_reads_back_exactly() {
    let values = [
        0.0,
        -0.0,
        1.0,
        -2.5,
        0.1 + 0.2,
        1.0 / 3.0,
        1e-300,
        -4.9e-324,
        123456789012345680.0,
        f64::MAX,
    ];
    let a = Array2::from_shape_vec((2, 5), values.to_vec())
        .unwrap()
        .into_dyn();
    let text = show("x", &a.view());
    let back = parse_display(&text);
    for (x, y) in back["x"].iter().zip(a.iter()) {
        assert_eq!(x.to_bits(), y.to_bits(), "{x:e} vs {y:e}");
    }
    let cube = Array3::from_shape_fn((2, 2, 3), |(i, j, k)| (i + 10 * j) as f64 / (k + 1) as f64);
    let back = parse_display(&show("c", &cube.view().into_dyn()));
    assert_eq!(back["c"], cube.into_dyn());
}

//! The Octave-compatible layer (`cagd_octave::compat`) against GNU Octave.
//!
//! 1. Every twin on the reference cases of `octave_ref/expected/` (written by Octave running
//!    the fixed thesis functions of `octave_ref/fixed/`), within 4 ULPs or 1e-14 relative to
//!    the array scale (`tests/common`). Several tests pin a bug of the printed original (see
//!    `octave_ref/BUGS.md`, which names them).
//! 2. Insta snapshots (`tests/it/snapshots/it__octave_compat__*.snap`) of the human-readable output of
//!    each twin on the thesis data, in an Octave-like display with every number written in full
//!    (the shortest decimal that reads back as the same double).
//! 3. A cross-check that parses every number back out of every committed snapshot file and
//!    compares it with the Octave-written reference variable it shows, so that a snapshot can
//!    never drift from Octave silently (accepting a changed snapshot with wrong numbers fails
//!    this test).
//!
//! Run with `--nocapture` to see the worst error observed.

use cagd_test_support as common;

use std::collections::BTreeMap;
use std::path::PathBuf;

use cagd::Error;
use cagd_octave::compat;
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

/// One patch of the `patches` case: the net `B_<key>`, its `A_<key>`, and the grids
/// `P_<key>_N<N>` with their `N`.
type PatchCase = (String, String, Vec<(String, usize)>);

/// `(B, A, [(P, N)])` of the patch file.
fn patch_cases() -> Vec<PatchCase> {
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
        compat::de_casteljau(Array2::<f64>::zeros((0, 3)).view(), 3),
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
        compat::untenzor(Array3::<f64>::zeros((2, 2, 4)).view()),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(compat::linspace(0.0, f64::NAN, 4).is_err());
}

// ---------------------------------------------------------------------------------------------
// Coons, Gordon and Lagrange twins

/// A `3 × 1` column of a reference file as an array.
fn column(ws: &cagd_octave::Workspace, name: &str) -> Array2<f64> {
    let m = matrix(ws, name);
    assert_eq!(m.dim(), (3, 1), "{name}");
    m
}

/// Thesis Primer 4.3 (u = 0.2, v = 0.5) — where the original only displays `T` and returns
/// nothing — and 15 random points of random compatible boundaries (`coons_random`).
#[test]
fn vrednost_coons_primer_4_3_matches_octave() {
    let ws = expected("coons_thesis");
    let corners: Vec<Array2<f64>> = ["P1", "P2", "P3", "P4"]
        .iter()
        .map(|p| column(&ws, p))
        .collect();
    let r = compat::vrednost_coons(
        ws.scalar("ex_u").unwrap(),
        ws.scalar("ex_v").unwrap(),
        column(&ws, "ex_c1").view(),
        column(&ws, "ex_c2").view(),
        column(&ws, "ex_d1").view(),
        column(&ws, "ex_d2").view(),
        corners[0].view(),
        corners[1].view(),
        corners[2].view(),
        corners[3].view(),
    )
    .unwrap();
    let mut stats = ErrorStats::default();
    for (name, ours) in [
        ("ex_T", &r.t),
        ("ex_rc", &r.rc),
        ("ex_rd", &r.rd),
        ("ex_rcd", &r.rcd),
    ] {
        stats.merge(&assert_close(
            &format!("vrednost_coons Primer 4.3 vs {name}"),
            &ours.clone().into_dyn(),
            &matrix(&ws, name).into_dyn(),
        ));
    }
    // The thesis's numbers: (0.2, 0.3, 0.38) = (0.2, 0.5, 0.18) + (0.2, 0.3, 0.3) − (0.2, 0.5, 0.1).
    let approx = |a: &Array2<f64>, b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-15);
    assert!(approx(&r.t, [0.2, 0.3, 0.38]), "{}", r.t);
    assert!(approx(&r.rc, [0.2, 0.5, 0.18]), "{}", r.rc);
    assert!(approx(&r.rd, [0.2, 0.3, 0.3]), "{}", r.rd);
    assert!(approx(&r.rcd, [0.2, 0.5, 0.1]), "{}", r.rcd);

    let ws = expected("coons_random");
    for r in 1..=3 {
        let get = |n: &str| matrix(&ws, &format!("r{r}_{n}"));
        let (q, a, b, uv) = (get("Q"), get("A"), get("B"), get("uv"));
        let corner = |k: usize| q.column(k).to_owned().insert_axis(Axis(1));
        // The case's curves, in its order of operations:
        // (1-u)*Pa + u*Pb + (u*(1-u))*(A(:,k) + B(:,k)*u).
        let curve = |k: usize, pa: usize, pb: usize, s: f64| {
            Array2::from_shape_fn((3, 1), |(c, _)| {
                (1.0 - s) * q[[c, pa]]
                    + s * q[[c, pb]]
                    + (s * (1.0 - s)) * (a[[c, k]] + b[[c, k]] * s)
            })
        };
        for k in 0..uv.ncols() {
            let (u, v) = (uv[[0, k]], uv[[1, k]]);
            let p = compat::vrednost_coons(
                u,
                v,
                curve(0, 0, 1, u).view(),
                curve(1, 2, 3, u).view(),
                curve(2, 0, 2, v).view(),
                curve(3, 1, 3, v).view(),
                corner(0).view(),
                corner(1).view(),
                corner(2).view(),
                corner(3).view(),
            )
            .unwrap();
            for (name, ours) in [("T", &p.t), ("rc", &p.rc), ("rd", &p.rd), ("rcd", &p.rcd)] {
                let octave = get(name).column(k).to_owned().insert_axis(Axis(1));
                stats.merge(&assert_close(
                    &format!("vrednost_coons coons_random r{r} point {} {name}", k + 1),
                    &ours.clone().into_dyn(),
                    &octave.into_dyn(),
                ));
            }
        }
    }
    eprintln!("[vrednost_coons] {stats}");
}

/// The sampled curves and corners of a Coons case (`<prefix>c1<suffix>`, …).
fn coons_inputs(
    ws: &cagd_octave::Workspace,
    curve: impl Fn(&str) -> String,
    corner: impl Fn(&str) -> String,
) -> ([Array2<f64>; 4], [Array2<f64>; 4]) {
    (
        ["c1", "c2", "d1", "d2"].map(|c| matrix(ws, &curve(c))),
        ["P1", "P2", "P3", "P4"].map(|p| column(ws, &corner(p))),
    )
}

fn run_krpa_coons(
    c: &[Array2<f64>; 4],
    p: &[Array2<f64>; 4],
) -> cagd::Result<compat::SampledPatch> {
    compat::krpa_coons(
        c[0].view(),
        c[1].view(),
        c[2].view(),
        c[3].view(),
        p[0].view(),
        p[1].view(),
        p[2].view(),
        p[3].view(),
    )
}

/// Appendix C's patch at N = 2, 3, 10, 101 — `N` taken from the curves, where the original
/// used it undefined — and the random boundaries of `coons_random` (N = 7, 12, 2).
#[test]
fn krpa_coons_appendix_c_matches_octave() {
    let ws = expected("coons_thesis");
    let mut stats = ErrorStats::default();
    for n in [2, 3, 10, 101] {
        let (c, p) = coons_inputs(&ws, |c| format!("{c}_N{n}"), str::to_string);
        let s = run_krpa_coons(&c, &p).unwrap();
        assert_eq!((s.r.dim(), s.p.dim()), ((n, 3 * n), (n, n, 3)));
        stats.merge(&assert_close(
            &format!("krpa_coons appendix C N = {n}"),
            &s.p.clone().into_dyn(),
            &common::array3(&ws, &format!("P_N{n}")).into_dyn(),
        ));
        if n <= 3 {
            stats.merge(&assert_close(
                &format!("krpa_coons appendix C N = {n}, packed R"),
                &s.r.clone().into_dyn(),
                &matrix(&ws, &format!("R_N{n}")).into_dyn(),
            ));
        }
    }
    let ws = expected("coons_random");
    for r in 1..=3 {
        let c = ["c1", "c2", "d1", "d2"].map(|c| matrix(&ws, &format!("r{r}_{c}")));
        let q = matrix(&ws, &format!("r{r}_Q"));
        let p = [0, 1, 2, 3].map(|k| q.column(k).to_owned().insert_axis(Axis(1)));
        let s = run_krpa_coons(&c, &p).unwrap();
        stats.merge(&assert_close(
            &format!("krpa_coons coons_random r{r}"),
            &s.p.into_dyn(),
            &common::array3(&ws, &format!("r{r}_P")).into_dyn(),
        ));
    }
    eprintln!("[krpa_coons] {stats}");
}

/// Appendix C's data script as printed sets `P3 = [1;1;1]` (meant as `P4`): with it the twin
/// reports the corner `x(0,1)`, where `c2(0) = d1(1) = (0,1,0)`, instead of drawing a wrong
/// patch.
#[test]
fn krpa_coons_thesis_p3_typo_is_a_corner_mismatch() {
    let ws = expected("coons_thesis");
    let (c, mut p) = coons_inputs(&ws, |c| format!("{c}_N10"), str::to_string);
    p[2] = array![[1.0], [1.0], [1.0]];
    match run_krpa_coons(&c, &p) {
        Err(Error::CornerMismatch { gaps, .. }) => {
            assert!(!gaps.is_empty());
            assert!(
                gaps.iter().all(|g| g.corner == cagd::coons::Corner::U0V1),
                "{gaps:?}"
            );
            assert_eq!(gaps[0].gap, 1.0);
        }
        other => panic!("expected CornerMismatch at x(0,1), got {other:?}"),
    }
}

/// The Lagrange basis of three node sets (appendix D's `[0 0.5 1]`, random, Chebyshev–Lobatto)
/// on parameter rows — the original returned 0 everywhere — and `L_m(x_m) = 1` exactly.
#[test]
fn lagrange_matches_octave_and_is_one_at_its_node() {
    let ws = expected("lagrange_basis");
    let mut stats = ErrorStats::default();
    for k in 1..=3 {
        let x = matrix(&ws, &format!("x{k}"));
        let t = matrix(&ws, &format!("t{k}"));
        let l = matrix(&ws, &format!("L{k}"));
        for m in 1..=x.len() {
            let ours = compat::lagrange(x.view(), m, t.view()).unwrap();
            stats.merge(&assert_close(
                &format!("lagrange(x{k}, {m}, t{k})"),
                &ours.into_dyn(),
                &l.row(m - 1).to_owned().insert_axis(Axis(0)).into_dyn(),
            ));
            let at_node = compat::lagrange(x.view(), m, array![x[[0, m - 1]]].view()).unwrap();
            assert_eq!(at_node[0], 1.0, "L_{m}(x{k}({m}))");
        }
    }
    eprintln!("[lagrange] {stats}");
}

/// Appendix D's network sampled at N = 3, 10, 101 — the data on which the original fails, by
/// counting curves by sample columns, reading samples as curves and adding crossing rows to
/// columns.
#[test]
fn krpa_gordon_appendix_d_matches_octave() {
    let ws = expected("gordon_thesis");
    let x = matrix(&ws, "x");
    let g_uv = matrix(&ws, "g_uv");
    let mut stats = ErrorStats::default();
    for n in [3, 10, 101] {
        let g_u = matrix(&ws, &format!("g_u_N{n}"));
        let g_v = matrix(&ws, &format!("g_v_N{n}"));
        let s = compat::krpa_gordon(g_u.view(), g_v.view(), g_uv.view(), x.view(), x.view(), n)
            .unwrap();
        assert_eq!((s.r.dim(), s.p.dim()), ((n, 3 * n), (n, n, 3)));
        assert_eq!(compat::untenzor(s.p.view()).unwrap(), s.r);
        stats.merge(&assert_close(
            &format!("krpa_gordon appendix D N = {n}"),
            &s.p.into_dyn(),
            &common::array3(&ws, &format!("P_N{n}")).into_dyn(),
        ));
    }
    eprintln!("[krpa_gordon appendix D] {stats}");
}

/// The Gordon surface of a sampled network on its sampling grid in exact rational arithmetic
/// (native `GordonSurface<BigRational>` over the samples, lifted exactly): the reference for
/// networks whose blending is ill-conditioned.
fn exact_gordon_grid(
    xu: &Array2<f64>,
    xv: &Array2<f64>,
    n: usize,
    g_u: &Array2<f64>,
    g_v: &Array2<f64>,
    g_uv: &Array2<f64>,
) -> Array3<f64> {
    use cagd::gordon::GordonSurface;
    use cagd::{SampledCurve, Scalar, Surface};
    use nalgebra::{DMatrix, DVector};
    use num_rational::BigRational as Q;
    let lift = |x: f64| <Q as Scalar>::from_f64(x).unwrap();
    let t: Vec<Q> = cagd::linspace(0.0, 1.0, n).into_iter().map(lift).collect();
    let family = |m: &Array2<f64>, k: usize| {
        SampledCurve::new(
            t.clone(),
            DMatrix::from_fn(3, n, |i, j| lift(m[[i, k * n + j]])),
        )
        .unwrap()
    };
    let points: Vec<Vec<DVector<Q>>> = (0..xu.len())
        .map(|i| {
            (0..xv.len())
                .map(|j| DVector::from_fn(3, |c, _| lift(g_uv[[i, 3 * j + c]])))
                .collect()
        })
        .collect();
    // On the grid only the samples are used; between them the polylines are not the network,
    // so the compatibility check is switched off (a huge absolute tolerance).
    let g = GordonSurface::with_points(
        xu.iter().map(|&x| lift(x)).collect(),
        xv.iter().map(|&x| lift(x)).collect(),
        (0..xu.len()).map(|i| family(g_v, i)).collect(),
        (0..xv.len()).map(|j| family(g_u, j)).collect(),
        points,
        cagd::coons::Tolerance::Absolute(1e300),
    )
    .unwrap();
    cagd_octave::arrays::to_array3(g.eval_grid(&t, &t).map(|x| x.to_f64()))
}

/// Networks with different numbers of curves and different nodes in u and v (4×3, 2×5 with
/// nodes off the sample grid, 3×2) — impossible with the original's single `x` and count.
///
/// Case r3 (nodes [0 0.5 1] and [0 1]) is well conditioned and must agree within the crate's
/// tolerance. The random nodes of r1 and r2 are clustered: the blending amplifies rounding by
/// `κ = Λ_u + Λ_v + Λ_u Λ_v` (Lebesgue constants; about 1800 and 175), so two correct operation
/// orders — the twin's barycentric basis and Octave's products — may differ by up to `κ·ε`
/// relative. For them both are checked against the exact rational Gordon surface of the same
/// doubles, within `κ·ε` of the scale, and against each other within the same bound.
#[test]
fn krpa_gordon_separate_nodes_match_octave() {
    let ws = expected("gordon_random");
    let mut stats = ErrorStats::default();
    for r in 1..=3 {
        let get = |n: &str| matrix(&ws, &format!("r{r}_{n}"));
        let (xu, xv, t) = (get("xu"), get("xv"), get("t"));
        let (g_u, g_v, g_uv) = (get("g_u"), get("g_v"), get("g_uv"));
        let n = t.len();
        let s = compat::krpa_gordon(g_u.view(), g_v.view(), g_uv.view(), xu.view(), xv.view(), n)
            .unwrap();
        let octave = common::array3(&ws, &format!("r{r}_P"));
        let label = format!(
            "krpa_gordon gordon_random r{r} ({}×{} curves)",
            xu.len(),
            xv.len()
        );
        let lebesgue = |x: &Array2<f64>| {
            cagd::lagrange::Lagrange::new(x.iter().copied().collect())
                .unwrap()
                .lebesgue_constant(0.0, 1.0, 4001)
                .value
        };
        let (lu, lv) = (lebesgue(&xu), lebesgue(&xv));
        let kappa = lu + lv + lu * lv;
        if kappa < 10.0 {
            stats.merge(&assert_close(&label, &s.p.into_dyn(), &octave.into_dyn()));
            continue;
        }
        let exact = exact_gordon_grid(&xu, &xv, n, &g_u, &g_v, &g_uv);
        let scale = octave.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let bound = kappa * f64::EPSILON * scale;
        let max_diff = |a: &Array3<f64>, b: &Array3<f64>| {
            a.iter()
                .zip(b.iter())
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        };
        let (ours_err, octave_err, diff) = (
            max_diff(&s.p, &exact),
            max_diff(&octave, &exact),
            max_diff(&s.p, &octave),
        );
        eprintln!(
            "[{label}] κ = {kappa:.0}: |twin − exact| = {ours_err:.2e}, |Octave − exact| = \
             {octave_err:.2e}, |twin − Octave| = {diff:.2e} (bound κ·ε·scale = {bound:.2e})"
        );
        assert!(
            ours_err <= bound,
            "{label}: twin {ours_err:e} from exact, bound {bound:e}"
        );
        assert!(
            octave_err <= bound,
            "{label}: Octave {octave_err:e} from exact, bound {bound:e}"
        );
        assert!(
            diff <= bound,
            "{label}: twin and Octave {diff:e} apart, bound {bound:e}"
        );
    }
    eprintln!("[krpa_gordon separate nodes, well conditioned] {stats}");
}

/// The four functions that only drew return what they drew: `T` (d × N), `P` (N × N × 3),
/// and `[R, P]` with `R` the packed form of `P` (N × 3N).
#[test]
fn plotting_twins_return_the_data() {
    let snap = expected("compat_snapshots");
    let t = compat::de_casteljau(matrix(&snap, "snap_P_primer_2_4").view(), 7).unwrap();
    assert_eq!(t.dim(), (3, 7));
    let p = compat::ploskev_b(matrix(&snap, "snap_B").view(), 4).unwrap();
    assert_eq!(p.dim(), (4, 4, 3));
    let c = ["c1", "c2", "d1", "d2"].map(|c| matrix(&snap, &format!("snap_coons_{c}")));
    let q = ["P1", "P2", "P3", "P4"].map(|p| column(&snap, &format!("snap_coons_{p}")));
    let coons = run_krpa_coons(&c, &q).unwrap();
    assert_eq!((coons.r.dim(), coons.p.dim()), ((5, 15), (5, 5, 3)));
    assert_eq!(compat::untenzor(coons.p.view()).unwrap(), coons.r);
    assert_eq!(compat::tenzor(coons.r.view()).unwrap(), coons.p);
    let x = matrix(&snap, "snap_gordon_x");
    let gordon = compat::krpa_gordon(
        matrix(&snap, "snap_gordon_g_u").view(),
        matrix(&snap, "snap_gordon_g_v").view(),
        matrix(&snap, "snap_gordon_g_uv").view(),
        x.view(),
        x.view(),
        5,
    )
    .unwrap();
    assert_eq!((gordon.r.dim(), gordon.p.dim()), ((5, 15), (5, 5, 3)));
    assert_eq!(compat::untenzor(gordon.p.view()).unwrap(), gordon.r);
}

/// Bad input to the Coons, Gordon and Lagrange twins: typed errors naming the argument.
#[test]
fn coons_gordon_lagrange_twins_reject_bad_input() {
    let snap = expected("compat_snapshots");
    let c = ["c1", "c2", "d1", "d2"].map(|c| matrix(&snap, &format!("snap_coons_{c}")));
    let q = ["P1", "P2", "P3", "P4"].map(|p| column(&snap, &format!("snap_coons_{p}")));
    let mut bad = c.clone();
    bad[1] = Array2::zeros((3, 4));
    assert!(matches!(
        run_krpa_coons(&bad, &q),
        Err(Error::ShapeMismatch {
            what: "krpa_coons: c2",
            ..
        })
    ));
    let mut nan = c.clone();
    nan[2][[1, 2]] = f64::NAN;
    assert!(matches!(
        run_krpa_coons(&nan, &q),
        Err(Error::NonFinite { .. })
    ));
    let mut corner = q.clone();
    corner[3] = Array2::zeros((2, 1));
    assert!(matches!(
        run_krpa_coons(&c, &corner),
        Err(Error::ShapeMismatch {
            what: "krpa_coons: P4",
            ..
        })
    ));

    let (g_u, g_v, g_uv) = (
        matrix(&snap, "snap_gordon_g_u"),
        matrix(&snap, "snap_gordon_g_v"),
        matrix(&snap, "snap_gordon_g_uv"),
    );
    let x = matrix(&snap, "snap_gordon_x");
    let two = array![[0.0, 1.0]];
    assert!(matches!(
        compat::krpa_gordon(g_u.view(), g_v.view(), g_uv.view(), x.view(), two.view(), 5),
        Err(Error::ShapeMismatch { .. })
    ));
    assert!(matches!(
        compat::krpa_gordon(g_u.view(), g_v.view(), g_uv.view(), x.view(), x.view(), 4),
        Err(Error::ShapeMismatch {
            what: "krpa_gordon: g_u",
            ..
        })
    ));
    let dup = array![[0.0, 0.5, 0.5]];
    assert!(matches!(
        compat::krpa_gordon(g_u.view(), g_v.view(), g_uv.view(), dup.view(), x.view(), 5),
        Err(Error::DuplicateNodes { .. })
    ));
    let mut off = g_uv.clone();
    off[[1, 4]] += 1e-3; // g(u_1, v_1) moved off both curves
    assert!(matches!(
        compat::krpa_gordon(g_u.view(), g_v.view(), off.view(), x.view(), x.view(), 5),
        Err(Error::NetworkMismatch { .. })
    ));

    assert!(matches!(
        compat::lagrange(x.view(), 0, array![0.5].view()),
        Err(Error::InvalidArgument { .. })
    ));
    assert!(matches!(
        compat::lagrange(dup.view(), 1, array![0.5].view()),
        Err(Error::DuplicateNodes { .. })
    ));
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
        (
            "krpa_coons_appendix_c",
            "[R, P] = krpa_coons(c1, c2, d1, d2, P1, P2, P3, P4): appendix C's data (Algoritem 5) \
             at N = 5, with its second \"P3 = [1;1;1]\" read as P4; P(i,j,:) is the patch at \
             (u, v) = (t(i), t(j)), t = linspace(0,1,5)",
            {
                let c = ["c1", "c2", "d1", "d2"].map(|c| matrix(&snap, &format!("snap_coons_{c}")));
                let q = ["P1", "P2", "P3", "P4"].map(|p| column(&snap, &format!("snap_coons_{p}")));
                let s = run_krpa_coons(&c, &q).unwrap();
                let [c1, c2, d1, d2] = c;
                let [p1, p2, p3, p4] = q;
                vec![
                    shown("c1", c1.into_dyn(), "compat_snapshots", "snap_coons_c1"),
                    shown("c2", c2.into_dyn(), "compat_snapshots", "snap_coons_c2"),
                    shown("d1", d1.into_dyn(), "compat_snapshots", "snap_coons_d1"),
                    shown("d2", d2.into_dyn(), "compat_snapshots", "snap_coons_d2"),
                    shown("P1", p1.into_dyn(), "compat_snapshots", "snap_coons_P1"),
                    shown("P2", p2.into_dyn(), "compat_snapshots", "snap_coons_P2"),
                    shown("P3", p3.into_dyn(), "compat_snapshots", "snap_coons_P3"),
                    shown("P4", p4.into_dyn(), "compat_snapshots", "snap_coons_P4"),
                    shown("R", s.r.into_dyn(), "compat_snapshots", "snap_coons_R"),
                    shown("P", s.p.into_dyn(), "compat_snapshots", "snap_coons_P"),
                ]
            },
        ),
        (
            "vrednost_coons_primer_4_3",
            "[T, rc, rd, rcd] = vrednost_coons(u, v, c1, c2, d1, d2, P1, P2, P3, P4): thesis \
             Primer 4.3 (appendix C, Algoritem 6), c1 = (u, 0, u-u^2), c2 = (u, 1, u), \
             d1 = (0, v^2, v-v^2), d2 = (1, v, v) at u = 0.2, v = 0.5",
            {
                let ws = expected("coons_thesis");
                let names = ["ex_c1", "ex_c2", "ex_d1", "ex_d2", "P1", "P2", "P3", "P4"];
                let a = names.map(|n| column(&ws, n));
                let (u, v) = (ws.scalar("ex_u").unwrap(), ws.scalar("ex_v").unwrap());
                let r = compat::vrednost_coons(
                    u,
                    v,
                    a[0].view(),
                    a[1].view(),
                    a[2].view(),
                    a[3].view(),
                    a[4].view(),
                    a[5].view(),
                    a[6].view(),
                    a[7].view(),
                )
                .unwrap();
                let one = |x: f64| Array2::from_elem((1, 1), x).into_dyn();
                let [c1, c2, d1, d2, p1, p2, p3, p4] = a;
                vec![
                    shown("u", one(u), "coons_thesis", "ex_u"),
                    shown("v", one(v), "coons_thesis", "ex_v"),
                    shown("c1", c1.into_dyn(), "coons_thesis", "ex_c1"),
                    shown("c2", c2.into_dyn(), "coons_thesis", "ex_c2"),
                    shown("d1", d1.into_dyn(), "coons_thesis", "ex_d1"),
                    shown("d2", d2.into_dyn(), "coons_thesis", "ex_d2"),
                    shown("P1", p1.into_dyn(), "coons_thesis", "P1"),
                    shown("P2", p2.into_dyn(), "coons_thesis", "P2"),
                    shown("P3", p3.into_dyn(), "coons_thesis", "P3"),
                    shown("P4", p4.into_dyn(), "coons_thesis", "P4"),
                    shown("T", r.t.into_dyn(), "coons_thesis", "ex_T"),
                    shown("rc", r.rc.into_dyn(), "coons_thesis", "ex_rc"),
                    shown("rd", r.rd.into_dyn(), "coons_thesis", "ex_rd"),
                    shown("rcd", r.rcd.into_dyn(), "coons_thesis", "ex_rcd"),
                ]
            },
        ),
        (
            "krpa_gordon_appendix_d",
            "[R, P] = krpa_gordon(g_u, g_v, g_uv, x, x, 5): appendix D's network (Algoritem 7), \
             c_j = g(u, v_j) sampled in g_u, d_i = g(u_i, v) in g_v, crossings g_uv as printed, \
             nodes x = [0 0.5 1] in both directions; P(i,j,:) = g(t(i), t(j))",
            {
                let get = |n: &str| matrix(&snap, &format!("snap_gordon_{n}"));
                let (g_u, g_v, g_uv, x) = (get("g_u"), get("g_v"), get("g_uv"), get("x"));
                let s =
                    compat::krpa_gordon(g_u.view(), g_v.view(), g_uv.view(), x.view(), x.view(), 5)
                        .unwrap();
                vec![
                    shown("g_u", g_u.into_dyn(), "compat_snapshots", "snap_gordon_g_u"),
                    shown("g_v", g_v.into_dyn(), "compat_snapshots", "snap_gordon_g_v"),
                    shown(
                        "g_uv",
                        g_uv.into_dyn(),
                        "compat_snapshots",
                        "snap_gordon_g_uv",
                    ),
                    shown("x", x.into_dyn(), "compat_snapshots", "snap_gordon_x"),
                    shown("R", s.r.into_dyn(), "compat_snapshots", "snap_gordon_R"),
                    shown("P", s.p.into_dyn(), "compat_snapshots", "snap_gordon_P"),
                ]
            },
        ),
        (
            "lagrange_appendix_d_nodes",
            "L(m,:) = lagrange(x, m, t), m = 1, 2, 3: the Lagrange basis of appendix D's nodes \
             x = [0 0.5 1] (Algoritem 8) at t = linspace(0,1,21)",
            {
                let ws = expected("lagrange_basis");
                let (x, t) = (matrix(&ws, "x1"), matrix(&ws, "t1"));
                let mut l = Array2::zeros((3, t.len()));
                for m in 1..=3 {
                    l.row_mut(m - 1)
                        .assign(&compat::lagrange(x.view(), m, t.view()).unwrap().row(0));
                }
                vec![
                    shown("x", x.into_dyn(), "lagrange_basis", "x1"),
                    shown("t", t.into_dyn(), "lagrange_basis", "t1"),
                    shown("L", l.into_dyn(), "lagrange_basis", "L1"),
                ]
            },
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
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/it/snapshots")
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
    // Per variable: its pages (page number, 0 for a matrix; rows of numbers).
    type Page = (usize, Vec<Vec<f64>>);
    let mut pages: BTreeMap<String, Vec<Page>> = BTreeMap::new();
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
        let path = snapshot_dir().join(format!("it__octave_compat__{name}.snap"));
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
        .filter(|f| f.starts_with("it__octave_compat__") && f.ends_with(".snap"))
        .collect();
    for f in &files {
        let name = &f["it__octave_compat__".len()..f.len() - ".snap".len()];
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

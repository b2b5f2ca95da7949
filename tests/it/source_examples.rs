//! Worked examples from the sources (docs/SOURCES.md), checked in `f64` and exactly in rationals.
//!
//! - Thesis Primer 2.4 (the thesis): the de Casteljau scheme of a cubic at t = 0.5.
//! - Course notes the matrix-form notes, §1.3: a planar cubic sampled at t = 0, 0.2, …, 1 through the matrix
//!   form, with the intermediate product `P · M_B`.
//!
//! Thesis Primer 3.2 (a patch) is not used: its control net is garbled beyond recovery in the
//! source text (the net is printed as dozens of repeated vectors), so it cannot serve as an
//! oracle.

use cagd::bernstein::basis_matrix;
use cagd::bezier::{bezier_to_monomial_matrix, cubic_bezier_matrix, BezierCurve};
use cagd::exact::rational_from_decimal;
use cagd::Scalar;
use nalgebra::DMatrix;
use num_rational::BigRational;

fn q(n: i64, d: i64) -> BigRational {
    <BigRational as Scalar>::from_ratio(n, d)
}

fn dec(text: &str) -> BigRational {
    rational_from_decimal(text).expect("decimal literal")
}

/// Distance in units in the last place between two finite doubles of the same sign (or zero).
fn ulps(a: f64, b: f64) -> u64 {
    if a == b {
        return 0;
    }
    let key = |x: f64| {
        let bits = x.to_bits() as i64;
        if bits < 0 {
            i64::MIN - bits
        } else {
            bits
        }
    };
    key(a).abs_diff(key(b))
}

// ---------------------------------------------------------------------------------------------
// Thesis Primer 2.4
// ---------------------------------------------------------------------------------------------

fn primer_2_4() -> BezierCurve<f64> {
    BezierCurve::from_points(&[
        [0.0, 0.0, 0.0],
        [0.0, 2.0, 2.0],
        [8.0, 2.0, 0.0],
        [4.0, 0.0, 0.0],
    ])
    .unwrap()
}

/// The correct scheme at t = 0.5, level by level, worked by hand (every value is a dyadic
/// rational, so `f64` must reproduce it exactly):
///
/// ```text
/// r = 0: b0 = (0,0,0)  b1 = (0,2,2)    b2 = (8,2,0)  b3 = (4,0,0)
/// r = 1:      (0,1,1)       (4,2,1)         (6,1,0)
/// r = 2:      (2,1.5,1)     (5,1.5,0.5)
/// r = 3:      (3.5,1.5,0.75)
/// ```
///
/// The scheme printed in the thesis is damaged in the source text (OCR): it shows eight column
/// vectors, in this order, of which only the last is right:
/// - `[0;0;0;0]` — b0 with a stray fourth entry;
/// - `[0;2;2;1]` — b1 = (0,2,2) with a stray `1`;
/// - `[0;1;1;1]` — b_0^1 = (0,1,1) with a stray `1`;
/// - `[8;2;2;1]` — should be b2 = (8,2,0): third entry wrong, stray `1`;
/// - `[4;2;1.5;1]` — b_1^1 = (4,2,1) and b_0^2 = (2,1.5,1) run together;
/// - `[4;-6;1;0;0]` — b3 = (4,0,0) and b_2^1 = (6,1,0) run together, `6` misread as `-6`;
/// - `[5;1.5;1.5;0.5]` — b_1^2 = (5,1.5,0.5) with the `1.5` doubled;
/// - `[3.5;1.5;0.75]` — b_0^3, correct.
///
/// b_0^2 = (2,1.5,1) never appears intact.
const PRIMER_2_4_LEVELS: [&[[f64; 3]]; 4] = [
    &[
        [0.0, 0.0, 0.0],
        [0.0, 2.0, 2.0],
        [8.0, 2.0, 0.0],
        [4.0, 0.0, 0.0],
    ],
    &[[0.0, 1.0, 1.0], [4.0, 2.0, 1.0], [6.0, 1.0, 0.0]],
    &[[2.0, 1.5, 1.0], [5.0, 1.5, 0.5]],
    &[[3.5, 1.5, 0.75]],
];

#[test]
fn primer_2_4_scheme_level_by_level_f64() {
    let curve = primer_2_4();
    let scheme = curve.scheme(0.5);
    assert_eq!(scheme.degree(), 3);
    assert_eq!(scheme.levels().len(), 4);
    for (r, expected) in PRIMER_2_4_LEVELS.iter().enumerate() {
        let level = scheme.level(r).unwrap();
        assert_eq!(level.ncols(), expected.len(), "level {r}");
        for (i, point) in expected.iter().enumerate() {
            assert_eq!(
                scheme.point(r, i).unwrap().as_slice(),
                point.as_slice(),
                "b_{i}^{r}"
            );
        }
    }
    assert!(scheme.level(4).is_none());
    assert!(scheme.point(1, 3).is_none());
    assert_eq!(scheme.point_on_curve().as_slice(), &[3.5, 1.5, 0.75]);
    assert_eq!(curve.eval(0.5).as_slice(), &[3.5, 1.5, 0.75]);
    assert_eq!(curve.eval_bernstein(0.5).as_slice(), &[3.5, 1.5, 0.75]);
    assert_eq!(
        curve.eval_matrix_form(0.5).unwrap().as_slice(),
        &[3.5, 1.5, 0.75]
    );
}

#[test]
fn primer_2_4_exact_in_rationals() {
    let curve = BezierCurve::new(primer_2_4().control().map(|x| q(x as i64, 1))).unwrap();
    let half = q(1, 2);
    let expected = [q(7, 2), q(3, 2), q(3, 4)];
    assert_eq!(curve.eval(half.clone()).as_slice(), &expected);
    assert_eq!(curve.eval_bernstein(half.clone()).as_slice(), &expected);
    assert_eq!(
        curve.eval_matrix_form(half.clone()).unwrap().as_slice(),
        &expected
    );
    let scheme = curve.scheme(half);
    for (r, level) in PRIMER_2_4_LEVELS.iter().enumerate() {
        for (i, point) in level.iter().enumerate() {
            let exact: Vec<BigRational> = point
                .iter()
                .map(|&x| <BigRational as Scalar>::from_f64(x).unwrap())
                .collect();
            assert_eq!(scheme.point(r, i).unwrap().as_slice(), exact.as_slice());
        }
    }
}

#[test]
fn primer_2_4_scheme_prints_as_the_thesis_triangle() {
    let text = primer_2_4().scheme(0.5).to_string();
    let expected = "\
de Casteljau scheme, degree 3, t = 0.5
r = 0       r = 1       r = 2           r = 3
(0, 0, 0)
(0, 2, 2)   (0, 1, 1)
(8, 2, 0)   (4, 2, 1)   (2, 1.5, 1)
(4, 0, 0)   (6, 1, 0)   (5, 1.5, 0.5)   (3.5, 1.5, 0.75)
";
    assert_eq!(text, expected);
    // In rationals the same triangle, exactly.
    let exact = BezierCurve::new(primer_2_4().control().map(|x| q(x as i64, 1))).unwrap();
    let text = exact.scheme(q(1, 2)).to_string();
    assert!(
        text.ends_with("(5, 3/2, 1/2)   (7/2, 3/2, 3/4)\n"),
        "{text}"
    );
}

#[test]
fn primer_2_4_subdivision_halves_come_from_the_scheme_edges() {
    let (left, right) = primer_2_4().subdivide(0.5).unwrap();
    let cols = |c: &BezierCurve| -> Vec<Vec<f64>> {
        c.control()
            .column_iter()
            .map(|x| x.iter().copied().collect())
            .collect()
    };
    assert_eq!(
        cols(&left),
        vec![
            vec![0.0, 0.0, 0.0],
            vec![0.0, 1.0, 1.0],
            vec![2.0, 1.5, 1.0],
            vec![3.5, 1.5, 0.75]
        ]
    );
    assert_eq!(
        cols(&right),
        vec![
            vec![3.5, 1.5, 0.75],
            vec![5.0, 1.5, 0.5],
            vec![6.0, 1.0, 0.0],
            vec![4.0, 0.0, 0.0]
        ]
    );
}

// ---------------------------------------------------------------------------------------------
// The matrix-form notes: matrix form of a cubic
// ---------------------------------------------------------------------------------------------

fn matrix_form_notes_curve() -> BezierCurve<f64> {
    BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]).unwrap()
}

/// The table of the matrix-form notes, §1.3: `t` and `p(t)` as printed (decimal commas read as points).
const MATRIX_FORM_NOTES_TABLE: [(&str, [&str; 2]); 6] = [
    ("0", ["0", "0"]),
    ("0.2", ["0.6", "0.392"]),
    ("0.4", ["1.2", "0.496"]),
    ("0.6", ["1.8", "0.504"]),
    ("0.8", ["2.4", "0.608"]),
    ("1", ["3", "1"]),
];

#[test]
fn matrix_form_notes_matrix_and_intermediate_product() {
    let m: DMatrix<f64> = cubic_bezier_matrix();
    #[rustfmt::skip]
    let printed = DMatrix::from_row_slice(4, 4, &[
        1.0, -3.0,  3.0, -1.0,
        0.0,  3.0, -6.0,  3.0,
        0.0,  0.0,  3.0, -3.0,
        0.0,  0.0,  0.0,  1.0,
    ]);
    assert_eq!(m, printed);
    assert_eq!(bezier_to_monomial_matrix::<f64>(3).unwrap(), printed);
    // "Najprej lahko izračunamo produkt prvih dveh matrik": [0 3 0 0; 0 3 -6 4].
    let product = matrix_form_notes_curve()
        .matrix_form()
        .unwrap()
        .coefficients()
        .clone();
    #[rustfmt::skip]
    let expected = DMatrix::from_row_slice(2, 4, &[
        0.0, 3.0,  0.0, 0.0,
        0.0, 3.0, -6.0, 4.0,
    ]);
    assert_eq!(product, expected);
    // Same in rationals.
    let exact =
        BezierCurve::new(matrix_form_notes_curve().control().map(|x| q(x as i64, 1))).unwrap();
    assert_eq!(
        exact.matrix_form().unwrap().coefficients(),
        &expected.map(|x| q(x as i64, 1))
    );
}

#[test]
fn matrix_form_notes_table_in_f64_by_all_three_forms() {
    let curve = matrix_form_notes_curve();
    let form = curve.matrix_form().unwrap();
    for (t, p) in MATRIX_FORM_NOTES_TABLE {
        let t: f64 = t.parse().unwrap();
        let expected: Vec<f64> = p.iter().map(|x| x.parse().unwrap()).collect();
        for (how, got) in [
            ("de Casteljau", curve.eval(t)),
            ("Bernstein", curve.eval_bernstein(t)),
            ("matrix form", form.eval(t)),
        ] {
            for k in 0..2 {
                assert!(
                    ulps(got[k], expected[k]) <= 4,
                    "{how}: p({t})[{k}] = {:e}, table says {:e}",
                    got[k],
                    expected[k]
                );
            }
        }
    }
    // The ends are exact.
    assert_eq!(curve.eval(0.0).as_slice(), &[0.0, 0.0]);
    assert_eq!(curve.eval(1.0).as_slice(), &[3.0, 1.0]);
}

#[test]
fn matrix_form_notes_table_exact_in_rationals() {
    let curve =
        BezierCurve::new(matrix_form_notes_curve().control().map(|x| q(x as i64, 1))).unwrap();
    let form = curve.matrix_form().unwrap();
    for (t, p) in MATRIX_FORM_NOTES_TABLE {
        let t = dec(t);
        let expected = [dec(p[0]), dec(p[1])];
        assert_eq!(curve.eval(t.clone()).as_slice(), &expected, "t = {t}");
        assert_eq!(curve.eval_bernstein(t.clone()).as_slice(), &expected);
        assert_eq!(form.eval(t.clone()).as_slice(), &expected);
    }
    // 0.2 really is 1/5 here: p(1/5) = (3/5, 49/125).
    assert_eq!(curve.eval(q(1, 5)).as_slice(), &[q(3, 5), q(49, 125)]);
}

#[test]
fn matrix_form_notes_table_through_the_basis_matrix() {
    // All six rows at once: B (6 × 4) times the control coordinates.
    let ts: Vec<BigRational> = MATRIX_FORM_NOTES_TABLE
        .iter()
        .map(|(t, _)| dec(t))
        .collect();
    let b = basis_matrix(3, &ts);
    let ys = nalgebra::DVector::from_vec(vec![q(0, 1), q(1, 1), q(0, 1), q(1, 1)]);
    let got = &b * &ys;
    for (k, (_, p)) in MATRIX_FORM_NOTES_TABLE.iter().enumerate() {
        assert_eq!(got[k], dec(p[1]));
    }
}

//! The course material (the lecture notes, the CAD notes) against GNU Octave: B-splines and NURBS against
//! octave-nurbs, interpolating splines against Octave's `spline` and the splines package's
//! `csape`, Hermite cubics against the two-point complete spline, Lagrange interpolation
//! against `polyfit`/`polyval` and `interp1`. The files are written by
//! `octave_ref/cases/{bspline_curves,bspline_surfaces,nurbs,spline,hermite,interp}.m`.
//!
//! Tolerance: 4 ULPs or 1e-14 relative (tests/common), except where a comment says why a
//! looser bound is justified. Run with `--nocapture` to see the worst error.

use cagd_test_support as common;

use cagd::bspline::{basis_functions, find_span, BSplineCurve, BSplineSurface};
use cagd::hermite::HermiteCubic;
use cagd::interpolation::{LagrangePolynomial, PiecewiseLinear};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::spline::{CubicSpline, EndCondition};
use cagd::{Curve, Surface};
use cagd_octave::Workspace;
use common::{array, assert_close, expected, matrix, report_worst, row};
use nalgebra::{DMatrix, DVector};
use ndarray::{Array2, Array3, Axis};

/// `assert_close` for arrays of any dimension given by reference.
fn close<D: ndarray::Dimension>(
    name: &str,
    ours: &ndarray::Array<f64, D>,
    octave: &ndarray::Array<f64, D>,
) {
    assert_close(name, ours.view().into_dyn(), octave.view().into_dyn());
}

fn dm(a: &Array2<f64>) -> DMatrix<f64> {
    DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[[i, j]])
}

fn nd(m: &DMatrix<f64>) -> Array2<f64> {
    Array2::from_shape_fn((m.nrows(), m.ncols()), |(i, j)| m[(i, j)])
}

fn keys(ws: &Workspace, prefix: &str) -> Vec<String> {
    ws.names()
        .filter_map(|n| n.strip_prefix(prefix))
        .map(str::to_string)
        .collect()
}

/// Octave's `3 × nu × nv` (or `4 × …`) array as our `(nu, nv, 3)` grid.
fn octave_grid(ws: &Workspace, name: &str) -> Array3<f64> {
    let a = array(ws, name);
    let a = a
        .into_dimensionality::<ndarray::Ix3>()
        .expect("3-D reference");
    a.permuted_axes([1, 2, 0]).as_standard_layout().to_owned()
}

/// The `k`-th coordinate slices of a `c × nu × nv` Octave array as `nu × nv` matrices.
fn coordinate_slices(ws: &Workspace, name: &str) -> Vec<DMatrix<f64>> {
    let a = array(ws, name)
        .into_dimensionality::<ndarray::Ix3>()
        .expect("3-D reference");
    a.axis_iter(Axis(0))
        .map(|s| DMatrix::from_fn(s.nrows(), s.ncols(), |i, j| s[[i, j]]))
        .collect()
}

#[test]
fn bspline_curves_match_octave_nurbs() {
    let ws = expected("bspline_curves");
    let ks = keys(&ws, "deg_");
    assert_eq!(ks.len(), 7, "{ks:?}");
    for key in &ks {
        let p = ws.scalar(&format!("deg_{key}")).unwrap() as usize;
        let knots = row(&ws, &format!("knots_{key}"));
        let c = dm(&matrix(&ws, &format!("C_{key}")));
        let u = row(&ws, &format!("u_{key}"));
        let curve = BSplineCurve::new(p, knots.clone(), c.clone()).unwrap();
        let ours = curve.eval_many(&u).unwrap();
        close(
            &format!("P_{key}"),
            &nd(&ours),
            &matrix(&ws, &format!("P_{key}")),
        );
        // The batch path of the Curve trait (clamping, no allocation per point).
        let mut batch = vec![f64::NAN; u.len() * ours.nrows()];
        Curve::eval_many_into(&curve, &u, &mut batch).unwrap();
        close(
            &format!("P_{key} (eval_many_into)"),
            &nd(&DMatrix::from_column_slice(ours.nrows(), u.len(), &batch)),
            &matrix(&ws, &format!("P_{key}")),
        );
        let by_de_boor = DMatrix::from_fn(ours.nrows(), u.len(), |r, k| {
            curve.de_boor(u[k]).unwrap()[r]
        });
        close(
            &format!("P_{key} (de Boor)"),
            &nd(&by_de_boor),
            &matrix(&ws, &format!("P_{key}")),
        );
        let d = curve.derivative().unwrap().eval_many(&u).unwrap();
        close(
            &format!("dP_{key}"),
            &nd(&d),
            &matrix(&ws, &format!("dP_{key}")),
        );
        // Spans (0-based in both) and the non-zero basis functions.
        let spans = row(&ws, &format!("S_{key}"));
        let b = matrix(&ws, &format!("B_{key}"));
        let n = c.ncols();
        let mut ours_b = Array2::zeros(b.dim());
        for (k, uk) in u.iter().enumerate() {
            let s = find_span(p, n, &knots, uk).unwrap();
            assert_eq!(s as f64, spans[k], "{key}: span at u = {uk}");
            for (i, v) in basis_functions(p, &knots, s, uk)
                .unwrap()
                .into_iter()
                .enumerate()
            {
                ours_b[[k, i]] = v;
            }
        }
        close(&format!("B_{key}"), &ours_b, &b);
        // Knot insertion.
        let ins = row(&ws, &format!("ins_{key}"));
        let refined = curve.insert_knots(&ins).unwrap();
        close(
            &format!("IC_{key}"),
            &nd(refined.control()),
            &matrix(&ws, &format!("IC_{key}")),
        );
        assert_eq!(
            refined.knots().as_slice(),
            row(&ws, &format!("IK_{key}")).as_slice(),
            "IK_{key}"
        );
    }
    report_worst("bspline curves");
}

#[test]
fn bspline_surfaces_match_octave_nurbs() {
    let ws = expected("bspline_surfaces");
    let ks = keys(&ws, "degu_");
    assert_eq!(ks.len(), 3);
    for key in &ks {
        let g = |v: &str| ws.scalar(&format!("{v}_{key}")).unwrap() as usize;
        let coords = ["X", "Y", "Z"]
            .iter()
            .map(|c| dm(&matrix(&ws, &format!("{c}_{key}"))))
            .collect();
        let s = BSplineSurface::new(
            g("degu"),
            g("degv"),
            row(&ws, &format!("ku_{key}")),
            row(&ws, &format!("kv_{key}")),
            coords,
        )
        .unwrap();
        let grid = cagd_octave::arrays::to_array3(s.eval_grid(
            &row(&ws, &format!("gu_{key}")),
            &row(&ws, &format!("gv_{key}")),
        ));
        let expected = octave_grid(&ws, &format!("S_{key}"));
        close(&format!("S_{key} (eval_grid)"), &grid, &expected);
        check_grid_paths(&s, &format!("S_{key}"), &ws, key, &expected);
    }
    report_worst("bspline surfaces");
}

/// The grid `gu_<key> × gv_<key>` of `s` by `eval_grid_into` and point by point with `eval`,
/// both against Octave's `expected`.
fn check_grid_paths<S: Surface>(
    s: &S,
    name: &str,
    ws: &Workspace,
    key: &str,
    expected: &Array3<f64>,
) {
    let (gu, gv) = (row(ws, &format!("gu_{key}")), row(ws, &format!("gv_{key}")));
    check_grid_paths_at(s, name, &gu, &gv, expected);
}

fn check_grid_paths_at<S: Surface>(
    s: &S,
    name: &str,
    gu: &[f64],
    gv: &[f64],
    expected: &Array3<f64>,
) {
    let d = s.dim();
    let mut out = vec![f64::NAN; gu.len() * gv.len() * d];
    s.eval_grid_into(gu, gv, &mut out).unwrap();
    let into = Array3::from_shape_vec((gu.len(), gv.len(), d), out).unwrap();
    close(&format!("{name} (eval_grid_into)"), &into, expected);
    let per_point =
        Array3::from_shape_fn((gu.len(), gv.len(), d), |(a, b, k)| s.eval(gu[a], gv[b])[k]);
    close(&format!("{name} (eval per point)"), &per_point, expected);
}

#[test]
fn nurbs_curves_match_octave_nurbs() {
    let ws = expected("nurbs");
    for key in ["p2", "p3"] {
        let p = ws.scalar(&format!("deg_{key}")).unwrap() as usize;
        let h = dm(&matrix(&ws, &format!("H_{key}")));
        let knots = row(&ws, &format!("knots_{key}"));
        let c = NurbsCurve::from_homogeneous(BSplineCurve::new(p, knots, h).unwrap()).unwrap();
        let u = row(&ws, &format!("u_{key}"));
        let pts = DMatrix::from_fn(3, u.len(), |r, k| c.try_eval(u[k]).unwrap()[r]);
        close(
            &format!("P_{key}"),
            &nd(&pts),
            &matrix(&ws, &format!("P_{key}")),
        );
        let mut batch = vec![f64::NAN; u.len() * 3];
        c.try_eval_many_into(&u, &mut batch).unwrap();
        close(
            &format!("P_{key} (try_eval_many_into)"),
            &nd(&DMatrix::from_column_slice(3, u.len(), &batch)),
            &matrix(&ws, &format!("P_{key}")),
        );
        let tan = DMatrix::from_fn(3, u.len(), |r, k| c.try_eval_derivative(u[k]).unwrap()[r]);
        close(
            &format!("T_{key}"),
            &nd(&tan),
            &matrix(&ws, &format!("T_{key}")),
        );
        let ins = row(&ws, &format!("ins_{key}"));
        let refined = c.insert_knots(&ins).unwrap();
        close(
            &format!("IH_{key}"),
            &nd(refined.homogeneous().control()),
            &matrix(&ws, &format!("IH_{key}")),
        );
        assert_eq!(refined.knots(), row(&ws, &format!("IK_{key}")).as_slice());
    }
    report_worst("nurbs curves");
}

#[test]
fn circles_match_nrbcirc() {
    let ws = expected("nurbs");
    for k in 1..=6 {
        let a = row(&ws, &format!("circ_{k}_args"));
        let c = NurbsCurve::arc(a[0], &a[1..4], a[4], a[5]).unwrap();
        assert_eq!(
            c.knots(),
            row(&ws, &format!("circ_{k}_knots")).as_slice(),
            "circle {k}"
        );
        close(
            &format!("circ_{k}_H"),
            &nd(c.homogeneous().control()),
            &matrix(&ws, &format!("circ_{k}_H")),
        );
        let u = row(&ws, &format!("circ_{k}_u"));
        let pts = DMatrix::from_fn(3, u.len(), |r, j| c.try_eval(u[j]).unwrap()[r]);
        close(
            &format!("circ_{k}_P"),
            &nd(&pts),
            &matrix(&ws, &format!("circ_{k}_P")),
        );
        let mut batch = vec![f64::NAN; u.len() * 3];
        Curve::eval_many_into(&c, &u, &mut batch).unwrap();
        close(
            &format!("circ_{k}_P (eval_many_into)"),
            &nd(&DMatrix::from_column_slice(3, u.len(), &batch)),
            &matrix(&ws, &format!("circ_{k}_P")),
        );
        for j in 0..u.len() {
            let x = pts.column(j);
            let r = ((x[0] - a[1]).powi(2) + (x[1] - a[2]).powi(2)).sqrt();
            assert!(
                (r - a[0]).abs() <= 4.0 * f64::EPSILON * a[0].max(1.0) * 4.0,
                "circle {k}: radius {r}"
            );
        }
    }
    report_worst("circles");
}

#[test]
fn nurbs_surface_and_ruled_surface_match_octave_nurbs() {
    let ws = expected("nurbs");
    let ku = row(&ws, "srf_ku");
    let kv = row(&ws, "srf_kv");
    let coords = coordinate_slices(&ws, "srf_H");
    let (nu, nv) = coords[0].shape();
    let (p, q) = (ku.len() - nu - 1, kv.len() - nv - 1);
    let s =
        NurbsSurface::from_homogeneous(BSplineSurface::new(p, q, ku, kv, coords).unwrap()).unwrap();
    let grid =
        cagd_octave::arrays::to_array3(s.eval_grid(&row(&ws, "srf_gu"), &row(&ws, "srf_gv")));
    let expected = octave_grid(&ws, "srf_S");
    close("srf_S", &grid, &expected);
    check_grid_paths_at(
        &s,
        "srf_S",
        &row(&ws, "srf_gu"),
        &row(&ws, "srf_gv"),
        &expected,
    );

    let curve = |h: &str, k: &str| {
        let h = dm(&matrix(&ws, h));
        let k = row(&ws, k);
        let p = k.len() - h.ncols() - 1;
        NurbsCurve::from_homogeneous(BSplineCurve::new(p, k, h).unwrap()).unwrap()
    };
    let ruled =
        NurbsSurface::ruled(&curve("rul_H1", "rul_k1"), &curve("rul_H2", "rul_k2")).unwrap();
    let grid =
        cagd_octave::arrays::to_array3(ruled.eval_grid(&row(&ws, "rul_gu"), &row(&ws, "rul_gv")));
    let expected = octave_grid(&ws, "rul_S");
    close("rul_S", &grid, &expected);
    check_grid_paths_at(
        &ruled,
        "rul_S",
        &row(&ws, "rul_gu"),
        &row(&ws, "rul_gv"),
        &expected,
    );
    report_worst("nurbs surfaces");
}

#[test]
fn splines_match_octave_spline_and_csape() {
    let ws = expected("spline");
    let ks = keys(&ws, "V_");
    assert_eq!(ks.len(), 13, "{ks:?}");
    for key in &ks {
        let t = row(&ws, &format!("t_{key}"));
        let y = dm(&matrix(&ws, &format!("Y_{key}")));
        let end = if key.starts_with("closed") {
            EndCondition::Closed
        } else if key.starts_with("natural") {
            EndCondition::Natural
        } else {
            let v = |n: &str| {
                DVector::from_column_slice(matrix(&ws, &format!("{n}_{key}")).as_slice().unwrap())
            };
            EndCondition::Clamped {
                start: v("s0"),
                end: v("sn"),
            }
        };
        let s = CubicSpline::interpolate_with_params(y, t, end).unwrap();
        let e = row(&ws, &format!("e_{key}"));
        close(
            &format!("V_{key}"),
            &nd(&s.eval_many(&e)),
            &matrix(&ws, &format!("V_{key}")),
        );
        let d = s.dim();
        let mut batch = vec![f64::NAN; e.len() * d];
        Curve::eval_many_into(&s, &e, &mut batch).unwrap();
        close(
            &format!("V_{key} (eval_many_into)"),
            &nd(&DMatrix::from_column_slice(d, e.len(), &batch)),
            &matrix(&ws, &format!("V_{key}")),
        );
        let per_point = DMatrix::from_fn(d, e.len(), |r, k| s.eval(e[k])[r]);
        close(
            &format!("V_{key} (eval per point)"),
            &nd(&per_point),
            &matrix(&ws, &format!("V_{key}")),
        );
    }
    report_worst("splines");
}

#[test]
fn hermite_cubics_match_two_point_complete_splines() {
    let ws = expected("hermite");
    let u = row(&ws, "u");
    for k in 1..=4 {
        let c = HermiteCubic::from_geometry(dm(&matrix(&ws, &format!("G_{k}")))).unwrap();
        let ours = DMatrix::from_fn(c.dim(), u.len(), |r, j| c.eval(u[j])[r]);
        close(
            &format!("V_{k}"),
            &nd(&ours),
            &matrix(&ws, &format!("V_{k}")),
        );
    }
    report_worst("hermite");
}

#[test]
fn lagrange_and_linear_interpolation_match_polyfit_and_interp1() {
    let ws = expected("interp");
    let ks = keys(&ws, "L_");
    assert_eq!(ks.len(), 4);
    for key in &ks {
        let x = row(&ws, &format!("x_{key}"));
        let y = row(&ws, &format!("y_{key}"));
        let e = row(&ws, &format!("e_{key}"));
        let f = LagrangePolynomial::new(x.clone(), y.clone()).unwrap();
        // polyfit solves a least-squares problem with a Vandermonde matrix (QR); its
        // coefficients carry errors of about cond(V)·eps (cond ≈ 1e4–1e5 for these nodes),
        // and polyval sums them. So coefficients and values are compared with a bound of
        // 1e-10 relative, and the values are also compared with the exact Lagrange values
        // computed in rationals from the same doubles (which must be within 1e-14).
        let c = f.coefficients().unwrap();
        let oc = row(&ws, &format!("c_{key}"));
        let scale_c = oc.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, b) in c.iter().zip(&oc) {
            assert!(
                (a - b).abs() <= 1e-10 * scale_c,
                "c_{key}: ours {a}, Octave {b}"
            );
        }
        let ol = row(&ws, &format!("L_{key}"));
        let scale_l = ol.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let exact = {
            use cagd::Scalar;
            use num_rational::BigRational;
            let q = |v: &f64| <BigRational as Scalar>::from_f64(*v).unwrap();
            LagrangePolynomial::new(x.iter().map(q).collect(), y.iter().map(q).collect()).unwrap()
        };
        for (k, ek) in e.iter().enumerate() {
            let ours = f.eval(*ek);
            assert!(
                (ours - ol[k]).abs() <= 1e-10 * scale_l,
                "L_{key}({k}): ours {ours}, Octave {}",
                ol[k]
            );
            use cagd::Scalar;
            let ex = exact
                .eval(<num_rational::BigRational as Scalar>::from_f64(*ek).unwrap())
                .to_f64();
            assert!(
                (ours - ex).abs() <= 1e-14 * scale_l,
                "L_{key}({k}): ours {ours}, exact {ex}"
            );
        }
        // interp1 sorts the nodes; PiecewiseLinear wants them increasing.
        let mut xy: Vec<(f64, f64)> = x.into_iter().zip(y).collect();
        xy.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (x, y): (Vec<f64>, Vec<f64>) = xy.into_iter().unzip();
        let pl = PiecewiseLinear::new(x, y).unwrap();
        let ours: Vec<f64> = e.iter().map(|v| pl.eval(*v)).collect();
        close(
            &format!("PL_{key}"),
            &ndarray::Array1::from(ours),
            &ndarray::Array1::from(row(&ws, &format!("PL_{key}"))),
        );
    }
    report_worst("interpolation");
}

//! The Coons view's patch: the bilinearly blended Coons patch (thesis 4.1) of four boundary
//! curves, each a Bézier curve or a B-spline curve on its own knot vector (its domain mapped
//! onto `[0, 1]`), on an `N × N` grid — the operation layer's `coons` request
//! ([`cagd_ops::ops::Coons`]), the one the command line and the Octave package run, with the
//! boundaries as [`CurveArg`]s.
//!
//! `x(u, v) = r_c + r_d − r_cd`, `r_c = (1 − v) c1(u) + v c2(u)`,
//! `r_d = (1 − u) d1(v) + u d2(v)`, `r_cd` the bilinear interpolation of the four corners.

use cagd::bezier::BezierCurve;
use cagd::limits::Limits;
use cagd_ops::bspline_arg::{BSplineArg, SplineDegree};
use cagd_ops::ops::coons::BOUNDARY_ROLES;
use cagd_ops::ops::surface::SurfaceParams;
use cagd_ops::ops::{Coons, BEZIER_CONTROL_FORM};
use cagd_ops::{curves::CurveArg, Context, Kind, OpError, Params, Role};
use nalgebra::DMatrix;
use serde_json::Value;
use wasm_bindgen::prelude::wasm_bindgen;

use crate::views::{op_error_text, MAX_VIEW_SAMPLES};

/// What a boundary of the view is: its control points, and its knots if it is a B-spline.
const BOUNDARY_FORM: &str =
    "{\"points\": [x, y, z, …], \"knots\": [u_0, …] or null} for each of c1, c2, d1, d2";

/// The bilinearly blended Coons patch of four boundary curves on the `n × n` grid of
/// `linspace(0, 1, n)²`, by the operation layer's `coons` request.
///
/// `boundaries` is JSON text, the curves `c1 = x(·,0)`, `c2 = x(·,1)`, `d1 = x(0,·)`,
/// `d2 = x(1,·)` in that order, each `{"points": [x0, y0, z0, x1, …], "knots": [u0, …]}`
/// with 3-D control points one after the other; without knots (or `null`) a Bézier curve,
/// with knots a B-spline curve whose degree is `knots − points − 1` (as `bspline(P, U)` on
/// the command line).
///
/// The answer is the grid `x` (`n·n·3` numbers, `(a·n + b)·3 + c` for coordinate `c` at
/// `(u_a, v_b)`), followed, if `parts`, by the grids of `r_c`, `r_d` and `r_cd` (4.1–4.3).
///
/// # Errors
/// `cagd: error: ROLE: PROBLEM; expected FORM`, the role named by its key (`c1`, `boundary`,
/// `grid`, …), which the page shows under the label of the view's field: boundaries that do
/// not meet at the corners, knots that do not fit their points, a grid above the limit.
///
/// ```
/// // The command line's example: c1 = bspline([0 1 2 3 4; 0 0 0 0 0; 0 1 0 1 0],
/// // [0 0 0 1 2 3 3 3]), c2 = [4u; 1; 0], d1 = [0; v; 0], d2 = [4; v; 0]: x(1/2, 0) = c1(3/2)
/// // = 1/8 (1, 0, 1) + 3/4 (2, 0, 0) + 1/8 (3, 0, 1) = (2, 0, 1/4) by de Boor.
/// let boundaries = r#"[
///   {"points": [0,0,0, 1,0,1, 2,0,0, 3,0,1, 4,0,0], "knots": [0,0,0,1,2,3,3,3]},
///   {"points": [0,1,0, 4,1,0]},
///   {"points": [0,0,0, 0,1,0]},
///   {"points": [4,0,0, 4,1,0]}
/// ]"#;
/// let x = cagd_web::coons_view(boundaries, 3, false).unwrap();
/// assert_eq!(x[9..12], [2.0, 0.0, 0.25]); // (u, v) = (1/2, 0): (1 · 3 + 0) · 3
/// ```
#[wasm_bindgen]
pub fn coons_view(boundaries: &str, n: usize, parts: bool) -> Result<Vec<f64>, String> {
    coons_grids(boundaries, n, parts).map_err(|e| op_error_text(&e))
}

fn coons_grids(boundaries: &str, n: usize, parts: bool) -> Result<Vec<f64>, OpError> {
    let boundary = curves(boundaries)?;
    if !(2..=MAX_VIEW_SAMPLES).contains(&n) {
        return Err(OpError::new(
            Role::Grid,
            Kind::Shape,
            format!("{n} × {n} points"),
            "between 2 × 2 and 2000 × 2000 points for a view",
        ));
    }
    let us = cagd::linspace(0.0, 1.0, n);
    let op = Coons {
        at: SurfaceParams {
            u: Params::Given(us.clone()),
            v: Params::Given(us),
            list: false,
        },
        steps: parts,
        ..Coons::new(boundary)
    };
    let mut cx = Context::new(Limits::default());
    let answer = cagd_ops::execute(&op, &mut cx)?;
    let names: &[&str] = if parts {
        &["result", "rc", "rd", "rcd"]
    } else {
        &["result"]
    };
    let mut out = Vec::with_capacity(names.len() * n * n * 3);
    for name in names {
        match answer.report.get(name) {
            Some(cagd_ops::Value::Grid(g)) if g.dim() == (n, n, 3) => {
                out.extend_from_slice(g.as_slice());
            }
            _ => {
                return Err(OpError::new(
                    Role::Boundary,
                    Kind::Shape,
                    format!("the patch's {name} is not a grid of 3-D points"),
                    "boundary curves in 3-D",
                ))
            }
        }
    }
    Ok(out)
}

/// The four boundary curves of `text` (JSON), each named by its role.
fn curves(text: &str) -> Result<[CurveArg<f64>; 4], OpError> {
    let bad = |problem: String| OpError::new(Role::Boundary, Kind::Shape, problem, BOUNDARY_FORM);
    let value: Value = serde_json::from_str(text).map_err(|e| bad(format!("{e}")))?;
    let list = value
        .as_array()
        .filter(|l| l.len() == 4)
        .ok_or_else(|| bad("not four curves".into()))?;
    let mut out = Vec::with_capacity(4);
    for (role, curve) in BOUNDARY_ROLES.into_iter().zip(list) {
        out.push(boundary_curve(role, curve)?);
    }
    out.try_into().map_err(|_| bad("not four curves".into()))
}

/// The list of numbers `key` of a boundary's JSON object (None when it is absent or null).
fn number_list(role: Role, curve: &Value, key: &str) -> Result<Option<Vec<f64>>, OpError> {
    let bad = |what: &str| OpError::new(role, Kind::Shape, format!("{key} {what}"), BOUNDARY_FORM);
    match curve.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Array(xs)) => xs
            .iter()
            .map(Value::as_f64)
            .collect::<Option<Vec<f64>>>()
            .map(Some)
            .ok_or_else(|| bad("that are not all numbers")),
        Some(_) => Err(bad("that are not a list")),
    }
}

/// One boundary: a Bézier curve of its points, or with knots the B-spline curve of degree
/// `knots − points − 1` (the operation layer's B-spline rule and words), each within the
/// degree limit.
fn boundary_curve(role: Role, curve: &Value) -> Result<CurveArg<f64>, OpError> {
    let flat = number_list(role, curve, "points")?.unwrap_or_default();
    if flat.is_empty() || flat.len() % 3 != 0 {
        return Err(OpError::new(
            role,
            Kind::Shape,
            format!("{} numbers do not make points of 3 coordinates", flat.len()),
            "control points in 3-D",
        ));
    }
    cagd_ops::check::finite(role, &flat)?;
    let points = DMatrix::from_column_slice(3, flat.len() / 3, &flat);
    let cx = Context::new(Limits::default());
    let Some(knots) = number_list(role, curve, "knots")? else {
        cx.check_degree(role, points.ncols() - 1)?;
        return BezierCurve::new(points)
            .map(CurveArg::curve)
            .map_err(cagd_ops::error::lib(role, BEZIER_CONTROL_FORM));
    };
    cagd_ops::check::finite(role, &knots)?;
    let Some(p) = knots.len().checked_sub(points.ncols() + 1) else {
        return Err(OpError::new(
            role,
            Kind::Knots,
            format!("{} knots for {} control points", knots.len(), points.ncols()),
            "at least one knot more than control points: the degree is the number of knots − the number of control points − 1",
        ));
    };
    cx.check_degree(role, p)?;
    let spline = BSplineArg {
        degree: SplineDegree::Degree(p),
        knots: Some(knots),
    };
    spline
        .curve(points)
        .map(CurveArg::curve)
        .map_err(|e| e.about(role))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The four boundaries as the page sends them (Bézier where `knots` is None).
    fn json(curves: [(&[f64], Option<&[f64]>); 4]) -> String {
        let list: Vec<Value> = curves
            .iter()
            .map(|(p, k)| serde_json::json!({ "points": p, "knots": k }))
            .collect();
        Value::Array(list).to_string()
    }

    fn line(p: [f64; 3], q: [f64; 3]) -> Vec<f64> {
        let mut v = Vec::new();
        for k in 0..4 {
            let s = f64::from(k) / 3.0;
            v.extend((0..3).map(|c| p[c] + s * (q[c] - p[c])));
        }
        v
    }

    #[test]
    fn parts_add_up_and_the_corner_is_p4() {
        // Straight boundaries of the unit square with one lifted corner: x = r_c + r_d − r_cd.
        let (p1, p2, p3, p4) = ([0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [1., 1., 1.]);
        let (c1, c2, d1, d2) = (line(p1, p2), line(p3, p4), line(p1, p3), line(p2, p4));
        let n = 5;
        let g = coons_view(
            &json([(&c1, None), (&c2, None), (&d1, None), (&d2, None)]),
            n,
            true,
        )
        .unwrap();
        let len = n * n * 3;
        assert_eq!(g.len(), 4 * len);
        for i in 0..len {
            let sum = g[len + i] + g[2 * len + i] - g[3 * len + i];
            assert!((g[i] - sum).abs() < 1e-14);
        }
        assert_eq!(g[len - 3..len], [1., 1., 1.]);
        let bad = coons_view(
            &json([(&c1, None), (&c2, None), (&line(p1, p4), None), (&d2, None)]),
            n,
            false,
        );
        let e = bad.unwrap_err();
        assert!(e.starts_with("cagd: error: boundary: "), "{e}");
    }

    #[test]
    fn a_bspline_boundary_on_its_own_knots() {
        // The command line's example (issue of the operation layer): x(1/2, v) = c1(3/2) at
        // v = 0, by de Boor on [0, 3]: 1/8 (1, 0, 1) + 3/4 (2, 0, 0) + 1/8 (3, 0, 1).
        let c1 = [0., 0., 0., 1., 0., 1., 2., 0., 0., 3., 0., 1., 4., 0., 0.];
        let knots = [0., 0., 0., 1., 2., 3., 3., 3.];
        let c2 = [0., 1., 0., 4., 1., 0.];
        let d1 = [0., 0., 0., 0., 1., 0.];
        let d2 = [4., 0., 0., 4., 1., 0.];
        let n = 5;
        let g = coons_view(
            &json([(&c1, Some(&knots)), (&c2, None), (&d1, None), (&d2, None)]),
            n,
            false,
        )
        .unwrap();
        let at = |a: usize, b: usize| g[(a * n + b) * 3..(a * n + b) * 3 + 3].to_vec();
        assert_eq!(at(2, 0), [2.0, 0.0, 0.25]);
        // At (1/2, 1/2): r_c = (c1(3/2) + c2(1/2))/2 = ((2, 0, 1/4) + (2, 1, 0))/2, r_d = (d1 +
        // d2)(1/2)/2 = (2, 1/2, 0), r_cd = the corners' mean (2, 1/2, 0): x = (2, 1/2, 1/8).
        let p = at(2, 2);
        assert!(
            (p[0] - 2.0).abs() < 1e-15
                && (p[1] - 0.5).abs() < 1e-15
                && (p[2] - 0.125).abs() < 1e-15,
            "{p:?}"
        );
    }

    #[test]
    fn messages_name_the_role_never_an_option() {
        let c1 = [0., 0., 0., 1., 0., 1., 2., 0., 0.];
        let c2 = [0., 1., 0., 2., 1., 0.];
        let d1 = [0., 0., 0., 0., 1., 0.];
        let d2 = [2., 0., 0., 2., 1., 0.];
        let cases: [(String, usize, &str); 7] = [
            // Decreasing knots, too few knots, corners that do not meet, a grid too small
            // or too large, a point that is not a number, not four curves.
            (
                json([
                    (&c1, Some(&[0., 0., 1., 0.5, 1., 1.])),
                    (&c2, None),
                    (&d1, None),
                    (&d2, None),
                ]),
                5,
                "c1",
            ),
            (
                json([
                    (&c1, Some(&[0., 1.])),
                    (&c2, None),
                    (&d1, None),
                    (&d2, None),
                ]),
                5,
                "c1",
            ),
            (
                json([(&c1, None), (&c2, None), (&d1, None), (&c2, None)]),
                5,
                "boundary",
            ),
            (
                json([(&c1, None), (&c2, None), (&d1, None), (&d2, None)]),
                1,
                "grid",
            ),
            (
                json([(&c1, None), (&c2, None), (&d1, None), (&d2, None)]),
                2001,
                "grid",
            ),
            (
                r#"[{"points": [0, 0, "x"]}, {"points": []}, {}, {}]"#.into(),
                5,
                "c1",
            ),
            ("[]".into(), 5, "boundary"),
        ];
        for (text, n, name) in cases {
            let e = coons_view(&text, n, false).unwrap_err();
            assert!(e.starts_with(&format!("cagd: error: {name}: ")), "{e}");
            assert!(!e.contains("--"), "{e}");
        }
        // The knot rule's words are the operation layer's, as every front end has them.
        let e = coons_view(
            &json([
                (&c1, Some(&[0., 0., 1., 0.5, 1., 1.])),
                (&c2, None),
                (&d1, None),
                (&d2, None),
            ]),
            5,
            false,
        )
        .unwrap_err();
        assert!(
            e.ends_with(&format!("expected {}", cagd_ops::knots::KNOTS_FORM)),
            "{e}"
        );
    }
}

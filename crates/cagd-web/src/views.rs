//! The interactive views' constructions: what the page redraws on every frame of a drag.
//!
//! Points come as flat `f64` slices, one point after the other (the storage of a d×(n+1)
//! matrix whose columns are the points, as the thesis's `kontrolneT`); answers are JSON text
//! with points in the same layout, or, for the Coons grids, one `Float64Array`. Inputs are
//! checked as the command line checks them (same limits, same one-line messages), so a view
//! never panics on what a page can send.

use cagd::limits::Limits;
use cagd_cli::{CliError, ErrorKind};
use cagd_ops::knots::Degree;
use cagd_ops::ops::{BSpline, Nurbs};
use cagd_ops::ops::{DeCasteljau, Elevate, Subdivide};
use cagd_ops::{execute, Context, OpError, Operation, Params, Role};
use nalgebra::DMatrix;
use serde_json::{json, Value};
use wasm_bindgen::prelude::wasm_bindgen;

use crate::ops;

/// Most samples of a view's curve or grid side (a view's picture, not a computation).
pub(crate) const MAX_VIEW_SAMPLES: usize = 2000;

fn error_json(e: &CliError) -> String {
    json!({ "error": format!("cagd: error: {e}") }).to_string()
}

fn shape(argument: &str, problem: String, expected: &str) -> CliError {
    CliError::new(argument, problem, expected, ErrorKind::Shape)
}

/// `flat` as a `dim × k` matrix of points (columns).
fn points(argument: &str, flat: &[f64], dim: usize) -> Result<DMatrix<f64>, CliError> {
    if dim == 0 || flat.is_empty() || flat.len() % dim != 0 {
        return Err(shape(
            argument,
            format!(
                "{} numbers do not make points of {dim} coordinates",
                flat.len()
            ),
            "control points given coordinate by coordinate, one point after the other",
        ));
    }
    if let Some((problem, expected)) = cagd_ops::check::non_finite(flat) {
        return Err(CliError::new(
            argument,
            problem,
            expected,
            ErrorKind::Operation(cagd_ops::Kind::NonFinite),
        ));
    }
    Ok(DMatrix::from_column_slice(dim, flat.len() / dim, flat))
}

fn sample_count(samples: usize) -> Result<usize, CliError> {
    if (2..=MAX_VIEW_SAMPLES).contains(&samples) {
        Ok(samples)
    } else {
        Err(shape(
            "samples",
            format!("{samples} samples"),
            "between 2 and 2000 samples for a view",
        ))
    }
}

fn flat(m: &DMatrix<f64>) -> Value {
    json!(m.as_slice())
}

/// The Bézier curve of the `dim`-dimensional control points `control` (thesis algorithm 1),
/// through the command line's requests ([`DeCasteljau`], [`Subdivide`], [`Elevate`]):
/// `samples` points of the curve, the whole de Casteljau scheme at `t` (`levels[r]` holds
/// `b_0^r(t) … b_{n−r}^r(t)`), the point `b_0^n(t)`, the control points of the two halves of
/// the subdivision at `t` (`left`, `right`; at the ends of the interval, where one half would
/// be empty, `halves_error` says so instead) and of the degree-elevated curve (`elevated`);
/// `warnings` lists the requests' warnings (a `t` outside `[0, 1]`).
///
/// ```
/// let v = cagd_web::bezier_view(vec![0., 0., 0., 2., 8., 2., 4., 0.], 2, 0.5, 3);
/// let v: serde_json::Value = serde_json::from_str(&v).unwrap();
/// assert_eq!(v["point"], serde_json::json!([3.5, 1.5]));
/// assert_eq!(v["levels"].as_array().unwrap().len(), 4);
/// ```
#[wasm_bindgen]
pub fn bezier_view(control: Vec<f64>, dim: usize, t: f64, samples: usize) -> String {
    let answer = || -> Result<Value, CliError> {
        let b = points("control", &control, dim)?;
        let n = sample_count(samples)?;
        let (curve, mut warnings) = ops::execute(&DeCasteljau {
            t: Params::Samples(n),
            ..DeCasteljau::new(b.clone())
        })?;
        let (scheme, more) = ops::execute(&DeCasteljau {
            t: Params::Given(vec![t]),
            steps: true,
            ..DeCasteljau::new(b.clone())
        })?;
        warnings.extend(more);
        // At the highest degree allowed the elevated curve is over the limit: the view shows
        // the rest and says why that part is missing.
        let elevated = ops::execute(&Elevate::new(b.clone()));
        let mut view = json!({
            "curve": item(&curve.report, "result"),
            "levels": levels(&scheme.report),
            "point": item(&scheme.report, "result"),
            "elevated": elevated.as_ref().map_or(Value::Null, |(e, _)| item(&e.report, "control")),
            "warnings": warnings.iter().map(|w| format!("{}: {}", w.role.key(), w.message)).collect::<Vec<_>>(),
        });
        if let Err(e) = &elevated {
            view["elevated_error"] = json!(format!("cagd: error: {e}"));
        }
        match ops::execute(&Subdivide {
            t: Some(t),
            ..Subdivide::new(b)
        }) {
            Ok((halves, _)) => {
                view["left"] = item(&halves.report, "left");
                view["right"] = item(&halves.report, "right");
            }
            Err(e) => view["halves_error"] = json!(format!("cagd: error: {e}")),
        }
        Ok(view)
    };
    answer().map_or_else(|e| error_json(&e), |v| v.to_string())
}

/// The report's matrix `name`, flat (column-major: one point after the other).
fn item(report: &cagd_ops::Report<f64>, name: &str) -> Value {
    report.matrix(name).map_or(Value::Null, flat)
}

/// The levels `r0 … rn` of the report's de Casteljau scheme, each flat.
fn levels(report: &cagd_ops::Report<f64>) -> Value {
    let Some(cagd_ops::Value::Shown { data, .. }) = report.get("scheme") else {
        return Value::Null;
    };
    let cagd_ops::Value::Record(parts) = data.as_ref() else {
        return Value::Null;
    };
    parts
        .iter()
        .filter_map(|p| match &p.value {
            cagd_ops::Value::Matrix(m) => Some(flat(m)),
            _ => None,
        })
        .collect()
}

/// An error of the operation layer as the page shows it: `cagd: error: NAME: PROBLEM;
/// expected FORM`, the argument named as the view names it (the role's key, `samples` for the
/// number of samples) and the words after it the operation's, as every front end has them.
pub(crate) fn op_error_text(e: &OpError) -> String {
    let name = match e.role {
        Role::Samples => "samples",
        role => role.key(),
    };
    format!("cagd: error: {name}: {e}")
}

/// A B-spline or NURBS view's request run on the page's defaults, and what the view draws:
/// the parameters, the curve there, the basis functions (row `i` for function `i`), the knots
/// and the domain.
fn spline_view_json<O: Operation<f64>>(
    op: &O,
    knots: &[f64],
    domain: (f64, f64),
) -> Result<Value, String> {
    let mut cx = Context::new(Limits::default());
    let answer = execute(op, &mut cx).map_err(|e| op_error_text(&e))?;
    let item = |name: &str| {
        answer
            .report
            .matrix(name)
            .cloned()
            .ok_or_else(|| format!("cagd: internal error: the answer has no `{name}`"))
    };
    let (t, curve, basis) = (item("t")?, item("result")?, item("basis")?);
    let rows: Vec<Vec<f64>> = basis
        .column_iter()
        .map(|c| c.iter().copied().collect())
        .collect();
    Ok(json!({
        "t": t.as_slice(),
        "curve": curve.as_slice(),
        "basis": rows,
        "knots": knots,
        "domain": [domain.0, domain.1],
    }))
}

/// A B-spline curve of degree `degree` (de Boor; the CAD notes): `samples` parameters over its
/// domain, the curve there and the basis functions `N_{i,p}` (row `i`), with the knot vector
/// used (`knots` empty means clamped uniform on [0, 1]). The `bspline` request of every front
/// end, so the same bad knots get the same words as on the command line.
///
/// ```
/// let v = cagd_web::bspline_view(vec![0., 0., 1., 2., 3., 2., 4., 0.], 2, 2, vec![], 5);
/// let v: serde_json::Value = serde_json::from_str(&v).unwrap();
/// assert_eq!(v["knots"], serde_json::json!([0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]));
/// assert_eq!(v["basis"].as_array().unwrap().len(), 4);
/// ```
#[wasm_bindgen]
pub fn bspline_view(
    control: Vec<f64>,
    dim: usize,
    degree: usize,
    knots: Vec<f64>,
    samples: usize,
) -> String {
    let answer = || -> Result<Value, String> {
        let b = points("control", &control, dim).map_err(|e| format!("cagd: error: {e}"))?;
        let n = sample_count(samples).map_err(|e| format!("cagd: error: {e}"))?;
        let op = BSpline {
            degree: Degree::Degree(degree),
            knots: (!knots.is_empty()).then(|| knots.clone()),
            t: Params::Samples(n),
            basis: true,
            ..BSpline::new(b)
        };
        // The knots used (clamped when none are given), by the request's one knot rule.
        let curve = op
            .curve(&Context::new(Limits::default()))
            .map_err(|e| op_error_text(&e))?;
        spline_view_json(&op, curve.knots().as_slice(), curve.domain())
    };
    answer()
        .unwrap_or_else(|e| json!({ "error": e }))
        .to_string()
}

/// A NURBS curve (the CAD notes): as [`bspline_view`], with one positive weight per control
/// point, and the rational basis functions `R_{i,p}` (row `i`).
///
/// ```
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let v = cagd_web::nurbs_view(vec![1., 0., 1., 1., 0., 1.], 2, vec![1., w, 1.], 2, vec![], 9);
/// let v: serde_json::Value = serde_json::from_str(&v).unwrap();
/// let xy: Vec<f64> = serde_json::from_value(v["curve"].clone()).unwrap();
/// assert!(xy.chunks(2).all(|p| (p[0].hypot(p[1]) - 1.0).abs() < 1e-15)); // a quarter circle
/// ```
#[wasm_bindgen]
pub fn nurbs_view(
    control: Vec<f64>,
    dim: usize,
    weights: Vec<f64>,
    degree: usize,
    knots: Vec<f64>,
    samples: usize,
) -> String {
    let answer = || -> Result<Value, String> {
        let b = points("control", &control, dim).map_err(|e| format!("cagd: error: {e}"))?;
        let n = sample_count(samples).map_err(|e| format!("cagd: error: {e}"))?;
        let op = Nurbs {
            degree: Degree::Degree(degree),
            knots: (!knots.is_empty()).then(|| knots.clone()),
            t: Params::Samples(n),
            basis: true,
            ..Nurbs::new(b, weights)
        };
        // The knots used (clamped when none are given), by the request's one knot rule.
        let curve = op
            .curve(&Context::new(Limits::default()))
            .map_err(|e| op_error_text(&e))?;
        spline_view_json(&op, curve.knots(), curve.domain())
    };
    answer()
        .unwrap_or_else(|e| json!({ "error": e }))
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(s: &str) -> Value {
        serde_json::from_str(s).unwrap()
    }

    #[test]
    fn bezier_scheme_halves_and_elevation_of_primer_2_4() {
        let control = vec![0., 0., 0., 0., 2., 2., 8., 2., 0., 4., 0., 0.];
        let v = parse(&bezier_view(control, 3, 0.5, 11));
        assert_eq!(v["point"], json!([3.5, 1.5, 0.75]));
        assert_eq!(v["levels"][1], json!([0., 1., 1., 4., 2., 1., 6., 1., 0.]));
        // The halves share the point at t; the elevated curve keeps the end points.
        assert_eq!(
            v["left"].as_array().unwrap()[9..],
            v["point"].as_array().unwrap()[..]
        );
        assert_eq!(
            v["right"].as_array().unwrap()[..3],
            v["point"].as_array().unwrap()[..]
        );
        let e = v["elevated"].as_array().unwrap();
        assert_eq!(e.len(), 15);
        assert_eq!(e[3..6], [json!(0.0), json!(1.5), json!(1.5)]);
        assert_eq!(v["curve"].as_array().unwrap().len(), 33);
    }

    #[test]
    fn the_ends_of_the_slider_show_the_scheme_without_halves() {
        let control = vec![0., 0., 0., 2., 8., 2., 4., 0.];
        for (t, point) in [(0.0, [0.0, 0.0]), (1.0, [4.0, 0.0])] {
            let v = parse(&bezier_view(control.clone(), 2, t, 11));
            assert_eq!(v["point"], json!(point), "{v}");
            assert!(v["left"].is_null() && v["halves_error"].is_string(), "{v}");
            assert_eq!(v["elevated"].as_array().unwrap().len(), 10);
        }
    }

    #[test]
    fn bad_view_input_is_a_one_line_message() {
        let v = parse(&bezier_view(vec![0., 1., 2.], 2, 0.5, 10));
        let e = v["error"].as_str().unwrap();
        assert!(e.starts_with("cagd: error: control: 3 numbers"), "{e}");
        // Outside [0, 1] the curve is extrapolated, as on the command line; there are no halves.
        let v = parse(&bezier_view(vec![0., 1., 2., 3.], 2, 1.5, 10));
        assert_eq!(
            v["warnings"][0],
            "t: t = 1.5 lies outside [0, 1]; the curve is extrapolated there"
        );
        let e = v["halves_error"].as_str().unwrap();
        assert!(e.starts_with("cagd: error: t: right half of a subdivided Bézier curve: interval [1.5, 1] is empty"), "{e}");
        // A degree over the limit, worded as the command line words it after the name.
        let v = parse(&bezier_view(vec![0.; 2 * 1002], 2, 0.5, 10));
        let e = v["error"].as_str().unwrap();
        assert_eq!(e, "cagd: error: control: degree: 1001 exceeds the limit of 1000; expected a lower degree (fewer control points or nodes)");
        let v = parse(&bspline_view(
            vec![0., 1., 2., 3.],
            2,
            1,
            vec![0., 1., 0.5, 1.],
            10,
        ));
        assert!(v["error"]
            .as_str()
            .unwrap()
            .starts_with("cagd: error: knots: "));
        let v = parse(&nurbs_view(
            vec![0., 1., 2., 3.],
            2,
            vec![1., -1.],
            1,
            vec![],
            10,
        ));
        assert!(v["error"]
            .as_str()
            .unwrap()
            .starts_with("cagd: error: weights: "));
    }

    #[test]
    fn bspline_basis_is_a_partition_of_unity() {
        let v = parse(&bspline_view(
            vec![0., 0., 1., 2., 3., 2., 4., 0., 5., 1.],
            2,
            3,
            vec![0., 0., 0., 0., 0.3, 1., 1., 1., 1.],
            21,
        ));
        let basis: Vec<Vec<f64>> = serde_json::from_value(v["basis"].clone()).unwrap();
        assert_eq!(basis.len(), 5);
        for k in 0..21 {
            let s: f64 = basis.iter().map(|row| row[k]).sum();
            assert!((s - 1.0).abs() < 1e-14);
        }
    }

    /// The command line's words after `argument: ` for `args`.
    /// The command line's words after `argument: `, without how it read a matrix of points
    /// (the page takes coordinates, never a matrix to orient).
    fn cli_words(args: &[&str], argument: &str) -> String {
        let e = cagd_cli::run(std::iter::once("cagd").chain(args.iter().copied())).unwrap_err();
        let text = e.to_string();
        let mut words = text
            .strip_prefix(&format!("{argument}: "))
            .unwrap_or_else(|| panic!("{text}"))
            .to_string();
        if let Some(i) = words.find(" (read as ") {
            let end = words[i..].find(");").map_or(words.len(), |j| i + j + 1);
            words.replace_range(i..end, "");
        }
        words
    }

    /// The page's words after `cagd: error: name: `.
    fn page_words(answer: &str, name: &str) -> String {
        let v = parse(answer);
        let e = v["error"].as_str().unwrap_or_else(|| panic!("{v}"));
        e.strip_prefix(&format!("cagd: error: {name}: "))
            .unwrap_or_else(|| panic!("{e}"))
            .to_string()
    }

    #[test]
    fn bad_knots_and_weights_read_as_on_the_command_line() {
        let cases = [
            // knots decreasing, too few, too many; too few control points; a point domain.
            (vec![0., 1., 0.5, 1.], "[0 1 0.5 1]", 1, "--knots", "knots"),
            (vec![0., 0., 1., 1.], "[0 0 1 1]", 2, "--knots", "knots"),
            (
                vec![0., 0., 0., 0.5, 1., 1., 1.],
                "[0 0 0 0.5 1 1 1]",
                1,
                "--knots",
                "knots",
            ),
            (vec![], "", 3, "CONTROL", "control"),
            (
                vec![0., 0., 0., 0., 0.],
                "[0 0 0 0 0]",
                1,
                "--knots",
                "knots",
            ),
        ];
        for (knots, text, degree, cli_name, page_name) in cases {
            let control = vec![0., 0., 1., 2., 3., 0.];
            let p = degree.to_string();
            let mut args = vec![
                "bspline",
                "[0 1 3; 0 2 0]",
                "--columns",
                "--degree",
                p.as_str(),
            ];
            if !text.is_empty() {
                args.extend(["--knots", text]);
            }
            let page = bspline_view(control, 2, degree, knots, 11);
            assert_eq!(page_words(&page, page_name), cli_words(&args, cli_name));
        }
        let w = bspline_view(vec![0., 0., 1., 2.], 2, 1, vec![], 1);
        assert!(page_words(&w, "samples").starts_with("1 samples"), "{w}");
        // Weights first, then the knots: a zero weight, a missing weight.
        for (weights, text) in [(vec![1., 0., 1.], "[1 0 1]"), (vec![1., 1.], "[1 1]")] {
            let args = [
                "nurbs",
                "[0 1 3; 0 2 0]",
                "--columns",
                "--weights",
                text,
                "--degree",
                "5",
            ];
            let page = nurbs_view(vec![0., 0., 1., 2., 3., 0.], 2, weights, 5, vec![], 11);
            assert_eq!(page_words(&page, "weights"), cli_words(&args, "--weights"));
        }
        // The degree limit is the operation's, without the command line's way to raise it.
        let page = bspline_view(vec![0., 0., 1., 2.], 2, 5000, vec![], 11);
        let cli = cli_words(
            &["bspline", "[0 1; 0 2]", "--columns", "--degree", "5000"],
            "--degree",
        );
        let raise = " (raise it with --max-degree or CAGD_MAX_DEGREE)";
        assert_eq!(page_words(&page, "degree"), cli.replacen(raise, "", 1));
        assert!(cli.contains(raise), "{cli}");
    }
}

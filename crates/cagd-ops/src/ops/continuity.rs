//! `continuity`: what holds where two Bézier curves join — `C⁰`, `C¹`, `G¹`, `C²` — with the
//! numbers compared (the lecture notes, "napojování"), and the free control point of the
//! lecture notes' example.
//!
//! The first curve `x` (degree `n`, `x_0 … x_n`) ends at `u = 1`, the second `¹x` (degree `m`,
//! `y_0 … y_m`) starts at `v = 0`: `x'(1) = n (x_n − x_{n−1})`, `¹x'(0) = m (y_1 − y_0)`,
//! `x''(1) = n(n−1)(x_n − 2x_{n−1} + x_{n−2})`, `¹x''(0) = m(m−1)(y_2 − 2y_1 + y_0)`. `C¹`
//! needs `x'(1) = ¹x'(0)`; `x'(1) = k · ¹x'(0)` with `k > 0` is `G¹` (the lecture notes call it
//! `C¹`). With the second-to-last point of the first curve free,
//! `x_{n−1}(k) = x_n + k · (m/n)(y_0 − y_1)` ([`cagd::continuity::free_point_line`]).
//!
//! ```
//! use cagd_ops::{execute, ops::Continuity, Context};
//! use nalgebra::dmatrix;
//! // The lecture notes' example: x = 3 + k, y = 4 − 2k, z = 3 + 3k; k = 1 is C1.
//! let first = dmatrix![2.0, 3.0, 3.0; 3.0, 1.0, 4.0; 3.0, 4.0, 3.0];
//! let second = dmatrix![3.0, 2.0, 5.0, 5.0; 4.0, 6.0, 7.0, 2.0; 3.0, 0.0, 5.0, 3.0];
//! let op = Continuity { free_point: true, ..Continuity::new(first, second) };
//! let answer = execute(&op, &mut Context::new(cagd::Limits::default()))?;
//! assert_eq!(answer.report.matrix("point").unwrap().as_slice(), &[4.0, 2.0, 6.0]);
//! assert_eq!(answer.report.get("continuity").map(|_| ()), Some(()));
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::bezier::BezierCurve;
use cagd::continuity::{bezier_joint, bezier_joint_cost, free_point_line, BezierJoint};
use cagd::cost::max_bits;
use cagd::Scalar;
use nalgebra::{DMatrix, DVector};

use super::to_f64;
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::{number_text_digits, Answer, Context, Operation, Report, Role, Value};

/// The form of the two curves.
const FORM: &str = "control points, one per column, of the same dimension";

/// The form of the two curves with a free point.
const FREE_FORM: &str = "with the free point: the first curve's control points without its second-to-last (at least 2), the second curve of degree ≥ 1, both of the same dimension";

/// The joint of two Bézier curves.
#[derive(Debug, Clone, PartialEq)]
pub struct Continuity<T> {
    /// The first curve's control points (without its second-to-last with `free_point`).
    pub first: DMatrix<T>,
    /// The second curve's control points.
    pub second: DMatrix<T>,
    /// The first curve's second-to-last control point is unknown: the line of points that
    /// make the joint smooth, and the joint with the point for `k`.
    pub free_point: bool,
    /// With `free_point`: the factor `k` of `x'(1) = k · ¹x'(0)` (default 1, the `C¹` point).
    pub k: Option<T>,
    /// Each curve's control points and derivative polygons.
    pub steps: bool,
    /// A picture: both curves and their control polygons.
    pub drawing: bool,
}

impl<T> Continuity<T> {
    /// The joint of the curves of `first` and `second`.
    pub fn new(first: DMatrix<T>, second: DMatrix<T>) -> Self {
        Continuity {
            first,
            second,
            free_point: false,
            k: None,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for Continuity<T> {
    /// With a free point `free_base`, `free_direction`, `free_point` (the line in words),
    /// `k_used`, `point`; with steps `first` and `second` (`control`, `d1`, `d2`); then `end`,
    /// `start`, `d_end`, `d_start`, `dd_end`, `dd_start` (`d × 1`), `k` if the tangents are
    /// parallel, `continuity` (`C0`, `C1`, `G1`, `C2`: 1 holds, 0 not) and `verdict`.
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        cx.check_degree(Role::First, self.first.ncols())?;
        cx.check_degree(Role::Second, self.second.ncols().saturating_sub(1))?;
        if self.k.is_some() && !self.free_point {
            return Err(OpError::new(
                Role::Factor,
                Kind::Usage,
                "has no effect without the free point",
                "the free point with k, or no k",
            ));
        }
        let points = self.first.ncols().max(self.second.ncols());
        let bits = max_bits(self.first.iter()).max(max_bits(self.second.iter()));
        let cost = bezier_joint_cost(points, self.first.nrows(), bits);
        cx.check_cost(Role::Joint, cost, T::EXACT)?;
        let second = BezierCurve::new(self.second.clone()).map_err(lib(Role::Second, FORM))?;
        let mut report = Report::new();
        let first = if self.free_point {
            self.with_free_point(&second, &mut report, cx)?
        } else {
            BezierCurve::new(self.first.clone()).map_err(lib(Role::First, FORM))?
        };
        if first.dim() != second.dim() {
            return Err(OpError::new(
                Role::Joint,
                Kind::Shape,
                format!("points of dimension {} and {}", first.dim(), second.dim()),
                FORM,
            ));
        }
        if self.steps {
            push_polygons(&mut report, [("first", &first), ("second", &second)]);
        }
        let joint = bezier_joint(&first, &second).map_err(lib(Role::Joint, FORM))?;
        push_joint(&mut report, &joint, cx.digits);
        let drawing = if self.drawing {
            Some(picture(cx, &first, &second, &joint)?)
        } else {
            None
        };
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }
}

impl<T: Scalar> Continuity<T> {
    /// The line of free points, the point for `k`, and the first curve with it.
    fn with_free_point(
        &self,
        second: &BezierCurve<T>,
        report: &mut Report<T>,
        cx: &mut Context,
    ) -> Result<BezierCurve<T>> {
        let (d, n) = self.first.shape();
        if n < 2 || second.degree() < 1 || d != second.dim() {
            return Err(OpError::new(
                Role::First,
                Kind::Shape,
                format!("{n} known point(s) of dimension {d}"),
                FREE_FORM,
            ));
        }
        let (base, direction) =
            free_point_line(&self.first, second).map_err(lib(Role::First, FREE_FORM))?;
        if base.as_slice() != self.second.column(0).as_slice() {
            cx.warn(
                Role::Joint,
                "the curves do not meet (the last point of the first curve is not the first of the second), so no free point makes the joint even C0",
            );
        }
        let k = self.k.clone().unwrap_or_else(T::one);
        let point = DVector::from_fn(d, |r, _| base[r].clone() + k.clone() * direction[r].clone());
        report.push("free_base", Value::column(&base));
        report.push("free_direction", Value::column(&direction));
        report.push(
            "free_point",
            Value::Text(line_text(&base, &direction, cx.digits)),
        );
        report.push("k_used", Value::scalar(k));
        report.push("point", Value::column(&point));
        let mut columns: Vec<DVector<T>> =
            self.first.column_iter().map(|c| c.into_owned()).collect();
        columns.insert(n - 1, point);
        BezierCurve::new(DMatrix::from_columns(&columns)).map_err(lib(Role::First, FORM))
    }
}

/// `x_(n-1)(k) = (3, 4, 3) + k·(1, -2, 3): x = 3 + k, y = 4 - 2k, z = 3 + 3k; …`.
fn line_text<T: Scalar>(base: &DVector<T>, direction: &DVector<T>, digits: usize) -> String {
    let d = base.len();
    let names = ["x", "y", "z"];
    let line: Vec<String> = (0..d)
        .map(|r| {
            let name = if d <= 3 {
                names[r].to_string()
            } else {
                format!("x{}", r + 1)
            };
            let (c, s) = (&base[r], &direction[r]);
            let start = number_text_digits(c, digits);
            if s.is_zero() {
                return format!("{name} = {start}");
            }
            let sign = if *s < T::zero() { "-" } else { "+" };
            let size = s.abs();
            let coefficient = if size == T::one() {
                String::new()
            } else {
                number_text_digits(&size, digits)
            };
            format!("{name} = {start} {sign} {coefficient}k")
        })
        .collect();
    format!(
        "x_(n-1)(k) = {} + k·{}: {}; k = 1 gives C1, every k > 0 G1",
        point_text(base, digits),
        point_text(direction, digits),
        line.join(", ")
    )
}

/// `(1, 2, 3)` as readable text prints it.
fn point_text<T: Scalar>(v: &DVector<T>, digits: usize) -> String {
    let parts: Vec<String> = v.iter().map(|x| number_text_digits(x, digits)).collect();
    format!("({})", parts.join(", "))
}

/// Each curve's control points and the control points of its first and second derivatives.
fn push_polygons<T: Scalar>(report: &mut Report<T>, curves: [(&str, &BezierCurve<T>); 2]) {
    for (name, curve) in curves {
        let mut parts = vec![("control", Value::Matrix(curve.control().clone()))];
        for (r, label) in [(1, "d1"), (2, "d2")] {
            if let Ok(d) = curve.derivative(r) {
                parts.push((label, Value::Matrix(d.control().clone())));
            }
        }
        report.push(name, Value::record(parts));
    }
}

/// The values compared, what holds, and the verdict in words.
fn push_joint<T: Scalar>(report: &mut Report<T>, j: &BezierJoint<T>, digits: usize) {
    let flag = |b: bool| Value::scalar(if b { T::one() } else { T::zero() });
    report.push("end", Value::column(&j.end));
    report.push("start", Value::column(&j.start));
    report.push("d_end", Value::column(&j.d_end));
    report.push("d_start", Value::column(&j.d_start));
    report.push("dd_end", Value::column(&j.dd_end));
    report.push("dd_start", Value::column(&j.dd_start));
    if let Some(k) = &j.k {
        report.push("k", Value::scalar(k.clone()));
    }
    report.push(
        "continuity",
        Value::record(vec![
            ("C0", flag(j.joint.c0)),
            ("C1", flag(j.joint.c1)),
            ("G1", flag(j.joint.g1)),
            ("C2", flag(j.c2)),
        ]),
    );
    report.push("verdict", Value::Text(verdict(j, digits)));
}

/// One line per property: whether it holds and the numbers compared.
fn verdict<T: Scalar>(j: &BezierJoint<T>, digits: usize) -> String {
    let yes = |b: bool| if b { "yes" } else { "no" };
    let p = |v: &DVector<T>| point_text(v, digits);
    let g1 = match (&j.k, j.joint.g1) {
        (Some(k), true) => format!(
            "G1: yes: x'(1) = k·¹x'(0) with k = {} > 0 (the lecture notes call this C1; C1 needs k = 1)",
            number_text_digits(k, digits)
        ),
        (Some(k), false) if j.joint.c0 => format!(
            "G1: no: the tangents are parallel but k = {} is not positive",
            number_text_digits(k, digits)
        ),
        _ if !j.joint.c0 => "G1: no: the curves do not meet".to_string(),
        _ => "G1: no: the tangents are not parallel".to_string(),
    };
    [
        format!(
            "C0: {}: x(1) = {}, ¹x(0) = {}",
            yes(j.joint.c0),
            p(&j.end),
            p(&j.start)
        ),
        format!(
            "C1: {}: x'(1) = {}, ¹x'(0) = {}",
            yes(j.joint.c1),
            p(&j.d_end),
            p(&j.d_start)
        ),
        g1,
        format!(
            "C2: {}: x''(1) = {}, ¹x''(0) = {}",
            yes(j.c2),
            p(&j.dd_end),
            p(&j.dd_start)
        ),
    ]
    .join("\n")
}

/// Both curves over `[0, 1]`, their control polygons, and the joint.
fn picture<T: Scalar>(
    cx: &Context,
    first: &BezierCurve<T>,
    second: &BezierCurve<T>,
    joint: &BezierJoint<T>,
) -> Result<Drawing> {
    let unit = (&T::zero(), &T::one());
    let la = crate::picture::curve_line(first, unit, 101, Role::First, cx)?;
    let lb = crate::picture::curve_line(second, unit, 101, Role::Second, cx)?;
    let ends = DMatrix::from_columns(&[joint.end.clone(), joint.start.clone()]);
    Ok(Drawing::new("the joint of two Bézier curves")
        .curve(la, Colour::Blue, "x(u)")
        .curve(lb, Colour::Green, "¹x(v)")
        .control_polygon(to_f64(first.control()), "control polygons")
        .control_polygon(to_f64(second.control()), "")
        .points(
            to_f64(&ends),
            vec!["x(1)".into(), "¹x(0)".into()],
            "the joint",
        ))
}

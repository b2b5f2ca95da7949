//! Continuity of joined segments (the lecture notes, "napojování"): `C0`, `C1` and `G1` (the notes'
//! `GC¹`) at the joint of a segment `x(u)` ending at `u = 1` and a segment `¹x(v)` starting at
//! `v = 0`.
//!
//! - `C0`: `x(1) = ¹x(0)`;
//! - `C1`: moreover `x'(1) = ¹x'(0)`;
//! - `G1`: `C0`, and the tangents are parallel (`x'(1) × ¹x'(0) = 0`, in any dimension: every
//!   2×2 minor vanishes) with the same orientation (`¹x'(0)ᵀ x'(1) > 0`).
//!
//! The lecture notes state their smoothness condition as `x'(1) = k · ¹x'(0)` with `k > 0` and call it
//! `C1`; that is `G1` — `C1` of the parametrisation needs `k = 1`. The worked example of the
//! notes (two cubic Bézier segments) is [`c1_free_point`].

use nalgebra::DVector;

use crate::bezier::BezierCurve;
use crate::error::{check_finite, Error, Result};
use crate::param::CurveDeriv;
use crate::scalar::Scalar;

/// What holds at a joint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Joint {
    /// Positions agree.
    pub c0: bool,
    /// Positions and first derivatives agree.
    pub c1: bool,
    /// Positions agree and the first derivatives are parallel, non-zero, same orientation.
    pub g1: bool,
}

/// Classifies the joint of `end` (value and derivative of the first segment at its end) and
/// `start` (of the second at its start), with absolute tolerance `tol` on coordinates (use 0
/// in exact arithmetic) and `tol · |a| |b|` on the parallelism minors.
///
/// # Errors
/// [`Error::ShapeMismatch`] for vectors of different dimensions, [`Error::NonFinite`].
///
/// ```
/// use cagd::continuity::joint;
/// use nalgebra::DVector;
/// let v = |x: &[f64]| DVector::from_column_slice(x);
/// let j = joint((&v(&[1.0, 1.0]), &v(&[2.0, 0.0])), (&v(&[1.0, 1.0]), &v(&[1.0, 0.0])), 0.0)?;
/// assert!(j.c0 && j.g1 && !j.c1);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn joint<T: Scalar>(
    end: (&DVector<T>, &DVector<T>),
    start: (&DVector<T>, &DVector<T>),
    tol: T,
) -> Result<Joint> {
    let d = end.0.len();
    if [end.1.len(), start.0.len(), start.1.len()]
        .iter()
        .any(|&n| n != d)
    {
        return Err(Error::ShapeMismatch {
            what: "joint",
            expected: format!("four vectors of dimension {d}"),
            found: "vectors of different dimensions".into(),
        });
    }
    check_finite(
        "joint",
        end.0
            .iter()
            .chain(end.1.iter())
            .chain(start.0.iter())
            .chain(start.1.iter()),
    )?;
    let near = |a: &DVector<T>, b: &DVector<T>| {
        a.iter()
            .zip(b.iter())
            .all(|(x, y)| (x.clone() - y.clone()).abs() <= tol)
    };
    let c0 = near(end.0, start.0);
    let c1 = c0 && near(end.1, start.1);
    let (a, b) = (end.1, start.1);
    let dot = a
        .iter()
        .zip(b.iter())
        .fold(T::zero(), |s, (x, y)| s + x.clone() * y.clone());
    let norm1 = |v: &DVector<T>| v.iter().fold(T::zero(), |s, x| s + x.abs());
    let scale = tol.clone() * norm1(a) * norm1(b);
    let mut parallel = true;
    for i in 0..d {
        for j in i + 1..d {
            let minor = a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone();
            if minor.abs() > scale {
                parallel = false;
            }
        }
    }
    let g1 = c0 && parallel && dot > T::zero();
    Ok(Joint { c0, c1, g1 })
}

/// The joint of two curves: `first` at `t1`, `second` at `t0` (usually 1 and 0), from their
/// values and derivatives ([`CurveDeriv::eval_derivative`]).
///
/// # Errors
/// The errors of [`joint`].
pub fn curve_joint<T: Scalar>(
    first: &impl CurveDeriv<T>,
    t1: T,
    second: &impl CurveDeriv<T>,
    t0: T,
    tol: T,
) -> Result<Joint> {
    let d1 = first.eval_derivative(t1.clone());
    let d0 = second.eval_derivative(t0.clone());
    joint((&first.eval(t1), &d1), (&second.eval(t0), &d0), tol)
}

/// The lecture notes' example: two cubic Bézier segments `x_A x_B x_C x_D` and `x_D x_E x_F x_G`
/// share `x_D`; the free point `x_C` makes the joint smooth when
/// `x'(1) = 3(x_D − x_C) = k · 3(x_E − x_D) = k · ¹x'(0)`, i.e.
/// `x_C(k) = x_D + k (x_D − x_E)`. Returns `(x_D, x_D − x_E)`: the point and direction of that
/// line. `k = 1` gives `C1`, any `k > 0` gives `G1`. For the notes' data (`x_D = (3, 4, 3)`,
/// `x_E = (2, 6, 0)`) this is `x = 3 + k, y = 4 − 2k, z = 3 + 3k`, as printed.
///
/// # Errors
/// [`Error::ShapeMismatch`] for points of different dimensions.
pub fn c1_free_point<T: Scalar>(
    x_d: &DVector<T>,
    x_e: &DVector<T>,
) -> Result<(DVector<T>, DVector<T>)> {
    if x_d.len() != x_e.len() {
        return Err(Error::ShapeMismatch {
            what: "C1 free point",
            expected: format!("{} coordinates", x_d.len()),
            found: format!("{}", x_e.len()),
        });
    }
    let dir = DVector::from_fn(x_d.len(), |r, _| x_d[r].clone() - x_e[r].clone());
    Ok((x_d.clone(), dir))
}

/// What is compared where two Bézier curves join ([`bezier_joint`]): the first curve `x`
/// (degree `n`) at `u = 1`, the second `¹x` (degree `m`) at `v = 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierJoint<T> {
    /// `x(1) = x_n`.
    pub end: DVector<T>,
    /// `¹x(0) = y_0`.
    pub start: DVector<T>,
    /// `x'(1) = n (x_n − x_{n−1})` (zero for a point).
    pub d_end: DVector<T>,
    /// `¹x'(0) = m (y_1 − y_0)`.
    pub d_start: DVector<T>,
    /// `x''(1) = n(n−1)(x_n − 2x_{n−1} + x_{n−2})` (zero below degree 2).
    pub dd_end: DVector<T>,
    /// `¹x''(0) = m(m−1)(y_2 − 2y_1 + y_0)`.
    pub dd_start: DVector<T>,
    /// `k` with `x'(1) = k · ¹x'(0)`, if the tangents are parallel and `¹x'(0) ≠ 0`.
    pub k: Option<T>,
    /// `C0`, `C1`, `G1` ([`joint`]).
    pub joint: Joint,
    /// `C1` and `x''(1) = ¹x''(0)`.
    pub c2: bool,
}

/// The joint of two Bézier curves: `first` ending at `u = 1`, `second` starting at `v = 0`,
/// with their first and second derivatives there and what holds (`C0`, `C1`, `G1`, `C2`).
/// Coordinates are compared exactly in rationals and, in `f64`, within `10⁻¹²` times the
/// largest control coordinate (at least 1).
///
/// # Errors
/// [`Error::ShapeMismatch`] for curves of different dimensions.
///
/// ```
/// use cagd::bezier::BezierCurve;
/// use cagd::continuity::bezier_joint;
/// let a = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 1.0]])?;
/// let b = BezierCurve::from_points(&[[2.0, 1.0], [4.0, 1.0], [5.0, 0.0]])?;
/// let j = bezier_joint(&a, &b)?;
/// assert!(j.joint.g1 && !j.joint.c1);
/// assert_eq!(j.k, Some(0.5)); // x'(1) = (2, 0), ¹x'(0) = (4, 0)
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bezier_joint<T: Scalar>(
    first: &BezierCurve<T>,
    second: &BezierCurve<T>,
) -> Result<BezierJoint<T>> {
    if first.dim() != second.dim() {
        return Err(Error::ShapeMismatch {
            what: "joint of two Bézier curves",
            expected: format!("points of dimension {}", first.dim()),
            found: format!("points of dimension {}", second.dim()),
        });
    }
    let (one, zero) = (T::one(), T::zero());
    let (end, start) = (first.eval(one.clone()), second.eval(zero.clone()));
    let (d_end, d_start) = (
        derivative_at(first, 1, one.clone()),
        derivative_at(second, 1, zero.clone()),
    );
    let (dd_end, dd_start) = (derivative_at(first, 2, one), derivative_at(second, 2, zero));
    let tol = if T::EXACT {
        T::zero()
    } else {
        let scale = first
            .control()
            .iter()
            .chain(second.control().iter())
            .fold(T::one(), |m, x| if x.abs() > m { x.abs() } else { m });
        scale * T::from_f64(1e-12).unwrap_or_else(T::zero)
    };
    let joint = joint((&end, &d_end), (&start, &d_start), tol.clone())?;
    let same = |x: &DVector<T>, y: &DVector<T>| {
        x.iter()
            .zip(y.iter())
            .all(|(s, t)| (s.clone() - t.clone()).abs() <= tol)
    };
    let c2 = joint.c1 && same(&dd_end, &dd_start);
    let k = parallel_factor(&d_end, &d_start, &tol);
    Ok(BezierJoint {
        end,
        start,
        d_end,
        d_start,
        dd_end,
        dd_start,
        k,
        joint,
        c2,
    })
}

/// The `r`-th derivative of `c` at `t`, zero where the degree is below `r`.
fn derivative_at<T: Scalar>(c: &BezierCurve<T>, r: usize, t: T) -> DVector<T> {
    match c.derivative(r) {
        Ok(d) => d.eval(t),
        Err(_) => DVector::from_element(c.dim(), T::zero()),
    }
}

/// `k` with `a = k b`, if `a` and `b` are parallel (within `tol`) and `b ≠ 0`: the least-squares
/// `k = aᵀb / bᵀb`, kept if every coordinate of `a − k b` is within `tol`.
fn parallel_factor<T: Scalar>(a: &DVector<T>, b: &DVector<T>, tol: &T) -> Option<T> {
    let bb = b.iter().fold(T::zero(), |s, x| s + x.clone() * x.clone());
    if bb.is_zero() {
        return None;
    }
    let k = a
        .iter()
        .zip(b.iter())
        .fold(T::zero(), |s, (x, y)| s + x.clone() * y.clone())
        / bb;
    a.iter()
        .zip(b.iter())
        .all(|(x, y)| (x.clone() - k.clone() * y.clone()).abs() <= *tol)
        .then_some(k)
}

/// The free point of the lecture notes' example for curves of any degree: the first curve's
/// control points are known but for the second-to-last (`known`: `x_0 … x_{n−2}, x_n`, `n ≥ 2`
/// columns), the second curve `¹x` (degree `m ≥ 1`) starts at `y_0 = x_n`. Then
/// `x'(1) = n (x_n − x_{n−1}) = k · m (y_1 − y_0) = k · ¹x'(0)` gives the line
///
/// ```text
/// x_{n−1}(k) = x_n + k · (m/n)(y_0 − y_1),
/// ```
///
/// returned as `(x_n, (m/n)(y_0 − y_1))`; `k = 1` gives `C1`, any `k > 0` `G1`. For two cubics
/// this is [`c1_free_point`].
///
/// # Errors
/// [`Error::TooFewPoints`] for fewer than 2 known points or a second curve of degree 0;
/// [`Error::ShapeMismatch`] for points of different dimensions.
///
/// ```
/// use cagd::bezier::BezierCurve;
/// use cagd::continuity::free_point_line;
/// use nalgebra::DMatrix;
/// // The lecture notes: x_A, x_B, x_D = (3, 4, 3) known; ¹x from x_D, x_E = (2, 6, 0).
/// let known = DMatrix::from_column_slice(3, 3, &[2.0, 3.0, 3.0, 3.0, 1.0, 4.0, 3.0, 4.0, 3.0]);
/// let second = BezierCurve::from_points(&[[3.0, 4.0, 3.0], [2.0, 6.0, 0.0], [5.0, 7.0, 5.0], [5.0, 2.0, 3.0]])?;
/// let (base, direction) = free_point_line(&known, &second)?;
/// assert_eq!(base.as_slice(), &[3.0, 4.0, 3.0]);
/// assert_eq!(direction.as_slice(), &[1.0, -2.0, 3.0]); // x = 3 + k, y = 4 − 2k, z = 3 + 3k
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn free_point_line<T: Scalar>(
    known: &nalgebra::DMatrix<T>,
    second: &BezierCurve<T>,
) -> Result<(DVector<T>, DVector<T>)> {
    let n = known.ncols();
    if n < 2 || second.degree() < 1 {
        return Err(Error::TooFewPoints {
            what: "free point of a joint",
            min: 2,
            found: n.min(second.degree() + 1),
        });
    }
    if known.nrows() != second.dim() {
        return Err(Error::ShapeMismatch {
            what: "free point of a joint",
            expected: format!("points of dimension {}", known.nrows()),
            found: format!("points of dimension {}", second.dim()),
        });
    }
    let base = known.column(n - 1).into_owned();
    let (y0, y1) = (second.control().column(0), second.control().column(1));
    let ratio = T::from_ratio(second.degree() as i64, n as i64);
    let direction = DVector::from_fn(base.len(), |r, _| {
        ratio.clone() * (y0[r].clone() - y1[r].clone())
    });
    Ok((base, direction))
}

/// The cost of [`bezier_joint`] (and [`free_point_line`]): the first and second derivatives
/// of both curves of at most `points` control points each (three rounds of differences and
/// the points at the ends, about `8 (n+1)² d` operations), on numbers of the control points'
/// `control_bits` and the falling factorials' `2(n+1)` bits.
///
/// ```
/// use cagd::cost::Cost;
/// assert_eq!(cagd::continuity::bezier_joint_cost(4, 3, 0), Cost::new(8 * 25 * 3, 10));
/// ```
pub fn bezier_joint_cost(points: usize, d: usize, control_bits: u128) -> crate::cost::Cost {
    let n = points as u128 + 1;
    crate::cost::Cost::new(
        (8 * n).saturating_mul(n).saturating_mul(d as u128),
        control_bits.saturating_add(2 * n),
    )
}

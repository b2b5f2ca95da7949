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

use crate::error::{check_finite, Error, Result};
use crate::param::Curve;
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
/// [`Error::ShapeMismatch`] for vectors of different dimensions, [`Error::NonFinite`] for a
/// NaN or infinite coordinate or tolerance, [`Error::InvalidArgument`] for a negative
/// tolerance, [`Error::Overflow`] when the products the classification compares overflow
/// (derivatives near ±10¹⁵⁴).
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
    crate::error::check_finite("joint tolerance", std::iter::once(&tol))?;
    if tol < T::zero() {
        return Err(Error::InvalidArgument {
            what: "joint tolerance",
            message: format!("expected a value >= 0, got {tol}"),
        });
    }
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
    let mut minors = Vec::new();
    for i in 0..d {
        for j in i + 1..d {
            let minor = a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone();
            if minor.abs() > scale {
                parallel = false;
            }
            minors.push(minor);
        }
    }
    // The classification compares these: one that overflowed would decide it wrongly.
    crate::error::check_overflow(
        "joint derivatives (products of their coordinates)",
        [&dot, &scale].into_iter().chain(&minors),
    )?;
    let g1 = c0 && parallel && dot > T::zero();
    Ok(Joint { c0, c1, g1 })
}

/// The joint of two curves: `first` at `t1`, `second` at `t0` (usually 1 and 0), from their
/// values and derivatives ([`Curve::eval_derivative`]).
///
/// # Errors
/// [`Error::InvalidArgument`] if a curve has no derivative, [`Error::NonFinite`] for a NaN or
/// infinite parameter, [`Error::Overflow`] for a point or derivative whose double
/// overflows, and the errors of [`joint`].
pub fn curve_joint<T: Scalar>(
    first: &impl Curve<T>,
    t1: T,
    second: &impl Curve<T>,
    t0: T,
    tol: T,
) -> Result<Joint> {
    let missing = || Error::InvalidArgument {
        what: "curve joint",
        message: "both curves must provide derivatives".into(),
    };
    crate::error::check_finite("curve joint parameters", [&t1, &t0])?;
    let d1 = first.eval_derivative(t1.clone()).ok_or_else(missing)?;
    let d0 = second.eval_derivative(t0.clone()).ok_or_else(missing)?;
    let (p1, p0) = (first.eval(t1), second.eval(t0));
    crate::error::check_overflow(
        "curve joint points and derivatives",
        p1.iter().chain(&d1).chain(&p0).chain(&d0),
    )?;
    joint((&p1, &d1), (&p0, &d0), tol)
}

/// The lecture notes' example: two cubic Bézier segments `x_A x_B x_C x_D` and `x_D x_E x_F x_G`
/// share `x_D`; the free point `x_C` makes the joint smooth when
/// `x'(1) = 3(x_D − x_C) = k · 3(x_E − x_D) = k · ¹x'(0)`, i.e.
/// `x_C(k) = x_D + k (x_D − x_E)`. Returns `(x_D, x_D − x_E)`: the point and direction of that
/// line. `k = 1` gives `C1`, any `k > 0` gives `G1`. For the notes' data (`x_D = (3, 4, 3)`,
/// `x_E = (2, 6, 0)`) this is `x = 3 + k, y = 4 − 2k, z = 3 + 3k`, as printed.
///
/// # Errors
/// [`Error::ShapeMismatch`] for points of different dimensions, [`Error::NonFinite`] for a
/// NaN or infinite coordinate, [`Error::Overflow`] for a direction whose double overflows.
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
    check_finite("C1 free point", x_d.iter().chain(x_e.iter()))?;
    let dir = DVector::from_fn(x_d.len(), |r, _| x_d[r].clone() - x_e[r].clone());
    crate::error::check_overflow("C1 free direction", dir.iter())?;
    Ok((x_d.clone(), dir))
}

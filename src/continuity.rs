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

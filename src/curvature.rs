//! Curvature and the Frenet frame of a curve at a point (differential geometry of curves, as
//! the thesis's §2.4 uses the derivatives of a Bézier curve):
//!
//! ```text
//! κ = |x′ × x″| / |x′|³,   T = x′ / |x′|,   B = (x′ × x″) / |x′ × x″|,   N = B × T
//! ```
//!
//! in three dimensions; in the plane the signed curvature `κ = (x′₁x″₂ − x′₂x″₁)/|x′|³` with
//! `N` the tangent turned by +90°. In any dimension the square of the curvature is rational in
//! the derivatives (Lagrange's identity `|x′ × x″|² = |x′|²|x″|² − (x′·x″)²`), so
//! [`curvature_squared`] is exact in rational arithmetic; `κ` and the frame need a square root.
//!
//! The second derivative is a capability of the curve ([`CurveDeriv2`]): Bézier and B-spline
//! curves differentiate their control points twice; a NURBS curve uses the quotient rule on its
//! homogeneous form, `C″ = (A″ − 2w′C′ − w″C)/w`.

use nalgebra::DVector;

use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::cost::Cost;
use crate::error::{Error, Result};
use crate::nurbs::NurbsCurve;
use crate::param::CurveDeriv;
use crate::scalar::Scalar;

/// A curve that knows its second derivative.
pub trait CurveDeriv2<T: Scalar = f64>: CurveDeriv<T> {
    /// `c″(t)` (of the continued curve outside the domain).
    fn eval_second_derivative(&self, t: T) -> DVector<T>;
}

impl<T: Scalar> CurveDeriv2<T> for BezierCurve<T> {
    /// The control points differenced twice (zero below degree 2).
    fn eval_second_derivative(&self, t: T) -> DVector<T> {
        match self.derivative(2) {
            Ok(d) => d.eval(t),
            Err(_) => DVector::from_element(self.dim(), T::zero()),
        }
    }
}

impl<T: Scalar> CurveDeriv2<T> for BSplineCurve<T> {
    /// The derivative curve's derivative (zero below degree 2).
    fn eval_second_derivative(&self, t: T) -> DVector<T> {
        match self.derivative().and_then(|d| d.derivative()) {
            Ok(d) => d.eval(t),
            Err(_) => DVector::from_element(self.dim(), T::zero()),
        }
    }
}

impl<T: Scalar> CurveDeriv2<T> for NurbsCurve<T> {
    /// `C″ = (A″ − 2w′C′ − w″C)/w` from the homogeneous curve `A = (wC, w)`.
    fn eval_second_derivative(&self, t: T) -> DVector<T> {
        let h = self.homogeneous();
        let d = self.dim();
        let a = h.eval(t.clone());
        let a1 = CurveDeriv::eval_derivative(h, t.clone());
        let a2 = h.eval_second_derivative(t);
        let (w, w1, w2) = (a[d].clone(), a1[d].clone(), a2[d].clone());
        let c = DVector::from_fn(d, |r, _| a[r].clone() / w.clone());
        let c1 = DVector::from_fn(d, |r, _| {
            (a1[r].clone() - w1.clone() * c[r].clone()) / w.clone()
        });
        DVector::from_fn(d, |r, _| {
            let two = T::from_usize(2);
            (a2[r].clone() - two * w1.clone() * c1[r].clone() - w2.clone() * c[r].clone())
                / w.clone()
        })
    }
}

/// `κ² = (|x′|²|x″|² − (x′·x″)²) / |x′|⁶`, exact in rational arithmetic.
///
/// # Errors
/// [`Error::ShapeMismatch`] for derivatives of different lengths; [`Error::InvalidArgument`]
/// where `x′ = 0` (a singular point: the curvature is not defined).
///
/// ```
/// use num_rational::BigRational;
/// use nalgebra::dvector;
/// let q = |n: i64| BigRational::from_integer(n.into());
/// // The parabola (t, t²) at t = 1: x′ = (1, 2), x″ = (0, 2); κ² = 4/125.
/// let k2 = cagd::curvature::curvature_squared(&dvector![q(1), q(2)], &dvector![q(0), q(2)])?;
/// assert_eq!(k2, BigRational::new(4.into(), 125.into()));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn curvature_squared<T: Scalar>(d1: &DVector<T>, d2: &DVector<T>) -> Result<T> {
    check_lengths(d1, d2)?;
    let dot = |a: &DVector<T>, b: &DVector<T>| {
        a.iter()
            .zip(b.iter())
            .fold(T::zero(), |s, (x, y)| s + x.clone() * y.clone())
    };
    let s11 = dot(d1, d1);
    if s11.is_zero() {
        return Err(singular());
    }
    let s22 = dot(d2, d2);
    let s12 = dot(d1, d2);
    let cross2 = s11.clone() * s22 - s12.clone() * s12;
    Ok(cross2 / (s11.clone() * s11.clone() * s11))
}

/// The curvature and the Frenet frame at a point of a plane or space curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Frenet {
    /// `κ`: signed in the plane (positive turning left), `≥ 0` in space.
    pub curvature: f64,
    /// The unit tangent `T`.
    pub tangent: DVector<f64>,
    /// The unit principal normal `N`; `None` in space where `κ = 0` (it is not defined there).
    pub normal: Option<DVector<f64>>,
    /// The unit binormal `B = T × N` (space curves only, where `κ ≠ 0`).
    pub binormal: Option<DVector<f64>>,
}

/// The Frenet frame from the first two derivatives `x′`, `x″` of a plane or space curve.
///
/// # Errors
/// [`Error::ShapeMismatch`] for derivatives other than both 2-D or both 3-D;
/// [`Error::InvalidArgument`] where `x′ = 0`; [`Error::NonFinite`] for non-finite
/// derivatives or a curvature that overflows.
///
/// ```
/// use nalgebra::dvector;
/// // The unit circle (cos t, sin t) at t = 0: κ = 1, T = (0, 1), N = (−1, 0).
/// let f = cagd::curvature::frenet(&dvector![0.0, 1.0], &dvector![-1.0, 0.0])?;
/// assert_eq!((f.curvature, f.tangent.as_slice(), f.normal.unwrap().as_slice()), (1.0, &[0.0, 1.0][..], &[-1.0, 0.0][..]));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn frenet(d1: &DVector<f64>, d2: &DVector<f64>) -> Result<Frenet> {
    check_lengths(d1, d2)?;
    if let Some(index) = d1.iter().chain(d2.iter()).position(|x| !x.is_finite()) {
        return Err(Error::NonFinite {
            what: "curve derivatives",
            index,
            value: f64::NAN,
        });
    }
    let speed = d1.norm();
    if speed == 0.0 {
        return Err(singular());
    }
    let tangent = d1 / speed;
    let frame = match d1.len() {
        2 => {
            let cross = d1[0] * d2[1] - d1[1] * d2[0];
            let normal = DVector::from_vec(vec![-tangent[1], tangent[0]]);
            Frenet {
                curvature: cross / speed.powi(3),
                tangent,
                normal: Some(normal),
                binormal: None,
            }
        }
        3 => {
            let (a, b) = (
                nalgebra::Vector3::new(d1[0], d1[1], d1[2]),
                nalgebra::Vector3::new(d2[0], d2[1], d2[2]),
            );
            let cross = a.cross(&b);
            let length = cross.norm();
            let t3 = nalgebra::Vector3::new(tangent[0], tangent[1], tangent[2]);
            let (normal, binormal) = if length == 0.0 {
                (None, None)
            } else {
                let bn = cross / length;
                let n = bn.cross(&t3);
                (
                    Some(DVector::from_column_slice(n.as_slice())),
                    Some(DVector::from_column_slice(bn.as_slice())),
                )
            };
            Frenet {
                curvature: length / speed.powi(3),
                tangent,
                normal,
                binormal,
            }
        }
        d => {
            return Err(Error::ShapeMismatch {
                what: "Frenet frame",
                expected: "a plane or space curve (2 or 3 coordinates)".into(),
                found: format!("{d} coordinates"),
            })
        }
    };
    if !frame.curvature.is_finite() {
        return Err(Error::NonFinite {
            what: "curvature",
            index: 0,
            value: frame.curvature,
        });
    }
    Ok(frame)
}

/// The work of the curvature (and frame) at one point from `d`-dimensional derivatives of
/// `bits` bits: the three dot products and the quotient of [`curvature_squared`], about `6d + 6`
/// operations, on numbers of six times the derivatives' size (`|x′|⁶`).
///
/// ```
/// assert_eq!(cagd::curvature::curvature_cost(3, 10), cagd::cost::Cost::new(24, 60));
/// ```
pub fn curvature_cost(d: usize, bits: u128) -> Cost {
    Cost::new(6 * d as u128 + 6, bits.saturating_mul(6))
}

fn check_lengths<T: Scalar>(d1: &DVector<T>, d2: &DVector<T>) -> Result<()> {
    if d1.len() == d2.len() && !d1.is_empty() {
        return Ok(());
    }
    Err(Error::ShapeMismatch {
        what: "curve derivatives",
        expected: format!("two vectors of {} coordinates", d1.len().max(1)),
        found: format!("{} and {}", d1.len(), d2.len()),
    })
}

fn singular() -> Error {
    Error::InvalidArgument {
        what: "curvature",
        message: "the tangent x′(t) is zero (a singular point): the curvature is not defined there"
            .into(),
    }
}

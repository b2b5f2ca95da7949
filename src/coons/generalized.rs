//! The generalized Coons patch with user blending functions (thesis §4.1, after (4.4)), and the
//! partially bicubic blend of §4.2.

use std::fmt;
use std::sync::Arc;

use nalgebra::DVector;

use super::{CoonsBoundary, CoonsPoint, Tolerance};
use crate::error::{Error, Result};
use crate::hermite::hermite_basis;
use crate::param::{Curve, Surface};
use crate::scalar::Scalar;

type BlendFn<T> = Arc<dyn Fn(T) -> T + Send + Sync>;

/// A pair of blending functions `(f1, f2)` of one parameter, as in the generalized Coons patch.
///
/// To interpolate, a pair must satisfy (thesis, remark after (4.4)) `f1 + f2 = 1`,
/// `f1(0) = 1` and `f1(1) = 0` (so also `f2(0) = 0`, `f2(1) = 1`);
/// [`GeneralizedCoonsPatch`] checks these.
#[derive(Clone)]
pub struct BlendingPair<T: Scalar = f64> {
    name: &'static str,
    first: BlendFn<T>,
    second: BlendFn<T>,
}

impl<T: Scalar> fmt::Debug for BlendingPair<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("BlendingPair")
            .field("name", &self.name)
            .finish_non_exhaustive()
    }
}

impl<T: Scalar> BlendingPair<T> {
    /// The pair `(f1, f2)` (not yet checked; the patch checks it).
    ///
    /// ```
    /// use cagd::coons::BlendingPair;
    /// let smooth = BlendingPair::new("smoothstep", |t: f64| 1.0 - t * t * (3.0 - 2.0 * t), |t: f64| t * t * (3.0 - 2.0 * t));
    /// assert_eq!(smooth.eval(0.5), (0.5, 0.5));
    /// ```
    pub fn new(
        name: &'static str,
        first: impl Fn(T) -> T + Send + Sync + 'static,
        second: impl Fn(T) -> T + Send + Sync + 'static,
    ) -> Self {
        BlendingPair {
            name,
            first: Arc::new(first),
            second: Arc::new(second),
        }
    }

    /// The linear pair `(1 − t, t)` of the bilinearly blended patch.
    pub fn linear() -> Self {
        Self::new("linear", |t: T| T::one() - t, |t: T| t)
    }

    /// The cubic Hermite pair `(H0³, H3³) = (B0³ + B1³, B2³ + B3³)` of the partially bicubic
    /// patch (§4.2), the value functions `f_1`, `f_2` of
    /// [`hermite_basis`](crate::hermite::hermite_basis). Both have zero derivative at 0 and 1, so the cross-boundary derivative
    /// along an edge depends only on the derivatives at its two ends.
    ///
    /// ```
    /// use cagd::coons::BlendingPair;
    /// let h = BlendingPair::<f64>::hermite_cubic();
    /// assert_eq!(h.eval(0.5), (0.5, 0.5));
    /// assert_eq!(h.eval(0.25), (27.0 / 32.0, 5.0 / 32.0));
    /// ```
    pub fn hermite_cubic() -> Self {
        Self::new(
            "Hermite cubic (H0, H3)",
            |t: T| {
                let [h0, ..] = hermite_basis(t);
                h0
            },
            |t: T| {
                let [_, h3, ..] = hermite_basis(t);
                h3
            },
        )
    }

    /// `(f1(t), f2(t))`.
    pub fn eval(&self, t: T) -> (T, T) {
        ((self.first)(t.clone()), (self.second)(t))
    }

    /// The name given at construction.
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// Checks `f1(0) = 1`, `f1(1) = 0` and `f1 + f2 = 1` at `t = k/32`, `k = 0..=32`, within the
    /// absolute `tolerance`; `which` is `'f'` (for `f1, f2`) or `'g'` (for `g1, g2`) and names
    /// the functions in the error.
    fn check(&self, which: char, tolerance: f64) -> Result<()> {
        let tol = T::from_f64(tolerance).unwrap_or_else(T::zero);
        let (first, sum) = if which == 'f' {
            ("f1", "f1 + f2")
        } else {
            ("g1", "g1 + g2")
        };
        let fail = |function, condition, t: &T, value: &T, expected: &T| Error::BlendingCondition {
            function,
            condition,
            t: t.to_f64(),
            value: value.to_f64(),
            expected: expected.to_f64(),
            tolerance,
        };
        for (t, expected, condition) in [
            (T::zero(), T::one(), "first function is 1 at 0"),
            (T::one(), T::zero(), "first function is 0 at 1"),
        ] {
            let value = (self.first)(t.clone());
            if !value.is_finite_value() || (value.clone() - expected.clone()).abs() > tol {
                return Err(fail(first, condition, &t, &value, &expected));
            }
        }
        for k in 0..=32 {
            let t = T::from_ratio(k, 32);
            let (a, b) = self.eval(t.clone());
            let value = a + b;
            if !value.is_finite_value() || (value.clone() - T::one()).abs() > tol {
                return Err(fail(sum, "partition of unity", &t, &value, &T::one()));
            }
        }
        Ok(())
    }
}

/// Default absolute tolerance for the blending function conditions.
pub const BLEND_TOLERANCE: f64 = 1e-12;

/// The generalized Coons patch (thesis, after (4.4)):
///
/// ```text
/// x(u,v) = [f1(u) f2(u)] [d1(v); d2(v)] + [c1(u) c2(u)] [g1(v); g2(v)]
///        − [f1(u) f2(u)] [x(0,0) x(0,1); x(1,0) x(1,1)] [g1(v); g2(v)]
/// ```
///
/// i.e. `r_c = g1 c1 + g2 c2`, `r_d = f1 d1 + f2 d2`, `r_cd = f1 g1 P1 + f2 g1 P2 + f1 g2 P3 +
/// f2 g2 P4`, `x = r_c + r_d − r_cd`. With the linear pair it is the bilinear
/// [`CoonsPatch`](super::CoonsPatch) (to the last bit), with [`BlendingPair::hermite_cubic`] the
/// partially bicubic patch of §4.2.
///
/// ```
/// use cagd::coons::{BlendingPair, GeneralizedCoonsPatch};
/// use cagd::{SampledCurve, Surface};
/// use nalgebra::{dmatrix, dvector};
/// let line = |a: [f64; 2], b: [f64; 2]| {
///     SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]]).unwrap()
/// };
/// let patch = GeneralizedCoonsPatch::partially_bicubic(
///     line([0.0, 0.0], [1.0, 0.0]), line([0.0, 1.0], [1.0, 1.0]),
///     line([0.0, 0.0], [0.0, 1.0]), line([1.0, 0.0], [1.0, 1.0]),
/// ).unwrap();
/// // The flat unit square comes out as the identity map: x(u,v) = (u, v).
/// assert_eq!(patch.eval(0.25, 0.5), dvector![0.25, 0.5]);
/// ```
#[derive(Debug, Clone)]
pub struct GeneralizedCoonsPatch<C, T: Scalar = f64> {
    boundary: CoonsBoundary<C, T>,
    f: BlendingPair<T>,
    g: BlendingPair<T>,
}

impl<T: Scalar, C: Curve<T>> GeneralizedCoonsPatch<C, T> {
    /// The generalized patch of `c1 = x(·,0)`, `c2 = x(·,1)`, `d1 = x(0,·)`, `d2 = x(1,·)` with
    /// blending pairs `f = (f1, f2)` in `u` and `g = (g1, g2)` in `v`; default tolerances.
    ///
    /// # Errors
    /// Those of [`CoonsBoundary::new`], and [`Error::BlendingCondition`] naming the function,
    /// the condition and the parameter where a pair breaks `f1 + f2 = 1`, `f1(0) = 1` or
    /// `f1(1) = 0` (checked at `t = k/32`, absolute tolerance [`BLEND_TOLERANCE`]).
    ///
    /// ```
    /// use cagd::coons::{BlendingPair, GeneralizedCoonsPatch};
    /// use cagd::{Error, SampledCurve};
    /// use nalgebra::dmatrix;
    /// let line = |a: [f64; 2], b: [f64; 2]| {
    ///     SampledCurve::new(vec![0.0, 1.0], dmatrix![a[0], b[0]; a[1], b[1]]).unwrap()
    /// };
    /// let bad = BlendingPair::new("no partition", |t: f64| 1.0 - t, |t: f64| t * t);
    /// let err = GeneralizedCoonsPatch::new(
    ///     line([0.0, 0.0], [1.0, 0.0]), line([0.0, 1.0], [1.0, 1.0]),
    ///     line([0.0, 0.0], [0.0, 1.0]), line([1.0, 0.0], [1.0, 1.0]),
    ///     BlendingPair::linear(), bad,
    /// ).unwrap_err();
    /// assert!(matches!(err, Error::BlendingCondition { function: "g1 + g2", t, .. } if t == 1.0 / 32.0));
    /// ```
    pub fn new(c1: C, c2: C, d1: C, d2: C, f: BlendingPair<T>, g: BlendingPair<T>) -> Result<Self> {
        let boundary = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default())?;
        Self::from_boundary(boundary, f, g, BLEND_TOLERANCE)
    }

    /// The patch of a checked boundary with blending pairs `f`, `g`, checked within the absolute
    /// `blend_tolerance`.
    ///
    /// # Errors
    /// [`Error::BlendingCondition`] as in [`GeneralizedCoonsPatch::new`];
    /// [`Error::InvalidArgument`] for a negative or non-finite tolerance.
    pub fn from_boundary(
        boundary: CoonsBoundary<C, T>,
        f: BlendingPair<T>,
        g: BlendingPair<T>,
        blend_tolerance: f64,
    ) -> Result<Self> {
        if !(blend_tolerance.is_finite() && blend_tolerance >= 0.0) {
            return Err(Error::InvalidArgument {
                what: "blending tolerance",
                message: format!("expected a finite value >= 0, got {blend_tolerance}"),
            });
        }
        f.check('f', blend_tolerance)?;
        g.check('g', blend_tolerance)?;
        Ok(GeneralizedCoonsPatch { boundary, f, g })
    }

    /// The partially bicubic patch (§4.2): `f1 = g1 = H0³ = B0³ + B1³`,
    /// `f2 = g2 = H3³ = B2³ + B3³`.
    ///
    /// # Errors
    /// As [`CoonsBoundary::new`].
    pub fn partially_bicubic(c1: C, c2: C, d1: C, d2: C) -> Result<Self> {
        Self::new(
            c1,
            c2,
            d1,
            d2,
            BlendingPair::hermite_cubic(),
            BlendingPair::hermite_cubic(),
        )
    }

    /// The point `x(u, v)` with its parts `r_c`, `r_d`, `r_cd`.
    pub fn eval_parts(&self, u: T, v: T) -> CoonsPoint<T> {
        let f = self.f.eval(u.clone());
        let g = self.g.eval(v.clone());
        self.boundary.blend(&u, &v, &f, &g)
    }
}

impl<T: Scalar, C> GeneralizedCoonsPatch<C, T> {
    /// The checked boundary curves and corners.
    pub fn boundary(&self) -> &CoonsBoundary<C, T> {
        &self.boundary
    }

    /// The blending pairs `(f, g)`.
    pub fn blending(&self) -> (&BlendingPair<T>, &BlendingPair<T>) {
        (&self.f, &self.g)
    }
}

impl<T: Scalar, C: Curve<T>> Surface<T> for GeneralizedCoonsPatch<C, T> {
    fn dim(&self) -> usize {
        self.boundary.dim()
    }

    /// `[0, 1]²` (the boundary curves reparametrised onto `[0, 1]`).
    fn domain(&self) -> ((T, T), (T, T)) {
        ((T::zero(), T::one()), (T::zero(), T::one()))
    }

    fn eval(&self, u: T, v: T) -> DVector<T> {
        self.eval_parts(u, v).x
    }

    /// [`eval`](Surface::eval) on `[0, 1]²`, each boundary curve through its own `try_eval`
    /// and the point checked (as the bilinear Coons patch's `try_eval`).
    fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        crate::param::check_parameter("Coons patch parameter u", &u, &(T::zero(), T::one()))?;
        crate::param::check_parameter("Coons patch parameter v", &v, &(T::zero(), T::one()))?;
        let f = self.f.eval(u.clone());
        let g = self.g.eval(v.clone());
        self.boundary.try_blend(&u, &v, &f, &g)
    }

    fn eval_grid_into(&self, us: &[T], vs: &[T], out: &mut [T]) -> Result<()> {
        crate::checked::eval_grid_into(self, "Coons patch grid", us, vs, out)
    }

    /// The patch on the grid `us × vs`, shape `(us.len(), vs.len(), d)`; curves and blending
    /// functions are evaluated once per grid line.
    fn eval_grid(&self, us: &[T], vs: &[T]) -> crate::grid::PointGrid<T> {
        let f: Vec<_> = us.iter().map(|u| self.f.eval(u.clone())).collect();
        let g: Vec<_> = vs.iter().map(|v| self.g.eval(v.clone())).collect();
        self.boundary.blend_grid(us, vs, &f, &g)
    }
}

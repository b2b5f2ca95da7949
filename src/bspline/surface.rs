//! Tensor-product B-spline surfaces (seed 004 "B-spline plocha", seed 001).

use nalgebra::{DMatrix, DVector};

use super::basis::{basis_functions, find_span};
use super::curve::clamp;
use super::knots::{check_knots, KnotVector};
use crate::error::{check_finite, Error, Result};
use crate::param::Surface;
use crate::scalar::Scalar;

/// A tensor-product B-spline surface
/// `S(u, v) = Σ_i Σ_j P_{i,j} N_{i,p}(u) N_{j,q}(v)` over `[u_p, u_{nu}] × [v_q, v_{nv}]`.
///
/// **Layout:** one `nu × nv` matrix per coordinate, entry `(i, j)` belonging to `P_{i,j}`,
/// `i` along `u`, `j` along `v` (as [`BezierPatch`](crate::BezierPatch) and octave-nurbs
/// `coefs(k, i, j)`).
///
/// Evaluation sums along `v` first, then along `u`, each in `bspeval`'s order (as octave-nurbs
/// `nrbeval`). The uniform bicubic case on one span is seed 004's "Coons B-spline surface"
/// `vᵀ M_Sᵀ X_S M_S u` with `M_S = M_C` (the notes print the Bézier matrix for `M_S`; see
/// [`crate::conversion::bspline_matrix`]).
///
/// ```
/// use cagd::bspline::BSplineSurface;
/// use cagd::Surface;
/// use nalgebra::DMatrix;
/// // Bilinear: degree (1, 1), one span each way.
/// let z = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 1.0, 3.0]);
/// let s = BSplineSurface::new(1, 1, vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 0.0, 1.0, 1.0], vec![z])?;
/// assert_eq!(s.try_eval(0.5, 0.5)?[0], 1.25);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface<T: Scalar = f64> {
    degrees: (usize, usize),
    knots: (KnotVector<T>, KnotVector<T>),
    coords: Vec<DMatrix<T>>,
}

impl<T: Scalar> BSplineSurface<T> {
    /// The surface of degrees `(p, q)` with knots `knots_u` (`nu + p + 1`), `knots_v`
    /// (`nv + q + 1`) and control net `coords` (one `nu × nv` matrix per coordinate).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for no coordinates or matrices of different shapes;
    /// [`Error::NonFinite`]; and per direction the knot errors of
    /// [`BSplineCurve::new`](super::BSplineCurve::new).
    pub fn new(
        p: usize,
        q: usize,
        knots_u: Vec<T>,
        knots_v: Vec<T>,
        coords: Vec<DMatrix<T>>,
    ) -> Result<Self> {
        let what = "B-spline surface";
        let first = coords.first().ok_or_else(|| Error::ShapeMismatch {
            what,
            expected: "at least one coordinate matrix".into(),
            found: "none".into(),
        })?;
        let shape = first.shape();
        for (k, c) in coords.iter().enumerate() {
            if c.shape() != shape {
                return Err(Error::ShapeMismatch {
                    what,
                    expected: format!(
                        "{}×{} in every coordinate (as coordinate 0)",
                        shape.0, shape.1
                    ),
                    found: format!("{}×{} in coordinate {k}", c.nrows(), c.ncols()),
                });
            }
            check_finite("B-spline surface control points", c.iter())?;
        }
        let ku = KnotVector::new(knots_u)?;
        let kv = KnotVector::new(knots_v)?;
        check_knots("B-spline surface, u direction", p, shape.0, &ku)?;
        check_knots("B-spline surface, v direction", q, shape.1, &kv)?;
        Ok(BSplineSurface {
            degrees: (p, q),
            knots: (ku, kv),
            coords,
        })
    }

    /// The surface with clamped uniform knots on `[0, 1]²` in both directions.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn clamped(p: usize, q: usize, coords: Vec<DMatrix<T>>) -> Result<Self> {
        let (nu, nv) = coords.first().map(|c| c.shape()).unwrap_or((0, 0));
        let ku = KnotVector::<T>::clamped_uniform(p, nu)?;
        let kv = KnotVector::<T>::clamped_uniform(q, nv)?;
        Self::new(p, q, ku.as_slice().to_vec(), kv.as_slice().to_vec(), coords)
    }

    /// The degrees `(p, q)`.
    pub fn degrees(&self) -> (usize, usize) {
        self.degrees
    }

    /// The knot vectors `(u, v)`.
    pub fn knots(&self) -> (&KnotVector<T>, &KnotVector<T>) {
        (&self.knots.0, &self.knots.1)
    }

    /// The control net, one `nu × nv` matrix per coordinate.
    pub fn coordinates(&self) -> &[DMatrix<T>] {
        &self.coords
    }

    /// The domain `([u_p, u_nu], [v_q, v_nv])`.
    pub fn domain(&self) -> ((T, T), (T, T)) {
        (
            self.knots.0.domain(self.degrees.0),
            self.knots.1.domain(self.degrees.1),
        )
    }

    /// The point `S(u, v)`.
    ///
    /// # Errors
    /// [`Error::ParameterOutOfRange`] outside the domain.
    pub fn try_eval(&self, u: T, v: T) -> Result<DVector<T>> {
        let (p, q) = self.degrees;
        let (nu, nv) = self.coords[0].shape();
        let (ku, kv) = (self.knots.0.as_slice(), self.knots.1.as_slice());
        let su = find_span(p, nu, ku, &u)?;
        let sv = find_span(q, nv, kv, &v)?;
        let bu = basis_functions(p, ku, su, &u);
        let bv = basis_functions(q, kv, sv, &v);
        Ok(DVector::from_fn(self.coords.len(), |k, _| {
            let c = &self.coords[k];
            bu.iter().enumerate().fold(T::zero(), |acc, (a, nu_a)| {
                let row = su - p + a;
                let along_v = bv.iter().enumerate().fold(T::zero(), |s, (b, nv_b)| {
                    s + nv_b.clone() * c[(row, sv - q + b)].clone()
                });
                acc + nu_a.clone() * along_v
            })
        }))
    }
}

impl<T: Scalar> Surface<T> for BSplineSurface<T> {
    fn dim(&self) -> usize {
        self.coords.len()
    }

    /// The point at `(u, v)` clamped to the domain (NaN gives NaN).
    fn eval(&self, u: T, v: T) -> DVector<T> {
        let ((a, b), (c, d)) = self.domain();
        let u = clamp(u, &a, &b);
        let v = clamp(v, &c, &d);
        self.try_eval(u.clone(), v)
            .unwrap_or_else(|_| DVector::from_element(self.coords.len(), u))
    }
}

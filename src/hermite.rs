//! Hermite (Ferguson) cubics (the lecture notes, "Hermitovská forma").
//!
//! A Ferguson cubic is given by its end points `x_1 = x(0)`, `x_2 = x(1)` and end tangents
//! `x'_1 = x'(0)`, `x'_2 = x'(1)`:
//!
//! ```text
//! x(u) = X_H M_H u,   X_H = [x_1 | x_2 | x'_1 | x'_2],   u = [u³, u², u, 1]ᵀ,
//!
//!        [ 2 −3  0  1]        f_1 = 2u³ − 3u² + 1
//! M_H =  [−2  3  0  0]        f_2 = −2u³ + 3u²
//!        [ 1 −2  1  0]        f_3 = u³ − 2u² + u
//!        [ 1 −1  0  0]        f_4 = u³ − u²
//! ```
//!
//! (rows of `M_H` are the Hermite basis functions `f_H = M_H u`; [`crate::conversion`] has the
//! matrices). Scaling both tangents by `q > 0` keeps the directions at the ends but changes
//! how long the curve "clings" to them ([`HermiteCubic::scaled_tangents`]).

use nalgebra::{DMatrix, DVector};

use crate::bezier::BezierCurve;
use crate::cost::{polynomial_bits, Cost};
use crate::error::{check_finite, Error, Result};
use crate::param::Curve;
use crate::scalar::Scalar;

/// The cubic Hermite basis `[f_1, f_2, f_3, f_4](u)` of the lecture notes (the rows of `M_H`,
/// see the module documentation), in the order of the geometry `X_H = [x(0) x(1) x'(0) x'(1)]`.
/// The thesis (§4.2–4.3) writes the same functions from the cubic Bernstein polynomials `B_i³`
/// and names them by their place in the Coons matrix (4.5), `H0 = f_1`, `H1 = f_3`,
/// `H2 = f_4`, `H3 = f_2`:
///
/// ```text
/// f_1 = H0 = B0 + B1 = (1−u)²(1+2u)      f_3 = H1 =  B1/3 = u(1−u)²
/// f_2 = H3 = B2 + B3 = u²(3−2u)          f_4 = H2 = −B2/3 = −u²(1−u)
/// ```
///
/// The Hermite conditions (the thesis states them only partly): `f_1`, `f_2` interpolate the
/// values (`f_1(0) = 1`, `f_1(1) = 0`, `f_2 = 1 − f_1`) and have zero derivative at both ends;
/// `f_3`, `f_4` vanish at both ends and carry the derivatives: `f_3'(0) = 1`, `f_3'(1) = 0`,
/// `f_4'(0) = 0`, `f_4'(1) = 1` — so the thesis's `H1 = B1/3` and `H2 = −B2/3` are right, signs
/// included.
///
/// This is the crate's one cubic Hermite basis (the Ferguson cubic, the bicubically blended
/// Coons patch and the partially bicubic blend use it). It is evaluated in the Bernstein form
/// above: for `u ∈ [0, 1]` the values are sums of non-negative terms, so they keep their
/// relative accuracy near both ends, where the monomial rows of `M_H` cancel.
///
/// ```
/// use cagd::hermite::hermite_basis;
/// assert_eq!(hermite_basis(0.5), [0.5, 0.5, 0.125, -0.125]);
/// assert_eq!(hermite_basis(0.0), [1.0, 0.0, 0.0, 0.0]);
/// ```
pub fn hermite_basis<T: Scalar>(u: T) -> [T; 4] {
    let s = T::one() - u.clone();
    let three = T::from_usize(3);
    let b0 = s.clone() * s.clone() * s.clone();
    let us2 = u.clone() * s.clone() * s.clone();
    let u2s = u.clone() * u.clone() * s;
    let b3 = u.clone() * u.clone() * u;
    [
        b0 + three.clone() * us2.clone(),
        three * u2s.clone() + b3,
        us2,
        -u2s,
    ]
}

/// The derivatives `[f'_1, f'_2, f'_3, f'_4](u)` of [`hermite_basis`]:
/// `f'_1 = −6u(1−u)`, `f'_2 = 6u(1−u)`, `f'_3 = (1−u)(1−3u)`, `f'_4 = u(3u−2)`.
///
/// ```
/// use cagd::hermite::hermite_basis_derivative;
/// assert_eq!(hermite_basis_derivative(0.0), [0.0, 0.0, 1.0, 0.0]);
/// assert_eq!(hermite_basis_derivative(1.0), [0.0, 0.0, 0.0, 1.0]);
/// ```
pub fn hermite_basis_derivative<T: Scalar>(u: T) -> [T; 4] {
    let s = T::one() - u.clone();
    let three = T::from_usize(3);
    let six_us = T::from_usize(6) * u.clone() * s.clone();
    [
        -six_us.clone(),
        six_us,
        s * (T::one() - three.clone() * u.clone()),
        u.clone() * (three * u - T::from_usize(2)),
    ]
}

/// The cost of the four Hermite functions at one parameter of `param_bits` bits
/// ([`hermite_basis`]): about 16 operations, on cubics in the parameter
/// ([`polynomial_bits`]`(3, param_bits, 0)` bits).
///
/// ```
/// assert_eq!(cagd::hermite::basis_cost(5), cagd::cost::Cost::new(16, 18));
/// ```
pub fn basis_cost(param_bits: u128) -> Cost {
    Cost::new(16, polynomial_bits(3, param_bits, 0))
}

/// A Ferguson (Hermite) cubic over `u ∈ [0, 1]` in any dimension.
///
/// ```
/// use cagd::hermite::HermiteCubic;
/// use nalgebra::DVector;
/// let v = |x: f64, y: f64| DVector::from_vec(vec![x, y]);
/// let c = HermiteCubic::new(v(0.0, 0.0), v(2.0, 0.0), v(1.0, 1.0), v(1.0, -1.0))?;
/// assert_eq!(c.eval(0.5).as_slice(), &[1.0, 0.25]);
/// assert_eq!(c.eval_derivative(1.0).as_slice(), &[1.0, -1.0]);
/// // Its Bézier points: x_1, x_1 + x'_1/3, x_2 − x'_2/3, x_2.
/// let b = c.to_bezier()?;
/// assert_eq!(b.control_point(1).unwrap().as_slice(), &[1.0 / 3.0, 1.0 / 3.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteCubic<T: Scalar = f64> {
    geometry: DMatrix<T>,
}

impl<T: Scalar> HermiteCubic<T> {
    /// The cubic with `x(0) = x1`, `x(1) = x2`, `x'(0) = t1`, `x'(1) = t2`.
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for vectors of different (or zero) length,
    /// [`Error::NonFinite`].
    pub fn new(x1: DVector<T>, x2: DVector<T>, t1: DVector<T>, t2: DVector<T>) -> Result<Self> {
        let d = x1.len();
        let cols = [x1, x2, t1, t2];
        if d == 0 || cols.iter().any(|c| c.len() != d) {
            return Err(Error::ShapeMismatch {
                what: "Hermite cubic",
                expected: "four vectors of the same positive length".into(),
                found: format!("{:?}", cols.iter().map(|c| c.len()).collect::<Vec<_>>()),
            });
        }
        Self::from_geometry(DMatrix::from_fn(d, 4, |r, c| cols[c][r].clone()))
    }

    /// The cubic with geometry matrix `X_H = [x_1 | x_2 | x'_1 | x'_2]` (`d × 4`).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] unless `d ≥ 1` and there are 4 columns; [`Error::NonFinite`].
    pub fn from_geometry(geometry: DMatrix<T>) -> Result<Self> {
        if geometry.ncols() != 4 || geometry.nrows() == 0 {
            return Err(Error::ShapeMismatch {
                what: "Hermite geometry matrix",
                expected: "d × 4 with d ≥ 1".into(),
                found: format!("{} × {}", geometry.nrows(), geometry.ncols()),
            });
        }
        check_finite("Hermite geometry matrix", geometry.iter())?;
        Ok(HermiteCubic { geometry })
    }

    /// The geometry matrix `X_H = [x_1 | x_2 | x'_1 | x'_2]` (`d × 4`).
    pub fn geometry(&self) -> &DMatrix<T> {
        &self.geometry
    }

    /// The dimension `d`.
    pub fn dim(&self) -> usize {
        self.geometry.nrows()
    }

    /// `x(u) = Σ f_i(u) X_H[:, i]`.
    pub fn eval(&self, u: T) -> DVector<T> {
        combine4(&self.geometry, &hermite_basis(u))
    }

    /// The cost of the point at one parameter of `param_bits` bits ([`eval`](Self::eval)):
    /// the four Hermite functions ([`basis_cost`]) and their combination, 8 operations per
    /// coordinate, on cubics in the parameter over coefficients of `bezier_bits + 2` bits,
    /// `bezier_bits` the size of the curve's Bézier points ([`to_bezier`](Self::to_bezier); the
    /// 2 bits cover the factors 3 and 1/3 between the forms).
    ///
    /// ```
    /// use cagd::hermite::HermiteCubic;
    /// use cagd::cost::Cost;
    /// use nalgebra::dvector;
    /// let c = HermiteCubic::new(dvector![0.0, 0.0], dvector![1.0, 0.0], dvector![1.0, 1.0], dvector![1.0, -1.0])?;
    /// assert_eq!(c.eval_cost(5, 10), Cost::new(16 + 2 * 8, 18 + 12));
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_cost(&self, param_bits: u128, bezier_bits: u128) -> Cost {
        Cost::new(
            basis_cost(param_bits).ops() + 8 * self.dim() as u128,
            polynomial_bits(3, param_bits, bezier_bits.saturating_add(2)),
        )
    }

    /// `x'(u)`.
    pub fn eval_derivative(&self, u: T) -> DVector<T> {
        combine4(&self.geometry, &hermite_basis_derivative(u))
    }

    /// `x''(u) = 6a u + 2b` with `a = 2x_1 − 2x_2 + x'_1 + x'_2`,
    /// `b = −3x_1 + 3x_2 − 2x'_1 − x'_2` (the lecture notes' algebraic form).
    pub fn eval_second_derivative(&self, u: T) -> DVector<T> {
        let c = |k: i64| T::from_ratio(k, 1);
        let w = [
            c(12) * u.clone() - c(6),
            c(-12) * u.clone() + c(6),
            c(6) * u.clone() - c(4),
            c(6) * u - c(2),
        ];
        combine4(&self.geometry, &w)
    }

    /// The same end points with both tangents multiplied by `q` (the lecture notes: `q ≠ 0`; the
    /// directions are kept for `q > 0`).
    pub fn scaled_tangents(&self, q: T) -> Self {
        let mut g = self.geometry.clone();
        for r in 0..g.nrows() {
            for c in 2..4 {
                g[(r, c)] = g[(r, c)].clone() * q.clone();
            }
        }
        HermiteCubic { geometry: g }
    }

    /// The same cubic in Bézier form: `b_0 = x_1`, `b_1 = x_1 + x'_1/3`, `b_2 = x_2 − x'_2/3`,
    /// `b_3 = x_2` (the lecture notes' table, "to Bézier from Hermite").
    ///
    /// # Errors
    /// [`Error::NonFinite`] when an inner Bézier point overflows the range of doubles (end
    /// points and tangents near ±1.8e308: `x_1 + x'_1/3` can exceed it).
    pub fn to_bezier(&self) -> Result<BezierCurve<T>> {
        let g = crate::conversion::convert(
            &self.geometry,
            crate::conversion::CubicForm::Hermite,
            crate::conversion::CubicForm::Bezier,
        )?;
        BezierCurve::new(g)
    }

    /// The cubic Bézier curve in Hermite form, tangents taken with respect to its local
    /// parameter `t ∈ [0, 1]`: `x'_1 = 3(b_1 − b_0)`, `x'_2 = 3(b_3 − b_2)`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless the curve is cubic.
    pub fn from_bezier(curve: &BezierCurve<T>) -> Result<Self> {
        if curve.degree() != 3 {
            return Err(Error::InvalidArgument {
                what: "Hermite cubic from Bézier curve",
                message: format!("expected a cubic, got degree {}", curve.degree()),
            });
        }
        Ok(HermiteCubic {
            geometry: crate::conversion::convert(
                curve.control(),
                crate::conversion::CubicForm::Bezier,
                crate::conversion::CubicForm::Hermite,
            )?,
        })
    }
}

/// `Σ_i w[i] g[:, i]`, `i` ascending.
fn combine4<T: Scalar>(g: &DMatrix<T>, w: &[T; 4]) -> DVector<T> {
    DVector::from_fn(g.nrows(), |r, _| {
        w.iter().enumerate().fold(T::zero(), |acc, (i, wi)| {
            acc + wi.clone() * g[(r, i)].clone()
        })
    })
}

impl<T: Scalar> Curve<T> for HermiteCubic<T> {
    fn dim(&self) -> usize {
        HermiteCubic::dim(self)
    }
    /// `[0, 1]` (the cubic continues outside it).
    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }
    fn eval(&self, t: T) -> DVector<T> {
        HermiteCubic::eval(self, t)
    }
    /// [`HermiteCubic::eval_cost`] on the cubic's own data.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        HermiteCubic::eval_cost(
            self,
            param_bits,
            crate::cost::max_bits(self.geometry.iter()),
        )
    }
}

impl<T: Scalar> crate::param::CurveDeriv<T> for HermiteCubic<T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        HermiteCubic::eval_derivative(self, t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn costs_of_the_basis_and_of_a_point() {
        assert_eq!(basis_cost(0), Cost::new(16, 3));
        let c = HermiteCubic::<f64>::from_geometry(DMatrix::zeros(3, 4)).unwrap();
        assert_eq!(c.eval_cost(0, 0), Cost::new(16 + 24, 3 + 2));
        assert_eq!(c.eval_cost(7, 30).bits(), 3 * 8 + 32);
    }
    use crate::conversion::CubicForm;
    use num_rational::BigRational;

    #[test]
    fn the_basis_is_the_matrix_form_and_its_derivative() {
        for (n, d) in [(0, 1), (1, 7), (3, 5), (1, 1), (-2, 3)] {
            let u = BigRational::new(n.into(), d.into());
            assert_eq!(hermite_basis(u.clone()), CubicForm::Hermite.basis(&u));
            // The derivative of the rows of M_H (ascending: c1 + 2 c2 u + 3 c3 u²).
            let m: DMatrix<BigRational> = CubicForm::Hermite.matrix();
            let d = hermite_basis_derivative(u.clone());
            for (i, di) in d.iter().enumerate() {
                let want = m[(i, 1)].clone()
                    + BigRational::from_integer(2.into()) * m[(i, 2)].clone() * u.clone()
                    + BigRational::from_integer(3.into())
                        * m[(i, 3)].clone()
                        * u.clone()
                        * u.clone();
                assert_eq!(*di, want, "f'_{} at {u}", i + 1);
            }
        }
    }

    #[test]
    fn the_bernstein_form_keeps_its_accuracy_near_the_ends() {
        // f_1(1 − 2⁻³⁰) = (2⁻³⁰)²(3 − 2⁻²⁹): the monomial rows would cancel to about 1e-16.
        let e = 2f64.powi(-30);
        let [f1, ..] = hermite_basis(1.0 - e);
        let exact = e * e * (3.0 - 2.0 * e);
        assert!(
            (f1 - exact).abs() <= 4.0 * f64::EPSILON * exact,
            "{f1} vs {exact}"
        );
    }
}

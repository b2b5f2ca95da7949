//! The matrix (monomial) form of a Bézier curve (course notes, the matrix-form notes, §1.2).
//!
//! A cubic is written there as
//!
//! ```text
//!            [1 −3  3 −1] [1  ]
//! p(t) = P · [0  3 −6  3] [t  ]  = (P · M_B) · [1, t, t², t³]ᵀ,   P = [p0 p1 p2 p3],
//!            [0  0  3 −3] [t² ]
//!            [0  0  0  1] [t³ ]
//! ```
//!
//! and `P · M_B` is computed once per curve. In general `M` is the `(n+1) × (n+1)` matrix whose
//! row `i` holds the monomial coefficients of `B_i^n`:
//! `M[i, j] = (−1)^(j−i) C(n, j) C(j, i)` for `j ≥ i`, zero below the diagonal — the matrices
//! are owned by [`crate::conversion`] ([`bezier_to_monomial_matrix`],
//! [`monomial_to_bezier_matrix`],
//! [`cubic_bezier_matrix`](crate::conversion::cubic_bezier_matrix)), in its power order (ascending, as
//! here).
//!
//! See [`MatrixForm`] for why de Casteljau's algorithm, not this form, is the default.

use nalgebra::{DMatrix, DVector};

use super::curve::{check_control, BezierCurve};
use super::mat_mul;
use crate::conversion::{bezier_to_monomial_matrix, monomial_to_bezier_matrix};
use crate::error::Result;
use crate::scalar::Scalar;

/// A polynomial curve in monomial form, `p(u) = Σ_j a_j t^j` with `t = (u − a)/(b − a)`.
///
/// **Layout:** the coefficients are the columns of a `d × (n + 1)` matrix, column `j` being
/// `a_j`; for a Bézier curve this is `P · M` (the matrix-form notes' intermediate product, e.g.
/// `[0 3 0 0; 0 3 −6 4]` for its example).
///
/// # Why de Casteljau is the stable one at high degree
///
/// The monomial coefficients `P · M` are alternating sums with entries of `M` as large as
/// `C(n, j) C(j, i)` (up to about `3^n`), so for a curve whose points are of size 1 the
/// coefficients can be of size `3^n` while the curve stays inside the convex hull of its control
/// points. Evaluating `Σ a_j t^j` then adds and subtracts huge terms to get a small result, and
/// the rounding errors of the big terms remain: the error grows exponentially with the degree
/// (at degree 30 with control values ±1 the monomial form is off by about 1e-3, de Casteljau
/// by about 1e-17; a unit test checks this). De Casteljau's algorithm only forms convex
/// combinations `(1 − t) x + t y` with `t ∈ [0, 1]`, whose rounding errors are bounded by the
/// size of the control points at every step, so its error grows only linearly with the degree.
/// The matrix form is worth it for low degrees sampled many times (the course notes' point);
/// [`BezierCurve::eval`] is the default everywhere else. In exact rationals all forms agree
/// exactly.
///
/// # Example
///
/// ```
/// use cagd::bezier::BezierCurve;
/// let p = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])?;
/// let form = p.matrix_form();
/// assert_eq!(form.coefficients().row(1).iter().copied().collect::<Vec<_>>(), vec![0.0, 3.0, -6.0, 4.0]);
/// assert_eq!(form.eval(1.0).as_slice(), &[3.0, 1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixForm<T: Scalar = f64> {
    coefficients: DMatrix<T>,
    a: T,
    b: T,
}

impl<T: Scalar> MatrixForm<T> {
    /// The polynomial over `[0, 1]` with monomial coefficients the columns of `coefficients`
    /// (`d × (n + 1)`, column `j` multiplies `t^j`).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`](crate::Error::TooFewPoints) for no columns,
    /// [`Error::ShapeMismatch`](crate::Error::ShapeMismatch) for no rows,
    /// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite coefficient.
    pub fn from_coefficients(coefficients: DMatrix<T>) -> Result<Self> {
        check_control("monomial coefficients", &coefficients)?;
        Ok(MatrixForm {
            coefficients,
            a: T::zero(),
            b: T::one(),
        })
    }

    /// The coefficients, column `j` multiplying `t^j` (`d × (n + 1)`).
    pub fn coefficients(&self) -> &DMatrix<T> {
        &self.coefficients
    }

    /// The degree `n` (number of coefficient columns minus one).
    pub fn degree(&self) -> usize {
        self.coefficients.ncols() - 1
    }

    /// The dimension `d`.
    pub fn dim(&self) -> usize {
        self.coefficients.nrows()
    }

    /// The parameter interval `[a, b]`.
    pub fn interval(&self) -> (&T, &T) {
        (&self.a, &self.b)
    }

    /// `Σ_j a_j t^j` with `t = (u − a)/(b − a)`: the power vector `[1, t, t², …]` (each power
    /// the previous one times `t`) multiplied into the coefficients, `j` ascending — the
    /// computation the course notes do by hand.
    pub fn eval(&self, u: T) -> DVector<T> {
        let t = if self.a.is_zero() && self.b.is_one() {
            u
        } else {
            (u - self.a.clone()) / (self.b.clone() - self.a.clone())
        };
        let mut powers = Vec::with_capacity(self.degree() + 1);
        powers.push(T::one());
        for j in 1..=self.degree() {
            let next = powers[j - 1].clone() * t.clone();
            powers.push(next);
        }
        DVector::from_fn(self.dim(), |c, _| {
            powers.iter().enumerate().fold(T::zero(), |acc, (j, p)| {
                acc + self.coefficients[(c, j)].clone() * p.clone()
            })
        })
    }

    /// Back to Bézier form: `b_i = Σ_{j ≤ i} C(i, j) / C(n, j) · a_j`
    /// ([`monomial_to_bezier_matrix`], the inverse of [`bezier_to_monomial_matrix`]), over the
    /// same interval.
    ///
    /// ```
    /// use cagd::bezier::{BezierCurve, MatrixForm};
    /// use nalgebra::DMatrix;
    /// // p(t) = t² has Bézier points 0, 0, 1.
    /// let form = MatrixForm::from_coefficients(DMatrix::from_row_slice(1, 3, &[0.0, 0.0, 1.0]))?;
    /// assert_eq!(form.to_bezier().control().as_slice(), &[0.0, 0.0, 1.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn to_bezier(&self) -> BezierCurve<T> {
        let inverse = monomial_to_bezier_matrix::<T>(self.degree());
        BezierCurve::from_valid(
            mat_mul(&self.coefficients, &inverse),
            self.a.clone(),
            self.b.clone(),
        )
    }
}

impl<T: Scalar> BezierCurve<T> {
    /// The matrix (monomial) form `P · M` of this curve, over the same interval (the matrix-form notes;
    /// [`cubic_bezier_matrix`](crate::conversion::cubic_bezier_matrix) for cubics,
    /// [`bezier_to_monomial_matrix`] in general).
    pub fn matrix_form(&self) -> MatrixForm<T> {
        let m = bezier_to_monomial_matrix::<T>(self.degree());
        let (a, b) = self.interval();
        MatrixForm {
            coefficients: mat_mul(self.control(), &m),
            a: a.clone(),
            b: b.clone(),
        }
    }

    /// The point at `u` from the matrix form (builds [`matrix_form`](Self::matrix_form) each
    /// call; keep the [`MatrixForm`] to evaluate many points). Accurate at low degree only —
    /// see [`MatrixForm`].
    ///
    /// ```
    /// use cagd::bezier::BezierCurve;
    /// let p = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])?;
    /// let x = p.eval_matrix_form(0.4);
    /// assert!((x[0] - 1.2).abs() < 1e-15 && (x[1] - 0.496).abs() < 1e-15);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn eval_matrix_form(&self, u: T) -> DVector<T> {
        self.matrix_form().eval(u)
    }
}

/// The monomial form as a [`Curve`](crate::Curve) over its interval `[a, b]` (the polynomial
/// continues outside it, as for every curve; see [`crate::param`]).
impl<T: Scalar> crate::param::Curve<T> for MatrixForm<T> {
    fn dim(&self) -> usize {
        MatrixForm::dim(self)
    }

    fn domain(&self) -> (T, T) {
        (self.a.clone(), self.b.clone())
    }

    fn eval(&self, t: T) -> DVector<T> {
        MatrixForm::eval(self, t)
    }

    /// Horner's rule per coordinate after mapping `t` onto `[0, 1]`: `2(n+1)d + 3`
    /// operations on numbers of degree `n` in the parameter.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        let (d, n1) = self.coefficients.shape();
        let bits = param_bits
            .saturating_add(self.a.bits())
            .saturating_add(self.b.bits());
        crate::cost::Cost::new(
            2 * (n1 as u128) * (d as u128) + 3,
            crate::cost::polynomial_bits(
                n1.saturating_sub(1),
                bits,
                crate::cost::max_bits(self.coefficients.iter()),
            ),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    #[test]
    fn matrix_times_inverse_is_identity_in_rationals() {
        for n in 0..9 {
            let m = bezier_to_monomial_matrix::<BigRational>(n);
            let curve = BezierCurve::new(DMatrix::identity(n + 1, n + 1)).unwrap();
            let back = curve.matrix_form().to_bezier();
            assert_eq!(back.control(), &DMatrix::identity(n + 1, n + 1), "n = {n}");
            assert_eq!(curve.matrix_form().coefficients(), &m);
        }
    }

    #[test]
    fn monomial_form_loses_digits_at_high_degree_but_de_casteljau_does_not() {
        // A degree-30 curve with alternating control values ±1: the exact value is computed in
        // rationals from the same doubles.
        let n = 30;
        let values: Vec<f64> = (0..=n)
            .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        let curve = BezierCurve::new(DMatrix::from_row_slice(1, n + 1, &values)).unwrap();
        let exact_curve = BezierCurve::new(
            curve
                .control()
                .map(|x| <BigRational as Scalar>::from_f64(x).unwrap()),
        )
        .unwrap();
        let form = curve.matrix_form();
        let (mut worst_casteljau, mut worst_monomial) = (0.0f64, 0.0f64);
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let exact = exact_curve.eval(<BigRational as Scalar>::from_f64(t).unwrap())[0].to_f64();
            worst_casteljau = worst_casteljau.max((curve.eval(t)[0] - exact).abs());
            worst_monomial = worst_monomial.max((form.eval(t)[0] - exact).abs());
        }
        assert!(
            worst_casteljau < 1e-14,
            "de Casteljau error {worst_casteljau}"
        );
        assert!(worst_monomial > 1e-6, "monomial error {worst_monomial}");
    }
}

//! Interpolation of points (the lecture notes, start of §3.11): the Lagrange polynomial through
//! `(x_i, y_i)`, piecewise-linear interpolation, and parametric polynomial curves through
//! `k` points at chosen parameter values (the notes' "geometric form" `x(u) = X G u` with the
//! blending matrix `G`).
//!
//! Everything is written on the product formula `L_{i,n}(x) = Π_{j≠i} (x − x_j)/(x_i − x_j)`
//! (the lecture notes) and its power form, both from [`crate::lagrange`] (the owner of the
//! Lagrange basis, whose node check is used here too: repeated nodes are
//! [`Error::DuplicateNodes`]), generic over the scalar, so the coefficients are exact in
//! rationals.

use nalgebra::{DMatrix, DVector};

use crate::error::{check_finite, Error, Result};
use crate::lagrange::{basis_product_unchecked, check_distinct_nodes, power_coefficients};
use crate::param::Curve;
use crate::scalar::Scalar;

/// The coefficients of `L_{i,n}` highest power first (the lecture notes' and `polyfit`'s
/// order): [`power_coefficients`] reversed.
fn descending_coefficients<T: Scalar>(xs: &[T], i: usize) -> Vec<T> {
    let mut c = power_coefficients(xs, i);
    c.reverse();
    c
}

/// The Lagrange interpolation polynomial `f_n(x) = Σ y_i L_{i,n}(x)` through `(x_i, y_i)`
/// (the lecture notes). The notes warn that the polynomial oscillates more as the degree grows; see
/// [`PiecewiseLinear`] for the other interpolant of their example.
///
/// ```
/// use cagd::interpolation::LagrangePolynomial;
/// use num_rational::BigRational;
/// use cagd::Scalar;
/// // The lecture notes: through (1,1), (2,2), (3,3), (4,2), (5,1) — exactly
/// // f(x) = 3 − 7/6 (x − 3)² + 1/6 (x − 3)⁴.
/// let q = |n: i64| BigRational::from_ratio(n, 1);
/// let f = LagrangePolynomial::new(
///     (1..=5).map(q).collect(), vec![q(1), q(2), q(3), q(2), q(1)])?;
/// assert_eq!(f.eval(BigRational::from_ratio(5, 2)), BigRational::from_ratio(87, 32));
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct LagrangePolynomial<T: Scalar = f64> {
    xs: Vec<T>,
    ys: Vec<T>,
}

impl<T: Scalar> LagrangePolynomial<T> {
    /// The polynomial of degree ≤ n through the n + 1 points `(xs[i], ys[i])`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for no points, [`Error::ShapeMismatch`] for lengths that
    /// differ, [`Error::NonFinite`], [`Error::DuplicateNodes`] for repeated nodes (any order).
    pub fn new(xs: Vec<T>, ys: Vec<T>) -> Result<Self> {
        let what = "Lagrange interpolation nodes";
        if xs.len() != ys.len() {
            return Err(Error::ShapeMismatch {
                what,
                expected: format!("{} values (one per node)", xs.len()),
                found: format!("{}", ys.len()),
            });
        }
        check_distinct_nodes(what, &xs, 1)?;
        check_finite("Lagrange interpolation values", ys.iter())?;
        Ok(LagrangePolynomial { xs, ys })
    }

    /// `Σ y_i L_{i,n}(x)`, each `L_{i,n}` by its product formula
    /// ([`basis_product`](crate::lagrange::basis_product)).
    pub fn eval(&self, x: T) -> T {
        self.ys.iter().enumerate().fold(T::zero(), |acc, (i, y)| {
            acc + y.clone() * basis_product_unchecked(&self.xs, i, &x)
        })
    }

    /// The monomial coefficients, highest power first (as Octave's
    /// `polyfit(x, y, n)`; exact in rationals).
    pub fn coefficients(&self) -> Vec<T> {
        let n = self.xs.len();
        let mut c = vec![T::zero(); n];
        for (i, y) in self.ys.iter().enumerate() {
            for (k, b) in descending_coefficients(&self.xs, i).into_iter().enumerate() {
                c[k] = c[k].clone() + y.clone() * b;
            }
        }
        c
    }
}

/// Piecewise-linear interpolation through `(x_i, y_i)`, `x_i` increasing (the lecture notes:
/// `f(x) = f(x_i) + (f(x_{i+1}) − f(x_i))/(x_{i+1} − x_i) · (x − x_i)` on `⟨x_i, x_{i+1}⟩`;
/// the notes print the last factor as `(x_{i+1} − x_i)`, which would give the constant
/// `f(x_{i+1})`). Outside `[x_0, x_n]` the end pieces are extended.
///
/// ```
/// use cagd::interpolation::PiecewiseLinear;
/// let f = PiecewiseLinear::new(vec![1.0, 2.0, 3.0], vec![1.0, 2.0, 3.0 - 1.0])?;
/// assert_eq!(f.eval(2.5), 2.0);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PiecewiseLinear<T: Scalar = f64> {
    xs: Vec<T>,
    ys: Vec<T>,
}

impl<T: Scalar> PiecewiseLinear<T> {
    /// The interpolant through `(xs[i], ys[i])`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 points, [`Error::ShapeMismatch`],
    /// [`Error::NonFinite`], [`Error::InvalidArgument`] unless `xs` strictly increases.
    pub fn new(xs: Vec<T>, ys: Vec<T>) -> Result<Self> {
        let what = "piecewise-linear interpolation";
        if xs.len() != ys.len() {
            return Err(Error::ShapeMismatch {
                what,
                expected: format!("{} values (one per node)", xs.len()),
                found: format!("{}", ys.len()),
            });
        }
        if xs.len() < 2 {
            return Err(Error::TooFewPoints {
                what,
                min: 2,
                found: xs.len(),
            });
        }
        check_finite(what, xs.iter().chain(ys.iter()))?;
        if let Some(k) = xs.windows(2).position(|w| w[0] >= w[1]) {
            return Err(Error::InvalidArgument {
                what,
                message: format!(
                    "nodes must strictly increase, but node {k} is not below node {}",
                    k + 1
                ),
            });
        }
        Ok(PiecewiseLinear { xs, ys })
    }

    /// The value at `x`: `y_i + (y_{i+1} − y_i)/(x_{i+1} − x_i) · (x − x_i)`.
    pub fn eval(&self, x: T) -> T {
        let last = self.xs.len() - 2;
        let i = self
            .xs
            .partition_point(|p| p <= &x)
            .saturating_sub(1)
            .min(last);
        let slope = (self.ys[i + 1].clone() - self.ys[i].clone())
            / (self.xs[i + 1].clone() - self.xs[i].clone());
        self.ys[i].clone() + slope * (x - self.xs[i].clone())
    }
}

/// The blending matrix `G` of the lecture notes' geometric form `x(u) = X G u`,
/// `u = [u^{k−1}, …, u, 1]ᵀ`, for `k` points interpolated at the parameters `params`: row `i`
/// holds the coefficients of `L_{i,k−1}(u)`, highest power first.
///
/// For `(0, ½, 1)` it is the notes' `[2 −3 1; −4 4 0; 2 −1 0]`; for `(0, ⅓, ⅔, 1)` their
/// `G` with rows `(−4.5, 9, −5.5, 1)`, `(13.5, −22.5, 9, 0)`, `(−13.5, 18, −4.5, 0)`,
/// `(4.5, −4.5, 1, 0)` (both checked exactly in the tests).
///
/// This is the lecture notes' printed view, highest power first; the crate's own power order
/// is ascending ([`power_coefficients`]): `G` is those coefficients with the columns
/// reversed.
///
/// # Errors
/// [`Error::DuplicateNodes`] for repeated parameters, [`Error::NonFinite`],
/// [`Error::TooFewPoints`] for none.
pub fn blending_matrix<T: Scalar>(params: &[T]) -> Result<DMatrix<T>> {
    check_distinct_nodes("interpolation parameters", params, 1)?;
    let k = params.len();
    let rows: Vec<Vec<T>> = (0..k).map(|i| descending_coefficients(params, i)).collect();
    Ok(DMatrix::from_fn(k, k, |i, j| rows[i][j].clone()))
}

/// The parametric polynomial curve of degree `k − 1` through `k` points at chosen parameter
/// values: `x(u_i) = x_i` (the lecture notes: the quadratic through 3 points, the cubic through 4, and
/// "Příklad 1" with other parameter choices).
///
/// The parameters need not increase: with `(0, ½, ¼, 1)` ("what happens if the sequence is not
/// monotone?") the curve still passes through every point, but at the parameters given, so it
/// visits them in the order `x_1, x_3, x_2, x_4` instead of following the polygon. On the
/// evenly spaced collinear points 0, 1, 2, 3 it runs along the line to 2, back to 1, further
/// back to ¼ (at `u = ¾`) and then out to 3 (checked exactly in the tests).
///
/// ```
/// use cagd::interpolation::ParametricInterpolant;
/// use nalgebra::DMatrix;
/// let x = DMatrix::from_column_slice(2, 3, &[0.0, 0.0, 1.0, 1.0, 2.0, 0.0]);
/// let c = ParametricInterpolant::new(x, vec![0.0, 0.5, 1.0])?;
/// assert_eq!(c.eval(0.5).as_slice(), &[1.0, 1.0]);
/// assert_eq!(c.eval(0.25).as_slice(), &[0.5, 0.75]);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ParametricInterpolant<T: Scalar = f64> {
    params: Vec<T>,
    points: DMatrix<T>,
    algebraic: DMatrix<T>,
}

impl<T: Scalar> ParametricInterpolant<T> {
    /// The curve through the columns of `points` (`d × k`) at `params` (length `k`).
    ///
    /// # Errors
    /// [`Error::ShapeMismatch`] for a wrong number of parameters or no coordinates, and the
    /// errors of [`blending_matrix`].
    pub fn new(points: DMatrix<T>, params: Vec<T>) -> Result<Self> {
        let what = "parametric interpolation";
        if points.nrows() == 0 || points.ncols() != params.len() {
            return Err(Error::ShapeMismatch {
                what,
                expected: format!("a d × {} point matrix (d ≥ 1)", params.len()),
                found: format!("{} × {}", points.nrows(), points.ncols()),
            });
        }
        check_finite("interpolated points", points.iter())?;
        let g = blending_matrix(&params)?;
        let algebraic = crate::bezier::mat_mul(&points, &g);
        Ok(ParametricInterpolant {
            params,
            points,
            algebraic,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &[T] {
        &self.params
    }

    /// The points `X` (`d × k`).
    pub fn points(&self) -> &DMatrix<T> {
        &self.points
    }

    /// The algebraic form `A = X G` (`d × k`, column `j` multiplies `u^{k−1−j}`).
    pub fn algebraic(&self) -> &DMatrix<T> {
        &self.algebraic
    }

    /// `x(u) = A u` by Horner's rule.
    pub fn eval(&self, u: T) -> DVector<T> {
        DVector::from_fn(self.points.nrows(), |r, _| {
            self.algebraic
                .row(r)
                .iter()
                .fold(T::zero(), |acc, c| acc * u.clone() + c.clone())
        })
    }
}

impl<T: Scalar> Curve<T> for ParametricInterpolant<T> {
    fn dim(&self) -> usize {
        self.points.nrows()
    }
    /// From the smallest to the largest interpolation parameter (they need not be in order;
    /// the polynomial continues outside).
    fn domain(&self) -> (T, T) {
        let mut lo = self.params[0].clone();
        let mut hi = lo.clone();
        for p in &self.params[1..] {
            if *p < lo {
                lo = p.clone();
            }
            if *p > hi {
                hi = p.clone();
            }
        }
        (lo, hi)
    }
    fn eval(&self, t: T) -> DVector<T> {
        ParametricInterpolant::eval(self, t)
    }

    /// Horner's rule on the algebraic coefficients: `2kd` operations on numbers of degree
    /// `k − 1` in the parameter.
    fn point_cost(&self, param_bits: u128) -> crate::cost::Cost {
        let (d, k) = self.algebraic.shape();
        crate::cost::Cost::new(
            2 * (k as u128) * (d as u128),
            crate::cost::polynomial_bits(
                k.saturating_sub(1),
                param_bits,
                crate::cost::max_bits(self.algebraic.iter()),
            ),
        )
    }
}

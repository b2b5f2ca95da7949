//! Integrals of Bernstein polynomials, Bézier curves and B-spline curves (the CAD notes §1.1
//! and §1.2: "for the definite integral … there are simple formulas").
//!
//! - Bernstein: `∫₀ᵗ B_i^n = 1/(n+1) Σ_{j=i+1}^{n+1} B_j^{n+1}(t)`, so `∫₀¹ B_i^n = 1/(n+1)`
//!   ([`bernstein_antiderivative`]).
//! - Bézier curve over `[a, b]` with control points `b_0 … b_n`: its antiderivative
//!   `∫_a^u c` is the Bézier curve of degree `n + 1` over `[a, b]` with control points
//!   `c_0 = 0`, `c_k = (b − a)/(n + 1) · (b_0 + … + b_{k−1})` ([`bezier_antiderivative`]),
//!   and `∫_a^b c = c_{n+1}` ([`bezier_integral`]).
//! - B-spline curve of degree `p` with knots `u_0 … u_{n+p}` and control points
//!   `P_0 … P_{n−1}`: `∫ N_{i,p} = (u_{i+p+1} − u_i)/(p + 1) · Σ_{j>i} N_{j,p+1}` over the knots
//!   with `u_0` and `u_{n+p}` once more, so the antiderivative is the B-spline of degree
//!   `p + 1` over `(u_0, u_0, …, u_{n+p}, u_{n+p})` with control points `Q_0 = 0`,
//!   `Q_i = Q_{i−1} + P_{i−1} (u_{i+p} − u_{i−1})/(p + 1)` ([`bspline_antiderivative`]); it is
//!   `∫_{u_0}^u`, so the integral over the domain `[u_p, u_n]` is `F(u_n) − F(u_p)`
//!   ([`bspline_integral`]; `Q_n` for a clamped knot vector).
//!
//! All are rational, so they are exact in `BigRational`.

use nalgebra::{DMatrix, DVector};

use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::cost::Cost;
use crate::error::Result;
use crate::scalar::Scalar;

/// The Bernstein coefficients (degree `n + 1`, `n + 2` values) of `∫₀ᵗ B_i^n`: `0` for
/// `j ≤ i`, `1/(n+1)` for `j > i` (all zero for `i > n`).
///
/// # Panics
/// If `n + 2` values cannot be held (`n` near `usize::MAX`); the front ends check the degree
/// against their limits first.
///
/// ```
/// let c: Vec<f64> = cagd::integral::bernstein_antiderivative(2, 1);
/// assert_eq!(c, vec![0.0, 0.0, 1.0 / 3.0, 1.0 / 3.0]);
/// ```
pub fn bernstein_antiderivative<T: Scalar>(n: usize, i: usize) -> Vec<T> {
    let len = n.checked_add(2).expect("n + 2 Bernstein coefficients");
    let w = T::one() / T::from_usize(len - 1);
    let mut c = crate::grid::try_filled("Bernstein antiderivative", len, T::zero())
        .unwrap_or_else(|e| panic!("{e}"));
    for x in c.iter_mut().skip(i.saturating_add(1)) {
        *x = w.clone();
    }
    c
}

/// The antiderivative `u ↦ ∫_a^u c` of a Bézier curve over `[a, b]`: degree `n + 1`, same
/// interval, control points `c_0 = 0`, `c_k = (b − a)/(n+1) Σ_{j<k} b_j`.
///
/// # Errors
/// [`Error::Overflow`](crate::Error::Overflow) for a control point whose double overflows
/// (control points near ±1.7·10³⁰⁸ summed, or a wide interval).
///
/// ```
/// use cagd::bezier::BezierCurve;
/// use cagd::integral::bezier_antiderivative;
/// // ∫₀ᵘ 2t dt = u²: the segment 0 → 2 integrates to the control points 0, 0, 1.
/// let c = BezierCurve::from_points(&[[0.0], [2.0]])?;
/// assert_eq!(bezier_antiderivative(&c)?.control().as_slice(), &[0.0, 0.0, 1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bezier_antiderivative<T: Scalar>(curve: &BezierCurve<T>) -> Result<BezierCurve<T>> {
    let (n, d) = (curve.degree(), curve.dim());
    let (a, b) = curve.interval();
    let scale = (b.clone() - a.clone()) / T::from_usize(n + 1);
    let mut control = DMatrix::from_element(d, n + 2, T::zero());
    for k in 1..=n + 1 {
        for r in 0..d {
            control[(r, k)] =
                control[(r, k - 1)].clone() + scale.clone() * curve.control()[(r, k - 1)].clone();
        }
    }
    crate::error::check_overflow("antiderivative control points", control.iter())?;
    BezierCurve::new_on_interval(control, a.clone(), b.clone())
}

/// `∫_a^b c = (b − a)/(n + 1) · Σ b_j`, one value per coordinate.
///
/// # Errors
/// As [`bezier_antiderivative`].
///
/// ```
/// use cagd::bezier::BezierCurve;
/// let c = BezierCurve::from_points(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])?;
/// assert_eq!(cagd::integral::bezier_integral(&c)?.as_slice(), &[1.0, 2.0 / 3.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bezier_integral<T: Scalar>(curve: &BezierCurve<T>) -> Result<DVector<T>> {
    let anti = bezier_antiderivative(curve)?;
    Ok(anti.control().column(curve.degree() + 1).into_owned())
}

/// The antiderivative `u ↦ ∫_{u_0}^u C` of a B-spline curve (see the
/// [module](self) documentation): degree `p + 1`, knots `(u_0, u_0, …, u_{n+p}, u_{n+p})`,
/// `n + 1` control points.
///
/// # Errors
/// [`Error::Overflow`](crate::Error::Overflow) for a control point whose double overflows;
/// otherwise those of [`BSplineCurve::new`] (none for a valid curve).
///
/// ```
/// use cagd::bspline::BSplineCurve;
/// use cagd::integral::bspline_antiderivative;
/// use nalgebra::DMatrix;
/// // The hat function N_{1,1} on the knots 0, 0, 1, 2, 2 has area 1, half of it up to 1.
/// let c = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0], DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 0.0]))?;
/// let f = bspline_antiderivative(&c)?;
/// assert_eq!(f.control().as_slice(), &[0.0, 0.0, 1.0, 1.0]);
/// assert_eq!(f.try_eval(1.0)?[0], 0.5);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bspline_antiderivative<T: Scalar>(curve: &BSplineCurve<T>) -> Result<BSplineCurve<T>> {
    let p = curve.degree();
    let u = curve.knots().as_slice();
    let (d, n) = (curve.dim(), curve.control().ncols());
    let denominator = T::from_usize(p + 1);
    let mut control = DMatrix::from_element(d, n + 1, T::zero());
    for i in 1..=n {
        let width = (u[i + p].clone() - u[i - 1].clone()) / denominator.clone();
        for r in 0..d {
            control[(r, i)] =
                control[(r, i - 1)].clone() + width.clone() * curve.control()[(r, i - 1)].clone();
        }
    }
    crate::error::check_overflow("antiderivative control points", control.iter())?;
    let mut knots = Vec::with_capacity(u.len() + 2);
    knots.push(u[0].clone());
    knots.extend(u.iter().cloned());
    knots.push(u[u.len() - 1].clone());
    BSplineCurve::new(p + 1, knots, control)
}

/// The integral over the domain `[u_p, u_n]`, one value per coordinate:
/// `F(u_n) − F(u_p)` with `F` the [`bspline_antiderivative`].
///
/// # Errors
/// Those of [`bspline_antiderivative`].
///
/// ```
/// use cagd::bspline::BSplineCurve;
/// use nalgebra::DMatrix;
/// // Clamped quadratic on [0, 1] with knots 0,0,0,½,1,1,1: ∫ N_{i,2} = 1/6, 1/3, 1/3, 1/6.
/// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
///     DMatrix::from_row_slice(1, 4, &[6.0, 0.0, 0.0, 0.0]))?;
/// assert_eq!(cagd::integral::bspline_integral(&c)?.as_slice(), &[1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bspline_integral<T: Scalar>(curve: &BSplineCurve<T>) -> Result<DVector<T>> {
    let f = bspline_antiderivative(curve)?;
    let (a, b) = curve.domain();
    let (fb, fa) = (f.try_eval(b)?, f.try_eval(a)?);
    crate::error::finite(
        "B-spline integral",
        DVector::from_fn(fb.len(), |r, _| fb[r].clone() - fa[r].clone()),
    )
}

/// `∫₀¹ B_i^n = 1/(n+1)`, the same for every `i` (for any `n`: `n + 1` is taken as an
/// integer of any size).
///
/// ```
/// assert_eq!(cagd::integral::bernstein_integral::<f64>(3), 0.25);
/// assert!(cagd::integral::bernstein_integral::<f64>(usize::MAX) > 0.0);
/// ```
pub fn bernstein_integral<T: Scalar>(n: usize) -> T {
    let n1 = num_bigint::BigUint::from(n) + 1u32;
    T::one() / T::from_biguint(&n1)
}

/// The values `∫₀ᵗ B_i^n` at each of `ts` for each `i` of `rows` (`k × rows.len()`, row = parameter):
/// the Bernstein polynomials of degree `n + 1` at `t` times the coefficients of
/// [`bernstein_antiderivative`], `1/(n+1) Σ_{j>i} B_j^{n+1}(t)`.
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) for an index `i > n`;
/// [`Error::TooLarge`](crate::Error::TooLarge) for a degree `n + 1` above
/// [`Limits::DEFAULT`](crate::limits::Limits::DEFAULT) (the caller prices the work with
/// [`bernstein_antiderivative_cost`]);
/// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite parameter;
/// [`Error::Overflow`](crate::Error::Overflow) for a value whose double overflows.
///
/// ```
/// // ∫₀^½ B_0^1 = ∫₀^½ (1 − t) dt = 3/8.
/// let v = cagd::integral::bernstein_antiderivative_values::<f64>(1, &[0, 1], &[0.5])?;
/// assert_eq!(v.as_slice(), &[0.375, 0.125]);
/// assert!(cagd::integral::bernstein_antiderivative_values::<f64>(1, &[2], &[0.5]).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bernstein_antiderivative_values<T: Scalar>(
    n: usize,
    rows: &[usize],
    ts: &[T],
) -> Result<DMatrix<T>> {
    let what = "Bernstein antiderivative values";
    if let Some(i) = rows.iter().find(|&&i| i > n) {
        return Err(crate::Error::InvalidArgument {
            what,
            message: format!("index {i} exceeds the degree {n}"),
        });
    }
    crate::limits::Limits::DEFAULT.check_degree(what, n.saturating_add(1))?;
    crate::error::check_finite_slice(what, ts)?;
    crate::grid::grid_len(what, &[ts.len(), rows.len()])?;
    let coefficients: Vec<Vec<T>> = rows
        .iter()
        .map(|&i| bernstein_antiderivative::<T>(n, i))
        .collect();
    let basis = crate::bernstein::basis_matrix(n + 1, ts);
    let values = DMatrix::from_fn(ts.len(), rows.len(), |k, r| {
        (0..n + 2).fold(T::zero(), |s, j| {
            s + basis[(k, j)].clone() * coefficients[r][j].clone()
        })
    });
    crate::error::finite(what, values)
}

/// The cost of the coefficients of `rows` antiderivatives of degree-`n` Bernstein polynomials
/// and of [`bernstein_antiderivative_values`] at `params` parameters of `param_bits` bits: the
/// basis of degree `n + 1` at each ([`basis_cost`](crate::bernstein::basis_cost)) and a dot
/// product of `n + 2` terms per row, on numbers grown by the coefficients' `1/(n+1)`.
///
/// ```
/// use cagd::cost::Cost;
/// // Degree 1, two rows, one parameter: 3 · 3 for the basis, 2 · 3 · 2 for the products, 2 · 3 coefficients.
/// assert_eq!(cagd::integral::bernstein_antiderivative_cost(1, 2, 1, 0), Cost::new(9 + 12 + 6, 2 + 6));
/// ```
pub fn bernstein_antiderivative_cost(
    n: usize,
    rows: usize,
    params: usize,
    param_bits: u128,
) -> Cost {
    let n2 = n as u128 + 2;
    let terms = (rows as u128).saturating_mul(n2);
    let per_param = crate::bernstein::basis_cost(n.saturating_add(1), param_bits);
    Cost::new(
        per_param
            .ops()
            .saturating_add(terms.saturating_mul(2))
            .saturating_mul(params as u128)
            .saturating_add(terms),
        per_param.bits().saturating_add(2 * n2),
    )
}

/// The factor `(b − a)/(n + 1)` of the partial sums of [`bezier_antiderivative`].
///
/// # Errors
/// [`Error::Overflow`](crate::Error::Overflow) when `b − a` is not a finite double (an
/// interval such as `[−10³⁰⁸, 10³⁰⁸]`).
///
/// ```
/// use cagd::bezier::BezierCurve;
/// let c = BezierCurve::new_on_interval(nalgebra::dmatrix![0.0, 1.0, 2.0], 1.0, 4.0)?;
/// assert_eq!(cagd::integral::bezier_antiderivative_factor(&c)?, 1.0);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bezier_antiderivative_factor<T: Scalar>(curve: &BezierCurve<T>) -> Result<T> {
    let (a, b) = curve.interval();
    let factor = (b.clone() - a.clone()) / T::from_usize(curve.degree() + 1);
    crate::error::check_overflow("Bézier antiderivative factor", [&factor])?;
    Ok(factor)
}

/// `∫ N_{i,p} = (u_{i+p+1} − u_i)/(p + 1)` for each basis function of the curve (over all the
/// knots): the factors of [`bspline_antiderivative`]'s partial sums.
///
/// ```
/// use cagd::bspline::BSplineCurve;
/// use nalgebra::DMatrix;
/// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], DMatrix::zeros(1, 4))?;
/// assert_eq!(cagd::integral::bspline_basis_integrals(&c), vec![1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bspline_basis_integrals<T: Scalar>(curve: &BSplineCurve<T>) -> Vec<T> {
    let p = curve.degree();
    let u = curve.knots().as_slice();
    (0..curve.control().ncols())
        .map(|i| (u[i + p + 1].clone() - u[i].clone()) / T::from_usize(p + 1))
        .collect()
}

/// `∫_{u_p}^t C` at each of `ts` (`d × k`), from the antiderivative `f` of `C`
/// ([`bspline_antiderivative`]): `f(t) − f(u_p)`, the domain of `f` being `C`'s with a knot
/// more at each end.
///
/// # Errors
/// [`Error::ParameterOutOfRange`](crate::Error::ParameterOutOfRange) for a parameter outside
/// the domain, [`Error::NonFinite`](crate::Error::NonFinite).
///
/// ```
/// use cagd::bspline::BSplineCurve;
/// use cagd::integral::{bspline_antiderivative, bspline_integral_to};
/// use nalgebra::DMatrix;
/// let c = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0], DMatrix::from_row_slice(1, 3, &[0.0, 1.0, 0.0]))?;
/// let f = bspline_antiderivative(&c)?;
/// assert_eq!(bspline_integral_to(&f, c.domain().0, &[1.0, 2.0])?.as_slice(), &[0.5, 1.0]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn bspline_integral_to<T: Scalar>(
    f: &BSplineCurve<T>,
    start: T,
    ts: &[T],
) -> Result<DMatrix<T>> {
    let at_start = f.try_eval(start)?;
    let mut out = DMatrix::from_element(f.dim(), ts.len(), T::zero());
    for (k, t) in ts.iter().enumerate() {
        let v = f.try_eval(t.clone())?;
        for r in 0..v.len() {
            out[(r, k)] = v[r].clone() - at_start[r].clone();
        }
    }
    Ok(out)
}

/// The cost of an antiderivative's control points ([`bezier_antiderivative`],
/// [`bspline_antiderivative`]) of a curve of degree `degree` with `points` `d`-dimensional
/// control points: partial sums with one factor each, `4d(points + 1)` operations on numbers
/// of `control_bits` grown by the factors (about `2(degree + 2)` bits).
///
/// ```
/// use cagd::cost::Cost;
/// assert_eq!(cagd::integral::antiderivative_cost(3, 2, 2, 5), Cost::new(32, 13));
/// ```
pub fn antiderivative_cost(points: usize, d: usize, degree: usize, control_bits: u128) -> Cost {
    Cost::new(
        (4 * d as u128).saturating_mul(points as u128 + 1),
        control_bits.saturating_add(2 * (degree as u128 + 2)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::from_ratio(n, d)
    }

    #[test]
    fn antiderivatives_differentiate_back_exactly() {
        let c = BezierCurve::new_on_interval(
            DMatrix::from_row_slice(1, 4, &[q(1, 1), q(-2, 3), q(5, 2), q(0, 1)]),
            q(1, 1),
            q(4, 1),
        )
        .unwrap();
        let f = bezier_antiderivative(&c).unwrap();
        assert_eq!(f.derivative(1).unwrap().control(), c.control());
        let knots = vec![
            q(0, 1),
            q(1, 3),
            q(1, 2),
            q(2, 1),
            q(5, 2),
            q(3, 1),
            q(4, 1),
        ];
        let s = BSplineCurve::new(
            2,
            knots,
            DMatrix::from_row_slice(1, 4, &[q(1, 1), q(3, 1), q(-1, 1), q(2, 1)]),
        )
        .unwrap();
        let g = bspline_antiderivative(&s).unwrap();
        let dg = g.derivative().unwrap();
        let (a, b) = s.domain();
        for k in 0..=12 {
            let t = a.clone() + (b.clone() - a.clone()) * q(k, 12);
            assert_eq!(dg.try_eval(t.clone()).unwrap(), s.try_eval(t).unwrap());
        }
    }
}

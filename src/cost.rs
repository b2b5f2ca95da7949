//! Estimates of a computation's work, made before it starts, so that a caller can refuse it
//! above [`Limits::max_work`](crate::limits::Limits::max_work).
//!
//! A [`Cost`] is a number of arithmetic operations and the size, in bits, that the numbers
//! they work on reach (numerator and denominator together; `0` when the caller computes in
//! `f64`, whose cost does not depend on the value). [`Cost::weigh`] turns it into units of one
//! `f64` operation: the operations themselves in `f64`, each weighed by
//! [`exact_op_cost`] of the size in exact arithmetic.
//!
//! Each construction estimates itself, beside its code, from the sizes of its inputs (which the
//! caller measures: this crate does not know how large a scalar is):
//!
//! | construction | estimate |
//! |---|---|
//! | Bernstein basis (triangular recurrence) | [`bernstein::basis_cost`](crate::bernstein::basis_cost) |
//! | de Casteljau on a Bézier curve | [`BezierCurve::eval_cost`](crate::BezierCurve::eval_cost) |
//! | Bézier patch on a grid, its scheme | [`BezierPatch::grid_cost`](crate::BezierPatch::grid_cost), [`BezierPatch::scheme_cost`](crate::BezierPatch::scheme_cost) |
//! | a sampled curve looked up | [`SampledCurve::eval_cost`](crate::SampledCurve::eval_cost) |
//! | Hermite basis, Ferguson cubic | [`hermite::basis_cost`](crate::hermite::basis_cost), [`HermiteCubic::eval_cost`](crate::HermiteCubic::eval_cost) |
//! | B-spline (and NURBS) basis and curve | [`bspline::basis_cost`](crate::bspline::basis_cost), [`bspline::curve_point_cost`](crate::bspline::curve_point_cost) |
//! | the Cox–de Boor triangle of a knot vector | [`bspline::triangle_cost`](crate::bspline::triangle_cost) |
//! | knot insertion (Boehm) | [`BSplineCurve::insertion_cost`](crate::BSplineCurve::insertion_cost) |
//! | B-spline and NURBS surfaces at a point | [`BSplineSurface::point_cost`](crate::bspline::BSplineSurface::point_cost), [`NurbsSurface::point_cost`](crate::nurbs::NurbsSurface::point_cost) |
//! | interpolating cubic spline | [`spline::interpolation_cost`](crate::spline::interpolation_cost), [`spline::sample_cost`](crate::spline::sample_cost) |
//! | Lagrange basis (barycentric) | [`Lagrange::weights_cost`](crate::lagrange::Lagrange::weights_cost), [`Lagrange::basis_cost`](crate::lagrange::Lagrange::basis_cost), [`Lagrange::interpolation_cost`](crate::lagrange::Lagrange::interpolation_cost) |
//! | Coons patches, Gordon surfaces (blends of curves) | [`coons::coons_point_cost`](crate::coons::coons_point_cost), [`coons::bicubic_point_cost`](crate::coons::bicubic_point_cost), [`gordon::gordon_point_cost`](crate::gordon::gordon_point_cost), all through [`blended`] |
//! | the set-up of a Gordon surface (crossings checked, Lagrange weights) | [`gordon::gordon_setup_cost`](crate::gordon::gordon_setup_cost) |
//! | the discrete Coons formula, its three parts | [`coons::discrete_coons_cost`](crate::coons::discrete_coons_cost), [`coons::discrete_coons_parts_cost`](crate::coons::discrete_coons_parts_cost) |
//! | ruled surfaces, Ferguson patches | [`surfaces::ruled_point_cost`](crate::surfaces::ruled_point_cost), [`surfaces::ferguson_point_cost`](crate::surfaces::ferguson_point_cost) |
//! | the band solve of a discrete Coons mask | [`Mask::solve_cost`](crate::coons::Mask::solve_cost) |
//! | degree elevation of a Bézier or B-spline curve | [`bernstein::elevate_cost`](crate::bernstein::elevate_cost), [`BezierCurve::elevate_cost`](crate::BezierCurve::elevate_cost), [`BSplineCurve::elevate_cost`](crate::BSplineCurve::elevate_cost) |
//! | conversion between geometry forms | [`conversion::form_conversion_cost`](crate::conversion::form_conversion_cost) |
//! | the joint of two Bézier curves | [`continuity::bezier_joint_cost`](crate::continuity::bezier_joint_cost) |
//! | antiderivatives, integrals of Bernstein polynomials | [`integral::antiderivative_cost`](crate::integral::antiderivative_cost), [`integral::bernstein_antiderivative_cost`](crate::integral::bernstein_antiderivative_cost) |
//!
//! The sizes grow with the construction ([`polynomial_bits`]): a de Casteljau scheme of degree
//! `n` at `t = p/q` multiplies denominators by `q` at each of its `n` levels; an interpolating
//! spline's tridiagonal solve builds continuants of about 4 bits per point.
//!
//! ```
//! use cagd::cost::Cost;
//! // 1000 operations on numbers of 100 bits: 1000 in f64, 1000 · 2064 in exact arithmetic.
//! let c = Cost::new(1000, 100);
//! assert_eq!((c.weigh(false), c.weigh(true)), (1000, 2_064_000));
//! ```

use crate::limits::exact_op_cost;
use crate::scalar::Scalar;

/// The most bits of any of `values` ([`Scalar::bits`]; 0 for none, and for `f64` without
/// looking at them): the size a caller measures before asking for an estimate.
///
/// ```
/// use cagd::Scalar;
/// use num_rational::BigRational;
/// let xs = [BigRational::from_ratio(1, 3), BigRational::from_ratio(255, 7)];
/// assert_eq!(cagd::cost::max_bits(&xs), 11);
/// assert_eq!(cagd::cost::max_bits(&[0.5f64]), 0);
/// ```
pub fn max_bits<'a, T: Scalar>(values: impl IntoIterator<Item = &'a T>) -> u128 {
    if T::EXACT {
        values.into_iter().map(Scalar::bits).max().unwrap_or(0)
    } else {
        0
    }
}

/// `ops` arithmetic operations on numbers of about `bits` bits (see the
/// [module documentation](self)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cost {
    ops: u128,
    bits: u128,
    exact_divisor: u128,
}

impl Default for Cost {
    /// No work.
    fn default() -> Self {
        Cost::new(0, 0)
    }
}

impl Cost {
    /// `ops` operations on numbers of `bits` bits.
    pub const fn new(ops: u128, bits: u128) -> Self {
        Cost {
            ops,
            bits,
            exact_divisor: 1,
        }
    }

    /// The number of operations.
    pub const fn ops(&self) -> u128 {
        self.ops
    }

    /// The size the numbers reach, in bits.
    pub const fn bits(&self) -> u128 {
        self.bits
    }

    /// The same work done `k` times (`k · ops`, saturating).
    ///
    /// ```
    /// assert_eq!(cagd::cost::Cost::new(3, 8).times(5).ops(), 15);
    /// ```
    pub const fn times(self, k: u128) -> Self {
        Cost {
            ops: self.ops.saturating_mul(k),
            ..self
        }
    }

    /// Both works: the operations added, on numbers as large as the larger of the two (and,
    /// if they were measured cheaper in exact arithmetic by different factors, the smaller
    /// factor).
    ///
    /// ```
    /// use cagd::cost::Cost;
    /// assert_eq!(Cost::new(3, 8).and(Cost::new(4, 100)), Cost::new(7, 100));
    /// ```
    pub fn and(self, other: Cost) -> Self {
        Cost {
            ops: self.ops.saturating_add(other.ops),
            bits: self.bits.max(other.bits),
            exact_divisor: self.exact_divisor.min(other.exact_divisor),
        }
    }

    /// The same operations on numbers `extra` bits larger.
    ///
    /// ```
    /// assert_eq!(cagd::cost::Cost::new(3, 8).grown(2).bits(), 10);
    /// ```
    pub const fn grown(self, extra: u128) -> Self {
        Cost {
            bits: self.bits.saturating_add(extra),
            ..self
        }
    }

    /// The same work, measured to take `1/divisor` of [`exact_op_cost`] per exact operation
    /// (an algorithm whose operations are mostly on zeros and small numbers).
    ///
    /// ```
    /// use cagd::cost::Cost;
    /// assert_eq!(Cost::new(16, 0).cheaper_when_exact(16).weigh(true), 1016);
    /// ```
    pub const fn cheaper_when_exact(self, divisor: u128) -> Self {
        Cost {
            exact_divisor: if divisor == 0 { 1 } else { divisor },
            ..self
        }
    }

    /// The work in units of one `f64` operation: [`ops`](Self::ops) in `f64`
    /// (`exact = false`), `ops · exact_op_cost(bits)` (divided as
    /// [`cheaper_when_exact`](Self::cheaper_when_exact) says) in exact arithmetic.
    pub fn weigh(self, exact: bool) -> u128 {
        if exact {
            self.ops.saturating_mul(exact_op_cost(self.bits)) / self.exact_divisor
        } else {
            self.ops
        }
    }
}

/// The size a polynomial of degree `degree` in a parameter of `param_bits` bits, with
/// coefficients of `coefficient_bits` bits, reaches:
///
/// ```text
/// coefficient_bits + degree · (param_bits + 1)
/// ```
///
/// (each level of a de Casteljau scheme or Bernstein recurrence multiplies by `t = p/q` or
/// `1 − t`, adding the bits of `p` and `q`; the `+ 1` covers binomials and carries).
///
/// ```
/// assert_eq!(cagd::cost::polynomial_bits(3, 4, 10), 25);
/// ```
pub fn polynomial_bits(degree: usize, param_bits: u128, coefficient_bits: u128) -> u128 {
    (degree as u128)
        .saturating_mul(param_bits.saturating_add(1))
        .saturating_add(coefficient_bits)
}

/// A blend of curves at one point (Coons patches, Gordon surfaces): each curve evaluated once
/// (its cost), then `blend_ops` operations, on numbers as large as the largest curve value grown
/// by `extra_bits` (the bits of the blending functions).
///
/// ```
/// use cagd::cost::{blended, Cost};
/// let c = blended([Cost::new(10, 30), Cost::new(5, 40)], 48, 6);
/// assert_eq!(c, Cost::new(63, 46));
/// ```
pub fn blended(curves: impl IntoIterator<Item = Cost>, blend_ops: u128, extra_bits: u128) -> Cost {
    curves
        .into_iter()
        .fold(Cost::new(blend_ops, 0), Cost::and)
        .grown(extra_bits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weighing_saturates_instead_of_overflowing() {
        let huge = Cost::new(u128::MAX / 2, 1 << 20);
        assert_eq!(huge.weigh(true), u128::MAX);
        assert_eq!(huge.times(4).weigh(false), u128::MAX);
        assert_eq!(Cost::new(1, u128::MAX).grown(5).bits(), u128::MAX);
    }

    #[test]
    fn exact_weight_follows_the_size() {
        assert_eq!(Cost::new(2, 0).weigh(true), 2 * exact_op_cost(0));
        assert_eq!(Cost::new(2, 200).weigh(true), 2 * exact_op_cost(200));
        assert_eq!(Cost::new(2, 200).weigh(false), 2);
        // The smaller divisor wins when works measured differently are joined.
        let c = Cost::new(16, 0)
            .cheaper_when_exact(16)
            .and(Cost::new(16, 0).cheaper_when_exact(4));
        assert_eq!(c.weigh(true), 32 * exact_op_cost(0) / 4);
        assert_eq!(Cost::default().weigh(true), 0);
    }

    #[test]
    fn polynomial_sizes() {
        assert_eq!(polynomial_bits(0, 100, 7), 7);
        assert_eq!(polynomial_bits(10, 0, 0), 10);
        assert_eq!(polynomial_bits(usize::MAX, u128::MAX, 1), u128::MAX);
    }
}

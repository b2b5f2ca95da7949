//! B-spline basis functions: the Cox–de Boor recursion (the CAD notes and the lecture notes) and the
//! triangular scheme that evaluates the `p + 1` non-zero ones at once.

use crate::cost::{polynomial_bits, Cost};
use crate::error::Result;
use crate::scalar::Scalar;

/// The index `s` of the knot span `[u_s, u_{s+1})` holding `u`, for a degree-`p` spline with
/// `n_control` control points (`p ≤ s ≤ n_control − 1`); at the right end of the domain,
/// `u = u_{n_control}`, the last non-empty span `n_control − 1` (as octave-nurbs `findspan`,
/// which numbers from 0 too).
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite `u` or knot,
/// [`Error::ParameterOutOfRange`](crate::Error::ParameterOutOfRange) unless
/// `u_p ≤ u ≤ u_{n_control}`; the count errors of [`BSplineCurve::new`](super::BSplineCurve::new).
///
/// ```
/// use cagd::bspline::find_span;
/// let knots = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
/// assert_eq!(find_span(2, 4, &knots, &0.25)?, 2);
/// assert_eq!(find_span(2, 4, &knots, &0.5)?, 3);
/// assert_eq!(find_span(2, 4, &knots, &1.0)?, 3);
/// assert!(find_span(2, 4, &knots, &1.5).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn find_span<T: Scalar>(p: usize, n_control: usize, knots: &[T], u: &T) -> Result<usize> {
    crate::error::check_finite("knot vector", knots.iter())?;
    span_of(p, n_control, knots, u)
}

/// [`find_span`] for knots already known to be finite (a [`KnotVector`](super::KnotVector)):
/// `O(log n)`.
pub(crate) fn span_of<T: Scalar>(p: usize, n_control: usize, knots: &[T], u: &T) -> Result<usize> {
    super::knots::check_knot_slice("knot vector", p, n_control, knots)?;
    let (lo, hi) = (&knots[p], &knots[n_control]);
    check_in_domain(u, lo, hi)?;
    if u == hi {
        return Ok(last_span(p, n_control, knots));
    }
    // Largest s with u_s <= u, within [p, n_control − 1].
    // (Knots out of order give some span in the range, never a panic.)
    let above = knots[..=n_control].partition_point(|k| k <= u);
    Ok(above.saturating_sub(1).clamp(p, n_control - 1))
}

/// The span [`find_span`] gives for the right end `u_{n_control}` of the domain: the last span
/// of positive length ending there.
pub(crate) fn last_span<T: Scalar>(p: usize, n_control: usize, knots: &[T]) -> usize {
    let mut s = n_control - 1;
    while s > p && knots[s] == knots[s + 1] {
        s -= 1;
    }
    s
}

/// `Ok` if `lo ≤ u ≤ hi`, else the error [`find_span`] reports: [`Error::NonFinite`](crate::Error::NonFinite) for NaN
/// or ±∞, [`Error::ParameterOutOfRange`](crate::Error::ParameterOutOfRange) for a finite `u` outside (the `try_eval` rule of
/// [`crate::param`]).
pub(crate) fn check_in_domain<T: Scalar>(u: &T, lo: &T, hi: &T) -> Result<()> {
    crate::param::check_parameter("B-spline parameter", u, &(lo.clone(), hi.clone()))
}

/// The span whose polynomial piece gives the curve at `u`: [`find_span`]'s inside the domain,
/// the first non-empty span below it and the last one above it (so the end pieces continue,
/// the `eval` rule of [`crate::param`]); `None` for NaN or ±∞.
pub(crate) fn extended_span<T: Scalar>(
    p: usize,
    n_control: usize,
    knots: &[T],
    u: &T,
) -> Option<usize> {
    if !u.is_finite_value() {
        return None;
    }
    let (lo, hi) = (&knots[p], &knots[n_control]);
    let at = if u < lo {
        lo
    } else if u > hi {
        hi
    } else {
        u
    };
    span_of(p, n_control, knots, at).ok()
}

/// The non-zero basis functions `N_{s−p,p}(u), …, N_{s,p}(u)` on the span `s`
/// (from [`find_span`]), by the triangular scheme of Cox–de Boor (Piegl & Tiller, A2.2),
/// in the operation order of octave-nurbs `basisfun`. They are non-negative and sum to one.
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite `u` or knot;
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) unless the knots
/// `u_{s−p+1} … u_{s+p}` the scheme reads exist (`p ≤ s + 1` and `s + p < knots.len()`);
/// [`Error::TooLarge`](crate::Error::TooLarge) when the `(p+1)²` operations exceed the
/// default work limit; [`Error::Overflow`](crate::Error::Overflow) for a value that is not a
/// finite double (knots out of order or too close together).
///
/// ```
/// use cagd::bspline::{basis_functions, find_span};
/// let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
/// // One span: the quadratic Bernstein polynomials.
/// let n = basis_functions(2, &knots, find_span(2, 3, &knots, &0.5)?, &0.5)?;
/// assert_eq!(n, vec![0.25, 0.5, 0.25]);
/// assert!(basis_functions(2, &knots, 4, &0.5).is_err()); // u_6 does not exist
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn basis_functions<T: Scalar>(p: usize, knots: &[T], span: usize, u: &T) -> Result<Vec<T>> {
    crate::error::check_finite("B-spline parameter", std::iter::once(u))?;
    crate::error::check_finite("knot vector", knots.iter())?;
    let reads = span
        .checked_add(p)
        .filter(|&last| last < knots.len() && p <= span + 1);
    if reads.is_none() {
        return Err(crate::Error::InvalidArgument {
            what: "B-spline basis span",
            message: format!(
                "the basis of degree {p} on span {span} reads the knots u_{{{span}+1−{p}}} … u_{{{span}+{p}}}, but there are {} knots",
                knots.len()
            ),
        });
    }
    crate::checked::point_work::<T>(
        "B-spline basis",
        basis_cost(p, u.bits(), crate::cost::max_bits(knots)),
    )?;
    let values = basis_values(p, knots, span, u);
    crate::error::check_overflow("B-spline basis", values.iter())?;
    Ok(values)
}

/// [`basis_functions`] for a span and knots already checked.
pub(crate) fn basis_values<T: Scalar>(p: usize, knots: &[T], span: usize, u: &T) -> Vec<T> {
    let mut n = vec![T::zero(); p + 1];
    let mut left = vec![T::zero(); p + 1];
    let mut right = vec![T::zero(); p + 1];
    basis_functions_into(p, knots, span, u, &mut n, &mut left, &mut right);
    n
}

/// [`basis_functions`] into caller-given buffers: `n` receives `N_{s−p,p}(u), …, N_{s,p}(u)`;
/// `left` and `right` are scratch. All three must hold at least `p + 1` entries. The same
/// operations in the same order as [`basis_functions`] (so the same values, bit for bit), with
/// no allocation: the batch evaluations of B-spline and NURBS curves and surfaces call it once
/// per parameter.
///
/// The scheme reads only the knots `u_{s+1−p}, …, u_{s+p}`; any span `s` for which they exist
/// gives the polynomial pieces of that span at `u` (a zero-length span divides zero by zero:
/// NaN), which is what octave-nurbs `basisfun` computes for a span it is given.
///
/// # Panics
/// If a buffer holds fewer than `p + 1` entries or the knots `u_{s+1−p} … u_{s+p}` do not
/// exist (`s + 1 < p` or `s + p ≥ knots.len()`).
///
/// ```
/// use cagd::bspline::basis_functions_into;
/// let knots = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
/// let (mut n, mut l, mut r) = ([0.0; 3], [0.0; 3], [0.0; 3]);
/// basis_functions_into(2, &knots, 2, &0.25, &mut n, &mut l, &mut r);
/// assert_eq!(n, [0.25, 0.625, 0.125]);
/// ```
pub fn basis_functions_into<T: Scalar>(
    p: usize,
    knots: &[T],
    span: usize,
    u: &T,
    n: &mut [T],
    left: &mut [T],
    right: &mut [T],
) {
    n[0] = T::one();
    for j in 1..=p {
        left[j] = u.clone() - knots[span + 1 - j].clone();
        right[j] = knots[span + j].clone() - u.clone();
        let mut saved = T::zero();
        for r in 0..j {
            let temp = n[r].clone() / (right[r + 1].clone() + left[j - r].clone());
            n[r] = saved + right[r + 1].clone() * temp.clone();
            saved = left[j - r].clone() * temp;
        }
        n[j] = saved;
    }
}

/// The basis function `N_{i,p}(u)` by the Cox–de Boor recursion itself:
///
/// ```text
/// N_{i,0}(u) = 1 if u_i ≤ u < u_{i+1}, else 0,
/// N_{i,p}(u) = (u − u_i)/(u_{i+p} − u_i) · N_{i,p−1}(u) + (u_{i+p+1} − u)/(u_{i+p+1} − u_{i+1}) · N_{i+1,p−1}(u),
/// ```
///
/// a term with a zero denominator being zero. At the right end of the domain the last span is
/// taken as closed, so the basis still sums to one there. Slow (exponential in `p`); for
/// teaching and testing — [`basis_functions`] is the algorithm to use.
///
/// The lecture notes print the recursion with `N_{i+1,k}` in the second term; it must be
/// `N_{i+1,k−1}` (order `k` = degree + 1 in its notation). It also writes `N_{i,1} = 1` for
/// `u_i ≤ u ≤ u_{i+1}`, a closed interval, which would count an interior knot twice; the
/// spans are half-open. Its explicit `N_{i,3}` (uniform knots) misses the factor ½ on the second
/// term of the recursion, and its list of uniform cubic pieces names the last one `N_{2,3}`
/// again (it is `N_{3,3}`); the matrix it derives from them, `M_C`, is right.
///
/// ```
/// use cagd::bspline::cox_de_boor;
/// let knots = [0.0, 1.0, 2.0, 3.0];
/// // The uniform quadratic B-spline: ½u² on [0, 1], peak ¾ at u = 1.5.
/// assert_eq!(cox_de_boor(0, 2, &knots, &0.5)?, 0.125);
/// assert_eq!(cox_de_boor(0, 2, &knots, &1.5)?, 0.75);
/// assert!(cox_de_boor(1, 2, &knots, &1.5).is_err()); // N_{1,2} needs the knots u_1 … u_4
/// # Ok::<(), cagd::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) unless the knots `u_i … u_{i+p+1}`
/// exist; [`Error::NonFinite`](crate::Error::NonFinite) for a NaN or infinite `u` or knot;
/// [`Error::TooLarge`](crate::Error::TooLarge) when the recursion's `2^(p+1)` calls exceed the
/// default work limit (from degree 27 or so); [`Error::Overflow`](crate::Error::Overflow) for a
/// value that is not a finite double.
pub fn cox_de_boor<T: Scalar>(i: usize, p: usize, knots: &[T], u: &T) -> Result<T> {
    let needed = i.checked_add(p).and_then(|x| x.checked_add(1));
    if needed.is_none_or(|last| last >= knots.len()) {
        return Err(crate::Error::InvalidArgument {
            what: "Cox-de Boor basis function",
            message: format!(
                "N_{{{i},{p}}} needs the knots u_{i} … u_{{{i}+{p}+1}}, but there are {} knots",
                knots.len()
            ),
        });
    }
    crate::error::check_finite("Cox-de Boor parameter", std::iter::once(u))?;
    crate::error::check_finite("knot vector", knots[i..=i + p + 1].iter())?;
    // The recursion makes 2^(p+1) − 1 calls, each reading up to the whole knot vector at the
    // bottom: refused before it starts when that exceeds the default work limit.
    let calls = 1u128
        .checked_shl(p.saturating_add(1).min(127) as u32)
        .unwrap_or(u128::MAX);
    crate::checked::point_work::<T>(
        "Cox-de Boor recursion",
        crate::cost::Cost::new(calls.saturating_mul(4 + knots.len() as u128 - i as u128), 0).grown(
            crate::cost::polynomial_bits(p, u.bits(), crate::cost::max_bits(knots)),
        ),
    )?;
    crate::error::finite(
        "Cox-de Boor basis function",
        [cox_de_boor_unchecked(i, p, knots, u)],
    )
    .map(|[v]| v)
}

/// [`cox_de_boor`] for `i + p + 1 < knots.len()`.
pub(crate) fn cox_de_boor_unchecked<T: Scalar>(i: usize, p: usize, knots: &[T], u: &T) -> T {
    let last = knots.len() - 1;
    if p == 0 {
        let (a, b) = (&knots[i], &knots[i + 1]);
        let inside = a <= u && u < b;
        // Close the last non-empty span at the right end of the whole knot vector.
        let at_end = u == b && a < b && knots[i + 1..].iter().all(|k| k == b) && *b == knots[last];
        return if inside || at_end {
            T::one()
        } else {
            T::zero()
        };
    }
    let mut value = T::zero();
    let d1 = knots[i + p].clone() - knots[i].clone();
    if !d1.is_zero() {
        value =
            value + (u.clone() - knots[i].clone()) / d1 * cox_de_boor_unchecked(i, p - 1, knots, u);
    }
    let d2 = knots[i + p + 1].clone() - knots[i + 1].clone();
    if !d2.is_zero() {
        value = value
            + (knots[i + p + 1].clone() - u.clone()) / d2
                * cox_de_boor_unchecked(i + 1, p - 1, knots, u);
    }
    value
}

/// All basis functions `N_{0,p}(u), …, N_{n−1,p}(u)` (zeros outside the span), for a
/// degree-`p` spline with `n_control` control points.
///
/// # Errors
/// [`Error::ParameterOutOfRange`](crate::Error::ParameterOutOfRange) outside the domain
/// `[u_p, u_n]`; those of [`find_span`] and [`basis_functions`].
pub fn basis_all<T: Scalar>(p: usize, n_control: usize, knots: &[T], u: &T) -> Result<Vec<T>> {
    let s = find_span(p, n_control, knots, u)?;
    let local = basis_functions(p, knots, s, u)?;
    let mut all = crate::grid::try_filled("B-spline basis", n_control, T::zero())?;
    for (k, v) in local.into_iter().enumerate() {
        all[s - p + k] = v;
    }
    Ok(all)
}

/// The cost of the `p + 1` non-zero basis functions of degree `p` at one parameter of
/// `param_bits` bits ([`basis_functions`], the triangular scheme): `(p+1)²` operations, on
/// numbers of `p` levels of `(u − u_i)/(u_{i+p} − u_i)`
/// ([`polynomial_bits`]`(p, param_bits + 3 knot_bits, 0)`, `knot_bits` the size of the knots).
///
/// ```
/// assert_eq!(cagd::bspline::basis_cost(2, 4, 1), cagd::cost::Cost::new(9, 16));
/// ```
pub fn basis_cost(p: usize, param_bits: u128, knot_bits: u128) -> Cost {
    Cost::new(
        (p as u128 + 1).saturating_pow(2),
        polynomial_bits(p, span_bits(param_bits, knot_bits), 0),
    )
}

/// The cost of the point of a degree-`p` B-spline curve in `d` coordinates at one parameter:
/// the basis ([`basis_cost`]) and its combination with the `p + 1` control points, `2d(p+1)`
/// operations, on numbers of [`polynomial_bits`]`(p, param_bits + 3 knot_bits,
/// coefficient_bits)` bits. A NURBS curve is the B-spline curve of its homogeneous points:
/// `d + 1` coordinates, coefficients as large as its points and weights together.
///
/// ```
/// use cagd::cost::Cost;
/// // A cubic in the plane: 16 + 2·2·4 operations.
/// assert_eq!(cagd::bspline::curve_point_cost(3, 2, 0, 0, 0), Cost::new(32, 3));
/// ```
pub fn curve_point_cost(
    p: usize,
    d: usize,
    param_bits: u128,
    knot_bits: u128,
    coefficient_bits: u128,
) -> Cost {
    tensor_point_cost(&[(p, param_bits)], d, knot_bits, coefficient_bits)
}

/// The cost of the point of a tensor product of B-splines in `d` coordinates, one
/// `(degree p_k, param_bits_k)` per direction (a curve, a surface, a volume): the basis of
/// each direction ([`basis_cost`]) and their combination with the `Π (p_k + 1)` control
/// points, `2d Π (p_k + 1)` operations, on numbers as large as the bases' together and
/// `coefficient_bits`. One direction is [`curve_point_cost`], two
/// [`BSplineSurface::point_cost`](crate::bspline::BSplineSurface::point_cost).
///
/// ```
/// use cagd::cost::Cost;
/// use cagd::bspline::{basis_cost, tensor_point_cost};
/// // A tricubic volume in 3-D: three bases, then 2 · 3 · 64 products and sums.
/// let c = tensor_point_cost(&[(3, 0), (3, 0), (3, 0)], 3, 0, 0);
/// assert_eq!(c.ops(), 3 * basis_cost(3, 0, 0).ops() + 2 * 3 * 64);
/// ```
pub fn tensor_point_cost(
    directions: &[(usize, u128)],
    d: usize,
    knot_bits: u128,
    coefficient_bits: u128,
) -> Cost {
    let bases = directions
        .iter()
        .map(|&(p, bits)| basis_cost(p, bits, knot_bits));
    let terms = directions
        .iter()
        .fold(1u128, |acc, &(p, _)| acc.saturating_mul(p as u128 + 1));
    let (ops, bits) = bases.fold(
        ((2 * d as u128).saturating_mul(terms), coefficient_bits),
        |(ops, bits), b| (ops.saturating_add(b.ops()), bits.saturating_add(b.bits())),
    );
    Cost::new(ops, bits)
}

/// The bits of one level of the triangular scheme, `(u − u_i)/(u_{i+p} − u_i)`.
fn span_bits(param_bits: u128, knot_bits: u128) -> u128 {
    param_bits.saturating_add(knot_bits.saturating_mul(3))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangular_scheme_agrees_with_recursion() {
        let knots = [0.0, 0.0, 0.0, 0.3, 0.3, 0.7, 1.0, 1.0, 1.0];
        let n = knots.len() - 3;
        for k in 0..=20 {
            let u = k as f64 / 20.0;
            let all = basis_all(2, n, &knots, &u).unwrap();
            for (i, v) in all.iter().enumerate() {
                let r = cox_de_boor(i, 2, &knots, &u).unwrap();
                assert!((v - r).abs() < 1e-15, "u={u} i={i}: {v} vs {r}");
            }
            assert!((all.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn costs_of_the_basis_and_of_a_point() {
        let basis = basis_cost(3, 10, 2);
        assert_eq!(basis, Cost::new(16, 3 * 17));
        let point = curve_point_cost(3, 4, 10, 2, 5);
        assert_eq!(point, Cost::new(16 + 32, 3 * 17 + 5));
        // Degree 0: one basis function, one copy per coordinate.
        assert_eq!(curve_point_cost(0, 3, 9, 9, 1), Cost::new(1 + 6, 1));
    }

    #[test]
    fn span_search_skips_repeated_end_knots() {
        let knots = [0.0, 0.0, 1.0, 2.0, 2.0];
        assert_eq!(find_span(1, 3, &knots, &2.0).unwrap(), 2);
        assert_eq!(find_span(1, 3, &knots, &0.0).unwrap(), 1);
        assert!(find_span(1, 3, &knots, &f64::NAN).is_err());
    }
}

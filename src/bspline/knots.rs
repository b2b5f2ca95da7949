//! Knot vectors (the CAD notes §1.2: `Ξ = (ξ_1, …, ξ_{n+p+1})`, non-decreasing, values may repeat).

use crate::error::{check_finite, Error, Result};
use crate::scalar::Scalar;

/// A non-decreasing sequence of knots `u_0 ≤ u_1 ≤ … ≤ u_{m}`.
///
/// A knot repeated `k` times lowers the smoothness of a degree-`p` spline across it to
/// `C^{p−k}` (the CAD notes). An *open* or *clamped* knot vector repeats its first and last knots
/// `p + 1` times, so that the curve interpolates its end control points.
///
/// ```
/// use cagd::bspline::KnotVector;
/// let k = KnotVector::new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0])?;
/// assert_eq!(k.multiplicity(&0.0), 3);
/// assert!(KnotVector::new(vec![0.0, 1.0, 0.5]).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct KnotVector<T: Scalar = f64> {
    knots: Vec<T>,
}

impl<T: Scalar> KnotVector<T> {
    /// A knot vector from its values.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 knots, [`Error::NonFinite`] for a NaN or
    /// infinite knot, [`Error::DecreasingKnots`] if a knot is below its predecessor.
    pub fn new(knots: Vec<T>) -> Result<Self> {
        let what = "knot vector";
        if knots.len() < 2 {
            return Err(Error::TooFewPoints {
                what,
                min: 2,
                found: knots.len(),
            });
        }
        check_finite(what, knots.iter())?;
        if let Some(k) = knots.windows(2).position(|w| w[1] < w[0]) {
            return Err(Error::DecreasingKnots {
                what,
                index: k + 1,
                previous: knots[k].to_f64(),
                next: knots[k + 1].to_f64(),
            });
        }
        crate::error::check_spacing(what, &knots)?;
        Ok(KnotVector { knots })
    }

    /// The clamped (open) uniform knot vector on `[0, 1]` for `n_control` control points of
    /// degree `p`: `p + 1` zeros, the interior knots `j / (n_control − p)`, `p + 1` ones.
    /// With `n_control = p + 1` it is the knot vector of a Bézier curve.
    ///
    /// # Errors
    /// [`Error::TooFewControlPoints`] if `n_control < p + 1`.
    ///
    /// ```
    /// use cagd::bspline::KnotVector;
    /// let k: KnotVector = KnotVector::clamped_uniform(2, 4)?;
    /// assert_eq!(k.as_slice(), &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn clamped_uniform(p: usize, n_control: usize) -> Result<Self> {
        check_count("clamped knot vector", p, n_control)?;
        let spans = n_control - p;
        let mut knots = crate::grid::try_filled("clamped knot vector", p + 1, T::zero())?;
        knots
            .try_reserve_exact(n_control)
            .map_err(|_| too_many_knots("clamped knot vector", p, n_control))?;
        for j in 1..spans {
            knots.push(T::from_ratio(j as i64, spans as i64));
        }
        knots.extend(std::iter::repeat_n(T::one(), p + 1));
        Ok(KnotVector { knots })
    }

    /// The uniform (unclamped) knot vector `−p, −p + 1, …, n_control` for `n_control`
    /// control points of degree `p`: its domain `[u_p, u_{n}] = [0, n_control − p]` has one
    /// unit span per segment, as the uniform ("Coons") B-spline of the lecture notes where every
    /// segment runs over `u ∈ ⟨0, 1⟩`.
    ///
    /// # Errors
    /// [`Error::TooFewControlPoints`] if `n_control < p + 1`.
    pub fn uniform(p: usize, n_control: usize) -> Result<Self> {
        check_count("uniform knot vector", p, n_control)?;
        let mut knots = Vec::new();
        knots
            .try_reserve_exact(n_control + p + 1)
            .map_err(|_| too_many_knots("uniform knot vector", p, n_control))?;
        knots.extend((0..n_control + p + 1).map(|j| T::from_ratio(j as i64 - p as i64, 1)));
        Ok(KnotVector { knots })
    }

    /// Knots already known to be valid (sorted, finite, spaced as [`KnotVector::new`]
    /// requires).
    pub(crate) fn from_valid(knots: Vec<T>) -> Self {
        KnotVector { knots }
    }

    /// The knots.
    pub fn as_slice(&self) -> &[T] {
        &self.knots
    }

    /// Number of knots.
    pub fn len(&self) -> usize {
        self.knots.len()
    }

    /// Always `false` (a knot vector has at least two knots).
    pub fn is_empty(&self) -> bool {
        self.knots.is_empty()
    }

    /// How many times `u` occurs.
    pub fn multiplicity(&self, u: &T) -> usize {
        self.knots.iter().filter(|k| *k == u).count()
    }

    /// Whether the first and the last knot occur `p + 1` times each.
    pub fn is_clamped(&self, p: usize) -> bool {
        let m = self.knots.len();
        p.checked_add(1)
            .and_then(|q| q.checked_mul(2))
            .is_some_and(|needed| m >= needed)
            && self.knots[..=p].iter().all(|k| *k == self.knots[0])
            && self.knots[m - p - 1..]
                .iter()
                .all(|k| *k == self.knots[m - 1])
    }

    /// The domain `[u_p, u_n]` of a degree-`p` spline with `n` control points (`n + p + 1`
    /// knots).
    pub(crate) fn domain(&self, p: usize) -> (T, T) {
        let n = self.knots.len() - p - 1;
        (self.knots[p].clone(), self.knots[n].clone())
    }
}

/// `n_control ≥ p + 1`, and `n_control + p + 1` knots a size that fits in memory.
pub(crate) fn check_count(what: &'static str, p: usize, n_control: usize) -> Result<()> {
    if n_control <= p {
        return Err(Error::TooFewControlPoints {
            what,
            degree: p,
            min: p.saturating_add(1),
            found: n_control,
        });
    }
    knot_count(what, p, n_control).map(|_| ())
}

/// `n_control + p + 1`, the number of knots, or [`Error::TooLarge`] when so many knots could
/// not be held in memory (the sum overflows, or exceeds `isize::MAX` bytes).
pub(crate) fn knot_count(what: &'static str, p: usize, n_control: usize) -> Result<usize> {
    let max = isize::MAX as usize / std::mem::size_of::<f64>();
    match n_control.checked_add(p).and_then(|x| x.checked_add(1)) {
        Some(m) if m <= max => Ok(m),
        _ => Err(Error::TooLarge {
            what,
            requested: n_control as u128 + p as u128 + 1,
            limit: max as u128,
            which: crate::error::Limit::Elements,
        }),
    }
}

/// [`Error::TooLarge`] for `n_control + p + 1` knots that cannot be allocated.
fn too_many_knots(what: &'static str, p: usize, n_control: usize) -> Error {
    Error::TooLarge {
        what,
        requested: n_control as u128 + p as u128 + 1,
        limit: (isize::MAX as usize / std::mem::size_of::<f64>()) as u128,
        which: crate::error::Limit::Elements,
    }
}

/// [`check_knots`] for knots given as a slice.
pub(crate) fn check_knot_slice<T: Scalar>(
    what: &'static str,
    p: usize,
    n_control: usize,
    knots: &[T],
) -> Result<()> {
    check_count(what, p, n_control)?;
    if knots.len() != n_control + p + 1 {
        return Err(Error::KnotCount {
            what,
            expected: n_control + p + 1,
            found: knots.len(),
        });
    }
    let (a, b) = (&knots[p], &knots[n_control]);
    if a >= b || !a.is_finite_value() || !b.is_finite_value() {
        return Err(Error::EmptyInterval {
            what,
            a: a.to_f64(),
            b: b.to_f64(),
        });
    }
    Ok(())
}

/// Refuses a knot vector that is not clamped for degree `p` exactly: its first and its last
/// knot must occur `p + 1` times each, no fewer (the curve would not start and end at its end
/// control points) and no more (the control point at that end would have no non-empty span;
/// degree elevation and a shared knot vector cannot be built for it).
pub(crate) fn check_clamped<T: Scalar>(
    what: &'static str,
    p: usize,
    knots: &KnotVector<T>,
) -> Result<()> {
    let k = knots.as_slice();
    let (first, last) = (
        knots.multiplicity(&k[0]),
        knots.multiplicity(&k[k.len() - 1]),
    );
    let times = p.saturating_add(1);
    if knots.is_clamped(p) && first == times && last == times {
        return Ok(());
    }
    let message = if first > times || last > times {
        format!(
            "the first knot occurs {first} times and the last {last}, more than degree + 1 = {times}: a control point at the end has no non-empty span"
        )
    } else {
        format!(
            "the knot vector must be clamped (its first and last knots {times} times each; they occur {first} and {last} times)"
        )
    };
    Err(Error::InvalidArgument { what, message })
}

/// The knot vector of a degree-`p` spline with `n_control` control points: the right length
/// and a domain `[u_p, u_n]` that is not a single point.
pub(crate) fn check_knots<T: Scalar>(
    what: &'static str,
    p: usize,
    n_control: usize,
    knots: &KnotVector<T>,
) -> Result<()> {
    check_knot_slice(what, p, n_control, knots.as_slice())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_has_unit_spans() {
        let k: KnotVector = KnotVector::uniform(3, 5).unwrap();
        assert_eq!(k.as_slice(), &[-3., -2., -1., 0., 1., 2., 3., 4., 5.]);
        assert_eq!(k.domain(3), (0.0, 2.0));
        assert!(!k.is_clamped(3));
        let c: KnotVector = KnotVector::clamped_uniform(3, 4).unwrap();
        assert!(c.is_clamped(3));
    }
}

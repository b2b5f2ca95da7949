//! `linspace` (Octave built-in; the thesis samples every curve and patch with it).

use ndarray::Array2;

use cagd::error::{check_finite, Result};

/// `linspace(a, b, N)` as GNU Octave 7 computes it, as the `1 × N` row Octave returns.
///
/// **Octave:** `y = linspace(base, limit, n)`, a built-in; every appendix function samples at
/// `linspace(0,1,N)`. Octave does not compute `a + k(b−a)/(N−1)`: it fills the row from both
/// ends and sets the middle element of an odd-length row to `(a+b)/2`, so the points are not
/// always the ones a naive formula gives; the twin gives Octave's, bit for bit (pinned by the
/// reference case `linspace_samples`).
///
/// # Layout
/// Result `1 × N`; `N = 1` gives `[b]`, `N = 0` a `1 × 0` row.
///
/// # Native function
/// [`cagd::linspace::linspace`].
///
/// # Errors
/// [`Error::NonFinite`](cagd::Error::NonFinite) for a NaN or infinite end (Octave would
/// fill the row with NaN).
///
/// ```
/// use cagd_octave::compat::linspace;
/// let t = linspace(0.0, 1.0, 5)?;
/// assert_eq!(t.dim(), (1, 5));
/// assert_eq!(t.row(0).to_vec(), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
/// assert_eq!(linspace(0.0, 1.0, 0)?.dim(), (1, 0));
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn linspace(a: f64, b: f64, n: usize) -> Result<Array2<f64>> {
    check_finite("linspace: base and limit", [a, b].iter())?;
    let t = cagd::linspace::linspace(a, b, n);
    Ok(Array2::from_shape_vec((1, t.len()), t).expect("1 × N holds N values"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_non_finite_ends() {
        assert!(linspace(f64::NAN, 1.0, 3).is_err());
        assert!(linspace(0.0, f64::INFINITY, 3).is_err());
        assert_eq!(linspace(2.0, 3.0, 1).unwrap().row(0).to_vec(), vec![3.0]);
    }
}

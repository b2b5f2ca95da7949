//! Where to put interpolation nodes: uniformly, or at the Chebyshev–Lobatto points.

use crate::scalar::Scalar;

/// The `count` Chebyshev–Lobatto points on `[0, 1]`,
/// `t_k = (1 − cos(kπ/(count−1)))/2`, `k = 0..count` (the extrema of the Chebyshev polynomial
/// `T_{count−1}` mapped to `[0, 1]`; they include both ends, so a Gordon network keeps its
/// boundary curves). Computed as `(1 + sin(π(2k − M)/(2M)))/2`, `M = count − 1`, so the ends
/// are exactly 0 and 1 and the middle of an odd count exactly 1/2. `count = 1` gives `[0.5]`.
///
/// ```
/// let t = cagd::lagrange::chebyshev_nodes(5);
/// assert_eq!((t[0], t[2], t[4]), (0.0, 0.5, 1.0));
/// assert!((t[1] - (1.0 - 0.5f64.sqrt()) / 2.0).abs() < 1e-16);
/// ```
///
/// # Panics
/// When `count` numbers cannot be allocated; [`try_chebyshev_nodes`] refuses such a count
/// instead.
pub fn chebyshev_nodes(count: usize) -> Vec<f64> {
    match try_chebyshev_nodes(count) {
        Ok(v) => v,
        Err(e) => panic!("{e}"),
    }
}

/// [`chebyshev_nodes`], with [`Error::TooLarge`](crate::Error::TooLarge) for a count whose
/// nodes cannot be allocated (`usize::MAX`, say) instead of an abort.
///
/// ```
/// assert_eq!(cagd::lagrange::try_chebyshev_nodes(3)?, vec![0.0, 0.5, 1.0]);
/// assert!(cagd::lagrange::try_chebyshev_nodes(usize::MAX).is_err());
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn try_chebyshev_nodes(count: usize) -> crate::Result<Vec<f64>> {
    let mut out = crate::grid::try_filled("Chebyshev nodes", count, 0.5)?;
    if count > 1 {
        let m = (count - 1) as f64;
        for (k, t) in out.iter_mut().enumerate() {
            let s = (std::f64::consts::PI * (2.0 * k as f64 - m) / (2.0 * m)).sin();
            *t = (1.0 + s) / 2.0;
        }
    }
    Ok(out)
}

/// Where to put the nodes of an interpolation (or the curves of a Gordon network).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NodePlacement {
    /// `t_k = k/M`, `M = count − 1` (exact in rationals); what the thesis uses
    /// (`x = [0 0.5 1]`).
    Uniform,
    /// The Chebyshev–Lobatto points of [`chebyshev_nodes`] (as the nearest doubles).
    Chebyshev,
}

impl NodePlacement {
    /// `count` nodes on `[0, 1]`, increasing, with both ends included (for `count ≥ 2`).
    ///
    /// # Panics
    /// When `count` nodes cannot be allocated; [`try_nodes`](Self::try_nodes) refuses such a
    /// count instead.
    ///
    /// ```
    /// use cagd::lagrange::NodePlacement;
    /// assert_eq!(NodePlacement::Uniform.nodes::<f64>(3), vec![0.0, 0.5, 1.0]);
    /// assert_eq!(NodePlacement::Chebyshev.nodes::<f64>(3), vec![0.0, 0.5, 1.0]);
    /// ```
    pub fn nodes<T: Scalar>(self, count: usize) -> Vec<T> {
        self.try_nodes(count).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`nodes`](Self::nodes), with [`Error::TooLarge`](crate::Error::TooLarge) for a count
    /// whose nodes cannot be allocated instead of a panic.
    ///
    /// ```
    /// use cagd::lagrange::NodePlacement;
    /// assert!(NodePlacement::Uniform.try_nodes::<f64>(usize::MAX).is_err());
    /// assert_eq!(NodePlacement::Uniform.try_nodes::<f64>(2)?, vec![0.0, 1.0]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn try_nodes<T: Scalar>(self, count: usize) -> crate::Result<Vec<T>> {
        let mut out = crate::grid::try_filled("interpolation nodes", count, T::zero())?;
        match self {
            NodePlacement::Uniform => match count {
                0 => {}
                1 => out[0] = T::from_ratio(1, 2),
                _ => {
                    let last = i64::try_from(count - 1).unwrap_or(i64::MAX);
                    for (k, t) in out.iter_mut().enumerate() {
                        *t = T::from_ratio(k as i64, last);
                    }
                }
            },
            NodePlacement::Chebyshev => {
                for (t, c) in out.iter_mut().zip(try_chebyshev_nodes(count)?) {
                    *t = T::from_f64(c).unwrap_or_else(T::zero);
                }
            }
        }
        Ok(out)
    }
}

//! The Lagrange basis, the blending functions of Gordon surfaces (thesis §4.5, appendix D) and
//! of polynomial interpolation (the lecture notes, §3.11). The thesis defines (after (4.9))
//!
//! ```text
//! L_i^m(t) = Π_{j≠i} (t − t_j) / Π_{j≠i} (t_i − t_j),   i = 0..m,
//! ```
//!
//! This module is the crate's one owner of the Lagrange basis and its forms, one file each:
//!
//! | form | items | used by |
//! |---|---|---|
//! | product, in the thesis's order of operations (`product.rs`) | [`basis_product`] | the Octave twin `compat::lagrange`, [`LagrangePolynomial`](crate::interpolation::LagrangePolynomial) |
//! | barycentric (`barycentric.rs`) | [`Lagrange`], [`LagrangeInterpolant`] | [`GordonSurface`](crate::GordonSurface) |
//! | barycentric, nodes in any order (`any_order.rs`) | [`NodesInAnyOrder`] | the `lagrange` command |
//! | power, ascending (`power.rs`) | [`power_coefficients`] | the lecture notes' blending matrix |
//! | Bernstein (`bernstein_form.rs`) | [`bernstein_coefficients`] | [`GordonSurface::to_bezier`](crate::GordonSurface::to_bezier) |
//!
//! with one check of the nodes ([`check_nodes`], [`check_distinct_nodes`]: equal nodes are
//! [`Error::DuplicateNodes`] wherever they occur) and the placement of nodes
//! ([`NodePlacement`], `placement.rs`).
//!
//! The thesis evaluates the basis as the product (appendix D, `Lagrange.m`; as printed the
//! product starts at zero, so the function always returns 0 — the fixed Octave reference starts
//! it at one). The barycentric form evaluates all `m+1` basis functions in `O(m)` operations
//! after an `O(m²)` set-up and is numerically stable (Berrut–Trefethen). Everything is generic
//! over the [`Scalar`], so every form is exact in rationals.
//!
//! Interpolation at equispaced nodes is badly conditioned for many nodes (the Lebesgue
//! constant grows like `2^m / (e m log m)`); [`chebyshev_nodes`] places nodes at the
//! Chebyshev–Lobatto points, where it grows like `(2/π) log m`. [`Lagrange::lebesgue_constant`]
//! estimates it.

use crate::error::{check_finite, Error, Result};
use crate::scalar::Scalar;

mod any_order;
mod barycentric;
mod bernstein_form;
mod placement;
mod power;
mod product;

pub use any_order::NodesInAnyOrder;
pub use barycentric::{Lagrange, LagrangeInterpolant, LebesgueEstimate};
pub use bernstein_form::bernstein_coefficients;
pub use placement::{chebyshev_nodes, try_chebyshev_nodes, NodePlacement};
pub use power::power_coefficients;
pub use product::basis_product;
pub(crate) use product::basis_product_unchecked;

/// Checks interpolation nodes: at least `min`, finite, strictly increasing (what the
/// barycentric basis and Gordon surfaces take).
///
/// # Errors
/// [`Error::TooFewPoints`], [`Error::NonFinite`], [`Error::DuplicateNodes`] (two equal
/// neighbours), [`Error::UnsortedNodes`] (a decrease) — whichever comes first, left to right.
///
/// ```
/// use cagd::lagrange::check_nodes;
/// assert!(check_nodes("x", &[0.0, 0.5, 1.0], 2).is_ok());
/// assert!(matches!(check_nodes("x", &[0.0, 0.5, 0.5], 2), Err(cagd::Error::DuplicateNodes { first: 1, second: 2, .. })));
/// assert!(matches!(check_nodes("x", &[0.5, 0.0], 2), Err(cagd::Error::UnsortedNodes { index: 0, .. })));
/// ```
pub fn check_nodes<T: Scalar>(what: &'static str, nodes: &[T], min: usize) -> Result<()> {
    check(what, nodes, min, true)
}

/// Checks interpolation nodes that may come in any order (the lecture notes interpolate at
/// parameters such as `(0, ½, ¼, 1)`; the thesis's `Lagrange` takes `x` as given): at least
/// `min`, finite, pairwise distinct.
///
/// # Errors
/// [`Error::TooFewPoints`], [`Error::NonFinite`], and [`Error::DuplicateNodes`] naming the
/// first node that repeats an earlier one (`second`) and that earlier one (`first`).
///
/// ```
/// use cagd::lagrange::check_distinct_nodes;
/// assert!(check_distinct_nodes("x", &[0.0, 0.5, 0.25, 1.0], 1).is_ok());
/// let err = check_distinct_nodes("x", &[0.0, 0.5, 0.0], 1).unwrap_err();
/// assert!(matches!(err, cagd::Error::DuplicateNodes { first: 0, second: 2, .. }));
/// ```
pub fn check_distinct_nodes<T: Scalar>(what: &'static str, nodes: &[T], min: usize) -> Result<()> {
    check(what, nodes, min, false)
}

/// The one node check: count, finiteness, then equal nodes (as [`Error::DuplicateNodes`]) and,
/// if `increasing`, order.
fn check<T: Scalar>(what: &'static str, nodes: &[T], min: usize, increasing: bool) -> Result<()> {
    if nodes.len() < min {
        return Err(Error::TooFewPoints {
            what,
            min,
            found: nodes.len(),
        });
    }
    check_finite(what, nodes.iter())?;
    let duplicate = |first: usize, second: usize| Error::DuplicateNodes {
        what,
        first,
        second,
        value: nodes[first].to_f64(),
    };
    if increasing {
        for (k, pair) in nodes.windows(2).enumerate() {
            if pair[0] == pair[1] {
                return Err(duplicate(k, k + 1));
            }
            if pair[0] > pair[1] {
                return Err(Error::UnsortedNodes {
                    what,
                    index: k,
                    value: pair[0].to_f64(),
                    next: pair[1].to_f64(),
                });
            }
        }
        return Ok(());
    }
    for (second, x) in nodes.iter().enumerate() {
        if let Some(first) = nodes[..second].iter().position(|y| y == x) {
            return Err(duplicate(first, second));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_checks_report_equal_nodes_alike() {
        let e = check_nodes("x", &[0.0, 0.2, 0.2], 1).unwrap_err();
        let f = check_distinct_nodes("x", &[0.0, 0.2, 0.2], 1).unwrap_err();
        assert_eq!(e, f);
        assert!(matches!(
            e,
            Error::DuplicateNodes {
                first: 1,
                second: 2,
                ..
            }
        ));
        // Any order: the first repeat, whichever node it repeats.
        assert!(matches!(
            check_distinct_nodes("x", &[1.0, 0.5, 0.25, 0.5, 1.0], 1),
            Err(Error::DuplicateNodes {
                first: 1,
                second: 3,
                value,
                ..
            }) if value == 0.5
        ));
    }

    #[test]
    fn counts_and_finiteness() {
        assert!(matches!(
            check_distinct_nodes::<f64>("x", &[], 1),
            Err(Error::TooFewPoints {
                min: 1,
                found: 0,
                ..
            })
        ));
        assert!(matches!(
            check_nodes("x", &[0.0], 2),
            Err(Error::TooFewPoints {
                min: 2,
                found: 1,
                ..
            })
        ));
        assert!(matches!(
            check_distinct_nodes("x", &[0.0, f64::NAN], 1),
            Err(Error::NonFinite { .. })
        ));
        assert!(check_distinct_nodes("x", &[1.0, 0.0], 1).is_ok());
        assert!(matches!(
            check_nodes("x", &[1.0, 0.0], 1),
            Err(Error::UnsortedNodes { index: 0, .. })
        ));
    }
}

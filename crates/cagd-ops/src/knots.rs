//! The rules of B-spline degrees and knot vectors, written once for every request with knots
//! (B-spline and NURBS curves and surfaces, knot insertion, the basis functions, and the
//! page's views), so that the same wrong knots get the same words everywhere.
//!
//! One convention, octave-nurbs' and the core's: a spline of degree `p` (the lecture notes'
//! order `k = p + 1`) with `n` control points has `n + p + 1` non-decreasing knots and is
//! defined between its knots number `p + 1` and `n + 1`; without knots it gets the clamped
//! uniform vector on `[0, 1]`. The words number knots from 1, as the CAD notes do
//! (`Ξ = (ξ_1, …, ξ_{n+p+1})`, §1.2) and as Octave indexes: `u_1 ≤ … ≤ u_(n+p+1)`, the domain
//! `[u_(p+1), u_(n+1)]`, "knot 3" the third (in the code the slice `knots[0..n+p+1]`, the
//! domain `[knots[p], knots[n]]`). Every check names the role at fault
//! with the library's error underneath, in this order: the knots themselves (finite,
//! non-decreasing), enough control points for the degree, the number of knots, a domain that
//! is not a single point.

use cagd::Scalar;

use crate::error::{lib, Kind, OpError, Result};
use crate::{Context, Params, Role};

/// The degree of a B-spline or NURBS request when none is given: cubic.
pub const DEFAULT_DEGREE: usize = 3;

/// The form of a knot vector, in words.
pub const KNOTS_FORM: &str =
    "n + p + 1 non-decreasing knots for n control points of degree p (n ≥ p + 1), with u_(p+1) < u_(n+1)";

/// The form of a knot vector whose basis functions are asked for (no control points).
pub const BASIS_KNOTS_FORM: &str =
    "n + p + 1 non-decreasing knots for n ≥ 1 basis functions of degree p, not all equal";

/// The form of parameters of a spline, which is not defined outside its domain.
pub const DOMAIN_FORM: &str = "parameters in the domain [u_(p+1), u_(n+1)] of the knot vector";

/// A degree as given: the degree `p`, the lecture notes' order `k = p + 1`, or neither
/// ([`DEFAULT_DEGREE`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Degree {
    /// [`DEFAULT_DEGREE`].
    #[default]
    Default,
    /// The degree `p`.
    Degree(usize),
    /// The order `k = p + 1`.
    Order(usize),
}

impl Degree {
    /// The degree from a degree and an order, at most one of them given.
    ///
    /// # Errors
    /// [`Kind::Usage`] about [`Role::Order`] when both are given.
    ///
    /// ```
    /// use cagd_ops::knots::Degree;
    /// assert_eq!(Degree::either(None, Some(4))?, Degree::Order(4));
    /// assert!(Degree::either(Some(3), Some(4)).is_err());
    /// # Ok::<(), cagd_ops::OpError>(())
    /// ```
    pub fn either(degree: Option<usize>, order: Option<usize>) -> Result<Self> {
        match (degree, order) {
            (Some(_), Some(_)) => Err(OpError::new(
                Role::Order,
                Kind::Usage,
                "given together with the degree",
                "the degree p or the order k = p + 1, not both",
            )),
            (Some(p), None) => Ok(Degree::Degree(p)),
            (None, Some(k)) => Ok(Degree::Order(k)),
            (None, None) => Ok(Degree::Default),
        }
    }

    /// The degree `p`, within [`cagd::Limits::max_degree`].
    ///
    /// # Errors
    /// [`Kind::Shape`] about [`Role::Order`] for the order 0; [`Kind::Limit`].
    ///
    /// ```
    /// use cagd_ops::{knots::Degree, Context};
    /// let cx = Context::new(cagd::Limits::default());
    /// assert_eq!(Degree::Order(4).resolve(&cx)?, 3);
    /// assert_eq!(Degree::Default.resolve(&cx)?, 3);
    /// assert_eq!(Degree::Order(0).resolve(&cx).unwrap_err().to_string(),
    ///     "order k = 0; expected an order k ≥ 1 (the degree p = k − 1)");
    /// # Ok::<(), cagd_ops::OpError>(())
    /// ```
    pub fn resolve(self, cx: &Context) -> Result<usize> {
        let (p, role) = match self {
            Degree::Default => (DEFAULT_DEGREE, Role::Degree),
            Degree::Degree(p) => (p, Role::Degree),
            Degree::Order(0) => {
                return Err(OpError::new(
                    Role::Order,
                    Kind::Shape,
                    "order k = 0",
                    "an order k ≥ 1 (the degree p = k − 1)",
                ))
            }
            Degree::Order(k) => (k - 1, Role::Order),
        };
        cx.check_degree(role, p)?;
        Ok(p)
    }
}

/// The roles a knot rule names, and the words for what it counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KnotRoles {
    /// The knot vector.
    pub knots: Role,
    /// The control points the knots are counted against.
    pub control: Role,
    /// The knot vector, in words (`knot vector`, `knot vector along u`).
    pub knots_what: &'static str,
    /// The control points, in words.
    pub control_what: &'static str,
}

/// The knots of a curve.
pub const CURVE: KnotRoles = KnotRoles {
    knots: Role::Knots,
    control: Role::Control,
    knots_what: "knot vector",
    control_what: "control points",
};

/// The knots of a surface along `u` (the rows of its net).
pub const SURFACE_U: KnotRoles = KnotRoles {
    knots: Role::UKnots,
    control: Role::Net,
    knots_what: "knot vector along u",
    control_what: "control points along u",
};

/// The knots of a surface along `v` (the columns of its net).
pub const SURFACE_V: KnotRoles = KnotRoles {
    knots: Role::VKnots,
    control: Role::Net,
    knots_what: "knot vector along v",
    control_what: "control points along v",
};

/// The knots of a spline of degree `p` with `n` control points: `given` (checked by
/// [`check_knots`]), or the clamped uniform vector on `[0, 1]`.
///
/// # Errors
/// As [`check_knots`]; [`Kind::Limit`] for a clamped vector too large to hold.
///
/// ```
/// use cagd_ops::knots::{knots_or_clamped, CURVE};
/// assert_eq!(knots_or_clamped::<f64>(None, 2, 4, CURVE)?, [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
/// let e = knots_or_clamped(Some(&[0.0, 0.0, 1.0, 1.0][..]), 2, 4, CURVE).unwrap_err();
/// assert_eq!(e.to_string(), "knot vector: expected 7 knots (control points + degree + 1), got 4; \
///     expected n + p + 1 non-decreasing knots for n control points of degree p (n ≥ p + 1), with u_(p+1) < u_(n+1)");
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
pub fn knots_or_clamped<T: Scalar>(
    given: Option<&[T]>,
    p: usize,
    n: usize,
    roles: KnotRoles,
) -> Result<Vec<T>> {
    if let Some(knots) = given {
        check_knots(knots, p, n, roles)?;
        return Ok(knots.to_vec());
    }
    enough_control_points(p, n, roles)?;
    cagd::KnotVector::<T>::clamped_uniform(p, n)
        .map(|k| k.as_slice().to_vec())
        .map_err(lib(roles.control, KNOTS_FORM))
}

/// Checks the knots of a spline of degree `p` with `n` control points, in the order of the
/// [module documentation](self).
///
/// # Errors
/// [`Kind::NonFinite`], [`Kind::Knots`] (decreasing, a wrong count) and [`Kind::Value`] (a
/// domain of one point) about the knots; [`Kind::Shape`] about the control points for fewer
/// than `p + 1` — each with the library's error underneath.
pub fn check_knots<T: Scalar>(knots: &[T], p: usize, n: usize, roles: KnotRoles) -> Result<()> {
    let at_fault = |e| OpError::library(roles.knots, e, KNOTS_FORM);
    crate::check::finite(roles.knots, knots)?;
    in_order(knots, roles.knots_what).map_err(at_fault)?;
    enough_control_points(p, n, roles)?;
    let expected = n.saturating_add(p).saturating_add(1);
    if knots.len() != expected {
        return Err(at_fault(cagd::Error::KnotCount {
            what: roles.knots_what,
            expected,
            found: knots.len(),
        }));
    }
    let (a, b) = domain(knots, p);
    if a >= b {
        return Err(at_fault(cagd::Error::EmptyInterval {
            what: "knot domain [u_(p+1), u_(n+1)]",
            a: a.to_f64(),
            b: b.to_f64(),
        }));
    }
    Ok(())
}

/// Checks a knot vector whose basis functions of degree `p` are asked for, and answers how
/// many there are (`n = m − p` for `m + 1` knots).
///
/// # Errors
/// [`Kind::NonFinite`], [`Kind::Knots`] for decreasing knots (the library's error
/// underneath); [`Kind::Shape`] for fewer than `p + 2` knots or all knots equal.
///
/// ```
/// use cagd_ops::knots::check_basis_knots;
/// assert_eq!(check_basis_knots(&[0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0], 2)?, 5);
/// assert!(check_basis_knots(&[0.0, 1.0], 3).is_err());
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
pub fn check_basis_knots<T: Scalar>(knots: &[T], p: usize) -> Result<usize> {
    crate::check::finite(Role::Knots, knots)?;
    in_order(knots, "knot vector").map_err(lib(Role::Knots, BASIS_KNOTS_FORM))?;
    let shape = |problem: String| OpError::new(Role::Knots, Kind::Shape, problem, BASIS_KNOTS_FORM);
    if knots.len() < p.saturating_add(2) {
        return Err(shape(format!("{} knot(s) for degree {p}", knots.len())));
    }
    if knots[0] >= knots[knots.len() - 1] {
        return Err(shape(format!(
            "all knots equal {}",
            crate::number_text(&knots[0])
        )));
    }
    Ok(knots.len() - p - 1)
}

/// The domain `[u_(p+1), u_(n+1)]` (in the words' numbering from 1; `knots[p]` and
/// `knots[n]` as a slice) of a spline of degree `p` on `knots` (checked).
pub fn domain<T: Scalar>(knots: &[T], p: usize) -> (T, T) {
    (knots[p].clone(), knots[knots.len() - 1 - p].clone())
}

/// The parameters of a construction that is not defined outside `[lo, hi]` (a spline's
/// domain, the knot range of the basis): given values, each within, or samples of `[lo, hi]`.
///
/// # Errors
/// As [`Params::resolve`]; [`Kind::Domain`] (the library's `ParameterOutOfRange`
/// underneath, about `what`) for a value outside, with `expected` as the form.
pub fn params_within<T: Scalar>(
    params: &Params<T>,
    role: Role,
    (lo, hi): (&T, &T),
    (what, expected): (&'static str, &str),
    cx: &mut Context,
) -> Result<Vec<T>> {
    let values = params.resolve(role, (lo, hi), "", cx)?;
    if let Some(x) = values.iter().find(|x| *x < lo || *x > hi) {
        return Err(OpError::library(
            role,
            cagd::Error::ParameterOutOfRange {
                what,
                value: x.to_f64(),
                min: lo.to_f64(),
                max: hi.to_f64(),
            },
            expected,
        ));
    }
    Ok(values)
}

/// At least `p + 1` control points.
fn enough_control_points(p: usize, n: usize, roles: KnotRoles) -> Result<()> {
    if n > p {
        return Ok(());
    }
    Err(OpError::library(
        roles.control,
        cagd::Error::TooFewControlPoints {
            what: roles.control_what,
            degree: p,
            min: p.saturating_add(1),
            found: n,
        },
        KNOTS_FORM,
    ))
}

/// Finite, non-decreasing, and with differences a double can hold and divide by
/// ([`cagd::error::check_spacing`]).
fn in_order<T: Scalar>(knots: &[T], what: &'static str) -> cagd::Result<()> {
    if let Some(index) = knots.iter().position(|k| !k.is_finite_value()) {
        return Err(cagd::Error::NonFinite {
            what,
            index,
            value: knots[index].to_f64(),
        });
    }
    match knots.windows(2).position(|w| w[1] < w[0]) {
        Some(k) => Err(cagd::Error::DecreasingKnots {
            what,
            index: k + 1,
            previous: knots[k].to_f64(),
            next: knots[k + 1].to_f64(),
        }),
        // Knots so close (5·10⁻³²⁴ apart) or so far that their differences overflow.
        None => cagd::error::check_spacing(what, knots),
    }
}

//! The parameters a request is evaluated at: given values, `N` samples of the domain (the
//! thesis's `linspace(0,1,N)` on a curve over `[0, 1]`), or the default samples.
//!
//! One convention for every construction: samples always cover the construction's own
//! domain (`[a, b]` of a Bézier curve on an interval, the knot domain of a B-spline, the
//! nodes of a Lagrange interpolant), and given values outside it get a warning saying what
//! happens there.

use cagd::Scalar;

use crate::error::{lib, Kind, OpError, Result};
use crate::{number_text, Context, Role};

/// Samples taken when no parameters are given: 11, `0:0.1:1` on `[0, 1]`.
pub const DEFAULT_SAMPLES: usize = 11;

/// The form of a parameter list, in words.
pub const PARAMS_FORM: &str = "a number, a list such as [0 0.25 0.5] or a range such as 0:0.1:1";

/// Which parameters.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Params<T> {
    /// These values.
    Given(Vec<T>),
    /// `N` equally spaced samples of the domain, ends included (`N ≥ 2`).
    Samples(usize),
    /// [`DEFAULT_SAMPLES`] samples of the domain.
    #[default]
    Default,
}

impl<T: Scalar> Params<T> {
    /// Whether the values are given (not sampled).
    pub fn is_given(&self) -> bool {
        matches!(self, Params::Given(_))
    }

    /// The values on the domain `[a, b]`: given values as they are (at least one, finite,
    /// at most [`cagd::Limits::max_samples`]; those outside `[a, b]` get a warning ending in
    /// `consequence`), or samples of `[a, b]`.
    ///
    /// # Errors
    /// [`Kind::Shape`] for no values or fewer than 2 samples, [`Kind::NonFinite`],
    /// [`Kind::Limit`].
    ///
    /// ```
    /// use cagd_ops::{Context, Params, Role};
    /// let mut cx = Context::new(cagd::Limits::default());
    /// let t = Params::Samples(3).resolve(Role::T, (&1.0, &2.0), "", &mut cx)?;
    /// assert_eq!(t, vec![1.0, 1.5, 2.0]);
    /// Params::Given(vec![3.0]).resolve(Role::T, (&1.0, &2.0), "the curve is extrapolated there", &mut cx)?;
    /// assert_eq!(cx.take_warnings()[0].message, "t = 3 lies outside [1, 2]; the curve is extrapolated there");
    /// # Ok::<(), cagd_ops::OpError>(())
    /// ```
    pub fn resolve(
        &self,
        role: Role,
        (a, b): (&T, &T),
        consequence: &str,
        cx: &mut Context,
    ) -> Result<Vec<T>> {
        match self {
            Params::Given(values) => {
                check_given(role, values, cx)?;
                outside(role, values, (a, b), consequence, cx);
                Ok(values.clone())
            }
            Params::Samples(n) => samples(*n, (a, b), cx),
            Params::Default => samples(DEFAULT_SAMPLES, (a, b), cx),
        }
    }
}

impl<T: Scalar> Params<T> {
    /// The values for a construction defined at every parameter (a user's expression):
    /// given values as they are, with no warning, or samples of `[a, b]`.
    ///
    /// # Errors
    /// As [`resolve`](Self::resolve).
    ///
    /// ```
    /// use cagd_ops::{Context, Params, Role};
    /// let mut cx = Context::new(cagd::Limits::default());
    /// assert_eq!(Params::Given(vec![3.0]).anywhere(Role::T, (&0.0, &1.0), &mut cx)?, vec![3.0]);
    /// assert!(cx.take_warnings().is_empty());
    /// # Ok::<(), cagd_ops::OpError>(())
    /// ```
    pub fn anywhere(&self, role: Role, (a, b): (&T, &T), cx: &mut Context) -> Result<Vec<T>> {
        match self {
            Params::Given(values) => {
                check_given(role, values, cx)?;
                Ok(values.clone())
            }
            Params::Samples(n) => samples(*n, (a, b), cx),
            Params::Default => samples(DEFAULT_SAMPLES, (a, b), cx),
        }
    }
}

/// Given parameter values: at least one, finite, within the sample limit.
pub fn check_given<T: Scalar>(role: Role, values: &[T], cx: &Context) -> Result<()> {
    if values.is_empty() {
        return Err(OpError::new(role, Kind::Shape, "no values", PARAMS_FORM));
    }
    crate::check::finite(role, values)?;
    cx.limits
        .check_samples("parameter values", values.len())
        .map_err(lib(role, PARAMS_FORM))
}

/// `n` samples of `[a, b]` (`n ≥ 2`, at most [`cagd::Limits::max_samples`]).
pub fn samples<T: Scalar>(n: usize, (a, b): (&T, &T), cx: &Context) -> Result<Vec<T>> {
    let max = cx.limits.max_samples;
    let expected = format!("an integer N with 2 ≤ N ≤ {max} (N equally spaced samples)");
    if n < 2 {
        return Err(OpError::new(
            Role::Samples,
            Kind::Shape,
            format!("N = {n} is too small"),
            expected,
        ));
    }
    cx.limits
        .check_samples("samples N", n)
        .map_err(lib(Role::Samples, &expected))?;
    cagd::linspace::linspace_in(a, b, n).map_err(lib(Role::Samples, &expected))
}

/// Warns when some of `values` lie outside `[lo, hi]`, the domain of the construction;
/// `consequence` says what happens there ("the curve is extrapolated there").
pub fn outside<T: Scalar>(
    role: Role,
    values: &[T],
    (lo, hi): (&T, &T),
    consequence: &str,
    cx: &mut Context,
) {
    let out: Vec<&T> = values.iter().filter(|x| *x < lo || *x > hi).collect();
    let Some(first) = out.first() else {
        return;
    };
    let name = role.key();
    let what = if out.len() == 1 {
        format!("{name} = {} lies", number_text(*first))
    } else {
        format!(
            "{} values lie (the first {name} = {})",
            out.len(),
            number_text(*first)
        )
    };
    cx.warn(
        role,
        format!(
            "{what} outside [{}, {}]; {consequence}",
            number_text(lo),
            number_text(hi)
        ),
    );
}

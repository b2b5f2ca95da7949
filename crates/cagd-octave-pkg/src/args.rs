//! One call of a package function: its arguments, checked up front, and the limits in force.
//!
//! Every reader refuses a wrong class (`cagd:class`), an empty array where data is needed
//! (`cagd:empty`), a wrong size (`cagd:shape`), NaN and ±Inf (`cagd:nonfinite`) and counts
//! that are not non-negative integers (`cagd:value`) before anything is computed or allocated.

use cagd::cost::Cost;
use cagd::limits::Limits;
use nalgebra::DMatrix;
use ndarray::{ArrayView2, ArrayViewD, IxDyn, ShapeBuilder};

use crate::error::{Kind, PkgError, Result};
use crate::value::{size_str, Real, Value};

/// Largest count accepted before the limits are even asked (`2^53`: every integer below is a
/// double).
const MAX_EXACT_INTEGER: f64 = 9_007_199_254_740_992.0;

/// The call of one package function.
pub struct Call<'c, 'a> {
    /// The Octave name of the function (for messages).
    pub name: &'static str,
    /// The arguments.
    pub args: &'c [Value<'a>],
    /// The number of outputs asked for (at least 1: `ans`).
    pub nargout: usize,
    /// The resource limits of the session (`cagd_limits`).
    pub limits: Limits,
    /// Whether the user asked to stop (Octave's Ctrl-C), asked every few milliseconds of work.
    pub interrupt: &'c (dyn Fn() -> bool + Sync),
}

impl std::fmt::Debug for Call<'_, '_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Call")
            .field("name", &self.name)
            .field("args", &self.args)
            .field("nargout", &self.nargout)
            .field("limits", &self.limits)
            .finish_non_exhaustive()
    }
}

/// The interrupt of a call nobody can interrupt.
fn never() -> bool {
    false
}

/// The form of a real double array, for messages.
pub const REAL_FORM: &str = "a real double array";

impl<'c, 'a> Call<'c, 'a> {
    /// A call of `name` with `args`, `nargout` outputs (0 counts as 1) and `limits`.
    pub fn new(name: &'static str, args: &'c [Value<'a>], nargout: usize, limits: Limits) -> Self {
        Call {
            name,
            args,
            nargout: nargout.max(1),
            limits,
            interrupt: &never,
        }
    }

    /// The same call, asking `interrupted` between chunks of its work: when it answers `true`
    /// the function stops with [`Kind::Interrupted`].
    pub fn with_interrupt(self, interrupted: &'c (dyn Fn() -> bool + Sync)) -> Self {
        Call {
            interrupt: interrupted,
            ..self
        }
    }

    /// The operation layer's context of this call: its limits and its interrupt.
    pub fn context(&self) -> cagd_ops::Context<'c> {
        cagd_ops::Context::new(self.limits).with_interrupt(self.interrupt)
    }

    /// Stops with [`Kind::Interrupted`] if the user asked to.
    ///
    /// # Errors
    /// [`Kind::Interrupted`].
    pub fn check_interrupt(&self) -> Result<()> {
        if (self.interrupt)() {
            return Err(PkgError::new(Kind::Interrupted, "interrupted"));
        }
        Ok(())
    }

    /// Fills `out` from `items` in chunks of work between which the user may interrupt:
    /// `fill(chunk, buffer)` for consecutive chunks of `items` and the matching buffers of `per`
    /// outputs per item, each chunk about [`cagd_ops::ops::CHECK_WORK`] operations of
    /// `per_item` each (at once for a few items, and once with nothing for no items, so that
    /// `fill` checks what it checks).
    ///
    /// # Errors
    /// `fill`'s; [`Kind::Interrupted`].
    pub fn in_chunks<I, O>(
        &self,
        (items, per_item): (&[I], Cost),
        (out, per): (&mut [O], usize),
        mut fill: impl FnMut(&[I], &mut [O]) -> Result<()>,
    ) -> Result<()> {
        if items.len() <= cagd_octave::octave_nurbs::FEW_ITEMS {
            return fill(items, out);
        }
        let chunk = cagd_ops::ops::chunk_points(per_item.weigh(false));
        let size = chunk.saturating_mul(per.max(1));
        for (k, (part, buffer)) in items.chunks(chunk).zip(out.chunks_mut(size)).enumerate() {
            if k > 0 {
                self.check_interrupt()?;
            }
            fill(part, buffer)?;
        }
        Ok(())
    }

    /// Checks the number of arguments: `min..=max`; `usage` names them.
    ///
    /// # Errors
    /// [`Kind::Nargin`].
    pub fn nargin(&self, min: usize, max: usize, usage: &str) -> Result<()> {
        let n = self.args.len();
        if (min..=max).contains(&n) {
            return Ok(());
        }
        let expected = if min == max {
            format!("{min}")
        } else {
            format!("{min} to {max}")
        };
        Err(PkgError::new(
            Kind::Nargin,
            format!(
                "called with {n} argument(s); expected {expected}: {usage} (see help {})",
                self.name
            ),
        ))
    }

    /// Checks the number of outputs asked for: at most `max`.
    ///
    /// # Errors
    /// [`Kind::Nargin`].
    pub fn nargout_max(&self, max: usize) -> Result<()> {
        if self.nargout <= max {
            return Ok(());
        }
        Err(PkgError::new(
            Kind::Nargin,
            format!("called with {} outputs; it has at most {max}", self.nargout),
        ))
    }

    /// Argument `i` (from 0), which [`nargin`](Self::nargin) has checked exists.
    pub fn arg(&self, i: usize) -> &'c Value<'a> {
        &self.args[i]
    }

    /// Whether argument `i` was given.
    pub fn has(&self, i: usize) -> bool {
        i < self.args.len()
    }

    /// Argument `i` as a real double array.
    ///
    /// # Errors
    /// [`Kind::Class`] for any other class, naming it.
    pub fn real(&self, i: usize, what: &str, form: &str) -> Result<Real<'a>> {
        real_of(self.arg(i), what, form)
    }

    /// Argument `i` as a real double array with at least one element.
    ///
    /// # Errors
    /// As [`real`](Self::real); [`Kind::Empty`].
    pub fn nonempty(&self, i: usize, what: &str, form: &str) -> Result<Real<'a>> {
        nonempty_of(self.arg(i), what, form)
    }

    /// Argument `i` as a matrix view (2-D, any size, maybe empty), without a copy.
    ///
    /// # Errors
    /// As [`real`](Self::real); [`Kind::Shape`] for more than two dimensions.
    pub fn view2(&self, i: usize, what: &str, form: &str) -> Result<ArrayView2<'a, f64>> {
        view2_of(self.real(i, what, form)?, what, form)
    }

    /// Argument `i` as an n-d view of Octave's size, without a copy.
    ///
    /// # Errors
    /// As [`real`](Self::real).
    pub fn view_dyn(&self, i: usize, what: &str, form: &str) -> Result<ArrayViewD<'a, f64>> {
        let r = self.real(i, what, form)?;
        Ok(ArrayViewD::from_shape(IxDyn(r.dims).f(), r.data)
            .expect("an Octave array holds prod(size) elements"))
    }

    /// Argument `i` as a matrix of finite values with at least one element.
    ///
    /// # Errors
    /// As [`view2`](Self::view2); [`Kind::Empty`], [`Kind::NonFinite`].
    pub fn matrix(&self, i: usize, what: &'static str, form: &str) -> Result<DMatrix<f64>> {
        matrix_of(self.arg(i), what, form)
    }

    /// The same call without its last argument (an option such as `"exact"`).
    pub fn without_last(&self) -> Call<'c, 'a> {
        Call {
            name: self.name,
            args: &self.args[..self.args.len().saturating_sub(1)],
            nargout: self.nargout,
            limits: self.limits,
            interrupt: self.interrupt,
        }
    }

    /// Argument `i` as a finite real scalar.
    ///
    /// # Errors
    /// [`Kind::Class`], [`Kind::Shape`] unless 1 × 1, [`Kind::NonFinite`].
    pub fn scalar(&self, i: usize, what: &'static str) -> Result<f64> {
        scalar_of(self.arg(i), what)
    }

    /// Argument `i` as a count: a non-negative integer scalar.
    ///
    /// # Errors
    /// As [`scalar`](Self::scalar); [`Kind::Value`] for a negative or fractional value.
    pub fn count(&self, i: usize, what: &'static str) -> Result<usize> {
        count_of(self.arg(i), what)
    }

    /// Argument `i` as finite parameters: any real array, read column-major (maybe empty).
    ///
    /// # Errors
    /// [`Kind::Class`], [`Kind::NonFinite`].
    pub fn params(&self, i: usize, what: &'static str) -> Result<&'a [f64]> {
        params_of(self.arg(i), what)
    }

    /// Argument `i` as text (a char row).
    ///
    /// # Errors
    /// [`Kind::Class`].
    pub fn text(&self, i: usize, what: &str, form: &str) -> Result<String> {
        text_of(self.arg(i), what, form)
    }

    /// Whether the last argument is the option `word` (case-insensitive), e.g. `"exact"`.
    pub fn last_is_option(&self, word: &str) -> bool {
        self.args
            .last()
            .and_then(Value::text)
            .is_some_and(|t| t.eq_ignore_ascii_case(word))
    }

    /// `count` parameter values along one axis within the limits.
    ///
    /// # Errors
    /// [`Kind::Limit`].
    pub fn check_samples(&self, what: &'static str, count: usize) -> Result<()> {
        Ok(self.limits.check_samples(what, count)?)
    }

    /// A grid of `nu × nv` points within the limits.
    ///
    /// # Errors
    /// [`Kind::Limit`].
    pub fn check_grid(&self, what: &'static str, nu: usize, nv: usize) -> Result<()> {
        self.check_samples(what, nu)?;
        self.check_samples(what, nv)?;
        Ok(self.limits.check_grid(what, nu, nv)?)
    }

    /// A degree within the limits.
    ///
    /// # Errors
    /// [`Kind::Limit`].
    pub fn check_degree(&self, what: &'static str, degree: usize) -> Result<()> {
        Ok(self.limits.check_degree(what, degree)?)
    }

    /// The work `cost` (in doubles) within the limits, refused as every front end refuses
    /// it: the operation layer's check ([`cagd_ops::Context::check_cost`]) about the argument
    /// `what`, `ARGUMENT: estimated operations: W exceeds the limit of L (raise it with
    /// cagd_limits ("max_work", VALUE)); expected fewer points or a lower degree`.
    ///
    /// # Errors
    /// [`Kind::Limit`].
    pub fn check_cost(&self, what: &'static str, cost: Cost) -> Result<()> {
        if cost.weigh(false) <= u128::from(self.limits.max_work) {
            return Ok(());
        }
        self.context()
            .check_cost(cagd_ops::Role::T, cost, false)
            .map_err(|e| crate::error::op_error(&[(cagd_ops::Role::T, what)], e))
    }
}

/// A value as a real double array.
///
/// # Errors
/// [`Kind::Class`] for any other class.
pub fn real_of<'a>(v: &Value<'a>, what: &str, form: &str) -> Result<Real<'a>> {
    match v {
        Value::Real(r) => Ok(*r),
        other => Err(PkgError::arg(
            Kind::Class,
            what,
            format!("{} is not accepted", describe_class(other)),
            form,
        )),
    }
}

/// "a cell array", "int32", "a struct without fields": the class of a refused value in words.
fn describe_class(v: &Value<'_>) -> String {
    match v {
        Value::Cell { .. } => "a cell array".into(),
        Value::Struct { fields } if fields.is_empty() => "a struct without fields".into(),
        Value::Struct { .. } => "a struct".into(),
        Value::Char { .. } => "text (char)".into(),
        other => other.class().to_string(),
    }
}

/// A value as a real double array with at least one element.
///
/// # Errors
/// [`Kind::Class`], [`Kind::Empty`].
pub fn nonempty_of<'a>(v: &Value<'a>, what: &str, form: &str) -> Result<Real<'a>> {
    let r = real_of(v, what, form)?;
    if r.is_empty() {
        return Err(PkgError::arg(
            Kind::Empty,
            what,
            format!("empty ({})", r.size_str()),
            form,
        ));
    }
    Ok(r)
}

/// A real array as a 2-D view (column-major, no copy).
///
/// # Errors
/// [`Kind::Shape`] for more than two dimensions.
pub fn view2_of<'a>(r: Real<'a>, what: &str, form: &str) -> Result<ArrayView2<'a, f64>> {
    if !r.is_matrix() {
        return Err(PkgError::arg(
            Kind::Shape,
            what,
            format!("an array of size {}", r.size_str()),
            form,
        ));
    }
    Ok(ArrayView2::from_shape((r.rows(), r.cols()).f(), r.data)
        .expect("an Octave matrix holds rows · cols elements"))
}

/// Refuses a NaN or ±Inf among `values`, in the operation layer's words
/// ([`cagd_ops::check::non_finite`]), so that the package reads the same as every front end.
///
/// # Errors
/// [`Kind::NonFinite`] about `what`.
pub fn finite(what: &str, values: &[f64]) -> Result<()> {
    match cagd_ops::check::non_finite(values) {
        None => Ok(()),
        Some((problem, expected)) => Err(PkgError::arg(Kind::NonFinite, what, problem, expected)),
    }
}

/// A value as a matrix of finite values with at least one element.
///
/// # Errors
/// [`Kind::Class`], [`Kind::Empty`], [`Kind::Shape`] for more than two dimensions,
/// [`Kind::NonFinite`].
pub fn matrix_of(v: &Value<'_>, what: &'static str, form: &str) -> Result<DMatrix<f64>> {
    let r = nonempty_of(v, what, form)?;
    if !r.is_matrix() {
        return Err(PkgError::arg(
            Kind::Shape,
            what,
            format!("an array of size {}", r.size_str()),
            form,
        ));
    }
    finite(what, r.data)?;
    Ok(DMatrix::from_column_slice(r.rows(), r.cols(), r.data))
}

/// A value as a finite real scalar.
///
/// # Errors
/// [`Kind::Class`], [`Kind::Shape`] unless 1 × 1, [`Kind::NonFinite`].
pub fn scalar_of(v: &Value<'_>, what: &'static str) -> Result<f64> {
    let form = "a real scalar";
    let r = nonempty_of(v, what, form)?;
    if r.len() != 1 {
        return Err(PkgError::arg(
            Kind::Shape,
            what,
            format!("an array of size {}", size_str(r.dims)),
            form,
        ));
    }
    finite(what, r.data)?;
    Ok(r.data[0])
}

/// A value as a count: a non-negative integer scalar.
///
/// # Errors
/// As [`scalar_of`]; [`Kind::Value`] for a negative or fractional value.
pub fn count_of(v: &Value<'_>, what: &'static str) -> Result<usize> {
    let x = scalar_of(v, what)?;
    if x < 0.0 || x.fract() != 0.0 || x >= MAX_EXACT_INTEGER {
        return Err(PkgError::arg(
            Kind::Value,
            what,
            format!("{x} is not a non-negative integer"),
            "a count 0, 1, 2, …",
        ));
    }
    Ok(x as usize)
}

/// A value as finite parameters (any real array, column-major, maybe empty).
///
/// # Errors
/// [`Kind::Class`], [`Kind::NonFinite`].
pub fn params_of<'a>(v: &Value<'a>, what: &'static str) -> Result<&'a [f64]> {
    let r = real_of(v, what, "real parameter values (a double array)")?;
    finite(what, r.data)?;
    Ok(r.data)
}

/// A value as text.
///
/// # Errors
/// [`Kind::Class`].
pub fn text_of(v: &Value<'_>, what: &str, form: &str) -> Result<String> {
    v.text().ok_or_else(|| {
        PkgError::arg(
            Kind::Class,
            what,
            format!("{} is not accepted", describe_class(v)),
            form,
        )
    })
}

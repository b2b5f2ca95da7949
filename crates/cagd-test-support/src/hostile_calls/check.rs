//! What a call must give back: a result of a `Result`-returning function is `Err`, or `Ok` of
//! a value whose every number is finite ([`ok`]); an infallible function just returns
//! ([`total`]). Each check names the function by its path in the crate (`"bezier::BezierCurve::
//! eval_many"`, or `"… as Curve::try_eval"` for a trait method), the names that
//! `fuzz/api_coverage.sh` counts against the crate's public API.

use std::fmt::Debug;

use cagd::bezier::{DeCasteljauScheme, MatrixForm, PatchScheme};
use cagd::bspline::{BSplineCurve, BSplineSurface, KnotVector};
use cagd::coons::{CoonsPoint, Mask};
use cagd::grid::PointGrid;
use cagd::lagrange::{Lagrange, LagrangeInterpolant, LebesgueEstimate};
use cagd::nurbs::{NurbsCurve, NurbsSurface};
use cagd::{BezierCurve, BezierPatch, CubicSpline, HermiteCubic};
use nalgebra::{DMatrix, DVector};

/// A value whose numbers must all be finite when a function returns it in `Ok`.
pub trait Finite {
    /// Whether every number it holds is finite.
    fn all_finite(&self) -> bool;
}

/// Values without numbers of their own (sizes, flags, joints).
macro_rules! trivially_finite {
    ($($t:ty),*) => {$(impl Finite for $t { fn all_finite(&self) -> bool { true } })*};
}
trivially_finite!(
    (),
    usize,
    bool,
    cagd::continuity::Joint,
    cagd::lagrange::Lagrange<num_rational::BigRational>
);

impl Finite for f64 {
    fn all_finite(&self) -> bool {
        self.is_finite()
    }
}

impl<T: Finite> Finite for Vec<T> {
    fn all_finite(&self) -> bool {
        self.iter().all(Finite::all_finite)
    }
}

impl<T: Finite + ?Sized> Finite for &T {
    fn all_finite(&self) -> bool {
        (**self).all_finite()
    }
}

impl<T: Finite, const N: usize> Finite for [T; N] {
    fn all_finite(&self) -> bool {
        self.iter().all(Finite::all_finite)
    }
}

impl<T: Finite> Finite for Option<T> {
    fn all_finite(&self) -> bool {
        self.as_ref().is_none_or(Finite::all_finite)
    }
}

impl<A: Finite, B: Finite> Finite for (A, B) {
    fn all_finite(&self) -> bool {
        self.0.all_finite() && self.1.all_finite()
    }
}

impl<A: Finite, B: Finite, C: Finite> Finite for (A, B, C) {
    fn all_finite(&self) -> bool {
        self.0.all_finite() && self.1.all_finite() && self.2.all_finite()
    }
}

impl Finite for DVector<f64> {
    fn all_finite(&self) -> bool {
        self.iter().all(|x| x.is_finite())
    }
}

impl Finite for DMatrix<f64> {
    fn all_finite(&self) -> bool {
        self.iter().all(|x| x.is_finite())
    }
}

impl Finite for PointGrid<f64> {
    fn all_finite(&self) -> bool {
        self.iter().all(|x| x.is_finite())
    }
}

impl Finite for BezierCurve<f64> {
    fn all_finite(&self) -> bool {
        let (a, b) = self.interval();
        self.control().all_finite() && a.is_finite() && b.is_finite() && (b - a).is_finite()
    }
}

impl Finite for BezierPatch<f64> {
    fn all_finite(&self) -> bool {
        self.coordinates().to_vec().all_finite()
    }
}

impl Finite for MatrixForm<f64> {
    fn all_finite(&self) -> bool {
        self.coefficients().all_finite()
    }
}

impl Finite for DeCasteljauScheme<f64> {
    fn all_finite(&self) -> bool {
        self.levels().to_vec().all_finite()
    }
}

impl Finite for PatchScheme<f64> {
    fn all_finite(&self) -> bool {
        (0..self.level_count()).all(|k| self.level(k).is_none_or(|l| l.to_vec().all_finite()))
    }
}

impl Finite for KnotVector<f64> {
    fn all_finite(&self) -> bool {
        self.as_slice().to_vec().all_finite()
    }
}

impl Finite for BSplineCurve<f64> {
    fn all_finite(&self) -> bool {
        self.control().all_finite() && self.knots().all_finite()
    }
}

impl Finite for BSplineSurface<f64> {
    fn all_finite(&self) -> bool {
        let (u, v) = self.knots();
        self.coordinates().to_vec().all_finite() && u.all_finite() && v.all_finite()
    }
}

impl Finite for NurbsCurve<f64> {
    fn all_finite(&self) -> bool {
        self.homogeneous().all_finite() && self.points().all_finite()
    }
}

impl Finite for NurbsSurface<f64> {
    fn all_finite(&self) -> bool {
        self.homogeneous().all_finite()
    }
}

impl Finite for Lagrange<f64> {
    fn all_finite(&self) -> bool {
        self.nodes().to_vec().all_finite() && self.weights().to_vec().all_finite()
    }
}

impl Finite for LagrangeInterpolant<f64> {
    fn all_finite(&self) -> bool {
        self.basis().all_finite() && self.values().all_finite()
    }
}

impl Finite for LebesgueEstimate {
    fn all_finite(&self) -> bool {
        self.value.is_finite() && self.at.is_finite()
    }
}

impl Finite for cagd::interpolation::ParametricInterpolant<f64> {
    fn all_finite(&self) -> bool {
        self.points().all_finite()
            && self.algebraic().all_finite()
            && self.params().to_vec().all_finite()
    }
}

impl Finite for CubicSpline<f64> {
    fn all_finite(&self) -> bool {
        self.params().to_vec().all_finite()
            && self.points().all_finite()
            && self.tangents().all_finite()
    }
}

impl Finite for HermiteCubic<f64> {
    fn all_finite(&self) -> bool {
        self.geometry().all_finite()
    }
}

impl Finite for Mask<f64> {
    fn all_finite(&self) -> bool {
        self.alpha().is_finite() && self.beta().is_finite()
    }
}

impl Finite for cagd::coons::GregoryTwist<f64> {
    fn all_finite(&self) -> bool {
        self.along_v().all_finite() && self.along_u().all_finite()
    }
}

impl Finite for CoonsPoint<f64> {
    fn all_finite(&self) -> bool {
        [&self.x, &self.rc, &self.rd, &self.rcd]
            .iter()
            .all(|v| v.all_finite())
    }
}

/// The result of the `Result`-returning function `name`: an `Err` is fine, an `Ok` must hold
/// finite numbers only (else this panics, naming the function and the value). Returns the
/// value for further calls.
#[track_caller]
pub fn ok<V: Finite + Debug>(name: &str, result: cagd::Result<V>) -> Option<V> {
    match result {
        Ok(v) if !v.all_finite() => {
            let shown: String = format!("{v:?}").chars().take(400).collect();
            panic!("{name}: Ok holds a non-finite value: {shown}")
        }
        Ok(v) => Some(v),
        Err(_) => None,
    }
}

/// The result of the `Result`-returning function `name` whose value holds arbitrary curves
/// (a Coons patch over closures, say), and numbers of its own that `numbers` reads (its
/// corners, nodes, coefficients): an `Err` is fine, an `Ok` must hold finite numbers only (else
/// this panics, naming the function and the numbers). The curves' values are checked through
/// the evaluations of the surface.
#[track_caller]
pub fn ok_with<V, N: Finite + Debug>(
    name: &str,
    result: cagd::Result<V>,
    numbers: impl FnOnce(&V) -> N,
) -> Option<V> {
    let v = result.ok()?;
    let held = numbers(&v);
    if !held.all_finite() {
        let shown: String = format!("{held:?}").chars().take(400).collect();
        panic!("{name}: Ok holds a non-finite value: {shown}")
    }
    Some(v)
}

/// The result of an `Ok`-only check on a value without numbers of its own to read (a ruled
/// surface of two arbitrary curves, the Lagrange polynomial, whose nodes and values are
/// private, an exact rational): only that it returned; its numbers are checked through its
/// evaluations.
pub fn any<V>(_name: &str, result: cagd::Result<V>) -> Option<V> {
    result.ok()
}

/// The value of the infallible function `name`: it must only return (no panic); outside a
/// domain, or for a NaN argument, its numbers may be anything.
pub fn total<V>(_name: &str, value: V) -> V {
    value
}

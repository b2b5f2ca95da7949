//! The constructions, one file each: what each front end offers as a command, a function or
//! a view.
//!
//! | request | construction |
//! |---|---|
//! | [`DeCasteljau`] | points of a Bézier curve, with the de Casteljau scheme |
//! | [`Coons`] | a Coons patch of any four boundary curves, with its parts |
//! | [`Curvature`] | the curvature and Frenet frame of a Bézier, B-spline or NURBS curve |
//! | [`BSpline`] | points of a B-spline curve, with its basis and de Boor's scheme |
//! | [`Nurbs`] | points of a NURBS curve, with its rational basis |
//! | [`InsertKnot`] | knots inserted into a B-spline or NURBS curve, Boehm's steps |
//! | [`BSplineBasis`] | the basis functions of a knot vector, the Cox–de Boor triangle |
//! | [`Lagrange`] | the Lagrange basis, or the polynomial through values at nodes |
//! | [`Hermite`] | a Hermite (Ferguson) cubic, with its basis and Bézier points |
//! | [`Spline`] | an interpolating cubic spline, with its system and segments |
//! | [`BSplineSurface`] | a tensor-product B-spline surface, with its bases |
//! | [`NurbsSurface`] | a tensor-product NURBS surface |
//! | [`Circle`] | a circle or a circular arc as an exact NURBS curve |
//! | [`CoonsBicubic`] | a bicubically blended Coons patch of any curves, with its parts |
//! | [`DiscreteCoons`] | the interior of a net from its boundary, by formula or mask |
//! | [`Gordon`] | a Gordon surface of a network of any curves, with its parts |
//! | [`Ruled`] | the ruled surface between any two curves |
//! | [`Ferguson`] | a Hermite bicubic patch of corner data or of four boundary curves |
//! | [`BezierPatchPoints`] | points of a Bézier patch or of a partial derivative, with the schemes |
//! | [`Bernstein`] | the Bernstein polynomials of one degree |
//! | [`Derivative`] | the derivative of a Bézier curve: control points and values |
//! | [`Subdivide`] | a Bézier curve split in two by de Casteljau's scheme |
//! | [`Continuity`] | the joint of two Bézier curves: C0, C1, G1, C2, the free point |
//! | [`Convert`] | a polynomial curve from one geometry form to another |
//! | [`Integrate`] | antiderivatives and integrals of Bernstein polynomials, Bézier and B-spline curves |
//! | [`CurveSamples`] | a curve known by evaluation (a user's expression) at parameters |
//! | [`SurfaceSamples`] | a surface known by evaluation (a user's expression) on a grid |
//! | [`Elevate`] | degree elevation of a Bézier or clamped B-spline curve |

use cagd::grid::PointGrid;
use cagd::{Curve, Scalar};
use nalgebra::DMatrix;

use crate::error::{lib, Result};
use crate::{number_text, Context, Role};

mod bernstein;
mod bezier_patch;
mod bspline;
mod bspline_basis;
mod bspline_surface;
mod circle;
mod continuity;
mod convert;
pub mod coons;
pub mod coons_bicubic;
mod curvature;
mod curve_samples;
mod decasteljau;
mod derivative;
pub mod discrete_coons;
mod elevate;
pub mod ferguson;
pub mod gordon;
pub mod hermite;
mod insert_knot;
mod integrate;
mod lagrange;
mod nurbs;
mod nurbs_surface;
pub mod patch;
pub mod ruled;
pub mod spline;
mod subdivide;
pub mod surface;
mod surface_samples;

pub use bernstein::Bernstein;
pub use bezier_patch::BezierPatchPoints;
pub use bezier_patch::NET_FORM as BEZIER_NET_FORM;
pub use bspline::BSpline;
pub use bspline::CONTROL_FORM as BSPLINE_CONTROL_FORM;
pub use bspline_basis::BSplineBasis;
pub use bspline_surface::BSplineSurface;
pub use circle::Circle;
pub use continuity::Continuity;
pub use convert::Convert;
pub use coons::{Blend, Coons};
pub use coons_bicubic::{CoonsBicubic, TwistChoice};
pub use curvature::Curvature;
pub use curve_samples::CurveSamples;
pub use decasteljau::DeCasteljau;
pub use decasteljau::CONTROL_FORM as BEZIER_CONTROL_FORM;
pub use derivative::Derivative;
pub use discrete_coons::DiscreteCoons;
pub use elevate::Elevate;
pub use ferguson::{Ferguson, FergusonData};
pub use gordon::Gordon;
pub use hermite::Hermite;
pub use insert_knot::InsertKnot;
pub use integrate::Integrate;
pub use lagrange::{
    Lagrange, NODES_FORM as LAGRANGE_NODES_FORM, VALUES_FORM as LAGRANGE_VALUES_FORM,
};
pub use nurbs::Nurbs;
pub use nurbs_surface::NurbsSurface;
pub use ruled::Ruled;
pub use spline::Spline;
pub use subdivide::Subdivide;
pub use surface_samples::{SurfaceEvaluator, SurfaceSamples};

/// How much more steps cost than the points alone: each scheme is computed again and laid out
/// as text, about as many numbers as operations, each number some 50 operations to format
/// and about 16 bytes of text. So a request whose schemes would fill gigabytes of memory is
/// refused up front like any other large work.
pub const STEPS_FACTOR: u128 = 50;

/// The operations of writing one number of an answer out as text: an answer that is mostly
/// numbers (a basis matrix) counts them with its work, so that a request whose output would
/// fill gigabytes is refused up front.
pub const WRITE_OPS: u128 = 100;

/// Most points evaluated between two interrupt checks.
const CHUNK: usize = 4096;

/// The work, in operations of one `f64` each, between two interrupt checks: a few
/// milliseconds (and far less for cheap points: at most 4096 of them).
pub const CHECK_WORK: u128 = 1 << 22;

/// How many points of `per_point` operations each to evaluate between two interrupt checks:
/// about [`CHECK_WORK`] operations, at least 1, at most 4096 points. A curve of degree
/// 1000 (a million operations a point) is asked every 4 points, a cubic every 4096.
///
/// ```
/// use cagd_ops::ops::chunk_points;
/// assert_eq!((chunk_points(1_000_000), chunk_points(16), chunk_points(0)), (4, 4096, 4096));
/// assert_eq!(chunk_points(u128::MAX), 1);
/// ```
pub fn chunk_points(per_point: u128) -> usize {
    (CHECK_WORK / per_point.max(1)).clamp(1, CHUNK as u128) as usize
}

/// The points of `curve` at `ts` (`d × k`, one per column), in chunks between which the
/// front end may interrupt.
pub fn eval_points<T: Scalar, C: Curve<T> + ?Sized>(
    curve: &C,
    ts: &[T],
    role: Role,
    cx: &Context,
) -> Result<DMatrix<T>> {
    let d = curve.dim();
    let too_large = |requested: u128| {
        crate::OpError::library(
            role,
            cagd::Error::TooLarge {
                what: "curve points",
                requested,
                limit: cx.limits.max_grid_points as u128,
                which: cagd::limits::Limit::GridPoints,
            },
            "fewer points",
        )
    };
    let len = d
        .checked_mul(ts.len())
        .ok_or_else(|| too_large(d as u128 * ts.len() as u128))?;
    let mut out = Vec::new();
    out.try_reserve_exact(len)
        .map_err(|_| too_large(len as u128))?;
    out.resize(len, T::zero());
    let chunk = chunk_points(curve.point_cost(cagd::cost::max_bits(ts)).weigh(T::EXACT));
    for (chunk, buffer) in ts.chunks(chunk).zip(out.chunks_mut(chunk * d.max(1))) {
        cx.check_interrupt()?;
        curve
            .eval_many_into(chunk, buffer)
            .map_err(lib(role, "finite parameter values"))?;
    }
    // Row-major k × d is column-major d × k: one point per column.
    Ok(DMatrix::from_vec(d, ts.len(), out))
}

/// The grid `us × vs` (`nu × nv × d`) evaluated by `eval` a band of `u` rows at a time, each
/// band about [`CHECK_WORK`] operations of `per_point` each, between which the front end may
/// interrupt. `eval(band, vs)` gives the grid of its rows.
///
/// # Errors
/// `eval`'s; [`Kind::Interrupted`](crate::Kind::Interrupted).
pub fn grid_in_bands<T: Scalar>(
    (us, vs): (&[T], &[T]),
    per_point: u128,
    cx: &Context,
    eval: impl Fn(&[T], &[T]) -> Result<PointGrid<T>>,
) -> Result<PointGrid<T>> {
    let rows = chunk_points(per_point.saturating_mul(vs.len().max(1) as u128));
    let mut bands = us.chunks(rows);
    cx.check_interrupt()?;
    let Some(first) = bands.next() else {
        return eval(us, vs);
    };
    let first = eval(first, vs)?;
    if first.dim().0 == us.len() {
        return Ok(first);
    }
    let d = first.dim().2;
    let mut data = first.into_vec();
    for band in bands {
        cx.check_interrupt()?;
        data.extend(eval(band, vs)?.into_vec());
    }
    Ok(PointGrid::from_vec((us.len(), vs.len(), d), data)
        .expect("bands of u rows make the whole grid"))
}

/// Labels `t = 1/2` of the points at `values`, named `name`.
pub fn point_labels<T: Scalar>(name: &str, values: &[T]) -> Vec<String> {
    values
        .iter()
        .map(|x| format!("{name} = {}", number_text(x)))
        .collect()
}

/// A matrix in doubles, for pictures.
pub fn to_f64<T: Scalar>(m: &DMatrix<T>) -> DMatrix<f64> {
    m.map(|x| x.to_f64())
}

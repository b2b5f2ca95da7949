//! The polyline a picture draws of a curve: enough samples that it shows no corners the curve
//! does not have, and no chord longer than a few pixels.
//!
//! A curve is drawn as the polyline through samples at uniform parameters. A first polyline
//! through `first` samples is measured in pixels of a picture the curve fills
//! ([`PICTURE_PIXELS`] for its extent): its longest chord, and its sag (how far the curve
//! strays from a chord, measured at every other sample as the distance of the sample between
//! from the chord of its neighbours, a chord twice as long). If a chord is longer than
//! [`MAX_CHORD_PIXELS`] or strays more than [`MAX_SAG_PIXELS`], the curve is sampled again,
//! uniformly, with as many samples as make both small enough (a chord shrinks with the
//! parameter step, its sag with its square), and measured again (a few times at most), up to
//! [`MAX_PICTURE_SAMPLES`] and only where the work is allowed (else the polyline so far is
//! drawn).
//!
//! ```
//! use cagd_ops::picture::{picture_line, MAX_CHORD_PIXELS, PICTURE_PIXELS};
//! use nalgebra::DMatrix;
//! // The unit circle from 9 samples: chords of 0.77 of its extent 2, 300 pixels.
//! let circle = |ts: &[f64]| -> cagd_ops::Result<DMatrix<f64>> {
//!     Ok(DMatrix::from_fn(2, ts.len(), |r, k| {
//!         let a = std::f64::consts::TAU * ts[k];
//!         if r == 0 { a.cos() } else { a.sin() }
//!     }))
//! };
//! let line = picture_line((&0.0, &1.0), 9, false, circle, |_| true)?;
//! let longest = (1..line.ncols())
//!     .map(|k| (line.column(k) - line.column(k - 1)).norm())
//!     .fold(0.0, f64::max);
//! assert!(longest * PICTURE_PIXELS / 2.0 <= MAX_CHORD_PIXELS);
//! # Ok::<(), cagd_ops::OpError>(())
//! ```

use cagd::cost::{max_bits, Cost};
use cagd::{Curve, Scalar};
use nalgebra::DMatrix;

use crate::error::{lib, Result};
use crate::ops::{eval_points, to_f64};
use crate::{Context, Role};

/// The pixels a curve's extent takes in a picture it fills: about the plotting area of a
/// 900×700 picture.
pub const PICTURE_PIXELS: f64 = 800.0;

/// The longest chord of a curve's picture, in pixels.
pub const MAX_CHORD_PIXELS: f64 = 6.0;

/// The most a curve strays from a chord of its picture, in pixels.
pub const MAX_SAG_PIXELS: f64 = 0.05;

/// The most samples a curve's picture takes.
pub const MAX_PICTURE_SAMPLES: usize = 2001;

/// How many uniform samples make the polyline of a curve short-chorded and close to it
/// (at most [`MAX_CHORD_PIXELS`] and [`MAX_SAG_PIXELS`]), measured on `line`, a polyline
/// through `n` uniform samples of the curve (one point per column): `n` if they already do,
/// else an odd number (so that every other sample is again a chord's middle), at most
/// [`MAX_PICTURE_SAMPLES`].
///
/// Pixels are [`PICTURE_PIXELS`] to the extent: for geometry, drawn with equal scales, its
/// largest side; a graph's axes are each fitted to its data, so each coordinate to its own.
pub fn samples_for(line: &DMatrix<f64>, graph: bool) -> usize {
    samples_within(line, &sides(std::slice::from_ref(line)), graph)
}

/// [`samples_for`] with the sides of the picture's extent given (several curves on the same
/// axes share them).
fn samples_within(line: &DMatrix<f64>, sides: &[f64], graph: bool) -> usize {
    let n = line.ncols();
    let Some(px) = in_pixels(line, sides, graph) else {
        return n;
    };
    let longest = (1..n)
        .map(|k| (px.column(k) - px.column(k - 1)).norm())
        .fold(0.0, f64::max);
    let sag = (2..n)
        .step_by(2)
        .map(|k| stray(&px, k - 2))
        .fold(0.0, f64::max);
    // A chord of one step strays about a quarter as far as one of two.
    let factor = (longest / MAX_CHORD_PIXELS).max((sag / 4.0 / MAX_SAG_PIXELS).sqrt());
    if factor <= 1.0 {
        return n;
    }
    let wanted = ((n - 1) as f64 * factor)
        .ceil()
        .min(MAX_PICTURE_SAMPLES as f64) as usize;
    (wanted + 1 + wanted % 2).min(MAX_PICTURE_SAMPLES).max(n)
}

/// The sides of the box around all of `lines` (finite values), one per coordinate.
fn sides(lines: &[DMatrix<f64>]) -> Vec<f64> {
    let d = lines.iter().map(|l| l.nrows()).max().unwrap_or(0);
    (0..d)
        .map(|r| {
            let values = lines
                .iter()
                .filter(|l| r < l.nrows())
                .flat_map(|l| l.row(r).iter().copied().collect::<Vec<_>>())
                .filter(|x| x.is_finite());
            let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            });
            if hi > lo {
                hi - lo
            } else {
                0.0
            }
        })
        .collect()
}

/// `line` in pixels ([`samples_for`]) within a box of `sides`; none for fewer than 3 points,
/// a non-finite value or a single point.
fn in_pixels(line: &DMatrix<f64>, sides: &[f64], graph: bool) -> Option<DMatrix<f64>> {
    if line.ncols() < 3 || line.nrows() > sides.len() || line.iter().any(|x| !x.is_finite()) {
        return None;
    }
    let largest = sides.iter().copied().fold(0.0, f64::max);
    if largest == 0.0 {
        return None;
    }
    let scale = |r: usize| match (graph, sides[r] > 0.0) {
        (false, _) => PICTURE_PIXELS / largest,
        (true, true) => PICTURE_PIXELS / sides[r],
        (true, false) => 0.0,
    };
    Some(DMatrix::from_fn(line.nrows(), line.ncols(), |r, k| {
        line[(r, k)] * scale(r)
    }))
}

/// How far the point `k + 1` of `px` lies from the chord from point `k` to point `k + 2`.
fn stray(px: &DMatrix<f64>, k: usize) -> f64 {
    let (a, m, b) = (px.column(k), px.column(k + 1), px.column(k + 2));
    let (ab, am) = (b - a, m - a);
    let length2 = ab.norm_squared();
    let along = if length2 > 0.0 {
        (am.dot(&ab) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (&am - &ab * along).norm()
}

/// The picture's polyline of `eval` (the points at parameters, one per column, in doubles)
/// over `[a, b]`: `first` uniform samples, or more as [`samples_for`] asks, measured again
/// after each sampling, while `affordable` allows evaluating at them.
pub fn picture_line<T: Scalar>(
    (a, b): (&T, &T),
    first: usize,
    graph: bool,
    mut eval: impl FnMut(&[T]) -> Result<DMatrix<f64>>,
    affordable: impl Fn(&[T]) -> bool,
) -> Result<DMatrix<f64>> {
    let lines = picture_lines((a, b), first, graph, |ts| Ok(vec![eval(ts)?]), affordable)?;
    Ok(lines.into_iter().next().unwrap_or_default())
}

/// The polylines of several curves on the same axes over the same parameters (`eval` gives
/// them all, in doubles), as [`picture_line`] samples one: pixels to the extent of them all,
/// as many samples as the most demanding asks.
pub fn picture_lines<T: Scalar>(
    (a, b): (&T, &T),
    first: usize,
    graph: bool,
    mut eval: impl FnMut(&[T]) -> Result<Vec<DMatrix<f64>>>,
    affordable: impl Fn(&[T]) -> bool,
) -> Result<Vec<DMatrix<f64>>> {
    let samples = |n| cagd::linspace::linspace_in(a, b, n).map_err(lib(Role::T, "a curve"));
    let mut lines = eval(&samples(first)?)?;
    let mut count = first;
    // A chord of the coarser polyline is the mean speed over its step, which the finer one
    // may exceed: measured again, at most a few times (the count grows each time).
    for _ in 0..REFINEMENTS {
        let box_sides = sides(&lines);
        let n = lines
            .iter()
            .map(|l| samples_within(l, &box_sides, graph))
            .fold(count, usize::max);
        if n <= count {
            break;
        }
        let ts = samples(n)?;
        if !affordable(&ts) {
            break;
        }
        lines = eval(&ts)?;
        count = n;
    }
    Ok(lines)
}

/// The most times a picture's curve is sampled again.
const REFINEMENTS: usize = 3;

/// Whether `cx` allows evaluating a point at each of `ts` for a picture, a point costing
/// `point(bits)` at parameters of `bits` bits.
pub fn allowed<T: Scalar>(cx: &Context, ts: &[T], point: impl Fn(u128) -> Cost) -> bool {
    let cost = point(max_bits(ts)).times(ts.len() as u128);
    cx.check_cost(Role::T, cost, T::EXACT).is_ok()
}

/// The picture's polyline of `curve` over `[a, b]` ([`picture_line`], its work priced by the
/// curve's cost of a point), errors about `role`.
pub fn curve_line<T: Scalar, C: Curve<T> + ?Sized>(
    curve: &C,
    (a, b): (&T, &T),
    first: usize,
    role: Role,
    cx: &Context,
) -> Result<DMatrix<f64>> {
    picture_line(
        (a, b),
        first,
        false,
        |ts| eval_points(curve, ts, role, cx).map(|m| to_f64(&m)),
        |ts| allowed(cx, ts, |bits| curve.point_cost(bits)),
    )
}

//! Refinement of B-splines and the constructions built on it: B-spline basis values into
//! caller-given buffers, curves made compatible (one degree, one knot vector), degree
//! elevation and knot insertion of B-spline surfaces, and the Coons patch of four B-spline
//! curves as one B-spline surface.

use cagd::bspline::{
    basis_functions, basis_functions_into, find_span, make_compatible, BSplineCurve, BSplineSurface,
};
use cagd::coons::{coons_bspline_net, CoonsPatch};
use nalgebra::{DMatrix, DVector};

use super::check::{ok, total};
use super::draws::*;

/// One group: the four families below, each from its own draws.
pub fn refinement(rng: &Draws) {
    basis_into(rng);
    compatible(rng);
    surface_refinement(rng);
    coons_in_bspline_form(rng);
}

/// [`basis_functions_into`] within its documented preconditions (a span whose knots
/// `u_{s+1−p} … u_{s+p}` exist, buffers of at least `p + 1` entries) with any knots and
/// parameter — NaN, ±∞, unsorted, subnormal, ±10³⁰⁸: it must return; where
/// [`basis_functions`] accepts the same arguments, the values are the same, bit for bit.
fn basis_into(rng: &Draws) {
    let p = small(rng);
    let k = knots(rng, 2 * p + small(rng));
    let u = parameter(rng);
    if k.len() < 2 * p || k.is_empty() {
        return;
    }
    // Spans s with s + 1 ≥ p and s + p < len: p − 1 … len − p − 1 (s ≥ 0).
    let (first, last) = (p.saturating_sub(1), k.len() - p - 1);
    let span = match find_span(p, k.len().saturating_sub(p + 1), &k, &u) {
        Ok(s) if rng.below(2) == 0 => s,
        _ => first + rng.below(last - first + 1),
    };
    let extra = rng.below(3);
    let (mut n, mut left, mut right) = (
        vec![0.0; p + 1 + extra],
        vec![0.0; p + 1 + extra],
        vec![0.0; p + 1 + extra],
    );
    basis_functions_into(p, &k, span, &u, &mut n, &mut left, &mut right);
    total("bspline::basis_functions_into", &n);
    if let Some(checked) = ok("bspline::basis_functions", basis_functions(p, &k, span, &u)) {
        assert_eq!(
            checked.as_slice(),
            &n[..=p],
            "basis_functions_into differs from basis_functions (p = {p}, span {span}, u = {u:e}, knots {k:?})"
        );
    }
}

/// Breakpoints shared by several curves: ordinary, equally spaced, subnormals apart, spread
/// over `[−10³⁰⁸, 10³⁰⁸]`, one ULP apart, or unsorted and non-finite.
fn breakpoints(rng: &Draws) -> Vec<f64> {
    ordered(rng, 2 + small(rng))
}

/// A clamped B-spline curve of dimension `d` over `breaks` (its first and last as the
/// domain, some interior ones as knots of multiplicity up to the degree), its ends at `ends`
/// when given; sometimes arbitrary knots instead (not clamped, too few, non-finite).
fn clamped_over(
    rng: &Draws,
    d: usize,
    breaks: &[f64],
    ends: Option<(&DVector<f64>, &DVector<f64>)>,
) -> Option<BSplineCurve> {
    let p = small(rng) % 4;
    let knots = if rng.below(8) == 0 || breaks.len() < 2 {
        knots(rng, small(rng) + small(rng))
    } else {
        let (a, b) = (breaks[0], breaks[breaks.len() - 1]);
        let mut k = vec![a; p + 1];
        for x in &breaks[1..breaks.len() - 1] {
            k.extend(std::iter::repeat_n(*x, rng.below(p + 1)));
        }
        k.extend(std::iter::repeat_n(b, p + 1));
        k
    };
    let n = knots.len().saturating_sub(p + 1).max(1);
    let mut control = matrix(rng, d, n);
    if let Some((from, to)) = ends {
        control.set_column(0, from);
        control.set_column(n - 1, to);
    }
    BSplineCurve::new(degree(rng, p), knots, control).ok()
}

/// Several curves over shared breakpoints (sometimes one of another dimension) made
/// compatible.
fn compatible(rng: &Draws) {
    let breaks = breakpoints(rng);
    let d = 1 + small(rng) % 3;
    let curves: Vec<BSplineCurve> = (0..small(rng))
        .filter_map(|_| {
            let d = if rng.below(10) == 0 { d + 1 } else { d };
            clamped_over(rng, d, &breaks, None)
        })
        .collect();
    if let Some(made) = ok("bspline::make_compatible", make_compatible(&curves)) {
        let same = made
            .windows(2)
            .all(|w| w[0].degree() == w[1].degree() && w[0].knots() == w[1].knots());
        assert!(
            same,
            "make_compatible: the curves differ in degree or knots"
        );
    }
}

/// Degree elevation (by small amounts and by sizes beyond every limit) and knot insertion
/// (inside, at the ends, outside, NaN) of B-spline surfaces of any net.
fn surface_refinement(rng: &Draws) {
    let (p, q, d) = (small(rng) % 4, small(rng) % 4, 1 + small(rng) % 3);
    let (m, n) = (1 + small(rng), 1 + small(rng));
    let coords: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
    let made = if rng.below(2) == 0 {
        BSplineSurface::clamped(degree(rng, p), degree(rng, q), coords)
    } else {
        BSplineSurface::new(
            degree(rng, p),
            degree(rng, q),
            knots(rng, m + p + 1),
            knots(rng, n + q + 1),
            coords,
        )
    };
    let Ok(s) = made else { return };
    let (ru, rv) = if rng.below(2) == 0 {
        (small(rng) % 3, small(rng) % 3)
    } else {
        (size(rng), size(rng))
    };
    ok(
        "bspline::BSplineSurface::elevate",
        s.elevate(ru, rv).inspect(|e| {
            let (p, q) = s.degrees();
            assert_eq!(e.degrees(), (p + ru, q + rv), "elevated degrees");
        }),
    );
    let (us, vs) = (parameters(rng, small(rng)), parameters(rng, small(rng)));
    ok(
        "bspline::BSplineSurface::insert_knots",
        s.insert_knots(&us, &vs),
    );
}

/// Four B-spline boundaries through four corners (the corners sometimes off, or of another
/// dimension), as a Coons patch in B-spline form: [`CoonsPatch::to_bspline`] and
/// [`coons_bspline_net`] with arbitrary corners.
fn coons_in_bspline_form(rng: &Draws) {
    let d = 1 + small(rng) % 3;
    let corners: [DVector<f64>; 4] = std::array::from_fn(|_| vector(rng, d));
    let [p00, p10, p01, p11] = &corners;
    let (bu, bv) = (breakpoints(rng), breakpoints(rng));
    let curves = [
        clamped_over(rng, d, &bu, Some((p00, p10))),
        clamped_over(rng, d, &bu, Some((p01, p11))),
        clamped_over(rng, d, &bv, Some((p00, p01))),
        clamped_over(rng, d, &bv, Some((p10, p11))),
    ];
    let [Some(c1), Some(c2), Some(d1), Some(d2)] = curves else {
        return;
    };
    let given: [DVector<f64>; 4] = std::array::from_fn(|k| match rng.below(6) {
        0 => vector(rng, d + rng.below(2)),
        _ => corners[k].clone(),
    });
    ok(
        "coons::coons_bspline_net",
        coons_bspline_net(&c1, &c2, &d1, &d2, &given),
    );
    if let Ok(patch) = CoonsPatch::new(c1, c2, d1, d2) {
        ok("coons::CoonsPatch::to_bspline", patch.to_bspline());
    }
}

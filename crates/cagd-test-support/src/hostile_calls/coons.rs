//! Coons patches (bilinear, generalized, bicubic, discrete, masks), Gordon surfaces, ruled,
//! matrix and Ferguson patches, over Bézier, sampled and closure curves of arbitrary values —
//! among them closures that return points of the wrong dimension, or NaN.

use cagd::conversion::CubicForm;
use cagd::coons::{
    bicubic_point_cost, coons_point_cost, discrete_coons, discrete_coons_cost, solve_mask,
    BicubicCoonsPatch, BlendingPair, CoonsBoundary, CoonsPatch, CrossDerivatives,
    GeneralizedCoonsPatch, GregoryTwist, Mask, Twist,
};
use cagd::cost::Cost;
use cagd::gordon::{gordon_point_cost, gordon_setup_cost, GordonSurface};
use cagd::surfaces::{CubicMatrixPatch, FergusonPatch, RuledSurface};
use cagd::tolerance::Corner;
use cagd::{Curve, CurveDeriv, FnCurve, OnUnitInterval, SampledCurve, Tolerance};
use nalgebra::{DMatrix, DVector};

use super::bezier::{curve_methods, deriv_methods, surface_methods};
use super::check::{any, ok, ok_with, total};
use super::draws::*;

/// A boundary curve of dimension `d`: Bézier (on `[0, 1]` or another interval), sampled, or a
/// closure — a straight line of the given ends, or one returning a point of another
/// dimension, NaN or ±∞ at some parameters.
type Boundary = Box<dyn CurveDeriv + Send + Sync>;

fn boundary(rng: &Draws, d: usize, from: &DVector<f64>, to: &DVector<f64>) -> Boundary {
    let (p, q) = (from.clone(), to.clone());
    match rng.below(5) {
        0 => {
            let mut control = DMatrix::from_fn(d, 2 + small(rng) % 3, |_, _| mostly_finite(rng));
            control.set_column(0, &p);
            let last = control.ncols() - 1;
            control.set_column(last, &q);
            match cagd::BezierCurve::new_on_interval(
                control,
                rng.pick(&[0.0, -1e308, 2.0]),
                rng.pick(&[1.0, 1e308, 3.0]),
            ) {
                Ok(c) => Box::new(c),
                Err(_) => Box::new(line(p, q, 0)),
            }
        }
        1 => {
            let n = 2 + small(rng);
            let params = ordered(rng, n);
            let samples = DMatrix::from_fn(d, n, |r, k| {
                let s = k as f64 / (n - 1) as f64;
                (1.0 - s) * p[r] + s * q[r]
            });
            match SampledCurve::new(params, samples) {
                Ok(c) => Box::new(c),
                Err(_) => Box::new(line(p, q, 0)),
            }
        }
        2 => Box::new(line(p, q, 1 + rng.below(3))),
        _ => Box::new(line(p, q, 0)),
    }
}

/// The line from `p` to `q` on `[0, 1]`, with its derivative; `bad` = 1 returns one coordinate
/// too many away from the ends, 2 returns NaN there, 3 overflows there.
fn line(p: DVector<f64>, q: DVector<f64>, bad: usize) -> impl CurveDeriv + Send + Sync {
    let (p2, q2) = (p.clone(), q.clone());
    FnCurve::with_derivative(
        p.len(),
        move |t: f64| {
            let x = &p * (1.0 - t) + &q * t;
            let inside = t > 0.0 && t < 1.0;
            match bad {
                1 if inside => DVector::from_element(x.len() + 1, 0.5),
                2 if inside => x.map(|_| f64::NAN),
                3 if inside => x.map(|v| v * f64::MAX * 4.0 + f64::MAX),
                _ => x,
            }
        },
        move |_t: f64| &q2 - &p2,
    )
}

/// The numbers a Gordon surface holds of its own: its nodes, the points of the network, the
/// Lagrange bases (their barycentric weights).
#[allow(clippy::type_complexity)]
fn gordon_numbers<C>(
    g: &GordonSurface<C>,
) -> (
    (Vec<f64>, Vec<f64>),
    (
        Vec<Vec<DVector<f64>>>,
        (cagd::lagrange::Lagrange, cagd::lagrange::Lagrange),
    ),
) {
    let (bu, bv) = g.bases();
    (
        (g.u_nodes().to_vec(), g.v_nodes().to_vec()),
        (g.points().to_vec(), (bu.clone(), bv.clone())),
    )
}

/// Four corners and the four boundary curves through them.
fn four(rng: &Draws) -> (usize, [DVector<f64>; 4], [Boundary; 4]) {
    let d = 1 + small(rng) % 3;
    let corners: [DVector<f64>; 4] = std::array::from_fn(|_| vector(rng, d));
    let [p00, p10, p01, p11] = &corners;
    let curves = [
        boundary(rng, d, p00, p10),
        boundary(rng, d, p01, p11),
        boundary(rng, d, p00, p01),
        boundary(rng, d, p10, p11),
    ];
    (d, corners, curves)
}

/// Bilinear, generalized and bicubic Coons patches, with and without given corners.
pub fn coons(rng: &Draws) {
    total(
        "coons::coons_point_cost",
        coons_point_cost([Cost::new(size(rng) as u128, 64); 4], size(rng), 64, 64),
    );
    total(
        "coons::bicubic_point_cost",
        bicubic_point_cost([Cost::new(3, 64); 8], size(rng), 64, 64),
    );
    let (d, corners, [c1, c2, d1, d2]) = four(rng);
    let tolerance = rng.pick(&[
        Tolerance::default(),
        Tolerance::Absolute(value(rng)),
        Tolerance::Relative(1e-9),
    ]);
    let (u, v) = (parameter(rng), parameter(rng));
    match rng.below(4) {
        0 => {
            if let Some(p) = ok_with(
                "coons::CoonsPatch::with_tolerance",
                CoonsPatch::with_tolerance(c1, c2, d1, d2, tolerance),
                |p| p.corners().to_vec(),
            ) {
                ok("coons::CoonsPatch::corners", Ok(p.corners().to_vec()));
                total("coons::CoonsPatch::boundary", p.boundary());
                total("coons::CoonsPatch::eval_parts", p.eval_parts(u, v));
                super::bspline::grid_into(
                    rng,
                    "coons::CoonsPatch::eval_grid_into",
                    d,
                    |us, vs, out| p.eval_grid_into(us, vs, out),
                );
                surface_methods(rng, "coons::CoonsPatch", &p);
            }
        }
        1 => {
            let corners = corners.map(|c| {
                if rng.below(4) == 0 {
                    vector(rng, d + 1)
                } else {
                    c
                }
            });
            if let Some(p) = ok_with(
                "coons::CoonsPatch::with_corners",
                CoonsPatch::with_corners(c1, c2, d1, d2, corners, tolerance),
                |p| p.corners().to_vec(),
            ) {
                surface_methods(rng, "coons::CoonsPatch", &p);
            }
        }
        2 => {
            let f = match rng.below(3) {
                0 => total("coons::BlendingPair::linear", BlendingPair::linear()),
                1 => total(
                    "coons::BlendingPair::hermite_cubic",
                    BlendingPair::hermite_cubic(),
                ),
                _ => total(
                    "coons::BlendingPair::new",
                    BlendingPair::new("shifted", |t: f64| 0.9 - t, |t: f64| 0.1 + t),
                ),
            };
            total("coons::BlendingPair::eval", f.eval(u));
            total("coons::BlendingPair::name", f.name());
            let made = match rng.below(3) {
                0 => ok_with(
                    "coons::GeneralizedCoonsPatch::new",
                    GeneralizedCoonsPatch::new(c1, c2, d1, d2, f, BlendingPair::linear()),
                    |p| p.boundary().corners().to_vec(),
                ),
                1 => ok_with(
                    "coons::GeneralizedCoonsPatch::partially_bicubic",
                    GeneralizedCoonsPatch::partially_bicubic(c1, c2, d1, d2),
                    |p| p.boundary().corners().to_vec(),
                ),
                _ => ok_with(
                    "coons::CoonsBoundary::with_corners",
                    CoonsBoundary::with_corners(c1, c2, d1, d2, corners, tolerance),
                    |p| p.corners().to_vec(),
                )
                .and_then(|b| {
                    ok_with(
                        "coons::GeneralizedCoonsPatch::from_boundary",
                        GeneralizedCoonsPatch::from_boundary(
                            b,
                            f,
                            BlendingPair::hermite_cubic(),
                            value(rng),
                        ),
                        |p| p.boundary().corners().to_vec(),
                    )
                }),
            };
            if let Some(p) = made {
                total("coons::GeneralizedCoonsPatch::boundary", p.boundary());
                total("coons::GeneralizedCoonsPatch::blending", p.blending());
                total(
                    "coons::GeneralizedCoonsPatch::eval_parts",
                    p.eval_parts(u, v),
                );
                surface_methods(rng, "coons::GeneralizedCoonsPatch", &p);
            }
        }
        _ => bicubic(rng, d, [c1, c2, d1, d2], tolerance),
    }
}

/// A bicubic Coons patch over the curves, with closures (and Bézier curves) across the edges.
fn bicubic(rng: &Draws, d: usize, [c1, c2, d1, d2]: [Boundary; 4], tolerance: Tolerance) {
    let Some(b) = ok_with(
        "coons::CoonsBoundary::new",
        CoonsBoundary::new(c1, c2, d1, d2, tolerance),
        |p| p.corners().to_vec(),
    ) else {
        return;
    };
    total("coons::CoonsBoundary::curves", b.curves());
    total("coons::CoonsBoundary::unit_curves", b.unit_curves());
    ok("coons::CoonsBoundary::corners", Ok(b.corners().to_vec()));
    total("coons::CoonsBoundary::tolerance", b.tolerance());
    total("coons::CoonsBoundary::dim", b.dim());
    let zero = DVector::zeros(d);
    let cross = |rng: &Draws| boundary(rng, d, &zero, &zero);
    let cross = CrossDerivatives {
        du0: cross(rng),
        du1: cross(rng),
        dv0: cross(rng),
        dv1: cross(rng),
    };
    let twist = match rng.below(3) {
        0 => Twist::Zero,
        1 => Twist::Given(std::array::from_fn(|_| vector(rng, d + rng.below(4) / 3))),
        _ => Twist::Gregory,
    };
    let Some(p) = ok_with(
        "coons::BicubicCoonsPatch::new",
        BicubicCoonsPatch::new(b, cross, twist),
        |p| p.boundary().corners().to_vec(),
    ) else {
        return;
    };
    let (u, v) = (parameter(rng), parameter(rng));
    total("coons::BicubicCoonsPatch::boundary", p.boundary());
    total(
        "coons::BicubicCoonsPatch::cross_derivatives",
        p.cross_derivatives(),
    );
    total("coons::BicubicCoonsPatch::gregory_twist", p.gregory_twist());
    total("coons::BicubicCoonsPatch::eval_parts", p.eval_parts(u, v));
    if let Some(s) = ok(
        "coons::BicubicCoonsPatch::eval_partials",
        p.eval_partials(u, v).map(|s| (s.x, s.xu, s.xv)),
    ) {
        let _ = s;
    }
    surface_methods(rng, "coons::BicubicCoonsPatch", &p);
}

/// Coons patches and Gordon surfaces of Bézier curves (of arbitrary control points through
/// shared corners), as one Bézier patch.
pub fn bezier_networks(rng: &Draws) {
    use cagd::BezierCurve;
    let d = 1 + small(rng) % 3;
    let corners: [DVector<f64>; 4] = std::array::from_fn(|_| vector(rng, d));
    let curve = |rng: &Draws, a: &DVector<f64>, b: &DVector<f64>| {
        let mut control = matrix(rng, d, 2 + small(rng) % 3);
        control.set_column(0, a);
        let last = control.ncols() - 1;
        control.set_column(last, b);
        BezierCurve::new(control).ok()
    };
    let [p00, p10, p01, p11] = &corners;
    let (Some(c1), Some(c2), Some(d1), Some(d2)) = (
        curve(rng, p00, p10),
        curve(rng, p01, p11),
        curve(rng, p00, p01),
        curve(rng, p10, p11),
    ) else {
        return;
    };
    if let Some(p) = ok_with(
        "coons::CoonsPatch::new",
        CoonsPatch::new(c1.clone(), c2.clone(), d1.clone(), d2.clone()),
        |p| p.corners().to_vec(),
    ) {
        ok("coons::CoonsPatch::to_bezier", p.to_bezier());
        let again = total(
            "coons::CoonsPatch::from_boundary",
            CoonsPatch::from_boundary(p.boundary().clone()),
        );
        surface_methods(rng, "coons::CoonsPatch", &again);
    }
    let nodes = vec![0.0, 1.0];
    let points = vec![
        vec![p00.clone(), p01.clone()],
        vec![p10.clone(), p11.clone()],
    ];
    let at_u = vec![d1, d2];
    let at_v = vec![c1, c2];
    if let Some(g) = ok_with(
        "gordon::GordonSurface::new",
        GordonSurface::new(nodes.clone(), nodes.clone(), at_u.clone(), at_v.clone()),
        gordon_numbers,
    ) {
        ok("gordon::GordonSurface::to_bezier", g.to_bezier());
        let c = total("gordon::GordonSurface::conditioning", g.conditioning());
        total("gordon::Conditioning::amplification", c.amplification());
    }
    let tolerance = rng.pick(&[Tolerance::default(), Tolerance::Absolute(value(rng))]);
    ok_with(
        "gordon::GordonSurface::with_points",
        GordonSurface::with_points(nodes.clone(), nodes, at_u, at_v, points, tolerance),
        gordon_numbers,
    );
}

/// Gregory twists of arbitrary vectors.
pub fn gregory(rng: &Draws) {
    let d = 1 + small(rng) % 3;
    // Sometimes one vector of another dimension.
    let twist = |rng: &Draws| vector(rng, if rng.below(12) == 0 { d + 1 } else { d });
    let Some(g) = ok(
        "coons::GregoryTwist::new",
        GregoryTwist::new(
            std::array::from_fn(|_| twist(rng)),
            std::array::from_fn(|_| twist(rng)),
        ),
    ) else {
        return;
    };
    let corner = rng.pick(&Corner::ALL);
    let (u, v) = (parameter(rng), parameter(rng));
    total("coons::GregoryTwist::along_v", g.along_v());
    total("coons::GregoryTwist::along_u", g.along_u());
    total("coons::GregoryTwist::eval", g.eval(corner, &u, &v));
    total(
        "coons::GregoryTwist::derivatives",
        g.derivatives(corner, &u, &v),
    );
}

/// Discrete Coons nets and masks of arbitrary weights.
pub fn discrete(rng: &Draws) {
    let (m, n, d) = (small(rng), small(rng), small(rng));
    let net: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
    total(
        "coons::discrete_coons_cost",
        discrete_coons_cost(size(rng), size(rng), size(rng)),
    );
    ok("coons::discrete_coons", discrete_coons(&net));
    let mask = if rng.below(2) == 0 {
        ok("coons::Mask::new", Mask::new(value(rng), value(rng)))
    } else {
        ok("coons::Mask::from_alpha", Mask::from_alpha(value(rng)))
    };
    let mask = mask.unwrap_or_else(|| total("coons::Mask::coons", Mask::coons()));
    total("coons::Mask::alpha", mask.alpha());
    total("coons::Mask::beta", mask.beta());
    total(
        "coons::Mask::smallest_eigenvalue",
        mask.smallest_eigenvalue(small(rng), small(rng)),
    );
    total(
        "coons::Mask::solve_cost",
        mask.solve_cost(size(rng), size(rng)),
    );
    ok(
        "coons::solve_mask",
        solve_mask(&net, &mask, &cagd::Limits::default()),
    );
}

/// Gordon surfaces over networks of Bézier curves and closures, with arbitrary nodes (1001
/// of them, equally spaced, among them).
pub fn gordon(rng: &Draws) {
    total(
        "gordon::gordon_point_cost",
        gordon_point_cost(
            [Cost::new(3, 64); 4],
            (size(rng), size(rng)),
            size(rng),
            (64, 64),
            (64, 64),
        ),
    );
    total(
        "gordon::gordon_setup_cost",
        gordon_setup_cost([Cost::new(3, 64); 2], [Cost::new(3, 64); 2], (64, 64)),
    );
    let d = 1 + small(rng) % 3;
    let (ku, kv) = (
        count(rng).min(if rng.below(8) == 0 { 1001 } else { 5 }),
        small(rng),
    );
    let (un, vn) = (ordered(rng, ku), ordered(rng, kv));
    // The network of the bilinear patch through four corners, so that the curves cross.
    let corners: [DVector<f64>; 4] = std::array::from_fn(|_| vector(rng, d));
    let at = |s: f64, a: &DVector<f64>, b: &DVector<f64>| a * (1.0 - s) + b * s;
    let (p00, p10, p01, p11) = (&corners[0], &corners[1], &corners[2], &corners[3]);
    let at_u: Vec<Boundary> = un
        .iter()
        .map(|&s| boundary(rng, d, &at(s, p00, p10), &at(s, p01, p11)))
        .collect();
    let at_v: Vec<Boundary> = vn
        .iter()
        .map(|&s| boundary(rng, d, &at(s, p00, p01), &at(s, p10, p11)))
        .collect();
    let tolerance = rng.pick(&[Tolerance::default(), Tolerance::Relative(1e-6)]);
    let Some(g) = ok_with(
        "gordon::GordonSurface::with_tolerance",
        GordonSurface::with_tolerance(un, vn, at_u, at_v, tolerance),
        gordon_numbers,
    ) else {
        return;
    };
    let (u, v) = (parameter(rng), parameter(rng));
    total("gordon::GordonSurface::u_nodes", g.u_nodes());
    total("gordon::GordonSurface::v_nodes", g.v_nodes());
    total("gordon::GordonSurface::curves_at_u", g.curves_at_u());
    total("gordon::GordonSurface::curves_at_v", g.curves_at_v());
    ok("gordon::GordonSurface::points", Ok(g.points().concat()));
    total("gordon::GordonSurface::tolerance", g.tolerance());
    let (bu, bv) = g.bases();
    ok("gordon::GordonSurface::bases", Ok((bu.clone(), bv.clone())));
    total("gordon::GordonSurface::unit_curves", g.unit_curves());
    total("gordon::GordonSurface::conditioning", g.conditioning());
    let parts = total("gordon::GordonSurface::eval_parts", g.eval_parts(u, v));
    let _ = parts;
    super::bspline::grid_into(
        rng,
        "gordon::GordonSurface::eval_grid_into",
        d,
        |us, vs, out| g.eval_grid_into(us, vs, out),
    );
    surface_methods(rng, "gordon::GordonSurface", &g);
}

/// Sampled curves, closures and reparametrised curves; ruled, matrix and Ferguson patches.
pub fn surfaces(rng: &Draws) {
    super::course::patch_extras(rng);
    let (d, n) = (small(rng), small(rng));
    let sampled = |rng: &Draws| SampledCurve::new(ordered(rng, n), matrix(rng, d, n));
    let f = FnCurve::new(1, |t: f64| DVector::from_element(1, t * t));
    // Infinite ends are allowed by design (a closure may be defined everywhere; constructions
    // refuse such a curve with `UnusableDomain`): the domain is only checked for NaN.
    let (a, b) = (value(rng), value(rng));
    let domain = f.clone().with_domain(a, b).map(|c| c.domain());
    if a.is_finite() && b.is_finite() {
        ok("param::FnCurve::with_domain", domain);
    }
    total(
        "param::FnCurve::new",
        FnCurve::new(2, |t: f64| DVector::from_element(2, t)).domain(),
    );
    total(
        "param::FnCurve::with_derivative",
        FnCurve::with_derivative(
            1,
            |t: f64| DVector::from_element(1, t),
            |_t: f64| DVector::from_element(1, 1.0),
        )
        .domain(),
    );
    if let Ok(c) = f.with_domain(mostly_finite(rng), mostly_finite(rng)) {
        curve_methods(rng, "param::FnCurve", &c);
        if let Some(unit) = ok_with(
            "param::OnUnitInterval::new",
            OnUnitInterval::new(c, "c"),
            |u| u.original_domain(),
        ) {
            total("param::OnUnitInterval::curve", unit.curve());
            total(
                "param::OnUnitInterval::original_domain",
                unit.original_domain(),
            );
            total(
                "param::OnUnitInterval::parameter",
                unit.parameter(parameter(rng)),
            );
            curve_methods(rng, "param::OnUnitInterval", &unit);
            total("param::OnUnitInterval::into_inner", unit.into_inner());
        }
    }
    if let (Some(a), Some(b)) = (
        ok(
            "param::SampledCurve::new",
            sampled(rng)
                .map(|c| {
                    let _ = c.params();
                    c.samples().clone()
                })
                .and_then(|_| sampled(rng))
                .map(|c| c.samples().clone()),
        ),
        sampled(rng).ok(),
    ) {
        let _ = a;
        total("param::SampledCurve::params", b.params());
        total("param::SampledCurve::samples", b.samples());
        total("param::SampledCurve::eval_cost", b.eval_cost(64, 64));
        deriv_methods(rng, "param::SampledCurve", &b);
        ok(
            "param::SampledCurve::with_domain",
            b.clone()
                .with_domain(mostly_finite(rng), mostly_finite(rng))
                .map(|c| c.samples().clone()),
        );
        if let Some(r) = any(
            "surfaces::RuledSurface::new",
            RuledSurface::new(b.clone(), b),
        ) {
            total("surfaces::RuledSurface::curves", r.curves());
            surface_methods(rng, "surfaces::RuledSurface", &r);
        }
    }
    let forms = [CubicForm::Hermite, CubicForm::Bezier, CubicForm::BSpline];
    let coords: Vec<DMatrix<f64>> = (0..d)
        .map(|_| matrix(rng, 3 + small(rng) % 2, 3 + small(rng) % 2))
        .collect();
    if let Some(p) = ok_with(
        "surfaces::CubicMatrixPatch::new",
        CubicMatrixPatch::new(rng.pick(&forms), coords),
        |p| p.coordinates().to_vec(),
    ) {
        total("surfaces::CubicMatrixPatch::form", p.form());
        ok(
            "surfaces::CubicMatrixPatch::coordinates",
            Ok(p.coordinates().to_vec()),
        );
        surface_methods(rng, "surfaces::CubicMatrixPatch", &p);
    }
    let dim = 1 + small(rng) % 3;
    let v = |rng: &Draws| vector(rng, if rng.below(10) == 0 { dim + 1 } else { dim });
    let corners = |rng: &Draws| [[v(rng), v(rng)], [v(rng), v(rng)]];
    if let Some(p) = ok_with(
        "surfaces::FergusonPatch::new",
        FergusonPatch::new(&corners(rng), &corners(rng), &corners(rng), &corners(rng)),
        |p| p.geometry().to_vec(),
    ) {
        ok(
            "surfaces::FergusonPatch::geometry",
            Ok(p.geometry().to_vec()),
        );
        total(
            "surfaces::FergusonPatch::as_matrix_patch",
            p.as_matrix_patch(),
        );
        surface_methods(rng, "surfaces::FergusonPatch", &p);
    }
}

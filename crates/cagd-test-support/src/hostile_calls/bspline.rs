//! B-spline and NURBS curves and surfaces, knot vectors, spans and bases.

use cagd::bspline::{
    basis_all, basis_cost, basis_functions, cox_de_boor, cox_de_boor_triangle, curve_point_cost,
    find_span, try_cox_de_boor_triangle, BSplineCurve, BSplineSurface, KnotVector,
};
use cagd::nurbs::{conic_arc, ConicKind, NurbsCurve, NurbsSurface};
use nalgebra::DMatrix;

use super::bezier::{curve, deriv_methods, surface_methods};
use super::check::{ok, total};
use super::draws::*;

/// Knot vectors, spans and basis functions of arbitrary degrees, counts and knots.
pub fn bases(rng: &Draws) {
    let (p, n) = (size(rng), memory(rng));
    ok(
        "bspline::KnotVector::clamped_uniform",
        KnotVector::<f64>::clamped_uniform(p, n),
    );
    ok(
        "bspline::KnotVector::uniform",
        KnotVector::<f64>::uniform(p, n),
    );
    let k = knots(rng, small(rng) + small(rng));
    if let Some(kv) = ok("bspline::KnotVector::new", KnotVector::new(k.clone())) {
        total("bspline::KnotVector::as_slice", kv.as_slice());
        total("bspline::KnotVector::len", kv.len());
        total("bspline::KnotVector::is_empty", kv.is_empty());
        total(
            "bspline::KnotVector::multiplicity",
            kv.multiplicity(&value(rng)),
        );
        total("bspline::KnotVector::is_clamped", kv.is_clamped(size(rng)));
    }
    let (p, n, u) = (
        if rng.below(2) == 0 {
            small(rng)
        } else {
            size(rng)
        },
        small(rng),
        parameter(rng),
    );
    if let Some(s) = ok("bspline::find_span", find_span(p, n, &k, &u)) {
        ok("bspline::basis_functions", basis_functions(p, &k, s, &u));
    }
    ok(
        "bspline::basis_functions",
        basis_functions(p, &k, size(rng), &u),
    );
    ok("bspline::basis_all", basis_all(p, n, &k, &u));
    ok("bspline::cox_de_boor", cox_de_boor(size(rng), p, &k, &u));
    ok(
        "bspline::try_cox_de_boor_triangle",
        try_cox_de_boor_triangle(degree(rng, p), &k, &u),
    );
    if p < 6 && k.len() >= p + 2 {
        total(
            "bspline::cox_de_boor_triangle",
            cox_de_boor_triangle(p, &k, &u),
        );
    }
    total("bspline::basis_cost", basis_cost(size(rng), 64, 64));
    total(
        "bspline::curve_point_cost",
        curve_point_cost(size(rng), size(rng), 64, 64, 64),
    );
    let directions: Vec<(usize, u128)> = (0..small(rng) % 4).map(|_| (size(rng), 64)).collect();
    let tensor = total(
        "bspline::tensor_point_cost",
        cagd::bspline::tensor_point_cost(&directions, size(rng), 64, 64),
    );
    total(
        "nurbs::rational_point_cost",
        cagd::nurbs::rational_point_cost(tensor, size(rng)),
    );
}

/// A B-spline curve from arbitrary knots and control points, clamped, uniform or from a
/// Bézier curve.
fn bspline(rng: &Draws) -> Option<BSplineCurve> {
    let (p, n, d) = (small(rng), small(rng), 1 + small(rng) % 3);
    match rng.below(4) {
        0 => ok(
            "bspline::BSplineCurve::clamped",
            BSplineCurve::clamped(degree(rng, p), matrix(rng, d, n)),
        ),
        1 => ok(
            "bspline::BSplineCurve::uniform_cubic",
            BSplineCurve::uniform_cubic(&matrix(rng, d, n), rng.below(2) == 0),
        ),
        2 => curve(rng).map(|c| {
            total(
                "bspline::BSplineCurve::from_bezier",
                BSplineCurve::from_bezier(&c),
            )
        }),
        _ => ok(
            "bspline::BSplineCurve::new",
            BSplineCurve::new(
                degree(rng, p),
                knots(rng, n + p + 1 - rng.below(2).min(n + p)),
                matrix(rng, d, n),
            ),
        ),
    }
}

/// Evaluations, derivatives, knot insertion, elevation and integrals of a B-spline curve.
pub fn bspline_curves(rng: &Draws) {
    super::course::bspline_extras(rng);
    let Some(c) = bspline(rng) else { return };
    let t = parameter(rng);
    total("bspline::BSplineCurve::degree", c.degree());
    total("bspline::BSplineCurve::dim", c.dim());
    total("bspline::BSplineCurve::control", c.control());
    total("bspline::BSplineCurve::knots", c.knots());
    total("bspline::BSplineCurve::domain", c.domain());
    total("bspline::BSplineCurve::eval", c.eval(t));
    ok("bspline::BSplineCurve::try_eval", c.try_eval(t));
    ok("bspline::BSplineCurve::basis", c.basis(&t));
    ok("bspline::BSplineCurve::de_boor", c.de_boor(t));
    if let Ok(s) = c.de_boor_scheme(t) {
        ok(
            "bspline::BSplineCurve::de_boor_scheme",
            Ok((s.levels, s.alphas)),
        );
    }
    ok(
        "bspline::BSplineCurve::eval_many",
        c.eval_many(&parameters(rng, small(rng))),
    );
    let ts = parameters(rng, small(rng));
    for (name, f) in [
        (
            "bspline::BSplineCurve::eval_many_into",
            BSplineCurve::eval_many_into as fn(&_, &_, &mut _) -> _,
        ),
        (
            "bspline::BSplineCurve::eval_many_exact_order_into",
            BSplineCurve::eval_many_exact_order_into,
        ),
        (
            "bspline::BSplineCurve::try_eval_many_into",
            BSplineCurve::try_eval_many_into,
        ),
    ] {
        let mut out = vec![0.0; ts.len() * c.dim() + rng.below(2)];
        if ok(name, f(&c, &ts, &mut out)).is_some() {
            ok(name, Ok(out));
        }
    }
    ok("bspline::BSplineCurve::derivative", c.derivative());
    ok(
        "bspline::BSplineCurve::try_eval_derivative",
        c.try_eval_derivative(t),
    );
    ok(
        "bspline::BSplineCurve::insert_knot",
        c.insert_knot(parameter(rng)),
    );
    ok(
        "bspline::BSplineCurve::insert_knots",
        c.insert_knots(&parameters(rng, small(rng))),
    );
    let r = size(rng);
    total(
        "bspline::BSplineCurve::elevate_cost",
        c.elevate_cost(r, 64, 64),
    );
    ok("bspline::BSplineCurve::elevate", c.elevate(r));
    ok(
        "integral::bspline_antiderivative",
        cagd::integral::bspline_antiderivative(&c),
    );
    ok(
        "integral::bspline_integral",
        cagd::integral::bspline_integral(&c),
    );
    deriv_methods(rng, "bspline::BSplineCurve", &c);
    let nurbs = total(
        "nurbs::NurbsCurve::from_bspline",
        NurbsCurve::from_bspline(&c),
    );
    ok("nurbs::NurbsCurve::try_eval", nurbs.try_eval(t));
    ok(
        "nurbs::NurbsCurve::from_homogeneous",
        NurbsCurve::from_homogeneous(c),
    );
}

/// NURBS curves from arbitrary knots, points and weights (all 10³⁰⁸, all 5·10⁻³²⁴, …),
/// conics, arcs and circles.
pub fn nurbs_curves(rng: &Draws) {
    let (p, n, d) = (small(rng), small(rng), 1 + small(rng) % 3);
    let k = knots(rng, n + p + 1 - rng.below(2).min(n + p));
    let made = ok(
        "nurbs::NurbsCurve::new",
        NurbsCurve::new(degree(rng, p), k, matrix(rng, d, n), weights(rng, n)),
    );
    total(
        "nurbs::ConicKind::of_weight",
        ConicKind::of_weight(&value(rng)),
    );
    ok(
        "nurbs::conic_arc",
        conic_arc(matrix(rng, d, 3), mostly_finite(rng)),
    );
    let center = finites(rng, small(rng));
    ok(
        "nurbs::NurbsCurve::circle",
        NurbsCurve::circle(mostly_finite(rng), &center),
    );
    ok(
        "nurbs::NurbsCurve::arc",
        NurbsCurve::arc(
            mostly_finite(rng),
            &center,
            mostly_finite(rng),
            mostly_finite(rng),
        ),
    );
    let Some(c) = made else { return };
    let t = parameter(rng);
    total("nurbs::NurbsCurve::homogeneous", c.homogeneous());
    total("nurbs::NurbsCurve::degree", c.degree());
    total("nurbs::NurbsCurve::dim", c.dim());
    total("nurbs::NurbsCurve::knots", c.knots());
    total("nurbs::NurbsCurve::domain", c.domain());
    total("nurbs::NurbsCurve::weights", c.weights());
    total("nurbs::NurbsCurve::points", c.points());
    total("nurbs::NurbsCurve::eval", c.eval(t));
    ok("nurbs::NurbsCurve::try_eval", c.try_eval(t));
    ok("nurbs::NurbsCurve::basis", c.basis(&t));
    ok(
        "nurbs::NurbsCurve::try_eval_derivative",
        c.try_eval_derivative(t),
    );
    ok(
        "nurbs::NurbsCurve::insert_knots",
        c.insert_knots(&parameters(rng, small(rng))),
    );
    let ts = parameters(rng, small(rng));
    for (name, f) in [
        (
            "nurbs::NurbsCurve::eval_many_into",
            NurbsCurve::eval_many_into as fn(&_, &_, &mut _) -> _,
        ),
        (
            "nurbs::NurbsCurve::eval_many_exact_order_into",
            NurbsCurve::eval_many_exact_order_into,
        ),
        (
            "nurbs::NurbsCurve::try_eval_many_into",
            NurbsCurve::try_eval_many_into,
        ),
    ] {
        let mut out = vec![0.0; ts.len() * c.dim() + rng.below(2)];
        if ok(name, f(&c, &ts, &mut out)).is_some() {
            ok(name, Ok(out));
        }
    }
    deriv_methods(rng, "nurbs::NurbsCurve", &c);
    ok(
        "nurbs::NurbsSurface::ruled",
        NurbsSurface::ruled(&c, &c.insert_knots(&[]).unwrap_or(c.clone())),
    );
}

/// B-spline and NURBS surfaces of arbitrary degrees, knots, nets and weights.
pub fn surfaces(rng: &Draws) {
    super::course::nurbs_extras(rng);
    let (p, q, d) = (small(rng), small(rng), 1 + small(rng) % 3);
    let (m, n) = (small(rng), small(rng));
    let coords: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
    let (ku, kv) = (knots(rng, m + p + 1), knots(rng, n + q + 1));
    let made = if rng.below(2) == 0 {
        ok(
            "bspline::BSplineSurface::clamped",
            BSplineSurface::clamped(degree(rng, p), degree(rng, q), coords.clone()),
        )
    } else {
        ok(
            "bspline::BSplineSurface::new",
            BSplineSurface::new(
                degree(rng, p),
                degree(rng, q),
                ku.clone(),
                kv.clone(),
                coords.clone(),
            ),
        )
    };
    let w = DMatrix::from_vec(m, n, weights(rng, m * n));
    if let Some(s) = ok(
        "nurbs::NurbsSurface::new",
        NurbsSurface::new(degree(rng, p), degree(rng, q), ku, kv, coords, w),
    ) {
        let (u, v) = (parameter(rng), parameter(rng));
        total("nurbs::NurbsSurface::homogeneous", s.homogeneous());
        total("nurbs::NurbsSurface::dim", s.dim());
        total("nurbs::NurbsSurface::domain", s.domain());
        total("nurbs::NurbsSurface::eval", s.eval(u, v));
        ok("nurbs::NurbsSurface::try_eval", s.try_eval(u, v));
        grid_into(
            rng,
            "nurbs::NurbsSurface::eval_grid_into",
            s.dim(),
            |us, vs, out| s.eval_grid_into(us, vs, out),
        );
        surface_methods(rng, "nurbs::NurbsSurface", &s);
        ok(
            "nurbs::NurbsSurface::from_homogeneous",
            NurbsSurface::from_homogeneous(s.homogeneous().clone()),
        );
    }
    let Some(s) = made else { return };
    let (u, v) = (parameter(rng), parameter(rng));
    total("bspline::BSplineSurface::degrees", s.degrees());
    total("bspline::BSplineSurface::knots", s.knots());
    total("bspline::BSplineSurface::coordinates", s.coordinates());
    total("bspline::BSplineSurface::domain", s.domain());
    total("bspline::BSplineSurface::eval", s.eval(u, v));
    ok("bspline::BSplineSurface::try_eval", s.try_eval(u, v));
    grid_into(
        rng,
        "bspline::BSplineSurface::eval_grid_into",
        s.coordinates().len(),
        |us, vs, out| s.eval_grid_into(us, vs, out),
    );
    surface_methods(rng, "bspline::BSplineSurface", &s);
}

/// A grid evaluation into a buffer of the right length (sometimes one too long): `Ok` only
/// with finite numbers in the buffer.
pub fn grid_into(
    rng: &Draws,
    name: &str,
    d: usize,
    f: impl FnOnce(&[f64], &[f64], &mut [f64]) -> cagd::Result<()>,
) {
    let (us, vs) = (parameters(rng, small(rng)), parameters(rng, small(rng)));
    let mut out = vec![0.0; us.len() * vs.len() * d + rng.below(2)];
    if ok(name, f(&us, &vs, &mut out)).is_some() {
        ok(name, Ok(out));
    }
}

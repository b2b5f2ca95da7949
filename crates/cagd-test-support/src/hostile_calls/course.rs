//! The functions the operation layer added to the core for the course's constructions: the
//! five geometry forms, joints of Bézier curves, integrals, B-spline design matrices, Boehm
//! schemes, extrapolation, curvature and the Frenet frame, Lagrange nodes in any order, the
//! spline's system, Ferguson patches from a boundary, and their cost estimates. Called from the
//! groups of their constructions (no group of their own, so the fuzz target's seeds keep their
//! groups).

use cagd::bspline::{
    design_matrix, triangle_cost, wrap_periodic, BSplineCurve, BSplineSurface, Extrapolation,
};
use cagd::conversion::{form_conversion, form_conversion_cost, GeometryForm};
use cagd::coons::{discrete_coons_parts, discrete_coons_parts_cost, CoonsBoundary};
use cagd::cost::Cost;
use cagd::curvature::{curvature_cost, curvature_squared, frenet, CurveDeriv2};
use cagd::integral::{
    antiderivative_cost, bernstein_antiderivative_cost, bernstein_antiderivative_values,
    bernstein_integral, bezier_antiderivative_factor, bspline_antiderivative,
    bspline_basis_integrals, bspline_integral_to,
};
use cagd::lagrange::NodesInAnyOrder;
use cagd::nurbs::{homogenize, NurbsCurve, NurbsSurface};
use cagd::spline::{CubicSpline, EndCondition, Parametrization};
use cagd::surfaces::{ferguson_point_cost, ruled_point_cost, FergusonPatch};
use cagd::{BezierCurve, Curve, FnCurve, OnUnitInterval, Tolerance};
use nalgebra::{DMatrix, DVector};

use super::bezier::{curve, curve_methods, deriv_methods};
use super::check::{ok, ok_with, total};
use super::draws::*;

const FORMS: [GeometryForm; 5] = [
    GeometryForm::Hermite,
    GeometryForm::Bezier,
    GeometryForm::BSpline,
    GeometryForm::Monomial,
    GeometryForm::Algebraic,
];

/// The five geometry forms, their conversion matrices and cost.
pub fn forms(rng: &Draws) {
    let (from, to) = (rng.pick(&FORMS), rng.pick(&FORMS));
    let k = if rng.below(2) == 0 { 4 } else { size(rng) };
    total("conversion::GeometryForm::cubic", from.cubic());
    total(
        "conversion::GeometryForm::is_cubic_only",
        from.is_cubic_only(),
    );
    total("conversion::GeometryForm::name", from.name());
    // Any size: k × k matrices, refused above the degree limit before they are built (sizes
    // up to usize::MAX once built an identity of that size).
    ok(
        "conversion::GeometryForm::to_bezier",
        from.to_bezier::<f64>(k),
    );
    ok(
        "conversion::GeometryForm::from_bezier",
        to.from_bezier::<f64>(k),
    );
    ok(
        "conversion::form_conversion",
        form_conversion::<f64>(from, to, k),
    );
    total(
        "conversion::form_conversion_cost",
        form_conversion_cost(size(rng), size(rng), u128::from(rng.below(200) as u8)),
    );
}

/// The joint of two Bézier curves, the free point of a joint, their cost.
pub fn joints(rng: &Draws) {
    total(
        "continuity::bezier_joint_cost",
        cagd::continuity::bezier_joint_cost(size(rng), size(rng), 64),
    );
    let (Some(a), Some(b)) = (curve(rng), curve(rng)) else {
        return;
    };
    ok(
        "continuity::bezier_joint",
        cagd::continuity::bezier_joint(&a, &b).map(|j| {
            (
                vec![j.end, j.start, j.d_end, j.d_start, j.dd_end, j.dd_start],
                j.k,
            )
        }),
    );
    let known = matrix(rng, a.dim() + rng.below(6) / 5, small(rng));
    ok(
        "continuity::free_point_line",
        cagd::continuity::free_point_line(&known, &b),
    );
}

/// Integrals of Bernstein polynomials, Bézier and B-spline curves, and their costs.
pub fn integrals(rng: &Draws) {
    let n = size(rng);
    total("integral::bernstein_integral", bernstein_integral::<f64>(n));
    let rows: Vec<usize> = (0..small(rng)).map(|_| size(rng)).collect();
    ok(
        "integral::bernstein_antiderivative_values",
        bernstein_antiderivative_values::<f64>(n, &rows, &parameters(rng, small(rng))),
    );
    ok(
        "integral::bernstein_antiderivative_values (small)",
        bernstein_antiderivative_values::<f64>(n % 40, &[0, n % 41], &[parameter(rng)]),
    );
    total(
        "integral::bernstein_antiderivative_cost",
        bernstein_antiderivative_cost(n, size(rng), size(rng), 64),
    );
    total(
        "integral::antiderivative_cost",
        antiderivative_cost(size(rng), size(rng), size(rng), 64),
    );
    if let Some(c) = curve(rng) {
        ok(
            "integral::bezier_antiderivative_factor",
            bezier_antiderivative_factor(&c),
        );
    }
    let c = BSplineCurve::clamped(small(rng), matrix(rng, 1 + small(rng) % 3, small(rng)));
    if let Ok(c) = c {
        ok(
            "integral::bspline_basis_integrals",
            Ok(bspline_basis_integrals(&c)),
        );
        let extrapolation = extrapolation(rng);
        let (a, b) = (parameter(rng), parameter(rng));
        ok(
            "bspline::BSplineCurve::integral",
            c.integral(a, b, extrapolation),
        );
        if let Ok(f) = bspline_antiderivative(&c) {
            ok(
                "integral::bspline_integral_to",
                bspline_integral_to(&f, parameter(rng), &parameters(rng, small(rng))),
            );
        }
    }
}

fn extrapolation(rng: &Draws) -> Extrapolation<f64> {
    match rng.below(3) {
        0 => Extrapolation::Continue,
        1 => Extrapolation::Periodic,
        // The fill value is the caller's: NaN is scipy's `extrapolate=False`.
        _ => Extrapolation::Outside(mostly_finite(rng)),
    }
}

/// The entries of an extrapolated batch `out` (`us.len() × d`) that must be finite: all of
/// them, but for the points outside the domain when the caller chose a non-finite fill value
/// (written there as given).
fn computed_entries(
    out: &[f64],
    us: &[f64],
    c: &BSplineCurve,
    extrapolation: &Extrapolation<f64>,
) -> Vec<f64> {
    let (lo, hi) = c.domain();
    let filled_by_caller = |u: f64| {
        matches!(extrapolation, Extrapolation::Outside(v) if !v.is_finite()) && (u < lo || u > hi)
    };
    us.iter()
        .zip(out.chunks(c.dim().max(1)))
        .filter(|(u, _)| !filled_by_caller(**u))
        .flat_map(|(_, point)| point.iter().copied())
        .collect()
}

/// Design matrices, basis elements, Boehm schemes, derivatives and extrapolation of B-splines;
/// the costs of the triangle, insertion, elevation and surface points.
pub fn bspline_extras(rng: &Draws) {
    let (p, n) = (small(rng), small(rng));
    let k = knots(rng, n + p + 1);
    let xs = parameters(rng, small(rng));
    // The degree as drawn for these knots, or any size.
    ok(
        "bspline::design_matrix",
        design_matrix(degree(rng, p), &k, &xs, rng.below(2) == 0).map(|a| a.values),
    );
    if let Ok(a) = design_matrix(p, &k, &xs, false) {
        ok("bspline::DesignMatrix::to_dense", Ok(a.to_dense()));
    }
    ok(
        "bspline::BSplineCurve::basis_element",
        BSplineCurve::<f64>::basis_element(&knots(rng, small(rng))).map(|c| c.control().clone()),
    );
    total(
        "bspline::triangle_cost",
        triangle_cost(size(rng), size(rng), 64, 64),
    );
    total(
        "bspline::wrap_periodic",
        wrap_periodic(value(rng), &finite(rng), &finite(rng)),
    );
    total(
        "bernstein::elevate_cost",
        cagd::bernstein::elevate_cost(size(rng), size(rng), 64),
    );
    if let Some(b) = curve(rng) {
        total(
            "bezier::BezierCurve::elevate_cost",
            b.elevate_cost(size(rng), 64),
        );
        total(
            "bezier::BezierCurve as CurveDeriv2::eval_second_derivative",
            b.eval_second_derivative(parameter(rng)),
        );
    }
    let Ok(c) = BSplineCurve::new(degree(rng, p), k, matrix(rng, 1 + small(rng) % 3, n)) else {
        return;
    };
    total(
        "bspline::BSplineCurve::insertion_cost",
        c.insertion_cost(size(rng), 64),
    );
    ok(
        "bspline::BSplineCurve::boehm_scheme",
        c.boehm_scheme(&parameters(rng, small(rng)))
            .map(|steps| steps.into_iter().map(|s| s.curve).collect::<Vec<_>>()),
    );
    ok(
        "bspline::BSplineCurve::derivative_of_order",
        c.derivative_of_order(size(rng)),
    );
    let us = parameters(rng, small(rng));
    let mut out = vec![0.0; us.len() * c.dim() + rng.below(2)];
    let extrapolation = extrapolation(rng);
    if ok(
        "bspline::BSplineCurve::eval_many_extrapolated_into",
        c.eval_many_extrapolated_into(&us, &mut out, &extrapolation),
    )
    .is_some()
    {
        let computed = computed_entries(&out, &us, &c, &extrapolation);
        ok("eval_many_extrapolated_into (buffer)", Ok(computed));
    }
    if ok(
        "bspline::BSplineCurve::eval_derivative_many_into",
        c.eval_derivative_many_into(size(rng), &us, &mut out, &extrapolation),
    )
    .is_some()
    {
        let computed = computed_entries(&out, &us, &c, &extrapolation);
        ok("eval_derivative_many_into (buffer)", Ok(computed));
    }
    total(
        "bspline::BSplineCurve as CurveDeriv2::eval_second_derivative",
        c.eval_second_derivative(parameter(rng)),
    );
}

/// Point costs of B-spline and NURBS surfaces, homogeneous points, NURBS second derivatives.
pub fn nurbs_extras(rng: &Draws) {
    let d = 1 + small(rng) % 3;
    let (m, n) = (1 + small(rng), 1 + small(rng));
    let coords: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
    let (p, q) = (small(rng) % 4, small(rng) % 4);
    if let Ok(s) = BSplineSurface::clamped(degree(rng, p), degree(rng, q), coords.clone()) {
        total("bspline::BSplineSurface::point_cost", s.point_cost(64, 64));
        let w = DMatrix::from_vec(m, n, weights(rng, m * n));
        let (ku, kv) = (
            s.knots().0.as_slice().to_vec(),
            s.knots().1.as_slice().to_vec(),
        );
        if let Ok(s) = NurbsSurface::new(p, q, ku, kv, coords, w) {
            total("nurbs::NurbsSurface::point_cost", s.point_cost(64, 64));
        }
    }
    let points = matrix(rng, d, n);
    ok(
        "nurbs::homogenize",
        homogenize("weights", &points, &weights(rng, n + rng.below(6) / 5)),
    );
    let k = knots(rng, n + p + 1);
    if let Ok(c) = NurbsCurve::new(degree(rng, p), k, points, weights(rng, n)) {
        total(
            "nurbs::NurbsCurve as CurveDeriv2::eval_second_derivative",
            c.eval_second_derivative(parameter(rng)),
        );
    }
}

/// Curvature, its cost and the Frenet frame, from arbitrary derivatives.
pub fn curvature(rng: &Draws) {
    let d = small(rng);
    let v = |rng: &Draws| vector(rng, if rng.below(10) == 0 { d + 1 } else { d });
    ok(
        "curvature::curvature_squared",
        curvature_squared(&v(rng), &v(rng)),
    );
    ok(
        "curvature::frenet",
        frenet(&v(rng), &v(rng)).map(|f| (f.curvature, f.tangent, (f.normal, f.binormal))),
    );
    total("curvature::curvature_cost", curvature_cost(size(rng), 64));
}

/// Lagrange nodes in any order, `linspace_in`.
pub fn nodes(rng: &Draws) {
    let n = small(rng);
    if let Some(l) = ok_with(
        "lagrange::NodesInAnyOrder::new",
        NodesInAnyOrder::new(values(rng, n)),
        |l| l.sorted().clone(),
    ) {
        total("lagrange::NodesInAnyOrder::sorted", l.sorted());
        total("lagrange::NodesInAnyOrder::increasing", l.increasing());
        ok("lagrange::NodesInAnyOrder::span", Ok(l.span()));
        total("lagrange::NodesInAnyOrder::basis", l.basis(&parameter(rng)));
        ok(
            "lagrange::NodesInAnyOrder::interpolate",
            l.interpolate(
                &matrix(rng, small(rng), n + rng.below(6) / 5),
                &parameter(rng),
            ),
        );
    }
    ok(
        "linspace::linspace_in",
        cagd::linspace::linspace_in(&value(rng), &value(rng), memory(rng)),
    );
}

/// The spline's linear system and parameter wrap, the parametrizations' parameters.
pub fn spline_extras(rng: &Draws) {
    let points = matrix(rng, 1 + small(rng) % 3, small(rng));
    let how = rng.pick(&[
        Parametrization::Uniform,
        Parametrization::Chord,
        Parametrization::Centripetal,
    ]);
    ok(
        "spline::Parametrization::params",
        how.params(&points, rng.below(2) == 0),
    );
    if let Ok(s) = CubicSpline::interpolate(points, EndCondition::Natural) {
        total(
            "spline::CubicSpline::system",
            s.system(&EndCondition::Natural),
        );
        total("spline::CubicSpline::wrap", s.wrap(&value(rng)));
    }
}

/// Closures with a cost and a derivative, and reparametrised; Ferguson patches from a Coons
/// boundary; ruled and Ferguson costs; the three parts of the discrete Coons formula.
pub fn patch_extras(rng: &Draws) {
    let f = FnCurve::with_derivative(
        1,
        |t: f64| DVector::from_element(1, t * t),
        |t: f64| DVector::from_element(1, 2.0 * t),
    )
    .with_cost(Cost::new(size(rng) as u128, 64));
    curve_methods(rng, "param::FnCurve", &f);
    deriv_methods(rng, "param::FnCurve", &f);
    total("param::FnCurve::with_cost", Curve::point_cost(&f, 0));
    if let Ok(c) = f.with_domain(mostly_finite(rng), mostly_finite(rng)) {
        if let Ok(unit) = OnUnitInterval::new(c, "c") {
            deriv_methods(rng, "param::OnUnitInterval", &unit);
        }
    }
    total(
        "surfaces::ruled_point_cost",
        ruled_point_cost([Cost::new(size(rng) as u128, 64); 2], size(rng), 64, 64),
    );
    total(
        "surfaces::ferguson_point_cost",
        ferguson_point_cost(size(rng), 64, 64, 64),
    );
    total(
        "coons::discrete_coons_parts_cost",
        discrete_coons_parts_cost(size(rng), size(rng), size(rng)),
    );
    let (m, n, d) = (small(rng), small(rng), small(rng) % 4);
    let net: Vec<DMatrix<f64>> = (0..d).map(|_| matrix(rng, m, n)).collect();
    ok(
        "coons::discrete_coons_parts",
        discrete_coons_parts(&net).map(|parts| parts.concat()),
    );
    let d = 1 + small(rng) % 3;
    let corner = |rng: &Draws| vector(rng, d);
    let [p00, p10, p01, p11] = [corner(rng), corner(rng), corner(rng), corner(rng)];
    let line = |a: &DVector<f64>, b: &DVector<f64>| {
        BezierCurve::new(DMatrix::from_columns(&[a.clone(), b.clone()]))
    };
    if let (Ok(c1), Ok(c2), Ok(d1), Ok(d2)) = (
        line(&p00, &p10),
        line(&p01, &p11),
        line(&p00, &p01),
        line(&p10, &p11),
    ) {
        if let Ok(boundary) = CoonsBoundary::new(c1, c2, d1, d2, Tolerance::default()) {
            let twist = [[corner(rng), corner(rng)], [corner(rng), corner(rng)]];
            ok(
                "surfaces::FergusonPatch::from_boundary",
                FergusonPatch::from_boundary(&boundary, &twist).map(|p| p.geometry().to_vec()),
            );
        }
    }
}

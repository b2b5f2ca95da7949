//! Lagrange bases and interpolants, node placements, interpolating splines and their
//! tridiagonal solves, Hermite cubics, the interpolation forms of the lecture notes.

use cagd::hermite::{basis_cost, hermite_basis, hermite_basis_derivative, HermiteCubic};
use cagd::interpolation::{
    blending_matrix, LagrangePolynomial, ParametricInterpolant, PiecewiseLinear,
};
use cagd::lagrange::{
    basis_product, bernstein_coefficients, chebyshev_nodes, check_distinct_nodes, check_nodes,
    power_coefficients, try_chebyshev_nodes, Lagrange, LagrangeInterpolant, NodePlacement,
};
use cagd::spline::{
    interpolation_cost, sample_cost, solve_cyclic_tridiagonal, solve_tridiagonal, CubicSpline,
    EndCondition,
};
use nalgebra::DVector;

use super::bezier::{curve, curve_methods, deriv_methods};
use super::check::{any, ok, total};
use super::draws::*;

/// Lagrange bases of arbitrary nodes (1001 equally spaced ones among them), their values,
/// interpolants, power and Bernstein forms, node placements.
pub fn lagrange(rng: &Draws) {
    super::course::nodes(rng);
    let nodes = ordered(rng, count(rng));
    let t = parameter(rng);
    ok(
        "lagrange::check_nodes",
        check_nodes("x", &nodes, size(rng)).map(|()| 0.0),
    );
    ok(
        "lagrange::check_distinct_nodes",
        check_distinct_nodes("x", &nodes, size(rng)).map(|()| 0.0),
    );
    ok(
        "lagrange::basis_product",
        basis_product(&nodes, size(rng), &t),
    );
    ok(
        "lagrange::power_coefficients",
        power_coefficients(&nodes, size(rng)),
    );
    ok(
        "lagrange::bernstein_coefficients",
        bernstein_coefficients(
            &nodes,
            if rng.below(2) == 0 {
                small(rng)
            } else {
                size(rng)
            },
        ),
    );
    ok(
        "lagrange::try_chebyshev_nodes",
        try_chebyshev_nodes(memory(rng)),
    );
    total("lagrange::chebyshev_nodes", chebyshev_nodes(small(rng)));
    ok(
        "lagrange::NodePlacement::try_nodes",
        NodePlacement::Uniform.try_nodes::<f64>(memory(rng)),
    );
    total(
        "lagrange::NodePlacement::nodes",
        NodePlacement::Chebyshev.nodes::<f64>(small(rng)),
    );
    total(
        "lagrange::Lagrange::weights_cost",
        Lagrange::<f64>::weights_cost(size(rng), 64),
    );
    total(
        "lagrange::Lagrange::basis_cost",
        Lagrange::<f64>::basis_cost(size(rng), 64, 64),
    );
    total(
        "lagrange::Lagrange::interpolation_cost",
        Lagrange::<f64>::interpolation_cost(size(rng), size(rng), 64, 64, 64),
    );
    let Some(l) = ok("lagrange::Lagrange::new", Lagrange::new(nodes)) else {
        return;
    };
    total("lagrange::Lagrange::nodes", l.nodes());
    total("lagrange::Lagrange::weights", l.weights());
    total("lagrange::Lagrange::degree", l.degree());
    total("lagrange::Lagrange::basis", l.basis(&t));
    total(
        "lagrange::Lagrange::lebesgue_function",
        l.lebesgue_function(&t),
    );
    let mut out = vec![0.0; l.nodes().len() + rng.below(2)];
    if ok("lagrange::Lagrange::basis_into", l.basis_into(&t, &mut out)).is_some() {
        ok("lagrange::Lagrange::basis_into", Ok(out));
    }
    let values = matrix(rng, 1 + small(rng) % 3, l.nodes().len() + rng.below(2));
    ok(
        "lagrange::Lagrange::interpolate",
        l.interpolate(&values, &t),
    );
    ok(
        "lagrange::Lagrange::lebesgue_constant",
        l.lebesgue_constant(mostly_finite(rng), mostly_finite(rng), size(rng)),
    );
    let Some(i) = ok(
        "lagrange::LagrangeInterpolant::new",
        LagrangeInterpolant::new(l, values),
    ) else {
        return;
    };
    total("lagrange::LagrangeInterpolant::basis", i.basis());
    total("lagrange::LagrangeInterpolant::values", i.values());
    deriv_methods(rng, "lagrange::LagrangeInterpolant", &i);
}

/// The interpolation forms of the lecture notes: the Lagrange polynomial, piecewise linear
/// interpolation, the blending matrix and the parametric interpolant.
pub fn forms(rng: &Draws) {
    let n = count(rng).min(60);
    let (xs, ys) = (ordered(rng, n), finites(rng, n + rng.below(2)));
    let x = parameter(rng);
    if let Some(p) = any(
        "interpolation::LagrangePolynomial::new",
        LagrangePolynomial::new(xs.clone(), ys.clone()),
    ) {
        total("interpolation::LagrangePolynomial::eval", p.eval(x));
        ok(
            "interpolation::LagrangePolynomial::coefficients",
            p.coefficients(),
        );
    }
    if let Some(p) = any(
        "interpolation::PiecewiseLinear::new",
        PiecewiseLinear::new(xs.clone(), ys),
    ) {
        total("interpolation::PiecewiseLinear::eval", p.eval(x));
    }
    ok("interpolation::blending_matrix", blending_matrix(&xs));
    let points = matrix(rng, 1 + small(rng) % 3, n + rng.below(2));
    if let Some(p) = ok(
        "interpolation::ParametricInterpolant::new",
        ParametricInterpolant::new(points, xs),
    ) {
        total("interpolation::ParametricInterpolant::params", p.params());
        total("interpolation::ParametricInterpolant::points", p.points());
        total(
            "interpolation::ParametricInterpolant::algebraic",
            p.algebraic(),
        );
        total("interpolation::ParametricInterpolant::eval", p.eval(x));
        curve_methods(rng, "interpolation::ParametricInterpolant", &p);
    }
}

/// Interpolating cubic splines through arbitrary points at arbitrary parameters (5·10⁻³²⁴
/// apart among them), and the tridiagonal solves behind them.
pub fn splines(rng: &Draws) {
    super::course::spline_extras(rng);
    let n = count(rng).min(60);
    let d = 1 + small(rng) % 3;
    let points = matrix(rng, d, n);
    let end = match rng.below(3) {
        0 => EndCondition::Natural,
        1 => EndCondition::Closed,
        _ => EndCondition::Clamped {
            start: vector(rng, d + rng.below(2)),
            end: vector(rng, d),
        },
    };
    total(
        "spline::interpolation_cost",
        interpolation_cost(size(rng), size(rng), &end, 64),
    );
    total(
        "spline::sample_cost",
        sample_cost(size(rng), size(rng), 64, 64),
    );
    let params = ordered(rng, n + usize::from(matches!(end, EndCondition::Closed)));
    let made = if rng.below(3) == 0 {
        ok(
            "spline::CubicSpline::interpolate",
            CubicSpline::interpolate(points, end),
        )
    } else {
        ok(
            "spline::CubicSpline::interpolate_with_params",
            CubicSpline::interpolate_with_params(points, params, end),
        )
    };
    let k = small(rng);
    let rhs: Vec<DVector<f64>> = (0..k).map(|_| vector(rng, 1 + small(rng) % 2)).collect();
    let (sub, diag, sup) = (finites(rng, k), finites(rng, k), finites(rng, k));
    ok(
        "spline::solve_tridiagonal",
        solve_tridiagonal(&sub, &diag, &sup, &rhs),
    );
    ok(
        "spline::solve_cyclic_tridiagonal",
        solve_cyclic_tridiagonal(&sub, &diag, &sup, &rhs),
    );
    let Some(s) = made else { return };
    let t = parameter(rng);
    total("spline::CubicSpline::params", s.params());
    total("spline::CubicSpline::points", s.points());
    total("spline::CubicSpline::tangents", s.tangents());
    total("spline::CubicSpline::is_closed", s.is_closed());
    total("spline::CubicSpline::dim", s.dim());
    total("spline::CubicSpline::segment_count", s.segment_count());
    ok("spline::CubicSpline::segment", s.segment(size(rng)));
    total(
        "spline::CubicSpline::eval_with_derivatives",
        s.eval_with_derivatives(t),
    );
    total("spline::CubicSpline::eval", s.eval(t));
    total(
        "spline::CubicSpline::eval_many",
        s.eval_many(&parameters(rng, small(rng))),
    );
    let ts = parameters(rng, small(rng));
    let mut out = vec![0.0; ts.len() * s.dim() + rng.below(2)];
    if ok(
        "spline::CubicSpline::eval_many_into",
        s.eval_many_into(&ts, &mut out),
    )
    .is_some()
    {
        ok("spline::CubicSpline::eval_many_into", Ok(out));
    }
    deriv_methods(rng, "spline::CubicSpline", &s);
}

/// Hermite (Ferguson) cubics from arbitrary points and tangents, and their bases.
pub fn hermite(rng: &Draws) {
    let t = parameter(rng);
    total("hermite::hermite_basis", hermite_basis(t));
    total(
        "hermite::hermite_basis_derivative",
        hermite_basis_derivative(t),
    );
    total("hermite::basis_cost", basis_cost(size(rng) as u128));
    let d = 1 + small(rng) % 3;
    let v = |rng: &Draws, d: usize| vector(rng, d);
    let made = if rng.below(2) == 0 {
        ok(
            "hermite::HermiteCubic::new",
            HermiteCubic::new(v(rng, d), v(rng, d), v(rng, d), v(rng, d + rng.below(2))),
        )
    } else {
        ok(
            "hermite::HermiteCubic::from_geometry",
            HermiteCubic::from_geometry(matrix(rng, d, 3 + rng.below(3))),
        )
    };
    if let Some(c) = curve(rng) {
        ok(
            "hermite::HermiteCubic::from_bezier",
            HermiteCubic::from_bezier(&c),
        );
    }
    let Some(h) = made else { return };
    total("hermite::HermiteCubic::geometry", h.geometry());
    total("hermite::HermiteCubic::dim", h.dim());
    total("hermite::HermiteCubic::eval", h.eval(t));
    total("hermite::HermiteCubic::eval_cost", h.eval_cost(64, 64));
    total(
        "hermite::HermiteCubic::eval_derivative",
        h.eval_derivative(t),
    );
    total(
        "hermite::HermiteCubic::eval_second_derivative",
        h.eval_second_derivative(t),
    );
    ok(
        "hermite::HermiteCubic::scaled_tangents",
        h.scaled_tangents(mostly_finite(rng)),
    );
    ok("hermite::HermiteCubic::to_bezier", h.to_bezier());
    deriv_methods(rng, "hermite::HermiteCubic", &h);
}

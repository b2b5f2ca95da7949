//! Bézier curves, their schemes and matrix forms; Bézier patches and their schemes.

use cagd::bezier::{bilinear_interpolate, BezierCurve, BezierPatch, Direction, Edge, MatrixForm};
use cagd::grid::PointGrid;
use cagd::{Curve, CurveDeriv, Surface};

use super::check::{ok, total};
use super::draws::*;

/// A Bézier curve from arbitrary control points, on `[0, 1]` or an arbitrary interval.
pub fn curve(rng: &Draws) -> Option<BezierCurve> {
    let control = matrix(rng, 1 + small(rng) % 3, small(rng));
    if rng.below(2) == 0 {
        ok("bezier::BezierCurve::new", BezierCurve::new(control))
    } else {
        let (a, b) = (mostly_finite(rng), mostly_finite(rng));
        ok(
            "bezier::BezierCurve::new_on_interval",
            BezierCurve::new_on_interval(control, a, b),
        )
    }
}

/// Constructors, evaluations, schemes, derivatives, subdivision and elevation of a curve.
pub fn curves(rng: &Draws) {
    let points: Vec<Vec<f64>> = (0..small(rng)).map(|_| finites(rng, small(rng))).collect();
    ok(
        "bezier::BezierCurve::from_points",
        BezierCurve::from_points(&points),
    );
    let Some(c) = curve(rng) else { return };
    let t = parameter(rng);
    total("bezier::BezierCurve::degree", c.degree());
    total("bezier::BezierCurve::dim", c.dim());
    total("bezier::BezierCurve::control", c.control());
    total(
        "bezier::BezierCurve::control_point",
        c.control_point(size(rng)),
    );
    total("bezier::BezierCurve::interval", c.interval());
    total("bezier::BezierCurve::domain", c.domain());
    total("bezier::BezierCurve::local_parameter", c.local_parameter(t));
    total("bezier::BezierCurve::eval", c.eval(t));
    ok("bezier::BezierCurve::try_eval", c.try_eval(t));
    total("bezier::BezierCurve::eval_bernstein", c.eval_bernstein(t));
    total("bezier::BezierCurve::eval_derivative", c.eval_derivative(t));
    total(
        "bezier::BezierCurve::eval_cost",
        c.eval_cost(size(rng) as u128, 64),
    );
    ok(
        "bezier::BezierCurve::eval_many",
        c.eval_many(&parameters(rng, small(rng))),
    );
    let ts = parameters(rng, small(rng));
    let mut out = vec![0.0; ts.len() * c.dim() + rng.below(2)];
    if ok(
        "bezier::BezierCurve::eval_many_into",
        c.eval_many_into(&ts, &mut out),
    )
    .is_some()
    {
        ok("bezier::BezierCurve::eval_many_into (buffer)", Ok(out));
    }
    ok("bezier::BezierCurve::derivative", c.derivative(size(rng)));
    ok("bezier::BezierCurve::hodograph", c.hodograph());
    ok("bezier::BezierCurve::subdivide", c.subdivide(t));
    total("bezier::BezierCurve::elevate", c.elevate());
    total("bezier::BezierCurve::reversed", c.reversed());
    ok(
        "bezier::BezierCurve::with_interval",
        c.clone()
            .with_interval(mostly_finite(rng), mostly_finite(rng)),
    );
    ok("bezier::BezierCurve::matrix_form", c.matrix_form());
    ok(
        "bezier::BezierCurve::eval_matrix_form",
        c.eval_matrix_form(t),
    );
    let scheme = total("bezier::BezierCurve::scheme", c.scheme(t));
    total("bezier::DeCasteljauScheme::parameter", scheme.parameter());
    total("bezier::DeCasteljauScheme::degree", scheme.degree());
    total("bezier::DeCasteljauScheme::dim", scheme.dim());
    total("bezier::DeCasteljauScheme::levels", scheme.levels());
    total("bezier::DeCasteljauScheme::level", scheme.level(size(rng)));
    total(
        "bezier::DeCasteljauScheme::point",
        scheme.point(size(rng), size(rng)),
    );
    total(
        "bezier::DeCasteljauScheme::point_on_curve",
        scheme.point_on_curve(),
    );
    total(
        "bezier::DeCasteljauScheme::left_control",
        scheme.left_control(),
    );
    total(
        "bezier::DeCasteljauScheme::right_control",
        scheme.right_control(),
    );
    deriv_methods(rng, "bezier::BezierCurve", &c);
}

/// Matrix (monomial) forms from arbitrary coefficients.
pub fn matrix_forms(rng: &Draws) {
    let coefficients = matrix(rng, 1 + small(rng) % 3, small(rng));
    let Some(f) = ok(
        "bezier::MatrixForm::from_coefficients",
        MatrixForm::from_coefficients(coefficients),
    ) else {
        return;
    };
    let t = parameter(rng);
    total("bezier::MatrixForm::coefficients", f.coefficients());
    total("bezier::MatrixForm::degree", f.degree());
    total("bezier::MatrixForm::dim", f.dim());
    total("bezier::MatrixForm::interval", f.interval());
    total("bezier::MatrixForm::eval", f.eval(t));
    ok("bezier::MatrixForm::to_bezier", f.to_bezier());
    curve_methods(rng, "bezier::MatrixForm", &f);
}

/// A Bézier patch from arbitrary coordinate matrices, nets or grids.
fn patch(rng: &Draws) -> Option<BezierPatch> {
    let (d, m, n) = (small(rng), small(rng), small(rng));
    match rng.below(4) {
        0 => {
            let net: Vec<Vec<Vec<f64>>> = (0..m)
                .map(|_| (0..n).map(|_| finites(rng, d)).collect())
                .collect();
            ok("bezier::BezierPatch::from_net", BezierPatch::from_net(&net))
        }
        1 => {
            let grid = PointGrid::from_shape_fn((m, n, d), |_| mostly_finite(rng));
            ok(
                "bezier::BezierPatch::from_grid",
                BezierPatch::from_grid(&grid),
            )
        }
        2 => {
            let corner = |rng: &Draws| finites(rng, 1 + small(rng) % 3);
            ok(
                "bezier::BezierPatch::bilinear",
                BezierPatch::bilinear(&corner(rng), &corner(rng), &corner(rng), &corner(rng)),
            )
        }
        _ => ok(
            "bezier::BezierPatch::new",
            BezierPatch::new((0..d).map(|_| matrix(rng, m, n)).collect()),
        ),
    }
}

/// Evaluations, schemes, derivatives and boundaries of a patch.
pub fn patches(rng: &Draws) {
    total(
        "bezier::BezierPatch::hyperbolic_paraboloid",
        BezierPatch::<f64>::hyperbolic_paraboloid(),
    );
    let corner = |rng: &Draws| finites(rng, 1 + small(rng) % 3);
    ok(
        "bezier::bilinear_interpolate",
        bilinear_interpolate(
            &corner(rng),
            &corner(rng),
            &corner(rng),
            &corner(rng),
            parameter(rng),
            parameter(rng),
        ),
    );
    let Some(p) = patch(rng) else { return };
    let (u, v) = (parameter(rng), parameter(rng));
    total("bezier::BezierPatch::to_grid", p.to_grid());
    total("bezier::BezierPatch::degree", p.degree());
    total("bezier::BezierPatch::dim", p.dim());
    total("bezier::BezierPatch::coordinates", p.coordinates());
    total(
        "bezier::BezierPatch::control_point",
        p.control_point(size(rng), size(rng)),
    );
    total("bezier::BezierPatch::eval", p.eval(u, v));
    ok("bezier::BezierPatch::try_eval", p.try_eval(u, v));
    total(
        "bezier::BezierPatch::eval_bernstein",
        p.eval_bernstein(u, v),
    );
    total(
        "bezier::BezierPatch::scheme_cost",
        p.scheme_cost(64, 64, 64),
    );
    total("bezier::BezierPatch::grid_cost", p.grid_cost(64, 64, 64));
    ok(
        "bezier::BezierPatch::derivative",
        p.derivative(size(rng), size(rng)),
    );
    ok("bezier::BezierPatch::twist", p.twist());
    // Degree elevation, subdivision and integration through the control curves.
    let (r, s) = (degree(rng, 2), degree(rng, 2));
    ok("bezier::BezierPatch::elevate", p.elevate(r, s));
    total(
        "bezier::BezierPatch::elevate_cost",
        p.elevate_cost(size(rng), size(rng), 64),
    );
    let dir = rng.pick(&[Direction::U, Direction::V]);
    total("bezier::BezierPatch::control_curves", p.control_curves(dir));
    ok(
        "bezier::BezierPatch::subdivide",
        p.subdivide(dir, value(rng)),
    );
    total(
        "bezier::BezierPatch::subdivide_cost",
        p.subdivide_cost(dir, 64, 64),
    );
    ok("bezier::BezierPatch::antiderivative", p.antiderivative(dir));
    total(
        "bezier::BezierPatch::antiderivative_cost",
        p.antiderivative_cost(dir, 64),
    );
    ok("bezier::BezierPatch::integral", p.integral());
    total("bezier::BezierPatch::integral_cost", p.integral_cost(64));
    let edge = rng.pick(&Edge::ALL);
    ok(
        "bezier::BezierPatch::boundary",
        Ok(total("bezier::BezierPatch::boundary", p.boundary(edge))),
    );
    let (us, vs) = (parameters(rng, small(rng)), parameters(rng, small(rng)));
    ok(
        "bezier::BezierPatch::try_eval_grid",
        p.try_eval_grid(&us, &vs),
    );
    let mut out = vec![0.0; us.len() * vs.len() * p.dim()];
    if ok(
        "bezier::BezierPatch::eval_grid_into",
        p.eval_grid_into(&us, &vs, &mut out),
    )
    .is_some()
    {
        ok("bezier::BezierPatch::eval_grid_into (buffer)", Ok(out));
    }
    let scheme = total("bezier::BezierPatch::scheme", p.scheme(u, v));
    total("bezier::PatchScheme::parameters", scheme.parameters());
    total("bezier::PatchScheme::level_count", scheme.level_count());
    total("bezier::PatchScheme::steps", scheme.steps());
    total("bezier::PatchScheme::level", scheme.level(size(rng)));
    total(
        "bezier::PatchScheme::level_shape",
        scheme.level_shape(size(rng)),
    );
    total(
        "bezier::PatchScheme::point",
        scheme.point(size(rng), size(rng), size(rng)),
    );
    total(
        "bezier::PatchScheme::point_on_surface",
        scheme.point_on_surface(),
    );
    surface_methods(rng, "bezier::BezierPatch", &p);
}

/// The `Surface` trait methods of any surface, under the names `"{name} as Surface::…"`.
pub fn surface_methods<S: Surface>(rng: &Draws, name: &'static str, s: &S) {
    let (u, v) = (parameter(rng), parameter(rng));
    let named = |method: &str| format!("{name} as Surface::{method}");
    total(&named("dim"), s.dim());
    total(&named("domain"), s.domain());
    total(&named("eval"), s.eval(u, v));
    ok(&named("try_eval"), s.try_eval(u, v));
    let (us, vs) = (parameters(rng, small(rng)), parameters(rng, small(rng)));
    total(&named("eval_grid"), s.eval_grid(&us, &vs));
    let mut out = vec![0.0; us.len() * vs.len() * s.dim() + rng.below(2)];
    if ok(
        &named("eval_grid_into"),
        s.eval_grid_into(&us, &vs, &mut out),
    )
    .is_some()
    {
        ok(&named("eval_grid_into (buffer)"), Ok(out));
    }
}

/// The `Curve` and `CurveDeriv` trait methods of a curve that knows its derivative, under the
/// names `"{name} as Curve::…"` and `"{name} as CurveDeriv::…"`.
pub fn deriv_methods<C: CurveDeriv>(rng: &Draws, name: &'static str, c: &C) {
    curve_methods(rng, name, c);
    let t = parameter(rng);
    let named = |method: &str| format!("{name} as CurveDeriv::{method}");
    total(&named("eval_derivative"), c.eval_derivative(t));
    ok(&named("try_eval_derivative"), c.try_eval_derivative(t));
}

/// The `Curve` trait methods of any curve, under the names `"{name} as Curve::…"`.
pub fn curve_methods<C: Curve>(rng: &Draws, name: &'static str, c: &C) {
    let t = parameter(rng);
    let named = |method: &str| format!("{name} as Curve::{method}");
    total(&named("dim"), c.dim());
    total(&named("domain"), c.domain());
    total(&named("eval"), c.eval(t));
    ok(&named("try_eval"), c.try_eval(t));
    total(&named("point_cost"), c.point_cost(rng.below(200) as u128));
    let ts = parameters(rng, small(rng));
    let mut out = vec![0.0; ts.len() * c.dim() + rng.below(2)];
    if ok(&named("eval_many_into"), c.eval_many_into(&ts, &mut out)).is_some() {
        ok(&named("eval_many_into (buffer)"), Ok(out));
    }
}

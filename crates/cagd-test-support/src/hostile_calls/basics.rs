//! Bernstein bases, binomials and degree elevation; the conversion matrices of the notes;
//! continuity; integrals; `linspace`; point grids; exact numbers and their doubles; limits,
//! costs and tolerances.

use cagd::bernstein::{self, binomial, binomial_f64, falling_factorial, power};
use cagd::conversion::{self, CubicForm};
use cagd::cost::{blended, polynomial_bits, Cost};
use cagd::exact::{rational_from_decimal, to_finite_f64};
use cagd::grid::PointGrid;
use cagd::limits::{exact_op_cost, Limit, Limits};
use cagd::tolerance::{Corner, Tolerance};
use cagd::Scalar;
use nalgebra::{DMatrix, DVector};
use num_rational::BigRational;

use super::bezier::curve;
use super::check::{any, ok, total};
use super::draws::*;

/// Bernstein polynomials of small degrees at arbitrary parameters; degree elevation to
/// arbitrary degrees; products.
pub fn bernstein(rng: &Draws) {
    let (n, t) = (small(rng), parameter(rng));
    total(
        "bernstein::bernstein",
        bernstein::bernstein(small(rng), n, t),
    );
    total("bernstein::bernstein_all", bernstein::bernstein_all(n, t));
    let mut out = vec![0.0; small(rng)];
    bernstein::bernstein_all_into(&t, &mut out);
    total("bernstein::bernstein_all_into", out);
    total(
        "bernstein::basis_cost",
        bernstein::basis_cost(size(rng), 64),
    );
    total(
        "bernstein::bernstein_derivative",
        bernstein::bernstein_derivative(small(rng), n, small(rng), t),
    );
    total(
        "bernstein::bernstein_derivative_all",
        bernstein::bernstein_derivative_all(n, small(rng), t),
    );
    total(
        "bernstein::basis_matrix",
        bernstein::basis_matrix(n, &parameters(rng, small(rng))),
    );
    total(
        "bernstein::basis_derivative_matrix",
        bernstein::basis_derivative_matrix(n, small(rng), &parameters(rng, small(rng))),
    );
    let (a, b) = (finites(rng, small(rng)), finites(rng, small(rng)));
    total("bernstein::elevate_once", bernstein::elevate_once(&a));
    ok(
        "bernstein::elevate",
        bernstein::elevate(
            &a,
            if rng.below(2) == 0 {
                small(rng) + small(rng)
            } else {
                size(rng)
            },
        ),
    );
    total("bernstein::product", bernstein::product(&a, &b));
    total(
        "bernstein::binomial",
        binomial(small(rng) * 40, small(rng) * 20),
    );
    total(
        "bernstein::binomial_f64",
        binomial_f64(size(rng), size(rng)),
    );
    total(
        "bernstein::binomial_scalar",
        bernstein::binomial_scalar::<f64>(small(rng) * 300, small(rng) * 150),
    );
    // In doubles both answer at once at any size (an infinite coefficient, the first
    // infinite product).
    total(
        "bernstein::binomial_scalar (any size)",
        bernstein::binomial_scalar::<f64>(size(rng), size(rng)),
    );
    total(
        "bernstein::falling_factorial",
        falling_factorial::<f64>(small(rng) * 100, small(rng) * 60),
    );
    total(
        "bernstein::falling_factorial (any size)",
        falling_factorial::<f64>(size(rng), size(rng)),
    );
    total("bernstein::power", power(&mostly_finite(rng), size(rng)));
}

/// The matrices of the matrix-form notes and the lecture notes, conversions of arbitrary
/// geometry, inversion of arbitrary matrices.
pub fn conversions(rng: &Draws) {
    super::course::forms(rng);
    let forms = [CubicForm::Hermite, CubicForm::Bezier, CubicForm::BSpline];
    let (from, to) = (rng.pick(&forms), rng.pick(&forms));
    total("conversion::CubicForm::matrix", from.matrix::<f64>());
    total(
        "conversion::CubicForm::lecture_notes_matrix",
        from.lecture_notes_matrix::<f64>(),
    );
    total("conversion::CubicForm::basis", from.basis(&parameter(rng)));
    total(
        "conversion::hermite_matrix",
        conversion::hermite_matrix::<f64>(),
    );
    total(
        "conversion::hermite_matrix_inverse",
        conversion::hermite_matrix_inverse::<f64>(),
    );
    total(
        "conversion::bezier_matrix",
        conversion::bezier_matrix::<f64>(),
    );
    total(
        "conversion::bspline_matrix",
        conversion::bspline_matrix::<f64>(),
    );
    total(
        "conversion::cubic_bezier_matrix",
        conversion::cubic_bezier_matrix::<f64>(),
    );
    total(
        "conversion::conversion_matrix",
        conversion::conversion_matrix::<f64>(from, to),
    );
    // Degree 1100 is above the default limit (refused at once); the overflow from degree 647
    // on is a unit test of the crate (a test build computes degree 700 for a second).
    let n = if rng.below(3) == 0 {
        size(rng)
    } else {
        rng.pick(&[small(rng), 1100])
    };
    ok(
        "conversion::bezier_to_monomial_matrix",
        conversion::bezier_to_monomial_matrix::<f64>(n),
    );
    ok(
        "conversion::monomial_to_bezier_matrix",
        conversion::monomial_to_bezier_matrix::<f64>(n),
    );
    let g = matrix(rng, small(rng), 2 + small(rng));
    ok("conversion::convert", conversion::convert(&g, from, to));
    let k = small(rng);
    ok(
        "conversion::invert",
        conversion::invert(&matrix(rng, k, k + rng.below(4) / 3)),
    );
}

/// Joints of arbitrary vectors and curves, free points; integrals of curves.
pub fn continuity(rng: &Draws) {
    super::course::joints(rng);
    super::course::integrals(rng);
    super::course::curvature(rng);
    let d = small(rng);
    let v = |rng: &Draws| vector(rng, if rng.below(10) == 0 { d + 1 } else { d });
    ok(
        "continuity::joint",
        cagd::continuity::joint((&v(rng), &v(rng)), (&v(rng), &v(rng)), value(rng)),
    );
    ok(
        "continuity::c1_free_point",
        cagd::continuity::c1_free_point(&v(rng), &v(rng)),
    );
    if let (Some(a), Some(b)) = (curve(rng), curve(rng)) {
        ok(
            "continuity::curve_joint",
            cagd::continuity::curve_joint(&a, parameter(rng), &b, parameter(rng), value(rng)),
        );
        ok(
            "integral::bezier_antiderivative",
            cagd::integral::bezier_antiderivative(&a),
        );
        ok(
            "integral::bezier_integral",
            cagd::integral::bezier_integral(&a),
        );
    }
    let n = small(rng);
    total(
        "integral::bernstein_antiderivative",
        cagd::integral::bernstein_antiderivative::<f64>(n, small(rng)),
    );
}

/// `linspace` of arbitrary ends and counts; point grids of arbitrary shapes.
pub fn grids(rng: &Draws) {
    let (a, b) = (value(rng), value(rng));
    ok(
        "linspace::try_linspace",
        cagd::linspace::try_linspace(a, b, memory(rng)),
    );
    // Any ends (NaN and ±∞ give NaNs, as in Octave); a count it can hold.
    total("linspace::linspace", cagd::linspace(a, b, small(rng)));
    let shape = (memory(rng), memory(rng), memory(rng));
    ok(
        "grid::PointGrid::try_from_shape_fn",
        PointGrid::try_from_shape_fn(shape, |_| 0.5),
    );
    ok(
        "grid::PointGrid::try_from_elem",
        PointGrid::try_from_elem(shape, 0.0),
    );
    let small_shape = (small(rng), small(rng), small(rng));
    let g = total(
        "grid::PointGrid::from_elem",
        PointGrid::from_elem(small_shape, mostly_finite(rng)),
    );
    total(
        "grid::PointGrid::from_shape_fn",
        PointGrid::from_shape_fn(small_shape, |_| 1.0),
    );
    total(
        "grid::PointGrid::from_vec",
        PointGrid::from_vec(shape, vec![0.0; small(rng)]),
    );
    total("grid::PointGrid::dim", g.dim());
    total("grid::PointGrid::shape", g.shape());
    total("grid::PointGrid::len", g.len());
    total("grid::PointGrid::is_empty", g.is_empty());
    total("grid::PointGrid::as_slice", g.as_slice());
    total("grid::PointGrid::iter", g.iter().count());
    total("grid::PointGrid::map", g.map(|x| x + 1.0));
    if !g.is_empty() {
        total("grid::PointGrid::point", g.point(0, 0));
    }
    let mut h = g.clone();
    total("grid::PointGrid::as_mut_slice", h.as_mut_slice().len());
    total("grid::PointGrid::into_vec", h.into_vec());
}

/// Exact decimals of arbitrary text, exact values to doubles; limits, costs, tolerances and
/// the checks of the error module.
pub fn numbers(rng: &Draws) {
    let texts = [
        "0.2",
        "-3.25e-1",
        "1e999999999",
        "1e-999999999",
        "1e99999999999999999999",
        "abc",
        "",
        ".",
        "1e",
        "12345678901234567890.5e-20",
    ];
    let text = if rng.below(3) == 0 {
        format!("{}e{}", rng.below(1000), size(rng) as i64)
    } else {
        rng.pick(&texts).to_string()
    };
    // An exact number has no non-finite value to check: only that it returns.
    if let Some(q) = any("exact::rational_from_decimal", rational_from_decimal(&text)) {
        let big = <BigRational as Scalar>::from_f64(1e308).expect("finite");
        let qs = [q.clone(), q * big.clone() * big];
        ok("exact::to_finite_f64", to_finite_f64("x", &qs));
    }
    total(
        "scalar::Scalar::from_f64",
        <f64 as Scalar>::from_f64(value(rng)),
    );
    total("scalar::Scalar::bits", value(rng).bits());
    let x = value(rng);
    ok(
        "error::check_finite",
        cagd::error::check_finite("x", &[x]).map(|()| 0.0),
    );
    ok(
        "error::check_overflow",
        cagd::error::check_overflow("x", &[x]).map(|()| 0.0),
    );
    let spaced = ordered(rng, small(rng));
    ok(
        "error::check_spacing",
        cagd::error::check_spacing("x", &spaced).map(|()| 0.0),
    );
    total("cost::max_bits", cagd::cost::max_bits(&spaced));
    total(
        "scalar::Scalar::from_ratio",
        f64::from_ratio(rng.bits() as i64, 1 + rng.below(9) as i64),
    );
    total("scalar::Scalar::to_f64", x.to_f64());
    total("scalar::Scalar::is_finite_value", x.is_finite_value());
    total("scalar::Scalar::from_usize", f64::from_usize(size(rng)));
    let big = cagd::bernstein::binomial(small(rng) * 40, small(rng) * 20);
    total("scalar::Scalar::from_biguint", f64::from_biguint(&big));
    total("scalar::Scalar::vectorized", f64::vectorized(|| x + 1.0));
    // The batch kernels' scans: any values, any length; the answers agree with the plain
    // definitions (a first non-finite value, all within [lo, hi] with NaN never within).
    let xs = values(rng, small(rng) * 100);
    let first = total(
        "scalar::Scalar::first_non_finite",
        f64::first_non_finite(&xs),
    );
    assert_eq!(first, xs.iter().position(|x| !x.is_finite()), "{xs:?}");
    let (lo, hi) = (value(rng), value(rng));
    let within = total("scalar::Scalar::all_within", f64::all_within(&xs, &lo, &hi));
    assert_eq!(
        within,
        xs.iter().all(|x| lo <= *x && *x <= hi),
        "{xs:?} in [{lo}, {hi}]"
    );
    ok(
        "error::check_finite_slice",
        cagd::error::check_finite_slice("xs", &xs).map(|()| 0.0),
    );
    let tol = rng.pick(&[
        Tolerance::Absolute(x),
        Tolerance::Relative(x),
        Tolerance::default(),
    ]);
    ok(
        "error::check_tolerance",
        cagd::error::check_tolerance(&tol).map(|()| 0.0),
    );
    total("tolerance::Tolerance::is_valid", tol.is_valid());
    let d = small(rng);
    total(
        "tolerance::Tolerance::gap",
        tol.gap(&vector(rng, d), &vector(rng, d)),
    );
    let corner = rng.pick(&Corner::ALL);
    total("tolerance::Corner::uv", corner.uv());
    total("tolerance::Corner::index", corner.index());
    let mut limits = Limits::default();
    let which = rng.pick(&Limit::ALL);
    limits.set(which, rng.bits());
    total("limits::Limits::set", &limits);
    total("limits::Limits::get", limits.get(which));
    total("limits::Limit::field", which.field());
    let n = size(rng);
    ok(
        "limits::Limits::check_samples",
        limits.check_samples("n", n).map(|()| 0.0),
    );
    ok(
        "limits::Limits::check_grid",
        limits.check_grid("n", n, size(rng)).map(|()| 0.0),
    );
    ok(
        "limits::Limits::check_degree",
        limits.check_degree("n", n).map(|()| 0.0),
    );
    ok(
        "limits::Limits::check_work",
        limits.check_work("n", rng.bits() as u128).map(|()| 0.0),
    );
    ok(
        "limits::Limits::check_system",
        limits.check_system("n", rng.bits() as u128).map(|()| 0.0),
    );
    total(
        "limits::exact_op_cost",
        exact_op_cost(u128::from(rng.bits()) << rng.below(64)),
    );
    let c = Cost::new(u128::from(rng.bits()), u128::from(rng.bits()));
    total("cost::Cost::new", c);
    total("cost::Cost::ops", c.ops());
    total("cost::Cost::bits", c.bits());
    total("cost::Cost::times", c.times(u128::from(rng.bits())));
    total("cost::Cost::and", c.and(c));
    total("cost::Cost::grown", c.grown(u128::from(rng.bits())));
    total(
        "cost::Cost::cheaper_when_exact",
        c.cheaper_when_exact(u128::from(rng.bits()) % 3),
    );
    total("cost::Cost::weigh", c.weigh(rng.below(2) == 0));
    total(
        "cost::polynomial_bits",
        polynomial_bits(size(rng), u128::from(rng.bits()), 1),
    );
    total("cost::blended", blended([c, c], u128::from(rng.bits()), 7));
    let m = DMatrix::from_element(1, 1, 0.5);
    total("scalar::Scalar::mat_mul", f64::mat_mul(&m, &m));
    let _ = DVector::<f64>::zeros(0);
}

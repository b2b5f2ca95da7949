//! Octave matrix literals, ranges, curve expressions and data scripts, checked against values
//! printed by GNU Octave 7.3 and against exact rational arithmetic.
//!
//! The Octave values below were printed with
//! `p = @(x) printf('%s\n', strjoin(arrayfun(@(y) sprintf('%.17g', y), x, 'UniformOutput', false), ', '));`
//! followed by the expression named in each comment, e.g. `p(0:0.1:1)`, run by
//! `octave --no-gui --quiet`. `%.17g` round-trips doubles, so equality is bit-for-bit.

// The expected values are copied as Octave prints them, with 17 significant digits.
#![allow(clippy::excessive_precision)]

use nalgebra::DMatrix;
use num_rational::BigRational;
use proptest::prelude::*;

use cagd::limits::Limits;
use cagd_octave::literal::{
    parse_matrix, parse_number, parse_params, Env, Expr, LiteralError, ParamExpr, Position,
};
use cagd_octave::script::{run, Binding};

fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn rows(r: usize, c: usize, v: &[f64]) -> DMatrix<f64> {
    DMatrix::from_row_slice(r, c, v)
}

// ---------------------------------------------------------------------------------------
// Matrix literals

#[test]
fn thesis_control_points_with_transpose() {
    let b = parse_matrix::<f64>("[0 0 0; 0 2 2; 8 2 0; 4 0 0]'").unwrap();
    assert_eq!(
        b,
        rows(3, 4, &[0., 0., 8., 4., 0., 2., 2., 0., 0., 2., 0., 0.])
    );
    // `.'` is the same transpose for real numbers.
    assert_eq!(
        parse_matrix::<f64>("[0 0 0; 0 2 2; 8 2 0; 4 0 0].'").unwrap(),
        b
    );
}

#[test]
fn separators_commas_newlines_and_comments() {
    let expected = rows(2, 3, &[1., 2., 3., 4., 5., 6.]);
    for text in [
        "[1 2 3; 4 5 6]",
        "[1,2,3;4,5,6]",
        "[1, 2, 3\n 4, 5, 6]",
        "[1 2 3 % first row\n 4 5 6]",
        "[1 2 3; ...\n 4 5 6]",
        "[1\t2\t3;4 5 6;]",
        "  [1 2 3; 4 5 6];  ",
        "[1 2 3;;4 5 6]",
    ] {
        assert_eq!(parse_matrix::<f64>(text).unwrap(), expected, "{text:?}");
    }
}

#[test]
fn white_space_decides_unary_or_binary_minus() {
    assert_eq!(
        parse_matrix::<f64>("[1 -2]").unwrap(),
        rows(1, 2, &[1., -2.])
    );
    assert_eq!(parse_matrix::<f64>("[1 - 2]").unwrap(), rows(1, 1, &[-1.]));
    assert_eq!(
        parse_matrix::<f64>("[1 -2 + 3]").unwrap(),
        rows(1, 2, &[1., 1.])
    );
    assert_eq!(parse_matrix::<f64>("[1-2]").unwrap(), rows(1, 1, &[-1.]));
    assert_eq!(
        parse_matrix::<f64>("[1 +2]").unwrap(),
        rows(1, 2, &[1., 2.])
    );
    assert_eq!(
        parse_matrix::<f64>("[-1 -2]").unwrap(),
        rows(1, 2, &[-1., -2.])
    );
}

#[test]
fn numbers_as_octave_writes_them() {
    assert_eq!(
        parse_matrix::<f64>("[1e-3 .5 5. 2E2 1.5e+1]").unwrap(),
        rows(1, 5, &[1e-3, 0.5, 5.0, 200.0, 15.0])
    );
    // Octave: p([0.1*3, 0.1+0.2, 1/3, 2^-2, -2^2, 2^3^2])
    assert_eq!(
        parse_matrix::<f64>("[0.1*3, 0.1+0.2, 1/3, 2^-2, -2^2, 2^3^2]").unwrap(),
        rows(
            1,
            6,
            &[
                0.30000000000000004,
                0.30000000000000004,
                0.33333333333333331,
                0.25,
                -4.0,
                64.0
            ]
        )
    );
}

#[test]
fn nested_concatenation_of_bound_row_vectors() {
    // Appendix D: g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22] packs the network points.
    let mut env = Env::<f64>::new();
    let points = [
        ("g00", [0., 0., 0.]),
        ("g01", [0.5, 0., 0.25]),
        ("g02", [1., 0., 0.]),
        ("g10", [0., 0.5, 0.5]),
        ("g11", [0.5, 0.5, 0.75]),
        ("g12", [1., 0.5, 0.5]),
        ("g20", [0., 1., 1.]),
        ("g21", [0.5, 1., 1.25]),
        ("g22", [1., 1., 1.]),
    ];
    for (name, p) in points {
        env.bind(name, rows(1, 3, &p));
    }
    let g = Expr::parse("[g00 g10 g20; g01 g11 g21; g02 g12 g22]")
        .unwrap()
        .eval(&mut env)
        .unwrap();
    assert_eq!(g.shape(), (3, 9));
    assert_eq!(
        g.row(1).iter().copied().collect::<Vec<_>>()[3..6],
        [0.5, 0.5, 0.75]
    );
    assert_eq!(g[(2, 8)], 1.0);
    assert_eq!(env.warnings().count(), 0);
}

#[test]
fn exact_decimals_are_exact_rationals() {
    let m = parse_matrix::<BigRational>("[0.2 0.1+0.2; 1/3 -2.5e-1]").unwrap();
    assert_eq!(m[(0, 0)], r(1, 5));
    assert_eq!(m[(0, 1)], r(3, 10));
    assert_eq!(m[(1, 0)], r(1, 3));
    assert_eq!(m[(1, 1)], r(-1, 4));
    assert_eq!(
        parse_matrix::<BigRational>("2^-3").unwrap()[(0, 0)],
        r(1, 8)
    );
}

// ---------------------------------------------------------------------------------------
// Ranges and parameter lists

#[test]
fn ranges_have_octaves_elements() {
    let cases: &[(&str, &[f64])] = &[
        // p(0:0.1:1)
        (
            "0:0.1:1",
            &[
                0.0,
                0.10000000000000001,
                0.20000000000000001,
                0.30000000000000004,
                0.40000000000000002,
                0.5,
                0.60000000000000009,
                0.70000000000000007,
                0.80000000000000004,
                0.90000000000000002,
                1.0,
            ],
        ),
        // p(1:-0.1:0)
        (
            "1:-0.1:0",
            &[
                1.0,
                0.90000000000000002,
                0.80000000000000004,
                0.69999999999999996,
                0.59999999999999998,
                0.5,
                0.39999999999999991,
                0.29999999999999993,
                0.19999999999999996,
                0.099999999999999978,
                0.0,
            ],
        ),
        // p(-1:0.2:1)
        (
            "-1:0.2:1",
            &[
                -1.0,
                -0.80000000000000004,
                -0.59999999999999998,
                -0.39999999999999991,
                -0.19999999999999996,
                0.0,
                0.20000000000000018,
                0.40000000000000013,
                0.60000000000000009,
                0.80000000000000004,
                1.0,
            ],
        ),
        // p(0.1:0.1:0.5)
        (
            "0.1:0.1:0.5",
            &[
                0.10000000000000001,
                0.20000000000000001,
                0.30000000000000004,
                0.40000000000000002,
                0.5,
            ],
        ),
        // p(0:0.05:0.15): the last element is clamped to the limit 0.15.
        (
            "0:0.05:0.15",
            &[
                0.0,
                0.050000000000000003,
                0.10000000000000001,
                0.14999999999999999,
            ],
        ),
        // p(0:0.7:2.1): here 3*0.7 stays below the limit and is kept.
        (
            "0:0.7:2.1",
            &[
                0.0,
                0.69999999999999996,
                1.3999999999999999,
                2.0999999999999996,
            ],
        ),
        // p(2:5)
        ("2:5", &[2.0, 3.0, 4.0, 5.0]),
    ];
    for (text, expected) in cases {
        assert_eq!(&parse_params::<f64>(text).unwrap(), expected, "{text}");
        // In brackets a range is a row of the same elements.
        let m = parse_matrix::<f64>(&format!("[{text}]")).unwrap();
        assert_eq!(m.as_slice(), *expected, "[{text}]");
    }
}

#[test]
fn empty_and_single_element_ranges() {
    assert!(parse_params::<f64>("1:0").unwrap().is_empty());
    assert!(parse_params::<f64>("0:-1:1").unwrap().is_empty());
    assert_eq!(parse_params::<f64>("0:5:1").unwrap(), vec![0.0]);
}

#[test]
fn exact_ranges_step_exactly() {
    let t = parse_params::<BigRational>("0:0.1:0.3").unwrap();
    assert_eq!(t, vec![r(0, 1), r(1, 10), r(1, 5), r(3, 10)]);
    let t = parse_params::<BigRational>("0:1/3:1").unwrap();
    assert_eq!(t, vec![r(0, 1), r(1, 3), r(2, 3), r(1, 1)]);
}

#[test]
fn parameter_lists_and_linspace() {
    assert_eq!(
        parse_params::<f64>("[0 0.25 0.5]").unwrap(),
        vec![0.0, 0.25, 0.5]
    );
    assert_eq!(parse_params::<f64>("[0; 0.5]").unwrap(), vec![0.0, 0.5]);
    assert_eq!(parse_params::<f64>("0.5").unwrap(), vec![0.5]);
    assert_eq!(
        parse_params::<f64>("linspace(0,1,5)").unwrap(),
        cagd::linspace(0.0, 1.0, 5)
    );
    assert_eq!(
        parse_params::<BigRational>("linspace(0,1,4)").unwrap(),
        vec![r(0, 1), r(1, 3), r(2, 3), r(1, 1)]
    );
    assert!(matches!(
        parse_params::<f64>("[0 1; 2 3]"),
        Err(LiteralError::Shape { .. })
    ));
}

// ---------------------------------------------------------------------------------------
// Expressions in a parameter

#[test]
fn thesis_curves_sampled_per_parameter_value() {
    let w = cagd::linspace(0.0, 1.0, 7);
    let c1 = ParamExpr::parse("[u; 0; u-u^2]").unwrap();
    let mut env = Env::<f64>::new();
    assert_eq!(c1.parameters(&env), vec!["u"]);
    let pts = c1.sample_curve(&mut env, "u", &w).unwrap();
    assert_eq!(pts.shape(), (3, 7));
    assert_eq!(pts.row(0).iter().copied().collect::<Vec<_>>(), w);
    // w = linspace(0,1,7); for k=1:7; q(k) = w(k)-w(k)^2; end; p(q)
    let octave = [
        0.0,
        0.1388888888888889,
        0.22222222222222221,
        0.25,
        0.22222222222222221,
        0.13888888888888884,
        0.0,
    ];
    assert_eq!(pts.row(2).iter().copied().collect::<Vec<_>>(), octave);
    assert_eq!(
        env.warnings().count(),
        0,
        "per-sample evaluation is plain Octave"
    );

    let d1 = ParamExpr::parse("[0.5; v; 0.25+v]").unwrap();
    let p = d1.sample_curve(&mut env, "v", &[0.5]).unwrap();
    assert_eq!(p.as_slice(), &[0.5, 0.5, 0.75]);
    // A row vector is a point too (the thesis's comment writes c2 = [u,1,u]).
    let c2 = ParamExpr::parse("[u,1,u]").unwrap();
    assert_eq!(
        c2.sample_curve(&mut env, "u", &[0.25]).unwrap().as_slice(),
        &[0.25, 1.0, 0.25]
    );
}

#[test]
fn scalar_power_is_pow_but_array_power_is_repeated_multiplication() {
    let w = cagd::linspace(0.0, 1.0, 7);
    let mut env = Env::<f64>::new();
    // for k=1:7; q3(k) = w(k)^3; end; p(q3)
    let scalar = [
        0.0,
        0.0046296296296296285,
        0.037037037037037028,
        0.125,
        0.29629629629629639,
        0.57870370370370383,
        1.0,
    ];
    let per_sample = ParamExpr::parse("u^3")
        .unwrap()
        .sample_curve(&mut env, "u", &w)
        .unwrap();
    assert_eq!(per_sample.as_slice(), scalar);
    // p(w.^3): Octave's elem_xpow computes x*x*x, which differs in the last bit.
    let array = [
        0.0,
        0.0046296296296296294,
        0.037037037037037035,
        0.125,
        0.29629629629629639,
        0.57870370370370383,
        1.0,
    ];
    env.bind("w", DMatrix::from_row_slice(1, 7, &w));
    let m = Expr::parse("w.^3").unwrap().eval(&mut env).unwrap();
    assert_eq!(m.as_slice(), array);
}

#[test]
fn functions_and_constants() {
    let mut env = Env::<f64>::new();
    let e = ParamExpr::parse("[cos(2*pi*t); sin(2*pi*t); sqrt(t)+abs(-t)+exp(0)+log(e)+tan(0)]")
        .unwrap();
    let p = e.sample_curve(&mut env, "t", &[0.25]).unwrap();
    assert!((p[0] - 0.0).abs() < 1e-15);
    assert_eq!(p[1], 1.0);
    assert_eq!(p[2], 0.5 + 0.25 + 1.0 + 1.0 + 0.0);
}

#[test]
fn exact_curve_values() {
    // Exact evaluation of the thesis's c1 at u = 1/5: (1/5, 0, 4/25).
    let c1 = ParamExpr::parse("[u; 0; u-u^2]").unwrap();
    let p = c1
        .sample_curve(&mut Env::<BigRational>::new(), "u", &[r(1, 5)])
        .unwrap();
    assert_eq!(p.as_slice(), &[r(1, 5), r(0, 1), r(4, 25)]);
    let err = ParamExpr::parse("[u; sin(u)]")
        .unwrap()
        .sample_curve(&mut Env::<BigRational>::new(), "u", &[r(1, 2)])
        .unwrap_err();
    assert!(matches!(err, LiteralError::NotRational { ref name, .. } if name == "sin"));
    let err = parse_matrix::<BigRational>("2^0.5").unwrap_err();
    assert!(matches!(err, LiteralError::NotRational { .. }));
    let err = parse_matrix::<BigRational>("1/(1-1)").unwrap_err();
    assert!(matches!(err, LiteralError::DivisionByZero { .. }));
}

#[test]
fn surface_expression_on_a_grid() {
    let e = ParamExpr::parse("[u; v; u.*v]").unwrap();
    let g = e
        .sample_surface(&mut Env::<f64>::new(), &[0.0, 0.5, 1.0], &[0.0, 1.0])
        .unwrap();
    assert_eq!(g.dim(), (3, 2, 3));
    assert_eq!((g[[1, 1, 0]], g[[1, 1, 1]], g[[1, 1, 2]]), (0.5, 1.0, 0.5));
}

// ---------------------------------------------------------------------------------------
// Errors

fn column(e: &LiteralError) -> usize {
    e.position().map(|p| p.column).unwrap_or(0)
}

#[test]
fn ragged_rows_name_the_row() {
    let e = parse_matrix::<f64>("[1 2; 3]").unwrap_err();
    assert_eq!(
        e,
        LiteralError::RaggedRows {
            at: Position { line: 0, column: 7 },
            row: 2,
            found: 1,
            expected: 2
        }
    );
    assert_eq!(e.to_string(), "column 7: row 2 has 1 column(s), expected 2");
    let e = parse_matrix::<f64>("[1 2 3\n4 5]").unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 2, column 1: row 2 has 2 column(s), expected 3"
    );
}

#[test]
fn unknown_names_are_named() {
    let e = ParamExpr::parse("[u; w]")
        .unwrap()
        .sample_curve(&mut Env::<f64>::new(), "u", &[0.0])
        .unwrap_err();
    assert_eq!(
        e,
        LiteralError::UnknownVariable {
            at: Position { line: 0, column: 5 },
            name: "w".into()
        }
    );
    // The other parameter is unknown to a curve in u.
    let e = ParamExpr::parse("[u; v]")
        .unwrap()
        .sample_curve(&mut Env::<f64>::new(), "u", &[0.0])
        .unwrap_err();
    assert!(matches!(e, LiteralError::UnknownVariable { ref name, .. } if name == "v"));
    let e = parse_matrix::<f64>("foo(3)").unwrap_err();
    assert!(matches!(e, LiteralError::UnknownFunction { ref name, .. } if name == "foo"));
}

#[test]
fn syntax_errors_say_what_was_expected() {
    let cases: &[(&str, usize, &str)] = &[
        (
            "[1 2",
            5,
            "expected `]` to close the `[` opened at column 1, found end of input",
        ),
        ("(1+2", 5, "expected `)`, found end of input"),
        (
            "1 +",
            4,
            "expected a number, a name, `(` or `[`, found end of input",
        ),
        ("[1,,2]", 4, "expected an element before `,`, found `,`"),
        (
            "2u",
            1,
            "expected an operator or separator after the number `2`, found `u`",
        ),
        (
            "1e",
            1,
            "expected digits after the exponent mark of a number, found `1e`",
        ),
        ("1 2", 3, "expected end of input, found the number `2`"),
    ];
    for (text, col, message) in cases {
        let e = parse_matrix::<f64>(text).unwrap_err();
        assert!(matches!(e, LiteralError::Syntax { .. }), "{text}: {e:?}");
        assert_eq!(column(&e), *col, "{text}");
        assert_eq!(e.to_string(), format!("column {col}: {message}"), "{text}");
    }
}

#[test]
fn policy_errors() {
    for text in [
        "Inf", "[1 NaN]", "-inf", "1/0", "1e400", "log(0)", "sqrt(-1)",
    ] {
        let e = parse_matrix::<f64>(text).unwrap_err();
        assert!(
            matches!(
                e,
                LiteralError::NonFinite { .. } | LiteralError::NumberOutOfRange { .. }
            ),
            "{text}: {e:?}"
        );
    }
    for text in [
        "'abc'",
        "[1 'a']",
        "1i",
        "[1 2] == 1",
        "{1}",
        "x = 1",
        "[1 2;3 4]^2",
    ] {
        let e = parse_matrix::<f64>(text).unwrap_err();
        assert!(
            matches!(e, LiteralError::Unsupported { .. }),
            "{text}: {e:?}"
        );
    }
    assert!(matches!(
        parse_matrix::<f64>("[1 2] + [1 2 3]").unwrap_err(),
        LiteralError::Shape { .. }
    ));
    assert!(matches!(
        parse_matrix::<f64>("1e99999").unwrap_err(),
        LiteralError::NumberOutOfRange { .. }
    ));
}

#[test]
fn limits_are_typed_errors() {
    let deep = format!("{}1{}", "(".repeat(10_000), ")".repeat(10_000));
    assert!(matches!(
        parse_matrix::<f64>(&deep).unwrap_err(),
        LiteralError::TooDeep { limit: 64, .. }
    ));
    let ok = format!("{}1{}", "(".repeat(60), ")".repeat(60));
    assert_eq!(parse_matrix::<f64>(&ok).unwrap()[(0, 0)], 1.0);
    let minus = format!("{}1", "-".repeat(100_000));
    assert!(matches!(
        parse_matrix::<f64>(&minus).unwrap_err(),
        LiteralError::TooDeep { .. }
    ));
    let brackets = format!("{}1{}", "[".repeat(5000), "]".repeat(5000));
    assert!(matches!(
        parse_matrix::<f64>(&brackets).unwrap_err(),
        LiteralError::TooDeep { .. }
    ));
    // Long flat chains are not nesting.
    let sum = vec!["1"; 50_000].join("+");
    assert_eq!(parse_matrix::<f64>(&sum).unwrap()[(0, 0)], 50_000.0);
    let long = "1".repeat(2 << 20);
    assert!(matches!(
        parse_matrix::<f64>(&long).unwrap_err(),
        LiteralError::TooLong { .. }
    ));
    assert!(matches!(
        parse_matrix::<f64>("1:1e12").unwrap_err(),
        LiteralError::TooLarge { .. }
    ));
    assert!(matches!(
        parse_matrix::<f64>("zeros(1e5)").unwrap_err(),
        LiteralError::TooLarge { .. }
    ));
    assert!(matches!(
        parse_matrix::<BigRational>("(2^1000)^1000^1000").unwrap_err(),
        LiteralError::NumberOutOfRange { .. }
    ));
    let small = Limits {
        max_depth: 3,
        ..Limits::default()
    };
    assert!(matches!(
        Expr::parse_with("(((1)))", &small).unwrap_err(),
        LiteralError::TooDeep { limit: 3, .. }
    ));
}

#[test]
fn numbers_in_data_files() {
    assert_eq!(parse_number::<f64>("-1.25e+02"), Some(-125.0));
    assert_eq!(parse_number::<BigRational>("0.2"), Some(r(1, 5)));
    assert_eq!(parse_number::<f64>("1d3"), Some(1000.0));
    for bad in [
        "",
        "-",
        ".",
        "1.2.3",
        "Inf",
        "nan",
        "0x10",
        "1e",
        "1e99999999",
        "1,5",
    ] {
        assert_eq!(parse_number::<f64>(bad), None, "{bad:?}");
    }
}

// ---------------------------------------------------------------------------------------
// Data scripts

fn script_file(name: &str) -> String {
    std::fs::read_to_string(cagd_test_support::data_file(name)).unwrap()
}

#[test]
fn appendix_c_data_script_runs() {
    let s = run::<f64>(&script_file("appendix_c.m"), Env::new()).unwrap();
    assert!(s.warnings().is_empty());
    let c1 = s.value("c1").unwrap();
    assert_eq!(c1.shape(), (3, 10));
    // N = 10; u = linspace(0,1,N); for i = 1:N; c1z(i) = u(i)-(u(i))^2; end; p(c1z)
    let c1z = [
        0.0,
        0.098765432098765427,
        0.1728395061728395,
        0.22222222222222221,
        0.24691358024691357,
        0.24691358024691357,
        0.22222222222222221,
        0.1728395061728395,
        0.098765432098765427,
        0.0,
    ];
    assert_eq!(c1.row(2).iter().copied().collect::<Vec<_>>(), c1z);
    assert_eq!(
        s.value("c1")
            .unwrap()
            .row(0)
            .iter()
            .copied()
            .collect::<Vec<_>>(),
        cagd::linspace(0.0, 1.0, 10)
    );
    // ... for i = 1:N; d1y(i) = (v(i))^2; end; p(d1y)
    let d1y = [
        0.0,
        0.012345679012345678,
        0.049382716049382713,
        0.1111111111111111,
        0.19753086419753085,
        0.30864197530864201,
        0.44444444444444453,
        0.60493827160493829,
        0.79012345679012341,
        1.0,
    ];
    assert_eq!(
        s.value("d1")
            .unwrap()
            .row(1)
            .iter()
            .copied()
            .collect::<Vec<_>>(),
        d1y
    );
    assert_eq!(s.value("c2").unwrap().row(1).iter().sum::<f64>(), 10.0);
    assert_eq!(s.value("P4").unwrap().as_slice(), &[1.0, 1.0, 1.0]);
    assert_eq!(s.value("P3").unwrap().as_slice(), &[0.0, 1.0, 0.0]);
}

#[test]
fn appendix_c_script_takes_n_from_the_caller() {
    // The printed script uses N without setting it; the command line binds it from --n.
    let text = script_file("appendix_c.m").replace("N = 10;", "");
    let err = run::<f64>(&text, Env::new()).unwrap_err();
    assert!(matches!(err, LiteralError::UnknownVariable { ref name, .. } if name == "N"));
    let mut env = Env::new();
    env.bind_scalar("N", 4.0);
    let s = run::<f64>(&text, env).unwrap();
    assert_eq!(s.value("c1").unwrap().shape(), (3, 4));
}

#[test]
fn appendix_c_point_script_keeps_curves_in_u_and_v() {
    let s = run::<f64>(&script_file("appendix_c_point.m"), Env::new()).unwrap();
    for (name, param) in [("c1", "u"), ("c2", "u"), ("d1", "v"), ("d2", "v")] {
        let f = s.function(name).unwrap();
        assert_eq!(f.parameters(s.env()), vec![param], "{name}");
    }
    let d1 = s.resolve("d1").unwrap();
    let p = d1.sample_curve(&mut s.env().clone(), "v", &[0.5]).unwrap();
    assert_eq!(p.as_slice(), &[0.0, 0.25, 0.25]);
    assert!(matches!(s.get("P2"), Some(Binding::Value(m)) if m.as_slice() == [1.0, 0.0, 0.0]));
}

#[test]
fn appendix_d_data_script_runs_elementwise_with_warnings() {
    let s = run::<f64>(&script_file("appendix_d.m"), Env::new()).unwrap();
    let g_u = s.value("g_u").unwrap();
    assert_eq!(g_u.shape(), (3, 30));
    // N = 10; u = linspace(0,1,N); c1 = [u; 0.5*ones(1,N); 0.5+u-u.^2]; p(c1(3,:))
    let c1z = [
        0.5,
        0.59876543209876543,
        0.6728395061728395,
        0.7222222222222221,
        0.74691358024691357,
        0.74691358024691357,
        0.72222222222222221,
        0.67283950617283939,
        0.59876543209876543,
        0.5,
    ];
    assert_eq!(
        s.value("c1")
            .unwrap()
            .row(2)
            .iter()
            .copied()
            .collect::<Vec<_>>(),
        c1z
    );
    assert_eq!(
        g_u.columns(10, 10)
            .row(1)
            .iter()
            .copied()
            .collect::<Vec<_>>(),
        vec![0.5; 10]
    );
    assert_eq!(s.value("g_uv").unwrap().shape(), (3, 9));
    assert_eq!(s.value("g_v").unwrap().shape(), (3, 30));
    assert_eq!(s.value("x").unwrap().as_slice(), &[0.0, 0.5, 1.0]);
    let warnings = s.warnings();
    // Three `u^2` and six constant rows (c0, c1, c2, d0, d1, d2).
    assert_eq!(warnings.len(), 9, "{warnings:#?}");
    assert!(warnings
        .iter()
        .any(|w| w.at.line == 18 && w.message.contains("`^`")));
}

#[test]
fn appendix_d_without_samples_defines_curves() {
    // Without N, u, v the same script defines the network curves as expressions: g_u at a
    // parameter value is the 3 × 3 matrix of the three curves' points, as krpaGordon reads it.
    let text: String = script_file("appendix_d.m")
        .lines()
        .filter(|l| !l.starts_with("N =") && !l.starts_with("u =") && !l.starts_with("v ="))
        .collect::<Vec<_>>()
        .join("\n");
    let s = run::<f64>(&text, Env::new()).unwrap();
    assert!(s.warnings().is_empty());
    let g_u = s.resolve("g_u").unwrap();
    let m = g_u.eval_at(s.env(), &[("u", 0.5)]).unwrap();
    assert_eq!(
        m,
        rows(3, 3, &[0.5, 0.5, 0.5, 0.0, 0.5, 1.0, 0.25, 0.75, 1.25])
    );
}

#[test]
fn script_statements() {
    let s = run::<f64>(
        "a = 1, b = [a 2]; # comment\nc = b'; d = ...\n  c(2);\nfor (k = 1:3)\n  e(k) = k^2;\nendfor\nM(2,3) = 7;\n3 + 4",
        Env::new(),
    )
    .unwrap();
    assert_eq!(s.value("c").unwrap().shape(), (2, 1));
    assert_eq!(s.value("d").unwrap()[(0, 0)], 2.0);
    assert_eq!(s.value("e").unwrap(), &rows(1, 3, &[1.0, 4.0, 9.0]));
    assert_eq!(
        s.value("M").unwrap(),
        &rows(2, 3, &[0., 0., 0., 0., 0., 7.])
    );
    assert_eq!(s.value("ans").unwrap()[(0, 0)], 7.0);
    assert_eq!(s.names(), vec!["a", "b", "c", "d", "k", "e", "M", "ans"]);
    // Exact evaluation of a script.
    let s = run::<BigRational>("x = 0.1; y = x*3;", Env::new()).unwrap();
    assert_eq!(s.value("y").unwrap()[(0, 0)], r(3, 10));
}

#[test]
fn script_errors() {
    let cases: &[(&str, usize, usize)] = &[
        ("a = 1;\ng1 = g2 = g12 = 0;", 2, 9),
        ("a = [1 2;\n 3];", 2, 2),
        ("function y = f(x)\n y = x;\nend", 1, 1),
        ("for i = 1:3\n a = i;\n", 3, 1),
        ("end", 1, 1),
        ("hold on", 1, 1),
        ("x = undefined_thing + 1;", 1, 5),
        ("x(0) = 1;", 1, 3),
        ("x = [1 2]; x(2,2,2) = 3;", 1, 12),
        ("if 1\nend", 1, 1),
    ];
    for (text, line, col) in cases {
        let e = run::<f64>(text, Env::new()).unwrap_err();
        let at = e.position().unwrap();
        assert_eq!((at.line, at.column), (*line, *col), "{text:?}: {e}");
    }
    assert!(matches!(
        run::<f64>("g1 = g2 = 0", Env::new()).unwrap_err(),
        LiteralError::ChainedAssignment { .. }
    ));
}

// ---------------------------------------------------------------------------------------
// No input panics

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn random_text_never_panics(text in "\\PC{0,60}") {
        let _ = parse_matrix::<f64>(&text);
        let _ = parse_matrix::<BigRational>(&text);
        let _ = parse_params::<f64>(&text);
        let _ = run::<f64>(&text, Env::new());
        if let Ok(e) = ParamExpr::parse(&text) {
            let _ = e.sample_curve(&mut Env::<f64>::new(), "u", &[0.0, 0.5]);
            let _ = e.sample_curve(&mut Env::<BigRational>::new(), "u", &[r(1, 3)]);
        }
    }

    #[test]
    fn octave_like_text_never_panics(
        text in "[-+*/^.'()\\[\\];:, \\n0-9euvtxi=%]{0,40}|(sin|zeros|linspace|for|end|u|v|1e|\\[|\\]|\\(|\\)|;|:|,|'|\\.\\^|\\^| |\\n|=|-|2){0,20}"
    ) {
        let _ = parse_matrix::<f64>(&text);
        let _ = parse_matrix::<BigRational>(&text);
        let _ = run::<f64>(&text, Env::new());
        let _ = run::<BigRational>(&text, Env::new());
        if let Ok(e) = ParamExpr::parse(&text) {
            let _ = e.sample_curve(&mut Env::<f64>::new(), "u", &[0.0, 0.5]);
            let _ = e.sample_surface(&mut Env::<f64>::new(), &[0.0, 1.0], &[0.5]);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Block comments (Octave's `%{ … %}` and `#{ … #}`, on lines of their own, nesting)

#[test]
fn block_comments_are_comments_in_scripts() {
    use cagd_octave::script::run;
    let src = "a = 1;\n%{\na = 2;\n  #{\n  a = 3;\n  #}\na = 4;\n%}\nb = a + 10;\n";
    let s = run::<f64>(src, Env::new()).unwrap();
    assert_eq!(s.value("a").unwrap()[(0, 0)], 1.0);
    assert_eq!(s.value("b").unwrap()[(0, 0)], 11.0);
    // Not alone on its line: an ordinary line comment, so the next line runs.
    let s = run::<f64>("a = 1; %{\na = 2;\n", Env::new()).unwrap();
    assert_eq!(s.value("a").unwrap()[(0, 0)], 2.0);
    // Line numbers after a block comment still point at the right line.
    let err = run::<f64>("%{\nx\n%}\ny = [1 2; 3];\n", Env::new()).unwrap_err();
    assert!(err.to_string().starts_with("line 4"), "{err}");
    // Never closed: an error, not commented-out code that silently vanishes.
    let err = run::<f64>("a = 1;\n%{\na = 2;\n", Env::new()).unwrap_err();
    assert!(matches!(err, LiteralError::Syntax { .. }), "{err:?}");
    assert!(err.to_string().contains("close the block comment"), "{err}");
}

#[test]
fn block_comments_in_a_literal_argument() {
    let m = parse_matrix::<f64>("[1 2\n%{\n 9 9\n%}\n3 4]").unwrap();
    assert_eq!(m.shape(), (2, 2));
    assert_eq!(m[(1, 0)], 3.0);
}

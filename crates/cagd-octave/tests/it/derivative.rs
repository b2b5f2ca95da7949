//! `ParamExpr::derivative`: exact derivatives checked against derivatives worked by hand and
//! against polynomial arithmetic on coefficient vectors (never against our own derivative),
//! `f64` derivatives of the transcendental functions against central differences, shapes, and
//! the constructs that have no derivative.

use nalgebra::DMatrix;
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::prelude::*;

use cagd_octave::literal::{Env, LiteralError, ParamExpr};
use cagd_octave::script::run;

/// A curve's source, its parameter, and its derivative worked by hand.
type HandDerivative = (
    &'static str,
    &'static str,
    fn(BigRational) -> [BigRational; 3],
);

fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn ints(values: &[i64]) -> Vec<BigRational> {
    values.iter().map(|&n| r(n, 1)).collect()
}

/// `d/du` of `source` at `u = x`, exactly.
fn exact_at(source: &str, x: BigRational) -> DMatrix<BigRational> {
    ParamExpr::parse(source)
        .unwrap()
        .derivative("u")
        .unwrap()
        .eval_at(&Env::new(), &[("u", x)])
        .unwrap()
}

// ---------------------------------------------------------------------------------------
// Exact derivatives, worked by hand

#[test]
fn thesis_curve_c1_at_a_third() {
    // c1(u) = (u, 0, u − u²), c1'(u) = (1, 0, 1 − 2u): at u = 1/3, (1, 0, 1/3).
    let t = exact_at("[u; 0; u-u^2]", r(1, 3));
    assert_eq!(t.shape(), (3, 1));
    assert_eq!(t.as_slice(), &[r(1, 1), r(0, 1), r(1, 3)]);
    // Exact at the ends, where u^1 and 0^0 would be traps: (1, 0, 1) and (1, 0, −1).
    assert_eq!(
        exact_at("[u; 0; u-u^2]", r(0, 1)).as_slice(),
        ints(&[1, 0, 1])
    );
    assert_eq!(
        exact_at("[u; 0; u-u^2]", r(1, 1)).as_slice(),
        ints(&[1, 0, -1])
    );
}

#[test]
fn primer_4_3_boundary_curves() {
    // c1 = (u, 0, u−u²), c2 = (u, 1, u), d1 = (0, v², v−v²), d2 = (1, v, v); their
    // derivatives (1, 0, 1−2u), (1, 0, 1), (0, 2v, 1−2v), (0, 1, 1).
    let curves: [HandDerivative; 4] = [
        ("[u;0;u-u^2]", "u", |u| {
            [r(1, 1), r(0, 1), r(1, 1) - r(2, 1) * u]
        }),
        ("[u;1;u]", "u", |_| [r(1, 1), r(0, 1), r(1, 1)]),
        ("[0;v^2;v-v^2]", "v", |v| {
            [r(0, 1), r(2, 1) * v.clone(), r(1, 1) - r(2, 1) * v]
        }),
        ("[1;v;v]", "v", |_| [r(0, 1), r(1, 1), r(1, 1)]),
    ];
    let samples = [r(0, 1), r(1, 5), r(1, 2), r(7, 10), r(1, 1)];
    for (source, param, hand) in curves {
        let d = ParamExpr::parse(source).unwrap().derivative(param).unwrap();
        assert_eq!(d.source(), format!("d/d{param} ({source})"));
        let got = d
            .sample_curve(&mut Env::<BigRational>::new(), param, &samples)
            .unwrap();
        assert_eq!(got.shape(), (3, samples.len()), "{source}");
        for (j, x) in samples.iter().enumerate() {
            let expected: Vec<BigRational> = hand(x.clone()).to_vec();
            assert_eq!(
                got.column(j).iter().cloned().collect::<Vec<_>>(),
                expected,
                "{source} at {x}"
            );
        }
    }
}

#[test]
fn script_curves_depending_on_other_curves() {
    // c = (u, u²), d = 2c: d' = (2, 4u).
    let s = run::<BigRational>("c = [u; u^2];\nd = 2*c;", Env::new()).unwrap();
    let d = s.function("d").unwrap().derivative("u").unwrap();
    let p = d.eval_at(s.env(), &[("u", r(3, 4))]).unwrap();
    assert_eq!(p.as_slice(), &[r(2, 1), r(3, 1)]);

    // Through indexing, products of curves and a value of the script: k = [1 2],
    // e = k*c + c(2)*c(1) = u + 2u² + u³, e' = 1 + 4u + 3u².
    let s = run::<BigRational>(
        "k = [1 2];\nc = [u; u^2];\ne = k*c + c(2)*c(1);",
        Env::new(),
    )
    .unwrap();
    let e = s.function("e").unwrap().derivative("u").unwrap();
    for x in [r(0, 1), r(1, 2), r(-2, 3)] {
        let expected = r(1, 1) + r(4, 1) * x.clone() + r(3, 1) * x.clone() * x.clone();
        let p = e.eval_at(s.env(), &[("u", x)]).unwrap();
        assert_eq!(p.as_slice(), &[expected]);
    }

    // A typed expression resolved in the script: `--c1 "c + [1; 0]"`.
    let t = s.resolve("c + [1; 0]").unwrap().derivative("u").unwrap();
    let p = t.eval_at(s.env(), &[("u", r(5, 1))]).unwrap();
    assert_eq!(p.as_slice(), &[r(1, 1), r(10, 1)]);
}

#[test]
fn a_curve_redefined_in_terms_of_its_old_self() {
    // c = (u, 1), d = 2c = (2u, 2), then c = c .* u = (u², u): e = c + d = (u² + 2u, u + 2),
    // e' = (2u + 2, 1). The derivative of the second c reads the first c, not itself.
    let s =
        run::<BigRational>("c = [u; 1];\nd = 2*c;\nc = c .* u;\ne = c + d;", Env::new()).unwrap();
    let e = s.function("e").unwrap();
    let x = r(3, 7);
    let value = e.eval_at(s.env(), &[("u", x.clone())]).unwrap();
    assert_eq!(
        value.as_slice(),
        &[x.clone() * x.clone() + r(6, 7), x.clone() + r(2, 1)]
    );
    let d = e.derivative("u").unwrap();
    let p = d.eval_at(s.env(), &[("u", x.clone())]).unwrap();
    assert_eq!(p.as_slice(), &[r(2, 1) * x + r(2, 1), r(1, 1)]);
}

#[test]
fn powers_quotients_and_abs_exactly() {
    // u^-1 → −1/u²; u^0 → 0 even at 0; (u+1)/(u−1) → −2/(u−1)²; 1/(u^2 + 1) → −2u/(u²+1)².
    assert_eq!(exact_at("u^-1", r(1, 2)).as_slice(), &[r(-4, 1)]);
    assert_eq!(exact_at("u^0", r(0, 1)).as_slice(), &[r(0, 1)]);
    assert_eq!(exact_at("u^1", r(0, 1)).as_slice(), &[r(1, 1)]);
    assert_eq!(exact_at("u.^3", r(0, 1)).as_slice(), &[r(0, 1)]);
    assert_eq!(exact_at("(u+1)/(u-1)", r(3, 1)).as_slice(), &[r(-1, 2)]);
    assert_eq!(exact_at("1./(u^2 + 1)", r(1, 1)).as_slice(), &[r(-1, 2)]);
    // log's derivative is rational though log is not; abs away from 0.
    assert_eq!(exact_at("log(u^2)", r(1, 4)).as_slice(), &[r(8, 1)]);
    assert_eq!(exact_at("abs(1 - 2*u)", r(1, 1)).as_slice(), &[r(2, 1)]);
    assert_eq!(exact_at("abs(1 - 2*u)", r(0, 1)).as_slice(), &[r(-2, 1)]);
    // The exponent 0.5 written as a decimal is exactly 1/2: not rational, as for the value.
    let d = ParamExpr::parse("u^0.5").unwrap().derivative("u").unwrap();
    let err = d
        .eval_at(&Env::<BigRational>::new(), &[("u", r(4, 1))])
        .unwrap_err();
    assert!(matches!(err, LiteralError::NotRational { .. }), "{err}");
    // abs has no derivative at 0: the derivative divides by zero there.
    let d = ParamExpr::parse("abs(u)").unwrap().derivative("u").unwrap();
    let err = d
        .eval_at(&Env::<BigRational>::new(), &[("u", r(0, 1))])
        .unwrap_err();
    assert!(matches!(err, LiteralError::DivisionByZero { .. }), "{err}");
}

#[test]
fn second_derivatives() {
    let d2 = ParamExpr::parse("[u^3; u.*u - 4*u]")
        .unwrap()
        .derivative("u")
        .unwrap()
        .derivative("u")
        .unwrap();
    assert_eq!(d2.source(), "d/du (d/du ([u^3; u.*u - 4*u]))");
    let p = d2
        .eval_at(&Env::<BigRational>::new(), &[("u", r(1, 2))])
        .unwrap();
    assert_eq!(p.as_slice(), &[r(3, 1), r(2, 1)]);
    // Through the prelude: c = (u², u³), d = c .* c = (u⁴, u⁶), d'' = (12u², 30u⁴).
    let s = run::<BigRational>("c = [u^2; u^3];\nd = c .* c;", Env::new()).unwrap();
    let d2 = s
        .function("d")
        .unwrap()
        .derivative("u")
        .unwrap()
        .derivative("u")
        .unwrap();
    let p = d2.eval_at(s.env(), &[("u", r(2, 1))]).unwrap();
    assert_eq!(p.as_slice(), &[r(48, 1), r(480, 1)]);
}

#[test]
fn other_parameters_are_constants() {
    // d/dv of u·v² + u is 2uv; d/du is v² + 1.
    let e = ParamExpr::parse("u*v^2 + u").unwrap();
    let at = [("u", r(3, 1)), ("v", r(1, 2))];
    let d = |p: &str| e.derivative(p).unwrap().eval_at(&Env::new(), &at).unwrap();
    assert_eq!(d("v").as_slice(), &[r(3, 1)]);
    assert_eq!(d("u").as_slice(), &[r(5, 4)]);
}

// ---------------------------------------------------------------------------------------
// Polynomials: the derivative against coefficient arithmetic

/// A polynomial in `u` as Octave text and as coefficients (constant term first).
#[derive(Debug, Clone)]
struct Poly {
    text: String,
    coeffs: Vec<BigRational>,
}

fn add(a: &[BigRational], b: &[BigRational], sign: i64) -> Vec<BigRational> {
    let n = a.len().max(b.len());
    let at = |p: &[BigRational], i: usize| p.get(i).cloned().unwrap_or_else(BigRational::zero);
    (0..n).map(|i| at(a, i) + at(b, i) * r(sign, 1)).collect()
}

fn mul(a: &[BigRational], b: &[BigRational]) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

fn power(a: &[BigRational], k: u32) -> Vec<BigRational> {
    (0..k).fold(vec![BigRational::one()], |p, _| mul(&p, a))
}

fn derive(a: &[BigRational]) -> Vec<BigRational> {
    let d: Vec<BigRational> = a
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c * r(i as i64, 1))
        .collect();
    if d.is_empty() {
        vec![BigRational::zero()]
    } else {
        d
    }
}

fn at(a: &[BigRational], x: &BigRational) -> BigRational {
    a.iter()
        .rev()
        .fold(BigRational::zero(), |acc, c| acc * x + c)
}

fn leaf() -> impl Strategy<Value = Poly> {
    prop_oneof![
        Just(Poly {
            text: "u".into(),
            coeffs: ints(&[0, 1]),
        }),
        (-4i64..=4).prop_map(|c| Poly {
            text: c.to_string(),
            coeffs: ints(&[c]),
        }),
        (1i64..=9).prop_map(|k| Poly {
            text: format!("0.{k}"),
            coeffs: vec![r(k, 10)],
        }),
    ]
}

/// Sums and products of 2 to 4 operands in one flat chain, unary minus, integer powers
/// (chained too, `(p)^2^1`), and divisions by constants.
fn poly() -> impl Strategy<Value = Poly> {
    leaf().prop_recursive(3, 24, 4, |inner| {
        let ops = prop::sample::select(vec!["+", "-", "*", ".*", "/2", "./4"]);
        prop_oneof![
            (
                inner.clone(),
                prop::collection::vec((ops, inner.clone()), 1..4)
            )
                .prop_map(|(first, rest)| {
                    let mut text = format!("({})", first.text);
                    let mut coeffs = first.coeffs;
                    // One precedence level per chain: a sum, or a product.
                    let additive = matches!(rest[0].0, "+" | "-");
                    for (op, p) in rest {
                        let op = match (additive, matches!(op, "+" | "-")) {
                            (true, false) => "+",
                            (false, true) => "*",
                            _ => op,
                        };
                        coeffs = match op {
                            "+" => add(&coeffs, &p.coeffs, 1),
                            "-" => add(&coeffs, &p.coeffs, -1),
                            "*" | ".*" => mul(&coeffs, &p.coeffs),
                            "/2" => mul(&coeffs, &[r(1, 2)]),
                            _ => mul(&coeffs, &[r(1, 4)]),
                        };
                        text = match op {
                            "/2" | "./4" => format!("{text}{op}"),
                            _ => format!("{text} {op} ({})", p.text),
                        };
                    }
                    Poly { text, coeffs }
                }),
            (
                inner.clone(),
                prop::collection::vec(0u32..=3, 1..3),
                any::<bool>()
            )
                .prop_map(|(base, ks, dotted)| {
                    let caret = if dotted { ".^" } else { "^" };
                    let mut text = format!("({})", base.text);
                    let mut coeffs = base.coeffs;
                    for k in ks {
                        text = format!("{text}{caret}{k}");
                        coeffs = power(&coeffs, k);
                    }
                    Poly { text, coeffs }
                }),
            inner.prop_map(|p| Poly {
                text: format!("-({})", p.text),
                coeffs: add(&[], &p.coeffs, -1),
            }),
        ]
    })
}

fn sample_point() -> impl Strategy<Value = BigRational> {
    prop_oneof![
        Just(r(0, 1)),
        Just(r(1, 1)),
        (-6i64..=6, 1i64..=5).prop_map(|(n, d)| r(n, d))
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn polynomial_derivatives_are_exact(p in poly(), x in sample_point()) {
        let e = ParamExpr::parse(&p.text).unwrap();
        let env = Env::<BigRational>::new();
        let value = e.eval_at(&env, &[("u", x.clone())]).unwrap();
        prop_assert_eq!(value.as_slice(), &[at(&p.coeffs, &x)], "the generator: {}", p.text);
        let d = e.derivative("u").unwrap();
        let got = d.eval_at(&env, &[("u", x.clone())]).unwrap();
        prop_assert_eq!(got.as_slice(), &[at(&derive(&p.coeffs), &x)], "d/du {} at {}", p.text, x);
    }

    #[test]
    fn derivatives_of_columns_of_polynomials_and_of_script_curves(
        p in poly(), q in poly(), x in sample_point()
    ) {
        let env = Env::<BigRational>::new();
        let column = format!("[{}; {}]", p.text, q.text);
        let d = ParamExpr::parse(&column).unwrap().derivative("u").unwrap();
        let got = d.eval_at(&env, &[("u", x.clone())]).unwrap();
        let (dp, dq) = (derive(&p.coeffs), derive(&q.coeffs));
        prop_assert_eq!(got.shape(), (2, 1));
        prop_assert_eq!(got.as_slice(), &[at(&dp, &x), at(&dq, &x)]);
        // The same through a script: c = [p; q; u], e = c(1) .* c(2) - c(2), e' = p'q + pq' − q'.
        let script = format!("c = [{}; {}; u];\ne = c(1) .* c(2) - c(2);", p.text, q.text);
        let s = run::<BigRational>(&script, Env::new()).unwrap();
        let de = s.function("e").unwrap().derivative("u").unwrap();
        let got = de.eval_at(s.env(), &[("u", x.clone())]).unwrap();
        let expected = add(&add(&mul(&dp, &q.coeffs), &mul(&p.coeffs, &dq), 1), &dq, -1);
        prop_assert_eq!(got.as_slice(), &[at(&expected, &x)]);
    }
}

// ---------------------------------------------------------------------------------------
// Transcendental functions in f64, against central differences

#[test]
fn functions_against_central_differences() {
    let cases = [
        "sin(2*u) + cos(u^2)",
        "tan(u/2)",
        "exp(-u.^2)",
        "sqrt(1 + u^2)",
        "log(2 + u) - log(u)",
        "abs(u - 0.5) .* u",
        "u^u",
        "2^u + u^0.5",
        "exp(sin(u)) ./ (1 + u)",
        "[cos(2*pi*u); sin(2*pi*u); u]",
    ];
    let h = 1e-6;
    for source in cases {
        let e = ParamExpr::parse(source).unwrap();
        let d = e.derivative("u").unwrap();
        let env = Env::<f64>::new();
        for x in [0.2, 0.7, 1.3] {
            let f = |u: f64| e.eval_at(&env, &[("u", u)]).unwrap();
            let central = (f(x + h) - f(x - h)) / (2.0 * h);
            let got = d.eval_at(&env, &[("u", x)]).unwrap();
            assert_eq!(got.shape(), central.shape(), "{source}");
            for (g, c) in got.iter().zip(central.iter()) {
                assert!(
                    (g - c).abs() <= 1e-6 * c.abs().max(1.0),
                    "{source} at {x}: {g} vs {c}"
                );
            }
        }
    }
}

#[test]
fn nested_functions_deep_within_the_limits() {
    // 60 nested sines, each the derivative of the one inside by the chain rule.
    let source = format!("{}u{}", "sin(".repeat(60), ")".repeat(60));
    let e = ParamExpr::parse(&source).unwrap();
    let d = e.derivative("u").unwrap();
    let (x, h) = (0.4, 1e-6);
    let f = |u: f64| e.eval_at(&Env::new(), &[("u", u)]).unwrap()[0];
    let central = (f(x + h) - f(x - h)) / (2.0 * h);
    let got = d.eval_at(&Env::<f64>::new(), &[("u", x)]).unwrap()[0];
    assert!((got - central).abs() < 1e-6, "{got} vs {central}");
}

// ---------------------------------------------------------------------------------------
// Shapes

#[test]
fn shapes_are_kept() {
    let env = {
        let mut env = Env::<f64>::new();
        env.bind("a", DMatrix::from_row_slice(3, 1, &[1.0, -2.0, 3.0]));
        env.bind_scalar("k", -2.0);
        env
    };
    let cases: [(&str, (usize, usize), &[f64]); 8] = [
        ("[1; 2; 3]", (3, 1), &[0.0, 0.0, 0.0]),
        ("a", (3, 1), &[0.0, 0.0, 0.0]),
        ("u + a", (3, 1), &[1.0, 1.0, 1.0]),
        ("a * u^2", (3, 1), &[1.0, -2.0, 3.0]),
        ("[u u; 1 2]", (2, 2), &[1.0, 0.0, 1.0, 0.0]),
        ("[1 2 3]' * u", (3, 1), &[1.0, 2.0, 3.0]),
        ("[u; k]", (2, 1), &[1.0, 0.0]),
        ("(a * u)'", (1, 3), &[1.0, -2.0, 3.0]),
    ];
    for (source, shape, expected) in cases {
        let d = ParamExpr::parse(source).unwrap().derivative("u").unwrap();
        let got = d.eval_at(&env, &[("u", 0.5)]).unwrap();
        assert_eq!(got.shape(), shape, "{source}");
        assert_eq!(got.as_slice(), expected, "{source}");
        // A constant's derivative is +0, not −0 (−0 prints as `-0`).
        assert!(
            got.iter().all(|x| *x != 0.0 || x.is_sign_positive()),
            "{source}: {got}"
        );
    }
    // A constant 1×1 row is still repeated along a longer row, as in the value.
    let s = run::<f64>("w = [1 2 3];\nc = [u*w; 5];", Env::new()).unwrap();
    let d = s.function("c").unwrap().derivative("u").unwrap();
    let got = d.eval_at(s.env(), &[("u", 2.0)]).unwrap();
    assert_eq!(
        got,
        DMatrix::from_row_slice(2, 3, &[1.0, 2.0, 3.0, 0.0, 0.0, 0.0])
    );
}

#[test]
fn long_products_stay_small_and_evaluate_on_a_small_stack() {
    // u·u·…·u (2000 factors) has derivative 2000·u^1999: 2000 at u = 1, exactly.
    let text = vec!["u"; 2000].join("*");
    let got = std::thread::Builder::new()
        .stack_size(4 << 20)
        .spawn(move || {
            let d = ParamExpr::parse(&text).unwrap().derivative("u").unwrap();
            assert!(d.node_count() < 40_000, "{} nodes", d.node_count());
            d.eval_at(&Env::<BigRational>::new(), &[("u", r(1, 1))])
                .unwrap()
        })
        .unwrap()
        .join()
        .expect("no stack overflow");
    assert_eq!(got.as_slice(), &[r(2000, 1)]);
}

// ---------------------------------------------------------------------------------------
// What has no derivative

fn refusal(source: &str) -> LiteralError {
    ParamExpr::parse(source)
        .unwrap()
        .derivative("u")
        .unwrap_err()
}

#[test]
fn refusals_name_the_construct_and_where() {
    let cases = [
        ("[u; u:2]", "column 5: not supported: the derivative in `u` of a range whose start, increment or limit depends on `u`"),
        ("0:0.5:u", "column 1: not supported: the derivative in `u` of a range whose start, increment or limit depends on `u`"),
        ("linspace(0, 1, 2+u)", "column 1: not supported: the derivative in `u` of `linspace(a, b, n)` whose number of points n depends on `u`"),
        ("1 + frob(u)", "column 5: not supported: the derivative in `u` of `frob(…)` with an argument that depends on `u`: only sin, cos, tan, sqrt, exp, log, abs, linspace and the indexing of a curve of the script by a constant index have derivatives"),
        ("u(u)", "column 3: not supported: the derivative in `u` of `u(…)` indexed by an index that depends on `u`"),
    ];
    for (source, message) in cases {
        let err = refusal(source);
        assert!(
            matches!(err, LiteralError::Unsupported { .. }),
            "{source}: {err:?}"
        );
        assert_eq!(err.to_string(), message);
    }
    // A value of the script indexed by the parameter; a curve indexed by a varying index
    // (lines count in a script).
    let s = run::<f64>(
        "a = [1 2 3];\nc = [u; 2];\nd = a(u);\ne = c(1 + 0*u);",
        Env::new(),
    )
    .unwrap();
    let err = s.function("d").unwrap().derivative("u").unwrap_err();
    assert!(
        err.to_string()
            .starts_with("line 3, column 5: not supported: the derivative in `u` of `a(…)`"),
        "{err}"
    );
    let err = s.function("e").unwrap().derivative("u").unwrap_err();
    assert_eq!(
        err.to_string(),
        "line 4, column 7: not supported: the derivative in `u` of `c(…)` indexed by an index that depends on `u`"
    );
    // A curve of the script without a derivative is refused where its derivative is needed
    // (with the position in the script), not where only its size is.
    let s = run::<BigRational>("k = [u, 1:u];\nn = numel(k) * u;\nm = 2 * k;", Env::new()).unwrap();
    let dn = s.function("n").unwrap().derivative("u").unwrap();
    let p = dn.eval_at(s.env(), &[("u", r(3, 1))]).unwrap();
    assert_eq!(p.as_slice(), &[r(4, 1)]);
    let err = s.function("m").unwrap().derivative("u").unwrap_err();
    assert_eq!(
        err.to_string(),
        "line 1, column 9: not supported: the derivative in `u` of a range whose start, increment or limit depends on `u`"
    );
    // A call the evaluator rejects is no refusal of the derivative: evaluating either reports it.
    let e = ParamExpr::parse("sin(u, 2)").unwrap();
    let d = e.derivative("u").unwrap();
    for x in [e, d] {
        let err = x.eval_at(&Env::<f64>::new(), &[("u", 0.5)]).unwrap_err();
        assert_eq!(err.to_string(), "column 1: sin: expected 1 argument, got 2");
    }
    // What does not vary is no refusal: a constant range, a constant index, numel of a curve.
    for source in ["[u, 1:3]", "u * size([1 2], 2)", "u * numel(1:3)"] {
        let d = ParamExpr::parse(source).map(|e| e.derivative("u"));
        assert!(matches!(d, Ok(Ok(_))), "{source}: {d:?}");
    }
    let s = run::<BigRational>(
        "c = [u; u^2; 1];\nd = c(numel(c) - 1) * c(1:2);",
        Env::new(),
    )
    .unwrap();
    let d = s.function("d").unwrap().derivative("u").unwrap();
    // d = u²·(u, u²) = (u³, u⁴), d' = (3u², 4u³).
    let p = d.eval_at(s.env(), &[("u", r(1, 2))]).unwrap();
    assert_eq!(p.as_slice(), &[r(3, 4), r(1, 2)]);
}

//! The derivative's tree, read back as Octave text, for the rules whose form matters (exact at
//! zero, operators kept, shared values bound once).

use super::*;

/// The tree as Octave text, parenthesising every operand that is itself a chain.
fn text(e: &Expr) -> String {
    let operand = |x: &Expr| match x.node {
        Node::Chain { .. } | Node::Range { .. } => format!("({})", text(x)),
        _ => text(x),
    };
    match &e.node {
        Node::Number { text, .. } => text.clone(),
        Node::Var(name) => name.clone(),
        Node::Colon => ":".into(),
        Node::Call { name, args } => {
            let args: Vec<String> = args.iter().map(text).collect();
            format!("{name}({})", args.join(", "))
        }
        Node::Neg(x) => format!("-{}", operand(x)),
        Node::Transpose(x) => format!("{}'", operand(x)),
        Node::Chain { first, rest } => {
            let mut s = operand(first);
            for (op, _, x) in rest {
                s.push_str(&format!(" {} {}", op.symbol(), operand(x)));
            }
            s
        }
        Node::Range {
            base,
            increment,
            limit,
        } => match increment {
            Some(s) => format!("{}:{}:{}", operand(base), operand(s), operand(limit)),
            None => format!("{}:{}", operand(base), operand(limit)),
        },
        Node::Matrix(rows) => {
            let rows: Vec<String> = rows
                .iter()
                .map(|r| r.elements.iter().map(text).collect::<Vec<_>>().join(", "))
                .collect();
            format!("[{}]", rows.join("; "))
        }
    }
}

fn derivative(source: &str, param: &str) -> ParamExpr {
    ParamExpr::parse(source).unwrap().derivative(param).unwrap()
}

fn d(source: &str) -> String {
    let e = derivative(source, "u");
    assert!(e.prelude.is_empty(), "{source}: {:?}", e.prelude);
    text(&e.expr)
}

#[test]
fn literal_powers_are_written_with_literal_exponents() {
    assert_eq!(d("u^2"), "2 .* u .* 1");
    assert_eq!(d("u.^3"), "3 .* (u .^ 2) .* 1");
    assert_eq!(d("u^1"), "1");
    assert_eq!(d("u^0"), "(0 .* (u ^ 0)) + 0");
    assert_eq!(d("u^-2"), "-2 .* (u ^ -3) .* 1");
    assert_eq!(d("u^2.0"), "2 .* u .* 1");
    assert_eq!(d("u^0.5"), "0.5 .* (u ^ (0.5 - 1)) .* 1");
    // Not the integer 3 in exact arithmetic, though it is the double 3.
    assert_eq!(
        d("u^3.0000000000000001"),
        "3.0000000000000001 .* (u ^ (3.0000000000000001 - 1)) .* 1"
    );
    assert_eq!(d("2^u"), "(2 ^ u) .* (1 .* log(2))");
    assert_eq!(d("u^u"), "(u ^ u) .* ((1 .* log(u)) + (u .* 1 ./ u))");
}

#[test]
fn sums_products_and_quotients_keep_their_operators() {
    assert_eq!(d("[u; 0; u-u^2]"), "[1; 0; 1 - (2 .* u .* 1)]");
    assert_eq!(d("3*u - 2"), "3 * 1");
    assert_eq!(d("u*v"), "1 * v");
    assert_eq!(d("v.*u"), "v .* 1");
    assert_eq!(d("u/2"), "1 / 2");
    assert_eq!(d("1./u"), "-(1 ./ u .* 1 ./ u)");
    assert_eq!(d("u/u"), "(1 / u) - (u / u .* 1 / u)");
    assert_eq!(d("-u'"), "-1'");
    // A constant that is not a number keeps its shape in a sum.
    assert_eq!(d("u + a"), "1 + ((0 .* a) + 0)");
    assert_eq!(d("[u; a]"), "[1; (0 .* a) + 0]");
    assert_eq!(d("a"), "(0 .* a) + 0");
}

#[test]
fn functions_by_the_chain_rule() {
    assert_eq!(d("sin(2*u)"), "cos(2 * u) .* (2 * 1)");
    assert_eq!(d("cos(u)"), "-(sin(u) .* 1)");
    assert_eq!(d("tan(u)"), "(1 + (tan(u) .^ 2)) .* 1");
    assert_eq!(d("sqrt(u)"), "1 ./ (2 .* sqrt(u))");
    assert_eq!(d("exp(u)"), "exp(u) .* 1");
    assert_eq!(d("log(u)"), "1 ./ u");
    assert_eq!(d("abs(u)"), "u ./ abs(u) .* 1");
    assert_eq!(d("linspace(0, u, 3)"), "linspace(0, 1, 3)");
    assert_eq!(
        d("zeros(1, 2) + numel(u)"),
        "(0 .* (zeros(1, 2) + numel(u))) + 0"
    );
    assert_eq!(d("u(1)"), "(0 .* u(1)) + 1");
}

#[test]
fn prelude_names_get_derivatives_under_names_no_user_can_type() {
    let e = ParamExpr {
        prelude: vec![
            ("c".into(), Expr::parse("[u; u^2]").unwrap()),
            ("k".into(), Expr::parse("[1 2]").unwrap()),
            ("c".into(), Expr::parse("c .* u").unwrap()),
        ],
        expr: Expr::parse("k * c + c(2)").unwrap(),
        source: "k * c + c(2)".into(),
    };
    let de = e.derivative("u").unwrap();
    let entries: Vec<(String, String)> = de
        .prelude
        .iter()
        .map(|(n, x)| (n.clone(), text(x)))
        .collect();
    let expected = [
        ("dc/du", "[1; 2 .* u .* 1]"),
        ("c", "[u; u ^ 2]"),
        ("k", "[1, 2]"),
        ("dc/du#2", "(dc/du .* u) + (c .* 1)"),
        // `c .* u` itself is not read by the derivative.
    ];
    let expected: Vec<(String, String)> = expected
        .iter()
        .map(|(n, x)| (n.to_string(), x.to_string()))
        .collect();
    assert_eq!(entries, expected);
    assert_eq!(text(&de.expr), "(k * dc/du#2) + dc/du#2(2)");
    assert_eq!(de.source(), "d/du (k * c + c(2))");
}

#[test]
fn long_chains_are_linear_in_size_and_shallow() {
    for n in [10usize, 100, 1000] {
        let text = vec!["u"; n].join("*");
        let de = derivative(&text, "u");
        let size = de.node_count();
        assert!(size < 20 * n, "{n} factors: {size} nodes");
        let deepest = de
            .prelude
            .iter()
            .map(|(_, x)| depth(x))
            .chain([depth(&de.expr)])
            .max()
            .unwrap();
        assert!(deepest <= SHARED_NODES + 4, "{n} factors: depth {deepest}");
    }
}

/// The number of nodes on the longest path from the root down.
fn depth(e: &Expr) -> usize {
    let deepest = |xs: &mut dyn Iterator<Item = &Expr>| xs.map(depth).max().unwrap_or(0);
    1 + match &e.node {
        Node::Number { .. } | Node::Var(_) | Node::Colon => 0,
        Node::Call { args, .. } => deepest(&mut args.iter()),
        Node::Neg(x) | Node::Transpose(x) => depth(x),
        Node::Chain { first, rest } => {
            deepest(&mut std::iter::once(&**first).chain(rest.iter().map(|r| &r.2)))
        }
        Node::Range {
            base,
            increment,
            limit,
        } => deepest(&mut [&**base, &**limit].into_iter().chain(increment.as_deref())),
        Node::Matrix(rows) => deepest(&mut rows.iter().flat_map(|r| r.elements.iter())),
    }
}

#[test]
fn literal_integers_are_exact() {
    let lit = |s: &str| literal_integer(&Expr::parse(s).unwrap());
    assert_eq!(lit("2"), Some(2));
    assert_eq!(lit("-3"), Some(-3));
    assert_eq!(lit("--3"), Some(3));
    assert_eq!(lit("2.0e0"), Some(2));
    assert_eq!(lit("0.5"), None);
    assert_eq!(lit("3.0000000000000001"), None);
    assert_eq!(lit("1e300"), None);
    assert_eq!(lit("n"), None);
}

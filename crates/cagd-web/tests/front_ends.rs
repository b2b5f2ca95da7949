//! The same bad input through the three front ends — the command line (`cagd_cli::run`), the
//! Octave package's entry point (`cagd_octave_pkg::call`) and the page's views
//! (`cagd_web::*_view`) — gives the same error kind and the same words after the argument's
//! name: each rule is checked and worded once, in the operation layer (`cagd-ops`).
//!
//! Each row is one construction (a Bézier curve, a B-spline curve, a NURBS curve) with one bad
//! argument, written as each front end takes it. The kinds compared are the Octave package's
//! identifiers (`cagd:knots`), which the command line's and the page's kinds map onto; the
//! words are everything after `NAME: ` (the command line's `--knots`, Octave's `U`, the page's
//! `knots`).

use cagd_octave_pkg::{call, Real, Value, VecSink};

/// A curve: its control points as rows of coordinates (row `k` holds coordinate `k` of every
/// point, the thesis's columns-are-points layout).
#[derive(Clone)]
struct Points(Vec<Vec<f64>>);

impl Points {
    fn dim(&self) -> usize {
        self.0.len()
    }
    fn count(&self) -> usize {
        self.0.first().map_or(0, Vec::len)
    }
    /// Column-major, one point after the other (Octave's and the page's layout).
    fn flat(&self) -> Vec<f64> {
        (0..self.count())
            .flat_map(|j| self.0.iter().map(move |row| row[j]))
            .collect()
    }
    /// As an Octave literal with full precision, `Inf`/`NaN` spelled as Octave does.
    fn literal(&self) -> String {
        let rows: Vec<String> = self.0.iter().map(|r| numbers(r)).collect();
        format!("[{}]", rows.join("; "))
    }
}

fn number(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "Inf" } else { "-Inf" }.into()
    } else {
        format!("{x:?}")
    }
}

fn numbers(xs: &[f64]) -> String {
    xs.iter().map(|x| number(*x)).collect::<Vec<_>>().join(" ")
}

/// One construction with its arguments.
#[derive(Clone)]
enum Request {
    /// `decasteljau P --t t` / `cagd_bezier (P, t)` / `bezier_view (P, d, t, 11)`.
    Bezier { p: Points, t: f64 },
    /// `decasteljau P --n n` / `cagd_bezier (P, linspace (0, 1, n))` /
    /// `bezier_view (P, d, 0.5, n)`: `n` points of the curve.
    BezierSamples { p: Points, n: usize },
    /// `bspline P --degree p --knots U --t 0.5` / `cagd_bspline (p, P, U, 0.5)` /
    /// `bspline_view (P, d, p, U, 11)`.
    BSpline {
        degree: usize,
        p: Points,
        knots: Vec<f64>,
    },
    /// `nurbs P --weights W --degree p --knots U --t 0.5` / `cagd_nurbs (p, P, W, U, 0.5)` /
    /// `nurbs_view (P, d, W, p, U, 11)`.
    Nurbs {
        degree: usize,
        p: Points,
        weights: Vec<f64>,
        knots: Vec<f64>,
    },
}

/// What a front end said: the kind (as an Octave identifier) and the words after the name.
#[derive(Debug, PartialEq)]
struct Said {
    kind: String,
    words: String,
}

/// The words after the argument's name in `NAME: WORDS`.
fn after_name(message: &str) -> String {
    message
        .split_once(": ")
        .map_or(message, |(_, words)| words)
        .to_string()
}

/// The command line's kind as the package's identifier.
fn cli_kind(e: &cagd_cli::CliError) -> String {
    use cagd_cli::ErrorKind as K;
    let kind = match &e.kind {
        K::Library(l) => cagd_ops::Kind::of(l),
        K::Operation(k) => *k,
        K::Shape => cagd_ops::Kind::Shape,
        K::Usage => cagd_ops::Kind::Usage,
        // A typed `NaN`, `Inf` or `1e999` is refused while reading, at its column.
        K::Literal(l) if matches!(**l, cagd_octave::literal::LiteralError::NonFinite { .. }) => {
            cagd_ops::Kind::NonFinite
        }
        other => return format!("{other:?}"),
    };
    format!("cagd:{}", cagd_octave_pkg::Kind::from(kind).name())
}

fn through_cli(r: &Request) -> Option<Said> {
    let argv: Vec<String> = match r {
        Request::Bezier { p, t } => {
            vec!["decasteljau".into(), p.literal(), "--t".into(), number(*t)]
        }
        Request::BezierSamples { p, n } => {
            vec![
                "decasteljau".into(),
                p.literal(),
                "--n".into(),
                n.to_string(),
            ]
        }
        Request::BSpline { degree, p, knots } => vec![
            "bspline".into(),
            p.literal(),
            "--degree".into(),
            degree.to_string(),
            "--knots".into(),
            format!("[{}]", numbers(knots)),
            "--t".into(),
            "0.5".into(),
        ],
        Request::Nurbs {
            degree,
            p,
            weights,
            knots,
        } => vec![
            "nurbs".into(),
            p.literal(),
            "--weights".into(),
            format!("[{}]", numbers(weights)),
            "--degree".into(),
            degree.to_string(),
            "--knots".into(),
            format!("[{}]", numbers(knots)),
            "--t".into(),
            "0.5".into(),
        ],
    };
    let args = std::iter::once("cagd".to_string()).chain(argv);
    let e = cagd_cli::run(args).err()?;
    Some(Said {
        kind: cli_kind(&e),
        words: format!("{}; expected {}", e.problem, e.expected),
    })
}

fn through_octave(r: &Request) -> Option<Said> {
    let owned: Vec<(Vec<usize>, Vec<f64>)> = match r {
        Request::Bezier { p, t } => {
            vec![(vec![p.dim(), p.count()], p.flat()), (vec![1, 1], vec![*t])]
        }
        Request::BezierSamples { p, n } => vec![
            (vec![p.dim(), p.count()], p.flat()),
            (vec![1, *n], cagd::linspace(0.0, 1.0, *n)),
        ],
        Request::BSpline { degree, p, knots } => vec![
            (vec![1, 1], vec![*degree as f64]),
            (vec![p.dim(), p.count()], p.flat()),
            (vec![1, knots.len()], knots.clone()),
            (vec![1, 1], vec![0.5]),
        ],
        Request::Nurbs {
            degree,
            p,
            weights,
            knots,
        } => vec![
            (vec![1, 1], vec![*degree as f64]),
            (vec![p.dim(), p.count()], p.flat()),
            (vec![1, weights.len()], weights.clone()),
            (vec![1, knots.len()], knots.clone()),
            (vec![1, 1], vec![0.5]),
        ],
    };
    let name = match r {
        Request::Bezier { .. } | Request::BezierSamples { .. } => "cagd_bezier",
        Request::BSpline { .. } => "cagd_bspline",
        Request::Nurbs { .. } => "cagd_nurbs",
    };
    let args: Vec<Value<'_>> = owned
        .iter()
        .map(|(dims, data)| Value::Real(Real { dims, data }))
        .collect();
    let mut limits = cagd::Limits::default();
    let e = call(name, &args, 1, &mut limits, &mut VecSink::default()).err()?;
    let message = e.to_string();
    let message = message
        .strip_prefix(&format!("{name}: "))
        .unwrap_or(&message);
    Some(Said {
        kind: e.identifier(),
        words: after_name(message),
    })
}

/// The page's error text `cagd: error: NAME: WORDS` and its kind (the page shows the words;
/// the kind is the operation's, recovered from the command line's run of the same request —
/// the views report text only).
fn through_page(r: &Request) -> Option<String> {
    let answer = match r {
        Request::Bezier { p, t } => cagd_web::bezier_view(p.flat(), p.dim(), *t, 11),
        Request::BezierSamples { p, n } => cagd_web::bezier_view(p.flat(), p.dim(), 0.5, *n),
        Request::BSpline { degree, p, knots } => {
            cagd_web::bspline_view(p.flat(), p.dim(), *degree, knots.clone(), 11)
        }
        Request::Nurbs {
            degree,
            p,
            weights,
            knots,
        } => cagd_web::nurbs_view(
            p.flat(),
            p.dim(),
            weights.clone(),
            *degree,
            knots.clone(),
            11,
        ),
    };
    let v: serde_json::Value = serde_json::from_str(&answer).expect("a view answers JSON");
    let text = v["error"].as_str()?;
    Some(after_name(
        text.strip_prefix("cagd: error: ").unwrap_or(text),
    ))
}

fn quarter() -> Points {
    Points(vec![vec![1.0, 1.0, 0.0], vec![0.0, 1.0, 1.0]])
}

fn four() -> Points {
    Points(vec![vec![0.0, 1.0, 3.0, 4.0], vec![0.0, 2.0, 2.0, 0.0]])
}

fn with(p: &Points, row: usize, col: usize, x: f64) -> Points {
    let mut p = p.clone();
    p.0[row][col] = x;
    p
}

const U4: [f64; 7] = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
const U3: [f64; 6] = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];

fn bspline(degree: usize, p: Points, knots: &[f64]) -> Request {
    Request::BSpline {
        degree,
        p,
        knots: knots.to_vec(),
    }
}

fn nurbs(degree: usize, p: Points, weights: &[f64], knots: &[f64]) -> Request {
    Request::Nurbs {
        degree,
        p,
        weights: weights.to_vec(),
        knots: knots.to_vec(),
    }
}

/// The shared bad inputs: (what, the request, the kind every front end must give).
fn table() -> Vec<(&'static str, Request, &'static str)> {
    let (nan, inf) = (f64::NAN, f64::INFINITY);
    let w = [1.0, 1.0, 2.0];
    vec![
        // Bézier curves: control points, parameters, sizes.
        (
            "bezier: NaN control point",
            Request::Bezier {
                p: with(&four(), 1, 2, nan),
                t: 0.5,
            },
            "cagd:nonfinite",
        ),
        (
            "bezier: Inf control point",
            Request::Bezier {
                p: with(&four(), 0, 0, inf),
                t: 0.5,
            },
            "cagd:nonfinite",
        ),
        (
            "bezier: -Inf control point",
            Request::Bezier {
                p: with(&four(), 0, 3, -inf),
                t: 0.5,
            },
            "cagd:nonfinite",
        ),
        (
            "bezier: NaN parameter",
            Request::Bezier { p: four(), t: nan },
            "cagd:nonfinite",
        ),
        (
            "bezier: Inf parameter",
            Request::Bezier { p: four(), t: inf },
            "cagd:nonfinite",
        ),
        (
            "bezier: degree over the limit",
            Request::Bezier {
                p: Points(vec![vec![0.0; 1002]]),
                t: 0.5,
            },
            "cagd:limit",
        ),
        (
            "bezier: a result beyond the doubles",
            Request::Bezier {
                p: Points(vec![vec![1e308, -1e308]]),
                t: 5.0,
            },
            "cagd:overflow",
        ),
        // B-spline curves: knots, degree, control points.
        (
            "bspline: decreasing knots",
            bspline(2, four(), &[0.0, 0.0, 0.0, 1.0, 0.5, 1.0, 1.0]),
            "cagd:knots",
        ),
        (
            "bspline: one knot too few",
            bspline(2, four(), &U3),
            "cagd:knots",
        ),
        (
            "bspline: one knot too many",
            bspline(2, four(), &[0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0]),
            "cagd:knots",
        ),
        (
            "bspline: NaN knot",
            bspline(2, four(), &[0.0, 0.0, 0.0, nan, 1.0, 1.0, 1.0]),
            "cagd:nonfinite",
        ),
        (
            "bspline: Inf knot",
            bspline(2, four(), &[0.0, 0.0, 0.0, 0.5, inf, inf, inf]),
            "cagd:nonfinite",
        ),
        (
            "bspline: all knots equal",
            bspline(2, four(), &[1.0; 7]),
            "cagd:value",
        ),
        (
            "bspline: degree above the points",
            bspline(4, four(), &[0.0; 9]),
            "cagd:shape",
        ),
        (
            "bspline: NaN control point",
            bspline(2, with(&four(), 0, 1, nan), &U4),
            "cagd:nonfinite",
        ),
        (
            "bspline: Inf control point",
            bspline(2, with(&four(), 1, 3, inf), &U4),
            "cagd:nonfinite",
        ),
        (
            "bspline: one control point",
            bspline(2, Points(vec![vec![1.0], vec![2.0]]), &[0.0, 0.0, 0.0, 1.0]),
            "cagd:shape",
        ),
        (
            "bspline: degree over the limit",
            bspline(1001, Points(vec![vec![0.0; 1002]]), &[0.0; 2004]),
            "cagd:limit",
        ),
        (
            "bspline: cubic with three knots too few",
            bspline(3, four(), &U4),
            "cagd:knots",
        ),
        (
            "bspline: knots that fall back at the end",
            bspline(2, four(), &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 0.0]),
            "cagd:knots",
        ),
        (
            "bspline: linear with a knot too many",
            bspline(1, four(), &[0.0, 0.0, 0.3, 0.6, 1.0, 1.0, 1.0]),
            "cagd:knots",
        ),
        (
            "bspline: a knot falling back in the middle",
            bspline(1, four(), &[0.0, 0.0, 0.6, 0.3, 1.0, 1.0]),
            "cagd:knots",
        ),
        (
            "bspline: an empty domain inside repeated knots",
            bspline(2, four(), &[0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0]),
            "cagd:value",
        ),
        (
            "bspline: degree 0 with a knot too few",
            bspline(0, four(), &[0.0, 0.25, 0.5, 1.0]),
            "cagd:knots",
        ),
        (
            "bspline: three points of a cubic",
            bspline(
                3,
                Points(vec![vec![0.0, 1.0, 2.0]]),
                &[0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            ),
            "cagd:shape",
        ),
        // NURBS curves: weights, knots, degree, control points.
        (
            "nurbs: a negative first weight",
            nurbs(2, quarter(), &[-1.0, 1.0, 2.0], &U3),
            "cagd:weights",
        ),
        (
            "nurbs: a zero last weight",
            nurbs(2, quarter(), &[1.0, 1.0, 0.0], &U3),
            "cagd:weights",
        ),
        (
            "nurbs: one weight for three points",
            nurbs(2, quarter(), &[1.0], &U3),
            "cagd:shape",
        ),
        (
            "nurbs: a knot too many",
            nurbs(2, quarter(), &w, &[0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]),
            "cagd:knots",
        ),
        (
            "nurbs: knots falling back at the end",
            nurbs(2, quarter(), &w, &[0.0, 0.0, 0.0, 1.0, 1.0, 0.0]),
            "cagd:knots",
        ),
        (
            "nurbs: linear with an empty domain",
            nurbs(1, quarter(), &w, &[0.0, 0.5, 0.5, 0.5, 1.0]),
            "cagd:value",
        ),
        (
            "nurbs: a negative weight",
            nurbs(2, quarter(), &[1.0, -1.0, 2.0], &U3),
            "cagd:weights",
        ),
        (
            "nurbs: a zero weight",
            nurbs(2, quarter(), &[1.0, 0.0, 2.0], &U3),
            "cagd:weights",
        ),
        (
            "nurbs: a weight too few",
            nurbs(2, quarter(), &[1.0, 1.0], &U3),
            "cagd:shape",
        ),
        (
            "nurbs: a weight too many",
            nurbs(2, quarter(), &[1.0, 1.0, 2.0, 1.0], &U3),
            "cagd:shape",
        ),
        (
            "nurbs: NaN weight",
            nurbs(2, quarter(), &[1.0, nan, 2.0], &U3),
            "cagd:nonfinite",
        ),
        (
            "nurbs: Inf weight",
            nurbs(2, quarter(), &[1.0, inf, 2.0], &U3),
            "cagd:nonfinite",
        ),
        (
            "nurbs: decreasing knots",
            nurbs(2, quarter(), &w, &[0.0, 0.0, 1.0, 0.5, 1.0, 1.0]),
            "cagd:knots",
        ),
        (
            "nurbs: one knot too few",
            nurbs(2, quarter(), &w, &[0.0, 0.0, 0.0, 1.0, 1.0]),
            "cagd:knots",
        ),
        (
            "nurbs: NaN knot",
            nurbs(2, quarter(), &w, &[0.0, 0.0, 0.0, nan, 1.0, 1.0]),
            "cagd:nonfinite",
        ),
        (
            "nurbs: all knots equal",
            nurbs(2, quarter(), &w, &[0.5; 6]),
            "cagd:value",
        ),
        (
            "nurbs: degree above the points",
            nurbs(3, quarter(), &w, &[0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
            "cagd:shape",
        ),
        (
            "nurbs: NaN control point",
            nurbs(2, with(&quarter(), 1, 0, nan), &w, &U3),
            "cagd:nonfinite",
        ),
        (
            "nurbs: Inf control point",
            nurbs(2, with(&quarter(), 0, 2, -inf), &w, &U3),
            "cagd:nonfinite",
        ),
        (
            "nurbs: degree over the limit",
            nurbs(
                1001,
                Points(vec![vec![0.0; 1002]]),
                &[1.0; 1002],
                &[0.0; 2004],
            ),
            "cagd:limit",
        ),
    ]
}

#[test]
fn the_same_bad_input_gets_the_same_kind_and_words_everywhere() {
    let table = table();
    let mut full_words = table.len();
    let mut failures = Vec::new();
    for (what, request, kind) in &table {
        let cli = through_cli(request);
        let octave = through_octave(request);
        let page = through_page(request);
        let (Some(cli), Some(octave), Some(page)) = (&cli, &octave, &page) else {
            failures.push(format!(
                "{what}: not refused everywhere: cli {cli:?}, octave {octave:?}, page {page:?}"
            ));
            continue;
        };
        if cli.kind != *kind || octave.kind != *kind {
            failures.push(format!(
                "{what}: kinds cli {} / octave {}, expected {kind}",
                cli.kind, octave.kind
            ));
        }
        let words = [plain(&cli.words), plain(&octave.words), plain(page)];
        // The command line reads text: a non-finite number is refused while reading, at its
        // column (it never holds a NaN; exact arithmetic has none), so only the kind is shared.
        let read_as_text = *kind == "cagd:nonfinite" && cli.words.contains("column");
        if read_as_text {
            full_words -= 1;
        }
        if words[1] != words[2] || (!read_as_text && words[0] != words[1]) {
            failures.push(format!(
                "{what}: different words\n  cli:    {}\n  octave: {}\n  page:   {}",
                words[0], words[1], words[2]
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // At least 30 bad inputs read word for word the same in all three.
    assert!(full_words >= 30, "{full_words} rows compared word for word");
}

/// The words without what each front end adds in its own terms: how to raise a limit
/// (`--max-degree` on the command line, `cagd_limits` in Octave; the page has no control) and,
/// on the command line, how the text of its points was read (`(read as 4 points in 2-D, one
/// per column; --rows if each row is a point)`, which the other front ends, given arrays, have
/// no need of).
fn plain(words: &str) -> String {
    let mut out = words.to_string();
    for start_of in [" (raise it with", " (read as", " (CONTROL read as"] {
        if let Some(start) = out.find(start_of) {
            out = without_group(&out, start);
        }
    }
    out
}

/// `words` without the parenthesised group that starts at `start` (a space, then `(`).
fn without_group(words: &str, start: usize) -> String {
    let mut depth = 0;
    for (k, c) in words[start..].char_indices() {
        match c {
            '(' => depth += 1,
            ')' if depth == 1 => {
                return format!("{}{}", &words[..start], &words[start + k + 1..]);
            }
            ')' => depth -= 1,
            _ => {}
        }
    }
    words[..start].to_string()
}

/// The largest Bézier, B-spline and NURBS curves the default limits allow are computed by all
/// three front ends, and one degree more is refused by all three with the same words.
#[test]
fn the_front_ends_share_the_largest_allowed_request() {
    let max = cagd::Limits::default().max_degree;
    let flat = |n: usize| Points(vec![(0..n).map(|i| i as f64).collect()]);
    let clamped = |n: usize, p: usize| -> Vec<f64> {
        let mut u = vec![0.0; p + 1];
        u.extend((1..n - p).map(|i| i as f64 / (n - p) as f64));
        u.extend(vec![1.0; p + 1]);
        u
    };
    for degree in [max, max + 1] {
        let n = degree + 1;
        let requests = [
            Request::Bezier { p: flat(n), t: 0.5 },
            bspline(degree, flat(n), &clamped(n, degree)),
            nurbs(degree, flat(n), &vec![1.0; n], &clamped(n, degree)),
        ];
        for r in &requests {
            let (cli, octave, page) = (through_cli(r), through_octave(r), through_page(r));
            if degree == max {
                assert_eq!(
                    (&cli, &octave, &page),
                    (&None, &None, &None),
                    "degree {degree}"
                );
            } else {
                let (cli, octave, page) = (cli.unwrap(), octave.unwrap(), page.unwrap());
                assert_eq!(cli.kind, "cagd:limit");
                assert_eq!(octave.kind, "cagd:limit");
                assert_eq!(plain(&cli.words), plain(&octave.words));
                assert_eq!(plain(&cli.words), plain(&page));
            }
        }
    }
}

/// The largest Bézier request the default `max_work` allows — as many points as the core's
/// estimate of de Casteljau's work ([`cagd::BezierCurve::eval_cost`]) allows for a curve of
/// degree 99 in 101 dimensions — is computed by all three front ends, and one point more is
/// refused by all three with the same words: each prices the work with the same estimate.
#[test]
fn the_front_ends_share_the_largest_allowed_work() {
    let max = u128::from(cagd::Limits::default().max_work);
    let p = Points(
        (0..101)
            .map(|r| (0..100).map(|j| ((r * 7 + j * 13) % 17) as f64).collect())
            .collect(),
    );
    let curve = cagd::BezierCurve::new(nalgebra::DMatrix::from_row_slice(101, 100, &{
        let rows: Vec<f64> = p.0.iter().flatten().copied().collect();
        rows
    }))
    .unwrap();
    let per_point = curve.eval_cost(0, 0).weigh(false);
    let largest = usize::try_from(max / per_point).unwrap();
    // 1980 points of 1 010 000 operations: within the page's 2000 samples, so that the page
    // refuses the next request for its work, as the others do.
    assert_eq!((per_point, largest), (1_010_000, 1980));
    let allowed = Request::BezierSamples {
        p: p.clone(),
        n: largest,
    };
    let (cli, octave, page) = (
        through_cli(&allowed),
        through_octave(&allowed),
        through_page(&allowed),
    );
    assert_eq!((&cli, &octave, &page), (&None, &None, &None));
    let over = Request::BezierSamples { p, n: largest + 1 };
    let (cli, octave, page) = (
        through_cli(&over).unwrap(),
        through_octave(&over).unwrap(),
        through_page(&over).unwrap(),
    );
    assert_eq!(
        (cli.kind.as_str(), octave.kind.as_str()),
        ("cagd:limit", "cagd:limit")
    );
    let words = format!(
        "estimated operations: {} exceeds the limit of {max}; expected fewer points or a lower degree",
        per_point * (largest as u128 + 1)
    );
    assert_eq!(plain(&cli.words), words);
    assert_eq!(plain(&octave.words), words);
    assert_eq!(plain(&page), words);
}

//! The catalogue against the messages the program really gives: the common errors (knots,
//! degree, weights, shapes, non-finite values, domain, limits) through the command box and the
//! views, each in Slovenian and Czech with no English word left.

use super::*;

fn error(args: &[&str]) -> String {
    let argv = std::iter::once("cagd")
        .chain(args.iter().copied())
        .map(String::from)
        .collect();
    let v: serde_json::Value = serde_json::from_str(&crate::run(argv, vec![], vec![])).unwrap();
    assert_eq!(v["ok"], false, "{args:?}");
    v["error"].as_str().unwrap().to_string()
}

/// English words of the messages that no translation may keep.
const ENGLISH: &[&str] = &[
    "expected", "knot", "knots", "must", "control", "points", "point", "degree", "weight",
    "weights", "outside", "domain", "column", "accepted", "finite", "values", "exceeds", "limit",
    "raise", "read", "error", "number", "list", "range", "samples", "is", "the", "of", "below",
    "given", "together", "order", "too", "small", "basis",
];

fn english_left(text: &str) -> Vec<String> {
    // "cagd: HEAD: NAME: BODY": the words of the body.
    let body = text.splitn(4, ": ").nth(3).unwrap_or(text);
    body.split_whitespace()
        .filter(|token| !token.trim_start_matches('(').starts_with('-')) // option names
        .flat_map(|token| token.split(|c: char| !c.is_alphanumeric()))
        .filter(|w| ENGLISH.contains(w))
        .map(String::from)
        .collect()
}

const C: &str = "[0 0; 1 1; 2 0; 3 1]'";

/// The common errors, as the command box gives them.
const COMMON_ERRORS: &[&[&str]] = &[
    &[
        "bspline",
        C,
        "--degree",
        "2",
        "--knots",
        "[0 0 0 1 0.5 1 1]",
    ],
    &["bspline", C, "--degree", "2", "--knots", "[0 0 0 1 1]"],
    &["bspline", C, "--degree", "5", "--knots", "[0 0 0 1 1 1]"],
    &["bspline", C, "--degree", "2", "--knots", "[0 0 0 0 0 0 0]"],
    &[
        "bspline",
        C,
        "--degree",
        "2",
        "--knots",
        "[0 0 0 NaN 1 1 1]",
    ],
    &["bspline", C, "--degree", "2", "--t", "3"],
    &["bspline", C, "--degree", "2", "--t", "Inf"],
    &["bspline", C, "--degree", "2000"],
    &["bspline", C, "--order", "0"],
    &["bspline", C, "--degree", "2", "--order", "3"],
    &["bspline", C, "--degree", "2", "--n", "1"],
    &["bspline", C, "--degree", "2", "--n", "100000000000"],
    &["bspline", "[0 NaN; 1 1; 2 0]'"],
    &["bspline", "[0 0; 1 1]'", "--knots", "[0 0 1 1]"],
    &["nurbs", C, "--degree", "2", "--weights", "[1 -1 1 1]"],
    &["nurbs", C, "--degree", "2", "--weights", "[1 0 1 1]"],
    &["nurbs", C, "--degree", "2", "--weights", "[1 1 1]"],
    &["nurbs", C, "--degree", "2", "--weights", "[1 NaN 1 1]"],
    &["decasteljau", "[1 2; 3]"],
    &["decasteljau", "[0 NaN; 1 1]"],
    &["decasteljau", C, "--n", "1"],
    &["decasteljau", C, "--t", "[0 1"],
    &["decasteljau", C, "--t", "NaN"],
    &["insert-knot", C, "--degree", "2", "--insert", "5"],
    &[
        "bspline-basis",
        "--degree",
        "2",
        "--knots",
        "[0 0 1 0.5 2 2]",
    ],
    &[
        "bspline-basis",
        "--degree",
        "2",
        "--knots",
        "[0 0 0 1 1 1]",
        "--t",
        "5",
    ],
    &["lagrange", "--nodes", "[0 0 1]"],
    &["lagrange", "--nodes", "[0 0.5 1]", "--points", "[1 2]"],
    &["elevate", C, "--by", "2000"],
    &["bernstein", "--degree", "3", "--i", "5"],
    &[
        "bspline-surface",
        "--x",
        "[0 1; 0 1]",
        "--y",
        "[0 0; 1 1]",
        "--z",
        "[0 0; 0 0]",
        "--degree",
        "3",
    ],
    &[
        "bspline-surface",
        "--x",
        "[0 1 2; 0 1 2; 0 1 2]",
        "--y",
        "[0 0 0; 1 1 1; 2 2 2]",
        "--z",
        "[0 0 0; 0 1 0; 0 0 0]",
        "--degree",
        "2",
        "--uknots",
        "[0 0 1 0 1 1]",
    ],
    &[
        "nurbs-surface",
        "--x",
        "[0 1 2; 0 1 2; 0 1 2]",
        "--y",
        "[0 0 0; 1 1 1; 2 2 2]",
        "--z",
        "[0 0 0; 0 1 0; 0 0 0]",
        "--degree",
        "2",
        "--weights",
        "[1 1 1; 1 -2 1; 1 1 1]",
    ],
];

#[test]
fn the_common_errors_of_the_command_box_read_wholly_in_slovenian_and_czech() {
    let mut wrong = Vec::new();
    for args in COMMON_ERRORS {
        let e = error(args);
        for lang in [Lang::Sl, Lang::Cs] {
            match translate(&e, lang) {
                Some(local) if english_left(&local).is_empty() && local != e => {}
                other => wrong.push(format!("{e}\n  ({}) {other:?}", lang.code())),
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn bad_knots_in_the_command_box_in_slovenian_and_czech() {
    let e = error(&[
        "bspline",
        C,
        "--degree",
        "2",
        "--knots",
        "[0 0 0 1 0.5 1 1]",
    ]);
    assert_eq!(
        message_in(&e, "sl"),
        "cagd: napaka: --knots: vozliščni vektor: vozel 5 (0.5) je manjši od vozla pred njim (1); \
         vozli morajo biti nepadajoči; pričakovano: n + p + 1 nepadajočih vozlov za n kontrolnih \
         točk stopnje p (n ≥ p + 1), pri čemer u_(p+1) < u_(n+1)"
    );
    assert_eq!(
        message_in(&e, "cs"),
        "cagd: chyba: --knots: uzlový vektor: uzel 5 (0.5) je menší než uzel před ním (1); \
         uzly musí být neklesající; očekává se: n + p + 1 neklesajících uzlů pro n řídicích bodů \
         stupně p (n ≥ p + 1), přičemž u_(p+1) < u_(n+1)"
    );
    let e = error(&["bspline", C, "--degree", "2", "--knots", "[0 0 0 1 1]"]);
    assert_eq!(
        message_in(&e, "sl"),
        "cagd: napaka: --knots: vozliščni vektor: pričakovano število vozlov je 7 (kontrolne točke \
         + stopnja + 1), podano: 5 (CONTROL prebrano kot točke v 2-D, ena na stolpec (število \
         točk: 4); --rows, če je vsaka vrstica točka); pričakovano: n + p + 1 nepadajočih vozlov \
         za n kontrolnih točk stopnje p (n ≥ p + 1), pri čemer u_(p+1) < u_(n+1)"
    );
}

#[test]
fn bad_knots_and_weights_of_the_views_in_slovenian() {
    let v: serde_json::Value = serde_json::from_str(&crate::bspline_view(
        vec![0., 0., 1., 1., 2., 0., 3., 1.],
        2,
        2,
        vec![0., 0., 0., 1., 0.5, 1., 1.],
        11,
    ))
    .unwrap();
    let e = v["error"].as_str().unwrap();
    assert_eq!(
        message_in(e, "sl"),
        "cagd: napaka: knots: vozliščni vektor: vozel 5 (0.5) je manjši od vozla pred njim (1); \
         vozli morajo biti nepadajoči; pričakovano: n + p + 1 nepadajočih vozlov za n kontrolnih \
         točk stopnje p (n ≥ p + 1), pri čemer u_(p+1) < u_(n+1)"
    );
    let v: serde_json::Value = serde_json::from_str(&crate::nurbs_view(
        vec![0., 0., 1., 1., 2., 0.],
        2,
        vec![1., -1., 1.],
        2,
        vec![],
        11,
    ))
    .unwrap();
    let e = v["error"].as_str().unwrap();
    assert_eq!(
        message_in(e, "cs"),
        "cagd: chyba: weights: váhy NURBS: váha 2 je -1; váhy musí být kladné; očekává se: jedna \
         kladná váha na řídicí bod"
    );
}

#[test]
fn a_message_with_words_outside_the_catalogue_stays_english_whole() {
    let e = "cagd: error: --t: spline parameters: t_3 = 2 is not above t_2 = 2; expected increasing values";
    assert_eq!(translate(e, Lang::Sl), None);
    assert_eq!(message_in(e, "sl"), e);
    // A known phrase inside an unknown message does not make it half Slovenian.
    let e = "cagd: error: --knots: knot vector: something new happened; expected knots";
    assert_eq!(message_in(e, "cs"), e);
    // Not a message of the program: as it is.
    assert_eq!(message_in("Done.", "sl"), "Done.");
}

#[test]
fn values_are_copied_as_they_are() {
    let e = "cagd: error: CONTROL: column 4: `Inf knot` is not accepted; expected finite real values; expected control points b_0..b_n, one per column";
    assert_eq!(
        message_in(e, "sl"),
        "cagd: napaka: CONTROL: stolpec 4: `Inf knot` ni dovoljeno; pričakovano: končne realne \
         vrednosti; pričakovano: kontrolne točke b_0..b_n, ena na stolpec"
    );
    // A limit names its flag and variable unchanged.
    let e = error(&["bspline", C, "--degree", "2000"]);
    let cs = message_in(&e, "cs");
    assert!(
        cs.contains(
            "2000 překračuje mez 1000 (zvýšíte ji pomocí --max-degree nebo CAGD_MAX_DEGREE)"
        ),
        "{cs}"
    );
}

#[test]
fn every_phrase_has_the_value_places_of_its_english_in_both_languages() {
    let places = |s: &str| {
        let mut p: Vec<usize> = parts(s)
            .into_iter()
            .filter_map(|p| match p {
                Part::Value(n) => Some(n),
                Part::Words(_) => None,
            })
            .collect();
        p.sort_unstable();
        p
    };
    let mut seen = std::collections::BTreeSet::new();
    for phrase in PHRASES {
        assert!(seen.insert(phrase.en), "twice: {}", phrase.en);
        assert!(
            !phrase.sl.is_empty() && !phrase.cs.is_empty(),
            "{}",
            phrase.en
        );
        let en = places(phrase.en);
        assert_eq!(places(phrase.sl), en, "{}", phrase.en);
        assert_eq!(places(phrase.cs), en, "{}", phrase.en);
        // Values are separated by words, so each one ends somewhere.
        let parts = parts(phrase.en);
        for pair in parts.windows(2) {
            assert!(
                !matches!(pair, [Part::Value(_), Part::Value(_)]),
                "{}",
                phrase.en
            );
        }
    }
}

#[test]
fn warnings_and_notes_read_in_the_page_language() {
    let w = "cagd: warning: CONTROL: read as 3 points in 3-D, one per column; --rows if each row is a point";
    assert_eq!(
        message_in(w, "sl"),
        "cagd: opozorilo: CONTROL: prebrano kot točke v 3-D, ena na stolpec (število točk: 3); \
         --rows, če je vsaka vrstica točka"
    );
    let w = "cagd: warning: --t: t = 1.5 lies outside [0, 1]; the curve is extrapolated there";
    assert_eq!(
        message_in(w, "cs"),
        "cagd: varování: --t: t = 1.5 leží mimo [0, 1]; křivka je tam extrapolována"
    );
}

#[test]
fn boundary_curves_that_do_not_meet_in_czech() {
    let e = error(&[
        "coons", "--c1", "[u;0;0]", "--c2", "[u;1;0]", "--d1", "[0;v;0]", "--d2", "[1;v;5]",
    ]);
    assert_eq!(
        message_in(&e, "cs"),
        "cagd: chyba: --c1/--c2/--d1/--d2: hraniční křivky se nestýkají v rozích (relativní \
         tolerance 1e-10): v x(1,0) (P2) c1(1) a d2(0): rozdíl 5e0 (povoleno 5e-10); v x(1,1) \
         (P4) c2(1) a d2(1): rozdíl 5e0 (povoleno 5e-10); očekává se: čtyři hraniční křivky, \
         které se stýkají v rozích: c1(0)=d1(0), c1(1)=d2(0), c2(0)=d1(1), c2(1)=d2(1)"
    );
}

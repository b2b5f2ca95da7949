//! `--lang en|sl|cs`: the readable steps labelled in the languages of the sources (the thesis
//! and the CAD notes are Slovenian, the lecture notes Czech) from one table, the items keeping
//! their names; the option may stand before or after the subcommand.

use cagd_cli::lang::{label, Lang};

fn stdout(args: &[&str]) -> String {
    let argv = std::iter::once("cagd").chain(args.iter().copied());
    match cagd_cli::run(argv) {
        Ok(outcome) => outcome.stdout,
        Err(e) => panic!("cagd {args:?}: {e}"),
    }
}

const PRIMER_2_4: [&str; 6] = [
    "decasteljau",
    "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'",
    "--t",
    "1/2",
    "--steps",
    "--exact",
];

#[test]
fn steps_are_labelled_in_slovenian_and_czech_and_keep_their_names() {
    let sl = stdout(&[&PRIMER_2_4[..], &["--lang", "sl"]].concat());
    assert!(sl.starts_with("% de Casteljaujeva shema b_i^r(t)"), "{sl}");
    assert!(
        sl.contains("scheme:\nde Casteljaujeva shema, stopnja 3, t = 1/2\n"),
        "{sl}"
    );
    assert!(
        sl.contains("% rezultat\nresult =\n\n    7/2\n    3/2\n    3/4\n"),
        "{sl}"
    );
    let cs = stdout(&[&PRIMER_2_4[..], &["--lang", "cs"]].concat());
    assert!(
        cs.contains("de Casteljauovo schéma, stupeň 3, t = 1/2"),
        "{cs}"
    );
    assert!(cs.contains("% výsledek\nresult ="), "{cs}");
    // Primer 4.3 in Slovenian: r_c, r_d and r_cd with the thesis's words.
    let coons = stdout(&[
        "coons",
        "--c1",
        "[u;0;u-u^2]",
        "--c2",
        "[u;1;u]",
        "--d1",
        "[0;v^2;v-v^2]",
        "--d2",
        "[1;v;v]",
        "--u",
        "0.2",
        "--v",
        "0.5",
        "--steps",
        "--exact",
        "--lang",
        "sl",
    ]);
    assert!(
        coons.contains(
            "% r_cd: bilinearna interpolacija štirih oglišč\nrcd =\n\n     1/5\n     1/2\n    1/10\n"
        ),
        "{coons}"
    );
}

#[test]
fn lang_before_the_subcommand_is_the_same_option() {
    let after = stdout(&[&PRIMER_2_4[..], &["--lang", "cs"]].concat());
    let before = stdout(&[&["--lang", "cs"], &PRIMER_2_4[..]].concat());
    assert_eq!(before, after);
}

#[test]
fn english_labels_only_when_asked_and_the_machine_formats_are_the_same_in_every_language() {
    let plain = stdout(&PRIMER_2_4);
    assert!(!plain.contains('%'), "{plain}");
    let en = stdout(&[&PRIMER_2_4[..], &["--lang", "en"]].concat());
    assert!(en.starts_with("% the de Casteljau scheme"), "{en}");
    assert_eq!(
        en.lines()
            .filter(|l| !l.starts_with('%'))
            .collect::<Vec<_>>(),
        plain.lines().collect::<Vec<_>>()
    );
    for format in ["json", "csv", "octave"] {
        let base = stdout(&[&PRIMER_2_4[..], &["--format", format]].concat());
        for lang in ["sl", "cs"] {
            assert_eq!(
                stdout(&[&PRIMER_2_4[..], &["--format", format, "--lang", lang]].concat()),
                base,
                "{format} {lang}"
            );
        }
    }
}

#[test]
fn every_step_the_course_prints_has_a_label_in_each_language() {
    let runs: [&[&str]; 6] = [
        &PRIMER_2_4,
        &[
            "bspline",
            "[0 0; 1 2; 2 3; 3 1; 4 2; 5 0]'",
            "--degree",
            "2",
            "--knots",
            "[0 0 0 1 2 2 3 3 3]",
            "--t",
            "3/2",
            "--steps",
            "--exact",
        ],
        &[
            "insert-knot",
            "[0 0; 1 2; 2 3; 3 1; 4 2; 5 0]'",
            "--degree",
            "2",
            "--knots",
            "[0 0 0 1 2 2 3 3 3]",
            "--insert",
            "3/2",
            "--steps",
            "--exact",
        ],
        &[
            "bspline-basis",
            "--knots",
            "[0 0 0 0 1 2 3 3 3 3]",
            "--degree",
            "3",
            "--t",
            "3/2",
            "--steps",
            "--exact",
        ],
        &[
            "spline",
            "[0 0; 2 1; 4 4; 6 0]'",
            "--start-tangent",
            "[1;1]",
            "--end-tangent",
            "[-1;1]",
            "--t",
            "1",
            "--steps",
            "--exact",
        ],
        &[
            "subdivide",
            "[0 0; 0 2; 8 2; 4 0]'",
            "--t",
            "1/3",
            "--steps",
            "--exact",
        ],
    ];
    for args in runs {
        let out = stdout(args);
        for line in out.lines() {
            let Some(name) = line
                .strip_suffix(" =")
                .or_else(|| line.strip_suffix(':'))
                .or_else(|| line.split(" = ").next().filter(|n| n.len() < line.len()))
            else {
                continue;
            };
            if name.is_empty() || name.contains(' ') || name.starts_with('(') {
                continue;
            }
            for lang in Lang::ALL {
                assert!(
                    label(name, lang).is_some(),
                    "no {lang:?} label for `{name}` ({args:?})"
                );
            }
        }
    }
}

//! Bad input across every subcommand: each case names the exact error (the argument and the
//! kind, down to the typed error underneath), and the `cagd` binary exits with code 2, prints
//! one line on standard error, nothing on standard output, and leaves no file behind.

use std::path::Path;

use assert_cmd::Command;
use cagd_cli::{run, ErrorKind};

use cagd_test_support as common;

use common::bad_input::{check_all, refused};
use common::thesis_args::{NET_3X3 as NET, PRIMER_2_4 as CUBIC, PRIMER_4_3 as COONS};

/// The kind of an error as `Kind` or `Kind::Variant` (the typed error underneath).
fn label(kind: &ErrorKind) -> String {
    let variant = |debug: String| {
        debug
            .split(|c: char| !c.is_alphanumeric())
            .next()
            .unwrap()
            .to_string()
    };
    match kind {
        ErrorKind::Literal(e) => format!("Literal::{}", variant(format!("{e:?}"))),
        ErrorKind::Library(e) => format!("Library::{}", variant(format!("{e:?}"))),
        ErrorKind::Io(k) => format!("Io::{k:?}"),
        other => variant(format!("{other:?}")),
    }
}

/// (arguments after `cagd`, the argument the error names, the kind).
fn cases(dir: &Path) -> Vec<(Vec<String>, &'static str, &'static str)> {
    let file = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let ragged = file("ragged.txt", "1 2\n3\n");
    let words = file("words.txt", "1 two\n");
    let binary = {
        let p = dir.join("binary.dat");
        std::fs::write(&p, [0xff, 0xfe, 0x00, 0x41]).unwrap();
        p.to_str().unwrap().to_string()
    };
    let octave_bad = file(
        "bad_octave.txt",
        "# name: A\n# type: matrix\n# rows: 3\n# columns: 2\n 1 2\n",
    );
    let cell = file(
        "cell.txt",
        "# name: s\n# type: string\n# elements: 1\n# length: 2\nab\n",
    );
    let script_syntax = file("syntax.m", "x = [1 2;\n");
    let script_loop = file("loop.m", "for i = 1:2000000\n  x = i;\nend\n");
    let script_chain = file("chain.m", "a = b = 0;\n");
    let missing = dir.join("missing.txt").to_str().unwrap().to_string();
    let folder = {
        let p = dir.join("a-folder.svg");
        std::fs::create_dir_all(&p).unwrap();
        p.to_str().unwrap().to_string()
    };
    let no_dir = dir
        .join("no/such/dir/out.svg")
        .to_str()
        .unwrap()
        .to_string();
    let deep = format!("{}u{}", "(".repeat(200), ")".repeat(200));
    let points = file("points.txt", "0 1 3\n0 2 0\n");
    let read_only = {
        let p = file("read-only.txt", "old");
        let mut perm = std::fs::metadata(&p).unwrap().permissions();
        perm.set_readonly(true);
        std::fs::set_permissions(&p, perm).unwrap();
        p
    };
    #[cfg(unix)]
    let looping = {
        let p = dir.join("loop.svg");
        std::os::unix::fs::symlink(&p, &p).unwrap();
        p.to_str().unwrap().to_string()
    };
    let nrb_bad = file(
        "nrb_bad.txt",
        "# name: srf\n# type: scalar struct\n# ndims: 2\n 1 1\n# length: 1\n# name: coefs\n# type: matrix\n# rows: 1\n# columns: 2\n 1 2\n\n\n",
    );
    let odd = cagd_test_support::data_file("appendix_d_odd.m")
        .to_str()
        .unwrap()
        .to_string();
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    let with = |head: &[&str], tail: &[&str]| {
        let mut v = s(&["coons"]);
        v.extend(s(head));
        v.extend(s(tail));
        v
    };
    vec![
        // usage
        (s(&[]), "cagd", "Usage"),
        (s(&["frobnicate"]), "frobnicate", "Usage"),
        (s(&["decasteljau"]), "<CONTROL>", "Usage"),
        (s(&["decasteljau", CUBIC, "--bogus"]), "--bogus", "Usage"),
        (
            s(&["decasteljau", CUBIC, "--format", "xml"]),
            "--format",
            "Usage",
        ),
        (s(&["bernstein", "--degree", "-1"]), "-1", "Usage"),
        (s(&["bernstein", "--degree", "three"]), "--degree", "Usage"),
        (s(&["thesis", "--bogus"]), "--bogus", "Usage"),
        (
            s(&["curve", "[u;u]", "--t", "0.5", "--n", "3"]),
            "--t",
            "Usage",
        ),
        (
            s(&["decasteljau", CUBIC, "--max-degree", "x"]),
            "--max-degree",
            "Usage",
        ),
        // literals and expressions
        (
            s(&["decasteljau", "[1 2; 3]"]),
            "CONTROL",
            "Literal::RaggedRows",
        ),
        (s(&["decasteljau", "[1 2"]), "CONTROL", "Literal::Syntax"),
        (
            s(&["decasteljau", "[1 w]"]),
            "CONTROL",
            "Literal::UnknownVariable",
        ),
        (
            s(&["decasteljau", "[1 2] + [1 2 3]"]),
            "CONTROL",
            "Literal::Shape",
        ),
        (s(&["decasteljau", CUBIC, "--t", "1:0"]), "--t", "Shape"),
        (
            s(&["decasteljau", CUBIC, "--t", "[0 1; 2 3]"]),
            "--t",
            "Literal::Shape",
        ),
        (
            s(&["decasteljau", CUBIC, "--t", "0:1e-9:1"]),
            "--t",
            "Literal::TooLarge",
        ),
        (
            s(&["decasteljau", "1e999"]),
            "CONTROL",
            "Literal::NumberOutOfRange",
        ),
        (
            s(&["decasteljau", "[0 sqrt(2)]", "--exact"]),
            "CONTROL",
            "Literal::NotRational",
        ),
        (
            s(&["curve", "[u; frob(u)]"]),
            "EXPR",
            "Literal::UnknownFunction",
        ),
        (
            s(&["curve", "[u; sqrt(u, 2)]"]),
            "EXPR",
            "Literal::Argument",
        ),
        (s(&["curve", &deep]), "EXPR", "Literal::TooDeep"),
        (
            s(&["curve", "[u; 1/(u-u)]", "--exact", "--t", "0.5"]),
            "EXPR",
            "Literal::DivisionByZero",
        ),
        (s(&["curve", "[u; q]"]), "EXPR", "Literal::UnknownVariable"),
        (s(&["curve", "[u; 'text']"]), "EXPR", "Literal::Unsupported"),
        (s(&["curve", "[u; Inf]"]), "EXPR", "Literal::NonFinite"),
        (s(&["curve", "[u; v]"]), "EXPR", "Shape"),
        (
            s(&["surface", "[u; v; u.*v]", "--u", "[0 NaN]"]),
            "--u",
            "Literal::NonFinite",
        ),
        // files
        (s(&["decasteljau", &missing]), "CONTROL", "Io::NotFound"),
        (s(&["decasteljau", &ragged]), "CONTROL", "Data"),
        (s(&["decasteljau", &words]), "CONTROL", "Data"),
        (s(&["decasteljau", &binary]), "CONTROL", "Data"),
        (s(&["bezier-patch", &octave_bad]), "NET", "Data"),
        (s(&["bezier-patch", &cell]), "NET", "Data"),
        (s(&["script", &missing]), "--script", "Io::NotFound"),
        (
            s(&["script", &script_syntax]),
            "--script",
            "Literal::Syntax",
        ),
        (
            s(&["script", &script_loop]),
            "--script",
            "Literal::TooLarge",
        ),
        (
            s(&["script", &script_chain]),
            "--script",
            "Literal::ChainedAssignment",
        ),
        (
            s(&["coons", "--script", &missing]),
            "--script",
            "Io::NotFound",
        ),
        // shapes, limits and constructions
        (s(&["decasteljau", CUBIC, "--n", "1"]), "--n", "Shape"),
        (
            s(&["decasteljau", CUBIC, "--n", "2000000"]),
            "--n",
            "Library::TooLarge",
        ),
        (
            s(&["decasteljau", "zeros(2, 1002)"]),
            "CONTROL",
            "Library::TooLarge",
        ),
        (
            s(&["decasteljau", CUBIC, "--max-degree", "2"]),
            "CONTROL",
            "Library::TooLarge",
        ),
        (
            s(&["bezier-patch", NET, "--n", "4000"]),
            "--u/--v",
            "Library::TooLarge",
        ),
        (
            s(&["decasteljau", "zeros(3, 1000)", "--n", "100000"]),
            "--t",
            "Library::TooLarge",
        ),
        (
            s(&["bernstein", "--degree", "1000", "--n", "100000"]),
            "--t",
            "Library::TooLarge",
        ),
        (
            s(&["lagrange", "--nodes", "0:0.001:0.999", "--n", "100000"]),
            "--t",
            "Library::TooLarge",
        ),
        (
            s(&["derivative", "zeros(3, 1000)", "--t", "0:1e-5:1"]),
            "--t",
            "Library::TooLarge",
        ),
        (s(&["bezier-patch", "[1 2]"]), "NET", "Shape"),
        (
            s(&["surface", "[u; v; u.*v]", "--n", "5000"]),
            "--u/--v",
            "Library::TooLarge",
        ),
        (s(&["surface", "[u; v; u.*v]", "--n", "1"]), "--n", "Shape"),
        (
            s(&["bernstein", "--degree", "5000"]),
            "--degree",
            "Library::TooLarge",
        ),
        (
            s(&["bernstein", "--degree", "3", "--i", "4"]),
            "--i",
            "Shape",
        ),
        (
            s(&["derivative", CUBIC, "-r", "4"]),
            "-r",
            "Library::DerivativeOrder",
        ),
        (
            s(&["lagrange", "--nodes", "[0 0.5 0.5]"]),
            "--nodes",
            "Library::DuplicateNodes",
        ),
        (
            s(&["lagrange", "--nodes", "[0 1]", "--points", "[1 2 3]"]),
            "--points",
            "Library::ShapeMismatch",
        ),
        (
            s(&[
                "coons", "--c1", "[u;0;0]", "--c2", "[u;1;0]", "--d1", "[0;v;0]", "--d2", "[2;v;0]",
            ]),
            "--c1/--c2/--d1/--d2",
            "Library::CornerMismatch",
        ),
        (with(&COONS, &["--n", "1"]), "--n", "Shape"),
        (with(&COONS[..6], &[]), "--d2", "Usage"),
        (
            with(&COONS, &["--n", "4000"]),
            "--u/--v",
            "Library::TooLarge",
        ),
        (
            s(&[
                "coons",
                "--c1",
                "[sin(u);0;0]",
                "--c2",
                "[u;1;0]",
                "--d1",
                "[0;v;0]",
                "--d2",
                "[1;v;0]",
                "--exact",
            ]),
            "--c1",
            "Literal::NotRational",
        ),
        (with(&COONS, &["--c1", "[u;0;0]"]), "--c1", "Usage"),
        (
            s(&[
                "coons-bicubic",
                "--c1",
                "[u;0;0]",
                "--c2",
                "[u;1;0]",
                "--d1",
                "[0;v;0]",
                "--d2",
                "[1;v;0]",
            ]),
            "--d1u",
            "Usage",
        ),
        (
            s(&[
                "coons-bicubic",
                "--c1",
                "[u;0;0]",
                "--c2",
                "[u;1;0]",
                "--d1",
                "[0;v;0]",
                "--d2",
                "[1;v;0]",
                "--c1v",
                "[0;1;0]",
                "--c2v",
                "[0;1;0]",
                "--d1u",
                "[1;0;0]",
                "--d2u",
                "[1;0;0]",
                "--twist",
                "given",
            ]),
            "--twists",
            "Usage",
        ),
        (s(&["discrete-coons", "[1 2]"]), "NET", "Shape"),
        (
            s(&["discrete-coons", NET, "--mask=0.1,0.2"]),
            "--mask",
            "Library::MaskNotAffine",
        ),
        (s(&["discrete-coons", NET, "--mask=1"]), "--mask", "Shape"),
        (
            s(&["gordon", "--v-curve", "[u;0;0]", "--u-curve", "[0;v;0]"]),
            "--u-curve",
            "Shape",
        ),
        (
            s(&[
                "gordon",
                "--v-curve",
                "[u;0;0]",
                "--v-curve",
                "[u;1;0]",
                "--u-curve",
                "[0;v;0]",
                "--u-curve",
                "[1;v;1]",
            ]),
            "--u-curve/--v-curve",
            "Library::NetworkMismatch",
        ),
        (
            s(&[
                "gordon",
                "--v-curve",
                "[u;0;0]",
                "--v-curve",
                "[u;1;0]",
                "--u-curve",
                "[0;v;0]",
                "--u-curve",
                "[1;v;0]",
                "--u-nodes",
                "[1 0]",
            ]),
            "--u-curve/--v-curve",
            "Library::UnsortedNodes",
        ),
        (
            s(&["spline", "[0 0; 1 1; 2 0]'", "--end", "clamped"]),
            "--start-tangent",
            "Usage",
        ),
        (s(&["spline", "[0 0]'"]), "POINTS", "Library::TooFewPoints"),
        (
            s(&[
                "hermite", "--p0", "[0;0]", "--p1", "[1;0;0]", "--t0", "[1;1]", "--t1", "[1;1]",
            ]),
            "--p0/--p1/--t0/--t1",
            "Library::ShapeMismatch",
        ),
        (
            s(&["bspline", "[0 0; 1 2]'", "--degree", "3"]),
            "CONTROL",
            "Library::TooFewControlPoints",
        ),
        (
            s(&[
                "bspline",
                "[0 0; 1 2; 3 2]'",
                "--degree",
                "1",
                "--knots",
                "[0 1 0.5 1 1]",
            ]),
            "--knots",
            "Library::DecreasingKnots",
        ),
        (
            s(&[
                "bspline",
                "[0 0; 1 2; 3 2]'",
                "--degree",
                "1",
                "--knots",
                "[0 0 1 1]",
            ]),
            "--knots",
            "Library::KnotCount",
        ),
        (
            s(&[
                "nurbs",
                "[1 0; 1 1; 0 1]'",
                "--weights",
                "[1 0 1]",
                "--degree",
                "2",
            ]),
            "--weights",
            "Library::NonPositiveWeight",
        ),
        (
            s(&[
                "nurbs",
                "[1 0; 1 1; 0 1]'",
                "--weights",
                "[1 1 1]",
                "--degree",
                "2",
                "--t",
                "2",
            ]),
            "--t",
            "Library::ParameterOutOfRange",
        ),
        // the course subcommands: wrong shapes, NaN, empty input, absurd sizes, options
        // without effect
        (
            s(&["convert", "[1 2 3]", "--from", "hermite", "--to", "bezier"]),
            "GEOMETRY",
            "Shape",
        ),
        (
            s(&[
                "convert",
                "[1 NaN 3 4]",
                "--from",
                "bezier",
                "--to",
                "hermite",
            ]),
            "GEOMETRY",
            "Literal::NonFinite",
        ),
        (
            s(&["convert", "[]", "--from", "bezier", "--to", "monomial"]),
            "GEOMETRY",
            "Shape",
        ),
        (
            s(&[
                "convert",
                "zeros(1, 2000)",
                "--from",
                "bezier",
                "--to",
                "monomial",
            ]),
            "GEOMETRY",
            "Library::TooLarge",
        ),
        (
            s(&["convert", "[1 2]", "--to", "bezier"]),
            "--from",
            "Usage",
        ),
        (
            s(&["elevate", "[0 1]", "--by", "5000"]),
            "--by",
            "Library::TooLarge",
        ),
        // A Bézier curve of degree 899 raised by 99 is some 10⁶ operations (it runs); the
        // blossoms of a cubic B-spline of 900 control points raised by 99 are 5.7·10⁹.
        (
            s(&[
                "elevate",
                "zeros(3, 900)",
                "--by",
                "99",
                "--knots",
                "[0 0 0 linspace(0, 1, 898) 1 1 1]",
            ]),
            "--by",
            "Library::TooLarge",
        ),
        (s(&["elevate", "[0 NaN]"]), "CONTROL", "Literal::NonFinite"),
        (s(&["elevate", "[]"]), "CONTROL", "Library::TooFewPoints"),
        (
            s(&[
                "elevate",
                "[0 1 2]",
                "--degree",
                "1",
                "--knots",
                "[0 1 2 3 4]",
            ]),
            "--knots",
            "Library::InvalidArgument",
        ),
        (
            s(&["subdivide", CUBIC, "--t", "1"]),
            "--t",
            "Library::EmptyInterval",
        ),
        (s(&["subdivide", CUBIC, "--t", "[0.2 0.3]"]), "--t", "Shape"),
        (
            s(&["subdivide", "[0 NaN 1]"]),
            "CONTROL",
            "Literal::NonFinite",
        ),
        (
            s(&["subdivide", "zeros(2, 1500)"]),
            "CONTROL",
            "Library::TooLarge",
        ),
        (
            s(&["insert-knot", "[0 1 2 3]", "--degree", "2", "--insert", "2"]),
            "--insert",
            "Library::ParameterOutOfRange",
        ),
        (
            s(&[
                "insert-knot",
                "[0 1 2 3]",
                "--degree",
                "2",
                "--insert",
                "[0.5 0.5 0.5 0.5]",
            ]),
            "--insert",
            "Library::InvalidArgument",
        ),
        (
            s(&[
                "insert-knot",
                "[0 1 2 3]",
                "--degree",
                "2",
                "--insert",
                "NaN",
            ]),
            "--insert",
            "Literal::NonFinite",
        ),
        (
            s(&["insert-knot", "[0 1]", "--degree", "3", "--insert", "0.5"]),
            "CONTROL",
            "Library::TooFewControlPoints",
        ),
        (
            s(&[
                "insert-knot",
                "[0 1 2 3]",
                "--insert",
                "0.01:0.01:0.99",
                "--max-work",
                "100",
            ]),
            "--insert",
            "Library::TooLarge",
        ),
        (
            s(&["bspline-basis", "--knots", "[0 1 0.5]", "--degree", "0"]),
            "--knots",
            "Library::DecreasingKnots",
        ),
        (
            s(&["bspline-basis", "--knots", "[0 1]", "--degree", "3"]),
            "--knots",
            "Shape",
        ),
        (
            s(&[
                "bspline-basis",
                "--knots",
                "[0 0 0 1 1 1]",
                "--degree",
                "2",
                "--t",
                "2",
            ]),
            "--t",
            "Library::ParameterOutOfRange",
        ),
        (
            s(&["bspline-basis", "--knots", "[0 NaN 1]"]),
            "--knots",
            "Literal::NonFinite",
        ),
        (
            s(&[
                "bspline-basis",
                "--knots",
                "0:1",
                "--degree",
                "0",
                "--order",
                "1",
            ]),
            "--order",
            "Usage",
        ),
        (
            s(&[
                "bspline-basis",
                "--knots",
                "0:3000",
                "--degree",
                "2",
                "--n",
                "100000",
            ]),
            "--t",
            "Library::TooLarge",
        ),
        (
            s(&["curvature", "[1 1 1; 2 2 2]", "--t", "0.5"]),
            "--t",
            "Library::InvalidArgument",
        ),
        (
            s(&["curvature", "bspline([0 1; 0 1], [0 1])"]),
            "CURVE",
            "Shape",
        ),
        (
            s(&[
                "curvature",
                "[0 1 2 3; 0 1 0 1; 0 0 1 1; 1 1 1 1]",
                "--t",
                "0.5",
            ]),
            "CURVE",
            "Library::ShapeMismatch",
        ),
        (
            s(&[
                "curvature",
                "nurbs([1 1 0; 0 1 1], [1 -1 2], [0 0 0 1 1 1])",
            ]),
            "CURVE",
            "Library::NonPositiveWeight",
        ),
        (
            s(&["continuity", "[0 1]", "[1 2; 3 4]"]),
            "FIRST/SECOND",
            "Shape",
        ),
        (
            s(&["continuity", "[0 NaN]", "[1 2]"]),
            "FIRST",
            "Literal::NonFinite",
        ),
        (
            s(&["continuity", "[0]", "[0 1]", "--free-point"]),
            "FIRST",
            "Shape",
        ),
        (
            s(&["continuity", "zeros(1, 2000)", "[0 1]"]),
            "FIRST",
            "Library::TooLarge",
        ),
        (
            s(&["continuity", "[0 1]", "[1 2]", "--k", "2"]),
            "--k",
            "Usage",
        ),
        (s(&["integrate"]), "CONTROL", "Usage"),
        (
            s(&["integrate", "--bernstein", "3", "--i", "4"]),
            "--i",
            "Shape",
        ),
        (s(&["integrate", "[0 1]", "--i", "1"]), "--i", "Usage"),
        (
            s(&["integrate", "[0 NaN]"]),
            "CONTROL",
            "Literal::NonFinite",
        ),
        (
            s(&["integrate", "--bernstein", "5000"]),
            "--bernstein",
            "Library::TooLarge",
        ),
        (
            s(&["integrate", "[0 1]", "--degree", "3"]),
            "CONTROL/--degree/--knots",
            "Library::TooFewControlPoints",
        ),
        (
            s(&["ruled", "--first", "[u;0]", "--second", "[u;1;0]"]),
            "--first/--second",
            "Library::ShapeMismatch",
        ),
        (
            s(&["ruled", "--first", "[u;NaN;0]", "--second", "[u;1;0]"]),
            "--first",
            "Literal::NonFinite",
        ),
        (
            s(&["ruled", "--first", "[u;v;0]", "--second", "[u;1;0]"]),
            "--first",
            "Shape",
        ),
        (
            s(&[
                "ruled", "--first", "[u;0;0]", "--second", "[u;1;0]", "--n", "5000",
            ]),
            "--u/--v",
            "Library::TooLarge",
        ),
        (
            s(&[
                "ferguson", "--points", "[0 0 0]'", "--du", "[0 0 0]'", "--dv", "[0 0 0]'",
            ]),
            "--points",
            "Shape",
        ),
        (
            s(&[
                "ferguson",
                "--points",
                "zeros(3,4)",
                "--du",
                "[0 0 0 NaN; 0 0 0 0; 0 0 0 0]",
                "--dv",
                "zeros(3,4)",
            ]),
            "--du",
            "Literal::NonFinite",
        ),
        (
            s(&[
                "ferguson",
                "--points",
                "zeros(3,4)",
                "--du",
                "zeros(3,4)",
                "--dv",
                "zeros(2,4)",
            ]),
            "--dv",
            "Shape",
        ),
        (
            s(&[
                "ferguson",
                "--points",
                "zeros(3,4)",
                "--du",
                "zeros(3,4)",
                "--dv",
                "zeros(3,4)",
                "--n",
                "5000",
            ]),
            "--u/--v",
            "Library::TooLarge",
        ),
        (s(&["bspline-surface", "[1 2]"]), "NET", "Shape"),
        (s(&["bspline-surface"]), "NET", "Usage"),
        (
            s(&["bspline-surface", NET, "--degree", "5"]),
            "NET",
            "Library::TooFewControlPoints",
        ),
        (
            s(&["bspline-surface", NET, "--degree", "2", "--u", "NaN"]),
            "--u",
            "Literal::NonFinite",
        ),
        (
            s(&["bspline-surface", NET, "--degree", "2", "--n", "5000"]),
            "--u/--v",
            "Library::TooLarge",
        ),
        (
            s(&["bspline-surface", NET, "--degree", "2", "--u", "2"]),
            "--u",
            "Library::ParameterOutOfRange",
        ),
        (
            s(&["bspline-surface", NET, "--degree", "x"]),
            "--degree",
            "Literal::UnknownVariable",
        ),
        (
            s(&["nurbs-surface", NET, "--degree", "2"]),
            "--weights",
            "Usage",
        ),
        (
            s(&[
                "nurbs-surface",
                NET,
                "--degree",
                "2",
                "--weights",
                "[1 1 1; 1 0 1; 1 1 1]",
            ]),
            "--weights",
            "Library::NonPositiveWeight",
        ),
        (
            s(&[
                "nurbs-surface",
                NET,
                "--degree",
                "2",
                "--weights",
                "[1 1; 1 1]",
            ]),
            "--weights",
            "Library::ShapeMismatch",
        ),
        (s(&["nurbs-surface", &nrb_bad]), "NET", "Data"),
        (
            s(&["circle", "--radius", "-1"]),
            "--radius/--center",
            "Library::InvalidArgument",
        ),
        (
            s(&["circle", "--radius", "NaN"]),
            "--radius",
            "Literal::NonFinite",
        ),
        (
            s(&["circle", "--center", "[0 0 0 0]"]),
            "--radius/--center",
            "Library::InvalidArgument",
        ),
        (s(&["circle", "--n", "2000000"]), "--n", "Library::TooLarge"),
        (
            s(&["arc", "--start", "0", "--end", "10"]),
            "--start/--end",
            "Library::InvalidArgument",
        ),
        (
            s(&["arc", "--start", "0", "--end", "[1 2]"]),
            "--end",
            "Shape",
        ),
        (
            s(&["course", "--out", "/proc/cagd-cannot-be-here"]),
            "--out /proc/cagd-cannot-be-here",
            "Io::NotFound",
        ),
        // the extensions of existing subcommands
        (
            s(&["bezier-patch", NET, "--du", "3"]),
            "--du/--dv",
            "Library::DerivativeOrder",
        ),
        (
            s(&["bezier-patch", "--x", "[0 1; 2 3]", "--y", "[0 1 2]"]),
            "--y",
            "Shape",
        ),
        (s(&["bezier-patch"]), "NET", "Usage"),
        (
            with(&COONS, &["--blend", "1-t^2/2"]),
            "--blend",
            "Library::BlendingCondition",
        ),
        (with(&COONS, &["--blend", "[t; t; t]"]), "--blend", "Shape"),
        (
            with(&COONS, &["--blend", "sin(t)", "--exact"]),
            "--blend",
            "Literal::NotRational",
        ),
        (with(&COONS, &["--samples"]), "--samples", "Usage"),
        (
            s(&["decasteljau", CUBIC, "--interval", "2,1"]),
            "--interval",
            "Shape",
        ),
        (
            s(&["decasteljau", CUBIC, "--interval", "[0 NaN]"]),
            "--interval",
            "Literal::NonFinite",
        ),
        (
            s(&[
                "spline",
                "[0 0; 1 1; 2 0]'",
                "--end",
                "natural",
                "--start-tangent",
                "[1;1]",
            ]),
            "--start-tangent",
            "Usage",
        ),
        (
            s(&["spline", "[0 0; 1 1; 2 0]'", "--params", "[0 1]"]),
            "--params",
            "Shape",
        ),
        (
            s(&["spline", "[0 0; 1 1; 2 0]'", "--params", "[0 2 1]"]),
            "--params",
            "Library::InvalidArgument",
        ),
        (
            s(&["spline", "[0 0; 0 0; 2 0]'", "--params", "chord"]),
            "POINTS",
            "Library::InvalidArgument",
        ),
        (
            s(&["bspline", "[0 0; 1 2]'", "--order", "0"]),
            "--order",
            "Shape",
        ),
        (
            s(&["bspline", "[0 0; 1 2]'", "--order", "2", "--degree", "1"]),
            "--order",
            "Usage",
        ),
        (
            s(&["discrete-coons", NET, "--mask=0,0.25", "--steps"]),
            "--steps",
            "Usage",
        ),
        (
            s(&["gordon", "--script", &odd, "--u-nodes", "[0 0.5 1]"]),
            "--u-nodes",
            "Usage",
        ),
        (
            s(&["bernstein", "--degree", "3", "--plot", "b.bmp"]),
            "--plot b.bmp",
            "Usage",
        ),
        // outputs
        (
            s(&["curve", "[u;u]", "--plot", "picture.bmp"]),
            "--plot picture.bmp",
            "Usage",
        ),
        (
            s(&["curve", "[u;u;u;u]", "--plot", "four.svg"]),
            "--plot four.svg",
            "Plot",
        ),
        (
            s(&["surface", "[u;v;u]", "--mesh", "mesh.3ds"]),
            "--mesh mesh.3ds",
            "Usage",
        ),
        (
            s(&["curve", "[u;u]", "--plot", &no_dir]),
            "--plot",
            "Io::NotFound",
        ),
        (
            s(&["thesis", "--out", "/proc/cagd-cannot-be-here"]),
            "--out /proc/cagd-cannot-be-here",
            "Io::NotFound",
        ),
        // Outputs that are not regular files, or two outputs on one path: before any work.
        (
            s(&["curve", "[u;u]", "-o", "/dev/null"]),
            "-o /dev/null",
            "Io::AlreadyExists",
        ),
        (
            s(&["curve", "[u;u]", "--plot", &folder]),
            "--plot",
            "Io::AlreadyExists",
        ),
        (
            s(&["curve", "[u;u]", "--plot", "x.svg", "-o", "./x.svg"]),
            "--plot x.svg",
            "Usage",
        ),
        (
            s(&["curve", "[u;u]", "-o", "-", "--plot", "-"]),
            "--plot -",
            "Usage",
        ),
        // A depth beyond what the command thread's stack holds.
        (
            s(&["--max-depth", "100000000", "curve", "[u;u]"]),
            "--max-depth",
            "Usage",
        ),
        // What Octave refuses, an argument may not rely on a lenient reading of.
        (
            s(&["decasteljau", "[1 2]*[3 4]"]),
            "CONTROL",
            "Literal::Unsupported",
        ),
        (
            s(&["decasteljau", CUBIC, "--t", "[0.5 1]*[1 1]"]),
            "--t",
            "Literal::Unsupported",
        ),
        // Results that overflow the range of doubles.
        (
            s(&["derivative", "[zeros(1,171) 1]", "-r", "171"]),
            "-r",
            "Library::Overflow",
        ),
        (
            s(&["spline", "[1.7e308 -1.7e308 1.7e308]"]),
            "POINTS",
            "Library::Overflow",
        ),
        (
            s(&["lagrange", "--nodes", "[0 1e-310 1]", "--t", "0.5"]),
            "--nodes",
            "Library::Overflow",
        ),
        (
            s(&[
                "hermite",
                "--p0",
                "[1.5e308;0]",
                "--p1",
                "[0;0]",
                "--t0",
                "[1.5e308;0]",
                "--t1",
                "[0;0]",
                "--t",
                "0.5",
            ]),
            "--p0/--p1/--t0/--t1",
            "Library::Overflow",
        ),
        // Finite input whose results leave the range of doubles, caught where they first
        // appear (the library's Error::Overflow), and work refused before it starts.
        (
            s(&[
                "integrate",
                "[0 0; 1 2; 2 0]",
                "--rows",
                "--interval=-1e308,1e308",
            ]),
            "--interval",
            "Library::Overflow",
        ),
        (
            s(&["derivative", "[1.7e308 -1.7e308 1.7e308]", "--t", "0.5"]),
            "-r",
            "Library::Overflow",
        ),
        (
            s(&[
                "bspline",
                "[0 1 2 3 4]",
                "--degree",
                "2",
                "--knots",
                "[0 0 0 5e-324 1e-320 1 1 1]",
                "--t",
                "0.5",
            ]),
            "--knots",
            "Library::Overflow",
        ),
        (
            s(&["lagrange", "--nodes", "linspace(0,1,1001)", "--t", "0.5"]),
            "--nodes",
            "Library::Overflow",
        ),
        (
            s(&["discrete-coons", "ones(30,90)", "--mask=0,0.25", "--exact"]),
            "NET",
            "Library::TooLarge",
        ),
        // Output files with the shell's rules, refused before any work.
        (
            s(&["bernstein", "--degree", "1", "-o", ""]),
            "--output",
            "Usage",
        ),
        (
            s(&["decasteljau", &points, "--t", "0.5", "-o", &points]),
            "-o",
            "Usage",
        ),
        (
            s(&["decasteljau", &points, "--t", "0.5", "-o", &read_only]),
            "-o",
            "Io::PermissionDenied",
        ),
        #[cfg(unix)]
        (
            s(&["decasteljau", &points, "--t", "0.5", "--plot", &looping]),
            "--plot",
            "Io::Other",
        ),
        // A folder given as an input file.
        (s(&["decasteljau", &folder]), "CONTROL", "Io::IsADirectory"),
        // An exact value whose double overflows, in Octave's format of doubles.
        (
            s(&[
                "decasteljau",
                "[1e308 -1e308; 0 1]",
                "--t",
                "5",
                "--exact",
                "--format",
                "octave",
            ]),
            "--format",
            "Library::NonFinite",
        ),
        // Pictures and meshes of values too large to draw or to store.
        (
            s(&[
                "decasteljau",
                "[-1e308 1e308; 0 1]",
                "--n",
                "3",
                "--plot",
                "p.svg",
            ]),
            "--plot p.svg",
            "Plot",
        ),
        (
            s(&["surface", "[1e39*u; v; u]", "--n", "3", "--mesh", "m.stl"]),
            "--mesh m.stl",
            "Shape",
        ),
    ]
}

#[test]
fn every_bad_input_names_its_argument_and_kind_exits_2_and_writes_nothing() {
    let inputs = tempfile::tempdir().unwrap();
    let table = cases(inputs.path());
    assert!(table.len() >= 89, "{} cases", table.len());
    let subcommands: std::collections::BTreeSet<&str> = table
        .iter()
        .filter_map(|(a, _, _)| a.first().map(String::as_str))
        .collect();
    // Every subcommand but `serve` (which only serves the page).
    let all = cagd_cli::subcommands();
    assert!(all.len() >= 31, "{all:?}");
    for sub in all.iter().filter(|s| *s != "serve") {
        assert!(subcommands.contains(sub.as_str()), "no bad input for {sub}");
    }
    check_all(&table, |(args, argument, kind)| {
        // In-process: the exact argument and kind.
        let mut full = vec!["cagd".to_string()];
        full.extend(args.iter().cloned());
        // Output errors surface when the staged files are committed.
        match run(&full).and_then(|out| out.files.commit()) {
            Ok(()) => return Err("succeeded".into()),
            Err(e) => {
                let got = label(&e.kind);
                // A file argument is named with its path: `CONTROL data.txt`.
                let named =
                    e.argument == *argument || e.argument.starts_with(&format!("{argument} "));
                if got != *kind || !named || e.exit_code() != 2 {
                    return Err(format!(
                        "got ({}, {got}, exit {}), expected ({argument}, {kind}): {e}",
                        e.argument,
                        e.exit_code()
                    ));
                }
            }
        }
        // The binary, in an empty folder, asked to write its result to a file.
        let work = tempfile::tempdir().unwrap();
        let mut cmd = Command::cargo_bin("cagd").unwrap();
        cmd.current_dir(work.path()).args(args);
        if args.first().is_some_and(|a| a != "thesis" && a != "course")
            && !args.iter().any(|a| a == "-o")
        {
            cmd.args(["-o", "result.txt"]);
        }
        refused(&mut cmd, Some(work.path()))
            .map(drop)
            .map_err(|e| format!("binary: {e}"))
    });
}

//! Octave's text format through live GNU Octave:
//! Octave saves → we read → we write → Octave loads and compares (`isequal`, `isequaln` for
//! NaN, and a strict check of class, size, field order, sign of zero and `NA`), and values made
//! in Rust → we write → Octave loads and compares with the same values made in Octave.
//!
//! Each test runs Octave in one batch (one process per direction). Without Octave the tests
//! print `skipped: octave not found` and pass, unless the environment variable `CI` is set.

use cagd_test_support as common;

use cagd_octave::text_format::{
    is_na, na, read_numeric_file, read_text_file, write_text_file, CharMatrix, Quote, Value,
    Workspace,
};
use common::{octave_available, run_octave, TempDir};
use ndarray::{array, ArrayD, IxDyn, ShapeBuilder};

/// Octave function `same(a, b)`: identical class, size, values (NaN = NaN), sign of zero, NA,
/// string quoting, struct field order; recursive through structs and cells. Also prints, for
/// each variable, `isequal` and `isequaln`.
const OCTAVE_SAME: &str = r#"1;
function r = same(a, b)
  r = strcmp(class(a), class(b)) && isequal(size(a), size(b));
  if !r
    return;
  end
  if isstruct(a)
    r = isequal(fieldnames(a), fieldnames(b));
    f = fieldnames(a);
    for k = 1:numel(f)
      r = r && same(a.(f{k}), b.(f{k}));
    end
  elseif iscell(a)
    for k = 1:numel(a)
      r = r && same(a{k}, b{k});
    end
  elseif isnumeric(a)
    r = isequaln(a, b) && isequal(signbit(a), signbit(b)) && isequal(isna(a), isna(b));
  elseif ischar(a)
    r = isequal(a, b) && is_dq_string(a) == is_dq_string(b);
  else
    r = isequal(a, b);
  end
end
function compare_all(A, B)
  na = fieldnames(A);
  nb = fieldnames(B);
  printf('NAMES %d\n', isequal(na, nb));
  for k = 1:numel(na)
    n = na{k};
    if !isfield(B, n)
      printf('VAR %s missing\n', n);
      continue;
    end
    printf('VAR %s isequal=%d isequaln=%d same=%d\n', n, isequal(A.(n), B.(n)), ...
           isequaln(A.(n), B.(n)), same(A.(n), B.(n)));
  end
end
"#;

/// One `VAR` line of `compare_all`.
struct VarResult {
    name: String,
    isequal: bool,
    isequaln: bool,
    same: bool,
}

fn parse_results(stdout: &str) -> Vec<VarResult> {
    assert!(
        stdout.lines().any(|l| l.trim() == "NAMES 1"),
        "variable names or their order differ:\n{stdout}"
    );
    stdout
        .lines()
        .filter_map(|l| l.strip_prefix("VAR "))
        .map(|l| {
            let parts: Vec<&str> = l.split_whitespace().collect();
            assert_eq!(parts.len(), 4, "Octave: {l}");
            let flag = |p: &str, key: &str| p == format!("{key}=1");
            VarResult {
                name: parts[0].to_string(),
                isequal: flag(parts[1], "isequal"),
                isequaln: flag(parts[2], "isequaln"),
                same: flag(parts[3], "same"),
            }
        })
        .collect()
}

/// Asserts every variable compared equal; `with_nan` lists those holding NaN (compared with
/// `isequaln`, since `isequal(NaN, NaN)` is false).
fn assert_all_equal(results: &[VarResult], with_nan: &[&str], expected_count: usize) {
    assert_eq!(
        results.len(),
        expected_count,
        "number of variables compared"
    );
    for r in results {
        if with_nan.contains(&r.name.as_str()) {
            assert!(r.isequaln, "{}: isequaln is false", r.name);
        } else {
            assert!(r.isequal, "{}: isequal is false", r.name);
        }
        assert!(
            r.same,
            "{}: class, size, sign of zero, NA or field order differ",
            r.name
        );
    }
}

/// Octave code defining the test values, shared by both directions.
const OCTAVE_VALUES: &str = r#"
pkg load nurbs
rand('state', 7);
s = 3.5;
neg0 = -0;
tiny = 1e-300;
denorm = [realmin/4, 5e-324, -5e-324, realmin];
special = [Inf, -Inf, NaN, NA, 0.1, -0];
big = [1e308, realmax, -realmax, 1e20, 123456789012345678];
M = magic(4)/7;
E = zeros(0,3);
E2 = zeros(3,0);
nd3 = rand(2,3,4);
nd4 = reshape(1:24, 2, 3, 2, 2)/3;
ndz = zeros(2,0,3);
r = 1:5;
rr = 0:0.1:1;
sq = 'hello';
dq = "tab\there";
multi = ['abc'; 'def'];
emptystr = '';
utf = 'čšž';
nl = "a\nb";
t = true;
f = false;
bm = [true false; false true];
bnd = logical(cat(3, [1 0; 0 1], [0 0; 1 1]));
st.x = 1;
st.name = 'n';
st.inner.v = [1 2 3];
st.inner.c = {1, 'two'};
ce = {1, 'a'; [1 2 3], {2, "x"}};
ce0 = {};
cnd = cell(1,2,2); cnd{1,1,1} = 1; cnd{1,2,2} = 'x';
crv = nrbmak([0 1 2; 0 1 0], [0 0 0 1 1 1]);
srf = nrbmak(rand(3,3,3), {[0 0 0 1 1 1], [0 0 0 1 1 1]});
wcrv = nrbmak([0 0.5 1; 0 0.5 0; 0 0 0; 1 0.5 1], [0 0 0 1 1 1]);
"#;

const NAN_VARS: &[&str] = &["special"];
const VALUE_COUNT: usize = 31;

#[test]
fn octave_saved_values_read_write_and_load_back_identically() {
    if !octave_available("octave_saved_values_read_write_and_load_back_identically") {
        return;
    }
    let dir = TempDir::new("fmt-octave-first");
    // 1. Octave saves.
    run_octave(
        dir.path(),
        "save_values",
        &format!("save_precision(17);\n{OCTAVE_VALUES}\nsave('-text', 'from_octave.txt');\ndisp('DONE');\n"),
    );
    // 2. We read, and check the delicate values ourselves.
    let ws = read_text_file(dir.path().join("from_octave.txt")).expect("read Octave's file");
    assert_eq!(ws.len(), VALUE_COUNT);
    assert_eq!(ws.scalar("tiny").unwrap(), 1e-300);
    let neg0 = ws.scalar("neg0").unwrap();
    assert!(neg0 == 0.0 && neg0.is_sign_negative());
    let denorm = ws.matrix("denorm").unwrap();
    assert_eq!(
        denorm[[0, 0]].to_bits(),
        (f64::MIN_POSITIVE / 4.0).to_bits()
    );
    assert_eq!(denorm[[0, 1]].to_bits(), 1);
    assert_eq!(denorm[[0, 2]].to_bits(), 1 | (1 << 63));
    let special = ws.matrix("special").unwrap();
    assert_eq!(special[[0, 0]], f64::INFINITY);
    assert_eq!(special[[0, 1]], f64::NEG_INFINITY);
    assert!(special[[0, 2]].is_nan() && !is_na(special[[0, 2]]));
    assert!(is_na(special[[0, 3]]));
    assert_eq!(special[[0, 4]], 0.1);
    assert!(special[[0, 5]].is_sign_negative());
    assert_eq!(ws.array("nd4").unwrap()[[1, 2, 1, 1]], 24.0 / 3.0);
    assert_eq!(ws.array("nd4").unwrap()[[1, 0, 0, 1]], 14.0 / 3.0);
    assert_eq!(ws.array("ndz").unwrap().shape(), &[2, 0, 3]);
    assert_eq!(ws.string("nl").unwrap(), "a\nb");
    assert_eq!(ws.string("utf").unwrap(), "čšž");
    assert!(matches!(ws.get("r"), Some(Value::Range { .. })));
    assert_eq!(ws.matrix("r").unwrap(), array![[1.0, 2.0, 3.0, 4.0, 5.0]]);
    // octave-nurbs: a curve has a knot vector, a surface a cell of two.
    let crv = ws.get("crv").unwrap();
    let fields: Vec<&str> = match crv {
        Value::Struct(f) => f.iter().map(|(n, _)| n.as_str()).collect(),
        other => panic!("crv is {}", other.describe()),
    };
    assert_eq!(fields, ["form", "dim", "number", "coefs", "knots", "order"]);
    assert_eq!(crv.field("form").and_then(Value::as_str), Some("B-NURBS"));
    assert_eq!(
        crv.field("coefs").and_then(Value::to_matrix),
        Some(array![
            [0.0, 1.0, 2.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 1.0]
        ])
    );
    assert_eq!(crv.field("order").and_then(Value::to_scalar), Some(3.0));
    let srf = ws.get("srf").unwrap();
    match srf.field("knots") {
        Some(Value::Cell(k)) => assert_eq!(k.shape(), &[1, 2]),
        other => panic!("srf.knots: {other:?}"),
    }
    assert_eq!(
        srf.field("coefs")
            .and_then(Value::to_array)
            .map(|a| a.shape().to_vec()),
        Some(vec![4, 3, 3])
    );
    // 3. We write.
    write_text_file(dir.path().join("ours.txt"), &ws).expect("write");
    // 4. Octave loads both and compares.
    let out = run_octave(
        dir.path(),
        "compare_values",
        &format!(
            "{OCTAVE_SAME}\nA = load('from_octave.txt');\nB = load('ours.txt');\ncompare_all(A, B);\ndisp('DONE');\n"
        ),
    );
    let results = parse_results(&out);
    assert_all_equal(&results, NAN_VARS, VALUE_COUNT);
    eprintln!(
        "[octave_format] {} variables saved by Octave, read, rewritten and loaded back identically",
        results.len()
    );
}

/// The same values built in Rust: written by us, loaded by Octave, compared with the values
/// Octave makes itself; then saved by Octave and read back by us, bit for bit.
#[test]
fn values_written_by_us_load_in_octave_identically() {
    if !octave_available("values_written_by_us_load_in_octave_identically") {
        return;
    }
    let dir = TempDir::new("fmt-rust-first");
    let mut ws = Workspace::new();
    ws.insert("s", 3.5);
    ws.insert("neg0", -0.0);
    ws.insert("tiny", 1e-300);
    ws.insert(
        "denorm",
        array![[f64::MIN_POSITIVE / 4.0, 5e-324, -5e-324, f64::MIN_POSITIVE]],
    );
    ws.insert(
        "special",
        array![[f64::INFINITY, f64::NEG_INFINITY, f64::NAN, na(), 0.1, -0.0]],
    );
    ws.insert(
        "big",
        array![[1e308, f64::MAX, -f64::MAX, 1e20, 123456789012345678.0]],
    );
    ws.insert("third", 1.0 / 3.0);
    ws.insert("pi_", std::f64::consts::PI);
    ws.insert(
        "M",
        ArrayD::from_shape_fn(IxDyn(&[3, 4]), |i| (i[0] * 4 + i[1]) as f64 / 7.0),
    );
    ws.insert("E", ArrayD::<f64>::zeros(IxDyn(&[0, 3])));
    // nd4 = reshape(1:24, 2, 3, 2, 2)/3, built column-major like Octave's reshape.
    let nd4 = ArrayD::from_shape_vec(
        IxDyn(&[2, 3, 2, 2]).f(),
        (1..=24).map(|k| k as f64 / 3.0).collect(),
    )
    .unwrap();
    ws.insert("nd4", nd4);
    ws.insert(
        "r",
        Value::Range {
            base: 1.0,
            limit: 5.0,
            increment: 1.0,
        },
    );
    ws.insert("sq", "hello");
    ws.insert(
        "dq",
        Value::Str(CharMatrix {
            rows: vec!["tab\there".into()],
            quote: Quote::Double,
        }),
    );
    ws.insert(
        "multi",
        Value::Str(CharMatrix {
            rows: vec!["abc".into(), "def".into()],
            quote: Quote::Single,
        }),
    );
    ws.insert("emptystr", Value::Str(CharMatrix::default()));
    ws.insert("utf", "čšž");
    ws.insert(
        "nl",
        Value::Str(CharMatrix {
            rows: vec!["a\nb".into()],
            quote: Quote::Double,
        }),
    );
    ws.insert("t", true);
    ws.insert(
        "bm",
        Value::BoolMatrix(array![[true, false], [false, true]].into_dyn()),
    );
    ws.insert(
        "st",
        Value::Struct(vec![
            ("x".into(), Value::Scalar(1.0)),
            ("name".into(), Value::from("n")),
            (
                "inner".into(),
                Value::Struct(vec![("v".into(), Value::from(array![[1.0, 2.0, 3.0]]))]),
            ),
        ]),
    );
    ws.insert(
        "ce",
        Value::Cell(
            array![
                [Value::Scalar(1.0), Value::from("a")],
                [
                    Value::from(array![[1.0, 2.0, 3.0]]),
                    Value::Cell(array![[Value::Scalar(2.0), Value::from("x")]].into_dyn())
                ]
            ]
            .into_dyn(),
        ),
    );
    ws.insert(
        "crv",
        Value::Struct(vec![
            ("form".into(), Value::from("B-NURBS")),
            ("dim".into(), Value::Scalar(4.0)),
            ("number".into(), Value::Scalar(3.0)),
            (
                "coefs".into(),
                Value::from(array![
                    [0.0, 1.0, 2.0],
                    [0.0, 1.0, 0.0],
                    [0.0, 0.0, 0.0],
                    [1.0, 1.0, 1.0]
                ]),
            ),
            (
                "knots".into(),
                Value::from(array![[0.0, 0.0, 0.0, 1.0, 1.0, 1.0]]),
            ),
            ("order".into(), Value::Scalar(3.0)),
        ]),
    );
    let knots = Value::from(array![[0.0, 0.0, 1.0, 1.0]]);
    ws.insert(
        "srf",
        Value::Struct(vec![
            ("form".into(), Value::from("B-NURBS")),
            ("dim".into(), Value::Scalar(4.0)),
            ("number".into(), Value::from(array![[2.0, 2.0]])),
            (
                "coefs".into(),
                Value::from(ArrayD::from_shape_fn(IxDyn(&[4, 2, 2]), |i| {
                    if i[0] == 3 {
                        1.0
                    } else {
                        (i[0] + i[1] + 2 * i[2]) as f64 * 0.25
                    }
                })),
            ),
            (
                "knots".into(),
                Value::Cell(ndarray::arr2(&[[knots.clone(), knots]]).into_dyn()),
            ),
            ("order".into(), Value::from(array![[2.0, 2.0]])),
        ]),
    );
    let count = ws.len();
    write_text_file(dir.path().join("ours.txt"), &ws).expect("write");

    let expected_in_octave = r#"
E.s = 3.5;
E.neg0 = -0;
E.tiny = 1e-300;
E.denorm = [realmin/4, 5e-324, -5e-324, realmin];
E.special = [Inf, -Inf, NaN, NA, 0.1, -0];
E.big = [1e308, realmax, -realmax, 1e20, 123456789012345678];
E.third = 1/3;
E.pi_ = pi;
E.M = reshape(0:11, 4, 3)'/7;
E.E = zeros(0,3);
E.nd4 = reshape(1:24, 2, 3, 2, 2)/3;
E.r = 1:5;
E.sq = 'hello';
E.dq = "tab\there";
E.multi = ['abc'; 'def'];
E.emptystr = '';
E.utf = 'čšž';
E.nl = "a\nb";
E.t = true;
E.bm = [true false; false true];
E.st = struct('x', 1, 'name', 'n', 'inner', struct('v', [1 2 3]));
E.ce = {1, 'a'; [1 2 3], {2, 'x'}};
E.crv = nrbmak([0 1 2; 0 1 0], [0 0 0 1 1 1]);
c = zeros(4,2,2); c(4,:,:) = 1;
for i = 0:2, for j = 0:1, for k = 0:1, c(i+1,j+1,k+1) = (i+j+2*k)*0.25; end; end; end;
E.srf = nrbmak(c, {[0 0 1 1], [0 0 1 1]});
"#;
    let out = run_octave(
        dir.path(),
        "load_ours",
        &format!(
            "{OCTAVE_SAME}\npkg load nurbs\nsave_precision(17);\n{expected_in_octave}\n\
             L = load('ours.txt');\ncompare_all(E, L);\n\
             save('-text', 'resaved.txt', '-struct', 'L');\ndisp('DONE');\n"
        ),
    );
    let results = parse_results(&out);
    assert_all_equal(&results, NAN_VARS, count);

    // Octave saved what it loaded from us; reading that gives our values back, bit for bit.
    let back = read_text_file(dir.path().join("resaved.txt")).expect("read Octave's resave");
    // (`save -struct` writes the fields in alphabetical order)
    let mut names_back: Vec<&str> = back.names().collect();
    let mut names_ours: Vec<&str> = ws.names().collect();
    names_back.sort_unstable();
    names_ours.sort_unstable();
    assert_eq!(names_back, names_ours);
    for (name, ours) in ws.iter() {
        let theirs = back.get(name).unwrap();
        assert!(
            bitwise_equal(ours, theirs),
            "{name}: ours {ours:?}, after Octave {theirs:?}"
        );
    }
    eprintln!("[octave_format] {count} variables written by us loaded by Octave identically");
}

/// Equality that also tells NaN payloads (NA) and the sign of zero apart.
fn bitwise_equal(a: &Value, b: &Value) -> bool {
    let bits = |x: &ArrayD<f64>| {
        (
            x.shape().to_vec(),
            x.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        )
    };
    match (a, b) {
        (Value::Scalar(x), Value::Scalar(y)) => x.to_bits() == y.to_bits(),
        (Value::Matrix(x), Value::Matrix(y)) => bits(x) == bits(y),
        (Value::Struct(x), Value::Struct(y)) => {
            x.len() == y.len()
                && x.iter()
                    .zip(y)
                    .all(|((n, u), (m, v))| n == m && bitwise_equal(u, v))
        }
        (Value::Cell(x), Value::Cell(y)) => {
            x.shape() == y.shape() && x.iter().zip(y.iter()).all(|(u, v)| bitwise_equal(u, v))
        }
        _ => a == b,
    }
}

/// `save -ascii` (with and without `-double`) and `dlmwrite` write plain numbers we can read.
#[test]
fn save_ascii_and_dlmwrite_are_read() {
    if !octave_available("save_ascii_and_dlmwrite_are_read") {
        return;
    }
    let dir = TempDir::new("fmt-ascii");
    run_octave(
        dir.path(),
        "ascii",
        r#"
A = [1 -2.5 3; 4 0.125 -6e3];
B = [pi, -1/3; 1e-300, Inf];
save('-ascii', 'a.txt', 'A');
save('-ascii', '-double', 'b.txt', 'B');
save('-ascii', '-double', '-tabs', 'bt.txt', 'B');
dlmwrite('a.csv', A);
dlmwrite('b.csv', B, 'precision', '%.17g');
dlmwrite('b_semi.txt', B, 'delimiter', ';', 'precision', '%.17g');
disp('DONE');
"#,
    );
    let a = array![[1.0, -2.5, 3.0], [4.0, 0.125, -6e3]];
    let b = array![[std::f64::consts::PI, -1.0 / 3.0], [1e-300, f64::INFINITY]];
    assert_eq!(read_numeric_file(dir.path().join("a.txt")).unwrap(), a);
    assert_eq!(read_numeric_file(dir.path().join("a.csv")).unwrap(), a);
    assert_eq!(read_numeric_file(dir.path().join("b.csv")).unwrap(), b);
    assert_eq!(read_numeric_file(dir.path().join("b_semi.txt")).unwrap(), b);
    // `save -ascii -double` writes 16 significant digits: close, not exact.
    for f in ["b.txt", "bt.txt"] {
        let got = read_numeric_file(dir.path().join(f)).unwrap();
        assert_eq!(got.dim(), (2, 2), "{f}");
        for (x, y) in got.iter().zip(b.iter()) {
            assert!(x == y || ((x - y) / y).abs() < 1e-15, "{f}: {x:e} vs {y:e}");
        }
    }
}

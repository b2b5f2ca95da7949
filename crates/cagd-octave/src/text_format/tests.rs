//! The reader and writer against what Octave writes.

use super::reader::parse_number;
use super::*;
use ndarray::{array, Array3};

/// Exactly what Octave 7.3 wrote for these values (`save_precision(17)`).
const OCTAVE_SAMPLE: &str = "# Created by Octave 7.3.0, Sat Nov 21 05:32:43 2026 UTC <root@vm>
# name: a
# type: scalar
3.5


# name: b
# type: matrix
# rows: 2
# columns: 2
 1 2
 3 4


# name: bm
# type: bool matrix
# rows: 2
# columns: 2
 1 0
 0 1


# name: bt
# type: bool
1


# name: c
# type: matrix
# ndims: 3
 2 3 2
 1
 2
 3
 4
 5
 6
 7
 8
 9
 10
 11
 12


# name: s2
# type: sq_string
# elements: 2
# length: 2
ab
# length: 2
cd


# name: ds
# type: string
# elements: 1
# length: 3
a
b


# name: em
# type: sq_string
# elements: 0


# name: r
# type: double_range
# base, limit, increment
1 3 1


# name: sp
# type: matrix
# rows: 1
# columns: 8
 Inf -Inf NaN NA 1e-300 5.5626846462680035e-309 -0 0.10000000000000001


# name: e
# type: matrix
# rows: 0
# columns: 3


";

#[test]
fn reads_what_octave_writes() {
    let ws = read_text(OCTAVE_SAMPLE).unwrap();
    assert_eq!(
        ws.names().collect::<Vec<_>>(),
        ["a", "b", "bm", "bt", "c", "s2", "ds", "em", "r", "sp", "e"]
    );
    assert_eq!(ws.scalar("a").unwrap(), 3.5);
    assert_eq!(ws.matrix("b").unwrap(), array![[1.0, 2.0], [3.0, 4.0]]);
    assert_eq!(
        ws.get("bm"),
        Some(&Value::BoolMatrix(
            array![[true, false], [false, true]].into_dyn()
        ))
    );
    assert_eq!(ws.get("bt"), Some(&Value::Bool(true)));
    let s2 = ws.get("s2").unwrap();
    assert_eq!(
        s2,
        &Value::Str(CharMatrix {
            rows: vec!["ab".into(), "cd".into()],
            quote: Quote::Single
        })
    );
    assert_eq!(ws.string("ds").unwrap(), "a\nb");
    assert_eq!(ws.string("em").unwrap(), "");
    assert_eq!(ws.matrix("r").unwrap(), array![[1.0, 2.0, 3.0]]);
    let sp = ws.matrix("sp").unwrap();
    assert_eq!(sp[[0, 0]], f64::INFINITY);
    assert_eq!(sp[[0, 1]], f64::NEG_INFINITY);
    assert!(sp[[0, 2]].is_nan() && !is_na(sp[[0, 2]]));
    assert!(is_na(sp[[0, 3]]));
    assert_eq!(sp[[0, 4]], 1e-300);
    assert_eq!(sp[[0, 5]], f64::MIN_POSITIVE / 4.0);
    assert!(sp[[0, 6]] == 0.0 && sp[[0, 6]].is_sign_negative());
    assert_eq!(sp[[0, 7]], 0.1);
    assert_eq!(ws.matrix("e").unwrap().dim(), (0, 3));
}

#[test]
fn nd_arrays_are_column_major() {
    let ws = read_text(OCTAVE_SAMPLE).unwrap();
    let c = ws.array("c").unwrap();
    assert_eq!(c.shape(), &[2, 3, 2]);
    // Octave: c(i,j,k) = i + 2(j-1) + 6(k-1) for the data 1..12.
    for i in 0..2 {
        for j in 0..3 {
            for k in 0..2 {
                assert_eq!(c[[i, j, k]], (1 + i + 2 * j + 6 * k) as f64);
            }
        }
    }
    let text = write_text(&ws).unwrap();
    assert!(text.contains("# ndims: 3\n 2 3 2\n 1\n 2\n 3\n 4\n"));
}

#[test]
fn round_trip_through_our_writer() {
    let ws = read_text(OCTAVE_SAMPLE).unwrap();
    let back = read_text(&write_text(&ws).unwrap()).unwrap();
    // NaN != NaN, so compare the text of both and the NaN positions separately.
    assert_eq!(write_text(&back).unwrap(), write_text(&ws).unwrap());
    let sp = back.matrix("sp").unwrap();
    assert!(is_na(sp[[0, 3]]) && sp[[0, 2]].is_nan() && !is_na(sp[[0, 2]]));
    assert!(sp[[0, 6]].is_sign_negative());
}

#[test]
fn struct_and_cell_as_octave_nurbs_writes_them() {
    // nrbmak(coefs, {[0 0 1 1], [0 0 1 1]}): knots is a cell for surfaces.
    let text = "# name: srf
# type: scalar struct
# ndims: 2
 1 1
# length: 3
# name: form
# type: sq_string
# elements: 1
# length: 7
B-NURBS


# name: number
# type: matrix
# rows: 1
# columns: 2
 2 2


# name: knots
# type: cell
# rows: 1
# columns: 2
# name: <cell-element>
# type: matrix
# rows: 1
# columns: 4
 0 0 1 1



# name: <cell-element>
# type: matrix
# rows: 1
# columns: 4
 0 0 1 1





";
    let ws = read_text(text).unwrap();
    let srf = ws.get("srf").unwrap();
    assert_eq!(srf.field("form").and_then(Value::as_str), Some("B-NURBS"));
    assert_eq!(
        srf.field("number").and_then(Value::to_matrix),
        Some(array![[2.0, 2.0]])
    );
    let Some(Value::Cell(knots)) = srf.field("knots") else {
        panic!("knots is not a cell")
    };
    assert_eq!(knots.shape(), &[1, 2]);
    assert_eq!(
        knots[[0, 1]].to_matrix(),
        Some(array![[0.0, 0.0, 1.0, 1.0]])
    );
    assert_eq!(read_text(&write_text(&ws).unwrap()).unwrap(), ws);
}

#[test]
fn cells_are_column_major() {
    let text = "# name: ce\n# type: cell\n# rows: 2\n# columns: 2\n\
            # name: <cell-element>\n# type: scalar\n1\n\n\n\
            # name: <cell-element>\n# type: scalar\n2\n\n\n\n\
            # name: <cell-element>\n# type: scalar\n3\n\n\n\
            # name: <cell-element>\n# type: scalar\n4\n\n\n\n\n";
    let ws = read_text(text).unwrap();
    let Some(Value::Cell(c)) = ws.get("ce") else {
        panic!()
    };
    assert_eq!(c[[1, 0]], Value::Scalar(2.0));
    assert_eq!(c[[0, 1]], Value::Scalar(3.0));
    assert_eq!(read_text(&write_text(&ws).unwrap()).unwrap(), ws);
}

#[test]
fn string_data_is_read_by_length_not_by_line() {
    let text = "# name: s\n# type: string\n# elements: 2\n# length: 3\nx\ny\n# length: 3\néz\n";
    let ws = read_text(text).unwrap();
    let Some(Value::Str(s)) = ws.get("s") else {
        panic!()
    };
    assert_eq!(s.rows, ["x\ny", "éz"]);
    assert_eq!(s.quote, Quote::Double);
    let empty_rows = "# name: e\n# type: sq_string\n# elements: 2\n# length: 0\n\n# length: 0\n\n";
    let ws = read_text(empty_rows).unwrap();
    assert_eq!(
        ws.get("e"),
        Some(&Value::Str(CharMatrix {
            rows: vec![String::new(), String::new()],
            quote: Quote::Single
        }))
    );
}

#[test]
fn number_formatting_round_trips() {
    let samples = [
        0.1,
        1.0 / 3.0,
        -2.5,
        1e-300,
        f64::MIN_POSITIVE,
        f64::MIN_POSITIVE / 4.0,
        5e-324,
        f64::MAX,
        -f64::MAX,
        1e16,
        1e17,
        123456789012345680.0,
        0.00001,
        0.0001234,
        std::f64::consts::PI,
    ];
    for x in samples {
        let s = format_number(x);
        assert_eq!(parse_number(&s, 1).unwrap().to_bits(), x.to_bits(), "{s}");
    }
    assert_eq!(format_number(1e16), "10000000000000000");
    assert_eq!(format_number(1e17), "1e+17");
    assert_eq!(format_number(0.0001234), "0.0001234");
    assert_eq!(format_number(0.00001), "1e-05");
    assert_eq!(format_number(5e-324), "5e-324");
    assert_eq!(format_number(-2.5), "-2.5");
}

#[test]
fn writer_lays_out_like_octave() {
    let mut ws = Workspace::new();
    ws.insert("x", 3.5);
    ws.insert("flag", true);
    ws.insert("name", "B-NURBS");
    let a = Array3::from_shape_fn((2, 1, 2), |(i, _, k)| (i + 2 * k) as f64);
    ws.insert("A", a.into_dyn());
    let text = write_text(&ws).unwrap();
    assert!(text.contains("# name: x\n# type: scalar\n3.5\n"));
    assert!(text.contains("# name: flag\n# type: bool\n1\n"));
    assert!(text.contains("# name: name\n# type: sq_string\n# elements: 1\n# length: 7\nB-NURBS\n"));
    assert!(text.contains("# name: A\n# type: matrix\n# ndims: 3\n 2 1 2\n 0\n 1\n 2\n 3\n"));
}

#[test]
fn writer_rejects_what_octave_cannot_load() {
    let mut ws = Workspace::new();
    ws.insert("1x", 1.0);
    assert!(matches!(
        write_text(&ws),
        Err(TextFormatError::Unwritable { .. })
    ));
    let mut ws = Workspace::new();
    ws.insert(
        "s",
        Value::Str(CharMatrix {
            rows: vec!["ab".into(), "c".into()],
            quote: Quote::Single,
        }),
    );
    assert!(matches!(
        write_text(&ws),
        Err(TextFormatError::Unwritable { .. })
    ));
    let mut ws = Workspace::new();
    ws.insert(
        "s",
        Value::Struct(vec![("bad name".into(), Value::Scalar(1.0))]),
    );
    assert_eq!(
        write_text(&ws),
        Err(TextFormatError::Unwritable {
            name: "s.bad name".into(),
            message: "not a valid field name".into()
        })
    );
}

#[test]
fn one_and_zero_dimensional_arrays_are_written_as_rows() {
    let mut ws = Workspace::new();
    ws.insert("v", ndarray::arr1(&[1.0, 2.0]).into_dyn());
    ws.insert("z", ndarray::arr0(7.0).into_dyn());
    let back = read_text(&write_text(&ws).unwrap()).unwrap();
    assert_eq!(back.matrix("v").unwrap(), array![[1.0, 2.0]]);
    assert_eq!(back.matrix("z").unwrap(), array![[7.0]]);
}

#[test]
fn ranges_expand() {
    let r = |base, limit, increment| {
        Value::Range {
            base,
            limit,
            increment,
        }
        .to_matrix()
        .unwrap()
    };
    assert_eq!(r(1.0, 3.0, 1.0), array![[1.0, 2.0, 3.0]]);
    assert_eq!(r(5.0, 1.0, -2.0), array![[5.0, 3.0, 1.0]]);
    assert_eq!(r(0.0, 1.0, 0.1).len(), 11);
    assert_eq!(r(1.0, 0.0, 1.0).dim(), (1, 0));
}

#[test]
fn plain_numeric_text() {
    let a = read_numeric_text("% comment\n1\t2 , 3\n\n4;5;6 # trailing\n").unwrap();
    assert_eq!(a, array![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
    assert_eq!(read_numeric_text("").unwrap().dim(), (0, 0));
    let x = read_numeric_text("Inf,-Inf,NaN,NA\n").unwrap();
    assert!(x[[0, 0]].is_infinite() && x[[0, 1]] < 0.0 && is_na(x[[0, 3]]));
    assert_eq!(
        read_numeric_text("1 2\n3\n"),
        Err(TextFormatError::WrongCount {
            line: 2,
            expected: 2,
            found: 1
        })
    );
    assert_eq!(
        read_numeric_text("1 2\n\n3 x\n"),
        Err(TextFormatError::NotANumber {
            line: 3,
            token: "x".into()
        })
    );
}

// ----- malformed input: a typed error with the line number, never a panic -----

fn err(text: &str) -> TextFormatError {
    read_text(text).unwrap_err()
}

#[test]
fn truncated_files() {
    assert_eq!(
        err("# name: x\n"),
        TextFormatError::Truncated {
            line: 2,
            expected: "`# type:`".into()
        }
    );
    assert_eq!(
        err("# name: x\n# type: scalar\n"),
        TextFormatError::MissingData {
            line: 3,
            name: "x".into(),
            declared: 1,
            found: 0
        }
    );
    assert!(matches!(
        err("# name: s\n# type: sq_string\n# elements: 1\n# length: 10\nabc\n"),
        TextFormatError::Truncated { line: 5, .. }
    ));
    assert!(matches!(
            err("# name: c\n# type: cell\n# rows: 1\n# columns: 2\n# name: <cell-element>\n# type: scalar\n1\n"),
            TextFormatError::Truncated { line: 8, .. }
        ));
    assert!(matches!(
        err("# name: c\n# type: matrix\n# ndims: 3\n 1 1 2\n 1\n"),
        TextFormatError::MissingData {
            line: 6,
            declared: 2,
            found: 1,
            ..
        }
    ));
}

#[test]
fn wrong_row_counts() {
    // `# rows:` too large: the next variable's header comes too early.
    let too_few = "# name: A\n# type: matrix\n# rows: 3\n# columns: 2\n 1 2\n 3 4\n\n\n# name: b\n# type: scalar\n1\n";
    assert_eq!(
        err(too_few),
        TextFormatError::MissingData {
            line: 7,
            name: "A".into(),
            declared: 3,
            found: 2
        }
    );
    // `# rows:` too small: a data line where a `# name:` belongs.
    let too_many = "# name: A\n# type: matrix\n# rows: 1\n# columns: 2\n 1 2\n 3 4\n";
    assert_eq!(
        err(too_many),
        TextFormatError::UnexpectedData {
            line: 6,
            found: " 3 4".into()
        }
    );
    // wrong number of columns on a line
    assert_eq!(
        err("# name: A\n# type: matrix\n# rows: 1\n# columns: 3\n 1 2\n"),
        TextFormatError::WrongCount {
            line: 5,
            expected: 3,
            found: 2
        }
    );
    assert!(matches!(
        err("# name: A\n# type: matrix\n# rows: two\n# columns: 3\n"),
        TextFormatError::BadHeader { line: 3, .. }
    ));
}

#[test]
fn unknown_and_unsupported_types() {
    assert_eq!(
        err("# name: A\n# type: quaternion\n1\n"),
        TextFormatError::UnknownType {
            line: 2,
            type_name: "quaternion".into()
        }
    );
    assert_eq!(
        err("# name: z\n# type: complex scalar\n(1,2)\n"),
        TextFormatError::Unsupported {
            line: 2,
            type_name: "complex scalar".into()
        }
    );
    assert!(matches!(
        err("# name: i\n# type: int32 scalar\n5\n"),
        TextFormatError::Unsupported { line: 2, .. }
    ));
}

#[test]
fn non_numeric_data() {
    assert_eq!(
        err("# name: A\n# type: matrix\n# rows: 1\n# columns: 2\n 1 abc\n"),
        TextFormatError::NotANumber {
            line: 5,
            token: "abc".into()
        }
    );
    assert!(matches!(
        err("# name: x\n# type: scalar\n0x10\n"),
        TextFormatError::NotANumber { line: 3, .. }
    ));
    assert!(matches!(
        err("# name: b\n# type: bool\n2\n"),
        TextFormatError::NotANumber { line: 3, .. }
    ));
    assert!(matches!(
        err("stray text\n"),
        TextFormatError::UnexpectedData { line: 1, .. }
    ));
    assert!(matches!(
        err("# name: s\n# type: sq_string\n# elements: 1\n# length: 2\nabc\n"),
        TextFormatError::BadString { line: 5, .. }
    ));
    assert!(matches!(
        err("# name: s\n# type: sq_string\n# elements: 1\n# length: 1\né\n"),
        TextFormatError::BadString { line: 5, .. }
    ));
}

#[test]
fn hostile_counts_give_errors_not_panics_or_huge_allocations() {
    let huge = "18446744073709551615";
    for text in [
        format!("# name: s\n# type: sq_string\n# elements: 1\n# length: {huge}\nab\n"),
        format!("# name: s\n# type: sq_string\n# elements: {huge}\n# length: 1\na\n"),
        format!("# name: A\n# type: matrix\n# rows: {huge}\n# columns: 2\n 1 2\n"),
        format!("# name: A\n# type: matrix\n# rows: 2\n# columns: {huge}\n 1 2\n"),
        "# name: A\n# type: matrix\n# ndims: 3\n 4294967296 4294967296 2\n 1\n".into(),
        format!("# name: c\n# type: cell\n# rows: {huge}\n# columns: {huge}\n"),
        format!("# name: c\n# type: cell\n# rows: {huge}\n# columns: 0\n"),
        format!("# name: A\n# type: matrix\n# rows: {huge}\n# columns: 0\n"),
        format!("# name: A\n# type: bool matrix\n# ndims: 3\n 0 {huge} 2\n"),
        format!("# name: s\n# type: scalar struct\n# ndims: 2\n 1 1\n# length: {huge}\n"),
    ] {
        assert!(read_text(&text).is_err(), "{text}");
    }
    let ws = read_text("# name: r\n# type: double_range\n# base, limit, increment\n0 1 1e-300\n")
        .unwrap();
    assert!(matches!(
        ws.matrix("r"),
        Err(TextFormatError::WrongType { .. })
    ));
}

#[test]
fn never_panics_on_prefixes_of_a_valid_file() {
    // Every prefix of a valid file either parses or gives a typed error.
    for end in 0..OCTAVE_SAMPLE.len() {
        if OCTAVE_SAMPLE.is_char_boundary(end) {
            let _ = read_text(&OCTAVE_SAMPLE[..end]);
        }
    }
}

#[test]
fn workspace_lookup_errors() {
    let ws = read_text(OCTAVE_SAMPLE).unwrap();
    assert_eq!(
        ws.matrix("nope"),
        Err(TextFormatError::MissingVariable {
            name: "nope".into()
        })
    );
    assert!(matches!(
        ws.matrix("c"),
        Err(TextFormatError::WrongType { .. })
    ));
    assert!(matches!(
        ws.scalar("b"),
        Err(TextFormatError::WrongType { .. })
    ));
    assert!(matches!(
        ws.string("a"),
        Err(TextFormatError::WrongType { .. })
    ));
}

mod properties {
    use super::super::reader::parse_number;
    use super::super::*;
    use ndarray::{ArrayD, IxDyn};
    use proptest::prelude::*;

    /// Any double: every bit pattern, NaN payloads included.
    fn any_double() -> impl Strategy<Value = f64> {
        any::<u64>().prop_map(f64::from_bits)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]

        /// Every finite double, ±Inf and ±0 are written so that they read back bit for bit;
        /// NaN reads back as NaN (NA as NA).
        #[test]
        fn numbers_round_trip(x in any_double()) {
            let y = parse_number(&format_number(x), 1).unwrap();
            if x.is_nan() {
                prop_assert!(y.is_nan());
                prop_assert_eq!(is_na(x), is_na(y));
            } else {
                prop_assert_eq!(x.to_bits(), y.to_bits());
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// Matrices and N-d arrays of any shape (zero sizes included) round-trip through
        /// the writer and the reader, bit for bit and in Octave's index order.
        #[test]
        fn arrays_round_trip(
            shape in prop::collection::vec(0usize..4, 2..5),
            seed in prop::collection::vec(-1e6..1e6f64, 64),
        ) {
            let total: usize = shape.iter().product();
            let data: Vec<f64> = (0..total).map(|k| seed[k % seed.len()] / (k + 1) as f64).collect();
            let a = ArrayD::from_shape_vec(IxDyn(&shape), data).unwrap();
            let mut ws = Workspace::new();
            ws.insert("a", a.clone());
            let back = read_text(&write_text(&ws).unwrap()).unwrap().array("a").unwrap();
            // Octave keeps trailing singleton dimensions only up to 2-D; we write them all,
            // so the shape comes back unchanged.
            prop_assert_eq!(back.shape(), a.shape());
            for (x, y) in back.iter().zip(a.iter()) {
                prop_assert_eq!(x.to_bits(), y.to_bits());
            }
        }

        /// Any text made of format fragments parses or gives a typed error, never a panic.
        #[test]
        fn malformed_text_never_panics(
            lines in prop::collection::vec(
                prop::sample::select(vec![
                    "# name: x", "# name: <cell-element>", "# type: matrix", "# type: scalar",
                    "# type: cell", "# type: sq_string", "# type: scalar struct",
                    "# type: bool matrix", "# type: double_range", "# rows: 2",
                    "# rows: 0", "# columns: 3", "# columns: 1", "# ndims: 3", " 2 1 2",
                    " 1 1", "# length: 2", "# length: 1", "# elements: 1", " 1 2 3",
                    " 1", "NaN", "Inf -Inf NA", "ab", "é", "", "x y", "# base, limit, increment",
                    "1 3 1", "# length: 18446744073709551615",
                    "# elements: 18446744073709551615", "# rows: 18446744073709551615",
                    "# columns: 18446744073709551615", "# ndims: 2",
                    " 4294967296 4294967296", " 18446744073709551615 2", "0 1 1e-300",
                ]),
                0..40,
            ),
        ) {
            let text = lines.join("\n");
            let _ = read_text(&text);
            let _ = read_numeric_text(&text);
        }
    }
}

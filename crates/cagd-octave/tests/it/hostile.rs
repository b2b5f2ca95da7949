//! Hostile input to the Octave layer: every recursive reader and writer is bounded, so no file
//! or value can overflow the stack (each case runs in a thread with a small stack).

use cagd::limits::Limits;
use cagd_octave::text_format::{
    read_text, read_text_with, write_text, TextFormatError, Value, Workspace,
};

/// A `save -text` file holding `levels` nested 1×1 cells around the scalar 1.
fn nested_cells(levels: usize) -> String {
    let mut text = String::from("# name: c\n");
    for _ in 0..levels {
        text.push_str("# type: cell\n# rows: 1\n# columns: 1\n# name: <cell-element>\n");
    }
    text.push_str("# type: scalar\n1\n");
    text
}

/// Runs `f` on a thread with a 4 MiB stack: enough for the levels the limits allow even in an
/// unoptimised build (about 10 KB a level), far too small for thousands of unbounded levels.
fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(4 << 20)
        .spawn(f)
        .unwrap()
        .join()
        .expect("no stack overflow, no panic")
}

#[test]
fn ten_thousand_nested_cells_are_refused_not_a_stack_overflow() {
    // The finding: a 590 KB file of 10 000 nested 1×1 cells crashed the reader by signal.
    let text = nested_cells(10_000);
    let err = on_small_stack(move || read_text(&text).unwrap_err());
    assert!(
        matches!(
            err,
            TextFormatError::TooDeep {
                limit: 64,
                line: 257
            }
        ),
        "{err:?}"
    );
    assert_eq!(
        err.to_string(),
        "line 257: structs and cells are nested deeper than 64 levels"
    );
}

#[test]
fn nesting_within_the_limit_reads_and_writes_back() {
    let ws = on_small_stack(|| read_text(&nested_cells(20)).unwrap());
    let mut v = ws.get("c").unwrap();
    for _ in 0..20 {
        match v {
            Value::Cell(c) => v = &c[[0, 0]],
            other => panic!("expected a cell, found {other:?}"),
        }
    }
    assert_eq!(v, &Value::Scalar(1.0));
    let again = read_text(&write_text(&ws).unwrap()).unwrap();
    assert_eq!(again, ws);
    // A lower depth limit refuses the same file.
    let small = Limits {
        max_depth: 10,
        ..Limits::default()
    };
    let err = read_text_with(&nested_cells(20), &small).unwrap_err();
    assert!(
        matches!(err, TextFormatError::TooDeep { limit: 10, .. }),
        "{err:?}"
    );
}

#[test]
fn the_writer_refuses_values_nested_beyond_what_it_can_write() {
    let mut v = Value::Scalar(1.0);
    for _ in 0..300 {
        v = Value::Cell(ndarray::ArrayD::from_elem(ndarray::IxDyn(&[1, 1]), v));
    }
    let mut ws = Workspace::new();
    ws.insert("c", v);
    let err = on_small_stack(move || write_text(&ws).unwrap_err());
    assert!(
        matches!(err, TextFormatError::Unwritable { ref message, .. } if message.contains("nested deeper than 256")),
        "{err:?}"
    );
}

/// The finding: a 1 MB data script of 170 000 distinct assignments took 187 s, because every
/// new name was searched for in the list of all names. The bookkeeping is now a set: linear.
#[test]
fn scripts_of_many_distinct_assignments_run_in_linear_time() {
    let source: String = (0..60_000)
        .map(|i| format!("v{i} = {};\n", i % 10))
        .collect();
    let start = std::time::Instant::now();
    let s = cagd_octave::script::run::<f64>(&source, cagd_octave::literal::Env::new()).unwrap();
    assert_eq!(s.names().len(), 60_000);
    assert_eq!(s.names()[59_999], "v59999");
    assert_eq!(s.value("v12345").unwrap()[(0, 0)], 5.0);
    // Quadratic bookkeeping took about 10 s for these 60 000 names in a release build.
    assert!(start.elapsed().as_secs() < 5, "{:?}", start.elapsed());
}

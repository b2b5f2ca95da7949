//! The Octave `save -text` reader and the plain numeric text reader must answer any bytes with
//! a value or a typed error, and what they read must write back and read again.
#![no_main]

use cagd::octave::text_format::{read_numeric_text, read_text, write_text};
use libfuzzer_sys::fuzz_target;

/// Fuzzing runs with smaller limits than the defaults (10⁴ elements instead of 4·10⁶): the
/// instrumented build is 10–50 times slower, and at the default sizes linear work (an exact
/// range of a million elements) would pass the 10-second timeout without being a bug. The
/// limits themselves are what is exercised.
fn small_limits() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        cagd::limits::Limits {
            max_elements: 10_000,
            max_iterations: 10_000,
            max_samples: 1_000,
            max_grid_points: 10_000,
            max_work: 5_000_000,
            max_system_entries: 100_000,
            ..cagd::limits::Limits::default()
        }
        .set_current();
    });
}


fuzz_target!(|data: &[u8]| {
    small_limits();
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(ws) = read_text(text) {
        // Whatever was read is loadable again (the writer may refuse odd names, never panic).
        if let Ok(written) = write_text(&ws) {
            let again = read_text(&written).expect("written text reads back");
            assert_eq!(again.len(), ws.len());
        }
        for (name, _) in ws.iter() {
            let _ = ws.array(name);
            let _ = ws.matrix(name);
            let _ = ws.scalar(name);
            let _ = ws.string(name);
        }
    }
    let _ = read_numeric_text(text);
});

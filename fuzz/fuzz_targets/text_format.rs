//! The Octave `save -text` reader and the plain numeric text reader must answer any bytes with
//! a value or a typed error, and what they read must write back and read again.
#![no_main]

mod common;
use common::fuzz_limits;

use cagd_octave::text_format::{read_numeric_text, read_text_with, write_text};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let limits = fuzz_limits();
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(ws) = read_text_with(text, &limits) {
        // Whatever was read is loadable again (the writer may refuse odd names, never panic).
        if let Ok(written) = write_text(&ws) {
            let again = read_text_with(&written, &limits).expect("written text reads back");
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

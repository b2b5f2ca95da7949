//! The core's public constructors and evaluators with arbitrary arguments: the first byte picks
//! a group of functions, the rest are the arguments, drawn by
//! `cagd_test_support::hostile_calls` (sizes up to `usize::MAX`, indices out of range, knot
//! vectors short or unsorted, values near the `f64` range, subnormals, NaN, ±∞ and any bit
//! pattern). The property test `tests/it/hostile_library.rs` makes the same calls from a seeded
//! stream. A call may return an error; a panic or an abort is a finding.
#![no_main]

use cagd_test_support::hostile_calls::{call, Draws, OPS};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&op, rest)) = data.split_first() else {
        return;
    };
    call(op as usize % OPS, &Draws::from_bytes(rest));
});

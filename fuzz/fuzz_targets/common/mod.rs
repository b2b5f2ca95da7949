//! What the parser fuzz targets share.

/// The limits the targets run at: the defaults, as a user gets them. What is fuzzed is that
/// every limit holds at the sizes users reach, and that nothing grows faster than the work it is
/// charged for. The instrumented build is 10–50 times slower than a release build, so
/// `run_fuzz.sh` allows 30 seconds per input: an input slower than that is up to 50 times
/// more work than a second of a release build, which the default limits must not allow.
pub fn fuzz_limits() -> cagd::limits::Limits {
    cagd::limits::Limits::default()
}

//! What the parser fuzz targets share.

/// Fuzzing runs with smaller limits than the defaults (10⁴ elements instead of 4·10⁶): the
/// instrumented build is 10–50 times slower, and at the default sizes linear work (an exact
/// range of a million elements) would pass the 10-second timeout without being a bug. The
/// limits themselves are what is exercised.
pub fn small_limits() -> cagd::limits::Limits {
    cagd::limits::Limits {
        max_elements: 10_000,
        max_iterations: 10_000,
        max_samples: 1_000,
        max_grid_points: 10_000,
        max_work: 5_000_000,
        max_system_entries: 100_000,
        ..cagd::limits::Limits::default()
    }
}

//! The criterion settings every benchmark of cagd-bench uses: 1 s warm-up, 2 s of
//! measurement, 10 samples (enough to separate the cases compared, short enough for a 2-core
//! machine).

use std::time::Duration;

use criterion::Criterion;

/// The shared configuration.
pub fn config() -> Criterion {
    Criterion::default()
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_secs(1))
        .sample_size(10)
}

//! Shared fixtures of the cagd benchmarks.

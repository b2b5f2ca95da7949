//! The context of one command: its limits, and what it collects while it runs.

use cagd::limits::Limits;

/// The context a subcommand runs in: passed by value down every call, never global.
#[derive(Debug, Clone)]
pub(crate) struct Cx {
    /// The resource limits (`--max-…`, `CAGD_MAX_…`, defaults).
    pub limits: Limits,
}

impl Cx {
    /// A context with `limits`.
    pub fn new(limits: Limits) -> Self {
        Cx { limits }
    }
}

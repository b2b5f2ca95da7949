//! What a command produced.

use cagd_octave::literal::Warning;

use crate::PendingWrites;

/// What a command produced: text for standard output, files, warnings.
#[derive(Debug)]
pub struct Outcome {
    /// The text for standard output.
    pub stdout: String,
    /// The files to write (staged, not yet written).
    pub files: PendingWrites,
    /// Warnings, each with the argument it is about.
    pub warnings: Vec<(String, Warning)>,
}

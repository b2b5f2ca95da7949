//! The integration tests of the Octave layer, one module per subject: literals and scripts,
//! the `save -text` format against live Octave, the thesis functions (`compat`) against the
//! fixed Octave code, the bug catalogue of the printed code.

mod bug_catalogue;
mod derivative;
mod differential;
mod hostile;
mod literal;
mod octave_compat;
mod octave_format;

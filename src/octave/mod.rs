//! The Octave-compatible layer.

pub mod literal;
pub mod script;

//! The Octave-compatible layer.

//! The integration tests of the core crate `cagd`, one module per subject: the Octave
//! references, properties, worked examples of the sources, bad input of the library.
//! (`tests/allocations.rs` is a separate binary: its counting allocator is process-wide.)

mod bezier_errors;
mod coons;
mod course_errors;
mod course_examples;
mod course_octave;
mod domain;
mod exact_paths;
mod examples;
mod gordon;
mod grid_eval;
mod hostile_library;
mod layers;
mod mixed_boundaries;
mod octave_reference;
mod patch_ops;
mod properties;
mod properties_coons;
mod properties_course;
mod source_examples;
mod spline_grid;
mod support;

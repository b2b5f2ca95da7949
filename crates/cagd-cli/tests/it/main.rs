//! The integration tests of the command line, one module per subject: snapshots of every
//! subcommand, bad inputs, limits, atomic output, meshes, fuzzing regressions; and the operation
//! layer's own tests ([`operations`]).

mod any_curve;
mod atomic_output;
mod bad_inputs;
mod cli;
mod course;
mod curvature;
mod error_catalogue;
mod file_rules;
mod function_length;
mod hostile;
mod lang;
mod limits;
mod mesh;
mod non_finite;
mod operations;
mod packed_network;
mod pictures;
mod regressions;
#[cfg(feature = "serve")]
mod serve;
mod slips;

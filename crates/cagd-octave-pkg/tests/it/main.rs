//! The package's tests, one binary: the functions through their public entry points (the
//! argument readers, the errors, the exact numbers, the octave-nurbs twins, the native splines
//! and surfaces), their prices against the operation layer's ([`cost`]) and their interrupts
//! ([`interrupt`]). The library itself has no unit tests (`[lib] test = false`): one test
//! binary links it once instead of compiling it a second time in test mode.

mod args;
mod cost;
mod error;
mod interrupt;
mod number;
mod nurbs;
mod splines;
mod surfaces;
mod values;

//! Step layouts shared by several constructions.

pub mod scheme;

//! The Octave-compatible layer.
//!
//! - [`text_format`]: GNU Octave's `save -text` file format (reader and writer) and the plain
//!   numeric text of `save -ascii` / `dlmwrite`; every reference number of the crate's tests is
//!   read through it.

pub mod text_format;

pub use text_format::{
    read_numeric_text, read_text, read_text_file, write_text, write_text_file, CharMatrix, Quote,
    TextFormatError, Value, Workspace,
};

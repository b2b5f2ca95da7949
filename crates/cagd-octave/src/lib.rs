//! The Octave-compatible layer.
//!
//! - [`compat`]: the thesis functions under their own names (`de_casteljau`, `ploskev_b`,
//!   `bilinearna`, `tenzor`, `linspace`, …), taking and returning `ndarray` arrays in the thesis
//!   layouts, each a thin layer over the native API;
//! - [`text_format`]: GNU Octave's `save -text` file format (reader and writer) and the plain
//!   numeric text of `save -ascii` / `dlmwrite`; every reference number of the crate's tests is
//!   read through it;
//! - [`literal`]: the Octave syntax users type (matrix literals, ranges, curve expressions);
//! - [`script`]: the thesis's data scripts;
//! - [`arrays`]: Octave-shaped `ndarray` arrays to the core's native types and back;
//! - [`octave_nurbs`]: octave-nurbs' functions with its conventions (homogeneous `coefs`,
//!   evaluation on `[U(1), U(end)]`, weights of any sign), as the Octave package's twins use
//!   them.

pub mod arrays;
pub mod compat;
pub mod literal;
pub mod octave_nurbs;
pub mod script;
pub mod text_format;

pub use text_format::{
    read_numeric_text, read_text, read_text_file, write_text, write_text_file, CharMatrix, Quote,
    TextFormatError, Value, Workspace,
};

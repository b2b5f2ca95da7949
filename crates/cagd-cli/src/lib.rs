//! The command line as a library: reading inputs, printing results, writing files.
//!
//! The `cagd` binary is a thin layer over this module: it parses arguments with the shared
//! argument groups of [`args`], loads inputs with [`load_matrix`], [`load_params`],
//! [`samples`], [`load_expression`] and [`load_script`], calls the library, renders the
//! [`Report`] with [`render`] and writes files with [`PendingWrites`] (atomically: a file is
//! complete or absent).
//!
//! The whole command line runs in-process with [`run`]: it parses the arguments, computes, and
//! returns an [`Outcome`] holding the text for standard output and the files to write, staged
//! in memory; nothing touches the file system until the caller commits the files (the binary
//! does, fuzzing and tests need not).
//!
//! `cagd serve` ([`serve`]) is the one subcommand that is not a computation: the binary asks
//! [`serve_request`] first and serves the web page on localhost.
//!
//! Every failure is a [`CliError`]: one line `<argument>: <problem>; expected <form>`, exit
//! code 2 (1 only for internal faults).

mod app;
pub mod args;
mod atomic;
mod error;
#[doc = include_str!("../../../docs/ERRORS.md")]
pub mod error_catalogue {}
pub mod faults;
mod input;
pub mod limits;
pub mod mesh;
mod output;
pub mod outputs;
pub mod plot;
pub mod schema;
#[cfg(all(feature = "serve", not(target_arch = "wasm32")))]
pub mod serve;
#[cfg(not(all(feature = "serve", not(target_arch = "wasm32"))))]
pub mod serve {
    //! `cagd serve` exists only in the program built with the feature `serve`; elsewhere (the
    //! browser, the fuzz targets) its arguments still parse and serving is refused.
    use crate::{CliError, ErrorKind};

    /// Serve the web page on localhost.
    #[derive(Debug, Clone, clap::Args)]
    pub struct ServeCommand {
        /// The port on 127.0.0.1.
        #[arg(long, value_name = "P", default_value_t = 8000)]
        pub port: u16,
        /// The folder of the built page.
        #[arg(long, value_name = "DIR", value_parser = crate::args::path_value)]
        pub dir: Option<std::path::PathBuf>,
    }

    /// Refuses: this build has no server.
    ///
    /// # Errors
    /// Always, [`ErrorKind::Unsupported`].
    pub fn serve(_: &ServeCommand) -> Result<(), CliError> {
        Err(CliError::new(
            "serve",
            "this build of cagd has no page server (built without the feature `serve`)",
            "a cagd built with its default features",
            ErrorKind::Unsupported,
        ))
    }
}
pub mod slips;
pub mod temporaries;

pub use app::{run, serve_request, subcommands, Outcome};
pub use atomic::{write_atomic, PendingWrites};
pub use error::{escape_path, escape_text, CliError, ErrorKind};
pub use input::{
    load_expression, load_matrix, load_net, load_params, load_script, parse_data_text,
    parse_data_text_variable, parse_numeric_text, read_octave_array, read_text, samples,
    scalar_from_double, unpack_net, with_input_files, CURVE_FORM, MATRIX_FORM, MAX_INPUT_BYTES,
    PARAMS_FORM,
};
pub use output::{
    number_text, number_text_digits, render, render_with, Format, Item, Report, Value, TEXT_DIGITS,
};

//! `cagd serve`: serving the page is the program's own loop (see [`crate::serve`]); run in
//! process, it is refused.

use cagd_octave::literal::LiteralScalar;

use super::cx::Cx;
use super::run::Run;
use super::Outcome;
use crate::serve::ServeCommand;
use crate::{CliError, ErrorKind};

impl Run for ServeCommand {
    fn run<T: LiteralScalar>(&self, _cx: &mut Cx) -> Result<Outcome, CliError> {
        Err(CliError::new(
            "serve",
            "serving the page is done by the cagd program itself, not in-process",
            "`cagd serve` typed in a terminal",
            ErrorKind::Unsupported,
        ))
    }
}

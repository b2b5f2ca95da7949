//! The subcommands not yet moved onto the operation layer, run as before (each is removed
//! from here when its own file implements [`Run`]).

use cagd_octave::literal::LiteralScalar;

use super::run::Run;
use super::*;

impl Run for thesis::ThesisCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        thesis::thesis(&cx.limits, self)
    }
}

impl Run for course_examples::CourseCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        course_examples::course(&cx.limits, self)
    }
}

impl Run for crate::serve::ServeCommand {
    fn run<T: LiteralScalar>(&self, _cx: &mut Cx) -> Result<Outcome, CliError> {
        Err(CliError::new(
            "serve",
            "serving the page is done by the cagd program itself, not in-process",
            "`cagd serve` typed in a terminal",
            ErrorKind::Unsupported,
        ))
    }
}

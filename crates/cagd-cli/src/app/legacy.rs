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

impl Run for bezier::BezierPatchCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        bezier::bezier_patch::<T>(&cx.limits, self)
    }
}

impl Run for bezier::BernsteinCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        bezier::bernstein::<T>(&cx.limits, self)
    }
}

impl Run for bezier::DerivativeCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        bezier::derivative::<T>(&cx.limits, self)
    }
}

impl Run for convert::ConvertCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        convert::convert::<T>(&cx.limits, self)
    }
}

impl Run for elevate::ElevateCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        elevate::elevate::<T>(&cx.limits, self)
    }
}

impl Run for subdivide::SubdivideCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        subdivide::subdivide::<T>(&cx.limits, self)
    }
}

impl Run for continuity::ContinuityCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        continuity::continuity::<T>(&cx.limits, self)
    }
}

impl Run for integrate::IntegrateCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        integrate::integrate::<T>(&cx.limits, self)
    }
}

impl Run for CurveCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        curve::<T>(&cx.limits, self)
    }
}

impl Run for SurfaceCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        surface::<T>(&cx.limits, self)
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

impl Run for ScriptCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        script::<T>(&cx.limits, self)
    }
}

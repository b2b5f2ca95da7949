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

impl Run for patches::CoonsBicubicCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        patches::coons_bicubic::<T>(&cx.limits, self)
    }
}

impl Run for patches::DiscreteCoonsCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        patches::discrete::<T>(&cx.limits, self)
    }
}

impl Run for patches::GordonCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        patches::gordon::<T>(&cx.limits, self)
    }
}

impl Run for lagrange::LagrangeCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        lagrange::lagrange::<T>(&cx.limits, self)
    }
}

impl Run for course::SplineCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        course::spline::<T>(&cx.limits, self)
    }
}

impl Run for course::HermiteCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        course::hermite::<T>(&cx.limits, self)
    }
}

impl Run for course::BSplineCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        course::bspline::<T>(&cx.limits, self)
    }
}

impl Run for course::NurbsCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        course::nurbs::<T>(&cx.limits, self)
    }
}

impl Run for insert_knot::InsertKnotCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        insert_knot::insert_knot::<T>(&cx.limits, self)
    }
}

impl Run for bspline_basis::BSplineBasisCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        bspline_basis::bspline_basis::<T>(&cx.limits, self)
    }
}

impl Run for ruled::RuledCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        ruled::ruled::<T>(&cx.limits, self)
    }
}

impl Run for ferguson::FergusonCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        ferguson::ferguson::<T>(&cx.limits, self)
    }
}

impl Run for bspline_surface::BSplineSurfaceCommand {
    fn exact(&self) -> bool {
        self.args.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        bspline_surface::bspline_surface::<T>(&cx.limits, self)
    }
}

impl Run for nurbs_surface::NurbsSurfaceCommand {
    fn exact(&self) -> bool {
        self.args.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        nurbs_surface::nurbs_surface::<T>(&cx.limits, self)
    }
}

impl Run for circle::CircleCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        circle::circle(&cx.limits, self)
    }
}

impl Run for circle::ArcCommand {
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        circle::arc(&cx.limits, self)
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

//! How a subcommand runs: the [`Run`] trait every subcommand implements, the one place where
//! the number type is chosen ([`run_any`]), and how the command line names the roles of the
//! operation layer ([`Names`]).

use cagd_octave::literal::LiteralScalar;
use cagd_ops::Role;
use num_rational::BigRational;

use super::cx::Cx;
use crate::{CliError, Outcome};

/// A subcommand: its arguments (the clap struct implementing this) and how it runs.
pub(crate) trait Run {
    /// Whether `--exact` asks for rational arithmetic.
    fn exact(&self) -> bool {
        false
    }

    /// Runs in the arithmetic `T`.
    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError>;
}

/// Runs `command` in `f64`, or with `--exact` in rationals: the only place the number type is
/// chosen.
pub(crate) fn run_any<R: Run>(command: &R, cx: &mut Cx) -> Result<Outcome, CliError> {
    if command.exact() {
        command.run::<BigRational>(cx)
    } else {
        command.run::<f64>(cx)
    }
}

/// How a subcommand names the roles of its operation: its own names first, then the
/// command line's usual ones ([`option_name`]); the result is named by the subcommand's main
/// input (a result that overflows is about what it was computed from).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Names {
    /// The argument the result is computed from (`CONTROL`).
    pub input: &'static str,
    /// Roles named otherwise than [`option_name`] says.
    pub special: &'static [(Role, &'static str)],
}

impl Names {
    /// The command line's name of `role` in this subcommand.
    pub fn of(&self, role: Role) -> &'static str {
        if role == Role::Result {
            return self.input;
        }
        self.special
            .iter()
            .find(|(r, _)| *r == role)
            .map_or_else(|| option_name(role), |(_, name)| *name)
    }
}

/// The command line's usual name of a role.
pub(crate) fn option_name(role: Role) -> &'static str {
    match role {
        Role::Control => "CONTROL",
        Role::Net => "NET",
        Role::Degree => "--degree",
        Role::Order => "--order",
        Role::Knots => "--knots",
        Role::UKnots => "--uknots",
        Role::VKnots => "--vknots",
        Role::Weights => "--weights",
        Role::Interval => "--interval",
        Role::T => "--t",
        Role::U => "--u",
        Role::V => "--v",
        Role::Grid => "--u/--v",
        Role::Samples => "--n",
        Role::DerivativeOrder => "--order",
        Role::DerivativeV => "--dv",
        Role::Nodes => "--nodes",
        Role::Points => "POINTS",
        Role::Ends => "--ends",
        Role::C1 => "--c1",
        Role::C2 => "--c2",
        Role::D1 => "--d1",
        Role::D2 => "--d2",
        Role::Boundary => "--c1/--c2/--d1/--d2",
        Role::C1v => "--c1v",
        Role::C2v => "--c2v",
        Role::D1u => "--d1u",
        Role::D2u => "--d2u",
        Role::Twist => "--twist",
        Role::Twists => "--twists",
        Role::Blend => "--blend",
        Role::Mask => "--mask",
        Role::UCurves => "--u-curve",
        Role::VCurves => "--v-curve",
        Role::UNodes => "--u-nodes",
        Role::VNodes => "--v-nodes",
        Role::Network => "--u-curve/--v-curve",
        Role::Cross => "--c1v/--c2v/--d1u/--d2u",
        Role::Du => "--du",
        Role::Dv => "--dv",
        Role::Steps => "--steps",
        Role::First => "--first",
        Role::Second => "--second",
        Role::P0 => "--p0",
        Role::P1 => "--p1",
        Role::T0 => "--t0",
        Role::T1 => "--t1",
        Role::Hermite => "--p0/--p1/--t0/--t1",
        Role::From => "--from",
        Role::To => "--to",
        Role::By => "--by",
        Role::At => "--at",
        Role::Radius => "--radius",
        Role::Center => "--center",
        Role::Angles => "--angles",
        Role::Tolerance => "--tolerance",
        Role::Index => "--i",
        Role::Spline => "CONTROL/--degree/--knots",
        Role::Factor => "--k",
        Role::Joint => "FIRST/SECOND",
        Role::Result => "RESULT",
        _ => "argument",
    }
}

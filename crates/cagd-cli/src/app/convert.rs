//! `cagd convert`: a polynomial curve from one geometry form to another (the lecture notes,
//! "Konverze mezi reprezentacemi"; the matrix-form notes' product `P · M`). The forms and
//! their conversion matrices are the core's ([`cagd::conversion::GeometryForm`]).

use cagd::conversion::GeometryForm;
use cagd_octave::literal::LiteralScalar;
use cagd_ops::ops::Convert;
use cagd_ops::Role;
use clap::{Args, ValueEnum};

use super::answer::{respond, Destinations};
use super::cx::Cx;
use super::read::points;
use super::run::{Names, Run};
use crate::args::{OutputArgs, PlotArgs, RowsArgs, StepsArgs};
use crate::{CliError, Outcome};

/// A representation of a polynomial curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Form {
    /// Hermite (Ferguson) cubic: [x(0) x(1) x'(0) x'(1)].
    Hermite,
    /// Bézier control points b_0 … b_n (any degree).
    Bezier,
    /// Uniform cubic B-spline segment ("Coons cubic"): [x_(i-1) x_i x_(i+1) x_(i+2)].
    Bspline,
    /// Monomial coefficients a_0 … a_n of 1, t, …, t^n (the matrix-form notes' P·M).
    Monomial,
    /// The lecture notes' algebraic form [a b c d] of u³, u², u, 1 (powers descending).
    Algebraic,
}

impl From<Form> for GeometryForm {
    fn from(form: Form) -> Self {
        match form {
            Form::Hermite => GeometryForm::Hermite,
            Form::Bezier => GeometryForm::Bezier,
            Form::Bspline => GeometryForm::BSpline,
            Form::Monomial => GeometryForm::Monomial,
            Form::Algebraic => GeometryForm::Algebraic,
        }
    }
}

/// Convert a curve between Hermite, Bézier, B-spline, monomial and algebraic forms.
#[derive(Debug, Args)]
#[command(after_help = "\
Input: GEOMETRY, the d×(n+1) geometry matrix of the --from form, one vector per column (rows
with --rows): hermite [x(0) x(1) x'(0) x'(1)], bezier [b_0 … b_n], bspline (the uniform cubic
segment of the lecture notes) [x_(i-1) x_i x_(i+1) x_(i+2)], monomial [a_0 … a_n] with
p(t) = Σ a_j t^j (the matrix-form notes' P·M), algebraic [a b c d] of u³ u² u 1 (the lecture
notes' A). hermite and bspline are cubic (4 columns); bezier, monomial and algebraic any degree.
Layout: result is the geometry of the --to form (d×(n+1)). X_to = X_from · T; --steps prints T
and, between the cubic forms, the basis matrices M_from, M_to and M_to⁻¹ (T = M_from·M_to⁻¹, the
lecture notes' conversion table); otherwise the matrices to and from the Bézier form.

Examples:
  cagd convert \"[0 0; 1 1; 2 0; 3 1]\" --rows --from bezier --to monomial --exact
  cagd convert \"[2 3; 5 3; 3 6; 3 -12]\" --rows --from hermite --to bspline --steps --exact")]
pub struct ConvertCommand {
    /// The geometry matrix of the curve, one vector per column (rows with --rows).
    #[arg(value_name = "GEOMETRY", allow_hyphen_values = true)]
    pub geometry: String,
    /// The form GEOMETRY is in.
    #[arg(long, value_enum)]
    pub from: Form,
    /// The form to convert to.
    #[arg(long, value_enum)]
    pub to: Form,
    #[command(flatten)]
    pub rows: RowsArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
}

/// The names of this command's arguments.
const NAMES: Names = Names {
    input: "GEOMETRY",
    special: &[(Role::Control, "GEOMETRY")],
};

impl Run for ConvertCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let op = Convert::<T> {
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
            ..Convert::new(
                points(cx, "GEOMETRY", &self.geometry, None, self.rows.rows)?,
                self.from.into(),
                self.to.into(),
            )
        };
        let to = Destinations {
            output: &self.output,
            plot: self.plot.plot.as_deref(),
            mesh: None,
        };
        respond(cx, &NAMES, &op, to)
    }
}

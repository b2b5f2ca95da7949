//! The `cagd` command line in-process: parse the arguments, call the library, and return what
//! would be printed and written (see [`crate::run`]).

use cagd::limits::Limits;
use std::ffi::OsString;

use cagd::grid::PointGrid;
use clap::error::{ContextKind, ErrorKind as ClapKind};
use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use nalgebra::DMatrix;
use num_rational::BigRational;

mod bezier;

mod blend;

mod bspline_basis;

mod bspline_surface;

mod circle;

mod common;

mod continuity;

mod convert;

mod course;

mod course_examples;

mod curve;

mod discrete_parts;

mod elevate;

mod ferguson;

mod insert_knot;

mod integrate;

mod nurbs_surface;

mod outcome;

mod lagrange;

mod patches;

mod ruled;

mod scheme;

mod spline_steps;

mod subdivide;

mod thesis;

mod work;

use crate::args::{
    CurveParamArgs, LimitArgs, MeshArgs, OutputArgs, PlotArgs, ScriptArgs, SurfaceParamArgs,
};
use crate::plot::{Colour, Figure};
use crate::{
    load_expression, load_params, load_script, samples, CliError, ErrorKind, PendingWrites, Report,
    Value, CURVE_FORM,
};
use cagd_octave::literal::{Env, LiteralScalar, Warning};
use cagd_octave::script::{Binding, Script};

/// Curves and surfaces of computer-aided geometric design, checked against GNU Octave.
#[derive(Debug, Parser)]
#[command(name = "cagd", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    #[command(flatten)]
    limits: LimitArgs,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Reproduce every worked example and appendix run of the thesis, with steps and pictures.
    #[command(after_help = "\
Needs no input. Prints Primer 2.4 (de Casteljau scheme at t = 1/2 and the curve), a Bézier
patch example in place of Primer 3.2 (whose net is garbled in the source and whose printed
z-values are inconsistent), Primer 4.3 (r_c, r_d, r_cd and x at (0.2, 0.5), exactly), the
appendix C Coons patch (data script with its N and P4 bugs fixed) and the appendix D Gordon
surface (g1, g2, g12 at a point, the grid, the conditioning). Pictures (SVG and PNG) and
meshes (STL, OBJ, PLY) go to --out, written atomically.

Example:
  cagd thesis --out cagd-out")]
    Thesis(thesis::ThesisCommand),
    /// Reproduce the worked examples of the course notes (matrix-form, lecture and CAD notes).
    #[command(after_help = "\
Needs no input. Prints, exactly where the maths is rational, the matrix-form notes' table
(P·M = [0 3 0 0; 0 3 -6 4] and the points at t = 0, 0.2, …, 1), the lecture notes' conversion
table on their Bézier example (Bézier → Hermite → B-spline and back), the three splines of
the lecture notes (clamped, natural, closed; the printed sign error of the clamped example
named), the Lagrange example and Příklad 1, the C1 joint with its free point, the NURBS
circle of the CAD notes and the discrete Coons patch with its 3×3 masks. Pictures (SVG and
PNG) go to --out, written atomically.

Example:
  cagd course --out cagd-course")]
    Course(course_examples::CourseCommand),
    /// Points of a Bézier curve by de Casteljau's algorithm (thesis algorithm 1).
    #[command(after_help = "\
Input: control points b_0..b_n as the columns of a d×(n+1) matrix (rows with --rows): a
literal, a numeric text/CSV file, an Octave save -text file (FILE or FILE:NAME; else its first
numeric variable), or - for standard input.
Layout: result is d×k, one point per column (like T in deCasteljau); t is 1×k.
--steps prints the whole scheme b_i^r(t) for each t, columns r = 0..n, as in Primer 2.4 (in
json and octave formats as data: scheme.r0 … scheme.rn, level r a d×(n+1−r) matrix).
--interval a,b puts the curve on [a, b] (thesis §2.3.2). Points typed as rows (more rows than
columns, or more than 3 rows) get a warning naming --rows.

Examples:
  cagd decasteljau \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'\" --t 0.5 --steps --exact
  cagd decasteljau \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]\" --rows --n 50 --plot curve.svg")]
    #[command(mut_arg("n", |a| a.help("Sample at linspace(0,1,N), like the thesis's N (mapped onto --interval if given)")))]
    Decasteljau(bezier::DeCasteljauCommand),
    /// Points of a Bézier patch (thesis algorithms 2-4, ploskevB/bilinearna/tenzor).
    #[command(after_help = "\
Input: the net packed (m+1)×3(n+1) as ploskevB takes it (row i = [b_i0 b_i1 ... b_in], x y z
side by side), or an Octave save -text file with an (m+1)×(n+1)×3 array.
Instead of NET: --x, --y, --z, the coordinate matrices (m+1)×(n+1) (entry (i,j) of b_ij).
Layout: with single --u and --v, result is the 3×1 point; otherwise result is the grid
nu×nv×3 (result(i,j,:) at (u(i), v(j)), like P in ploskevB), or with --list one row u v x y z
per point. --steps prints the tensor de Casteljau scheme for each (u, v). --du R --dv S give
the partial derivative ∂^(R+S)x/∂u^R∂v^S (thesis Trditev 3.3; --du 1 --dv 1 the twist): its
values as result and its net as net.

Examples:
  cagd bezier-patch \"[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0]\" --u 0.5 --v 0.5 --steps
  cagd bezier-patch net.txt --n 20 --plot patch.png --mesh patch.stl")]
    BezierPatch(bezier::BezierPatchCommand),
    /// A bilinearly blended Coons patch x = r_c + r_d - r_cd (thesis 4.1, algorithms 5, 6).
    #[command(after_help = "\
Input: --c1 x(u,0), --c2 x(u,1) (expressions in u), --d1 x(0,v), --d2 x(1,v) (in v), as the
thesis writes them, e.g. \"[u;0;u-u^2]\"; a constant matrix or data file instead gives the
control points (columns) of a Bézier curve. Or --script FILE: the appendix C data script
(sampled c1, c2, d1, d2 and corners P1..P4); --n binds its N. A script's matrix named in a
curve argument (--c1 c1) is read as Bézier control points, with a warning; --samples reads it
as samples of the curve, as appendix C means. --blend linear|hermite|EXPR chooses the blending
functions of thesis (4.4) (hermite: the partially bicubic patch of §4.2).
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3 (like P), or with
--list one row u v x y z per point. --steps also prints rc, rd, rcd (same layout). --plot draws
the surface with c1, c2 in red and d1, d2 in green, as appendix C does.

Examples:
  cagd coons --c1 \"[u;0;u-u^2]\" --c2 \"[u;1;u]\" --d1 \"[0;v^2;v-v^2]\" --d2 \"[1;v;v]\" --u 0.2 --v 0.5 --steps --exact
  cagd coons --script appendix_c.m --n 10 --plot coons.png --mesh coons.obj")]
    Coons(patches::CoonsCommand),
    /// A bicubically blended Coons patch with cross-boundary derivatives (thesis 4.3).
    #[command(after_help = "\
Input: the boundaries as for coons, and the cross-boundary derivative curves --c1v x_v(u,0),
--c2v x_v(u,1) (in u), --d1u x_u(0,v), --d2u x_u(1,v) (in v). --twist zero|gregory|given
chooses the corner twists x_uv (given: --twists, a d×4 matrix for P1..P4; gregory needs
Bézier cross-boundary curves, whose derivatives it uses).
Layout: as for coons; --steps prints the three parts of thesis (4.5): hc (the curves in v
blended along u), hd (the curves in u blended along v) and hcd (the corner data), x = hc + hd − hcd.

Example:
  cagd coons-bicubic --c1 \"[u;0;0]\" --c2 \"[u;1;0]\" --d1 \"[0;v;0]\" --d2 \"[1;v;0]\" --c1v \"[0;1;0]\" --c2v \"[0;1;0]\" --d1u \"[1;0;0]\" --d2u \"[1;0;0]\" --n 5")]
    CoonsBicubic(patches::CoonsBicubicCommand),
    /// The discrete Coons patch: interior control points from the boundary of a net.
    #[command(after_help = "\
Input: a net as for bezier-patch; only its boundary rows and columns are used.
Layout: result is the full net (m+1)×(n+1)×3; --steps also prints its parts bu, bv, buv (the
CAD notes (6): net = bu + bv − buv).
--mask=ALPHA,BETA solves the affine mask instead (alpha + beta = 1/4): α = −1/4, β = 1/2 is the
permanence principle's mask, the discrete Coons patch again; α = 0, β = 1/4 the discrete Laplace
mask.

Examples:
  cagd discrete-coons \"[0 0 0 0 1 0 0 2 0; 1 0 0 0 0 0 1 2 1; 2 0 0 2 1 1 2 2 0]\"
  cagd discrete-coons net.txt --mask=0,0.25")]
    DiscreteCoons(patches::DiscreteCoonsCommand),
    /// A Gordon surface g = g1 + g2 - g12 of a curve network (thesis 4.4, algorithm 7).
    #[command(after_help = "\
Input: repeated --u-curve g(u_i, v) (expressions in v) and --v-curve g(u, v_j) (in u), in node
order, with --u-nodes and --v-nodes (default equally spaced); or --script FILE with appendix
D's packed g_u (3×kN), g_v, g_uv (k×3k) and nodes x, read as krpa_gordon reads them: each curve
is the polyline through its N samples (at the script's u and v, else linspace(0,1,N)), with the
crossing from g_uv added where a node is not a sample; default --u/--v: the samples.
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3. --steps also prints
g1, g2, g12. The conditioning line gives the Lebesgue constants of the node vectors.

Examples:
  cagd gordon --v-curve \"[u;0;u-u^2]\" --v-curve \"[u;0.5;0.5+u-u^2]\" --v-curve \"[u;1;1+u-u^2]\" \\
              --u-curve \"[0;v;v]\" --u-curve \"[0.5;v;0.25+v]\" --u-curve \"[1;v;v]\" --u 0.25 --v 0.75 --steps --exact
  cagd gordon --script appendix_d.m --n 10 --plot gordon.png")]
    Gordon(patches::GordonCommand),
    /// Lagrange basis polynomials, or the polynomial interpolating values at nodes.
    #[command(after_help = "\
Nodes: distinct, in any order (the lecture notes' Příklad 1 takes 0, 1/2, 1/4, 1).
Layout: without --points, result is k×(m+1): row = parameter, column = L_0..L_m (in the order of
the nodes given). With --points (d×(m+1), one column per node), result is d×k, the interpolant
at each t. --coefficients adds coefficients (row i: L_i, highest power first, the lecture notes'
G) and with --points polynomial (the interpolant's, A = X G). --linear interpolates --points
piecewise linearly instead (the lecture notes' linear interpolation; increasing nodes).

Examples:
  cagd lagrange --nodes \"[0 0.5 1]\" --t 0.25 --exact
  cagd lagrange --nodes 1:5 --points \"[1 2 3 2 1]\" --t 1:0.5:5")]
    Lagrange(lagrange::LagrangeCommand),
    /// Bernstein polynomial values B_i^n(t).
    #[command(after_help = "\
Layout: t is k×1, result k×(n+1) (row = parameter, column = B_0^n..B_n^n), or k×1 with --i.
--plot draws the polynomials over [0, 1].

Examples:
  cagd bernstein --degree 3 --t 0.5 --exact
  cagd bernstein --degree 3 --i 1 --n 5")]
    Bernstein(bezier::BernsteinCommand),
    /// Control points (and values) of the r-th derivative of a Bézier curve.
    #[command(after_help = "\
Layout: control is d×(n-r+1), the points n!/(n-r)! Δ^r b_i as columns; with --t, result is d×k.

Example:
  cagd derivative \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'\" --order 1 --t 0.5 --exact")]
    Derivative(bezier::DerivativeCommand),
    /// An interpolating cubic spline (the lecture notes): tangents at the points and curve samples.
    #[command(after_help = "\
Input: points as columns (rows with --rows); --end clamped (with --start-tangent and
--end-tangent; the default when both are given), natural or closed (a tangent with natural or
closed is an error). --params uniform (t_k = k, the lecture notes: segment k over [k, k+1]),
chord, centripetal or a list of values. A closed spline is periodic: every t is on the curve.
Layout: tangents is d×m (one per point); result d×k at --t (default: 10 samples per segment).
--steps prints params, the linear system (system, m×m, and rhs, d×m: system · tangentsᵀ = rhsᵀ,
as the lecture notes write it) and each segment's hermite data [x_k x_(k+1) h·x'_k h·x'_(k+1)]
and bezier control points.

Example:
  cagd spline \"[0 0; 2 1; 4 4; 6 0]'\" --end clamped --start-tangent \"[1;1]\" --end-tangent \"[-1;1]\" --exact")]
    Spline(course::SplineCommand),
    /// A Hermite (Ferguson) cubic from end points and end tangents (the lecture notes).
    #[command(after_help = "\
Layout: result d×k at the parameters; --steps prints the Hermite basis values and the Bézier
control points of the same cubic.

Example:
  cagd hermite --p0 \"[0;0]\" --p1 \"[1;0]\" --t0 \"[1;1]\" --t1 \"[1;-1]\" --t 0.5 --exact")]
    Hermite(course::HermiteCommand),
    /// A B-spline curve by de Boor's algorithm (the CAD notes and the lecture notes).
    #[command(after_help = "\
Input: control points as columns, --degree p or --order k = p + 1 (as the lecture notes
count), --knots (n+p+2 values; default clamped uniform). --n samples the knot domain.
Layout: result d×k at the parameters; --steps prints the basis functions N_i,p(t) (k×(n+1)) and
the de Boor scheme of each t (span, α's and levels d0..dp).

Example:
  cagd bspline \"[0 0; 1 2; 3 2; 4 0]'\" --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --t 0.25 --steps --exact")]
    #[command(mut_arg("n", |a| a.help("Sample the knot domain [u_p, u_n] (not [0, 1]) at N equally spaced parameters")))]
    Bspline(course::BSplineCommand),
    /// A NURBS curve (the CAD notes): rational B-spline with weights.
    #[command(after_help = "\
Input: control points as columns, --weights (one per point, positive), --degree (or --order),
--knots.
Layout: result d×k; --steps prints the rational basis functions R_i,p(t).

Example (a quarter circle):
  cagd nurbs \"[1 0; 1 1; 0 1]'\" --weights \"[1 0.7071067811865476 1]\" --degree 2 --n 5")]
    #[command(mut_arg("n", |a| a.help("Sample the knot domain [u_p, u_n] (not [0, 1]) at N equally spaced parameters")))]
    Nurbs(course::NurbsCommand),
    /// Convert a curve between Hermite, Bézier, B-spline, monomial and algebraic forms.
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
    Convert(convert::ConvertCommand),
    /// Raise the degree of a Bézier curve (or of a clamped B-spline curve) without changing it.
    #[command(after_help = "\
Input: control points as columns (rows with --rows); --by R. A Bézier curve, or a B-spline with
--degree/--order and --knots (clamped: first and last knot p+1 times; default clamped uniform).
Layout: control is d×(n+R+1); for a B-spline also knots (each distinct knot R times more, as
octave-nurbs nrbdegelev). --steps prints every intermediate Bézier polygon
b'_i = i/(n+1)·b_(i-1) + (1 − i/(n+1))·b_i.

Examples:
  cagd elevate \"[0 0; 1 2; 3 2; 4 0]\" --rows --by 1 --steps --exact
  cagd elevate \"[0 0; 1 2; 3 2; 4 0]\" --rows --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --by 1 --exact")]
    Elevate(elevate::ElevateCommand),
    /// Split a Bézier curve at t into two Bézier curves (de Casteljau subdivision).
    #[command(after_help = "\
Input: control points as columns (rows with --rows); --t (default the middle of the interval).
Layout: left and right are d×(n+1), the control polygons of the parts before and after t.
--steps prints the de Casteljau scheme with the two polygons marked: L on the diagonal
b_0^r (left part), R on the last row b_(n-r)^r (right part).

Example:
  cagd subdivide \"[0 0 0; 0 2 2; 8 2 0; 4 0 0]'\" --t 0.5 --steps --exact")]
    Subdivide(subdivide::SubdivideCommand),
    /// Insert knots into a B-spline or NURBS curve (Boehm's algorithm).
    #[command(after_help = "\
Input: control points as columns (rows with --rows), --degree P (or --order K), --knots
(default clamped uniform), --insert the knots to add (strictly inside the domain); --weights for
a NURBS curve (the homogeneous points (w P, w) are refined).
Layout: knots 1×(n+p+1+r) and control d×(n+r) (weights 1×(n+r) for NURBS). --steps prints each
insertion: the span k, α_i = (u − u_i)/(u_(i+p) − u_i) for i = k−p+1..k, and the new polygon.

Example:
  cagd insert-knot \"[0 0; 1 2; 3 2; 4 0]\" --rows --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --insert 0.25 --steps --exact")]
    InsertKnot(insert_knot::InsertKnotCommand),
    /// B-spline basis functions N_i,p(u) of a knot vector (Cox–de Boor).
    #[command(after_help = "\
Input: --knots u_0..u_m, --degree P (or --order K = P + 1, as the lecture notes count); --t in
[u_0, u_m], or --n samples of it.
Layout: t is k×1, result k×n (row = parameter, column = N_0,p..N_(n-1),p, n = m − p). --steps
prints the Cox–de Boor triangle N_i,j(t) for j = 0..p (triangle.p0 … triangle.pP). --plot draws
the functions.

Examples:
  cagd bspline-basis --knots \"[0 0 0 1 2 3 3 3]\" --degree 2 --t 1.5 --steps --exact
  cagd bspline-basis --knots 0:7 --order 4 --n 50 --plot basis.svg")]
    #[command(mut_arg("n", |a| a.help("Sample the whole knot range [u_0, u_m] at N equally spaced parameters")))]
    BsplineBasis(bspline_basis::BSplineBasisCommand),
    /// Continuity (C0, C1, G1, C2) where two Bézier curves join; the free point of a C1 joint.
    #[command(after_help = "\
Input: FIRST (ends at u = 1) and SECOND (starts at v = 0), Bézier control points as columns
(rows with --rows). With --free-point the second-to-last point of FIRST is unknown and left out:
the line x_(n-1)(k) = x_n + k·(m/n)(y_0 − y_1) of points giving x'(1) = k·¹x'(0) is printed
(k = 1: C1; k > 0: G1, which the lecture notes call C1), and the joint with k = --k (default 1).
Layout: end, start (x(1), ¹x(0)), d_end, d_start (first derivatives), dd_end, dd_start
(second), k if the tangents are parallel, continuity (1 = holds), verdict (the comparison);
--steps adds each curve's control points and derivative polygons (first.d1, first.d2, …).

Examples:
  cagd continuity \"[2 3 4; 3 1 5; 3 4 3]\" \"[3 4 3; 2 6 0; 5 7 5; 5 2 3]\" --rows --free-point --exact
  cagd continuity \"[0 0; 1 1; 2 1]'\" \"[2 1; 3 1; 4 0]'\" --exact")]
    Continuity(continuity::ContinuityCommand),
    /// Antiderivative and definite integral of Bernstein polynomials, Bézier or B-spline curves.
    #[command(after_help = "\
Input: Bézier control points as columns (rows with --rows) over [0, 1] or --interval a,b; with
--degree/--order and --knots a B-spline; or --bernstein N [--i I] alone.
Layout: antiderivative holds the control points of ∫ (d×(n+2); a B-spline's with its knots,
(u_0, u_0, …, u_m, u_m)); integral the definite integral over the domain (d×1); with --t, result
holds ∫ from the start of the domain to t. Bernstein: rows of Bernstein coefficients of degree
N+1 of ∫₀ᵗ B_i^N, and ∫₀¹ B_i^N = 1/(N+1).

Examples:
  cagd integrate \"[0 0; 1 2; 2 0]\" --rows --exact
  cagd integrate --bernstein 3 --exact
  cagd integrate \"[6 0 0 0]\" --degree 2 --knots \"[0 0 0 0.5 1 1 1]\" --exact")]
    Integrate(integrate::IntegrateCommand),
    /// The ruled surface (1 − v)·¹x(u) + v·²x(u) between two curves (the lecture notes).
    #[command(after_help = "\
Input: --first ¹x(u) and --second ²x(u): expressions in u such as \"[u;0;u-u^2]\", or Bézier
control points (columns; rows with --rows).
Layout: single --u and --v give the d×1 point; otherwise the grid nu×nv×d (like P), or with
--list one row u v x y z per point. --steps prints both curves at the u's.

Examples:
  cagd ruled --first \"[u;0;0]\" --second \"[u;1;u-u^2]\" --u 0.5 --v 0.25 --exact
  cagd ruled --first \"[0 0 0; 1 0 1; 2 0 0]'\" --second \"[0 1 1; 2 1 1]'\" --n 10 --plot ruled.png")]
    Ruled(ruled::RuledCommand),
    /// The Hermite bicubic (Ferguson) patch from corner points, tangents and twists.
    #[command(after_help = "\
Input: --points, --du, --dv, --twists (default zero: the F-patch): d×4 matrices whose columns
are the vectors at the corners (u,v) = (0,0), (1,0), (0,1), (1,1) (rows with --rows).
Layout: single --u and --v give the d×1 point; otherwise the grid nu×nv×d, or --list. --steps
prints the geometry matrices G (one per coordinate, rows x(0,·) x(1,·) x_u(0,·) x_u(1,·),
columns x(·,0) x(·,1) x_v(·,0) x_v(·,1)): x(u,v) = f(u)ᵀ G f(v) with the Hermite basis f. The
lecture notes write vᵀ M_Hᵀ X_H M_H u with X_H = Gᵀ.

Example (z = uv):
  cagd ferguson --points \"[0 0 0; 1 0 0; 0 1 0; 1 1 1]'\" --du \"[1 0 0; 1 0 0; 1 0 1; 1 0 1]'\" \\
                --dv \"[0 1 0; 0 1 1; 0 1 0; 0 1 1]'\" --twists \"[0 0 1; 0 0 1; 0 0 1; 0 0 1]'\" --u 0.5 --v 0.25 --exact")]
    Ferguson(ferguson::FergusonCommand),
    /// A tensor-product B-spline surface (the CAD notes, the lecture notes).
    #[command(after_help = "\
Input: the control net packed (m+1)×3(n+1) as for bezier-patch, an Octave (m+1)×(n+1)×3 array
file, or an Octave save -text file with an octave-nurbs nrbmak struct (weights all 1);
--degree P or P,Q (or --order), --uknots and --vknots (default clamped uniform).
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3, or --list. Parameters
default to --n samples of the domain; outside it the surface is not defined (an error). --steps
prints the knots and the basis values N_i,p(u), N_j,q(v).

Example:
  cagd bspline-surface net.txt --degree 2 --n 20 --plot surface.png --mesh surface.stl")]
    BsplineSurface(bspline_surface::BSplineSurfaceCommand),
    /// A tensor-product NURBS surface (the CAD notes): weights and homogeneous points.
    #[command(after_help = "\
Input: as for bspline-surface, with --weights (an (m+1)×(n+1) matrix of positive weights), or
an Octave save -text file with an octave-nurbs nrbmak struct (coefs 4×nu×nv homogeneous
[w·x; w·y; w·z; w], knots {ku, kv}, order) — e.g. from Octave: srf = nrbmak(coefs, {ku, kv});
save -text srf.txt srf.
Layout: as for bspline-surface.

Example:
  cagd nurbs-surface srf.txt --n 20 --plot srf.png")]
    NurbsSurface(nurbs_surface::NurbsSurfaceCommand),
    /// A circle as an exact NURBS curve (octave-nurbs nrbcirc).
    #[command(after_help = "\
Input: --radius (default 1), --center (2 or 3 coordinates, default [0 0]).
Layout: knots, control (d×9: four quarter arcs), weights (1 and √2/2), and the points at --t
(default --n 11 samples of [0, 1]). --steps prints the homogeneous coefficients (w·x, w·y, w),
as octave-nurbs stores them.

Example:
  cagd circle --radius 2 --center \"[1 -1]\" --n 9 --plot circle.svg")]
    Circle(circle::CircleCommand),
    /// A circular arc as an exact NURBS curve (octave-nurbs nrbcirc with angles).
    #[command(after_help = "\
Input: as for circle, with --start and --end angles in radians (expressions such as pi/2).
Layout: as for circle; 1 to 4 rational quadratic pieces of at most 90° each.

Example:
  cagd arc --radius 1 --start 0 --end pi/2 --n 5")]
    Arc(circle::ArcCommand),
    /// Sample a curve given as an expression in its parameter, as the thesis writes curves.
    #[command(after_help = "\
Layout: the result is d × k, one point per column (like T in the thesis's deCasteljau).

Examples:
  cagd curve \"[u; 0; u-u^2]\" --n 5
  cagd curve \"[u; 0.5; 0.5+u-u^2]\" --t \"[0 0.25 0.5]\" --exact
  cagd curve \"[cos(2*pi*t); sin(2*pi*t)]\" --n 50 --plot circle.svg")]
    Curve(CurveCommand),
    /// Sample a surface given as an expression in u and v on a grid.
    #[command(after_help = "\
Layout: the result is a grid of shape (nu, nv, d): result(i,j,:) is the point at (u(i), v(j)),
like P in the thesis's ploskevB.

Examples:
  cagd surface \"[u; v; u.*v]\" --n 3
  cagd surface \"[u; v; u-u^2+v]\" --n 20 --plot patch.png --mesh patch.stl")]
    Surface(SurfaceCommand),
    /// Serve the web page (every construction, in the browser) on localhost.
    #[command(after_help = "\
Serves the page built by `bash web/build.sh` (web/dist/) on http://127.0.0.1:P/ until stopped
with Ctrl-C; the page computes in the browser, the server only hands out its files. A link
such as http://127.0.0.1:8000/#cmd=cagd%20bernstein%20--degree%203%20--t%200.5 opens the page
with that command run.

Examples:
  cagd serve
  cagd serve --port 8080 --dir web/dist")]
    Serve(crate::serve::ServeCommand),
    /// Run a thesis-style Octave data script and print the variables it defines.
    #[command(after_help = "\
Scripts may contain assignments, indexed assignments x(i) = ..., for loops, comments and
continuations. Right-hand sides that use u, v or t without defining them are kept as curves
in that parameter (appendix C: c1 = [u;0;u-u^2]).

Examples:
  cagd script data.m --n 10
  cagd script data.m --format json")]
    Script(ScriptCommand),
}

#[derive(Debug, Args)]
struct CurveCommand {
    /// The curve: an expression in one parameter t, u or v, e.g. "[u; 0; u-u^2]".
    #[arg(value_name = "EXPR", allow_hyphen_values = true)]
    expr: String,
    #[command(flatten)]
    params: CurveParamArgs,
    #[command(flatten)]
    script: ScriptArgs,
    #[command(flatten)]
    output: OutputArgs,
    #[command(flatten)]
    plot: PlotArgs,
}

#[derive(Debug, Args)]
struct SurfaceCommand {
    /// The surface: an expression in u and v, e.g. "[u; v; u.*v]".
    #[arg(value_name = "EXPR", allow_hyphen_values = true)]
    expr: String,
    #[command(flatten)]
    params: SurfaceParamArgs,
    #[command(flatten)]
    script: ScriptArgs,
    #[command(flatten)]
    output: OutputArgs,
    #[command(flatten)]
    plot: PlotArgs,
    #[command(flatten)]
    mesh: MeshArgs,
}

#[derive(Debug, Args)]
struct ScriptCommand {
    /// The Octave data script, or - for standard input.
    #[arg(value_name = "FILE")]
    file: String,
    /// Bind N (used by the thesis scripts, e.g. u = linspace(0,1,N)) before running.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    n: Option<usize>,
    #[command(flatten)]
    output: OutputArgs,
}

use common::DEFAULT_SAMPLES;
pub use outcome::Outcome;

/// Parses `args` (the program name first, as `std::env::args_os` gives them) and runs the
/// subcommand. Nothing is written: the files are returned staged in the [`Outcome`].
pub fn run<I, A>(args: I) -> Result<Outcome, CliError>
where
    I: IntoIterator<Item = A>,
    A: Into<OsString> + Clone,
{
    let matches = match Cli::command().try_get_matches_from(args) {
        Ok(m) => m,
        Err(e) => return usage_error(e),
    };
    // Output targets are checked before any work (and before the limits, which may fail).
    crate::outputs::check(&matches)?;
    let cli = match Cli::from_arg_matches(&matches) {
        Ok(cli) => cli,
        Err(e) => return usage_error(e),
    };
    let limits = &cli.limits.resolve()?;
    crate::slips::take();
    let outcome = dispatch(limits, &cli.command).map_err(|e| {
        // A non-finite result is about the command's input (see `common::finish`).
        if e.argument == common::RESULT {
            let (name, input) = cli.command.input();
            CliError {
                argument: input.to_string(),
                problem: e
                    .problem
                    .replacen("the result", &format!("the {name} result"), 1),
                ..e
            }
        } else {
            e
        }
    });
    // The slips noticed while reading the input come first; each warning is printed once.
    let mut warnings = crate::slips::take();
    let mut outcome = outcome?;
    warnings.append(&mut outcome.warnings);
    outcome.warnings = crate::slips::dedup(warnings);
    Ok(outcome)
}

impl Command {
    /// The subcommand's name and the input its result is computed from.
    fn input(&self) -> (&'static str, &'static str) {
        match self {
            Command::Thesis(_) => ("thesis", "thesis"),
            Command::Decasteljau(_) => ("decasteljau", "CONTROL"),
            Command::BezierPatch(_) => ("bezier-patch", "NET"),
            Command::Coons(_) => ("coons", "--c1/--c2/--d1/--d2"),
            Command::CoonsBicubic(_) => ("coons-bicubic", "--c1/--c2/--d1/--d2"),
            Command::DiscreteCoons(_) => ("discrete-coons", "NET"),
            Command::Gordon(_) => ("gordon", "--u-curve/--v-curve"),
            Command::Lagrange(_) => ("lagrange", "--nodes/--points"),
            Command::Bernstein(_) => ("bernstein", "--degree"),
            Command::Derivative(_) => ("derivative", "CONTROL"),
            Command::Spline(_) => ("spline", "POINTS"),
            Command::Hermite(_) => ("hermite", "--p0/--p1/--t0/--t1"),
            Command::Bspline(_) => ("bspline", "CONTROL"),
            Command::Nurbs(_) => ("nurbs", "CONTROL"),
            Command::Curve(_) => ("curve", "EXPR"),
            Command::Surface(_) => ("surface", "EXPR"),
            Command::Script(_) => ("script", "FILE"),
            Command::Serve(_) => ("serve", "--dir"),
            Command::Course(_) => ("course", "course"),
            Command::Convert(_) => ("convert", "GEOMETRY"),
            Command::Elevate(_) => ("elevate", "CONTROL"),
            Command::Subdivide(_) => ("subdivide", "CONTROL"),
            Command::InsertKnot(_) => ("insert-knot", "CONTROL"),
            Command::BsplineBasis(_) => ("bspline-basis", "--knots"),
            Command::Continuity(_) => ("continuity", "FIRST/SECOND"),
            Command::Integrate(_) => ("integrate", "CONTROL"),
            Command::Ruled(_) => ("ruled", "--first/--second"),
            Command::Ferguson(_) => ("ferguson", "--points"),
            Command::BsplineSurface(_) => ("bspline-surface", "NET"),
            Command::NurbsSurface(_) => ("nurbs-surface", "NET"),
            Command::Circle(_) => ("circle", "--radius"),
            Command::Arc(_) => ("arc", "--radius"),
        }
    }
}

/// Runs the subcommand, in `f64` or with `--exact` in rationals.
fn dispatch(limits: &Limits, command: &Command) -> Result<Outcome, CliError> {
    match command {
        Command::Curve(c) if c.output.exact => curve::<BigRational>(limits, c),
        Command::Curve(c) => curve::<f64>(limits, c),
        Command::Surface(c) if c.output.exact => surface::<BigRational>(limits, c),
        Command::Surface(c) => surface::<f64>(limits, c),
        Command::Script(c) if c.output.exact => script::<BigRational>(limits, c),
        Command::Script(c) => script::<f64>(limits, c),
        Command::Thesis(c) => thesis::thesis(limits, c),
        Command::Course(c) => course_examples::course(limits, c),
        Command::Decasteljau(c) if c.output.exact => bezier::decasteljau::<BigRational>(limits, c),
        Command::Decasteljau(c) => bezier::decasteljau::<f64>(limits, c),
        Command::BezierPatch(c) if c.output.exact => bezier::bezier_patch::<BigRational>(limits, c),
        Command::BezierPatch(c) => bezier::bezier_patch::<f64>(limits, c),
        Command::Coons(c) if c.output.exact => patches::coons::<BigRational>(limits, c),
        Command::Coons(c) => patches::coons::<f64>(limits, c),
        Command::CoonsBicubic(c) if c.output.exact => {
            patches::coons_bicubic::<BigRational>(limits, c)
        }
        Command::CoonsBicubic(c) => patches::coons_bicubic::<f64>(limits, c),
        Command::DiscreteCoons(c) if c.output.exact => patches::discrete::<BigRational>(limits, c),
        Command::DiscreteCoons(c) => patches::discrete::<f64>(limits, c),
        Command::Gordon(c) if c.output.exact => patches::gordon::<BigRational>(limits, c),
        Command::Gordon(c) => patches::gordon::<f64>(limits, c),
        Command::Lagrange(c) if c.output.exact => lagrange::lagrange::<BigRational>(limits, c),
        Command::Lagrange(c) => lagrange::lagrange::<f64>(limits, c),
        Command::Bernstein(c) if c.output.exact => bezier::bernstein::<BigRational>(limits, c),
        Command::Bernstein(c) => bezier::bernstein::<f64>(limits, c),
        Command::Derivative(c) if c.output.exact => bezier::derivative::<BigRational>(limits, c),
        Command::Derivative(c) => bezier::derivative::<f64>(limits, c),
        Command::Spline(c) if c.output.exact => course::spline::<BigRational>(limits, c),
        Command::Spline(c) => course::spline::<f64>(limits, c),
        Command::Hermite(c) if c.output.exact => course::hermite::<BigRational>(limits, c),
        Command::Hermite(c) => course::hermite::<f64>(limits, c),
        Command::Bspline(c) if c.output.exact => course::bspline::<BigRational>(limits, c),
        Command::Bspline(c) => course::bspline::<f64>(limits, c),
        Command::Nurbs(c) if c.output.exact => course::nurbs::<BigRational>(limits, c),
        Command::Nurbs(c) => course::nurbs::<f64>(limits, c),
        Command::Convert(c) if c.output.exact => convert::convert::<BigRational>(limits, c),
        Command::Convert(c) => convert::convert::<f64>(limits, c),
        Command::Elevate(c) if c.output.exact => elevate::elevate::<BigRational>(limits, c),
        Command::Elevate(c) => elevate::elevate::<f64>(limits, c),
        Command::Subdivide(c) if c.output.exact => subdivide::subdivide::<BigRational>(limits, c),
        Command::Subdivide(c) => subdivide::subdivide::<f64>(limits, c),
        Command::InsertKnot(c) if c.output.exact => {
            insert_knot::insert_knot::<BigRational>(limits, c)
        }
        Command::InsertKnot(c) => insert_knot::insert_knot::<f64>(limits, c),
        Command::BsplineBasis(c) if c.output.exact => {
            bspline_basis::bspline_basis::<BigRational>(limits, c)
        }
        Command::BsplineBasis(c) => bspline_basis::bspline_basis::<f64>(limits, c),
        Command::Continuity(c) if c.output.exact => {
            continuity::continuity::<BigRational>(limits, c)
        }
        Command::Continuity(c) => continuity::continuity::<f64>(limits, c),
        Command::Integrate(c) if c.output.exact => integrate::integrate::<BigRational>(limits, c),
        Command::Integrate(c) => integrate::integrate::<f64>(limits, c),
        Command::Ruled(c) if c.output.exact => ruled::ruled::<BigRational>(limits, c),
        Command::Ruled(c) => ruled::ruled::<f64>(limits, c),
        Command::Ferguson(c) if c.output.exact => ferguson::ferguson::<BigRational>(limits, c),
        Command::Ferguson(c) => ferguson::ferguson::<f64>(limits, c),
        Command::BsplineSurface(c) if c.args.output.exact => {
            bspline_surface::bspline_surface::<BigRational>(limits, c)
        }
        Command::BsplineSurface(c) => bspline_surface::bspline_surface::<f64>(limits, c),
        Command::NurbsSurface(c) if c.args.output.exact => {
            nurbs_surface::nurbs_surface::<BigRational>(limits, c)
        }
        Command::NurbsSurface(c) => nurbs_surface::nurbs_surface::<f64>(limits, c),
        Command::Circle(c) => circle::circle(limits, c),
        Command::Arc(c) => circle::arc(limits, c),
        Command::Serve(_) => Err(CliError::new(
            "serve",
            "serving the page is done by the cagd program itself, not in-process",
            "`cagd serve` typed in a terminal",
            ErrorKind::Unsupported,
        )),
    }
}

/// The names of the subcommands, in the order of `cagd --help` (without clap's `help`).
pub fn subcommands() -> Vec<String> {
    Cli::command()
        .get_subcommands()
        .map(|s| s.get_name().to_string())
        .collect()
}

/// The `serve` subcommand, if `args` (the program name first) ask for it and parse; anything
/// else, including errors and `--help`, is left to [`run`].
pub fn serve_request<I, A>(args: I) -> Option<crate::serve::ServeCommand>
where
    I: IntoIterator<Item = A>,
    A: Into<OsString> + Clone,
{
    match Cli::try_parse_from(args) {
        Ok(Cli {
            command: Command::Serve(c),
            ..
        }) => Some(c),
        _ => None,
    }
}

/// Runs `--script` if given, binding `N` first.
pub fn prepare_script<T: LiteralScalar>(
    limits: &Limits,
    script: &ScriptArgs,
    n: Option<usize>,
) -> Result<Option<Script<T>>, CliError> {
    let Some(path) = &script.script else {
        return Ok(None);
    };
    let mut env = Env::with_limits(*limits);
    if let Some(n) = n {
        env.bind_scalar("N", T::from_usize(n));
    }
    load_script(limits, "--script", path, env).map(Some)
}

fn script_warnings<T: LiteralScalar>(
    script: &ScriptArgs,
    loaded: Option<&Script<T>>,
) -> Vec<(String, Warning)> {
    match (&script.script, loaded) {
        (Some(path), Some(s)) => s
            .warnings()
            .into_iter()
            .map(|w| (format!("--script {path}"), w))
            .collect(),
        _ => Vec::new(),
    }
}

fn to_f64_matrix<T: LiteralScalar>(m: &DMatrix<T>) -> DMatrix<f64> {
    m.map(|x| x.to_f64())
}

fn curve<T: LiteralScalar>(limits: &Limits, cmd: &CurveCommand) -> Result<Outcome, CliError> {
    let loaded = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let expr = load_expression(limits, "EXPR", &cmd.expr, loaded.as_ref())?;
    let mut env = loaded.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let params = expr.parameters(&env);
    let param = match params.as_slice() {
        [] => "t",
        [p] => p,
        _ => {
            return Err(CliError::new(
                "EXPR",
                format!(
                    "`{}` uses the parameters {}",
                    cmd.expr.trim(),
                    params.join(" and ")
                ),
                "a curve in one parameter (t, u or v); use `cagd surface` for u and v",
                ErrorKind::Shape,
            ))
        }
    };
    let values: Vec<T> = match (&cmd.params.t, cmd.params.n) {
        (Some(t), _) => load_params(limits, "--t", t)?,
        (None, n) => samples(limits, n.unwrap_or(DEFAULT_SAMPLES), 2)?,
    };
    work::check_expression_work(
        limits,
        &[work::Sampling {
            argument: "EXPR",
            expr: &expr,
            params: vec![(param, &values)],
        }],
        &env,
    )?;
    let points = expr
        .sample_curve(&mut env, param, &values)
        .map_err(|e| CliError::literal("EXPR", e, CURVE_FORM))?;
    let mut report = Report::new();
    report.push(
        param,
        Value::Matrix(DMatrix::from_row_slice(1, values.len(), &values)),
    );
    report.push("result", Value::Matrix(points.clone()));
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let figure = Figure::new(format!("curve {}", cmd.expr.trim())).curve(
            to_f64_matrix(&points),
            Colour::Blue,
            format!("{param} ↦ {}", cmd.expr.trim()),
        );
        common::add_plot(&mut files, "--plot", path, &figure)?;
    }
    let mut warnings = script_warnings(&cmd.script, loaded.as_ref());
    warnings.extend(env.take_warnings().into_iter().map(|w| ("EXPR".into(), w)));
    common::finish(&report, &cmd.output, files, warnings)
}

fn surface<T: LiteralScalar>(limits: &Limits, cmd: &SurfaceCommand) -> Result<Outcome, CliError> {
    let loaded = prepare_script::<T>(limits, &cmd.script, cmd.params.n)?;
    let expr = load_expression(limits, "EXPR", &cmd.expr, loaded.as_ref())?;
    let mut env = loaded.as_ref().map(|s| s.env().clone()).unwrap_or_default();
    let grid_samples = |given: &Option<String>, name: &str| -> Result<Vec<T>, CliError> {
        match given {
            Some(text) => load_params(limits, name, text),
            None => samples(limits, cmd.params.n.unwrap_or(DEFAULT_SAMPLES), 2),
        }
    };
    let us = grid_samples(&cmd.params.u, "--u")?;
    let vs = grid_samples(&cmd.params.v, "--v")?;
    common::check_grid(limits, us.len(), vs.len())?;
    work::check_expression_work(
        limits,
        &[work::Sampling {
            argument: "EXPR",
            expr: &expr,
            params: vec![("u", &us), ("v", &vs)],
        }],
        &env,
    )?;
    let grid = expr.sample_surface(&mut env, &us, &vs).map_err(|e| {
        CliError::literal(
            "EXPR",
            e,
            "an expression in u and v such as \"[u; v; u.*v]\"",
        )
    })?;
    let mut report = Report::new();
    report.push(
        "u",
        Value::Matrix(DMatrix::from_row_slice(1, us.len(), &us)),
    );
    report.push(
        "v",
        Value::Matrix(DMatrix::from_row_slice(1, vs.len(), &vs)),
    );
    let grid_f64: PointGrid<f64> = grid.map(|x| x.to_f64());
    common::push_surface(&mut report, "result", (&us, &vs), grid, cmd.params.list);
    let mut files = PendingWrites::new();
    if let Some(path) = &cmd.plot.plot {
        let figure = Figure::new(format!("surface {}", cmd.expr.trim()))
            .surface(grid_f64.clone(), "surface");
        common::add_plot(&mut files, "--plot", path, &figure)?;
    }
    if let Some(path) = &cmd.mesh.mesh {
        common::add_mesh(&mut files, "--mesh", path, &grid_f64)?;
    }
    let mut warnings = script_warnings(&cmd.script, loaded.as_ref());
    warnings.extend(env.take_warnings().into_iter().map(|w| ("EXPR".into(), w)));
    common::finish(&report, &cmd.output, files, warnings)
}

fn script<T: LiteralScalar>(limits: &Limits, cmd: &ScriptCommand) -> Result<Outcome, CliError> {
    let args = ScriptArgs {
        script: Some(cmd.file.clone()),
    };
    let loaded = prepare_script::<T>(limits, &args, cmd.n)?
        .ok_or_else(|| CliError::new("FILE", "no script", "a script file", ErrorKind::Internal))?;
    let mut report = Report::new();
    for name in loaded.names() {
        match loaded.get(name) {
            Some(Binding::Value(m)) => {
                report.push(name, Value::Matrix(m.clone()));
            }
            Some(Binding::Function(f)) => {
                let params = f.parameters(loaded.env());
                report.push(
                    name,
                    Value::Text(format!(
                        "{}    (expression in {})",
                        f.source(),
                        params.join(", ")
                    )),
                );
            }
            None => {}
        }
    }
    let warnings = loaded
        .warnings()
        .into_iter()
        .map(|w| (cmd.file.clone(), w))
        .collect();
    common::finish(&report, &cmd.output, PendingWrites::new(), warnings)
}

/// Turns a clap error into the one-line form (help and version are printed as a result).
fn usage_error(e: clap::Error) -> Result<Outcome, CliError> {
    if matches!(e.kind(), ClapKind::DisplayHelp | ClapKind::DisplayVersion) {
        return Ok(Outcome {
            stdout: e.render().to_string(),
            files: PendingWrites::new(),
            warnings: Vec::new(),
        });
    }
    let context = |k: ContextKind| e.get(k).map(|v| v.to_string());
    // Clap names an option with its value placeholder (`--format <FORMAT>`); keep the name.
    let strip = |s: String| -> String {
        s.split(", ")
            .map(|a| a.split_whitespace().next().unwrap_or(a))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let arg = context(ContextKind::InvalidArg)
        .map(strip)
        .unwrap_or_else(|| "cagd".into());
    let value = context(ContextKind::InvalidValue).unwrap_or_default();
    let subcommands = subcommands().join(", ");
    let (argument, problem, expected) = match e.kind() {
        ClapKind::InvalidValue => (
            arg,
            format!("invalid value '{value}'"),
            context(ContextKind::ValidValue)
                .map(|v| format!("one of {v}"))
                .unwrap_or_else(|| "a value".into()),
        ),
        ClapKind::ValueValidation => {
            let reason = std::error::Error::source(&e)
                .map(|s| s.to_string())
                .unwrap_or_default();
            let expected = if reason.contains("digit") || reason.contains("empty string") {
                "a whole number such as 10".to_string()
            } else {
                "a value of the form shown by --help".to_string()
            };
            let reason = if reason.is_empty() {
                reason
            } else {
                format!(" ({reason})")
            };
            (arg, format!("invalid value '{value}'{reason}"), expected)
        }
        ClapKind::UnknownArgument => (
            arg,
            "unknown option".into(),
            context(ContextKind::SuggestedArg)
                .map(|s| format!("{s} perhaps, or an option listed by --help"))
                .unwrap_or_else(|| "an option listed by --help".into()),
        ),
        ClapKind::InvalidSubcommand => (
            context(ContextKind::InvalidSubcommand).unwrap_or(value),
            "unknown subcommand".into(),
            format!("one of {subcommands}"),
        ),
        ClapKind::MissingSubcommand | ClapKind::DisplayHelpOnMissingArgumentOrSubcommand => (
            "cagd".into(),
            "no subcommand given".into(),
            format!("one of {subcommands} (see cagd --help)"),
        ),
        ClapKind::MissingRequiredArgument => {
            (arg, "missing".into(), "the argument (see --help)".into())
        }
        ClapKind::ArgumentConflict
            if context(ContextKind::PriorArg).map(strip).as_deref() == Some(arg.as_str()) =>
        {
            (arg, "given more than once".into(), "the option once".into())
        }
        ClapKind::ArgumentConflict => (
            arg,
            format!(
                "cannot be used together with {}",
                context(ContextKind::PriorArg)
                    .map(strip)
                    .unwrap_or_else(|| "another option".into())
            ),
            "only one of them".into(),
        ),
        _ => {
            let rendered = e.render().to_string();
            let first = rendered
                .lines()
                .next()
                .unwrap_or("invalid arguments")
                .trim_start_matches("error: ")
                .to_string();
            ("cagd".into(), first, "arguments as listed by --help".into())
        }
    };
    Err(CliError::new(argument, problem, expected, ErrorKind::Usage))
}

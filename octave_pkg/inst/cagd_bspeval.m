## -*- texinfo -*-
## @deftypefn {} {@var{p} =} cagd_bspeval (@var{d}, @var{c}, @var{k}, @var{u})
## Evaluate a B-spline at parametric points: octave-nurbs' @code{bspeval}, argument for
## argument.
##
## @var{d} is the degree, @var{c} the control points @math{mc × nc} (one per column, any
## number of rows), @var{k} the knot vector (@math{nc + d + 1} knots), @var{u} the
## parameters (any size, any real numeric class).  @var{p} is @math{mc × numel (u)}, double.
## The sums are those of @code{bspeval} (its knot span, the triangular basis of The NURBS
## Book A2.2, then @math{Σ_i N_i c_i}, @math{i} ascending): the values agree bit for bit.
##
## As @code{bspeval}, it takes any parameter in @math{[k(1), k(end)]}: past the last knot
## of the domain the last span continues, an empty last span gives NaN, a NaN parameter
## gives NaN; a parameter outside the knots is an error.  @var{c} and @var{k} may be double
## or single, full or sparse; @var{d} is truncated toward zero.
##
## Differences from octave-nurbs 1.4.3: where @code{bspeval} reads before its arrays (a
## parameter below @math{k(d+1)} of a knot vector not clamped at its start, where it returns
## whatever memory lies there) this gives the B-spline's value, the sum over the basis
## functions that exist; called with no output it returns @code{ans} (@code{bspeval} prints
## its usage).  Errors carry the identifiers @code{cagd:domain}, @code{cagd:value},
## @code{cagd:class}.
##
## Example:
## @example
## @group
## cagd_bspeval (2, [0 1 2; 0 2 0], [0 0 0 1 1 1], [0 0.5 1])
##   @result{} [0 1 2; 0 1 0]
## @end group
## @end example
## @seealso{cagd_nrbeval, cagd_basisfun, cagd_findspan, cagd_bspline}
## @end deftypefn

function p = cagd_bspeval (varargin)
  p = __cagd__ ("cagd_bspeval", varargin{:});
endfunction

%!assert (cagd_bspeval (2, [0 1 2; 0 2 0], [0 0 0 1 1 1], [0 0.5 1]), [0 1 2; 0 1 0])
%!test
%! ## octave-nurbs 1.4.3: bspeval (2, [0 1 2 3], [0 0 0 .5 1 1 1], [0 .5; .7 1]) = [0 1.98 1.5 3]
%! p = cagd_bspeval (2, [0 1 2 3], [0 0 0 .5 1 1 1], [0 .5; .7 1]);
%! assert (p, [0 1.98 1.5 3], 1e-15);
%!test
%! ## Knots not clamped at the end: NaN from 0.4 on, where the last span [0.4, 0.4] is empty.
%! p = cagd_bspeval (2, [0 1 3 4 5], [0 0 0 .4 .4 .4 1 1], [0.2 0.4 0.7 1]);
%! assert (p(1), 1.25, 1e-15);
%! assert (isnan (p(2:4)));
%!test
%! ## Other classes, as bspeval takes them; NaN parameters give NaN.
%! k = [0 0 0 .5 1 1 1];
%! assert (cagd_bspeval (int8 (2), single ([0 1 2 3]), k, uint8 (1)), 3);
%! assert (isnan (cagd_bspeval (2, [0 1 2 3], k, NaN)));
%! assert (class (cagd_bspeval (2, [0 1 2 3], single (k), logical ([0 1]))), "double");
%!test
%! ## Degree 0 and a degree truncated toward zero.
%! assert (cagd_bspeval (0, [0 1 2 3], [0 1 2 3 4], [0 .5 1 1.5 3.5 4]), [0 0 1 1 3 3]);
%! assert (cagd_bspeval (2.7, [0 1 2 3], [0 0 0 .5 1 1 1], 1), 3);
%!error <outside the knots> cagd_bspeval (2, [0 1 2 3], [0 0 0 .5 1 1 1], 1.5)
%!error <inconsistent bspline data> cagd_bspeval (1, [0 1], [0 0 1], 0.5)
%!error <int32 is not accepted> cagd_bspeval (2, int32 ([0 1 2 3]), [0 0 0 .5 1 1 1], 0.5)
%!error <cagd_bspeval> cagd_bspeval (2, [0 1 2 3], [0 0 0 .5 1 1 1])

%!demo
%! ## A quadratic B-spline, its control polygon and a parameter past the end of its domain.
%! c = [0 1 3 4 5; 0 2 2 0 1]; k = [0 0 0 .3 .6 1 1 1];
%! u = linspace (0, 1, 101);
%! p = cagd_bspeval (2, c, k, u);
%! plot (c(1,:), c(2,:), "o--", p(1,:), p(2,:), "-");
%! legend ("control polygon", "cagd\\_bspeval"); axis equal;
%! title ("cagd\\_bspeval: a quadratic B-spline");

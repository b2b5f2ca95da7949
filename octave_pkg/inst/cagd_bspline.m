## -*- texinfo -*-
## @deftypefn  {} {@var{X} =} cagd_bspline (@var{p}, @var{P}, @var{U}, @var{t})
## @deftypefnx {} {@var{X} =} cagd_bspline (@dots{}, "exact")
## The B-spline curve of degree @var{p} with control points @var{P} (@math{d × n}, columns)
## and knots @var{U} (@math{n + p + 1}, non-decreasing; @code{[]} for the clamped uniform knots
## on [0, 1]) at the parameters @var{t}, which must lie in the domain
## @math{[U(p+1), U(n+1)]}.  @var{X} is @math{d × numel (t)}.  With @code{"exact"}: exact
## fractions (see @code{cagd_bezier}).  For octave-nurbs' argument order see
## @code{cagd_bspeval}.
##
## Example (a quadratic with a double knot at 1/2):
## @example
## @group
## cagd_bspline (2, [0 1 2 3], [0 0 0 0.5 1 1 1], 0.5)
##   @result{} 1.5
## @end group
## @end example
## @seealso{cagd_bspeval, cagd_nurbs}
## @end deftypefn

function X = cagd_bspline (varargin)
  X = __cagd__ ("cagd_bspline", varargin{:});
endfunction

%!assert (cagd_bspline (2, [0 1 2; 0 2 0], [], [0 0.5 1]), [0 1 2; 0 1 0])
%!assert (cagd_bspline (2, [0 1 2 3], [0 0 0 0.5 1 1 1], [0 0.5 1]), [0 1.5 3])
%!assert (cagd_bspline (2, [0 1 2 3], [0 0 0 0.5 1 1 1], 0.25, "exact"), {"7/8"})
%!assert (cagd_bspline (2, [0 1 2 3], "[0 0 0 1/3 1 1 1]", "1/3", "exact"), {"4/3"})
%!error <expected 7 knots> cagd_bspline (2, [0 1 2 3], [0 0 0 1 1 1], 0.5)
%!error <outside the domain> cagd_bspline (2, [0 1 2 3], [0 0 0 0.5 1 1 1], 1.5)
## Knots 5e-324 apart: the basis would divide by a difference that is not a double.
%!error id=cagd:overflow cagd_bspline (2, [0 1 2 3], [0 0 0 5e-324 1e-320 1e-320 1e-320], 1e-321)

%!demo
%! ## A quadratic B-spline with a double knot at 1/2 (a corner) and its control polygon.
%! P = [0 1 2 3 4; 0 2 0 2 0]; U = [0 0 0 0.5 0.5 1 1 1];
%! X = cagd_bspline (2, P, U, linspace (0, 1, 201));
%! plot (P(1,:), P(2,:), "ro--", X(1,:), X(2,:), "b-"); title ("cagd\_bspline: a double knot");

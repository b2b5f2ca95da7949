## -*- texinfo -*-
## @deftypefn  {} {@var{X} =} cagd_nurbs (@var{p}, @var{P}, @var{w}, @var{U}, @var{t})
## @deftypefnx {} {@var{X} =} cagd_nurbs (@dots{}, "exact")
## The NURBS curve of degree @var{p} with control points @var{P} (@math{d × n}, columns),
## positive weights @var{w} (@math{n} values) and knots @var{U} (@math{n + p + 1}; @code{[]}
## for the clamped uniform knots on [0, 1]) at @var{t} (in the domain):
## @math{C(t) = Σ_k w_k N_@{k,p@}(t) P_k / Σ_k w_k N_@{k,p@}(t)}.  @var{X} is
## @math{d × numel (t)}.  With @code{"exact"}: exact fractions (see @code{cagd_bezier}).
## For octave-nurbs structures see @code{cagd_nrbeval}.
##
## Example (a quarter of the unit circle):
## @example
## @group
## X = cagd_nurbs (2, [1 1 0; 0 1 1], [1 sqrt(2)/2 1], [], linspace (0, 1, 5));
## max (abs (sqrt (sum (X.^2)) - 1))
##   @result{} 1.1102e-16
## @end group
## @end example
## @seealso{cagd_nrbeval, cagd_bspline}
## @end deftypefn

function X = cagd_nurbs (varargin)
  X = __cagd__ ("cagd_nurbs", varargin{:});
endfunction

%!test
%! X = cagd_nurbs (2, [1 1 0; 0 1 1], [1 sqrt(2)/2 1], [], linspace (0, 1, 9));
%! assert (sqrt (sum (X.^2)), ones (1, 9), 2e-16);
%! assert (X(:, [1 end]), [1 0; 0 1]);
%!assert (cagd_nurbs (2, [0 1 2], [1 2 1], [], 0.5, "exact"), {"1"})
%!assert (cagd_nurbs (2, [0 1 2], [1 2 1], [], "1/3", "exact"), {"10/13"})
%!error <weight 2 is 0> cagd_nurbs (2, [0 1 2], [1 0 1], [], 0.5)
%!error <expected 3 weights> cagd_nurbs (2, [0 1 2], [1 1], [], 0.5)
## Weights all 5e-324 are scaled exactly (a NURBS does not change when all its weights are
## multiplied by one factor): the curve of weights 1, (3/4, 3/4) at 1/2, as an independent
## Bernstein sum gives: (1·1/4 + 1·1/2 + 0·1/4, 0·1/4 + 1·1/2 + 1·1/4).
%!assert (cagd_nurbs (2, [1 1 0; 0 1 1], [5e-324 5e-324 5e-324], [0 0 0 1 1 1], 0.5), [0.75; 0.75])
## A weighted point w·P beyond the doubles: refused, not Inf.
%!error id=cagd:overflow cagd_nurbs (1, [1e300 0], [1e10 1], [0 0 1 1], 0.5)

%!demo
%! ## A circle from four rational quadratic arcs (weights 1 and sqrt(2)/2).
%! h = sqrt (2) / 2;
%! P = [1 1 0 -1 -1 -1 0 1 1; 0 1 1 1 0 -1 -1 -1 0];
%! w = [1 h 1 h 1 h 1 h 1];
%! U = [0 0 0 1 1 2 2 3 3 4 4 4] / 4;
%! X = cagd_nurbs (2, P, w, U, linspace (0, 1, 201));
%! plot (X(1,:), X(2,:), "b", P(1,:), P(2,:), "ro--"); axis equal; title ("cagd\_nurbs: a circle");

## -*- texinfo -*-
## @deftypefn {} {[@var{dc}, @var{dk}] =} cagd_bspderiv (@var{d}, @var{c}, @var{k})
## The derivative of a B-spline as a B-spline: octave-nurbs' @code{bspderiv}, argument for
## argument.
##
## @var{d} is the degree, @var{c} the control points @math{mc × nc} (one per column),
## @var{k} the knots.  The derivative has degree @math{d-1}, control points @var{dc}
## (@math{mc × (nc-1)}), @code{dc(:,i) = d/(k(i+d+1)-k(i+1)) (c(:,i+1)-c(:,i))}, and knots
## @var{dk} = @code{k(2:end-1)}, in the operation order of @code{bspderiv} (bit for bit).  As
## there, a zero knot difference gives Inf or NaN.
##
## Differences from octave-nurbs 1.4.3: too few knots (@math{numel (k) < nc + d}), no control
## point or a negative degree are errors (@code{cagd:value}); @code{bspderiv} reads outside
## its arrays there.
##
## Example:
## @example
## @group
## [dc, dk] = cagd_bspderiv (2, [0 1 2 3], [0 0 0 .5 1 1 1])
##   @result{} dc = [4 2 4], dk = [0 0 .5 1 1]
## @end group
## @end example
## @seealso{cagd_nrbderiv, cagd_bspeval}
## @end deftypefn

function [dc, dk] = cagd_bspderiv (varargin)
  [dc, dk] = __cagd__ ("cagd_bspderiv", varargin{:});
endfunction

%!test
%! [dc, dk] = cagd_bspderiv (2, [0 1 2 3], [0 0 0 .5 1 1 1]);
%! assert (dc, [4 2 4]);
%! assert (dk, [0 0 .5 1 1]);
%!test
%! ## The derivative of a random cubic against a difference quotient.
%! c = rand (2, 6); k = [0 0 0 0 .2 .5 1 1 1 1]; u = linspace (0.01, 0.99, 9); h = 1e-6;
%! [dc, dk] = cagd_bspderiv (3, c, k);
%! fd = (cagd_bspeval (3, c, k, u + h) - cagd_bspeval (3, c, k, u - h)) / (2 * h);
%! assert (cagd_bspeval (2, dc, dk, u), fd, 1e-7);
%!assert (cagd_bspderiv (2, [0 1 2 3], [0 0 0 1 1 1 1]), [2 2 Inf])
%!error <reads outside its arrays> cagd_bspderiv (2, [0 1 2 3], [0 0 0 1 1])

%!demo
%! ## A cubic B-spline and its derivative, a quadratic B-spline.
%! c = [0 1 3 4 6; 0 2 -1 2 0]; k = [0 0 0 0 .5 1 1 1 1]; u = linspace (0, 1, 101);
%! [dc, dk] = cagd_bspderiv (3, c, k);
%! subplot (2, 1, 1); p = cagd_bspeval (3, c, k, u); plot (p(1,:), p(2,:)); title ("C(u)");
%! subplot (2, 1, 2); d = cagd_bspeval (2, dc, dk, u); plot (u, d); title ("C'(u) from cagd\\_bspderiv");

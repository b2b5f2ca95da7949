## -*- texinfo -*-
## @deftypefn {} {@var{p} =} cagd_bspeval (@var{d}, @var{c}, @var{k}, @var{u})
## Evaluate a B-spline at parametric points: a drop-in replacement of octave-nurbs'
## @code{bspeval}.
##
## @var{d} is the degree, @var{c} the control points @math{mc × nc} (one per column, any
## number of rows), @var{k} the knot vector (@math{nc + d + 1} knots, non-decreasing), @var{u}
## the parameters (any size).  @var{p} is @math{mc × numel (u)}.  The sums are those of
## @code{bspeval} (the triangular basis of The NURBS Book, A2.2, then
## @math{Σ_i N_i c_i}, @math{i} ascending), so the values agree bit for bit.  A parameter
## outside the domain @math{[k(d+1), k(end-d)]} is an error (@code{cagd:domain}).
##
## Example:
## @example
## @group
## cagd_bspeval (2, [0 1 2; 0 2 0], [0 0 0 1 1 1], [0 0.5 1])
##   @result{} [0 1 2; 0 1 0]
## @end group
## @end example
## @seealso{cagd_nrbeval, cagd_bspline}
## @end deftypefn

function p = cagd_bspeval (varargin)
  p = __cagd__ ("cagd_bspeval", varargin{:});
endfunction

%!assert (cagd_bspeval (2, [0 1 2; 0 2 0], [0 0 0 1 1 1], [0 0.5 1]), [0 1 2; 0 1 0])
%!test
%! k = [0 0 0 0.3 0.3 0.7 1 1 1]; c = magic (6)(1:2, :);
%! u = linspace (0, 1, 11);
%! if (exist ("bspeval"))
%!   assert (cagd_bspeval (2, c, k, u), bspeval (2, c, k, u), 1e-14 * max (abs (c(:))));
%! endif
%! assert (size (cagd_bspeval (2, c, k, u')), [2 11]);
%!error <knot 2 \(0\) is below> cagd_bspeval (1, [0 1], [0 1 0 1], 0.5)
%!error <expected 4 knots> cagd_bspeval (1, [0 1], [0 0 1], 0.5)
%!error <outside the domain> cagd_bspeval (1, [0 1], [0 0 1 1], 2)

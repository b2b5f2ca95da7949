## -*- texinfo -*-
## @deftypefn {} {@var{s} =} cagd_findspan (@var{n}, @var{p}, @var{u}, @var{U})
## The knot spans of parameters: octave-nurbs' @code{findspan}, argument for argument.
##
## @var{n} is the number of control points minus one, @var{p} the degree (not used, as in
## @code{findspan}), @var{u} the parameters (any size), @var{U} the knot vector.  @var{s} has
## the size of @var{u}: @code{s(k)} is @var{n} when @code{u(k) = U(n+2)}, otherwise the
## (0-based) index of the last knot @math{≤ u(k)}.  As @code{findspan}, @var{n} is not
## checked against the number of knots (@code{bspinterpcrv} and @code{bspinterpsurf} rely
## on it); parameters outside @math{[U(1), U(end)]} and NaN parameters are errors.
##
## Differences from octave-nurbs 1.4.3: none in the values; errors carry the identifiers
## @code{cagd:value} and @code{cagd:shape}.  Output is double (@code{findspan} returns the
## class of an integer or single @var{n} when some @code{u(k) = U(n+2)}).
##
## Example:
## @example
## @group
## cagd_findspan (3, 2, [0 0.25 0.5 1], [0 0 0 1/2 1 1 1])
##   @result{} [2 2 3 3]
## @end group
## @end example
## @seealso{cagd_basisfun, cagd_bspeval}
## @end deftypefn

function s = cagd_findspan (varargin)
  s = __cagd__ ("cagd_findspan", varargin{:});
endfunction

%!assert (cagd_findspan (3, 2, [0 0.25 0.5 1], [0 0 0 1/2 1 1 1]), [2 2 3 3])
%!assert (size (cagd_findspan (3, 2, zeros (2, 3), [0 0 0 1/2 1 1 1])), [2 3])
%!test
%! ## n is not checked against the knots (octave-nurbs 1.4.3 gives 3 and 5).
%! assert (cagd_findspan (4, 2, 0.5, [0 0 0 .5 1 1 1]), 3);
%! assert (cagd_findspan (5, 2, 1, [0 0 0 .5 1 1 1]), 5);
%! assert (cagd_findspan (3, {}, single ([0 1]), int8 ([0 0 0 1 1 1 1])), [2 3]);
%! assert (size (cagd_findspan (3, 2, zeros (0, 3), [0 0 0 1 1 1 1])), [0 3]);
%!error <outside the knots> cagd_findspan (3, 2, 1.5, [0 0 0 1/2 1 1 1])
%!error <NaN> cagd_findspan (3, 2, NaN, [0 0 0 1/2 1 1 1])
%!error <out of bound> cagd_findspan (9, 2, 0.5, [0 0 0 1/2 1 1 1])

%!demo
%! ## The spans of 11 parameters on knots with a double interior knot.
%! U = [0 0 0 0.3 0.3 0.7 1 1 1]; u = linspace (0, 1, 11);
%! s = cagd_findspan (5, 2, u, U);
%! stairs (u, s); xlabel ("u"); ylabel ("span (from 0)");
%! title ("cagd\\_findspan on [0 0 0 .3 .3 .7 1 1 1]");

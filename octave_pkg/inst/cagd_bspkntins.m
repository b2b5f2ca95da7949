## -*- texinfo -*-
## @deftypefn {} {[@var{ic}, @var{ik}] =} cagd_bspkntins (@var{d}, @var{c}, @var{k}, @var{u})
## Insert knots into a B-spline: octave-nurbs' @code{bspkntins}, argument for argument.
##
## @var{d} is the degree, @var{c} the control points @math{mc × nc} (one per column),
## @var{k} the knots, @var{u} the knots to insert (any order, repeats allowed).  @var{ic}
## (@math{mc × (nc + numel (u))}) and @var{ik} are the control points and knots of the same
## curve over the refined knot vector, by The NURBS Book A5.4 in the operation order of
## @code{bspkntins} (bit for bit).  As there, knots may be inserted at the ends of the knot
## range and beyond the multiplicity @math{d+1} (the added basis functions are zero); a knot
## outside @math{[k(1), k(end)]}, a NaN knot or no knot at all is an error; the result is
## double whatever the classes of the arguments.
##
## Differences from octave-nurbs 1.4.3: none in the values of double arguments.  With single
## or integer knots or parameters octave-nurbs computes in that class's arithmetic, rounding
## (integers: to whole numbers, so that the coefficients are not the curve's) at each step;
## this computes with their values in double (single knots: within single precision of
## octave-nurbs').  Errors carry the identifiers @code{cagd:value}, @code{cagd:shape},
## @code{cagd:class}.
##
## Example:
## @example
## @group
## [ic, ik] = cagd_bspkntins (2, [0 1 2 3], [0 0 0 .5 1 1 1], 0.25)
##   @result{} ic = [0 0.5 1.25 2 3], ik = [0 0 0 .25 .5 1 1 1]
## @end group
## @end example
## @seealso{cagd_nrbkntins, cagd_bspdegelev, cagd_bspeval}
## @end deftypefn

function [ic, ik] = cagd_bspkntins (varargin)
  if (nargout < 2)
    ic = __cagd__ ("cagd_bspkntins", varargin{:});
  else
    [ic, ik] = __cagd__ ("cagd_bspkntins", varargin{:});
  endif
endfunction

%!test
%! [ic, ik] = cagd_bspkntins (2, [0 1 2 3], [0 0 0 .5 1 1 1], 0.25);
%! assert (ic, [0 0.5 1.25 2 3], 1e-15);
%! assert (ik, [0 0 0 .25 .5 1 1 1]);
%!test
%! ## The curve does not change; knots in any order.
%! c = rand (3, 6); k = [0 0 0 0 .3 .6 1 1 1 1]; u = linspace (0, 1, 23);
%! [ic, ik] = cagd_bspkntins (3, c, k, [0.7 0.1 0.3 0.3]);
%! assert (cagd_bspeval (3, ic, ik, u), cagd_bspeval (3, c, k, u), 1e-14);
%!error <outside the knots> cagd_bspkntins (2, [0 1 2 3], [0 0 0 .5 1 1 1], 1.5)
%!error <out of bound> cagd_bspkntins (2, [0 1 2 3], [0 0 0 .5 1 1 1], [])

%!demo
%! ## Knot insertion: the control polygon approaches the curve, the curve stays.
%! c = [0 1 3 4 6; 0 2 -1 2 0]; k = [0 0 0 0 .5 1 1 1 1]; u = linspace (0, 1, 101);
%! [ic, ik] = cagd_bspkntins (3, c, k, [0.25 0.5 0.75]);
%! p = cagd_bspeval (3, c, k, u);
%! plot (c(1,:), c(2,:), "o--", ic(1,:), ic(2,:), "s-", p(1,:), p(2,:), "k-");
%! legend ("control polygon", "after cagd\\_bspkntins", "curve");
%! title ("cagd\\_bspkntins: three knots inserted");

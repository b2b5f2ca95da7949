## -*- texinfo -*-
## @deftypefn {} {[@var{ic}, @var{ik}] =} cagd_bspdegelev (@var{d}, @var{c}, @var{k}, @var{t})
## Raise the degree of a B-spline: octave-nurbs' @code{bspdegelev}, argument for argument.
##
## @var{d} is the degree, @var{c} the control points @math{mc × nc} (one per column),
## @var{k} the knots, @var{t} the number of degrees to add.  @var{ic} and @var{ik} are the
## control points and knots of the same curve of degree @math{d + t}: every distinct knot
## gains multiplicity @var{t}.  The algorithm is The NURBS Book A5.9 in the operation order
## of @code{bspdegelev} (including its integer @code{bet}); as there, knot vectors that are
## not clamped at their end fail, and @var{ic} has the class of @var{c}, @var{ik} that of
## @var{k}.
##
## Differences from octave-nurbs 1.4.3: with single, integer or logical @var{c} or @var{k},
## or an integer degree @var{d}, octave-nurbs computes in that class's arithmetic, rounding
## at each step (an int32 @var{d} gives control points and knots that do not fit together);
## this computes with the values in double and converts the results once.  Errors carry the identifiers @code{cagd:value},
## @code{cagd:shape}, @code{cagd:class}.
##
## Example:
## @example
## @group
## [ic, ik] = cagd_bspdegelev (1, [0 1], [0 0 1 1], 1)
##   @result{} ic = [0 0.5 1], ik = [0 0 0 1 1 1]
## @end group
## @end example
## @seealso{cagd_nrbdegelev, cagd_bspkntins, cagd_bezier_elevate}
## @end deftypefn

function [ic, ik] = cagd_bspdegelev (d, c, k, t)
  if (nargin != 4)
    print_usage ();
  endif
  [ic, ik] = __cagd__ ("cagd_bspdegelev", d, c, k, t);
  ic = as_class (ic, c);
  ik = as_class (ik, k);
endfunction

function y = as_class (x, like)
  if (islogical (like))
    y = logical (x);
  elseif (isnumeric (like) && ! isa (like, "double"))
    y = cast (x, class (like));
  else
    y = x;
  endif
endfunction

%!test
%! [ic, ik] = cagd_bspdegelev (1, [0 1], [0 0 1 1], 1);
%! assert (ic, [0 0.5 1], 1e-15);
%! assert (ik, [0 0 0 1 1 1]);
%!test
%! ## The curve does not change; each distinct knot gains multiplicity t.
%! c = rand (2, 6); k = [0 0 0 .3 .3 .6 1 1 1]; u = linspace (0, 1, 17);
%! [ic, ik] = cagd_bspdegelev (2, c, k, 2);
%! assert (ik, [0 0 0 0 0 .3 .3 .3 .3 .6 .6 .6 1 1 1 1 1]);
%! assert (cagd_bspeval (4, ic, ik, u), cagd_bspeval (2, c, k, u), 1e-14);
%! assert (class (cagd_bspdegelev (2, single (c), k, 1)), "single");
%!error <out of bound> cagd_bspdegelev (2, [0 1 3 4; 0 2 2 0], [0 0 0 1 2 3 3.5], 1)

%!demo
%! ## A quadratic raised to degree 3 and 5: the control polygons approach the curve.
%! c = [0 1 3 4 6; 0 2 -1 2 0]; k = [0 0 0 .4 .6 1 1 1]; u = linspace (0, 1, 101);
%! [c3, k3] = cagd_bspdegelev (2, c, k, 1); [c5, k5] = cagd_bspdegelev (2, c, k, 3);
%! p = cagd_bspeval (2, c, k, u);
%! plot (c(1,:), c(2,:), "o--", c3(1,:), c3(2,:), "s-", c5(1,:), c5(2,:), "d-", p(1,:), p(2,:), "k-");
%! legend ("degree 2", "degree 3", "degree 5", "curve");
%! title ("cagd\\_bspdegelev");

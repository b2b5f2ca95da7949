## -*- texinfo -*-
## @deftypefn {} {@var{srf} =} cagd_nrbcoons (@var{u1}, @var{u2}, @var{v1}, @var{v2})
## The bilinearly blended Coons patch of four NURBS boundary curves as an exact NURBS
## surface: octave-nurbs' @code{nrbcoons}, argument for argument.
##
## @var{u1} and @var{u2} are the boundaries @math{S(u, 0)} and @math{S(u, 1)}, @var{v1} and
## @var{v2} the boundaries @math{S(0, v)} and @math{S(1, v)} (structures from @code{nrbmak},
## @code{nrbcirc}, @dots{}, on @math{[0, 1]}).  The pairs are made compatible (degree
## elevation and knot insertion), the ruled surfaces between them and the bilinear patch of
## the corners are raised to common degrees and knots, and the boolean sum
## @math{r_u + r_v - r_@{uv@}} of their homogeneous coefficients is the result — the structure
## @code{nrbcoons} builds, with the same knots and orders and the coefficients to rounding
## (cagd's core: @code{cagd::coons::coons_bspline_net}).  As there, the curves must meet at
## the corners within 1e-10 ("The four curves do not define a closed boundary") and have the
## knot range @math{[0, 1]}.
##
## Differences from octave-nurbs 1.4.3: a boundary whose knot vector is not clamped at both
## ends is an error (@code{cagd:value}); @code{nrbcoons} then builds a surface that does not
## interpolate it.  The result is double.
##
## Example:
## @example
## @group
## line = @@(a, b) struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
##   "coefs", [a(:) b(:); 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
## srf = cagd_nrbcoons (line ([0 0], [1 0]), line ([0 1], [1 1]), ...
##                      line ([0 0], [0 1]), line ([1 0], [1 1]));
## cagd_nrbeval (srf, [0.3; 0.6])'
##   @result{} [0.3 0.6 0]
## @end group
## @end example
## @seealso{cagd_coons, cagd_nrbeval, cagd_nrbdegelev, cagd_nrbkntins}
## @end deftypefn

function srf = cagd_nrbcoons (varargin)
  out = cell (1, 5);
  [out{:}] = __cagd__ ("cagd_nrbcoons", varargin{:});
  srf = __cagd_nrb__ (out{:});
endfunction

%!shared u1, u2, v1, v2
%! u1 = struct ("form", "B-NURBS", "dim", 4, "number", 6, "coefs", ...
%!   [0 3 4.5 6.5 8 10; 0 0 0 0 0 0; 2 2 7 4 7 9; 1 1 1 1 1 1], ...
%!   "knots", [0 0 0 1/3 0.5 2/3 1 1 1], "order", 3);
%! u2 = struct ("form", "B-NURBS", "dim", 4, "number", 5, "coefs", ...
%!   [0 3 5 8 10; 10 10 10 10 10; 3 5 8 6 10; 1 1 1 1 1], ...
%!   "knots", [0 0 0 1/3 2/3 1 1 1], "order", 3);
%! v1 = struct ("form", "B-NURBS", "dim", 4, "number", 4, "coefs", ...
%!   [0 0 0 0; 0 3 8 10; 2 0 5 3; 1 1 1 1], "knots", [0 0 0 0.5 1 1 1], "order", 3);
%! v2 = struct ("form", "B-NURBS", "dim", 4, "number", 5, "coefs", ...
%!   [10 10 10 10 10; 0 3 5 8 10; 9 7 7 10 10; 1 1 1 1 1], ...
%!   "knots", [0 0 0 0.25 0.75 1 1 1], "order", 3);
%!test
%! ## octave-nurbs' own demo patch: the boundaries are interpolated.
%! srf = cagd_nrbcoons (u1, u2, v1, v2);
%! assert (srf.order, [3 3]);
%! t = linspace (0, 1, 11);
%! assert (squeeze (cagd_nrbeval (srf, {t, 0})), cagd_nrbeval (u1, t), 1e-12);
%! assert (squeeze (cagd_nrbeval (srf, {t, 1})), cagd_nrbeval (u2, t), 1e-12);
%! assert (squeeze (cagd_nrbeval (srf, {0, t})), cagd_nrbeval (v1, t), 1e-12);
%! assert (squeeze (cagd_nrbeval (srf, {1, t})), cagd_nrbeval (v2, t), 1e-12);
%!error <closed boundary> cagd_nrbcoons (u1, u2, v2, v1)

%!demo
%! ## octave-nurbs' nrbcoons demo, by the twin: the patch and its four boundaries.
%! u1 = struct ("form", "B-NURBS", "dim", 4, "number", 6, "coefs", ...
%!   [0 3 4.5 6.5 8 10; 0 0 0 0 0 0; 2 2 7 4 7 9; 1 1 1 1 1 1], ...
%!   "knots", [0 0 0 1/3 0.5 2/3 1 1 1], "order", 3);
%! u2 = struct ("form", "B-NURBS", "dim", 4, "number", 5, "coefs", ...
%!   [0 3 5 8 10; 10 10 10 10 10; 3 5 8 6 10; 1 1 1 1 1], ...
%!   "knots", [0 0 0 1/3 2/3 1 1 1], "order", 3);
%! v1 = struct ("form", "B-NURBS", "dim", 4, "number", 4, "coefs", ...
%!   [0 0 0 0; 0 3 8 10; 2 0 5 3; 1 1 1 1], "knots", [0 0 0 0.5 1 1 1], "order", 3);
%! v2 = struct ("form", "B-NURBS", "dim", 4, "number", 5, "coefs", ...
%!   [10 10 10 10 10; 0 3 5 8 10; 9 7 7 10 10; 1 1 1 1 1], ...
%!   "knots", [0 0 0 0.25 0.75 1 1 1], "order", 3);
%! srf = cagd_nrbcoons (u1, u2, v1, v2);
%! t = linspace (0, 1, 25);
%! p = cagd_nrbeval (srf, {t, t});
%! surf (squeeze (p(1,:,:)), squeeze (p(2,:,:)), squeeze (p(3,:,:))); hold on;
%! for c = {u1, u2, v1, v2}
%!   q = cagd_nrbeval (c{1}, t); plot3 (q(1,:), q(2,:), q(3,:), "r", "linewidth", 2.5);
%! endfor
%! hold off; title ("cagd\\_nrbcoons: the bilinearly blended Coons patch of four NURBS curves");

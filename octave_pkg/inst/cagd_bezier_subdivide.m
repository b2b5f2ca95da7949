## -*- texinfo -*-
## @deftypefn  {} {[@var{L}, @var{R}] =} cagd_bezier_subdivide (@var{P}, @var{t})
## @deftypefnx {} {[@var{L}, @var{R}] =} cagd_bezier_subdivide (@var{P}, @var{t}, "exact")
## Subdivision of the Bézier curve with control points @var{P} (@math{d × (n+1)}, columns) at
## @math{0 < t < 1}: @var{L} and @var{R} (@math{d × (n+1)} each) are the control points of the
## pieces over [0, t] and [t, 1], each reparametrised to [0, 1]: the diagonals of the de
## Casteljau scheme, @math{L_i = b_0^i(t)}, @math{R_i = b_i^@{n-i@}(t)} (thesis §2.3).
## With @code{"exact"}: exact fractions (see @code{cagd_bezier}).
##
## Example:
## @example
## @group
## [L, R] = cagd_bezier_subdivide ([0 0 8 4; 0 2 2 0; 0 2 0 0], 0.5);
## L(:,end)'
##   @result{} [3.5 1.5 0.75]
## @end group
## @end example
## @seealso{cagd_bezier}
## @end deftypefn

function [L, R] = cagd_bezier_subdivide (varargin)
  [L, R] = __cagd__ ("cagd_bezier_subdivide", varargin{:});
endfunction

%!test
%! P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
%! [L, R] = cagd_bezier_subdivide (P, 0.5);
%! assert (L, [0 0 2 3.5; 0 1 1.5 1.5; 0 1 1 0.75]);
%! assert (R, [3.5 5 6 4; 1.5 1.5 1 0; 0.75 0.5 0 0]);
%! ## The pieces are the curve.
%! s = linspace (0, 1, 7);
%! assert (cagd_bezier (L, s), cagd_bezier (P, s / 2), 1e-14);
%! assert (cagd_bezier (R, s), cagd_bezier (P, 0.5 + s / 2), 1e-14);
%!test
%! [L, R] = cagd_bezier_subdivide ([0 1 3], "1/3", "exact");
%! assert (L, {"0", "1/3", "7/9"});
%! assert (R, {"7/9", "5/3", "3"});
%!error <interval \[0, 0\] is empty> cagd_bezier_subdivide ([0 1 3], 0)
%!error <t: an array of size 1×2> cagd_bezier_subdivide ([0 1 3], [0.2 0.4])

%!demo
%! ## Thesis Primer 2.4 split at t = 1/2: two cubics, their polygons closer to the curve.
%! P = [0 0 8 4; 0 2 2 0]; [L, R] = cagd_bezier_subdivide (P, 0.5);
%! X = cagd_bezier (P, linspace (0, 1, 101));
%! plot (X(1,:), X(2,:), "k", P(1,:), P(2,:), "o--", L(1,:), L(2,:), "s-", R(1,:), R(2,:), "d-");
%! legend ("curve", "polygon", "left half", "right half"); title ("cagd\_bezier\_subdivide");

## -*- texinfo -*-
## @deftypefn  {} {@var{Q} =} cagd_bezier_elevate (@var{P})
## @deftypefnx {} {@var{Q} =} cagd_bezier_elevate (@var{P}, @var{r})
## @deftypefnx {} {@var{Q} =} cagd_bezier_elevate (@dots{}, "exact")
## Degree elevation: the control points @var{Q} (@math{d × (n+r+1)}) of the same curve as
## @var{P} (@math{d × (n+1)}) written with degree @math{n + r} (@var{r} default 1):
## @math{q_i = (i/(n+1)) b_@{i-1@} + (1 - i/(n+1)) b_i}, applied @var{r} times.
## With @code{"exact"}: exact fractions (see @code{cagd_bezier}).
##
## Example:
## @example
## @group
## cagd_bezier_elevate ([0 3 3], 1)
##   @result{} [0 2 3 3]
## @end group
## @end example
## @seealso{cagd_bezier}
## @end deftypefn

function Q = cagd_bezier_elevate (varargin)
  Q = __cagd__ ("cagd_bezier_elevate", varargin{:});
endfunction

%!assert (cagd_bezier_elevate ([0 3 3]), [0 2 3 3])
%!assert (cagd_bezier_elevate ([0 3 3], 0), [0 3 3])
%!assert (cagd_bezier_elevate ([0 1], 2, "exact"), {"0", "1/3", "2/3", "1"})
%!test
%! P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
%! s = linspace (0, 1, 9);
%! assert (cagd_bezier (cagd_bezier_elevate (P, 3), s), cagd_bezier (P, s), 1e-14);
%!error <r: -1 is not a non-negative integer> cagd_bezier_elevate ([0 1], -1)
%!error <cagd_limits> cagd_bezier_elevate ([0 1], 5000)

%!demo
%! ## A cubic raised to degree 4 and 8: the polygons approach the curve.
%! P = [0 1 3 4; 0 2 -1 1]; X = cagd_bezier (P, linspace (0, 1, 101));
%! Q4 = cagd_bezier_elevate (P, 1); Q8 = cagd_bezier_elevate (P, 5);
%! plot (P(1,:), P(2,:), "o--", Q4(1,:), Q4(2,:), "s-", Q8(1,:), Q8(2,:), "d-", X(1,:), X(2,:), "k");
%! legend ("degree 3", "degree 4", "degree 8", "curve"); title ("cagd\_bezier\_elevate");

## -*- texinfo -*-
## @deftypefn  {} {@var{G} =} cagd_convert (@var{G}, @var{from}, @var{to})
## @deftypefnx {} {@var{G} =} cagd_convert (@dots{}, "exact")
## The geometry of a cubic in one form as the geometry of the same cubic in another
## (@code{"hermite"}: @math{[x(0), x(1), x'(0), x'(1)]}; @code{"bezier"}: the four control
## points; @code{"bspline"}: four consecutive control points of a uniform cubic B-spline, the
## lecture notes' "Coons cubic").  @var{G} is @math{d × 4} in and out:
## @math{G_to = G_from M_from M_to^@{-1@}}.  With @code{"exact"}: exact fractions (see
## @code{cagd_bezier}).
##
## Example:
## @example
## @group
## cagd_convert ([0 1 2 4], "bezier", "hermite")
##   @result{} [0 4 3 6]
## cagd_convert ([0 1 2 4], "bspline", "bezier", "exact")
##   @result{} @{"1", "4/3", "5/3", "13/6"@}
## @end group
## @end example
## @seealso{cagd_hermite}
## @end deftypefn

function G = cagd_convert (varargin)
  G = __cagd__ ("cagd_convert", varargin{:});
endfunction

%!assert (cagd_convert ([0 1 2 4], "bezier", "hermite"), [0 4 3 6], 1e-14)
%!assert (cagd_convert ([0 1 2 4], "bspline", "bezier", "exact"), {"1", "4/3", "5/3", "13/6"})
%!test
%! G = [0 1 3 4; 0 2 -1 1];
%! assert (cagd_convert (cagd_convert (G, "bezier", "bspline"), "bspline", "bezier"), G, 1e-13);
%!error <to: 'monomial'> cagd_convert ([0 1 2 4], "bezier", "monomial")
%!error <G: 3 column\(s\) for the hermite form; expected 4 columns> cagd_convert ([0 1 2], "bezier", "hermite")
## Finite Hermite data whose Bézier points x ± x'/3 overflow: refused, not Inf.
%!error id=cagd:overflow cagd_convert (ones (2, 4) * 1.7e308, "hermite", "bspline")

%!demo
%! ## One cubic in three forms: Bezier control points, Hermite data, B-spline points.
%! B = [0 1 3 4; 0 2 -1 1];
%! H = cagd_convert (B, "bezier", "hermite"); S = cagd_convert (B, "bezier", "bspline");
%! X = cagd_bezier (B, linspace (0, 1, 101));
%! plot (X(1,:), X(2,:), "k", B(1,:), B(2,:), "o--", S(1,:), S(2,:), "s--");
%! legend ("curve", "Bezier polygon", "uniform B-spline polygon"); title ("cagd\_convert");

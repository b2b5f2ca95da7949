## -*- texinfo -*-
## @deftypefn  {} {[@var{X}, @var{B}] =} cagd_hermite (@var{p0}, @var{p1}, @var{t0}, @var{t1}, @var{u})
## @deftypefnx {} {[@var{X}, @var{B}] =} cagd_hermite (@dots{}, "exact")
## The Hermite (Ferguson) cubic with @math{x(0) = p0}, @math{x(1) = p1}, @math{x'(0) = t0},
## @math{x'(1) = t1} (each a point or vector of dimension @math{d}) at @var{u}, and its Bézier
## control points @math{B = [p0, p0 + t0/3, p1 - t1/3, p1]} (@math{d × 4}).
## @var{X} is @math{d × numel (u)}.  With @code{"exact"}: exact fractions (see
## @code{cagd_bezier}).
##
## Example:
## @example
## @group
## [X, B] = cagd_hermite ([0;0], [1;0], [1;1], [1;-1], 0.5)
##   @result{} X = [0.5; 0.25],  B = [0 1/3 2/3 1; 0 1/3 1/3 0]
## @end group
## @end example
## @seealso{cagd_convert, cagd_spline}
## @end deftypefn

function [X, B] = cagd_hermite (varargin)
  [X, B] = __cagd__ ("cagd_hermite", varargin{:});
endfunction

%!test
%! [X, B] = cagd_hermite ([0;0], [1;0], [1;1], [1;-1], 0.5);
%! assert (X, [0.5; 0.25], 1e-15);
%! assert (B, [0 1/3 2/3 1; 0 1/3 1/3 0], 1e-15);
%! assert (cagd_bezier (B, [0 0.3 1]), cagd_hermite ([0;0], [1;0], [1;1], [1;-1], [0 0.3 1]), 1e-15);
%!test
%! [X, B] = cagd_hermite ([0 0], [1 0], [1 1], [1 -1], 0.5, "exact");
%! assert (X, {"1/2"; "1/4"});
%! assert (B, {"0", "1/3", "2/3", "1"; "0", "1/3", "1/3", "0"});
%!error <Hermite cubic: expected four vectors of the same positive length> cagd_hermite ([0;0], [1;0;0], [1;1], [1;-1], 0.5)
%!error id=cagd:overflow cagd_hermite (1.7e308, -1.7e308, 1.7e308, -1.7e308, 0.5)

%!demo
%! ## A Hermite (Ferguson) cubic from (0,0) to (1,0) with tangents (1,1) and (1,-1).
%! u = linspace (0, 1, 101);
%! [X, B] = cagd_hermite ([0;0], [1;0], [1;1], [1;-1], u);
%! plot (X(1,:), X(2,:), "b", B(1,:), B(2,:), "ro--"); axis equal;
%! legend ("cubic", "its Bezier polygon"); title ("cagd\_hermite");

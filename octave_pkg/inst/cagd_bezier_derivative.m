## -*- texinfo -*-
## @deftypefn  {} {[@var{X}, @var{Q}] =} cagd_bezier_derivative (@var{P}, @var{t})
## @deftypefnx {} {[@var{X}, @var{Q}] =} cagd_bezier_derivative (@var{P}, @var{t}, @var{r})
## @deftypefnx {} {[@var{X}, @var{Q}] =} cagd_bezier_derivative (@dots{}, "exact")
## The @var{r}-th derivative (default 1) of the Bézier curve with control points @var{P}
## (@math{d × (n+1)}, columns) at @var{t}, and the control points of the derivative curve.
##
## @math{b^@{(r)@}(t) = n(n-1)…(n-r+1) Σ_i Δ^r b_i B_i^@{n-r@}(t)} (thesis §2.4).  @var{X} is
## @math{d × numel (t)}, @var{Q} is @math{d × (n-r+1)}.  @var{r} above the degree is an
## error (@code{cagd:value}).  With @code{"exact"}: exact fractions (see @code{cagd_bezier}).
##
## Example (the hodograph of thesis Primer 2.4 at t = 1/2):
## @example
## @group
## [X, Q] = cagd_bezier_derivative ([0 0 8 4; 0 2 2 0; 0 2 0 0], 0.5)
##   @result{} X = [9; 0; -1.5],  Q = [0 24 -12; 6 0 -6; 6 -6 0]
## @end group
## @end example
## @seealso{cagd_bezier}
## @end deftypefn

function [X, Q] = cagd_bezier_derivative (varargin)
  [X, Q] = __cagd__ ("cagd_bezier_derivative", varargin{:});
endfunction

%!shared P
%! P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
%!test
%! [X, Q] = cagd_bezier_derivative (P, 0.5);
%! assert (X, [9; 0; -1.5]);
%! assert (Q, [0 24 -12; 6 0 -6; 6 -6 0]);
%!test
%! [X, Q] = cagd_bezier_derivative (P, [0 1], 2);
%! assert (Q, 6 * [8 -12; -2 -2; -4 2]);
%! assert (X, Q);
%! assert (cagd_bezier_derivative (P, 0.3, 3), 6 * (P(:,4) - 3*P(:,3) + 3*P(:,2) - P(:,1)));
%!assert (cagd_bezier_derivative (P, "1/3", 1, "exact"), {"28/3"; "2"; "0"})
%!error <derivative order 4 exceeds the degree 3> cagd_bezier_derivative (P, 0.5, 4)
## Differences of ±1.7e308 overflow: refused, not Inf.
%!error id=cagd:overflow cagd_bezier_derivative ([1.7e308 -1.7e308 1.7e308], 0.5)

%!demo
%! ## A plane cubic with its tangent vectors (the hodograph's values) at 9 points.
%! P = [0 1 3 4; 0 2 2 0]; t = linspace (0, 1, 9);
%! X = cagd_bezier (P, linspace (0, 1, 101)); [D, Q] = cagd_bezier_derivative (P, t);
%! Y = cagd_bezier (P, t);
%! plot (X(1,:), X(2,:), "b-", P(1,:), P(2,:), "ro--"); hold on;
%! quiver (Y(1,:), Y(2,:), D(1,:), D(2,:), 0.3); hold off; axis equal;
%! title ("cagd\_bezier\_derivative: tangents of a cubic");

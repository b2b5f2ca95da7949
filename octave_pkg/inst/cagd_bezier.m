## -*- texinfo -*-
## @deftypefn  {} {@var{X} =} cagd_bezier (@var{P}, @var{t})
## @deftypefnx {} {@var{X} =} cagd_bezier (@var{P}, @var{t}, "exact")
## The Bézier curve with control points @var{P} at the parameters @var{t}.
##
## @var{P} is @math{d × (n+1)}, one control point per column (any dimension @math{d}, degree
## @math{n}); @var{t} is any array of parameters (outside [0, 1] the curve is extrapolated).
## @var{X} is @math{d × numel (t)}: @code{X(:,k)} is @math{b(t(k)) = Σ_i B_i^n(t(k)) b_i}.
##
## With @code{"exact"} the computation is in exact fractions and @var{X} is a cell array of
## strings of the same size (@code{"7/2"}); a double is read as the shortest decimal that gives
## it back (0.2 is 1/5), and @var{P} or @var{t} may be given as text (@code{"[0 1/3 1]"}).
##
## Example (thesis Primer 2.4):
## @example
## @group
## P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
## cagd_bezier (P, 0.5)'
##   @result{} [3.5 1.5 0.75]
## cagd_bezier (P, 0.5, "exact")'
##   @result{} @{"7/2", "3/2", "3/4"@}
## @end group
## @end example
## @seealso{deCasteljau, cagd_bezier_derivative, cagd_bezier_subdivide, cagd_bezier_elevate}
## @end deftypefn

function X = cagd_bezier (varargin)
  X = __cagd__ ("cagd_bezier", varargin{:});
endfunction

%!shared P
%! P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
%!assert (cagd_bezier (P, [0 0.5 1]), [0 3.5 4; 0 1.5 0; 0 0.75 0])
%!assert (cagd_bezier (P, 0.5, "exact"), {"7/2"; "3/2"; "3/4"})
%!assert (cagd_bezier (P, "1/3", "exact"), {"52/27"; "4/3"; "8/9"})
%!assert (cagd_bezier ("[0 1/3 1]", 0.5, "exact"), {"5/12"})
%!assert (size (cagd_bezier (P, zeros (2, 3))), [3 6])
%!assert (cagd_bezier ([1 2 4], 2), 9)
%!error <P: empty> cagd_bezier ([], 0.5)
%!error <t: value 2 is not finite> cagd_bezier (P, [0 NaN])
%!error <called with 1 argument> cagd_bezier (P)
%!error <P: .* does not parse|P: > cagd_bezier ("[0 1", 0.5, "exact")
## A result beyond the doubles (finite control points, t = 5) is refused, not returned as Inf.
%!error id=cagd:overflow cagd_bezier ([1e308 -1e308], 5)
%!error <not a finite double> cagd_bezier ([1e308 -1e308], 5)

%!demo
%! ## Thesis Primer 2.4: the cubic and its control polygon.
%! P = [0 0 8 4; 0 2 2 0; 0 2 0 0];
%! X = cagd_bezier (P, linspace (0, 1, 101));
%! plot3 (P(1,:), P(2,:), P(3,:), "ro--", X(1,:), X(2,:), X(3,:), "b-"); grid on;
%! title ("cagd\_bezier: thesis Primer 2.4");

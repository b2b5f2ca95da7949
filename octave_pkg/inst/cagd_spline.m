## -*- texinfo -*-
## @deftypefn  {} {[@var{X}, @var{D}] =} cagd_spline (@var{Q}, @var{t})
## @deftypefnx {} {[@var{X}, @var{D}] =} cagd_spline (@var{Q}, @var{t}, @var{ends})
## @deftypefnx {} {[@var{X}, @var{D}] =} cagd_spline (@dots{}, "exact")
## The interpolating cubic spline (C², Hermite cubics between the points) through the columns
## of @var{Q} (@math{d × m}) at the parameters @math{0, 1, …, m-1}, evaluated at @var{t}
## (in @math{[0, m-1]}; beyond it the end segments continue, as @code{cagd spline} on the
## command line; a closed spline is periodic with period @math{m}).
##
## @var{ends} is @code{"natural"} (default: zero second derivative at both ends),
## @code{"closed"} (one more segment back to the first point, C² there too) or the end tangents
## as a @math{d × 2} matrix @code{[x'(0), x'(m-1)]}.  @var{X} is @math{d × numel (t)}; @var{D}
## (@math{d × m}) holds the tangents at the points.  With @code{"exact"}: exact fractions (see
## @code{cagd_bezier}).
##
## Example:
## @example
## @group
## [X, D] = cagd_spline ([0 1 0], [0.5 1 1.5], "natural", "exact")
##   @result{} X = @{"11/16", "1", "11/16"@},  D = @{"3/2", "0", "-3/2"@}
## @end group
## @end example
## @seealso{cagd_hermite, cagd_bspline}
## @end deftypefn

function [X, D] = cagd_spline (varargin)
  [X, D] = __cagd__ ("cagd_spline", varargin{:});
endfunction

%!test
%! [X, D] = cagd_spline ([0 1 0], [0.5 1 1.5], "natural", "exact");
%! assert (X, {"11/16", "1", "11/16"});
%! assert (D, {"3/2", "0", "-3/2"});
%!test
%! Q = [0 2 4 6; 0 1 4 0];
%! [X, D] = cagd_spline (Q, 0:3, [1 -1; 1 1]);
%! assert (X, Q, 1e-14);
%! assert (D(:, [1 end]), [1 -1; 1 1]);
%! assert (D(2, 3), -27/15, 1e-14);
%!test
%! X = cagd_spline ([1 0 -1 0; 0 1 0 -1], linspace (0, 4, 9), "closed");
%! assert (X(:, 1), X(:, end), 1e-15);
%!error <ends: 'periodic'> cagd_spline ([0 1 0], 0.5, "periodic")
%!assert (cagd_spline ([0 1 0], 2.5, "natural", "exact"), {"-11/16"})
%!assert (cagd_spline ([1 0 -1 0; 0 1 0 -1], 5, "closed"), cagd_spline ([1 0 -1 0; 0 1 0 -1], 1, "closed"), 1e-15)
%!error id=cagd:overflow cagd_spline ([1.7e308 -1.7e308 1.7e308], 0.5)

%!demo
%! ## The natural cubic spline through five points.
%! Q = [0 1 2 3 4; 0 1 0 1 0]; t = linspace (0, 4, 201);
%! X = cagd_spline (Q, t, "natural");
%! plot (X(1,:), X(2,:), "b", Q(1,:), Q(2,:), "ro"); title ("cagd\_spline: a natural spline");

## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} cagd_nrbeval (@var{crv}, @var{ut})
## @deftypefnx {} {@var{p} =} cagd_nrbeval (@var{srf}, @{@var{ut}, @var{vt}@})
## @deftypefnx {} {@var{p} =} cagd_nrbeval (@var{vol}, @{@var{ut}, @var{vt}, @var{wt}@})
## @deftypefnx {} {@var{p} =} cagd_nrbeval (@var{srf}, @var{pts})
## @deftypefnx {} {[@var{p}, @var{w}] =} cagd_nrbeval (@dots{})
## Evaluate a NURBS curve, surface or volume: octave-nurbs' @code{nrbeval}, argument for
## argument, with the same sizes of the results.
##
## The NURBS is a structure from @code{nrbmak}, @code{nrbcirc}, @code{nrbcoons},
## @code{nrbderiv}, @dots{} (fields @code{form = "B-NURBS"}, @code{coefs} @math{4 × n1 × …}
## homogeneous @math{(w x, w y, w z, w)}, @code{knots} (a vector, or a cell of two or three),
## @code{order}, @code{number}).
## @itemize
## @item curve, parameters @var{ut} of any size: @var{p} is @math{3 × numel (ut)} for a row
## (otherwise @code{[3, size(ut)]}), @var{w} is the size of @var{ut};
## @item surface or volume on a grid @code{@{ut, vt@}} / @code{@{ut, vt, wt@}}: @var{p} is
## @math{3 × nu × nv (× nw)}, @code{p(:, i, j)} the point at @code{(ut(i), vt(j))};
## @item surface or volume at scattered points @var{pts} (@math{2 × n} or @math{3 × n},
## or @math{2 × a × b …}; @math{n × 2} is transposed as @code{nrbeval} does): @var{p} is
## @math{3 × n}.
## @end itemize
## With two outputs @var{p} holds the homogeneous coordinates (w·x, w·y, w·z) and @var{w} the
## weights, as @code{nrbeval}.
##
## As @code{nrbeval}: weights may have any sign (a zero weight gives Inf or NaN, as the
## NURBS of a derivative from @code{nrbderiv} needs); any parameter in
## @math{[U(1), U(end)]} of its knots is evaluated (past the last knot of the domain the last
## span continues, an empty last span gives NaN) and a parameter outside the knots is an
## error (octave-nurbs 1.4.3 does not extrapolate); NaN parameters give NaN; @code{coefs} and
## knots may be double or single, parameters any real numeric class.  The values agree
## with @code{nrbeval} to rounding (most bit for bit): where every parameter lies in the
## domain they come from cagd's batch kernels (a surface grid in one tensor-product sweep,
## a curve at many sorted parameters by its Bézier pieces).
##
## Differences from octave-nurbs 1.4.3: where @code{nrbeval} reads before its arrays (a
## parameter below @math{U(p+1)} of a knot vector not clamped at its start, where it
## returns whatever memory lies there) this gives the NURBS's value, the sum over the basis
## functions that exist.  Errors carry the identifiers @code{cagd:domain},
## @code{cagd:value}, @code{cagd:shape}, @code{cagd:class}, @code{cagd:struct}.
##
## Example:
## @example
## @group
## crv = nrbcirc (1);                       % octave-nurbs
## p = cagd_nrbeval (crv, linspace (0, 1, 5));
## max (abs (sqrt (sum (p.^2)) - 1))
##   @result{} 1.1102e-16
## @end group
## @end example
## @seealso{cagd_bspeval, cagd_basisfun, cagd_findspan, cagd_nrbdeval, cagd_nurbs}
## @end deftypefn

function [p, w] = cagd_nrbeval (varargin)
  if (nargout < 2)
    p = __cagd__ ("cagd_nrbeval", varargin{:});
  else
    [p, w] = __cagd__ ("cagd_nrbeval", varargin{:});
  endif
endfunction

%!shared crv, srf
%! ## A quarter circle (rational quadratic) and a bilinear-by-quadratic surface, by hand.
%! h = sqrt (2) / 2;
%! crv = struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
%!               "coefs", [1 h 0; 0 h 1; 0 0 0; 1 h 1], "knots", [0 0 0 1 1 1], "order", 3);
%! c = zeros (4, 2, 3);
%! c(1,:,:) = [0 0 0; 1 1 1]; c(2,:,:) = [0 0.5 1; 0 0.5 1]; c(3,:,:) = [0 1 0; 0 2 0];
%! c(4,:,:) = 1;
%! srf = struct ("form", "B-NURBS", "dim", 4, "number", [2 3], "coefs", c, ...
%!               "knots", {{[0 0 1 1], [0 0 0 1 1 1]}}, "order", [2 3]);
%!test
%! p = cagd_nrbeval (crv, linspace (0, 1, 9));
%! assert (size (p), [3 9]);
%! assert (sqrt (sum (p.^2)), ones (1, 9), 1e-15);
%! [p, w] = cagd_nrbeval (crv, [0 1]');
%! assert (size (p), [3 2]);
%! assert (size (w), [2 1]);
%! assert (w, [1; 1]);
%!test
%! p = cagd_nrbeval (srf, {[0 0.5 1], [0 0.25 0.5 1]});
%! assert (size (p), [3 3 4]);
%! assert (squeeze (p(1,:,1)), [0 0.5 1]);
%! assert (p(3,2,3), 0.75, 1e-15);   % z: 0.5 and 1 along v, averaged along u
%! q = cagd_nrbeval (srf, [0.5; 0.5]);
%! assert (q, p(:,2,3), 1e-15);
%!test
%! ## Weights of any sign: the homogeneous form of a NURBS whose weights change sign.
%! c = [0 1 2; 0 1 0; 0 0 0; 1 -1 2];
%! n = struct ("form", "B-NURBS", "dim", 4, "number", 3, "coefs", c, ...
%!             "knots", [0 0 0 1 1 1], "order", 3);
%! [p, w] = cagd_nrbeval (n, 0.5);
%! assert (w, 0.25 - 0.5 + 0.5, 1e-15);
%! assert (p, [1; 0.5; 0], 1e-15);
%! assert (cagd_nrbeval (n, 0.5), p / w, 1e-15);
%!test
%! ## Knots not clamped at the end (octave-nurbs gives NaN from 0.4 on); NaN parameters.
%! c = [0 1 3 4 5; 0 2 2 0 1; 0 0 0 0 0; 1 1 1 1 1];
%! n = struct ("form", "B-NURBS", "dim", 4, "number", 5, "coefs", c, ...
%!             "knots", [0 0 0 .4 .4 .4 1 1], "order", 3);
%! p = cagd_nrbeval (n, [0.2 0.7 NaN]);
%! assert (p(:,1), [1.25; 1.5; 0], 1e-15);
%! assert (all (isnan (p(:, 2:3)(:))));
%!test
%! ## Parameters of other classes; cell grids with one point per direction.
%! assert (cagd_nrbeval (crv, single (0.5)), cagd_nrbeval (crv, 0.5));
%! assert (size (cagd_nrbeval (srf, {int8(1), 0.5})), [3 1]);
%!error <is not a NURBS structure> cagd_nrbeval (1, 0.5)
%!error <has no field 'coefs'> cagd_nrbeval (struct ("form", "B-NURBS", "knots", [0 1], "order", 1), 0.5)
%!error <outside the knots> cagd_nrbeval (crv, 1.5)

%!demo
%! ## A circle (octave-nurbs' nrbcirc) and a test surface evaluated by the twin.
%! if (exist ("nrbcirc"))
%!   crv = nrbcirc (1, [0 0], 0, pi);
%!   p = cagd_nrbeval (crv, linspace (0, 1, 50));
%!   subplot (1, 2, 1); plot (p(1,:), p(2,:)); axis equal; title ("cagd\\_nrbeval: a half circle");
%!   srf = nrbtestsrf ();
%!   p = cagd_nrbeval (srf, {linspace(0, 1, 30), linspace(0, 1, 30)});
%!   subplot (1, 2, 2); surf (squeeze (p(1,:,:)), squeeze (p(2,:,:)), squeeze (p(3,:,:)));
%!   title ("cagd\\_nrbeval: nrbtestsrf on a 30 x 30 grid");
%! endif

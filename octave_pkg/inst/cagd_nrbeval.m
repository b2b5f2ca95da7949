## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} cagd_nrbeval (@var{crv}, @var{ut})
## @deftypefnx {} {@var{p} =} cagd_nrbeval (@var{srf}, @{@var{ut}, @var{vt}@})
## @deftypefnx {} {@var{p} =} cagd_nrbeval (@var{vol}, @{@var{ut}, @var{vt}, @var{wt}@})
## @deftypefnx {} {@var{p} =} cagd_nrbeval (@var{srf}, @var{pts})
## @deftypefnx {} {[@var{p}, @var{w}] =} cagd_nrbeval (@dots{})
## Evaluate a NURBS curve, surface or volume: a drop-in replacement of octave-nurbs'
## @code{nrbeval}, with the same arguments and the same sizes of the results.
##
## The NURBS is a structure from @code{nrbmak}, @code{nrbcirc}, @code{nrbcoons},
## @code{nrbtestsrf}, @dots{} (fields @code{form = "B-NURBS"}, @code{coefs} @math{4 × n1 × …}
## homogeneous, @code{knots} (a vector, or a cell of two or three), @code{order}).
## @itemize
## @item curve, parameters @var{ut} of any size: @var{p} is @math{3 × numel (ut)} for a row
## (otherwise @code{[3, size(ut)]}), @var{w} is the size of @var{ut};
## @item surface or volume on a grid @code{@{ut, vt@}} / @code{@{ut, vt, wt@}}: @var{p} is
## @math{3 × nu × nv (× nw)}, @code{p(:, i, j)} the point at @code{(ut(i), vt(j))};
## @item surface or volume at scattered points @var{pts} (@math{2 × n} or @math{3 × n};
## @math{n × 2} is transposed as @code{nrbeval} does): @var{p} is @math{3 × n}.
## @end itemize
## With two outputs @var{p} holds the homogeneous coordinates (w·x, w·y, w·z) and @var{w} the
## weights, as @code{nrbeval}.
##
## The values agree with @code{nrbeval} to rounding (the tests ask 1e-13 relative; most agree
## bit for bit); a surface grid is computed as one tensor-product sweep, not by two calls of
## @code{bspeval}.  One difference: a parameter outside the domain of the knots is an error
## (@code{cagd:domain}) where @code{nrbeval} extrapolates.
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
## @seealso{cagd_bspeval, cagd_basisfun, cagd_findspan, cagd_nurbs}
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
%! if (exist ("nrbmak"))
%!   s = nrbtestsrf ();
%!   tt = {linspace(0, 1, 7), linspace(0, 1, 5)};
%!   assert (cagd_nrbeval (s, tt), nrbeval (s, tt), 1e-13 * max (abs (s.coefs(:))));
%!   [p1, w1] = cagd_nrbeval (s, tt); [p2, w2] = nrbeval (s, tt);
%!   assert (p1, p2, 1e-12); assert (w1, w2, 1e-14);
%! endif
%!error <NURBS: double is not a NURBS structure> cagd_nrbeval (1, 0.5)
%!error <has no field 'coefs'> cagd_nrbeval (struct ("form", "B-NURBS", "knots", [0 1], "order", 1), 0.5)
%!error <outside the domain> cagd_nrbeval (crv, 1.5)
%!error <weights must be positive> cagd_nrbeval (setfield (crv, "coefs", [1 0 0; 0 0 1; 0 0 0; 1 0 1]), 0.5)

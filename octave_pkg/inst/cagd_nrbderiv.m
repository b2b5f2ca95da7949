## -*- texinfo -*-
## @deftypefn  {} {@var{ders} =} cagd_nrbderiv (@var{nrb})
## @deftypefnx {} {[@var{ders}, @var{ders2}, @var{ders3}, @var{ders4}] =} cagd_nrbderiv (@var{nrb})
## The NURBS structures of the derivatives of a NURBS curve, surface or volume:
## octave-nurbs' @code{nrbderiv}, argument for argument.
##
## Each structure holds the homogeneous coefficients differentiated along one direction
## (@code{cagd_bspderiv}), so its weights are derivatives of the weights — of any sign;
## @code{cagd_nrbdeval} (or @code{nrbdeval}) turns them into derivatives of the cartesian
## points.  For a curve @var{ders} is a structure; for a surface or volume a cell of one
## structure per direction, @var{ders2} a @math{D × D} cell (@code{ders2@{i, j@}}),
## @var{ders3} @math{D × D × D}, @var{ders4} @math{D × D × D × D}.  With two or more outputs
## the NURBS is first raised to degree @code{nargout} in every direction where it is lower,
## as @code{nrbderiv} does, and octave-nurbs' warning @code{nrbderiv:SecondDerivative} is
## given when a second-derivative structure has Inf or NaN coefficients.
##
## Differences from octave-nurbs 1.4.3: none in the values; errors carry @code{cagd:}
## identifiers.
##
## Example:
## @example
## @group
## line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
##                "coefs", [0 2; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
## cagd_nrbderiv (line).coefs
##   @result{} [2; 0; 0; 0]
## @end group
## @end example
## @seealso{cagd_nrbdeval, cagd_bspderiv}
## @end deftypefn

function varargout = cagd_nrbderiv (nurbs)
  if (nargin != 1)
    print_usage ();
  endif
  nout = max (nargout, 1);
  dirs = 1;
  curve = true;
  if (isstruct (nurbs) && isfield (nurbs, "knots") && iscell (nurbs.knots))
    dirs = columns (nurbs.knots);
    curve = false;
  endif
  per = 3 + dirs;
  out = cell (1, 1 + per * sum (dirs .^ (1:nout)));
  [out{:}] = __cagd__ ("cagd_nrbderiv", nurbs, nout);
  at = 1;
  varargout = cell (1, nout);
  for r = 1:nout
    if (curve)
      varargout{r} = __cagd_nrb__ (out{at+1:at+per});
      at += per;
      continue;
    endif
    ## Octave's loops of nrbderiv fill ders_r{i1, ..., ir} with ir fastest.
    if (r == 1), sz = [1 dirs]; else, sz = repmat (dirs, 1, r); endif
    c = cell (sz);
    for p = 0:dirs^r - 1
      subs = mod (floor (p ./ dirs .^ (r-1:-1:0)), dirs) + 1;
      c{sub2ind_ (sz, subs)} = __cagd_nrb__ (out{at+1:at+per});
      at += per;
    endfor
    varargout{r} = c;
  endfor
  if (nout >= 2 && out{1})
    warning ("nrbderiv:SecondDerivative", ...
             ["The structure for the second derivative contains Inf and/or NaN coefficients, " ...
              "probably due to low continuity at repeated knots. This should not affect the " ...
              "computation of the second derivatives, except at those knots."]);
  endif
endfunction

function k = sub2ind_ (sz, subs)
  if (numel (subs) == 1)
    k = subs;
  else
    c = num2cell (subs);
    k = sub2ind (sz, c{:});
  endif
endfunction

%!test
%! line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
%!                "coefs", [0 2; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
%! d = cagd_nrbderiv (line);
%! assert (d.coefs, [2; 0; 0; 0]);
%! assert (d.knots, [0 1]);
%!test
%! ## The derivative of a circle arc by cagd_nrbdeval: tangent to the circle.
%! h = sqrt (2) / 2;
%! arc = struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
%!               "coefs", [1 h 0; 0 h 1; 0 0 0; 1 h 1], "knots", [0 0 0 1 1 1], "order", 3);
%! d = cagd_nrbderiv (arc);
%! [p, dp] = cagd_nrbdeval (arc, d, linspace (0, 1, 7));
%! assert (sum (p .* dp), zeros (1, 7), 1e-14);
%! assert (min (d.coefs(4,:)) < 0);     % weights of the derivative change sign
%!test
%! ## Surfaces: cells of structures, ders2 2 x 2.
%! c = zeros (4, 3, 3); [c(1,:,:), c(2,:,:)] = ndgrid ([0 .5 1]); c(4,:,:) = 1;
%! s = struct ("form", "B-NURBS", "dim", 4, "number", [3 3], "coefs", c, ...
%!             "knots", {{[0 0 0 1 1 1], [0 0 0 1 1 1]}}, "order", [3 3]);
%! [d, d2] = cagd_nrbderiv (s);
%! assert (size (d), [1 2]);
%! assert (size (d2), [2 2]);

%!demo
%! ## Tangents along a quarter circle from cagd_nrbderiv and cagd_nrbdeval.
%! h = sqrt (2) / 2;
%! arc = struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
%!               "coefs", [1 h 0; 0 h 1; 0 0 0; 1 h 1], "knots", [0 0 0 1 1 1], "order", 3);
%! [p, dp] = cagd_nrbdeval (arc, cagd_nrbderiv (arc), linspace (0, 1, 9));
%! q = cagd_nrbeval (arc, linspace (0, 1, 50));
%! plot (q(1,:), q(2,:), "k"); hold on;
%! quiver (p(1,:), p(2,:), dp(1,:), dp(2,:), 0.3); hold off; axis equal;
%! title ("cagd\\_nrbderiv: tangents of a quarter circle");

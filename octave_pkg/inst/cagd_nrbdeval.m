## -*- texinfo -*-
## @deftypefn  {} {[@var{pnt}, @var{jac}] =} cagd_nrbdeval (@var{crv}, @var{dcrv}, @var{tt})
## @deftypefnx {} {[@var{pnt}, @var{jac}, @var{hess}] =} cagd_nrbdeval (@var{nrb}, @var{dnrb}, @var{dnrb2}, @var{tt})
## @deftypefnx {} {[@var{pnt}, @var{jac}, @var{hess}, @var{third}, @var{fourth}] =} cagd_nrbdeval (@var{nrb}, @var{dnrb}, @var{dnrb2}, @var{dnrb3}, @var{dnrb4}, @var{tt})
## Points and derivatives of a NURBS curve, surface or volume from the structures of
## @code{cagd_nrbderiv} (or @code{nrbderiv}): octave-nurbs' @code{nrbdeval}, argument for
## argument.
##
## The homogeneous values of @var{nrb} and of each derivative structure at @var{tt} (any
## form @code{cagd_nrbeval} takes) are combined by the quotient rule in @code{nrbdeval}'s
## formulas: @var{pnt} @math{= c/w}, @var{jac} @math{= (c' - w' pnt)/w} (a cell of one array
## per direction for surfaces and volumes; for a curve a cell when @var{tt} is a cell),
## @var{hess}, @var{third}, @var{fourth} likewise (cells @code{@{i, j@}}, …).  As there, an
## output of a surface or volume whose structures were not given is @code{[]} with
## octave-nurbs' warning, and third and fourth derivatives of volumes are @code{[]}.  The
## sizes follow @code{nrbdeval}'s own indexing @code{w(ones (3, 1), :)}: for a curve at a
## column of parameters every point is divided by the first weight, as there.
##
## Differences from octave-nurbs 1.4.3: none in the values; errors carry @code{cagd:}
## identifiers.
##
## Example:
## @example
## @group
## line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
##                "coefs", [0 2; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
## [p, dp] = cagd_nrbdeval (line, cagd_nrbderiv (line), [0 0.5])
##   @result{} p = [0 1; 0 0; 0 0], dp = [2 2; 0 0; 0 0]
## @end group
## @end example
## @seealso{cagd_nrbderiv, cagd_nrbeval}
## @end deftypefn

function varargout = cagd_nrbdeval (varargin)
  nout = max (nargout, 1);
  nurbs = varargin{1};
  if (nout <= 2 && nargin >= 1 && isstruct (nurbs) && ! iscell (nurbs.knots) && ! iscell (varargin{end}))
    ## A curve at an array of parameters: the points and first derivatives, no cells.
    [~, p, d] = __cagd__ ("cagd_nrbdeval", varargin{:}, 2);
    varargout = {p, d};
    return;
  endif
  dirs = 1;
  if (isstruct (nurbs) && isfield (nurbs, "knots") && iscell (nurbs.knots))
    dirs = columns (nurbs.knots);
  endif
  counts = [1, 1, dirs, dirs^2, dirs^3, dirs^4];
  out = cell (1, sum (counts(1:nout+1)));
  [out{:}] = __cagd__ ("cagd_nrbdeval", varargin{:}, nout);
  status = out{1};
  curve = ! iscell (nurbs.knots);
  wrap = curve && iscell (varargin{end});
  varargout = cell (1, nout);
  varargout{1} = out{2};
  at = 3;
  names = {"jac", "hess", "third", "fourth"};
  for r = 1:min (nout - 1, 4)
    if (r > 1 && status(r-1) != 2)
      if (status(r-1) == 1)
        if (dirs == 3)
          if (r == 2)
            warning ("nrbdeval: dnurbs2 missing. The second derivative is not computed");
          elseif (r == 3)
            warning ("nrbdeval: 3rd and 4th order derivatives not implemented for volumes");
          endif
        else
          warning (sprintf ("nrbdeval: dnurbs%d missing. The %s derivative is not computed", ...
                            r, {"", "second", "third", "fourth"}{r}));
        endif
      endif
      varargout{r+1} = [];
      continue;
    endif
    n = dirs^r;
    if (curve)
      v = out{at};
      if (wrap), v = {v}; endif
    elseif (r == 1)
      v = out(at:at+n-1);
    else
      v = reshape (out(at:at+n-1), repmat (dirs, 1, r));
    endif
    varargout{r+1} = v;
    at += n;
  endfor
endfunction

%!test
%! line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
%!                "coefs", [0 2; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
%! [p, dp] = cagd_nrbdeval (line, cagd_nrbderiv (line), [0 0.5]);
%! assert (p, [0 1; 0 0; 0 0]);
%! assert (dp, [2 2; 0 0; 0 0]);
%!test
%! ## A parabola y = x^2 (x = u): second derivative (0, 2, 0).
%! par = struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
%!               "coefs", [0 .5 1; 0 0 1; 0 0 0; 1 1 1], "knots", [0 0 0 1 1 1], "order", 3);
%! [d, d2] = cagd_nrbderiv (par);
%! [p, dp, d2p] = cagd_nrbdeval (par, d, d2, [0.2 0.7]);
%! assert (p(2,:), [0.04 0.49], 1e-15);
%! assert (d2p, [0 0; 2 2; 0 0], 1e-13);
%!test
%! ## A surface at scattered points; the Hessian of a surface without dnrb2 is [] (warning).
%! c = zeros (4, 2, 2); c(1,:,:) = [0 0; 1 1]; c(2,:,:) = [0 1; 0 1]; c(3,:,:) = [0 0; 0 1]; c(4,:,:) = 1;
%! s = struct ("form", "B-NURBS", "dim", 4, "number", [2 2], "coefs", c, ...
%!             "knots", {{[0 0 1 1], [0 0 1 1]}}, "order", [2 2]);
%! [p, jac] = cagd_nrbdeval (s, cagd_nrbderiv (s), [0.5; 0.25]);
%! assert (jac{1}, [1; 0; 0.25], 1e-15);
%! assert (jac{2}, [0; 1; 0.5], 1e-15);
%! warning ("off", "all", "local");
%! [p, jac, h] = cagd_nrbdeval (s, cagd_nrbderiv (s), [0.5; 0.25]);
%! assert (h, []);

%!demo
%! ## Tangents over octave-nurbs' test surface (as nrbdeval's own demo).
%! if (exist ("nrbtestsrf"))
%!   srf = nrbtestsrf ();
%!   p = cagd_nrbeval (srf, {linspace(0, 1, 20), linspace(0, 1, 20)});
%!   surf (squeeze (p(1,:,:)), squeeze (p(2,:,:)), squeeze (p(3,:,:)));
%!   tt = linspace (0, 1, 5);
%!   [p1, dp] = cagd_nrbdeval (srf, cagd_nrbderiv (srf), {tt, tt});
%!   hold on;
%!   quiver3 (p1(1,:), p1(2,:), p1(3,:), dp{1}(1,:), dp{1}(2,:), dp{1}(3,:));
%!   quiver3 (p1(1,:), p1(2,:), p1(3,:), dp{2}(1,:), dp{2}(2,:), dp{2}(3,:));
%!   hold off; title ("cagd\\_nrbdeval: first derivatives over nrbtestsrf");
%! endif

## -*- texinfo -*-
## @deftypefn  {} {@var{ecrv} =} cagd_nrbdegelev (@var{crv}, @var{utimes})
## @deftypefnx {} {@var{esrf} =} cagd_nrbdegelev (@var{srf}, [@var{utimes}, @var{vtimes}])
## @deftypefnx {} {@var{evol} =} cagd_nrbdegelev (@var{vol}, [@var{utimes}, @var{vtimes}, @var{wtimes}])
## Raise the degree of a NURBS curve, surface or volume: octave-nurbs' @code{nrbdegelev},
## argument for argument.
##
## Each direction's degree is raised by @code{cagd_bspdegelev} on the homogeneous
## coefficients (the last direction first, as @code{nrbdegelev}; a direction with 0 is left
## as it is) and the structure is rebuilt as @code{nrbmak} builds it.  As there, the sizes of
## a surface or volume are those of its @code{coefs}, knot vectors not clamped at their end
## fail, and the coefficients and knots keep their classes.
##
## Differences from octave-nurbs 1.4.3: with single, integer or logical coefficients or
## knots octave-nurbs computes in that class's arithmetic; this computes in double and
## converts the results once.  Errors carry @code{cagd:} identifiers.
##
## Example:
## @example
## @group
## line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
##                "coefs", [0 1; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
## cagd_nrbdegelev (line, 1).coefs(1,:)
##   @result{} [0 0.5 1]
## @end group
## @end example
## @seealso{cagd_bspdegelev, cagd_nrbkntins, cagd_nrbeval}
## @end deftypefn

function inurbs = cagd_nrbdegelev (varargin)
  out = cell (1, 6);
  [out{:}] = __cagd__ ("cagd_nrbdegelev", varargin{:});
  inurbs = __cagd_nrb__ (out{:});
  nurbs = varargin{1};
  if (! isa (nurbs.coefs, "double") && (isnumeric (nurbs.coefs) || islogical (nurbs.coefs)))
    inurbs.coefs = cast (inurbs.coefs, class (nurbs.coefs));
  endif
  if (iscell (nurbs.knots))
    for k = 1:numel (inurbs.knots)
      if (! isa (nurbs.knots{k}, "double"))
        inurbs.knots{k} = cast (inurbs.knots{k}, class (nurbs.knots{k}));
      endif
    endfor
  elseif (! isa (nurbs.knots, "double"))
    inurbs.knots = cast (inurbs.knots, class (nurbs.knots));
  endif
endfunction

%!test
%! line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
%!                "coefs", [0 1; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
%! r = cagd_nrbdegelev (line, 1);
%! assert (r.coefs(1,:), [0 0.5 1], 1e-15);
%! assert (r.knots, [0 0 0 1 1 1]);
%! assert ([r.number r.order], [3 3]);
%!test
%! ## A rational surface raised (1, 2): the same surface.
%! c = rand (4, 3, 4); c(4,:,:) = 0.5 + rand (1, 3, 4); c(1:3,:,:) .*= c([4 4 4],:,:);
%! s = struct ("form", "B-NURBS", "dim", 4, "number", [3 4], "coefs", c, ...
%!             "knots", {{[0 0 0 1 1 1], [0 0 0 .5 1 1 1]}}, "order", [3 3]);
%! r = cagd_nrbdegelev (s, [1 2]);
%! assert (r.order, [4 5]);
%! tt = {linspace(0, 1, 7), linspace(0, 1, 5)};
%! assert (cagd_nrbeval (r, tt), cagd_nrbeval (s, tt), 1e-13);

%!demo
%! ## octave-nurbs' test curve raised by one degree: the same curve, more control points.
%! if (exist ("nrbtestcrv"))
%!   crv = nrbtestcrv ();
%!   icrv = cagd_nrbdegelev (crv, 1);
%!   p = cagd_nrbeval (icrv, linspace (0, 1, 100));
%!   plot (crv.coefs(1,:), crv.coefs(2,:), "bo--", icrv.coefs(1,:), icrv.coefs(2,:), "rs-", p(1,:), p(2,:), "k");
%!   title ("cagd\\_nrbdegelev: degree elevation of nrbtestcrv");
%! endif

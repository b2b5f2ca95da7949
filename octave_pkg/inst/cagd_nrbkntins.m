## -*- texinfo -*-
## @deftypefn  {} {@var{icrv} =} cagd_nrbkntins (@var{crv}, @var{iuknots})
## @deftypefnx {} {@var{isrf} =} cagd_nrbkntins (@var{srf}, @{@var{iuknots}, @var{ivknots}@})
## @deftypefnx {} {@var{ivol} =} cagd_nrbkntins (@var{vol}, @{@var{iuknots}, @var{ivknots}, @var{iwknots}@})
## Insert knots into a NURBS curve, surface or volume: octave-nurbs' @code{nrbkntins},
## argument for argument.
##
## The knots of each direction are inserted by @code{cagd_bspkntins} into the homogeneous
## coefficients (the last direction first, as @code{nrbkntins}), and the structure is rebuilt
## as @code{nrbmak} builds it (fields @code{form}, @code{dim}, @code{number}, @code{coefs},
## @code{knots}, @code{order}).  An empty array leaves its direction as it is.  As there,
## knots outside a direction's knot range are an error ("Trying to insert a knot outside the
## interval of definition"), knots may be inserted at the ends of the range and beyond the
## order (zero basis functions), and the coefficients become double.
##
## Differences from octave-nurbs 1.4.3: none in the values of double knots.  With single or
## integer knots to insert octave-nurbs computes in that class's arithmetic, rounding at each
## step (integers: to whole numbers); this computes with their values in double.  Errors
## carry @code{cagd:} identifiers.
##
## Example:
## @example
## @group
## line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
##                "coefs", [0 1; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
## cagd_nrbkntins (line, 0.5).coefs
##   @result{} [0 0.5 1; 0 0 0; 0 0 0; 1 1 1]
## @end group
## @end example
## @seealso{cagd_bspkntins, cagd_nrbdegelev, cagd_nrbeval}
## @end deftypefn

function inurbs = cagd_nrbkntins (varargin)
  out = cell (1, 6);
  [out{:}] = __cagd__ ("cagd_nrbkntins", varargin{:});
  inurbs = __cagd_nrb__ (out{:});
  ## Directions without inserted knots keep their knots' class (nrbmak does not convert).
  [nurbs, iknots] = varargin{:};
  if (iscell (nurbs.knots))
    for k = 1:numel (inurbs.knots)
      if (isempty (iknots{k}) && ! isa (nurbs.knots{k}, "double"))
        inurbs.knots{k} = cast (inurbs.knots{k}, class (nurbs.knots{k}));
      endif
    endfor
    if (all (cellfun (@isempty, iknots)) && ! isa (nurbs.coefs, "double"))
      inurbs.coefs = cast (inurbs.coefs, class (nurbs.coefs));
    endif
  elseif (isempty (iknots))
    inurbs.knots = cast (inurbs.knots, class (nurbs.knots));
    inurbs.coefs = cast (inurbs.coefs, class (nurbs.coefs));
  endif
endfunction

%!test
%! line = struct ("form", "B-NURBS", "dim", 4, "number", 2, ...
%!                "coefs", [0 1; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2);
%! r = cagd_nrbkntins (line, 0.5);
%! assert (r.coefs, [0 0.5 1; 0 0 0; 0 0 0; 1 1 1]);
%! assert (r.knots, [0 0 0.5 1 1]);
%! assert ([r.number r.order], [3 2]);
%!test
%! ## A rational surface: the same surface after insertion in both directions.
%! c = rand (4, 3, 4); c(4,:,:) = 0.5 + rand (1, 3, 4); c(1:3,:,:) .*= c([4 4 4],:,:);
%! s = struct ("form", "B-NURBS", "dim", 4, "number", [3 4], "coefs", c, ...
%!             "knots", {{[0 0 0 1 1 1], [0 0 0 .5 1 1 1]}}, "order", [3 3]);
%! r = cagd_nrbkntins (s, {[0.3 0.3], []});
%! assert (r.number, [5 4]);
%! tt = {linspace(0, 1, 7), linspace(0, 1, 5)};
%! assert (cagd_nrbeval (r, tt), cagd_nrbeval (s, tt), 1e-13);
%!error <outside the interval of definition> cagd_nrbkntins (struct ("form", "B-NURBS", "dim", 4, "number", 2, "coefs", [0 1; 0 0; 0 0; 1 1], "knots", [0 0 1 1], "order", 2), 1.5)

%!demo
%! ## Knots inserted into octave-nurbs' test curve: the curve stays, its polygon changes.
%! if (exist ("nrbtestcrv"))
%!   crv = nrbtestcrv ();
%!   icrv = cagd_nrbkntins (crv, [0.125 0.375 0.625 0.875]);
%!   p = cagd_nrbeval (crv, linspace (0, 1, 100));
%!   plot (crv.coefs(1,:), crv.coefs(2,:), "bo--", icrv.coefs(1,:), icrv.coefs(2,:), "rs-", p(1,:), p(2,:), "k");
%!   title ("cagd\\_nrbkntins: knot insertion along nrbtestcrv");
%! endif

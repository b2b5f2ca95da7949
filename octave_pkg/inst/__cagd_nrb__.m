## -*- texinfo -*-
## @deftypefn {} {@var{nrb} =} __cagd_nrb__ (@var{coefs}, @var{order}, @var{number}, @var{k1}, @dots{})
## Internal: the NURBS structure octave-nurbs' @code{nrbmak} builds, from the arrays the
## package's twins compute (fields @code{form}, @code{dim}, @code{number}, @code{coefs},
## @code{knots}, @code{order} in nrbmak's order; @code{knots} a vector for a curve, a cell of
## @code{numel (order)} vectors otherwise).
## @end deftypefn

function nrb = __cagd_nrb__ (coefs, order, number, varargin)
  if (numel (order) == 1)
    knots = varargin{1};
  else
    knots = varargin(1:numel (order));
  endif
  nrb = struct ("form", "B-NURBS", "dim", 4, "number", number, "coefs", coefs, ...
                "knots", [], "order", order);
  nrb.knots = knots;
endfunction

%!test
%! n = __cagd_nrb__ (ones (4, 2, 3), [2 3], [2 3], [0 0 1 1], [0 0 0 1 1 1]);
%! assert (fieldnames (n), {"form"; "dim"; "number"; "coefs"; "knots"; "order"});
%! assert (iscell (n.knots) && numel (n.knots) == 2);
%! assert (__cagd_nrb__ (ones (4, 2), 2, 2, [0 0 1 1]).knots, [0 0 1 1]);

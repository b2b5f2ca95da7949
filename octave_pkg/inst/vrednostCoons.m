## -*- texinfo -*-
## @deftypefn  {} {[@var{T}, @var{rc}, @var{rd}, @var{rcd}] =} vrednostCoons (@var{u}, @var{v}, @var{c1}, @var{c2}, @var{d1}, @var{d2}, @var{P1}, @var{P2}, @var{P3}, @var{P4})
## @deftypefnx {} {} vrednostCoons (@dots{})
## The point of the bilinearly blended Coons patch at @math{(u, v)} from the values of its
## boundary curves there, with its three parts: the thesis's @code{vrednostCoons} (appendix C,
## Algoritem 6), fixed.
##
## @table @var
## @item u, v
## the parameters (scalars);
## @item c1, c2
## @math{d × 1}: @math{c1(u) = x(u,0)}, @math{c2(u) = x(u,1)};
## @item d1, d2
## @math{d × 1}: @math{d1(v) = x(0,v)}, @math{d2(v) = x(1,v)};
## @item P1 @dots{} P4
## @math{d × 1}: the corners @math{x(0,0), x(1,0), x(0,1), x(1,1)};
## @item T
## the point @math{x(u,v) = rc + rd - rcd} (Izrek 4.2);
## @item rc, rd, rcd
## its parts @math{(1-v) c1 + v c2}, @math{(1-u) d1 + u d2} and the corner blend, eqs.
## (4.1)--(4.3).
## @end table
##
## Called without an output argument it displays @code{T = @dots{}}, as the original did.
## Fixed in the original: it returned nothing.
##
## Example (thesis Primer 4.3, the result (0.2, 0.3, 0.38)):
## @example
## @group
## u = 0.2; v = 0.5;
## T = vrednostCoons (u, v, [u;0;u-u^2], [u;1;u], [0;v^2;v-v^2], [1;v;v], ...
##                    [0;0;0], [1;0;0], [0;1;0], [1;1;1])
##   @result{} T = [0.2; 0.3; 0.38]
## @end group
## @end example
## @seealso{krpaCoons, cagd_coons}
## @end deftypefn

function [T, rc, rd, rcd] = vrednostCoons (varargin)
  [T, rc, rd, rcd] = __cagd__ ("vrednostCoons", varargin{:});
  if (nargout == 0)
    T
    clear T rc rd rcd;
  endif
endfunction

%!test
%! u = 0.2; v = 0.5;
%! [T, rc, rd, rcd] = vrednostCoons (u, v, [u;0;u-u^2], [u;1;u], [0;v^2;v-v^2], [1;v;v], ...
%!                                  [0;0;0], [1;0;0], [0;1;0], [1;1;1]);
%! assert (T, [0.2; 0.3; 0.38], 1e-15);
%! assert (rc, [0.2; 0.5; 0.18], 1e-15);
%! assert (rd, [0.2; 0.3; 0.3], 1e-15);
%! assert (rcd, [0.2; 0.5; 0.1], 1e-15);
%! assert (T, rc + rd - rcd);
%!test
%! ## Any dimension: a plane rectangle, extrapolated at u = 1.5.
%! T = vrednostCoons (1.5, 0.25, [3;0], [3;1], [0;0.25], [2;0.25], [0;0], [2;0], [0;1], [2;1]);
%! assert (T, [3; 0.25]);
%!error <corners> vrednostCoons (0, 0.5, [1;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0])
%!error <d2: expected a 3×1 column> vrednostCoons (0.5, 0.5, [0;0;0], [0;0;0], [0;0;0], [0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0])
%!error <u: complex double is not accepted> vrednostCoons (1i, 0.5, [0;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0], [0;0;0])
## (1 - u) c1 + u c2 at u = 1e300 of unit vectors: Inf - Inf in the sum, refused.
%!error id=cagd:overflow vrednostCoons (1e300, 1e300, [0;0;0], [1;0;0], [0;0;0], [0;1;0], [0;0;0], [0;1;0], [1;0;0], [1;1;0])

%!demo
%! ## Thesis Primer 4.3: the point x(0.2, 0.5) = (0.2, 0.3, 0.38) and its three parts.
%! u = 0.2; v = 0.5;
%! [T, rc, rd, rcd] = vrednostCoons (u, v, [u;0;u-u^2], [u;1;u], [0;v^2;v-v^2], [1;v;v], ...
%!                                   [0;0;0], [1;0;0], [0;1;0], [1;1;1]);
%! printf ("x = rc + rd - rcd:\n"); disp ([T, rc, rd, rcd]);

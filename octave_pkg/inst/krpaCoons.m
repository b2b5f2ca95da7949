## -*- texinfo -*-
## @deftypefn  {} {[@var{R}, @var{P}] =} krpaCoons (@var{c1}, @var{c2}, @var{d1}, @var{d2}, @var{P1}, @var{P2}, @var{P3}, @var{P4})
## @deftypefnx {} {} krpaCoons (@dots{})
## The bilinearly blended Coons patch of four sampled boundary curves on
## @code{linspace (0, 1, N)} in both directions: the thesis's @code{krpaCoons} (appendix C,
## Algoritem 5), fixed.
##
## @example
## x(u,v) = (1-v) c1(u) + v c2(u) + (1-u) d1(v) + u d2(v)
##          - [(1-u)(1-v) P1 + u(1-v) P2 + (1-u) v P3 + u v P4]      (Izrek 4.2)
## @end example
##
## @table @var
## @item c1, c2
## @math{3 × N}: the curves @math{x(u,0)}, @math{x(u,1)} sampled at @code{u = linspace (0, 1, N)};
## @item d1, d2
## @math{3 × N}: the curves @math{x(0,v)}, @math{x(1,v)} sampled at @code{v = linspace (0, 1, N)};
## @item P1 @dots{} P4
## @math{3 × 1}: the corners @math{x(0,0), x(1,0), x(0,1), x(1,1)};
## @item R
## @math{N × 3N}, packed: @code{R(i, 3*j-2:3*j) = x(u(i), v(j))'};
## @item P
## @math{N × N × 3}: @code{P(i,j,:) = x(u(i), v(j))} (@code{tenzor (R)}).
## @end table
##
## The grid is computed by the core's grid evaluation of the Coons patch (the formula
## regrouped per row); it agrees with @file{octave_ref/fixed/krpaCoons.m} within 4 ULPs or
## 1e-14 of the largest coordinate.
##
## Called without an output argument it draws what the original drew: the patch
## (@code{surf}) and the boundary curves, @var{c1}, @var{c2} in red and @var{d1}, @var{d2} in
## green.
##
## Fixed in the original: @var{N} was never defined; @var{R} and @var{P} are returned.  The
## corners must be where the curves meet (relative tolerance 1e-10; @code{cagd:corners}):
## appendix C's data script sets @code{P3} twice and never @code{P4}.
##
## Example (the unit square with straight sides):
## @example
## @group
## t = linspace (0, 1, 3); o = ones (1, 3); z = zeros (1, 3);
## [R, P] = krpaCoons ([t; z; z], [t; o; z], [z; t; z], [o; t; z], ...
##                     [0;0;0], [1;0;0], [0;1;0], [1;1;0]);
## R(2,:)
##   @result{} [0.5 0 0  0.5 0.5 0  0.5 1 0]
## @end group
## @end example
## @seealso{vrednostCoons, cagd_coons}
## @end deftypefn

function [R, P] = krpaCoons (varargin)
  [R, P] = __cagd__ ("krpaCoons", varargin{:});
  if (nargout == 0)
    __cagd_draw__ ("coons", P, varargin{1:4});
    clear R P;
  endif
endfunction

%!shared c1, c2, d1, d2, P1, P2, P3, P4
%! N = 5; u = linspace (0, 1, N); v = u;
%! c1 = [u; zeros(1,N); u - u.^2];
%! c2 = [u; ones(1,N); u];
%! d1 = [zeros(1,N); v.^2; v - v.^2];
%! d2 = [ones(1,N); v; v];
%! P1 = [0;0;0]; P2 = [1;0;0]; P3 = [0;1;0]; P4 = [1;1;1];
%!test
%! [R, P] = krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4);
%! assert (size (R), [5 15]);
%! assert (size (P), [5 5 3]);
%! assert (squeeze (P(1,:,:)), d1');
%! assert (squeeze (P(:,5,:)), c2');
%! assert (R(3, 7:9), squeeze (P(3,3,:))');
%!test
%! f = figure ("visible", "off");
%! unwind_protect
%!   krpaCoons (c1, c2, d1, d2, P1, P2, P3, P4);
%!   assert (numel (get (gca, "children")), 5);
%! unwind_protect_cleanup
%!   close (f);
%! end_unwind_protect
%!error <corners> krpaCoons (c1, c2, d1, d2, P1, P2, [1;1;1], P4)
%!error <d2: expected 3×5> krpaCoons (c1, c2, d1, d2(:,1:4), P1, P2, P3, P4)
%!error <P4: empty> krpaCoons (c1, c2, d1, d2, P1, P2, P3, [])

%!demo
%! ## Appendix C of the thesis, drawn by krpaCoons itself (no output argument): the patch
%! ## with its boundary curves c1, c2 (red) and d1, d2 (green).
%! N = 25; u = linspace (0, 1, N); v = u;
%! c1 = [u; zeros(1, N); u - u.^2]; c2 = [u; ones(1, N); u];
%! d1 = [zeros(1, N); v.^2; v - v.^2]; d2 = [ones(1, N); v; v];
%! krpaCoons (c1, c2, d1, d2, [0;0;0], [1;0;0], [0;1;0], [1;1;1]);
%! title ("krpaCoons: the appendix C patch");

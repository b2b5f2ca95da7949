## -*- texinfo -*-
## @deftypefn  {} {@var{P} =} ploskevB (@var{kontrolneT}, @var{N})
## @deftypefnx {} {} ploskevB (@var{kontrolneT}, @var{N})
## The Bézier patch with the packed control net @var{kontrolneT} sampled on
## @code{linspace (0, 1, @var{N})} in both directions: the thesis's @code{ploskevB}
## (appendix B, Algoritem 2), fixed.
##
## @var{kontrolneT} is the packed net @math{(m+1) × 3(n+1)}:
## @code{kontrolneT(i+1, 3*j+1:3*j+3)} is the control point @math{b_{i,j}} (as @code{tenzor}
## reads it); @math{m ≠ n} is allowed.  @var{P} is @math{N × N × 3}: @code{P(i,j,:)} is the
## point at @code{(u, v) = (t(i), t(j))}, @code{t = linspace (0, 1, N)}.
##
## The grid is computed by the core's grid evaluation (Bernstein rows, the net contracted once
## per row); it agrees with @file{octave_ref/fixed/ploskevB.m} within 4 ULPs or 1e-14 of the
## largest coordinate.
##
## Called without an output argument it draws the patch with @code{surf}, as the original did.
##
## Fixed in the original: it returned nothing, and (through @code{bilinearna}) was wrong for
## @math{m ≠ n}.
##
## Example (degree (1, 1), the hyperbolic paraboloid z = uv):
## @example
## @group
## B = [0 0 0  0 1 0; 1 0 0  1 1 1];
## P = ploskevB (B, 3);
## squeeze (P(2,2,:))'
##   @result{} [0.5 0.5 0.25]
## @end group
## @end example
## @seealso{bilinearna, tenzor, cagd_bezier_patch}
## @end deftypefn

function P = ploskevB (varargin)
  P = __cagd__ ("ploskevB", varargin{:});
  if (nargout == 0)
    __cagd_draw__ ("surface", P);
    clear P;
  endif
endfunction

%!test
%! B = [0 0 0  0 1 0; 1 0 0  1 1 1];
%! P = ploskevB (B, 3);
%! assert (size (P), [3 3 3]);
%! assert (squeeze (P(2,2,:))', [0.5 0.5 0.25]);
%! assert (squeeze (P(3,3,:))', [1 1 1]);
%!test
%! ## m ~= n: degree (0, 1) and (2, 0) nets.
%! P = ploskevB ([1 2 3 3 2 1], 2);
%! assert (squeeze (P(1,:,:)), [1 2 3; 3 2 1]);
%! assert (size (ploskevB ([0 0 0; 1 1 1; 2 2 2], 0)), [0 0 3]);
%!test
%! f = figure ("visible", "off");
%! unwind_protect
%!   ploskevB ([0 0 0  0 1 0; 1 0 0  1 1 1], 4);
%!   assert (get (get (gca, "children"), "type"), "surface");
%! unwind_protect_cleanup
%!   close (f);
%! end_unwind_protect
%!error <divisible by 3> ploskevB ([0 1 2 3], 3)
%!error <cagd_limits> ploskevB ([0 0 0], 1e5)

%!demo
%! ## A bicubic Bezier patch drawn by the thesis function (no output argument).
%! B = zeros (4, 12);
%! for i = 0:3, for j = 0:3, B(i+1, 3*j+1:3*j+3) = [i/3, j/3, mod(7*i + 3*j, 5)/4 - 1/2]; end, end
%! ploskevB (B, 30);
%! title ("ploskevB: a bicubic patch");

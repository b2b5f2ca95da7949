## -*- texinfo -*-
## @deftypefn {} {@var{L} =} bilinearna (@var{B}, @var{u}, @var{v}, @var{N})
## One point of the Bézier patch with the packed net @var{B} by the tensor de Casteljau
## algorithm (repeated bilinear interpolation): the thesis's @code{bilinearna} (appendix B,
## Algoritem 3), fixed.
##
## @var{B} is the packed net @math{(m+1) × 3(n+1)} (see @code{tenzor}), @math{m ≠ n} allowed;
## @var{u}, @var{v} are the parameters (outside [0, 1] the patch is extrapolated); @var{N} is
## accepted for the original's signature (it only sized a work array) and must be a
## non-negative integer.  @var{L} is @math{1 × 1 × 3}, the point @math{x(u, v)}.
##
## Fixed in the original: for @math{m ≠ n} it stopped after @math{m} bilinear steps (or ran
## steps that changed nothing), and for a degree-0 direction returned zeros; now
## @math{min(m,n)} bilinear steps are followed by @math{|m-n|} linear ones.
##
## Example:
## @example
## @group
## squeeze (bilinearna ([0 0 0  0 1 0; 1 0 0  1 1 1], 0.5, 0.5, 10))'
##   @result{} [0.5 0.5 0.25]
## @end group
## @end example
## @seealso{ploskevB, tenzor}
## @end deftypefn

function L = bilinearna (varargin)
  L = __cagd__ ("bilinearna", varargin{:});
endfunction

%!test
%! L = bilinearna ([0 0 0  0 1 0; 1 0 0  1 1 1], 0.5, 0.5, 10);
%! assert (size (L), [1 1 3]);
%! assert (squeeze (L)', [0.5 0.5 0.25]);
%!test
%! ## Degree (0, 1): the original returned zeros(1,1,3).
%! assert (squeeze (bilinearna ([1 2 3 3 2 1], 0.25, 0.5, 2))', [2 2 2]);
%!test
%! ## Degree (1, 2): b_{0,j} = (0, j/2, 0), b_{1,j} = (1, j/2, z_j), z = 0, 2, 0.
%! B = [0 0 0 0 0.5 0 0 1 0; 1 0 0 1 0.5 2 1 1 0];
%! assert (squeeze (bilinearna (B, 0.5, 0.5, 10))', [0.5 0.5 0.5]);
%!error <u: value 1 is not finite> bilinearna ([0 0 0], NaN, 0, 1)
%!error <B: logical is not accepted> bilinearna (true (1, 3), 0, 0, 1)
%!error id=cagd:overflow bilinearna ([0 0 0 1 0 0; 0 1 0 1 1 1], 1e308, 1e308, 3)

%!demo
%! ## The bilinear patch z = uv (thesis: bilinearna) on a 15 x 15 grid.
%! B = [0 0 0  0 1 0; 1 0 0  1 1 1];
%! L = bilinearna (B, 0, 0, 15);
%! surf (L(:,:,1), L(:,:,2), L(:,:,3)); title ("bilinearna: the hyperbolic paraboloid z = uv");

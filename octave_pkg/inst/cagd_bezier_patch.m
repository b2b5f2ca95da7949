## -*- texinfo -*-
## @deftypefn  {} {@var{X} =} cagd_bezier_patch (@var{B}, @var{u}, @var{v})
## @deftypefnx {} {@var{X} =} cagd_bezier_patch (@var{B}, @var{u}, @var{v}, "exact")
## The tensor-product Bézier patch with control net @var{B} on the grid @var{u} × @var{v}.
##
## @var{B} is @math{d × (m+1) × (n+1)}: @code{B(:, i+1, j+1)} is the control point
## @math{b_@{i,j@}} (octave-nurbs' layout of coefficients; @code{permute (tenzor (K), [3 1 2])}
## turns a thesis packed net @var{K} into it).  @var{X} is @math{d × numel (u) × numel (v)}:
## @code{X(:, i, j)} is @math{x(u(i), v(j)) = Σ_a Σ_b B_a^m(u) B_b^n(v) b_@{a,b@}}.
## With @code{"exact"}: exact fractions (see @code{cagd_bezier}).
##
## Example (z = uv):
## @example
## @group
## B = zeros (3, 2, 2);
## B(:,:,1) = [0 1; 0 0; 0 0]; B(:,:,2) = [0 1; 1 1; 0 1];
## squeeze (cagd_bezier_patch (B, 0.5, 0.5))'
##   @result{} [0.5 0.5 0.25]
## @end group
## @end example
## @seealso{ploskevB, cagd_coons}
## @end deftypefn

function X = cagd_bezier_patch (varargin)
  X = __cagd__ ("cagd_bezier_patch", varargin{:});
endfunction

%!shared B
%! B = zeros (3, 2, 2);
%! B(:,:,1) = [0 1; 0 0; 0 0]; B(:,:,2) = [0 1; 1 1; 0 1];
%!assert (squeeze (cagd_bezier_patch (B, 0.5, 0.5))', [0.5 0.5 0.25])
%!assert (size (cagd_bezier_patch (B, [0 0.5 1], [0 1])), [3 3 2])
%!assert (cagd_bezier_patch (B, 0.5, "1/3", "exact"), {"1/2"; "1/3"; "1/6"})
%!test
%! ## The thesis's packed net through tenzor, the same patch as ploskevB.
%! K = [0 0 0 0 1 0 0 2 0; 1 0 1 1 1 2 1 2 1; 2 0 0 2 1 1 2 2 0];
%! P = ploskevB (K, 4);
%! X = cagd_bezier_patch (permute (tenzor (K), [3 1 2]), linspace (0, 1, 4), linspace (0, 1, 4));
%! assert (permute (X, [2 3 1]), P, 1e-15);
%!error <B: an array of size 3×2×2×2> cagd_bezier_patch (zeros (3, 2, 2, 2), 0, 0)
%!error id=cagd:overflow cagd_bezier_patch (reshape ([1.7e308 -1.7e308 -1.7e308 1.7e308], 1, 2, 2), 5, 5)

%!demo
%! ## A bicubic Bezier patch on a 25 x 25 grid with its control net.
%! B = zeros (3, 4, 4);
%! for i = 0:3, for j = 0:3, B(:, i+1, j+1) = [i/3; j/3; mod(7*i + 3*j, 5)/4 - 1/2]; end, end
%! t = linspace (0, 1, 25); X = cagd_bezier_patch (B, t, t);
%! surf (squeeze (X(1,:,:)), squeeze (X(2,:,:)), squeeze (X(3,:,:))); hold on;
%! plot3 (B(1,:), B(2,:), B(3,:), "ro"); hold off; title ("cagd\_bezier\_patch: a bicubic patch");

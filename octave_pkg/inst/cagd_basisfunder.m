## -*- texinfo -*-
## @deftypefn {} {@var{ders} =} cagd_basisfunder (@var{ii}, @var{pl}, @var{uu}, @var{U}, @var{nd})
## The non-zero B-spline basis functions and their derivatives: octave-nurbs'
## @code{basisfunder}, argument for argument.
##
## @var{ii} are the knot spans (from @code{cagd_findspan}, from 0), @var{pl} the degree,
## @var{uu} the parameters (as many as spans), @var{U} the knots, @var{nd} the highest
## derivative order.  @var{ders} is @math{numel (uu) × (nd+1) × (pl+1)}:
## @code{ders(k, r+1, j+1)} is the @math{r}-th derivative of @math{N_@{s-pl+j,pl@}} at
## @code{uu(k)}, @math{s = ii(k)}, by The NURBS Book A2.3 in the operation order of
## @code{basisfunder}.  Orders above @var{pl} are zero.
##
## Differences from octave-nurbs 1.4.3: a span without the knots
## @math{U(s+2-pl) … U(s+1+pl)} is an error (@code{cagd:value}) where @code{basisfunder}
## reads outside its arrays.
##
## Example:
## @example
## @group
## squeeze (cagd_basisfunder (2, 2, 0.3, [0 0 0 .5 1 1 1], 1))
##   @result{} [0.16 0.66 0.18; -1.6 0.4 1.2]
## @end group
## @end example
## @seealso{cagd_basisfun, cagd_findspan, cagd_bspderiv}
## @end deftypefn

function ders = cagd_basisfunder (varargin)
  ders = __cagd__ ("cagd_basisfunder", varargin{:});
endfunction

%!test
%! ders = cagd_basisfunder (2, 2, 0.3, [0 0 0 .5 1 1 1], 1);
%! assert (size (ders), [1 2 3]);
%! assert (squeeze (ders), [0.16 0.66 0.18; -1.6 0.4 1.2], 1e-14);
%!test
%! ## Every derivative of a partition of unity sums to zero; orders above pl are zero.
%! k = [0 0 0 0 1/3 2/3 1 1 1 1]; u = rand (50, 1);
%! ders = cagd_basisfunder (cagd_findspan (5, 3, u, k), 3, u, k, 5);
%! assert (sum (ders(:, 1, :), 3), ones (50, 1), 1e-14);
%! assert (sum (ders(:, 2:4, :), 3), zeros (50, 3), 1e-11);
%! assert (ders(:, 5:6, :), zeros (50, 2, 4));
%!error <Invalid call to basisfunder> cagd_basisfunder ([2 2], 2, 0.3, [0 0 0 .5 1 1 1], 1)

%!demo
%! ## The cubic basis functions on [0 0 0 0 .5 1 1 1 1] and their first derivatives.
%! k = [0 0 0 0 .5 1 1 1 1]; u = linspace (0, 1, 201);
%! s = cagd_findspan (4, 3, u, k);
%! ders = cagd_basisfunder (s, 3, u, k, 1);
%! N = zeros (numel (u), 5); dN = N;
%! for i = 1:numel (u)
%!   N(i, s(i)-2:s(i)+1) = ders(i, 1, :); dN(i, s(i)-2:s(i)+1) = ders(i, 2, :);
%! end
%! subplot (2, 1, 1); plot (u, N); title ("cagd\\_basisfunder: N_{i,3}");
%! subplot (2, 1, 2); plot (u, dN); title ("their derivatives");

## -*- texinfo -*-
## @deftypefn {} {@var{A} =} tenzor (@var{B})
## The packed control net @var{B} as a 3-D array: the thesis's @code{tenzor} (appendix B,
## Algoritem 4), fixed.
##
## @var{B} is @math{(m+1) × 3(n+1)}: row @math{k} holds the points
## @math{b_{k-1,0}, @dots{}, b_{k-1,n}} one after the other as x y z triples,
## @code{B(k, 3*l-2:3*l)} = @math{b_{k-1,l-1}}.  @var{A} is @math{(m+1) × (n+1) × 3},
## @code{A(k,l,:) = B(k, 3*l-2:3*l)}.  The values are copied bit for bit.
##
## Fixed in the original: a number of columns that is not a multiple of 3 silently dropped
## the last columns; it is now an error (@code{cagd:shape}).
##
## Example:
## @example
## @group
## A = tenzor ([0 0 0 0 1 0; 1 0 0 1 1 1]);
## squeeze (A(2,2,:))'
##   @result{} [1 1 1]
## @end group
## @end example
## @seealso{ploskevB, bilinearna}
## @end deftypefn

function A = tenzor (varargin)
  A = __cagd__ ("tenzor", varargin{:});
endfunction

%!test
%! A = tenzor ([0 0 0 0 1 0; 1 0 0 1 1 1]);
%! assert (size (A), [2 2 3]);
%! assert (squeeze (A(2,2,:))', [1 1 1]);
%! assert (squeeze (A(1,2,:))', [0 1 0]);
%!test
%! B = reshape (1:36, 3, 12) - 7.5;
%! A = tenzor (B);
%! for k = 1:3
%!   for l = 1:4
%!     assert (squeeze (A(k,l,:))', B(k, 3*l-2:3*l));
%!   endfor
%! endfor
%!error <B: .*multiple of 3|divisible by 3> tenzor ([0 1 2 3])
%!error <B: a cell array is not accepted> tenzor ({1, 2, 3})

%!demo
%! ## The control net of the bilinear patch z = uv as tenzor returns it.
%! A = tenzor ([0 0 0  0 1 0; 1 0 0  1 1 1]);
%! plot3 (A(:,:,1)(:), A(:,:,2)(:), A(:,:,3)(:), "ro"); grid on;
%! title ("tenzor: the net as an (m+1) x (n+1) x 3 array");

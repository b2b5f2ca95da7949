## -*- texinfo -*-
## @deftypefn {} {@var{v} =} Lagrange (@var{x}, @var{m}, @var{u})
## The Lagrange basis polynomial @math{L_m} of the nodes @var{x} at every parameter of
## @var{u}: the thesis's @code{Lagrange} (appendix D, Algoritem 8), fixed.
##
## @example
## L_m(u) = prod_@{j ~= m@} (u - x(j)) / (x(m) - x(j))
## @end example
##
## @var{x} is a row (or column) of distinct nodes; @var{m} is the index of the basis
## polynomial, from 1 (the thesis calls it the degree; it is not); @var{u} is an array of any
## size, and @var{v} has its size.  The product is formed in the original's order, so the
## values are those of @file{octave_ref/fixed/Lagrange.m} bit for bit.
##
## Fixed in the original: the product started at zero, so the function always returned 0.
##
## Example:
## @example
## @group
## Lagrange ([0 0.5 1], 2, [0 0.25 0.5 1])
##   @result{} [0 0.75 1 0]
## @end group
## @end example
## @seealso{krpaGordon, cagd_gordon}
## @end deftypefn

function v = Lagrange (varargin)
  v = __cagd__ ("Lagrange", varargin{:});
endfunction

%!assert (Lagrange ([0 0.5 1], 2, [0 0.25 0.5 1]), [0 0.75 1 0])
%!assert (Lagrange ([0 0.5 1]', 1, [0; 1]), [1; 0])
%!assert (size (Lagrange ([0 1], 1, zeros (2, 3, 4))), [2 3 4])
%!error <m: expected the index of a node> Lagrange ([0 0.5 1], 4, 0.5)
%!error <nodes 1 and 2 are equal> Lagrange ([1 1], 1, 0.5)
%!error <u: value 2 is not finite> Lagrange ([0 1], 1, [0 Inf])
## L_1 of the nodes 0, 1, 2 at 1e300 is (1e300 - 1)(1e300 - 2)/2: beyond the doubles.
%!error id=cagd:overflow Lagrange ([0 1 2], 1, 1e300)

%!demo
%! ## The three quadratic Lagrange basis polynomials on the nodes 0, 1/2, 1.
%! x = [0 0.5 1]; u = linspace (0, 1, 101);
%! plot (u, Lagrange (x, 1, u), u, Lagrange (x, 2, u), u, Lagrange (x, 3, u));
%! legend ("L_1", "L_2", "L_3"); title ("Lagrange: the basis on the nodes 0, 1/2, 1");

## -*- texinfo -*-
## @deftypefn {} {@var{B} =} cagd_basisfun (@var{iv}, @var{uv}, @var{p}, @var{U})
## The non-zero B-spline basis functions: a drop-in replacement of octave-nurbs'
## @code{basisfun}.
##
## @var{iv} are the knot spans (from @code{cagd_findspan}, numbered from 0), @var{uv} the
## parameters (as many as spans), @var{p} the degree, @var{U} the knot vector.  @var{B} is
## @math{numel (uv) × (p+1)}: row @math{k} holds @math{N_@{s-p,p@}(u), …, N_@{s,p@}(u)} for
## @math{s = iv(k)}, @math{u = uv(k)}, in the operation order of @code{basisfun} (bit for bit).
## A span must be an integer @math{p ≤ s ≤ numel (U) - p - 2} with @math{U(s+1) < U(s+2)}.
##
## Example:
## @example
## @group
## U = [0 0 0 1/2 1 1 1];
## cagd_basisfun (cagd_findspan (3, 2, 0.25, U), 0.25, 2, U)
##   @result{} [0.25 0.625 0.125]
## @end group
## @end example
## @seealso{cagd_findspan, cagd_bspeval}
## @end deftypefn

function B = cagd_basisfun (varargin)
  B = __cagd__ ("cagd_basisfun", varargin{:});
endfunction

%!test
%! U = [0 0 0 1/2 1 1 1];
%! assert (cagd_basisfun (2, 0.25, 2, U), [0.25 0.625 0.125], 1e-15);
%! u = linspace (0, 1, 10);
%! B = cagd_basisfun (cagd_findspan (3, 2, u, U), u, 2, U);
%! assert (size (B), [10 3]);
%! assert (sum (B, 2), ones (10, 1), 1e-15);
%!error <one span per parameter> cagd_basisfun ([2 2], 0.5, 2, [0 0 0 1/2 1 1 1])
%!error <span 1 is not a non-empty knot span> cagd_basisfun (1, 0.5, 2, [0 0 0 1/2 1 1 1])

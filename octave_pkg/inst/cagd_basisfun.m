## -*- texinfo -*-
## @deftypefn {} {@var{B} =} cagd_basisfun (@var{iv}, @var{uv}, @var{p}, @var{U})
## The non-zero B-spline basis functions: octave-nurbs' @code{basisfun}, argument for
## argument.
##
## @var{iv} are the knot spans (from @code{cagd_findspan}, numbered from 0), @var{uv} the
## parameters, @var{p} the degree, @var{U} the knot vector (any real numeric classes).
## @var{B} is @math{numel (uv) × (p+1)}: row @math{k} holds
## @math{N_@{s-p,p@}(u), …, N_@{s,p@}(u)} for @math{s = iv(k)}, @math{u = uv(k)}, by the
## triangular scheme of The NURBS Book (A2.2) in the operation order of @code{basisfun}:
## the values agree bit for bit.  As there, a span is truncated toward zero and used as
## given (a span that does not hold @math{u} gives that span's polynomials, an empty span
## NaN or Inf), and @math{u} is not checked against the knots.
##
## Differences from octave-nurbs 1.4.3: one span for several parameters is used for all of
## them, and a span without the knots @math{U(s+2-p) … U(s+1+p)} or fewer spans than
## parameters is an error (@code{cagd:value}) — @code{basisfun} reads outside its arrays
## there and returns whatever memory lies there.
##
## Example:
## @example
## @group
## U = [0 0 0 1/2 1 1 1];
## cagd_basisfun (cagd_findspan (3, 2, 0.25, U), 0.25, 2, U)
##   @result{} [0.25 0.625 0.125]
## @end group
## @end example
## @seealso{cagd_findspan, cagd_basisfunder, cagd_bspeval}
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
%!test
%! ## As octave-nurbs 1.4.3: a wrong span is used as given, spans are truncated, u is not
%! ## checked, degree 0 is 1.
%! U = [0 0 0 1/2 1 1 1];
%! B = cagd_basisfun (1, 0.5, 2, U);
%! assert (isinf (B([1 3])) && isnan (B(2)));
%! assert (cagd_basisfun (3, 0.3, 2, U), [0.98 -0.14 0.16], 1e-15);
%! assert (cagd_basisfun (2.7, 0.3, 2, U), [0.16 0.66 0.18], 1e-15);
%! assert (cagd_basisfun (2, 1.5, 2, U), [4 -7.5 4.5], 1e-15);
%! assert (cagd_basisfun (2, 0.3, 0, U), 1);
%! assert (size (cagd_basisfun ([], [], 2, U)), [0 3]);
%!test
%! ## One span for several parameters.
%! U = [0 0 0 1/2 1 1 1];
%! assert (cagd_basisfun (2, [0.1 0.2], 2, U), cagd_basisfun ([2 2], [0.1 0.2], 2, U));
%!error <reads outside its arrays> cagd_basisfun ([2 2], [0.1 0.2 0.3], 2, [0 0 0 1/2 1 1 1])
%!error <reads outside its arrays> cagd_basisfun (5, 0.5, 2, [0 0 0 1/2 1 1 1])

%!demo
%! ## The quadratic basis functions on [0 0 0 .3 .6 1 1 1], each span in its colour.
%! U = [0 0 0 .3 .6 1 1 1]; u = linspace (0, 1, 201);
%! s = cagd_findspan (4, 2, u, U);
%! B = cagd_basisfun (s, u, 2, U);
%! N = zeros (numel (u), 5);
%! for k = 1:numel (u), N(k, s(k)-1:s(k)+1) = B(k, :); end
%! plot (u, N); xlabel ("u"); title ("cagd\\_basisfun: N_{i,2} on [0 0 0 .3 .6 1 1 1]");

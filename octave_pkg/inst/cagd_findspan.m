## -*- texinfo -*-
## @deftypefn {} {@var{s} =} cagd_findspan (@var{n}, @var{p}, @var{u}, @var{U})
## The knot spans of parameters: a drop-in replacement of octave-nurbs' @code{findspan}.
##
## @var{n} is the number of control points minus one, @var{p} the degree, @var{u} the
## parameters (any size), @var{U} the knot vector (@math{n + p + 2} knots).  @var{s} has the
## size of @var{u}: @code{s(k)} is the index (from 0) of the knot span
## @math{[U(s+1), U(s+2))} holding @code{u(k)}, and @math{n} at the right end of the domain.
## Parameters outside the domain @math{[U(p+1), U(n+2)]} are an error (@code{cagd:domain}).
##
## Example:
## @example
## @group
## cagd_findspan (3, 2, [0 0.25 0.5 1], [0 0 0 1/2 1 1 1])
##   @result{} [2 2 3 3]
## @end group
## @end example
## @seealso{cagd_basisfun}
## @end deftypefn

function s = cagd_findspan (varargin)
  s = __cagd__ ("cagd_findspan", varargin{:});
endfunction

%!assert (cagd_findspan (3, 2, [0 0.25 0.5 1], [0 0 0 1/2 1 1 1]), [2 2 3 3])
%!assert (size (cagd_findspan (3, 2, zeros (2, 3), [0 0 0 1/2 1 1 1])), [2 3])
%!error <expected 7 knots> cagd_findspan (3, 2, 0.5, [0 0 1/2 1 1 1])
%!error <outside the domain> cagd_findspan (3, 2, 1.5, [0 0 0 1/2 1 1 1])

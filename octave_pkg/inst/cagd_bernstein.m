## -*- texinfo -*-
## @deftypefn  {} {@var{B} =} cagd_bernstein (@var{n}, @var{t})
## @deftypefnx {} {@var{B} =} cagd_bernstein (@var{n}, @var{t}, "exact")
## The Bernstein polynomials of degree @var{n} at @var{t}:
## @code{B(i+1, k)} is @math{B_i^n(t(k)) = C(n,i) t^i (1-t)^@{n-i@}} (thesis §2.2);
## @var{B} is @math{(n+1) × numel (t)}, so @code{P * B} evaluates a Bézier curve with control
## points @var{P} (columns).  With @code{"exact"}: exact fractions (see @code{cagd_bezier}).
##
## Example:
## @example
## @group
## cagd_bernstein (2, [0 0.5 1])
##   @result{} [1 0.25 0; 0 0.5 0; 0 0.25 1]
## @end group
## @end example
## @seealso{cagd_bezier}
## @end deftypefn

function B = cagd_bernstein (varargin)
  B = __cagd__ ("cagd_bernstein", varargin{:});
endfunction

%!assert (cagd_bernstein (2, [0 0.5 1]), [1 0.25 0; 0 0.5 0; 0 0.25 1])
%!assert (cagd_bernstein (3, "1/3", "exact"), {"8/27"; "4/9"; "2/9"; "1/27"})
%!test
%! P = [0 0 8 4; 0 2 2 0; 0 2 0 0]; t = linspace (0, 1, 7);
%! assert (P * cagd_bernstein (3, t), cagd_bezier (P, t), 1e-14);
%!error <n: 1.5 is not a non-negative integer> cagd_bernstein (1.5, 0.5)
%!error id=cagd:overflow cagd_bernstein (3, 1e103)

%!demo
%! ## The cubic Bernstein polynomials.
%! t = linspace (0, 1, 101);
%! plot (t, cagd_bernstein (3, t)); title ("cagd\_bernstein: B_{i,3}(t)");
%! legend ("B_0", "B_1", "B_2", "B_3");

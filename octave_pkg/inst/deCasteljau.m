## -*- texinfo -*-
## @deftypefn  {} {@var{T} =} deCasteljau (@var{kontrolneT}, @var{N})
## @deftypefnx {} {} deCasteljau (@var{kontrolneT}, @var{N})
## The Bézier curve with control points @var{kontrolneT} sampled at
## @code{linspace (0, 1, @var{N})} by the de Casteljau algorithm: the thesis's
## @code{deCasteljau} (appendix A, Algoritem 1), fixed.
##
## @var{kontrolneT} is @math{d × (n+1)}, one control point per @strong{column} (row 1 = x,
## row 2 = y, @dots{}), any dimension @math{d ≥ 1}.  @var{T} is @math{d × N}: @code{T(:,k)} is
## the point at @code{t(k)}, @code{t = linspace (0, 1, N)}; @var{N} = 0 gives @math{d × 0}.
## The points are computed as Bernstein sums @math{Σ_i B_i^n(t) b_i} (the core's batch
## evaluation, one to three orders of magnitude faster than point-by-point de Casteljau); they
## agree with @file{octave_ref/fixed/deCasteljau.m} within 4 ULPs or 1e-14 of the largest
## coordinate (the package's tests: about two thirds bit for bit, the rest a few units of
## rounding of the scale).
##
## Called without an output argument it draws what the original drew: the curve and the
## control polygon with its points (@code{plot3}; @code{plot} for plane curves).
##
## Fixed in the original (see @file{octave_ref/BUGS.md}): it interpolated the rows (the
## coordinates) instead of the columns (the points), overwrote its own control points for
## every parameter, fixed the dimension at 3 and returned nothing.
##
## Example (thesis Primer 2.4, b(1/2) = (3.5, 1.5, 0.75)):
## @example
## @group
## T = deCasteljau ([0 0 8 4; 0 2 2 0; 0 2 0 0], 3);
## T(:,2)
##   @result{} [3.5; 1.5; 0.75]
## @end group
## @end example
##
## Errors (identifiers @code{cagd:class}, @code{cagd:empty}, @code{cagd:value},
## @code{cagd:nonfinite}, @code{cagd:limit}, @code{cagd:overflow}): a class other than double,
## no control points, an @var{N} that is not a non-negative integer, NaN or Inf, @var{N} above
## @code{cagd_limits ().max_samples} or work above @code{cagd_limits ().max_work}, a result
## beyond the range of doubles (refused, never returned as Inf). Ctrl-C stops it within a few
## milliseconds, as it stops Octave's own functions.
## @seealso{cagd_bezier, cagd_bezier_derivative, cagd_limits}
## @end deftypefn

function T = deCasteljau (varargin)
  T = __cagd__ ("deCasteljau", varargin{:});
  if (nargout == 0)
    __cagd_draw__ ("curve", T, varargin{1});
    clear T;
  endif
endfunction

%!test
%! T = deCasteljau ([0 0 8 4; 0 2 2 0; 0 2 0 0], 3);
%! assert (T, [0 3.5 4; 0 1.5 0; 0 0.75 0]);
%!test
%! ## Any dimension, N = 0 and N = 1 as the fixed Octave code.
%! assert (size (deCasteljau ([0 1 2; 3 4 5], 0)), [2 0]);
%! assert (deCasteljau ([0 1 2; 3 4 5], 1), [2; 5]);
%! assert (deCasteljau ([1 2 4], 3), [1 2.25 4]);
%!test
%! ## The original drew the curve and the control polygon.
%! f = figure ("visible", "off");
%! unwind_protect
%!   deCasteljau ([0 0 8 4; 0 2 2 0; 0 2 0 0], 10);
%!   assert (numel (get (gca, "children")), 3);
%! unwind_protect_cleanup
%!   close (f);
%! end_unwind_protect
%!error <deCasteljau: called with 1 argument> deCasteljau ([0 1])
%!error <kontrolneT: int32 is not accepted> deCasteljau (int32 ([0 1]), 3)
%!error <N: 2.5 is not a non-negative integer> deCasteljau ([0 1], 2.5)
%!error <kontrolneT: empty> deCasteljau (zeros (3, 0), 3)
%!error <not finite> deCasteljau ([0 NaN], 3)
## Control points at the largest double: a sum of the Bernstein terms rounds past it.
%!error id=cagd:overflow deCasteljau (1.7976931348623157e308 * ones (1, 30), 7)

%!demo
%! ## Thesis Primer 2.4 drawn by the thesis function itself (no output argument).
%! deCasteljau ([0 0 8 4; 0 2 2 0; 0 2 0 0], 50);
%! title ("deCasteljau: thesis Primer 2.4");

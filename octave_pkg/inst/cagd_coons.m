## -*- texinfo -*-
## @deftypefn  {} {[@var{X}, @var{rc}, @var{rd}, @var{rcd}] =} cagd_coons (@var{c1}, @var{c2}, @var{d1}, @var{d2}, @var{u}, @var{v})
## @deftypefnx {} {[@dots{}] =} cagd_coons (@dots{}, "exact")
## The bilinearly blended Coons patch of four boundary curves (Bézier or NURBS) on the grid
## @var{u} × @var{v}, with its three parts (thesis §4.2, Izrek 4.2):
##
## @example
## x(u,v) = rc + rd - rcd,   rc = (1-v) c1(u) + v c2(u),   rd = (1-u) d1(v) + u d2(v),
## rcd = (1-u)(1-v) P1 + u(1-v) P2 + (1-u) v P3 + u v P4
## @end example
##
## @table @var
## @item c1, c2
## the curves @math{x(u,0)}, @math{x(u,1)}: Bézier control points (@math{d × (k+1)},
## columns, any degrees), or NURBS curves as structures from @code{nrbmak} (fields
## @code{coefs}, @math{4 × n} homogeneous, @code{knots}, @code{order}), whose domain
## @math{[U(p+1), U(n+1)]} is mapped onto @math{[0, 1]};
## @item d1, d2
## the curves @math{x(0,v)}, @math{x(1,v)}, likewise;
## @item u, v
## parameter arrays (any size);
## @item X, rc, rd, rcd
## @math{d × numel (u) × numel (v)}: @code{X(:, i, j)} is the point at @code{(u(i), v(j))}.
## @end table
## The corners @math{P1 … P4} are the curves' ends; they must meet (relative tolerance 1e-10,
## else @code{cagd:corners} naming each corner).  With @code{"exact"}: exact fractions (see
## @code{cagd_bezier}).
##
## Example (thesis Primer 4.3, x(0.2, 0.5) = (1/5, 3/10, 19/50)):
## @example
## @group
## c1 = [0 0.5 1; 0 0 0; 0 0.5 0];     % (u, 0, u - u^2) as a quadratic
## c2 = [0 1; 1 1; 0 1];               % (u, 1, u)
## d1 = [0 0 0; 0 0 1; 0 0.5 0];       % (0, v^2, v - v^2)
## d2 = [1 1; 0 1; 0 1];               % (1, v, v)
## [X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, 0.2, 0.5);
## X'
##   @result{} [0.2 0.3 0.38]
## cagd_coons (c1, c2, d1, d2, 0.2, 0.5, "exact")'
##   @result{} @{"1/5", "3/10", "19/50"@}
## @end group
## @end example
## @seealso{krpaCoons, vrednostCoons, cagd_gordon}
## @end deftypefn

function varargout = cagd_coons (varargin)
  [varargout{1:max (nargout, 1)}] = __cagd__ ("cagd_coons", varargin{:});
endfunction

%!shared c1, c2, d1, d2
%! c1 = [0 0.5 1; 0 0 0; 0 0.5 0]; c2 = [0 1; 1 1; 0 1];
%! d1 = [0 0 0; 0 0 1; 0 0.5 0]; d2 = [1 1; 0 1; 0 1];
%!test
%! [X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, 0.2, 0.5);
%! assert (X, [0.2; 0.3; 0.38], 1e-15);
%! assert (rc, [0.2; 0.5; 0.18], 1e-15);
%! assert (rd, [0.2; 0.3; 0.3], 1e-15);
%! assert (rcd, [0.2; 0.5; 0.1], 1e-15);
%!assert (cagd_coons (c1, c2, d1, d2, 0.2, 0.5, "exact"), {"1/5"; "3/10"; "19/50"})
%!test
%! u = linspace (0, 1, 5); v = linspace (0, 1, 4);
%! X = cagd_coons (c1, c2, d1, d2, u, v);
%! assert (size (X), [3 5 4]);
%! assert (squeeze (X(:,:,1)), cagd_bezier (c1, u), 1e-15);
%! assert (squeeze (X(:,end,:)), cagd_bezier (d2, v), 1e-15);
%! ## The same patch as the thesis function on the same samples.
%! t = linspace (0, 1, 6);
%! [~, P] = krpaCoons (cagd_bezier (c1, t), cagd_bezier (c2, t), cagd_bezier (d1, t), ...
%!                     cagd_bezier (d2, t), [0;0;0], [1;0;0], [0;1;0], [1;1;1]);
%! assert (permute (cagd_coons (c1, c2, d1, d2, t, t), [2 3 1]), P, 1e-15);
%!test
%! ## NURBS boundaries (nrbmak's fields): quarter circles (weights 1, 1, 2) at z = 0 and 1 and
%! ## the lines between their ends: the cylinder, exactly (cos, sin) = (3/5, 4/5) at u = 1/2.
%! arc = @(z) struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
%!                    "coefs", [1 1 0; 0 1 2; z z 2*z; 1 1 2], "order", 3, ...
%!                    "knots", [0 0 0 1 1 1]);
%! X = cagd_coons (arc (0), arc (1), [1 1; 0 0; 0 1], [0 0; 1 1; 0 1], 0.5, 0.25);
%! assert (X, [3/5; 4/5; 1/4], 1e-15);
%! assert (cagd_coons (arc (0), arc (1), [1 1; 0 0; 0 1], [0 0; 1 1; 0 1], 0.5, 0.25, "exact"), ...
%!         {"3/5"; "4/5"; "1/4"});
%! if (exist ("nrbmak"))
%!   c = nrbmak ([1 1 0; 0 1 2; 0 0 0; 1 1 2], [0 0 0 1 1 1]);
%!   assert (cagd_coons (c, arc (1), [1 1; 0 0; 0 1], [0 0; 1 1; 0 1], 0.5, 0.25), X, 1e-15);
%! endif
%!error <do not meet at the corners> cagd_coons (c1, c2, d1, d2 + 1, 0.5, 0.5)
%!error <c1: .*has no field 'order'> cagd_coons (struct ("coefs", [1 0; 0 1; 0 0; 1 1], "knots", [0 0 1 1]), c2, d1, d2, 0.5, 0.5)
%!error <c2: .*not accepted> cagd_coons (c1, {c2}, d1, d2, 0.5, 0.5)
## rc + rd of boundaries at 1.7e308 overflows before rcd is subtracted: refused, not Inf.
%!error id=cagd:overflow cagd_coons (1.7e308 * ones (3, 2), 1.7e308 * ones (3, 2), 1.7e308 * ones (3, 2), 1.7e308 * ones (3, 2), 0.5, 0.5)

%!demo
%! ## Appendix C of the thesis: the Coons patch of c1 = (u, 0, u - u^2), c2 = (u, 1, u),
%! ## d1 = (0, v^2, v - v^2), d2 = (1, v, v), with its four boundary curves.
%! c1 = [0 0.5 1; 0 0 0; 0 0.5 0]; c2 = [0 1; 1 1; 0 1];
%! d1 = [0 0 0; 0 0 1; 0 0.5 0];   d2 = [1 1; 0 1; 0 1];
%! t = linspace (0, 1, 25);
%! X = cagd_coons (c1, c2, d1, d2, t, t);
%! surf (squeeze (X(1,:,:)), squeeze (X(2,:,:)), squeeze (X(3,:,:))); hold on;
%! for c = {c1, c2, d1, d2}
%!   b = cagd_bezier (c{1}, t); plot3 (b(1,:), b(2,:), b(3,:), "r", "linewidth", 2.5);
%! endfor
%! hold off; title ("cagd\_coons: the appendix C patch and its boundary curves");

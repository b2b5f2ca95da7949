## -*- texinfo -*-
## @deftypefn  {} {[@var{X}, @var{g1}, @var{g2}, @var{g12}] =} cagd_gordon (@var{cu}, @var{cv}, @var{un}, @var{vn}, @var{u}, @var{v})
## @deftypefnx {} {[@dots{}] =} cagd_gordon (@dots{}, "exact")
## The Gordon surface of a network of curves (Bézier or NURBS) on the grid @var{u} × @var{v},
## with its three parts (thesis §4.5, Izrek 4.4):
##
## @example
## g = g1 + g2 - g12,   g1 = sum_i g(u_i, v) L_i(u),   g2 = sum_j g(u, v_j) L_j(v),
## g12 = sum_i sum_j g(u_i, v_j) L_i(u) L_j(v)
## @end example
##
## @table @var
## @item un, vn
## the nodes @math{u_0 < … < u_m} and @math{v_0 < … < v_n};
## @item cu
## a cell of @math{m+1} curves @math{g(u_i, ·)}, functions of @math{v}: Bézier control
## points (@math{d × (k+1)}, columns), or NURBS curves as structures from @code{nrbmak}
## (fields @code{coefs}, @math{4 × n} homogeneous, @code{knots}, @code{order}), whose domain
## @math{[U(p+1), U(n+1)]} is mapped onto @math{[0, 1]};
## @item cv
## a cell of @math{n+1} curves @math{g(·, v_j)}, functions of @math{u}, likewise;
## @item X, g1, g2, g12
## @math{d × numel (u) × numel (v)}, as @code{cagd_coons}.
## @end table
## The crossings @math{g(u_i, v_j)} are taken from @var{cu}; each must lie on the curve of
## @var{cv} through it (relative tolerance 1e-10, else @code{cagd:network}).  With
## @code{"exact"}: exact fractions (see @code{cagd_bezier}).
##
## Example (appendix D's network, the surface (u, v, v + u - u^2)):
## @example
## @group
## d = @{[0 0; 0 1; 0 1], [0.5 0.5; 0 1; 0.25 1.25], [1 1; 0 1; 0 1]@};     % g(u_i, v)
## c = @{[0 0.5 1; 0 0 0; 0 0.5 0], [0 0.5 1; 0.5 0.5 0.5; 0.5 1 0.5], ...
##      [0 0.5 1; 1 1 1; 1 1.5 1]@};                                         % g(u, v_j)
## x = [0 0.5 1];
## cagd_gordon (d, c, x, x, 0.2, 0.7)'
##   @result{} [0.2 0.7 0.86]
## @end group
## @end example
## @seealso{krpaGordon, Lagrange, cagd_coons}
## @end deftypefn

function varargout = cagd_gordon (varargin)
  [varargout{1:max (nargout, 1)}] = __cagd__ ("cagd_gordon", varargin{:});
endfunction

%!shared d, c, x
%! d = {[0 0; 0 1; 0 1], [0.5 0.5; 0 1; 0.25 1.25], [1 1; 0 1; 0 1]};
%! c = {[0 0.5 1; 0 0 0; 0 0.5 0], [0 0.5 1; 0.5 0.5 0.5; 0.5 1 0.5], [0 0.5 1; 1 1 1; 1 1.5 1]};
%! x = [0 0.5 1];
%!test
%! [X, g1, g2, g12] = cagd_gordon (d, c, x, x, 0.2, 0.7);
%! assert (X, [0.2; 0.7; 0.86], 1e-15);
%! assert (X, g1 + g2 - g12, 1e-15);
%!assert (cagd_gordon (d, c, x, x, 0.2, 0.7, "exact"), {"1/5"; "7/10"; "43/50"})
%!test
%! t = linspace (0, 1, 5);
%! X = cagd_gordon (d, c, x, x, t, t);
%! [V, U] = meshgrid (t, t);
%! assert (squeeze (X(3,:,:)), V + U - U.^2, 1e-15);
%!test
%! ## NURBS curves (nrbmak's fields): the quarter circles (weights 1, 1, 2) at z = 0 and 1,
%! ## and three lines of the cylinder between them; at u = 1/4 (cos, sin) = (15/17, 8/17).
%! arc = @(z) struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
%!                    "coefs", [1 1 0; 0 1 2; z z 2*z; 1 1 2], "order", 3, ...
%!                    "knots", [0 0 0 1 1 1]);
%! lines = {[1 1; 0 0; 0 1], [3/5 3/5; 4/5 4/5; 0 1], [0 0; 1 1; 0 1]};
%! X = cagd_gordon (lines, {arc(0), arc(1)}, [0 0.5 1], [0 1], 0.25, 0.75);
%! assert (X, [15/17; 8/17; 3/4], 1e-15);
%! assert (cagd_gordon (lines, {arc(0), arc(1)}, [0 0.5 1], [0 1], 0.25, 0.75, "exact"), ...
%!         {"15/17"; "8/17"; "3/4"});
%! if (exist ("nrbmak"))
%!   c = nrbmak ([1 1 0; 0 1 2; 0 0 0; 1 1 2], [0 0 0 1 1 1]);
%!   assert (cagd_gordon (lines, {c, arc(1)}, [0 0.5 1], [0 1], 0.25, 0.75), X, 1e-15);
%! endif
%!error <network is not compatible> cagd_gordon (d, {c{1}, c{2} + 1, c{3}}, x, x, 0.5, 0.5)
%!error <cu: double is not accepted> cagd_gordon ([0 1], c, x, x, 0.5, 0.5)
%!error <nodes must increase> cagd_gordon (d, c, [0 1 0.5], x, 0.5, 0.5)
%!error <cv: .*not a recognised NURBS> cagd_gordon (d, {c{1}, struct("form", "L-NURBS"), c{3}}, x, x, 0.5, 0.5)
%!error id=cagd:overflow cagd_gordon ({[0 0; 0 1; 0 0], [1 1; 0 1; 0 0]}, {[0 1; 0 0; 0 0], [0 1; 1 1; 0 0]}, [0 1], [0 1], 1e308, 1e308)

%!demo
%! ## Appendix D's network: the Gordon surface (u, v, v + u - u^2) through six curves.
%! d = {[0 0; 0 1; 0 1], [0.5 0.5; 0 1; 0.25 1.25], [1 1; 0 1; 0 1]};
%! c = {[0 0.5 1; 0 0 0; 0 0.5 0], [0 0.5 1; 0.5 0.5 0.5; 0.5 1 0.5], [0 0.5 1; 1 1 1; 1 1.5 1]};
%! x = [0 0.5 1]; t = linspace (0, 1, 25);
%! X = cagd_gordon (d, c, x, x, t, t);
%! surf (squeeze (X(1,:,:)), squeeze (X(2,:,:)), squeeze (X(3,:,:))); hold on;
%! for k = 1:3
%!   a = cagd_bezier (c{k}, t); b = cagd_bezier (d{k}, t);
%!   plot3 (a(1,:), a(2,:), a(3,:), "r", b(1,:), b(2,:), b(3,:), "g", "linewidth", 2);
%! endfor
%! hold off; title ("cagd\_gordon: appendix D's network");

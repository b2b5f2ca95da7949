## -*- texinfo -*-
## @deftypefn  {} {[@var{X}, @var{C1}, @var{C2}] =} cagd_ruled (@var{c1}, @var{c2}, @var{u}, @var{v})
## @deftypefnx {} {[@dots{}] =} cagd_ruled (@dots{}, "exact")
## The ruled surface between two curves (Bézier or NURBS) on the grid @var{u} × @var{v}
## (the lecture notes, "plochy válcové"):
##
## @example
## x(u,v) = (1-v) c1(u) + v c2(u),   u, v in [0, 1]
## @end example
##
## each curve on its own domain mapped onto @math{u ∈ [0, 1]}; the straight lines
## @math{v ↦ x(u, v)} join the points of the two curves at the same @var{u}.
##
## @table @var
## @item c1, c2
## the curves @math{x(u,0)} and @math{x(u,1)}, of the same dimension: Bézier control points
## (@math{d × (k+1)}, columns, any degrees), or NURBS curves as structures from
## @code{nrbmak} (fields @code{coefs}, @math{4 × n} homogeneous, @code{knots},
## @code{order}), whose domain @math{[U(p+1), U(n+1)]} is mapped onto @math{[0, 1]};
## @item u, v
## parameter arrays (any size; outside @math{[0, 1]} the curves and the lines are extended);
## @item X
## @math{d × numel (u) × numel (v)}: @code{X(:, i, j)} is the point at @code{(u(i), v(j))};
## @item C1, C2
## the two curves at @var{u}, @math{d × numel (u)}.
## @end table
## With @code{"exact"}: exact fractions (see @code{cagd_bezier}; NURBS coefficients exactly as
## given). Errors: @code{cagd:shape} for curves of different dimensions, the errors of the
## curves (@code{cagd:struct}, @code{cagd:weights}, @code{cagd:knots}, …),
## @code{cagd:limit}, @code{cagd:overflow}. Ctrl-C stops a long evaluation.
##
## Example: between the parabola (u, 0, 2u(1-u)) and the line (u, 1, 1), at u = 1/4,
## v = 1/2 the midpoint of (1/4, 0, 3/8) and (1/4, 1, 1):
## @example
## @group
## c1 = [0 0.5 1; 0 0 0; 0 1 0];    % (u, 0, 2u(1-u)) as a quadratic Bézier curve
## c2 = [0 1; 1 1; 1 1];            % (u, 1, 1)
## cagd_ruled (c1, c2, 0.25, 0.5)'
##   @result{} [0.25 0.5 0.6875]
## cagd_ruled (c1, c2, 0.25, 0.5, "exact")'
##   @result{} @{"1/4", "1/2", "11/16"@}
## @end group
## @end example
## @seealso{cagd_coons, cagd_gordon, cagd_nurbs}
## @end deftypefn

function varargout = cagd_ruled (varargin)
  [varargout{1:max (nargout, 1)}] = __cagd__ ("cagd_ruled", varargin{:});
endfunction

%!shared c1, c2, arc
%! c1 = [0 0.5 1; 0 0 0; 0 1 0]; c2 = [0 1; 1 1; 1 1];
%! ## The quarter circle (1, 0) -> (0, 1) at height z: weights 1, 1, 2 (nrbmak's fields).
%! arc = @(z) struct ("form", "B-NURBS", "dim", 4, "number", 3, ...
%!                    "coefs", [1 1 0; 0 1 2; z z 2*z; 1 1 2], "order", 3, ...
%!                    "knots", [0 0 0 1 1 1]);
%!test
%! ## By hand: c1(1/4) = (1/4, 0, 2 (1/4)(3/4)) = (1/4, 0, 3/8), c2(1/4) = (1/4, 1, 1), and
%! ## their midpoint (1/4, 1/2, 11/16).
%! [X, C1, C2] = cagd_ruled (c1, c2, 0.25, 0.5);
%! assert (X, [1/4; 1/2; 11/16], 1e-15);
%! assert (C1, [1/4; 0; 3/8], 1e-15);
%! assert (C2, [1/4; 1; 1], 1e-15);
%!assert (cagd_ruled (c1, c2, 0.25, 0.5, "exact"), {"1/4"; "1/2"; "11/16"})
%!test
%! ## On a grid: the first and last rows are the curves themselves, every v-line straight.
%! u = linspace (0, 1, 7); v = [0 0.25 1];
%! X = cagd_ruled (c1, c2, u, v);
%! assert (size (X), [3 7 3]);
%! assert (X(:,:,1), cagd_bezier (c1, u), 1e-15);
%! assert (X(:,:,3), cagd_bezier (c2, u), 1e-15);
%! assert (X(:,:,2), 0.75 * X(:,:,1) + 0.25 * X(:,:,3), 1e-15);
%!test
%! ## Between two NURBS quarter circles at z = 0 and z = 1: the cylinder, exactly. At u = 1/2
%! ## the circle is (1/4 (1, 0) + 1/2 (1, 1) + 1/4 · 2 (0, 1)) / (1/4 + 1/2 + 1/4 · 2)
%! ## = (3/5, 4/5); at v = 1/4 the height is 1/4.
%! assert (cagd_ruled (arc (0), arc (1), 0.5, 0.25), [3/5; 4/5; 1/4], 1e-15);
%! assert (cagd_ruled (arc (0), arc (1), 0.5, 0.25, "exact"), {"3/5"; "4/5"; "1/4"});
%! ## A NURBS and a Bézier curve mixed; nrbmak's own structure where octave-nurbs is there.
%! assert (cagd_ruled (arc (0), [1 0; 0 1; 1 1], 0.5, 1), [0.5; 0.5; 1], 1e-15);
%! if (exist ("nrbmak"))
%!   c = nrbmak ([1 1 0; 0 1 2; 0 0 0; 1 1 2], [0 0 0 1 1 1]);
%!   assert (cagd_ruled (c, arc (1), 0.5, 0.25), [3/5; 4/5; 1/4], 1e-15);
%! endif
%!error <c1, c2: .*dimension> cagd_ruled ([0 1; 0 0], c2, 0.5, 0.5)
%!error <c1: .*has no field 'order'> cagd_ruled (struct ("coefs", [1 0; 0 1; 0 0; 1 1], "knots", [0 0 1 1]), c2, 0.5, 0.5)
%!error <c2: .*not accepted> cagd_ruled (c1, {c2}, 0.5, 0.5)
%!error <called with 3 argument> cagd_ruled (c1, c2, 0.5)
%!error id=cagd:weights cagd_ruled (setfield (arc (0), "coefs", [1 1 0; 0 1 2; 0 0 0; 1 -1 2]), c2, 0.5, 0.5)
%!error id=cagd:overflow cagd_ruled ([1.7e308 1.7e308], [-1.7e308 -1.7e308], 0.5, 5)

%!demo
%! ## The ruled surface between a NURBS half circle at z = 0 and a Bézier wave at z = 1 (its
%! ## mesh lines along v are its straight lines), with its two curves.
%! h = sqrt (2) / 2; w = [1 h 1 h 1];
%! P = [1 1 0 -1 -1; 0 1 1 1 0; 0 0 0 0 0];
%! half = struct ("form", "B-NURBS", "dim", 4, "number", 5, "coefs", [P .* w; w], ...
%!                "order", 3, "knots", [0 0 0 0.5 0.5 1 1 1]);
%! wave = [1 0.5 -0.5 -1; 0 1.5 -0.5 0.5; 1 1 1 1];
%! u = linspace (0, 1, 41); v = linspace (0, 1, 11);
%! [X, C1, C2] = cagd_ruled (half, wave, u, v);
%! surf (squeeze (X(1,:,:)), squeeze (X(2,:,:)), squeeze (X(3,:,:))); hold on;
%! plot3 (C1(1,:), C1(2,:), C1(3,:), "r", "linewidth", 2.5);
%! plot3 (C2(1,:), C2(2,:), C2(3,:), "g", "linewidth", 2.5);
%! hold off; title ("cagd\_ruled: between a NURBS half circle and a Bézier curve");

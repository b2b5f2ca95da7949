## -*- texinfo -*-
## @deftypefn  {} {[@var{R}, @var{P}] =} krpaGordon (@var{g_u}, @var{g_v}, @var{g_uv}, @var{x_u}, @var{x_v}, @var{N})
## @deftypefnx {} {} krpaGordon (@dots{})
## The Gordon surface of a sampled curve network on @code{linspace (0, 1, N)} in both
## directions: the thesis's @code{krpaGordon} (appendix D, Algoritem 7), fixed.
##
## @example
## g = g1 + g2 - g12  (Izrek 4.4),  g1 = sum_j c_j(u) L_j(v),  g2 = sum_i d_i(v) L_i(u),
## g12 = sum_i sum_j g(u_i, v_j) L_i(u) L_j(v)
## @end example
##
## @table @var
## @item x_u, x_v
## the nodes @math{u_0 < @dots{} < u_m} and @math{v_0 < @dots{} < v_n} (@math{m ≠ n} allowed);
## @item g_u
## @math{3 × (n+1)N}: @code{[c_0 c_1 @dots{} c_n]}, @math{c_j = g(·, v_j)} sampled at
## @code{t = linspace (0, 1, N)}: @code{g_u(:, j*N + i) = g(t(i), v_j)};
## @item g_v
## @math{3 × (m+1)N}: @code{[d_0 @dots{} d_m]}, @math{d_i = g(u_i, ·)}:
## @code{g_v(:, i*N + j) = g(u_i, t(j))};
## @item g_uv
## @math{(m+1) × 3(n+1)}: the crossings, @code{g_uv(i+1, 3*j+1:3*j+3) = g(u_i, v_j)}
## (appendix D's @code{[g00 g10 g20; g01 g11 g21; g02 g12 g22]});
## @item R, P
## @math{N × 3N} packed and @math{N × N × 3}, as @code{krpaCoons}.
## @end table
##
## Called without an output argument it draws the surface with @code{surf}, as the original.
##
## Fixed in the original: one node vector and one count for both directions; curves indexed
## by sample instead of by curve; crossings added as rows to columns; nothing returned.  The
## network must be compatible (@code{cagd:network}) and the nodes increasing
## (@code{cagd:nodes}).
## @seealso{Lagrange, krpaCoons, cagd_gordon}
## @end deftypefn

function [R, P] = krpaGordon (varargin)
  [R, P] = __cagd__ ("krpaGordon", varargin{:});
  if (nargout == 0)
    __cagd_draw__ ("surface", P);
    clear R P;
  endif
endfunction

%!shared g_u, g_v, g_uv, x, N
%! ## Appendix D's network, N = 5 (the node 0.5 is a sample).
%! N = 5; x = [0 0.5 1];
%! u = linspace (0, 1, N); v = u; o = ones (1, N);
%! g_u = [[u; 0*o; u-u.^2] [u; 0.5*o; 0.5+u-u.^2] [u; o; 1+u-u.^2]];
%! g_v = [[0*o; v; v] [0.5*o; v; 0.25+v] [o; v; v]];
%! g_uv = [0 0 0 0 0.5 0.5 0 1 1; 0.5 0 0.25 0.5 0.5 0.75 0.5 1 1.25; 1 0 0 1 0.5 0.5 1 1 1];
%!test
%! [R, P] = krpaGordon (g_u, g_v, g_uv, x, x, N);
%! t = linspace (0, 1, N);
%! [V, U] = meshgrid (t, t);
%! assert (P(:,:,1), U, 1e-15);
%! assert (P(:,:,2), V, 1e-15);
%! assert (P(:,:,3), V + U - U.^2, 1e-15);
%! assert (R(:, 3:3:end), P(:,:,3));
%!test
%! f = figure ("visible", "off");
%! unwind_protect
%!   krpaGordon (g_u, g_v, g_uv, x, x, N);
%!   assert (get (get (gca, "children"), "type"), "surface");
%! unwind_protect_cleanup
%!   close (f);
%! end_unwind_protect
%!error <network> krpaGordon (g_u, g_v, g_uv + 0.25, x, x, N)
%!error <nodes must increase> krpaGordon (g_u, g_v, g_uv, [0 1 0.5], x, N)
%!error <g_u: expected 3×15> krpaGordon (g_u(:, 1:14), g_v, g_uv, x, x, N)
## g1 + g2 of curves at 1.7e308 overflows before g12 is subtracted: refused, not Inf.
%!error id=cagd:overflow krpaGordon (1.7e308 * ones (3, 10), 1.7e308 * ones (3, 10), 1.7e308 * ones (2, 6), [0 1], [0 1], 5)

%!demo
%! ## Appendix D of the thesis, drawn by krpaGordon itself (no output argument): the Gordon
%! ## surface of the network c_j(u) = g(u, v_j), d_i(v) = g(u_i, v), g = (u, v, v + u - u^2).
%! N = 25; u = linspace (0, 1, N); v = u; o = ones (1, N);
%! g_u = [[u; 0*o; u-u.^2], [u; 0.5*o; 0.5+u-u.^2], [u; o; 1+u-u.^2]];
%! g_v = [[0*o; v; v], [0.5*o; v; 0.25+v], [o; v; v]];
%! g_uv = [0 0 0  0 0.5 0.5  0 1 1; 0.5 0 0.25  0.5 0.5 0.75  0.5 1 1.25; 1 0 0  1 0.5 0.5  1 1 1];
%! x = [0 0.5 1];
%! krpaGordon (g_u, g_v, g_uv, x, x, N);
%! title ("krpaGordon: the appendix D surface");

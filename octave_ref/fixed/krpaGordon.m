% krpaGordon.m -- fixed version of ../original/krpaGordon.m (thesis appendix D, Algoritem 7).
%
% [R, P] = krpaGordon(g_u, g_v, g_uv, x_u, x_v, N)
%   x_u    1 x (m+1): the nodes u_0 < ... < u_m
%   x_v    1 x (n+1): the nodes v_0 < ... < v_n          (m ~= n allowed)
%   g_u    3 x (n+1)N: [c_0 c_1 ... c_n], c_j = g(u, v_j) (a curve in u) sampled at
%          u = linspace(0,1,N): g_u(:, j*N + i) = g(t(i), v_j)     (j counted from 0)
%   g_v    3 x (m+1)N: [d_0 d_1 ... d_m], d_i = g(u_i, v) (a curve in v) sampled at
%          v = linspace(0,1,N): g_v(:, i*N + j) = g(u_i, t(j))
%   g_uv   (m+1) x 3(n+1): the crossings, g_uv(i+1, 3*j+1:3*j+3) = g(u_i, v_j)
%          (appendix D's g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22] has this layout:
%          its printed g_ab is g(u_b, v_a))
%   N      the number of samples per direction
%   R      N x 3N, packed: R(i, 3*j-2:3*j) = g(t(i), t(j))'
%   P      N x N x 3:      P(i, j, :) = g(t(i), t(j))
%   g = g1 + g2 - g12 (Izrek 4.4), g1 = sum_j c_j(u) L_j(v), g2 = sum_i d_i(v) L_i(u),
%   g12 = sum_i sum_j g(u_i, v_j) L_i(u) L_j(v), L from Lagrange.m.
%
% What was changed, and why:
%   1. Separate node vectors x_u, x_v and separate counts m+1 = length(x_u), n+1 = length(x_v):
%      the original used one vector x and one count for both directions, so networks with a
%      different number of curves in u and v (or different nodes) were impossible.
%   2. The counts are the numbers of curves: the original took m = size(g_u)(2), n =
%      size(g_v)(2), which for sampled curves is the number of sample columns (3N), and then
%      ran Lagrange(x, l, .) with l up to 3N, beyond the nodes.
%   3. Sampled curves are indexed by curve AND sample: the original's g_u(:,l) is sample l of
%      the first curve c_0, not the curve c_l at the current parameter.  Now curve c_l at u =
%      t(i) is g_u(:, (l-1)*N + i), curve d_l at v = t(j) is g_v(:, (l-1)*N + j).
%   4. The crossing g_uv(l, 3*s-2:3*s) is transposed to a column: as a row it was broadcast
%      against the column vectors g1, g2, making g1 + g2 - g12 a 3 x 3 matrix that does not fit
%      into R(i, k:k+2).  The original's "s+c:s+c+2" with c = 0, 2, 4, ... is 3*s-2:3*s.
%   5. The loops over the two directions are separate (m+1 curves d_i, n+1 curves c_j; the
%      crossings in a double loop l = 1..m+1, s = 1..n+1).
%   6. R is preallocated as zeros(N, 3*N) (the original's zeros(N,N) was too small), R and P are
%      returned and the plotting is removed; P is built with tenzor's copy loop, inline.
% Kept from the original: the accumulation "term + sum" in ascending index order, the
% crossing term as (g * L_l(u)) * L_s(v), and g1 + g2 - g12.
function [R, P] = krpaGordon(g_u,g_v,g_uv,x_u,x_v,N)
m = length(x_u);
n = length(x_v);
if !isequal(size(g_u), [3 n*N]) || !isequal(size(g_v), [3 m*N]) || !isequal(size(g_uv), [m 3*n])
    error('krpaGordon: expected g_u 3 x %d, g_v 3 x %d, g_uv %d x %d', n*N, m*N, m, 3*n);
end;
t = linspace(0,1,N);
R = zeros(N, 3*N);
for i = 1:N
    u = t(i);
    k = 1;
    for j = 1:N
        v = t(j);
        g1 = g2 = g12 = 0;
        for l = 1:n
            g1 = g_u(:,(l-1)*N+i)*Lagrange(x_v,l,v)+g1;
        end;
        for l = 1:m
            g2 = g_v(:,(l-1)*N+j)*Lagrange(x_u,l,u)+g2;
            for s = 1:n
                g12 = g_uv(l,3*s-2:3*s)'*Lagrange(x_u,l,u)*Lagrange(x_v,s,v)+g12;
            end;
        end;
        R(i,k:(k+2)) = g1+g2-g12;
        k = k+3;
    end;
end;
P = zeros(N, N, 3);
for k = 1:N
    for l = 1:N
        P(k,l,:) = R(k,3*l-2:3*l);
    end;
end;
end;

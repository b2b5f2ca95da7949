% Bug: krpaGordon(g_u,g_v,g_uv,x,N) has ONE node vector x and ONE count for both directions,
% so a network with different nodes (or a different number of curves) in u and v cannot be
% passed; the fixed signature krpaGordon(g_u,g_v,g_uv,x_u,x_v,N) is rejected by the original.
bug_setup;
N = 5;
u = linspace(0, 1, N);
o = ones(1, N);
g_u = [[u; 0*o; 0*o], [u; o; o]];                            % 2 curves g(u, v_j), v = 0, 1
g_v = [[0*o; u; u], [0.5*o; u; u], [o; u; u]];                % 3 curves g(u_i, v), u = 0, 0.5, 1
g_uv = [0 0 0 0 1 1; 0.5 0 0 0.5 1 1; 1 0 0 1 1 1];
krpaGordon(g_u, g_v, g_uv, [0 0.5 1], [0 1], N);

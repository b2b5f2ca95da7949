% Case "gordon_thesis": appendix D's network through the fixed krpaGordon (and Lagrange).
%
% The network (appendix D, data for Algoritem 7, with u, v sampled and the powers elementwise):
%   c_j(u) = g(u, v_j): c0 = (u, 0, u-u^2), c1 = (u, 0.5, 0.5+u-u^2), c2 = (u, 1, 1+u-u^2)
%   d_i(v) = g(u_i, v): d0 = (0, v, v),     d1 = (0.5, v, 0.25+v),    d2 = (1, v, v)
%   nodes x = [0 0.5 1] in both directions; g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22] as
%   printed, so g_uv(i+1, 3j+1:3j+3) = g(u_i, v_j) (the printed g_ab is g(u_b, v_a)).
% For N = 3, 10, 101:
% Inputs:  x                     1 x 3, the nodes (x_u = x_v = x)
%          g_uv                  3 x 9, the crossings
%          t_N<N>                1 x N, linspace(0,1,N)
%          g_u_N<N>              3 x 3N, [c0 c1 c2] sampled at t
%          g_v_N<N>              3 x 3N, [d0 d1 d2] sampled at t
% Outputs: P_N<N>                N x N x 3, [R, P] = krpaGordon(g_u, g_v, g_uv, x, x, N)
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

g00 = [0 0 0];
g01 = [0.5 0 0.25];
g02 = [1 0 0];
g10 = [0 0.5 0.5];
g11 = [0.5 0.5 0.75];
g12 = [1 0.5 0.5];
g20 = [0 1 1];
g21 = [0.5 1 1.25];
g22 = [1 1 1];
g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22];
x = [0 0.5 1];
names = {'x', 'g_uv'};
for N = [3 10 101]
    u = linspace(0,1,N);
    v = linspace(0,1,N);
    o = ones(1,N);
    c0 = [u; 0*o; u-u.^2];
    c1 = [u; 0.5*o; 0.5+u-u.^2];
    c2 = [u; o; 1+u-u.^2];
    g_u = [c0 c1 c2];
    d0 = [0*o; v; v];
    d1 = [0.5*o; v; 0.25+v];
    d2 = [o; v; v];
    g_v = [d0 d1 d2];
    [~, P] = krpaGordon(g_u, g_v, g_uv, x, x, N);
    eval(sprintf('t_N%d = u; g_u_N%d = g_u; g_v_N%d = g_v; P_N%d = P;', N, N, N, N));
    names(end+1:end+4) = {sprintf('t_N%d', N), sprintf('g_u_N%d', N), ...
                          sprintf('g_v_N%d', N), sprintf('P_N%d', N)};
end;
save('-text', fullfile(outdir, 'gordon_thesis.txt'), names{:});

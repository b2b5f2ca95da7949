% Bug: krpaGordon takes the numbers of curves from the sizes of the sampled curve matrices,
% m = size(g_u)(2) and n = size(g_v)(2): with three curves of N samples each that is 3N, not 3,
% and the loops run past the three nodes of x and the three crossings of g_uv.  It also reads
% g_u(:,l) as "curve l" where it is sample l of the first curve.  Data: appendix D's network,
% sampled as krpaGordon needs it (elementwise powers, N = 5).
bug_setup;
N = 5;
u = linspace(0, 1, N);
v = u;
o = ones(1, N);
g_uv = [0 0 0 0 0.5 0.5 0 1 1; 0.5 0 0.25 0.5 0.5 0.75 0.5 1 1.25; 1 0 0 1 0.5 0.5 1 1 1];
g_u = [[u; 0*o; u-u.^2], [u; 0.5*o; 0.5+u-u.^2], [u; o; 1+u-u.^2]];
g_v = [[0*o; v; v], [0.5*o; v; 0.25+v], [o; v; v]];
x = [0 0.5 1];
printf('size(g_u) = %s, size(g_v) = %s, size(g_uv) = %s: m = n = %d curves taken\n', ...
       mat2str(size(g_u)), mat2str(size(g_v)), mat2str(size(g_uv)), size(g_u)(2));
krpaGordon(g_u, g_v, g_uv, x, N);

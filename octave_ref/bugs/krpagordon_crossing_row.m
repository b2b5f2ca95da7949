% Bug: krpaGordon adds the crossing g_uv(l, s+c:s+c+2), a 1x3 ROW, to g12 while g1 and g2 are
% 3x1 COLUMNS; Octave broadcasts g1 + g2 - g12 to a 3x3 matrix, which does not fit into
% R(i, k:k+2).  Data: appendix D's script run with scalar u and v (the only way it runs), so
% that g_u and g_v are 3x3 and the counts m = n = 3 happen to be right.
bug_setup;
u = 0.25;
v = 0.5;
krpaGordon_data;
printf('size(g_u) = %s, size(g_v) = %s, size(g_uv(1, 1:3)) = %s\n', ...
       mat2str(size(g_u)), mat2str(size(g_v)), mat2str(size(g_uv(1, 1:3))));
krpaGordon(g_u, g_v, g_uv, x, 2);

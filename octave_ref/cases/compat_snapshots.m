% Case "compat_snapshots": exactly the inputs and outputs shown by the snapshot tests of the
% Octave-compatible layer (crates/cagd-octave/tests/it/octave_compat.rs, tests/snapshots/octave_compat__*.snap), so
% that every number of a snapshot can be checked against Octave.  (Primer 4.3 and the Lagrange
% basis of appendix D's nodes are taken from the cases coons_thesis and lagrange_basis.)
% Every name starts with snap_ so that no case variable is shadowed.
%
% Appendix A, thesis Primer 2.4 at N = 5:
%   snap_P_primer_2_4      3 x 4, b0 = (0,0,0), b1 = (0,2,2), b2 = (8,2,0), b3 = (4,0,0) as columns
%   snap_t_N5              1 x 5, linspace(0,1,5)
%   snap_T_primer_2_4_N5   3 x 5, deCasteljau(snap_P_primer_2_4, 5)
% Appendix B, a degree (2,3) net with small integer coordinates, b(i,j) = (i, j, z(i,j)):
%   snap_B                 3 x 12, packed: snap_B(i+1, 3j+1:3j+3) = b(i,j)
%   snap_A                 3 x 4 x 3, tenzor(snap_B)
%   snap_P_B_N5            5 x 5 x 3, ploskevB(snap_B, 5)
%   snap_L_B               1 x 1 x 3, bilinearna(snap_B, 0.5, 0.25, 5)
% Appendix C, the data for Algoritem 5 at N = 5 (the printed loops; its "P3 = [1;1;1]" read as
% P4 = [1;1;1]), through the fixed krpaCoons:
%   snap_coons_c1, _c2, _d1, _d2   3 x 5, the sampled boundary curves
%   snap_coons_P1 .. _P4           3 x 1, the corners
%   snap_coons_R                   5 x 15, [R, P] = krpaCoons(...)
%   snap_coons_P                   5 x 5 x 3
% Appendix D, the network at N = 5 (the printed data with u, v sampled and .^), through the
% fixed krpaGordon with x_u = x_v = x:
%   snap_gordon_g_u, _g_v          3 x 15, [c0 c1 c2] and [d0 d1 d2] sampled at linspace(0,1,5)
%   snap_gordon_g_uv               3 x 9, the crossings as printed
%   snap_gordon_x                  1 x 3, [0 0.5 1]
%   snap_gordon_R                  5 x 15, [R, P] = krpaGordon(g_u, g_v, g_uv, x, x, 5)
%   snap_gordon_P                  5 x 5 x 3
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

snap_P_primer_2_4 = [0 0 8 4; 0 2 2 0; 0 2 0 0];
snap_t_N5 = linspace(0,1,5);
snap_T_primer_2_4_N5 = deCasteljau(snap_P_primer_2_4, 5);

z = [0 1 1 0; 1 3 2 1; 0 2 2 -1];
snap_B = zeros(3, 12);
for i = 0:2
    for j = 0:3
        snap_B(i+1, 3*j+1:3*j+3) = [i j z(i+1,j+1)];
    end;
end;
snap_A = tenzor(snap_B);
snap_P_B_N5 = ploskevB(snap_B, 5);
snap_L_B = bilinearna(snap_B, 0.5, 0.25, 5);

N = 5;
u = linspace(0,1,N);
v = linspace(0,1,N);
c1z = zeros(1,N);
d1y = zeros(1,N);
d1z = zeros(1,N);
for i = 1:N
    c1z(i) = u(i)-(u(i))^2;
    d1y(i) = (v(i))^2;
    d1z(i) = v(i)-(v(i))^2;
end;
snap_coons_c1 = [u; zeros(1,N); c1z];
snap_coons_c2 = [u; ones(1,N); u];
snap_coons_d1 = [zeros(1,N); d1y; d1z];
snap_coons_d2 = [ones(1,N); v; v];
snap_coons_P1 = [0;0;0];
snap_coons_P2 = [1;0;0];
snap_coons_P3 = [0;1;0];
snap_coons_P4 = [1;1;1];
[snap_coons_R, snap_coons_P] = krpaCoons(snap_coons_c1, snap_coons_c2, snap_coons_d1, ...
    snap_coons_d2, snap_coons_P1, snap_coons_P2, snap_coons_P3, snap_coons_P4);

o = ones(1,N);
snap_gordon_g_u = [[u; 0*o; u-u.^2], [u; 0.5*o; 0.5+u-u.^2], [u; o; 1+u-u.^2]];
snap_gordon_g_v = [[0*o; v; v], [0.5*o; v; 0.25+v], [o; v; v]];
g00 = [0 0 0]; g01 = [0.5 0 0.25]; g02 = [1 0 0];
g10 = [0 0.5 0.5]; g11 = [0.5 0.5 0.75]; g12 = [1 0.5 0.5];
g20 = [0 1 1]; g21 = [0.5 1 1.25]; g22 = [1 1 1];
snap_gordon_g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22];
snap_gordon_x = [0 0.5 1];
[snap_gordon_R, snap_gordon_P] = krpaGordon(snap_gordon_g_u, snap_gordon_g_v, ...
    snap_gordon_g_uv, snap_gordon_x, snap_gordon_x, N);

save('-text', fullfile(outdir, 'compat_snapshots.txt'), 'snap_P_primer_2_4', 'snap_t_N5', ...
     'snap_T_primer_2_4_N5', 'snap_B', 'snap_A', 'snap_P_B_N5', 'snap_L_B', ...
     'snap_coons_c1', 'snap_coons_c2', 'snap_coons_d1', 'snap_coons_d2', ...
     'snap_coons_P1', 'snap_coons_P2', 'snap_coons_P3', 'snap_coons_P4', ...
     'snap_coons_R', 'snap_coons_P', ...
     'snap_gordon_g_u', 'snap_gordon_g_v', 'snap_gordon_g_uv', 'snap_gordon_x', ...
     'snap_gordon_R', 'snap_gordon_P');

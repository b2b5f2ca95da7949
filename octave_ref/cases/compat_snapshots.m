% Case "compat_snapshots": exactly the inputs and outputs shown by the snapshot tests of the
% Octave-compatible layer (tests/octave_compat.rs, tests/snapshots/octave_compat__*.snap), so
% that every number of a snapshot can be checked against Octave.  (Primer 4.3 and the Lagrange
% basis of appendix D's nodes are taken from the cases coons_thesis and lagrange_basis.)
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

save('-text', fullfile(outdir, 'compat_snapshots.txt'), 'snap_P_primer_2_4', 'snap_t_N5', ...
     'snap_T_primer_2_4_N5', 'snap_B', 'snap_A', 'snap_P_B_N5', 'snap_L_B');

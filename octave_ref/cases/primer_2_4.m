% Case "primer_2_4": thesis Primer 2.4 through the fixed deCasteljau.
% b0 = (0,0,0), b1 = (0,2,2), b2 = (8,2,0), b3 = (4,0,0); the thesis gives b(0.5) = (3.5, 1.5, 0.75).
% Inputs:  P_primer_2_4           3 x 4, one control point per column
%          t_N<N>                 1 x N, linspace(0,1,N)
% Outputs: T_primer_2_4_N<N>      3 x N, deCasteljau(P_primer_2_4, N); N = 3 has t = 0.5 as t(2)
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

P_primer_2_4 = [0 0 8 4; 0 2 2 0; 0 2 0 0];
names = {'P_primer_2_4'};
for N = [2 3 10 101]
    eval(sprintf('t_N%d = linspace(0,1,N);', N));
    eval(sprintf('T_primer_2_4_N%d = deCasteljau(P_primer_2_4, N);', N));
    names(end+1:end+2) = {sprintf('t_N%d', N), sprintf('T_primer_2_4_N%d', N)};
end;
if !isequal(T_primer_2_4_N3(:,2), [3.5; 1.5; 0.75])
    error('primer_2_4: fixed deCasteljau does not reproduce the thesis value (3.5, 1.5, 0.75)');
end;
save('-text', fullfile(outdir, 'primer_2_4.txt'), names{:});

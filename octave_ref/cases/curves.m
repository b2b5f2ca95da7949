% Case "curves": random Bezier curves through the fixed deCasteljau.
% Degrees 0, 1, 2, 3, 7, 20 in 1-D (degree 3 only), 2-D and 3-D; control coordinates uniform in
% [-10, 10] from a fixed Mersenne-twister state, so the file is reproducible bit for bit.
% Inputs:  P_deg<n>_<d>d          d x (n+1), one control point per column
%          t_N<N>                 1 x N, linspace(0,1,N)
% Outputs: T_deg<n>_<d>d_N<N>     d x N, deCasteljau(P_deg<n>_<d>d, N)
% N = 2, 3, 10 for every curve; N = 101 also for degrees 3 and 20.
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

rand('state', 2014);
names = {};
for N = [2 3 10 101]
    eval(sprintf('t_N%d = linspace(0,1,N);', N));
    names{end+1} = sprintf('t_N%d', N);
end;
specs = [0 2; 0 3; 1 2; 1 3; 2 2; 2 3; 3 1; 3 2; 3 3; 7 2; 7 3; 20 2; 20 3];
for r = 1:rows(specs)
    n = specs(r,1);
    d = specs(r,2);
    key = sprintf('deg%d_%dd', n, d);
    P = 20*rand(d, n+1) - 10;
    eval(sprintf('P_%s = P;', key));
    names{end+1} = ['P_' key];
    Ns = [2 3 10];
    if n == 3 || n == 20
        Ns(end+1) = 101;
    end;
    for N = Ns
        eval(sprintf('T_%s_N%d = deCasteljau(P, N);', key, N));
        names{end+1} = sprintf('T_%s_N%d', key, N);
    end;
end;
save('-text', fullfile(outdir, 'curves.txt'), names{:});

% Case "patches": random tensor-product Bezier patches through the fixed ploskevB/bilinearna.
% Degrees (m,n) = (0,0), (0,3), (4,0), (1,1), (2,2), (3,3), (2,5), (5,2), (1,4); coordinates
% uniform in [-10, 10] from a fixed Mersenne-twister state, so the file is reproducible bit for bit.
% Inputs:  B_deg<m>x<n>           (m+1) x 3(n+1), packed net: B(i+1, 3*j+1:3*j+3) = b(i,j)
%          t_N<N>                 1 x N, linspace(0,1,N) (both u and v)
% Outputs: A_deg<m>x<n>           (m+1) x (n+1) x 3, tenzor(B)
%          P_deg<m>x<n>_N<N>      N x N x 3, ploskevB(B, N): P(i,j,:) = b(t(i), t(j))
% N = 2, 3, 10 for every patch; N = 101 also for (3,3) and (2,5).
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

rand('state', 2015);
names = {};
for N = [2 3 10 101]
    eval(sprintf('t_N%d = linspace(0,1,N);', N));
    names{end+1} = sprintf('t_N%d', N);
end;
specs = [0 0; 0 3; 4 0; 1 1; 2 2; 3 3; 2 5; 5 2; 1 4];
for r = 1:rows(specs)
    m = specs(r,1);
    n = specs(r,2);
    key = sprintf('deg%dx%d', m, n);
    B = 20*rand(m+1, 3*(n+1)) - 10;
    eval(sprintf('B_%s = B;', key));
    eval(sprintf('A_%s = tenzor(B);', key));
    names(end+1:end+2) = {['B_' key], ['A_' key]};
    Ns = [2 3 10];
    if isequal([m n], [3 3]) || isequal([m n], [2 5])
        Ns(end+1) = 101;
    end;
    for N = Ns
        eval(sprintf('P_%s_N%d = ploskevB(B, N);', key, N));
        names{end+1} = sprintf('P_%s_N%d', key, N);
    end;
end;
save('-text', fullfile(outdir, 'patches.txt'), names{:});

% Case "gordon_random": networks cut from random polynomial surfaces through the fixed
% krpaGordon, with different node vectors and numbers of curves in u and v.
%
% Surface: S(u,v) = sum_k A(:,k) * (U(ea(k)+1) * V(eb(k)+1)), U = cumprod([1 u u u u]),
% V = cumprod([1 v v v]), over all exponents 0 <= ea <= 4, 0 <= eb <= 3 (20 terms, ea varying
% fastest), A uniform in [-1, 1]; the sum is accumulated left to right (Octave's sum).
% Its degree (4, 3) exceeds what the networks interpolate exactly, so the Gordon surface is
% not S itself.
% Cases r = 1, 2, 3: (m+1, n+1, N) = (4, 3, 9), (2, 5, 11), (3, 2, 6); nodes x_u, x_v: r = 1
% [0, sorted uniform, 1]; r = 2 all sorted uniform in [0, 1] (not containing 0 and 1); r = 3
% [0 0.5 1] and [0 1] (the Coons case in v).
% Inputs:  r<r>_A     3 x 20        r<r>_ea, r<r>_eb   1 x 20, the exponents
%          r<r>_xu    1 x (m+1)     r<r>_xv   1 x (n+1)
%          r<r>_t     1 x N, linspace(0,1,N)
%          r<r>_g_u   3 x (n+1)N, [c_0 .. c_n], c_j(:, i) = S(t(i), x_v(j))
%          r<r>_g_v   3 x (m+1)N, [d_0 .. d_m], d_i(:, j) = S(x_u(i), t(j))
%          r<r>_g_uv  (m+1) x 3(n+1), g_uv(i, 3j-2:3j) = S(x_u(i), x_v(j))'
% Outputs: r<r>_P     N x N x 3, krpaGordon(g_u, g_v, g_uv, x_u, x_v, N)
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

rand('seed', 44);
[EB, EA] = meshgrid(0:3, 0:4);
ea = EA(:)';
eb = EB(:)';
S = @(A, u, v) sum(A .* (cumprod([1 u u u u])(ea+1) .* cumprod([1 v v v])(eb+1)), 2);
specs = [4 3 9; 2 5 11; 3 2 6];
names = {};
for r = 1:rows(specs)
    m1 = specs(r,1);
    n1 = specs(r,2);
    N = specs(r,3);
    A = 2*rand(3, numel(ea)) - 1;
    switch r
        case 1
            xu = [0 sort(rand(1, m1-2)) 1];
            xv = [0 sort(rand(1, n1-2)) 1];
        case 2
            xu = sort(rand(1, m1));
            xv = sort(rand(1, n1));
        otherwise
            xu = [0 0.5 1];
            xv = [0 1];
    end;
    t = linspace(0,1,N);
    g_u = zeros(3, n1*N);
    for j = 1:n1
        for i = 1:N
            g_u(:, (j-1)*N+i) = S(A, t(i), xv(j));
        end;
    end;
    g_v = zeros(3, m1*N);
    for i = 1:m1
        for j = 1:N
            g_v(:, (i-1)*N+j) = S(A, xu(i), t(j));
        end;
    end;
    g_uv = zeros(m1, 3*n1);
    for i = 1:m1
        for j = 1:n1
            g_uv(i, 3*j-2:3*j) = S(A, xu(i), xv(j))';
        end;
    end;
    [~, P] = krpaGordon(g_u, g_v, g_uv, xu, xv, N);
    key = sprintf('r%d', r);
    vars = {'A', 'ea', 'eb', 'xu', 'xv', 't', 'g_u', 'g_v', 'g_uv', 'P'};
    for k = 1:numel(vars)
        eval(sprintf('%s_%s = %s;', key, vars{k}, vars{k}));
        names{end+1} = sprintf('%s_%s', key, vars{k});
    end;
end;
save('-text', fullfile(outdir, 'gordon_random.txt'), names{:});

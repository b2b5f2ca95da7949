% Case "coons_random": random polynomial boundary curves with compatible corners through the
% fixed krpaCoons (on a grid) and vrednostCoons (at random points).
%
% For each case r = 1, 2, 3 (N = 7, 12, 2): corners Q = [P1 P2 P3 P4] uniform in [-2, 2]^3, and
% boundary curves through them, cubic with random coefficients A, B (uniform in [-1, 1]^3):
%   c1(u) = (1-u)*P1 + u*P2 + (u*(1-u))*(A(:,1) + B(:,1)*u)        x(u,0)
%   c2(u) = (1-u)*P3 + u*P4 + (u*(1-u))*(A(:,2) + B(:,2)*u)        x(u,1)
%   d1(v) = (1-v)*P1 + v*P3 + (v*(1-v))*(A(:,3) + B(:,3)*v)        x(0,v)
%   d2(v) = (1-v)*P2 + v*P4 + (v*(1-v))*(A(:,4) + B(:,4)*v)        x(1,v)
% evaluated for scalar parameters in exactly this order of operations.
% Inputs:  r<r>_Q    3 x 4, the corners P1..P4
%          r<r>_A, r<r>_B   3 x 4, the coefficients (columns: c1, c2, d1, d2)
%          r<r>_t    1 x N, linspace(0,1,N)
%          r<r>_c1, r<r>_c2, r<r>_d1, r<r>_d2   3 x N, the curves sampled at t
%          r<r>_uv   2 x 5, random parameter pairs (u; v)
% Outputs: r<r>_P    N x N x 3, krpaCoons(...)
%          r<r>_T, r<r>_rc, r<r>_rd, r<r>_rcd   3 x 5, vrednostCoons at the pairs r<r>_uv
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

rand('seed', 43);
names = {};
Ns = [7 12 2];
for r = 1:numel(Ns)
    N = Ns(r);
    Q = 4*rand(3,4) - 2;
    A = 2*rand(3,4) - 1;
    B = 2*rand(3,4) - 1;
    P1 = Q(:,1); P2 = Q(:,2); P3 = Q(:,3); P4 = Q(:,4);
    f_c1 = @(u) (1-u)*P1 + u*P2 + (u*(1-u))*(A(:,1) + B(:,1)*u);
    f_c2 = @(u) (1-u)*P3 + u*P4 + (u*(1-u))*(A(:,2) + B(:,2)*u);
    f_d1 = @(v) (1-v)*P1 + v*P3 + (v*(1-v))*(A(:,3) + B(:,3)*v);
    f_d2 = @(v) (1-v)*P2 + v*P4 + (v*(1-v))*(A(:,4) + B(:,4)*v);
    t = linspace(0,1,N);
    c1 = zeros(3,N); c2 = zeros(3,N); d1 = zeros(3,N); d2 = zeros(3,N);
    for i = 1:N
        c1(:,i) = f_c1(t(i));
        c2(:,i) = f_c2(t(i));
        d1(:,i) = f_d1(t(i));
        d2(:,i) = f_d2(t(i));
    end;
    [~, P] = krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4);
    uv = rand(2,5);
    T = zeros(3,5); rc = T; rd = T; rcd = T;
    for k = 1:5
        u = uv(1,k);
        v = uv(2,k);
        [T(:,k), rc(:,k), rd(:,k), rcd(:,k)] = ...
            vrednostCoons(u,v,f_c1(u),f_c2(u),f_d1(v),f_d2(v),P1,P2,P3,P4);
    end;
    key = sprintf('r%d', r);
    vars = {'Q', 'A', 'B', 't', 'c1', 'c2', 'd1', 'd2', 'uv', 'P', 'T', 'rc', 'rd', 'rcd'};
    for k = 1:numel(vars)
        eval(sprintf('%s_%s = %s;', key, vars{k}, vars{k}));
        names{end+1} = sprintf('%s_%s', key, vars{k});
    end;
end;
save('-text', fullfile(outdir, 'coons_random.txt'), names{:});

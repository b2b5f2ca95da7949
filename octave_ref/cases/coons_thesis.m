% Case "coons_thesis": the thesis's Coons data through the fixed vrednostCoons and krpaCoons.
%
% Primer 4.3: c1(u) = (u, 0, u-u^2), c2(u) = (u, 1, u), d1(v) = (0, v^2, v-v^2),
% d2(v) = (1, v, v), corners P1..P4 = x(0,0), x(1,0), x(0,1), x(1,1) = (0,0,0), (1,0,0),
% (0,1,0), (1,1,1), at u = 0.2, v = 0.5 (appendix C, data for Algoritem 6, with u, v set).
% Inputs:  ex_u, ex_v                      the parameters
%          ex_c1, ex_c2, ex_d1, ex_d2      3 x 1, the curves at u (c) and v (d)
%          P1, P2, P3, P4                  3 x 1, the corners
% Outputs: ex_T, ex_rc, ex_rd, ex_rcd      3 x 1, [T, rc, rd, rcd] = vrednostCoons(...)
%
% Appendix C's patch (data for Algoritem 5 as printed, with its "P3 = [1;1;1]" read as
% P4 = [1;1;1]) for N = 2, 3, 10, 101:
% Inputs:  t_N<N>                          1 x N, linspace(0,1,N) (both u and v)
%          c1_N<N>, c2_N<N>, d1_N<N>, d2_N<N>   3 x N, the sampled boundary curves
% Outputs: P_N<N>                          N x N x 3, [R, P] = krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)
%          R_N<N>                          N x 3N, the packed R (N = 2, 3 only)
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);

P1 = [0;0;0];
P2 = [1;0;0];
P3 = [0;1;0];
P4 = [1;1;1];
names = {'P1', 'P2', 'P3', 'P4'};

% Primer 4.3 (appendix C, data for Algoritem 6, evaluated at u = 0.2, v = 0.5).
ex_u = 0.2;
ex_v = 0.5;
u = ex_u;
v = ex_v;
ex_c1 = [u;0;u-u^2];
ex_c2 = [u;1;u];
ex_d1 = [0;v^2;v-v^2];
ex_d2 = [1;v;v];
[ex_T, ex_rc, ex_rd, ex_rcd] = vrednostCoons(u,v,ex_c1,ex_c2,ex_d1,ex_d2,P1,P2,P3,P4);
names(end+1:end+10) = {'ex_u', 'ex_v', 'ex_c1', 'ex_c2', 'ex_d1', 'ex_d2', ...
                       'ex_T', 'ex_rc', 'ex_rd', 'ex_rcd'};

% Appendix C, data for Algoritem 5 (the printed loops, with N set).
for N = [2 3 10 101]
    u = linspace(0,1,N);
    v = linspace(0,1,N);
    c1x = u;
    c1y = zeros(1,N);
    c1z = zeros(1,N);
    for i = 1:N
        c1z(i) = u(i)-(u(i))^2;
    end;
    c1 = [c1x;c1y;c1z];
    c2 = [u;ones(1,N);u];
    d1y = zeros(1,N);
    for i = 1:N
        d1y(i) = (v(i))^2;
    end;
    d1z = zeros(1,N);
    for i = 1:N
        d1z(i) = v(i)-(v(i))^2;
    end;
    d1 = [zeros(1,N);d1y;d1z];
    d2 = [ones(1,N);v;v];
    [R, P] = krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4);
    eval(sprintf('t_N%d = u;', N));
    eval(sprintf('c1_N%d = c1; c2_N%d = c2; d1_N%d = d1; d2_N%d = d2;', N, N, N, N));
    eval(sprintf('P_N%d = P;', N));
    names(end+1:end+6) = {sprintf('t_N%d', N), sprintf('c1_N%d', N), sprintf('c2_N%d', N), ...
                          sprintf('d1_N%d', N), sprintf('d2_N%d', N), sprintf('P_N%d', N)};
    if N <= 3
        eval(sprintf('R_N%d = R;', N));
        names{end+1} = sprintf('R_N%d', N);
    end;
end;
save('-text', fullfile(outdir, 'coons_thesis.txt'), names{:});

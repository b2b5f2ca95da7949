% Case "course_cli": references for the course subcommands of the command line (cagd elevate,
% bezier-patch --du/--dv, spline --params and closed splines, ruled, bspline-surface and
% nurbs-surface with an nrbmak struct as input), through octave-nurbs and octave-splines.
% Control points uniform in [-10, 10] from a fixed rand state; points are columns.
%   el_bez_C (2x4)          a cubic Bezier curve; el_bez_E1, el_bez_E2 = nrbdegelev by 1, 2
%   el_bsp_C (3x6), el_bsp_K (degree 2); el_bsp_C1/K1, el_bsp_C2/K2 = nrbdegelev by 1, 2
%   dp_B (3x3x4 net, degree (2,3), dp_B(:,i,j) = b_ij), dp_gu, dp_gv; dp_P = nrbeval,
%     dp_Du, dp_Dv (first derivatives), dp_Duu, dp_Duv, dp_Dvv (second; nrbdeval's hessian)
%   sp_Y (2x6), sp_s0, sp_sn; sp_t chord-length parameters; sp_e; sp_V = ppval(spline(sp_t,
%     [s0 Y sn]), e); sp_tc closed chord parameters (return to Y(:,1)), sp_ec parameters beyond
%     [sp_tc(1), sp_tc(end)], sp_Vc = ppval(csape periodic) at sp_ec wrapped by whole periods
%   ru_C1 (3x4), ru_C2 (3x3) Bezier curves; ru_gu, ru_gv; ru_S = nrbeval(nrbruled(c1, c2))
%   srf: an nrbmak struct (rational, degree (2,3)); srf_gu, srf_gv, srf_S = nrbeval(srf, {gu, gv})
%   bsrf: an nrbmak struct with weights 1 (degree (3,2)); bsrf_gu, bsrf_gv, bsrf_S = nrbeval
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
pkg load nurbs;
pkg load splines;
save_precision(17);
rand('state', 4015);
names = {};

el_bez_C = 20*rand(2, 4) - 10;
bez = nrbmak(el_bez_C, [0 0 0 0 1 1 1 1]);
e1 = nrbdegelev(bez, 1); e2 = nrbdegelev(bez, 2);
el_bez_E1 = e1.coefs(1:2, :); el_bez_E2 = e2.coefs(1:2, :);
el_bsp_C = 20*rand(3, 6) - 10;
el_bsp_K = [0 0 0 0.3 0.3 0.7 1 1 1];
bsp = nrbmak(el_bsp_C, el_bsp_K);
b1 = nrbdegelev(bsp, 1); b2 = nrbdegelev(bsp, 2);
el_bsp_C1 = b1.coefs(1:3, :); el_bsp_K1 = b1.knots;
el_bsp_C2 = b2.coefs(1:3, :); el_bsp_K2 = b2.knots;
names = [names, {'el_bez_C', 'el_bez_E1', 'el_bez_E2', 'el_bsp_C', 'el_bsp_K', 'el_bsp_C1', 'el_bsp_K1', 'el_bsp_C2', 'el_bsp_K2'}];

dp_B = 20*rand(3, 3, 4) - 10;
dp_srf = nrbmak(dp_B, {[0 0 0 1 1 1], [0 0 0 0 1 1 1 1]});
[d1, d2] = nrbderiv(dp_srf);
dp_gu = linspace(0, 1, 5); dp_gv = [0 0.3 0.75 1];
[dp_P, D, H] = nrbdeval(dp_srf, d1, d2, {dp_gu, dp_gv});
dp_Du = D{1}; dp_Dv = D{2}; dp_Duu = H{1,1}; dp_Duv = H{1,2}; dp_Dvv = H{2,2};
names = [names, {'dp_B', 'dp_gu', 'dp_gv', 'dp_P', 'dp_Du', 'dp_Dv', 'dp_Duu', 'dp_Duv', 'dp_Dvv'}];

sp_Y = 20*rand(2, 6) - 10;
sp_s0 = 4*rand(2, 1) - 2; sp_sn = 4*rand(2, 1) - 2;
sp_t = [0, cumsum(sqrt(sum(diff(sp_Y, 1, 2).^2, 1)))];
sp_e = linspace(sp_t(1), sp_t(end), 17);
sp_V = ppval(spline(sp_t, [sp_s0 sp_Y sp_sn]), sp_e);
closing = sqrt(sum((sp_Y(:, 1) - sp_Y(:, end)).^2));
sp_tc = [sp_t, sp_t(end) + closing];
period = sp_tc(end) - sp_tc(1);
sp_ec = linspace(sp_tc(1) - 0.6*period, sp_tc(end) + 1.3*period, 23);
wrapped = sp_tc(1) + mod(sp_ec - sp_tc(1), period);
sp_Vc = ppval(csape(sp_tc, [sp_Y sp_Y(:, 1)], 'periodic'), wrapped);
names = [names, {'sp_Y', 'sp_s0', 'sp_sn', 'sp_t', 'sp_e', 'sp_V', 'sp_tc', 'sp_ec', 'sp_Vc'}];

ru_C1 = 20*rand(3, 4) - 10; ru_C2 = 20*rand(3, 3) - 10;
ru_gu = linspace(0, 1, 7); ru_gv = [0 0.25 0.6 1];
ruled = nrbruled(nrbmak(ru_C1, [0 0 0 0 1 1 1 1]), nrbmak(ru_C2, [0 0 0 1 1 1]));
ru_S = nrbeval(ruled, {ru_gu, ru_gv});
names = [names, {'ru_C1', 'ru_C2', 'ru_gu', 'ru_gv', 'ru_S'}];

w = 0.5 + 1.5*rand(4, 5);
coefs = zeros(4, 4, 5);
for c = 1:3
  coefs(c, :, :) = (20*rand(4, 5) - 10) .* w;
end;
coefs(4, :, :) = w;
srf = nrbmak(coefs, {[0 0 0 0.5 1 1 1], [0 0 0 0 0.4 1 1 1 1]});
srf_gu = linspace(0, 1, 6); srf_gv = linspace(0, 1, 5);
srf_S = nrbeval(srf, {srf_gu, srf_gv});
bcoefs = zeros(4, 5, 4);
for c = 1:3
  bcoefs(c, :, :) = 20*rand(5, 4) - 10;
end;
bcoefs(4, :, :) = 1;
bsrf = nrbmak(bcoefs, {[0 0 0 0 0.5 1 1 1 1], [0 0 0 0.25 1 1 1]});
bsrf_gu = linspace(0, 1, 5); bsrf_gv = linspace(0, 1, 6);
bsrf_S = nrbeval(bsrf, {bsrf_gu, bsrf_gv});
names = [names, {'srf', 'srf_gu', 'srf_gv', 'srf_S', 'bsrf', 'bsrf_gu', 'bsrf_gv', 'bsrf_S'}];

save('-text', fullfile(outdir, 'course_cli.txt'), names{:});

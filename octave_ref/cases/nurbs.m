% Case "nurbs": NURBS curves and surfaces through octave-nurbs.
% Curves, per key: deg_<key>, knots_<key>, H_<key> (4 x n homogeneous coefs [w.*x; w] as given
%   to nrbmak), u_<key>, P_<key> = nrbeval (3 x N), T_<key> = second output of nrbdeval(crv, nrbderiv(crv), u)
%   (3 x N), ins_<key>, IH_<key>/IK_<key> = coefs/knots of nrbkntins(crv, ins).
% Circles: circ_<k>_args = [radius cx cy cz sang eang], circ_<k>_H = nrbcirc(...).coefs,
%   circ_<k>_knots, circ_<k>_u, circ_<k>_P = nrbeval.
% Surface: srf_ku, srf_kv, srf_H (4 x nu x nv), srf_gu, srf_gv, srf_S = nrbeval(srf, {gu, gv}).
% Ruled: rul_H1, rul_k1, rul_H2, rul_k2 (two cubic curves, different interior knots),
%   rul_gu, rul_gv, rul_S = nrbeval(nrbruled(c1, c2), {gu, gv}).
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
pkg load nurbs;
save_precision(17);
rand('state', 4006);
names = {};
specs = {
  'p2', 2, [0 0 0 0.3 0.7 1 1 1], [0.5];
  'p3', 3, [0 0 0 0 0.25 0.5 0.5 1 1 1 1], [0.1 0.75 0.75];
};
for r = 1:rows(specs)
  [key, p, knots, ins] = specs{r,:};
  n = numel(knots) - p - 1;
  X = 20*rand(3, n) - 10;
  w = 0.5 + 1.5*rand(1, n);
  H = [X .* repmat(w, 3, 1); w];
  crv = nrbmak(H, knots);
  u = linspace(0, 1, 21);
  P = nrbeval(crv, u);
  [~, T] = nrbdeval(crv, nrbderiv(crv), u);
  icrv = nrbkntins(crv, ins);
  IH = icrv.coefs; IK = icrv.knots;
  eval(sprintf('deg_%s = p; knots_%s = knots; H_%s = H; u_%s = u; P_%s = P; T_%s = T; ins_%s = ins; IH_%s = IH; IK_%s = IK;', ...
       key, key, key, key, key, key, key, key, key));
  for v = {'deg', 'knots', 'H', 'u', 'P', 'T', 'ins', 'IH', 'IK'}
    names{end+1} = sprintf('%s_%s', v{1}, key);
  end;
end;
circ = [1 0 0 0 0 2*pi; 2.5 1 -2 0.5 0 2*pi; 3 0 0 0 0.3 1.2; 0.7 -1 1 2 1 3.5; 1.5 2 2 0 -0.5 4; 2 0 0 0 5 1];
for k = 1:rows(circ)
  a = circ(k,:);
  c = nrbcirc(a(1), a(2:4), a(5), a(6));
  cu = linspace(0, 1, 33);
  eval(sprintf('circ_%d_args = a; circ_%d_H = c.coefs; circ_%d_knots = c.knots; circ_%d_u = cu; circ_%d_P = nrbeval(c, cu);', k, k, k, k, k));
  for v = {'args', 'H', 'knots', 'u', 'P'}
    names{end+1} = sprintf('circ_%d_%s', k, v{1});
  end;
end;
srf_ku = [0 0 0 0.4 1 1 1]; srf_kv = [0 0 0 0 0.5 1 1 1 1];
nu = 4; nv = 5;
srf_H = zeros(4, nu, nv);
wts = 0.5 + 1.5*rand(nu, nv);
for c = 1:3
  srf_H(c,:,:) = (20*rand(nu, nv) - 10) .* wts;
end;
srf_H(4,:,:) = wts;
srf_gu = linspace(0, 1, 8); srf_gv = linspace(0, 1, 6);
srf_S = nrbeval(nrbmak(srf_H, {srf_ku, srf_kv}), {srf_gu, srf_gv});
names = [names, {'srf_ku', 'srf_kv', 'srf_H', 'srf_gu', 'srf_gv', 'srf_S'}];
rul_k1 = [0 0 0 0 0.5 1 1 1 1]; rul_k2 = [0 0 0 0 0.25 0.75 1 1 1 1];
w1 = 0.5 + 1.5*rand(1, 5); w2 = 0.5 + 1.5*rand(1, 6);
rul_H1 = [(20*rand(3,5) - 10) .* repmat(w1, 3, 1); w1];
rul_H2 = [(20*rand(3,6) - 10) .* repmat(w2, 3, 1); w2];
rul_gu = linspace(0, 1, 9); rul_gv = linspace(0, 1, 5);
rul_S = nrbeval(nrbruled(nrbmak(rul_H1, rul_k1), nrbmak(rul_H2, rul_k2)), {rul_gu, rul_gv});
names = [names, {'rul_k1', 'rul_k2', 'rul_H1', 'rul_H2', 'rul_gu', 'rul_gv', 'rul_S'}];
save('-text', fullfile(outdir, 'nurbs.txt'), names{:});

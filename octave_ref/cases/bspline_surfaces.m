% Case "bspline_surfaces": tensor-product B-spline surfaces (all weights 1) through
% octave-nurbs nrbmak/nrbeval on a grid.  Per key:
%   degu_<key>, degv_<key>; ku_<key>, kv_<key> knot vectors; X_<key>, Y_<key>, Z_<key> the
%   nu x nv control coordinates (entry (i,j) = P_ij, i along u); gu_<key>, gv_<key> grid
%   parameters; S_<key> 3 x numel(gu) x numel(gv) = nrbeval(nrbmak(coefs, {ku, kv}), {gu, gv}).
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
pkg load nurbs;
save_precision(17);
rand('state', 4005);
names = {};
specs = {
  'bicubic_clamped', 3, 3, [0 0 0 0 0.5 1 1 1 1], [0 0 0 0 0.3 0.6 1 1 1 1];
  'p2q1',            2, 1, [0 0 0 0.25 0.75 1 1 1], [0 0 0.5 1 1];
  'bicubic_uniform', 3, 3, [-3 -2 -1 0 1 2 3 4 5], [-3 -2 -1 0 1 2 3 4];
};
for r = 1:rows(specs)
  [key, p, q, ku, kv] = specs{r,:};
  nu = numel(ku) - p - 1;
  nv = numel(kv) - q - 1;
  X = 20*rand(nu, nv) - 10; Y = 20*rand(nu, nv) - 10; Z = 20*rand(nu, nv) - 10;
  coefs = zeros(4, nu, nv);
  coefs(1,:,:) = X; coefs(2,:,:) = Y; coefs(3,:,:) = Z; coefs(4,:,:) = 1;
  gu = linspace(ku(p+1), ku(nu+1), 9);
  gv = linspace(kv(q+1), kv(nv+1), 7);
  S = nrbeval(nrbmak(coefs, {ku, kv}), {gu, gv});
  eval(sprintf('degu_%s = p; degv_%s = q; ku_%s = ku; kv_%s = kv; X_%s = X; Y_%s = Y; Z_%s = Z; gu_%s = gu; gv_%s = gv; S_%s = S;', ...
       key, key, key, key, key, key, key, key, key, key));
  for v = {'degu', 'degv', 'ku', 'kv', 'X', 'Y', 'Z', 'gu', 'gv', 'S'}
    names{end+1} = sprintf('%s_%s', v{1}, key);
  end;
end;
save('-text', fullfile(outdir, 'bspline_surfaces.txt'), names{:});

% Case "hermite": Ferguson (Hermite) cubics.  The complete spline through two points,
% spline([0 1], [x1' x1 x2 x2']), is exactly the Hermite cubic with those end tangents, so
% Octave's spline/ppval is an independent reference.  Per key k:
%   G_<k> = [x1 x2 x1' x2'] (d x 4, the lecture notes' X_H);  u = linspace(0,1,21);
%   V_<k> = ppval(spline([0 1], [G(:,3) G(:,1) G(:,2) G(:,4)]), u) (d x 21).
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);
rand('state', 4008);
u = linspace(0, 1, 21);
names = {'u'};
for k = 1:4
  d = [1 2 3 3](k);
  G = 20*rand(d, 4) - 10;
  V = ppval(spline([0 1], [G(:,3) G(:,1) G(:,2) G(:,4)]), u);
  eval(sprintf('G_%d = G; V_%d = V;', k, k));
  names = [names, {sprintf('G_%d', k), sprintf('V_%d', k)}];
end;
save('-text', fullfile(outdir, 'hermite.txt'), names{:});

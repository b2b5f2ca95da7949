% Case "spline": interpolating cubic splines.  Clamped: Octave's spline(t, [s0 y sn]) (the
% complete spline) and ppval; natural: csape(t, y, 'variational'); closed: csape(t, y,
% 'periodic') with the first point appended at the end (parameter t_m).  Per key:
%   t_<key> parameters (1 x m, or 1 x (m+1) for closed); Y_<key> points (d x m, columns);
%   s0_<key>, sn_<key> end tangents (clamped only); e_<key> evaluation parameters;
%   V_<key> = ppval(pp, e) (d x N).
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
pkg load splines;
save_precision(17);
rand('state', 4007);
names = {};
% The lecture notes' example, clamped, unit parameters.
t_seed = 0:3; Y_seed = [0 2 4 6; 0 1 4 0]; s0_seed = [1; 1]; sn_seed = [-1; 1];
e_seed = linspace(0, 3, 31);
V_seed = ppval(spline(t_seed, [s0_seed Y_seed sn_seed]), e_seed);
names = [names, {'t_seed', 'Y_seed', 's0_seed', 'sn_seed', 'e_seed', 'V_seed'}];
for r = 1:2
  m = [7 12](r); d = [2 3](r);
  Y = 20*rand(d, m) - 10;
  tu = 0:m-1;
  tr = cumsum([0, 0.2 + 1.8*rand(1, m-1)]);
  s0 = 4*rand(d,1) - 2; sn = 4*rand(d,1) - 2;
  for kind = {'uniform', 'random'}
    if strcmp(kind{1}, 'uniform'), t = tu; else, t = tr; end;
    e = linspace(t(1), t(end), 41);
    key = sprintf('clamped_%s_%d', kind{1}, r);
    eval(sprintf('t_%s = t; Y_%s = Y; s0_%s = s0; sn_%s = sn; e_%s = e; V_%s = ppval(spline(t, [s0 Y sn]), e);', key, key, key, key, key, key));
    names = [names, cellfun(@(v) [v '_' key], {'t', 'Y', 's0', 'sn', 'e', 'V'}, 'UniformOutput', false)];
    key = sprintf('natural_%s_%d', kind{1}, r);
    eval(sprintf('t_%s = t; Y_%s = Y; e_%s = e; V_%s = ppval(csape(t, Y, ''variational''), e);', key, key, key, key));
    names = [names, cellfun(@(v) [v '_' key], {'t', 'Y', 'e', 'V'}, 'UniformOutput', false)];
    if strcmp(kind{1}, 'uniform'), tc = 0:m; else, tc = [tr, tr(end) + 0.2 + 1.8*rand()]; end;
    ec = linspace(tc(1), tc(end), 41);
    key = sprintf('closed_%s_%d', kind{1}, r);
    eval(sprintf('t_%s = tc; Y_%s = Y; e_%s = ec; V_%s = ppval(csape(tc, [Y Y(:,1)], ''periodic''), ec);', key, key, key, key));
    names = [names, cellfun(@(v) [v '_' key], {'t', 'Y', 'e', 'V'}, 'UniformOutput', false)];
  end;
end;
save('-text', fullfile(outdir, 'spline.txt'), names{:});

% Case "bspline_curves": B-spline curves through octave-nurbs (bspeval, bspderiv, bspkntins,
% findspan, basisfun).  Control points uniform in [-10, 10] from a fixed rand state.
% Per key:
%   deg_<key>   degree p;  knots_<key> 1 x (n+p+1);  C_<key> d x n control points (columns)
%   u_<key>     1 x N parameters (linspace over the domain [u_p, u_n])
%   P_<key>     d x N  bspeval(p, C, knots, u)
%   dP_<key>    d x N  derivative: bspderiv then bspeval
%   S_<key>     1 x N  findspan (0-based);  B_<key>  N x (p+1)  basisfun
%   ins_<key>   knots inserted;  IC_<key>, IK_<key>  bspkntins(p, C, knots, ins)
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
pkg load nurbs;
save_precision(17);
rand('state', 4004);
names = {};
specs = {
  'p1_clamped',   1, [0 0 0.25 0.5 1 1],                       2, [0.1 0.6 0.6];
  'p2_clamped',   2, [0 0 0 0.2 0.55 0.7 1 1 1],               3, [0.3 0.55 0.9];
  'p3_clamped',   3, [0 0 0 0 1/3 2/3 1 1 1 1],                3, [0.5 0.5 0.1];
  'p3_repeated',  3, [0 0 0 0 0.4 0.4 0.4 0.8 1 1 1 1],        2, [0.2 0.9];
  'p3_uniform',   3, [-3 -2 -1 0 1 2 3 4 5],                   2, [0.5 1.5];
  'p4_nonunif',   4, [0 0.5 1 1.5 2.5 3 4 5.5 6 7 7.5],        3, [3.25];
  'p5_bezier',    5, [0 0 0 0 0 0 1 1 1 1 1 1],                3, [0.5 0.25];
};
for r = 1:rows(specs)
  [key, p, knots, d, ins] = specs{r,:};
  n = numel(knots) - p - 1;
  C = 20*rand(d, n) - 10;
  u = linspace(knots(p+1), knots(n+1), 23);
  P = bspeval(p, C, knots, u);
  [dc, dk] = bspderiv(p, C, knots);
  dP = bspeval(p-1, dc, dk, u);
  S = findspan(n-1, p, u, knots);
  B = basisfun(S, u, p, knots);
  [IC, IK] = bspkntins(p, C, knots, ins);
  eval(sprintf('deg_%s = p; knots_%s = knots; C_%s = C; u_%s = u; P_%s = P; dP_%s = dP; S_%s = S; B_%s = B; ins_%s = ins; IC_%s = IC; IK_%s = IK;', ...
       key, key, key, key, key, key, key, key, key, key, key));
  for v = {'deg', 'knots', 'C', 'u', 'P', 'dP', 'S', 'B', 'ins', 'IC', 'IK'}
    names{end+1} = sprintf('%s_%s', v{1}, key);
  end;
end;
save('-text', fullfile(outdir, 'bspline_curves.txt'), names{:});

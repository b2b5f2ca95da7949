% Case "interp": Lagrange interpolation through polyfit/polyval, piecewise linear through
% interp1.  Per key:
%   x_<key>, y_<key> data (1 x n);  c_<key> = polyfit(x, y, n-1) (descending powers);
%   e_<key> evaluation points;  L_<key> = polyval(c, e);  PL_<key> = interp1(x, y, e, 'linear').
% The lecture notes' example is key "seed": (1,1),(2,2),(3,3),(4,2),(5,1).
% polyfit solves a least-squares problem with a Vandermonde matrix (QR in the machine's LAPACK):
% its coefficients and values carry about cond(V)*eps, cond(V) up to 1e5 for these nodes, and
% differ in the last digits between BLAS/LAPACK builds and processors.  The Rust test compares
% with 1e-10; so does octave_ref/check.sh:
% compare: relative 1e-10
outdir = getenv('CAGD_REF_OUT');
if isempty(outdir), error('CAGD_REF_OUT is not set'); end;
save_precision(17);
rand('state', 4009);
names = {};
sets = {'seed', [1 2 3 4 5], [1 2 3 2 1]};
sets(end+1,:) = {'cheb6', cos(pi*(2*(0:5)+1)/12), 20*rand(1,6) - 10};
sets(end+1,:) = {'rand4', sort(10*rand(1,4)), 20*rand(1,4) - 10};
sets(end+1,:) = {'uniform8', linspace(-1, 1, 8), 2*rand(1,8) - 1};
for r = 1:rows(sets)
  [key, x, y] = sets{r,:};
  c = polyfit(x, y, numel(x) - 1);
  e = linspace(min(x), max(x), 29);
  eval(sprintf('x_%s = x; y_%s = y; c_%s = c; e_%s = e; L_%s = polyval(c, e); PL_%s = interp1(x, y, e, ''linear'');', key, key, key, key, key, key));
  names = [names, cellfun(@(v) [v '_' key], {'x', 'y', 'c', 'e', 'L', 'PL'}, 'UniformOutput', false)];
end;
save('-text', fullfile(outdir, 'interp.txt'), names{:});

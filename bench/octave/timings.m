% timings.m -- Octave side of bench/compare_octave.sh.
%
% Prints one line per case, "case<TAB>function<TAB>seconds" (best of several tic/toc runs),
% on the same geometry as cagd-bench (bench/src/lib.rs):
%   bicubic patch  b(i,j) = (i/3, j/3, mod(7i+3j, 5)/4 - 1/2), i, j = 0..3
%   cubic curve    (0,0,0), (1,2,1), (3,-1,2), (4,1,0)
%   Coons          the four boundary curves of the patch, sampled at linspace(0,1,N)
%   Gordon         the 5 x 5 network of its isoparametric cubics at 0, 1/4, 1/2, 3/4, 1
%   B-spline       bicubic over the 10 x 10 net (i/9, j/9, mod(7i+3j, 5)/4 - 1/2), clamped
%                  uniform knots 0 0 0 0 1/7 ... 6/7 1 1 1 1
% Functions: the fixed thesis functions (octave_ref/fixed: ploskevB, krpaCoons, krpaGordon)
% and octave-nurbs nrbeval.  Sampling the curves for krpaCoons / krpaGordon is not timed.
% Run from the repository root: octave --no-gui --quiet bench/octave/timings.m
addpath(fullfile(pwd, 'octave_ref', 'fixed'));
pkg load nurbs

function t = best_of(f, reps)
  t = Inf;
  for r = 1:reps
    tic; f(); t = min(t, toc);
  end
end

function report(name, fn, t)
  printf('%s\t%s\t%.6e\n', name, fn, t);
  fflush(stdout);
end

% Bernstein matrix: rows = parameters, columns = B_0..B_n.
function B = bern(n, t)
  t = t(:);
  B = zeros(numel(t), n + 1);
  for i = 0:n
    B(:, i + 1) = nchoosek(n, i) * t.^i .* (1 - t).^(n - i);
  end
end

b = zeros(4, 4, 3);
for i = 0:3
  for j = 0:3
    b(i+1, j+1, :) = [i/3, j/3, mod(7*i + 3*j, 5)/4 - 0.5];
  end
end
% Packed net for ploskevB: kontrolneT(i+1, 3j+1:3j+3) = b(i,j).
kontrolneT = zeros(4, 12);
for i = 1:4
  for j = 1:4
    kontrolneT(i, 3*j-2:3*j) = squeeze(b(i, j, :))';
  end
end
% octave-nurbs forms: coefs 4 x 4 x 4 (weights 1).
coefs = ones(4, 4, 4);
for k = 1:3
  coefs(k, :, :) = b(:, :, k);
end
srf = nrbmak(coefs, {[0 0 0 0 1 1 1 1], [0 0 0 0 1 1 1 1]});
crv = nrbmak([0 1 3 4; 0 2 -1 1; 0 1 2 0], [0 0 0 0 1 1 1 1]);

% x(u, v) on parameter vectors: X(:, :, k) = Bu * b(:,:,k) * Bv'.
function X = patch_grid(b, us, vs)
  Bu = bern(3, us); Bv = bern(3, vs);
  X = zeros(numel(us), numel(vs), 3);
  for k = 1:3
    X(:, :, k) = Bu * b(:, :, k) * Bv';
  end
end

% Bezier patch: ploskevB (per point de Casteljau, interpreted) and nrbeval.
for N = [30 100]
  report(sprintf('patch_bicubic_N%d', N), 'ploskevB', best_of(@() ploskevB(kontrolneT, N), 2));
end
for N = [100 1000]
  t = linspace(0, 1, N);
  report(sprintf('patch_bicubic_N%d', N), 'nrbeval', best_of(@() nrbeval(srf, {t, t}), 3));
end
% B-spline surface: bicubic over the 10 x 10 net P(i,j) = (i/9, j/9, mod(7i+3j, 5)/4 - 1/2),
% clamped uniform knots (as cagd-bench bspline_surface(3, 10)).
kn = [0 0 0 0 (1:6)/7 1 1 1 1];
bcoefs = ones(4, 10, 10);
for i = 0:9
  for j = 0:9
    bcoefs(1:3, i+1, j+1) = [i/9; j/9; mod(7*i + 3*j, 5)/4 - 0.5];
  end
end
bsrf = nrbmak(bcoefs, {kn, kn});
for N = [100 1000]
  t = linspace(0, 1, N);
  report(sprintf('bspline_bicubic_N%d', N), 'nrbeval', best_of(@() nrbeval(bsrf, {t, t}), 3));
end
for K = [10000 1000000]
  t = linspace(0, 1, K);
  report(sprintf('curve_cubic_K%d', K), 'nrbeval', best_of(@() nrbeval(crv, t), 3));
end

% Coons: krpaCoons on the sampled boundary of the patch.
P1 = squeeze(b(1,1,:)); P2 = squeeze(b(4,1,:)); P3 = squeeze(b(1,4,:)); P4 = squeeze(b(4,4,:));
for N = [100 300]
  t = linspace(0, 1, N);
  X0 = patch_grid(b, t, [0 1]);    % c1 = x(u, 0), c2 = x(u, 1)
  Y0 = patch_grid(b, [0 1], t);    % d1 = x(0, v), d2 = x(1, v)
  c1 = squeeze(X0(:, 1, :))'; c2 = squeeze(X0(:, 2, :))';
  d1 = squeeze(Y0(1, :, :))'; d2 = squeeze(Y0(2, :, :))';
  report(sprintf('coons_N%d', N), 'krpaCoons', ...
         best_of(@() krpaCoons(c1, c2, d1, d2, P1, P2, P3, P4), 2));
end

% Gordon: krpaGordon on the sampled 5 x 5 network.
nodes = [0 0.25 0.5 0.75 1];
for N = [20 50]
  t = linspace(0, 1, N);
  A = patch_grid(b, t, nodes);     % c_j(t_i) = x(t_i, v_j)
  D = patch_grid(b, nodes, t);     % d_i(t_j) = x(u_i, t_j)
  C = patch_grid(b, nodes, nodes); % crossings
  g_u = zeros(3, 5*N); g_v = zeros(3, 5*N); g_uv = zeros(5, 15);
  for j = 1:5
    g_u(:, (j-1)*N+1:j*N) = squeeze(A(:, j, :))';
    g_v(:, (j-1)*N+1:j*N) = squeeze(D(j, :, :))';
    for i = 1:5
      g_uv(i, 3*j-2:3*j) = squeeze(C(i, j, :))';
    end
  end
  report(sprintf('gordon_N%d', N), 'krpaGordon', ...
         best_of(@() krpaGordon(g_u, g_v, g_uv, nodes, nodes, N), 2));
end

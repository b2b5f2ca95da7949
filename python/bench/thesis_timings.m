% thesis_timings.m -- Octave side of python/bench/bench.py: times the fixed thesis functions
% (octave_ref/fixed) on the geometry of bench/octave/timings.m and saves the inputs, so that
% the Python side times cagd.octave on exactly the same arrays.
% Prints "case<TAB>function<TAB>seconds" (best of several tic/toc runs).
% Usage (from the repository root): octave --no-gui --quiet python/bench/thesis_timings.m OUT.txt
addpath(fullfile(pwd, 'octave_ref', 'fixed'));
out = argv(){end};

function t = best_of(f, reps)
  t = Inf;
  for r = 1:reps
    tic; f(); t = min(t, toc);
  end
end

function B = bern(n, t)
  t = t(:);
  B = zeros(numel(t), n + 1);
  for i = 0:n
    B(:, i + 1) = nchoosek(n, i) * t.^i .* (1 - t).^(n - i);
  end
end

function X = patch_grid(b, us, vs)
  Bu = bern(3, us); Bv = bern(3, vs);
  X = zeros(numel(us), numel(vs), 3);
  for k = 1:3
    X(:, :, k) = Bu * b(:, :, k) * Bv';
  end
end

b = zeros(4, 4, 3);
for i = 0:3
  for j = 0:3
    b(i+1, j+1, :) = [i/3, j/3, mod(7*i + 3*j, 5)/4 - 0.5];
  end
end
kontrolneT = zeros(4, 12);
for i = 1:4
  for j = 1:4
    kontrolneT(i, 3*j-2:3*j) = squeeze(b(i, j, :))';
  end
end
curve = [0 1 3 4; 0 2 -1 1; 0 1 2 0];
for N = [1000 10000]
  printf('deCasteljau_N%d\tdeCasteljau\t%.6e\n', N, best_of(@() deCasteljau(curve, N), 2));
end
for N = [30 100]
  printf('ploskevB_N%d\tploskevB\t%.6e\n', N, best_of(@() ploskevB(kontrolneT, N), 2));
end
printf('bilinearna\tbilinearna\t%.6e\n', best_of(@() bilinearna(kontrolneT, 0.3, 0.7, 10), 20));
printf('tenzor_4x4\ttenzor\t%.6e\n', best_of(@() tenzor(kontrolneT), 20));
% A packed net of 200 x 200 points: tenzor's loops over every point.
bigT = zeros(200, 600);
for i = 1:200
  for j = 1:600
    bigT(i, j) = mod(7*i + 3*j, 11) / 10;
  end
end
printf('tenzor_200x200\ttenzor\t%.6e\n', best_of(@() tenzor(bigT), 2));
P1 = squeeze(b(1,1,:)); P2 = squeeze(b(4,1,:)); P3 = squeeze(b(1,4,:)); P4 = squeeze(b(4,4,:));
names = {'curve', 'kontrolneT', 'bigT', 'P1', 'P2', 'P3', 'P4'};
% vrednostCoons at (0.3, 0.7): the boundary curves of the patch b at u = 0.3 (c1, c2) and
% v = 0.7 (d1, d2), 3 x 1 each.
X0 = patch_grid(b, 0.3, [0 1]);
Y0 = patch_grid(b, [0 1], 0.7);
vc_c1 = squeeze(X0(1, 1, :)); vc_c2 = squeeze(X0(1, 2, :));
vc_d1 = squeeze(Y0(1, 1, :)); vc_d2 = squeeze(Y0(2, 1, :));
printf('vrednostCoons\tvrednostCoons\t%.6e\n', ...
       best_of(@() vrednostCoons(0.3, 0.7, vc_c1, vc_c2, vc_d1, vc_d2, P1, P2, P3, P4), 20));
names(end+1:end+4) = {'vc_c1', 'vc_c2', 'vc_d1', 'vc_d2'};
for N = [100 300]
  t = linspace(0, 1, N);
  X0 = patch_grid(b, t, [0 1]);
  Y0 = patch_grid(b, [0 1], t);
  c1 = squeeze(X0(:, 1, :))'; c2 = squeeze(X0(:, 2, :))';
  d1 = squeeze(Y0(1, :, :))'; d2 = squeeze(Y0(2, :, :))';
  printf('krpaCoons_N%d\tkrpaCoons\t%.6e\n', N, ...
         best_of(@() krpaCoons(c1, c2, d1, d2, P1, P2, P3, P4), 2));
  eval(sprintf('coons_c1_N%d = c1; coons_c2_N%d = c2; coons_d1_N%d = d1; coons_d2_N%d = d2;', N, N, N, N));
  names(end+1:end+4) = {sprintf('coons_c1_N%d', N), sprintf('coons_c2_N%d', N), sprintf('coons_d1_N%d', N), sprintf('coons_d2_N%d', N)};
end
nodes = [0 0.25 0.5 0.75 1];
for N = [20 50]
  t = linspace(0, 1, N);
  A = patch_grid(b, t, nodes);
  D = patch_grid(b, nodes, t);
  C = patch_grid(b, nodes, nodes);
  g_u = zeros(3, 5*N); g_v = zeros(3, 5*N); g_uv = zeros(5, 15);
  for j = 1:5
    g_u(:, (j-1)*N+1:j*N) = squeeze(A(:, j, :))';
    g_v(:, (j-1)*N+1:j*N) = squeeze(D(j, :, :))';
    for i = 1:5
      g_uv(i, 3*j-2:3*j) = squeeze(C(i, j, :))';
    end
  end
  printf('krpaGordon_N%d\tkrpaGordon\t%.6e\n', N, ...
         best_of(@() krpaGordon(g_u, g_v, g_uv, nodes, nodes, N), 2));
  eval(sprintf('gordon_g_u_N%d = g_u; gordon_g_v_N%d = g_v; gordon_g_uv_N%d = g_uv;', N, N, N));
  names(end+1:end+3) = {sprintf('gordon_g_u_N%d', N), sprintf('gordon_g_v_N%d', N), sprintf('gordon_g_uv_N%d', N)};
end
u = linspace(-0.1, 1.1, 100000);
printf('Lagrange_K100000\tLagrange\t%.6e\n', best_of(@() Lagrange(nodes, 3, u), 3));
names(end+1) = 'nodes';
save_precision(17);
save('-text', out, names{:});

% bench_cagd (refdir) -- the speed of the Octave package cagd, measured in this one Octave
% session (octave_pkg/bench/run.sh installs the package and calls this):
%   * the thesis functions against the fixed Octave code of octave_ref/fixed (copied into a
%     temporary directory as fixed_*, their bodies unchanged): deCasteljau (B, 1e6),
%     ploskevB at N = 100, krpaCoons at N = 100 and 300, krpaGordon at N = 20 and 50;
%   * cagd_nrbeval against octave-nurbs' nrbeval: a 1000 x 1000 grid of a bicubic patch and of
%     a rational bicubic with interior knots, 1e6 points of a cubic and of a rational cubic
%     with interior knots;
%   * the cost of one call for a single point.
% Times are the best of several runs (tic/toc, the outputs' allocation included); each fixed
% Octave function runs once or twice (seconds to minutes).  CAGD_BENCH_FIXED_N = k runs the
% fixed deCasteljau at k points instead of 1e6 and scales its time linearly (stated).
% The geometry is that of bench/octave/timings.m and the criterion benches: the bicubic net
% b_ij = (i/3, j/3, mod(7i+3j, 5)/4 - 1/2), the cubic (0,0,0), (1,2,1), (3,-1,2), (4,1,0),
% the patch's boundary curves (Coons) and its 5 x 5 network of isoparametric cubics at
% 0, 1/4, 1/2, 3/4, 1 (Gordon), sampled by the package before timing.
function bench_cagd (refdir)
  pkg load nurbs;
  if isempty (which ("__cagd__")), pkg load cagd; end
  names = {"deCasteljau", "ploskevB", "bilinearna", "tenzor", "Lagrange", ...
           "vrednostCoons", "krpaCoons", "krpaGordon"};
  fixed = tempname ();
  mkdir (fixed);
  for f = dir (fullfile (refdir, "fixed", "*.m"))'
    text = regexprep (fileread (fullfile (refdir, "fixed", f.name)), ...
                      ['\<(' strjoin(names, '|') ')\>'], 'fixed_$1');
    fid = fopen (fullfile (fixed, ["fixed_" f.name]), "w"); fputs (fid, text); fclose (fid);
  end
  addpath (fixed);
  cleanup = onCleanup (@() rmdir_ (fixed));

  [~, cpu] = system ("sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1");
  threads = getenv ("RAYON_NUM_THREADS");
  if isempty (threads), threads = sprintf ("%d (all cores)", nproc ()); end
  printf ("# %d cores, %s", nproc (), cpu);
  printf ("# GNU Octave %s, octave-nurbs %s; package cagd threads: %s\n", version (), ...
          pkg_version ("nurbs"), threads);
  printf ("# %s; load before: %s", datestr (now (), "yyyy-mm-dd HH:MM"), fileread ("/proc/loadavg"));

  % The bicubic net, the cubic, their samples.
  B = zeros (4, 12); net = zeros (3, 4, 4);
  for i = 0:3
    for j = 0:3
      b = [i/3, j/3, mod(7*i + 3*j, 5)/4 - 1/2];
      B(i+1, 3*j+1:3*j+3) = b; net(:, i+1, j+1) = b';
    end
  end
  cubic = [0 1 3 4; 0 2 -1 1; 0 1 2 0];

  rows = cell (0, 4);
  % deCasteljau (B, 1e6), B the cubic (the thesis's appendix A function).
  n_fixed = str2double (getenv ("CAGD_BENCH_FIXED_N"));
  if isnan (n_fixed), n_fixed = 1e6; end
  t_fixed = once (@() fixed_deCasteljau (cubic, n_fixed)) * (1e6 / n_fixed);
  note = ""; if n_fixed != 1e6, note = sprintf (" (fixed run at N = %g, scaled)", n_fixed); end
  rows = add (rows, ["deCasteljau (cubic, 1e6)" note], "fixed .m", t_fixed, ...
              best (@() deCasteljau (cubic, 1e6), 10));
  rows = add (rows, "ploskevB (bicubic, N = 100)", "fixed .m", once (@() fixed_ploskevB (B, 100)), ...
              best (@() ploskevB (B, 100), 20));
  for N = [100 300]
    t = linspace (0, 1, N);
    edge = @(e) cagd_bezier (e, t);
    c1 = edge (net(:, :, 1)); c2 = edge (net(:, :, 4));
    d1 = edge (squeeze (net(:, 1, :))); d2 = edge (squeeze (net(:, 4, :)));
    corners = {net(:,1,1), net(:,4,1), net(:,1,4), net(:,4,4)};
    rows = add (rows, sprintf ("krpaCoons (bicubic's boundary, N = %d)", N), "fixed .m", ...
                      once (@() fixed_krpaCoons (c1, c2, d1, d2, corners{:})), ...
                      best (@() krpaCoons (c1, c2, d1, d2, corners{:}), 20));
  end
  x = [0 0.25 0.5 0.75 1];
  for N = [20 50]
    t = linspace (0, 1, N);
    P = cagd_bezier_patch (net, t, x); Q = cagd_bezier_patch (net, x, t);
    g_u = reshape (P, 3, N * 5);                        % [c_0 ... c_4], c_j = g(., x_j)
    g_v = reshape (permute (Q, [1 3 2]), 3, N * 5);     % [d_0 ... d_4], d_i = g(x_i, .)
    G = cagd_bezier_patch (net, x, x);
    g_uv = reshape (permute (G, [2 1 3]), 5, 15);       % g_uv(i, 3j-2:3j) = g(x_i, x_j)
    rows = add (rows, sprintf ("krpaGordon (5 x 5 network, N = %d)", N), "fixed .m", ...
                      once (@() fixed_krpaGordon (g_u, g_v, g_uv, x, x, N)), ...
                      best (@() krpaGordon (g_u, g_v, g_uv, x, x, N), 20));
  end

  % cagd_nrbeval against nrbeval.
  srf = nrbmak ([net; ones(1, 4, 4)], {[0 0 0 0 1 1 1 1], [0 0 0 0 1 1 1 1]});
  rand ("state", 7);
  w = 0.5 + rand (1, 7, 7);
  rat = nrbmak ([rand(3, 7, 7) .* repmat(w, 3, 1); w], ...
                {[0 0 0 0 0.2 0.5 0.7 1 1 1 1], [0 0 0 0 0.3 0.5 0.6 1 1 1 1]});
  t = linspace (0, 1, 1000);
  for s = {{"bicubic patch", srf}, {"rational bicubic, 7 x 7, interior knots", rat}}
    [label, S] = s{1}{:};
    rows = add (rows, sprintf ("nrbeval, 1000 x 1000 grid: %s", label), "nrbeval", ...
                      best (@() nrbeval (S, {t, t}), 3), best (@() cagd_nrbeval (S, {t, t}), 10));
  end
  crv = nrbmak ([cubic; ones(1, 4)], [0 0 0 0 1 1 1 1]);
  w = 0.5 + rand (1, 10);
  rcrv = nrbmak ([rand(3, 10) .* repmat(w, 3, 1); w], [0 0 0 0 0.1 0.3 0.3 0.5 0.7 0.9 1 1 1 1]);
  t = linspace (0, 1, 1e6);
  for s = {{"cubic", crv}, {"rational cubic, 10 points, interior knots", rcrv}}
    [label, C] = s{1}{:};
    rows = add (rows, sprintf ("nrbeval, 1e6 points: %s", label), "nrbeval", ...
                best (@() nrbeval (C, t), 3), best (@() cagd_nrbeval (C, t), 10));
  end

  printf ("\n| case | against | it (s) | cagd (s) | ratio |\n|---|---|---|---|---|\n");
  for k = 1:size (rows, 1)
    printf ("| %s | %s | %.4g | %.4g | %.0f× |\n", rows{k, 1}, rows{k, 2}, rows{k, 3}, ...
            rows{k, 4}, rows{k, 3} / rows{k, 4});
  end

  % One call for one point (mean over 20000 calls, best of 3 batches).
  P3 = [0 0 8 4; 0 2 2 0; 0 2 0 0];
  calls = {
    "cagd_nrbeval (cubic curve, 0.5)",          @() cagd_nrbeval (crv, 0.5)
    "cagd_nrbeval (bicubic patch, {0.3, 0.4})", @() cagd_nrbeval (srf, {0.3, 0.4})
    "cagd_bspeval (3, c, k, 0.5)",              @() cagd_bspeval (3, cubic, [0 0 0 0 1 1 1 1], 0.5)
    "cagd_bezier (P, 0.5)",                     @() cagd_bezier (P3, 0.5)
    "deCasteljau (P, 1)",                       @() deCasteljau (P3, 1)
    "bilinearna (B, 0.3, 0.4, 1)",              @() bilinearna (B, 0.3, 0.4, 1)
    "Lagrange ([0 0.5 1], 2, 0.3)",             @() Lagrange ([0 0.5 1], 2, 0.3)
    "for comparison: nrbeval (cubic curve, 0.5)", @() nrbeval (crv, 0.5)
    "for comparison: Octave's builtin max (1, 2)", @() max (1, 2)
  };
  printf ("\n| one call, one point | µs per call |\n|---|---|\n");
  for k = 1:rows_ (calls)
    f = calls{k, 2};
    per = inf;
    for batch = 1:3
      tic; for i = 1:20000, x = f (); end; per = min (per, toc / 20000);
    end
    printf ("| %s | %.1f |\n", calls{k, 1}, per * 1e6);
  end
  printf ("\n# load after: %s", fileread ("/proc/loadavg"));
end

function rows = add (rows, varargin)
  rows(end+1, :) = varargin;
end

function r = rows_ (c)
  r = size (c, 1);
end

% Calls with one output: called without, the thesis functions would draw their figure.
function t = best (f, reps)
  x = f ();                               % warm up (thread pool, caches)
  t = inf;
  for k = 1:reps
    tic; x = f (); t = min (t, toc);
  end
end

function t = once (f)
  tic; x = f (); t = toc;
end

function v = pkg_version (name)
  [~, info] = pkg ("list", name);
  v = info{1}.version;
end

function rmdir_ (d)
  rmpath (d);
  confirm_recursive_rmdir (false, "local");
  rmdir (d, "s");
end

% bench_twins () -- the octave-nurbs twins of the package cagd against octave-nurbs' own
% functions, every case of each twin, in this one Octave session (octave_pkg/bench/run.sh
% twins runs it with RAYON_NUM_THREADS=1: one thread against Octave's one).
%
% Each time is the best of several runs of a loop of calls (the loop chosen so that a run
% takes about 0.2 s or more), divided by the calls in the loop: the arguments' conversion, the
% evaluation and the allocation of the results included.  Each pair is checked to agree first
% (1e-12 relative).  Prints a Markdown table: case, octave-nurbs' time, the twin's, the ratio.
function bench_twins ()
  pkg load nurbs;
  if isempty (which ("__cagd__")), pkg load cagd; end
  [~, cpu] = system ("sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1");
  threads = getenv ("RAYON_NUM_THREADS");
  if isempty (threads), threads = sprintf ("%d (all cores)", nproc ()); end
  printf ("# %d cores, %s", nproc (), cpu);
  printf ("# GNU Octave %s, octave-nurbs %s; package cagd threads: %s\n", version (), ...
          pkg_version ("nurbs"), threads);
  printf ("# %s; load before: %s", datestr (now (), "yyyy-mm-dd HH:MM"), fileread ("/proc/loadavg"));
  rand ("state", 7);

  % The geometry: a cubic and a rational cubic with interior knots, the bicubic patch of
  % bench_cagd and a rational bicubic 7 x 7, a rational tricubic volume 8 x 8 x 8.
  cubic = [0 1 3 4; 0 2 -1 1; 0 1 2 0];
  crv = nrbmak ([cubic; ones(1, 4)], [0 0 0 0 1 1 1 1]);
  w = 0.5 + rand (1, 10);
  rcrv = nrbmak ([rand(3, 10) .* repmat(w, 3, 1); w], [0 0 0 0 0.1 0.3 0.3 0.5 0.7 0.9 1 1 1 1]);
  net = zeros (3, 4, 4);
  for i = 0:3
    for j = 0:3
      net(:, i+1, j+1) = [i/3, j/3, mod(7*i + 3*j, 5)/4 - 1/2];
    end
  end
  srf = nrbmak ([net; ones(1, 4, 4)], {[0 0 0 0 1 1 1 1], [0 0 0 0 1 1 1 1]});
  w = 0.5 + rand (1, 7, 7);
  rsrf = nrbmak ([rand(3, 7, 7) .* repmat(w, 3, 1); w], ...
                 {[0 0 0 0 0.2 0.5 0.7 1 1 1 1], [0 0 0 0 0.3 0.5 0.6 1 1 1 1]});
  kv = [0 0 0 0 .2 .4 .6 .8 1 1 1 1];
  w = 0.5 + rand (1, 8, 8, 8);
  vol = nrbmak ([rand(3, 8, 8, 8) .* repmat(w, 3, 1); w], {kv, kv, kv});
  K = [0 0 0 0 linspace(0.01, 0.99, 996) 1 1 1 1];       % 1000 control points, cubic
  C = rand (3, 1000);
  U = [0 0 0 0 .5 1 1 1 1];

  rows = cell (0, 3);
  t6 = linspace (0, 1, 1e6); t1k = linspace (0, 1, 1000); t30 = linspace (0, 1, 30);
  pts = rand (2, 1e4); pts3 = rand (3, 1e3);
  rows = add (rows, "nrbeval: cubic, 1e6 points", @() nrbeval (crv, t6), @() cagd_nrbeval (crv, t6));
  rows = add (rows, "nrbeval: rational cubic, 1e6 points", @() nrbeval (rcrv, t6), @() cagd_nrbeval (rcrv, t6));
  rows = add (rows, "nrbeval: rational cubic, 1e6 points, [p, w]", @() two (@nrbeval, rcrv, t6), @() two (@cagd_nrbeval, rcrv, t6));
  rows = add (rows, "nrbeval: bicubic, 1000 x 1000 grid", @() nrbeval (srf, {t1k, t1k}), @() cagd_nrbeval (srf, {t1k, t1k}));
  rows = add (rows, "nrbeval: rational bicubic 7 x 7, 1000 x 1000 grid", @() nrbeval (rsrf, {t1k, t1k}), @() cagd_nrbeval (rsrf, {t1k, t1k}));
  rows = add (rows, "nrbeval: rational bicubic 7 x 7, 1e4 scattered points", @() nrbeval (rsrf, pts), @() cagd_nrbeval (rsrf, pts));
  rows = add (rows, "nrbeval: rational tricubic 8^3, 30^3 grid", @() nrbeval (vol, {t30, t30, t30}), @() cagd_nrbeval (vol, {t30, t30, t30}));
  rows = add (rows, "nrbeval: rational tricubic 8^3, 1e3 scattered points", @() nrbeval (vol, pts3), @() cagd_nrbeval (vol, pts3));
  rows = add (rows, "nrbeval: cubic, one point", @() nrbeval (crv, 0.5), @() cagd_nrbeval (crv, 0.5));
  rows = add (rows, "nrbeval: bicubic, one point {u, v}", @() nrbeval (srf, {0.3, 0.4}), @() cagd_nrbeval (srf, {0.3, 0.4}));
  rows = add (rows, "nrbeval: bicubic, one scattered point", @() nrbeval (srf, [0.3; 0.4]), @() cagd_nrbeval (srf, [0.3; 0.4]));
  rows = add (rows, "nrbeval: tricubic, one point {u, v, w}", @() nrbeval (vol, {0.3, 0.4, 0.5}), @() cagd_nrbeval (vol, {0.3, 0.4, 0.5}));
  rows = add (rows, "bspeval: 1000 control points, 1e6 points", @() bspeval (3, C, K, t6), @() cagd_bspeval (3, C, K, t6));
  rows = add (rows, "bspeval: cubic, one point", @() bspeval (3, cubic, [0 0 0 0 1 1 1 1], 0.5), @() cagd_bspeval (3, cubic, [0 0 0 0 1 1 1 1], 0.5));
  u5 = rand (1, 1e5);
  rows = add (rows, "findspan: 1000 control points, 1e5 points", @() findspan (999, 3, u5, K), @() cagd_findspan (999, 3, u5, K));
  rows = add (rows, "findspan: one point", @() findspan (4, 3, 0.3, U), @() cagd_findspan (4, 3, 0.3, U));
  s5 = findspan (999, 3, u5, K);
  rows = add (rows, "basisfun: cubic, 1e5 points", @() basisfun (s5, u5, 3, K), @() cagd_basisfun (s5, u5, 3, K));
  rows = add (rows, "basisfun: cubic, one point", @() basisfun (3, 0.3, 3, U), @() cagd_basisfun (3, 0.3, 3, U));
  rows = add (rows, "basisfunder: cubic, 1e5 points, 2 derivatives", @() basisfunder (s5, 3, u5, K, 2), @() cagd_basisfunder (s5, 3, u5, K, 2));
  rows = add (rows, "basisfunder: cubic, one point", @() basisfunder (3, 3, 0.3, U, 1), @() cagd_basisfunder (3, 3, 0.3, U, 1));
  rows = add (rows, "bspderiv: 1000 control points", @() two (@bspderiv, 3, C, K), @() two (@cagd_bspderiv, 3, C, K));
  rows = add (rows, "bspderiv: cubic", @() two (@bspderiv, 3, cubic, [0 0 0 0 1 1 1 1]), @() two (@cagd_bspderiv, 3, cubic, [0 0 0 0 1 1 1 1]));
  ins = rand (1, 100);
  rows = add (rows, "bspkntins: 1000 control points, 100 knots", @() two (@bspkntins, 3, C, K, ins), @() two (@cagd_bspkntins, 3, C, K, ins));
  rows = add (rows, "bspkntins: cubic, one knot", @() two (@bspkntins, 3, cubic, [0 0 0 0 1 1 1 1], 0.5), @() two (@cagd_bspkntins, 3, cubic, [0 0 0 0 1 1 1 1], 0.5));
  rows = add (rows, "bspdegelev: 1000 control points, +1", @() two (@bspdegelev, 3, C, K, 1), @() two (@cagd_bspdegelev, 3, C, K, 1));
  rows = add (rows, "bspdegelev: cubic, +1", @() two (@bspdegelev, 3, cubic, [0 0 0 0 1 1 1 1], 1), @() two (@cagd_bspdegelev, 3, cubic, [0 0 0 0 1 1 1 1], 1));
  rows = add (rows, "nrbkntins: rational bicubic 7 x 7, 10 knots each way", @() nrbkntins (rsrf, {rand(1, 10), rand(1, 10)}), @() cagd_nrbkntins (rsrf, {rand(1, 10), rand(1, 10)}), false);
  rows = add (rows, "nrbkntins: rational cubic, one knot", @() nrbkntins (rcrv, 0.4), @() cagd_nrbkntins (rcrv, 0.4));
  rows = add (rows, "nrbdegelev: rational bicubic 7 x 7, +1 each way", @() nrbdegelev (rsrf, [1 1]), @() cagd_nrbdegelev (rsrf, [1 1]));
  rows = add (rows, "nrbdegelev: rational cubic, +1", @() nrbdegelev (rcrv, 1), @() cagd_nrbdegelev (rcrv, 1));
  rows = add (rows, "nrbderiv: rational bicubic 7 x 7, 2 outputs", @() outs (@nrbderiv, 2, rsrf), @() outs (@cagd_nrbderiv, 2, rsrf));
  rows = add (rows, "nrbderiv: rational cubic", @() nrbderiv (rcrv), @() cagd_nrbderiv (rcrv));
  [ds, ds2] = nrbderiv (rsrf); dc = nrbderiv (rcrv);
  t100 = linspace (0, 1, 100);
  rows = add (rows, "nrbdeval: rational bicubic, 100 x 100 grid, Hessian", @() outs (@nrbdeval, 3, rsrf, ds, ds2, {t100, t100}), @() outs (@cagd_nrbdeval, 3, rsrf, ds, ds2, {t100, t100}));
  rows = add (rows, "nrbdeval: rational cubic, 1e4 points", @() outs (@nrbdeval, 2, rcrv, dc, linspace (0, 1, 1e4)), @() outs (@cagd_nrbdeval, 2, rcrv, dc, linspace (0, 1, 1e4)));
  rows = add (rows, "nrbdeval: rational cubic, one point", @() outs (@nrbdeval, 2, rcrv, dc, 0.5), @() outs (@cagd_nrbdeval, 2, rcrv, dc, 0.5));
  b = coons_boundaries ();
  rows = add (rows, "nrbcoons: octave-nurbs' demo boundaries", @() nrbcoons (b{:}), @() cagd_nrbcoons (b{:}));

  printf ("\n| case | octave-nurbs (s) | cagd twin (s) | ratio |\n|---|---|---|---|\n");
  for k = 1:size (rows, 1)
    printf ("| %s | %.3g | %.3g | %.1f× |\n", rows{k, 1}, rows{k, 2}, rows{k, 3}, rows{k, 2} / rows{k, 3});
  end
  printf ("\n# load after: %s", fileread ("/proc/loadavg"));
end

% One row: checks that the pair agrees, then times both.
function rows = add (rows, label, f_nurbs, f_cagd, check)
  if nargin < 5, check = true; end
  if check
    a = f_nurbs (); b = f_cagd ();
    if ! agree (a, b)
      error ("bench_twins: %s: the twin and octave-nurbs disagree", label);
    end
  end
  rows(end+1, :) = {label, per_call(f_nurbs), per_call(f_cagd)};
end

function ok = agree (a, b)
  if iscell (a)
    ok = isequal (size (a), size (b));
    for k = 1:numel (a)
      ok = ok && agree (a{k}, b{k});
    end
  elseif isstruct (a)
    ok = agree (a.coefs, b.coefs) && isequal (a.knots, b.knots) && isequal (a.order, b.order);
  else
    a = double (a); b = double (b);
    ok = isequal (size (a), size (b)) && isequal (isnan (a), isnan (b)) ...
         && max ([abs(a(:) - b(:)); 0]) <= 1e-12 * max ([abs(a(:)); 1]);
  end
end

% Seconds per call: the best of 5 runs of a loop sized to take about 0.2 s.
function t = per_call (f)
  x = f ();                                  % warm up
  tic; x = f (); once = toc;
  n = max (1, min (20000, ceil (0.2 / max (once, 1e-7))));
  t = inf;
  for r = 1:5
    tic;
    for i = 1:n
      x = f ();
    end
    t = min (t, toc / n);
  end
end

function o = two (f, varargin)
  [a, b] = f (varargin{:});
  o = {a, b};
end

function o = outs (f, n, varargin)
  o = cell (1, n);
  [o{:}] = f (varargin{:});
end

function b = coons_boundaries ()
  b = {nrbmak([0 3 4.5 6.5 8 10; 0 0 0 0 0 0; 2 2 7 4 7 9], [0 0 0 1/3 0.5 2/3 1 1 1]), ...
       nrbmak([0 3 5 8 10; 10 10 10 10 10; 3 5 8 6 10], [0 0 0 1/3 2/3 1 1 1]), ...
       nrbmak([0 0 0 0; 0 3 8 10; 2 0 5 3], [0 0 0 0.5 1 1 1]), ...
       nrbmak([10 10 10 10 10; 0 3 5 8 10; 9 7 7 10 10], [0 0 0 0.25 0.75 1 1 1])};
end

function v = pkg_version (name)
  [~, info] = pkg ("list", name);
  v = info{1}.version;
end

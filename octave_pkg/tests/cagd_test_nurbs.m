% cagd_test_nurbs (count, seed) -- the octave-nurbs twins against octave-nurbs itself.
%
% 1. octave-nurbs' own test blocks (%!shared, %!test, %!assert, %!error) of nrbeval, bspeval,
%    basisfun and findspan, read from the installed package (the .m files and the -tst files
%    its build extracted from the C++ sources), with every call of those four functions
%    replaced by its cagd_ twin, run with Octave's test ().  (bspeval has no test block of its
%    own; part 2 covers it.)  Then, the same way, every other test file of octave-nurbs whose
%    blocks call one of the four (nrbderiv, nrbdeval, nrbclamp, nrbsurfderiveval, …): they
%    must pass with the twins as they pass with the originals.
% 2. `count` random NURBS (default 600: half curves, half surfaces; seed 2014): degrees 1-5,
%    non-uniform knots with interior multiplicities up to the degree (a fifth of them
%    unclamped), random weights in [0.3, 3] (a fifth
%    of them all 1, B-splines), coordinates of scale 1e-2 to 1e2; curves at sorted,
%    unsorted and column parameters (few, and from 256 on, where sorted parameters are
%    evaluated through Bezier pieces), surfaces on grids {u, v} and at scattered points, with one
%    output and with the homogeneous [p, w]; plus bspeval, findspan and basisfun at the same
%    knots.  cagd_nrbeval must equal nrbeval within 1e-13 relative to the scale of the result
%    (bspeval likewise; findspan exactly; basisfun within 1e-13).  Then 40 random volumes
%    (three knot vectors) on grids {u, v, w} and at scattered points.
% Prints the counts and the worst errors and "nurbs: OK".
function cagd_test_nurbs (count, seed)
  if nargin < 1 || isempty (count), count = 600; end
  if nargin < 2 || isempty (seed), seed = 2014; end
  pkg load nurbs;
  own_blocks ();
  random_cases (count, seed);
  printf ("nurbs: OK\n");
end

function own_blocks ()
  mdir = fileparts (which ("nrbmak"));
  adir = fileparts (which ("bspeval"));
  own = {fullfile(mdir, "nrbeval.m"), fullfile(mdir, "bspeval.m"), ...
         fullfile(mdir, "basisfun.m"), fullfile(mdir, "findspan.m"), ...
         fullfile(adir, "basisfun.cc-tst"), fullfile(adir, "bspeval.cc-tst")};
  others = [cellfun(@(f) fullfile (mdir, f), {dir(fullfile (mdir, "*.m")).name}, "UniformOutput", false), ...
            cellfun(@(f) fullfile (adir, f), {dir(fullfile (adir, "*-tst")).name}, "UniformOutput", false)];
  others = setdiff (others, own);
  twins = '(?<![\w.])(nrbeval|bspeval|basisfun|findspan)(?!\w)';
  tmp = tempname ();
  mkdir (tmp);
  unwind_protect
    total = [0 0];
    for k = 1:numel (own) + numel (others)
      is_own = k <= numel (own);
      if is_own, source = own{k}; else, source = others{k - numel (own)}; end
      [~, base, ext] = fileparts (source);
      label = [base ext];
      if ! exist (source, "file")
        printf ("  %-24s (not installed)\n", label);
        continue;
      end
      lines = strsplit (fileread (source), "\n");
      code = strjoin (lines(strncmp (lines, "%!", 2)), "\n");
      if isempty (regexp (code, '^%!(test|assert|error|shared)', "once", "lineanchors"))
        if is_own, printf ("  %-24s no test blocks\n", label); end
        continue;
      end
      if ! is_own && isempty (regexp (code, twins, "once"))
        continue;
      end
      name = sprintf ("cagd_twin_tests_%d", k);
      file = fullfile (tmp, [name ".m"]);
      fid = fopen (file, "w");
      fprintf (fid, "function %s ()\nend\n%s\n", name, regexprep (code, twins, 'cagd_$1'));
      fclose (fid);
      [ok, n] = test (file, "quiet", 0);
      printf ("  %-24s %2d of %2d test blocks pass with the cagd_ twins\n", label, ok, n);
      if ok != n
        test (file, "verbose", stdout);
        error ("nurbs: %s: %d of %d test blocks fail with the cagd_ twins", label, n - ok, n);
      end
      total += [is_own, ! is_own] * n;
    end
    printf ("  octave-nurbs test blocks: %d of nrbeval/basisfun/findspan, %d of others calling them\n", total);
    if total(1) == 0
      error ("nurbs: no octave-nurbs test block found");
    end
  unwind_protect_cleanup
    confirm_recursive_rmdir (false, "local");
    rmdir (tmp, "s");
  end_unwind_protect
end

% Knots of degree p for n control points: clamped (p+1 equal ends) with interior knots of
% multiplicity 1..p, or unclamped (sorted random, some repeated).
function U = random_knots (p, n)
  if rand () < 0.8
    interior = [];
    while numel (interior) < n - p - 1
      m = min (1 + floor (p * rand ()), n - p - 1 - numel (interior));
      x = 0.02 + 0.96 * rand ();
      if all (abs (x - interior) > 1e-3)
        interior = [interior, repmat(x, 1, m)];
      end
    end
    U = [zeros(1, p + 1), sort(interior), ones(1, p + 1)];
  else
    do
      U = sort (rand (1, n + p + 1));
      k = 1 + floor ((n + p) * rand ());
      U(k + 1) = U(k);              % one repeated knot
    until U(p + 1) < U(n + 1)
  end
end

function C = random_coefs (varargin)
  sz = [varargin{:}];
  s = 10 ^ (4 * rand () - 2);
  w = exp (log (0.3) + (log (3) - log (0.3)) * rand ([1, sz]));
  if rand () < 0.2
    w(:) = 1;                         % a B-spline written as a NURBS
  end
  C = zeros ([4, sz]);
  C(4, :) = w(:)';
  C(1:3, :) = s * (2 * rand (3, prod (sz)) - 1) .* repmat (w(:)', 3, 1);
end

% Parameters in the domain [a, b]: sorted with the ends, or unsorted.
function t = params (a, b, n)
  if rand () < 0.6
    t = linspace (a, b, n);
  else
    t = a + (b - a) * rand (1, n);
    t(1) = b;
  end
end

function e = rel (a, b)
  e = max (abs (a(:) - b(:))) / max ([abs(b(:)); realmin]);
end

function random_cases (count, seed)
  rand ("state", seed);
  worst = struct ("curve", 0, "surface", 0, "bspeval", 0, "basisfun", 0);
  counts = struct ("curve", 0, "surface", 0, "bspeval", 0, "basisfun", 0, "findspan", 0);
  for k = 1:count
    if k <= count / 2
      p = 1 + floor (5 * rand ()); n = p + 1 + floor (8 * rand ());
      U = random_knots (p, n);
      crv = nrbmak (random_coefs (n), U);
      % Few points (the core's NURBS batch) or many (cut into Bezier pieces, from 256 sorted).
      if rand () < 0.5, m = 1 + floor (200 * rand ()); else, m = 256 + floor (1500 * rand ()); end
      t = params (U(p + 1), U(n + 1), m);
      if rand () < 0.2, t = t'; end
      if rand () < 0.3
        [p1, w1] = nrbeval (crv, t); [p2, w2] = cagd_nrbeval (crv, t);
        e = max (rel (p2, p1), rel (w2, w1));
        same = isequal (size (p1), size (p2)) && isequal (size (w1), size (w2));
      else
        p1 = nrbeval (crv, t); p2 = cagd_nrbeval (crv, t);
        e = rel (p2, p1); same = isequal (size (p1), size (p2));
      end
      if ! same || e > 1e-13
        error ("nurbs: random curve %d (degree %d, knots %s): error %g", k, p, mat2str (U, 4), e);
      end
      worst.curve = max (worst.curve, e); counts.curve += 1;
      % bspeval, findspan, basisfun at the same knots (the homogeneous coefficients).
      c = crv.coefs;
      e = rel (cagd_bspeval (p, c, U, t), bspeval (p, c, U, t));
      if e > 1e-13
        error ("nurbs: bspeval, case %d: error %g", k, e);
      end
      worst.bspeval = max (worst.bspeval, e); counts.bspeval += 1;
      if U(1) == U(p + 1) && U(end) == U(n + 1)    % findspan numbers spans of clamped knots
        s1 = findspan (n - 1, p, t, U); s2 = cagd_findspan (n - 1, p, t, U);
        if ! isequal (s1, s2)
          error ("nurbs: findspan, case %d differs", k);
        end
        counts.findspan += 1;
        e = rel (cagd_basisfun (s2, t, p, U), basisfun (s1, t, p, U));
        if e > 1e-13
          error ("nurbs: basisfun, case %d: error %g", k, e);
        end
        worst.basisfun = max (worst.basisfun, e); counts.basisfun += 1;
      end
    else
      p = 1 + floor (5 * rand (1, 2)); n = p + 1 + floor (6 * rand (1, 2));
      U = {random_knots(p(1), n(1)), random_knots(p(2), n(2))};
      srf = nrbmak (random_coefs (n(1), n(2)), U);
      u = params (U{1}(p(1) + 1), U{1}(n(1) + 1), 1 + floor (40 * rand ()));
      v = params (U{2}(p(2) + 1), U{2}(n(2) + 1), 1 + floor (40 * rand ()));
      if rand () < 0.25
        tt = [u(1:min(end, numel(v))); v(1:min(end, numel(u)))];
      else
        tt = {u, v};
      end
      if rand () < 0.3
        [p1, w1] = nrbeval (srf, tt); [p2, w2] = cagd_nrbeval (srf, tt);
        e = max (rel (p2, p1), rel (w2, w1));
        same = isequal (size (p1), size (p2)) && isequal (size (w1), size (w2));
      else
        p1 = nrbeval (srf, tt); p2 = cagd_nrbeval (srf, tt);
        e = rel (p2, p1); same = isequal (size (p1), size (p2));
      end
      if ! same || e > 1e-13
        error ("nurbs: random surface %d (degrees %d, %d): error %g", k, p, e);
      end
      worst.surface = max (worst.surface, e); counts.surface += 1;
    end
  end
  worst.volume = 0;
  for k = 1:40
    p = 1 + floor (3 * rand (1, 3)); n = p + 1 + floor (3 * rand (1, 3));
    U = {random_knots(p(1), n(1)), random_knots(p(2), n(2)), random_knots(p(3), n(3))};
    vol = nrbmak (random_coefs (n(1), n(2), n(3)), U);
    t = arrayfun (@(d) params (U{d}(p(d) + 1), U{d}(n(d) + 1), 1 + floor (8 * rand ())), 1:3, ...
                  "UniformOutput", false);
    if rand () < 0.5
      tt = t;
    else
      m = min (cellfun (@numel, t));
      tt = [t{1}(1:m); t{2}(1:m); t{3}(1:m)];
    end
    p1 = nrbeval (vol, tt); p2 = cagd_nrbeval (vol, tt);
    e = rel (p2, p1);
    if ! isequal (size (p1), size (p2)) || e > 1e-13
      error ("nurbs: random volume %d: error %g", k, e);
    end
    worst.volume = max (worst.volume, e);
  end
  printf ("  random: %d curves (worst %.2g), %d surfaces (worst %.2g), 40 volumes (worst %.2g) against nrbeval;\n", ...
          counts.curve, worst.curve, counts.surface, worst.surface, worst.volume);
  printf ("          %d bspeval (worst %.2g), %d findspan (exact), %d basisfun (worst %.2g);\n", ...
          counts.bspeval, worst.bspeval, counts.findspan, counts.basisfun, worst.basisfun);
  printf ("          errors relative to the largest value of each result; seed %d\n", seed);
end

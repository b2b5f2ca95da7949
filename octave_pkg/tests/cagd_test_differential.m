% cagd_test_differential (refdir, count, seed) -- the package's thesis functions against the
% fixed Octave code, in this one Octave process, on `count` random cases (default 1200, seed
% 2014; seed "random" for a fresh one, printed).
%
% The fixed functions of octave_ref/fixed have the package's names, so they are copied into a
% temporary directory as fixed_deCasteljau, fixed_ploskevB, ... (their bodies unchanged, the
% calls between them renamed alike).  Every function is drawn at least once, then by weight:
% deCasteljau (random dimension 1-4, degree 0-12, N 0-25, coordinates of scale 1e-3 to 1e3),
% ploskevB and bilinearna (packed nets of degrees up to (4,4) and (6,6), parameters also
% outside [0, 1]), tenzor, Lagrange (distinct nodes in any order, rows or columns, parameter
% arrays), vrednostCoons and krpaCoons (random cubic boundaries through random corners),
% krpaGordon (networks cut from random polynomial surfaces, separate node vectors of 2-5
% nodes, N 2-10) -- the generators of crates/cagd-octave/tests/it/differential.rs.
% Every output must agree within 4 ULPs or 1e-14 relative to the scale of the array; tenzor
% bit for bit.  Prints the count and worst error per function and "differential: OK".
function cagd_test_differential (refdir, count, seed)
  if nargin < 2 || isempty (count), count = 1200; end
  if nargin < 3 || isempty (seed), seed = 2014; end
  if ischar (seed), seed = floor (mod (now () * 86400e3, 2^31)); end
  names = {"deCasteljau", "ploskevB", "bilinearna", "tenzor", "Lagrange", ...
           "vrednostCoons", "krpaCoons", "krpaGordon"};
  weights = [20 8 15 10 15 10 7 5];
  fixed = tempname ();
  mkdir (fixed);
  unwind_protect
    for f = dir (fullfile (refdir, "fixed", "*.m"))'
      text = fileread (fullfile (refdir, "fixed", f.name));
      text = regexprep (text, ['\<(' strjoin(names, '|') ')\>'], 'fixed_$1');
      fid = fopen (fullfile (fixed, ["fixed_" f.name]), "w");
      fputs (fid, text);
      fclose (fid);
    end
    addpath (fixed);
    rand ("state", seed);
    stats = struct ();
    tic ();
    for k = 1:count
      if k <= numel (names)
        fn = k;
      else
        fn = find (rand () * sum (weights) < cumsum (weights), 1);
      end
      name = names{fn};
      [args, nout] = feval (["gen_" name]);
      ours = cell (1, nout); theirs = cell (1, nout);
      [ours{:}] = feval (name, args{:});
      [theirs{:}] = feval (["fixed_" name], args{:});
      if ! isfield (stats, name)
        stats.(name) = struct ("cases", 0, "n", 0, "identical", 0, "ulps", 0, "rel", 0);
      end
      s = stats.(name);
      s.cases += 1;
      for j = 1:nout
        a = ours{j}; b = theirs{j};
        if ! isequal (size (a), size (b)) && numel (a) == numel (b)
          b = reshape (b, size (a));    % Octave drops trailing singletons; compare as ours
        end
        c = rmfield (s, "cases");
        [ok, c] = cagd_close (a, b, c);
        if strcmp (name, "tenzor")
          ok = isequal (a, b);
        end
        s.n = c.n; s.identical = c.identical; s.ulps = c.ulps; s.rel = c.rel;
        if ! ok
          error ("differential: case %d (%s), output %d differs (seed %d, count %d)", ...
                 k, name, j, seed, count);
        end
      end
      stats.(name) = s;
    end
    elapsed = toc ();
  unwind_protect_cleanup
    rmpath (fixed);
    confirm_recursive_rmdir (false, "local");
    rmdir (fixed, "s");
  end_unwind_protect
  worst = [0 0];
  for f = fieldnames (stats)'
    s = stats.(f{1});
    printf ("  %-14s %5d cases, %7d numbers, %7d bit for bit; worst %.1f ULPs, %.2g of the scale\n", ...
            f{1}, s.cases, s.n, s.identical, s.ulps, s.rel);
    worst = max (worst, [s.ulps s.rel]);
  end
  printf ("  %d random cases (seed %d) in %.1f s; worst %.1f ULPs, %.2g relative to the scale\n", ...
          count, seed, elapsed, worst(1), worst(2));
  printf ("differential: OK, %d case(s)\n", count);
end

% A coordinate scale between 1e-3 and 1e3.
function s = scale ()
  s = 10 ^ (6 * rand () - 3);
end

function x = uniform (r, c, s)
  x = s * (2 * rand (r, c) - 1);
end

% A parameter: mostly in [0, 1], sometimes outside, sometimes an end.
function t = param ()
  switch (floor (10 * rand ()))
    case 0, t = 0;
    case 1, t = 1;
    case 2, t = 2 * rand () - 0.5;
    otherwise, t = rand ();
  end
end

function n = irand (lo, hi)
  n = lo + floor ((hi - lo + 1) * rand ());
end

function [args, nout] = gen_deCasteljau ()
  d = irand (1, 4); n = irand (0, 12);
  if rand () < 0.05, N = 0; else N = irand (1, 25); end
  args = {uniform(d, n + 1, scale ()), N}; nout = 1;
end

function B = packed_net (max_degree)
  B = uniform (irand (0, max_degree) + 1, 3 * (irand (0, max_degree) + 1), scale ());
end

function [args, nout] = gen_ploskevB ()
  args = {packed_net(4), irand(1, 6)}; nout = 1;
end

function [args, nout] = gen_bilinearna ()
  args = {packed_net(6), param(), param(), irand(1, 10)}; nout = 1;
end

function [args, nout] = gen_tenzor ()
  args = {packed_net(7)}; nout = 1;
end

function [args, nout] = gen_Lagrange ()
  k = irand (1, 8); x = [];
  while numel (x) < k
    y = 3 * rand () - 1;
    if all (abs (y - x) > 0.05), x(end+1) = y; end
  end
  if rand () < 0.5, x = x'; end
  u = 2 * rand (irand (1, 4), irand (1, 6)) - 0.5;
  at = rand (size (u)) < 0.1;
  u(at) = x(irand (1, k));
  args = {x, irand(1, k), u}; nout = 1;
end

% Random Coons data: corners and, per curve, c(s) = (1-s) Pa + s Pb + s(1-s)(A + B s).
function [Q, A, B] = coons_data (d)
  s = scale ();
  Q = uniform (d, 4, s); A = uniform (d, 4, s); B = uniform (d, 4, s);
end

function c = coons_curve (Q, A, B, k, t)
  ends = [1 2; 3 4; 1 3; 2 4];
  pa = Q(:, ends(k, 1)); pb = Q(:, ends(k, 2));
  c = zeros (rows (Q), numel (t));
  for j = 1:numel (t)
    c(:, j) = (1 - t(j)) * pa + t(j) * pb + (t(j) * (1 - t(j))) * (A(:, k) + B(:, k) * t(j));
  end
end

function [args, nout] = gen_vrednostCoons ()
  [Q, A, B] = coons_data (irand (1, 4));
  u = param (); v = param ();
  args = {u, v, coons_curve(Q, A, B, 1, u), coons_curve(Q, A, B, 2, u), ...
          coons_curve(Q, A, B, 3, v), coons_curve(Q, A, B, 4, v), Q(:,1), Q(:,2), Q(:,3), Q(:,4)};
  nout = 4;
end

function [args, nout] = gen_krpaCoons ()
  [Q, A, B] = coons_data (3);
  t = linspace (0, 1, irand (2, 15));
  args = {coons_curve(Q, A, B, 1, t), coons_curve(Q, A, B, 2, t), coons_curve(Q, A, B, 3, t), ...
          coons_curve(Q, A, B, 4, t), Q(:,1), Q(:,2), Q(:,3), Q(:,4)};
  nout = 2;
end

% count increasing nodes about [0, 1], each within a quarter spacing of the equispaced one.
function x = spread_nodes (count)
  h = 1 / (count - 1);
  keep = rand () < 0.5;
  x = (0:count-1) * h;
  for i = 1:count
    if ! (keep && (i == 1 || i == count))
      x(i) += (rand () / 2 - 0.25) * h;
    end
  end
end

function [args, nout] = gen_krpaGordon ()
  mu = irand (2, 5); nv = irand (2, 5); N = irand (2, 10);
  xu = spread_nodes (mu); xv = spread_nodes (nv);
  da = irand (0, 4); db = irand (0, 3); s = scale ();
  C = uniform (3, (da + 1) * (db + 1), s);
  S = @(u, v) C * kron (u .^ (0:da)', v .^ (0:db)');
  t = linspace (0, 1, N);
  g_u = zeros (3, nv * N); g_v = zeros (3, mu * N); g_uv = zeros (mu, 3 * nv);
  for j = 1:nv
    for i = 1:N, g_u(:, (j-1)*N + i) = S (t(i), xv(j)); end
  end
  for i = 1:mu
    for j = 1:N, g_v(:, (i-1)*N + j) = S (xu(i), t(j)); end
  end
  for i = 1:mu
    for j = 1:nv, g_uv(i, 3*j-2:3*j) = S (xu(i), xv(j))'; end
  end
  args = {g_u, g_v, g_uv, xu, xv, N}; nout = 2;
end

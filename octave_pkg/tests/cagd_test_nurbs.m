% cagd_test_nurbs (count, seed) -- the octave-nurbs twins against octave-nurbs itself, in this
% Octave session (octave-nurbs loaded; octave-nurbs' own tests and demos on the twins run in a
% process without it, cagd_test_nurbs_copies):
%
% 1. A differential test over random inputs of every argument form the twins take (about
%    `count` cases per group, default 150; seed 2014): NURBS curves, surfaces and volumes with
%    weights of any sign and zero, knots clamped or not at either end, parameters anywhere in
%    [U(1), U(end)] and outside, NaN, every class octave-nurbs takes (single, integer, logical,
%    sparse), rows, columns, matrices, cell grids, scattered points, the homogeneous [p, w];
%    bspeval, findspan (n not matching the knots), basisfun and basisfunder (wrong spans),
%    bspderiv, bspkntins (knots at the ends, beyond the order), bspdegelev, nrbkntins and
%    nrbdegelev (curves, surfaces and volumes, knots clamped or not), with single, int32 and
%    logical arguments, nrbderiv (1 to 4 outputs) with nrbdeval (2 to 5 outputs) on curves,
%    surfaces and volumes with knots clamped or not and weights of any sign and zero, each
%    against the octave-nurbs function of the same name on the same arguments.  Each pair
%    must agree: both fail, or both return results of the same class and size, NaN and Inf at
%    the same places, and values within 1e-12 relative to the result's scale (NURBS points are
%    compared weighted by their weights, so that a weight near zero does not magnify
%    rounding).
% 2. cagd_nrbcoons against nrbcoons on random NURBS boundaries: the same knots and orders, the
%    surfaces equal on a 21 x 21 grid within 1e-12 relative.
% Prints the counts and "nurbs: OK".
function cagd_test_nurbs (count, seed)
  if nargin < 1 || isempty (count), count = 150; end
  if nargin < 2 || isempty (seed), seed = 2014; end
  pkg load nurbs;
  warning ("off", "all", "local");
  rand ("state", seed);
  t0 = tic ();
  g = struct ("pairs", 0, "errors", 0, "worst", 0, "class_steps", 0);
  g = evaluators (g, count);
  g = spans_and_bases (g, count);
  g = refinement (g, count);
  g = derivatives (g, count);
  printf ("  differential: %d pairs against octave-nurbs (%d refused by both), worst %.2g relative; %.0f s\n", ...
          g.pairs, g.errors, g.worst, toc (t0));
  printf ("  (%d results of single, int32 or logical arguments where octave-nurbs' own arithmetic in that class\n", g.class_steps);
  printf ("   differs from its result on the same values in double; the twins give the latter)\n");
  coons_cases (ceil (count / 3));
  printf ("nurbs: OK\n");
end

% ---------------------------------------------------------------------------------------------
% Comparison.

% Runs f_nurbs and f_cagd (function handles returning a cell of outputs); both fail, or both
% give the same outputs.  `weights` (optional) holds the weights for NURBS points: the
% comparison is then of p .* w.
function g = check (g, label, f_nurbs, f_cagd, weights)
  if nargin < 5, weights = []; end
  [a, ea] = attempt (f_nurbs);
  [b, eb] = attempt (f_cagd);
  g.pairs += 1;
  if ! isempty (ea) || ! isempty (eb)
    if isempty (ea) || isempty (eb)
      error ("nurbs: %s: octave-nurbs %s, the twin %s", label, ...
             ifelse_ (isempty (ea), "succeeds", ["fails (" ea ")"]), ...
             ifelse_ (isempty (eb), "succeeds", ["fails (" eb ")"]));
    end
    g.errors += 1;
    return;
  end
  for k = 1:numel (a)
    w = [];
    if k == 1, w = weights; end
    [e, why] = differ (a{k}, b{k}, w);
    if ! isempty (why)
      error ("nurbs: %s, output %d: %s", label, k, why);
    end
    g.worst = max (g.worst, e);
  end
end

% As check, for arguments of which one may be single, int32 or logical. A twin computes with
% the values of its arguments in double and converts its result once; octave-nurbs' .m code
% computes in the class of the argument, rounding (and for integers saturating) at every step,
% which for integer knots, parameters or degrees gives coefficients that are not the
% B-spline's. So: where octave-nurbs refuses the arguments (a class it does not take), the
% twin must refuse them; otherwise the twin must do what octave-nurbs does with the same
% values in double (`f_double`): fail where it fails, else give its result in the classes of
% octave-nurbs' result on the arguments. `g.class_steps` counts the cases where octave-nurbs'
% own result (or success) differs from its result on the values in double.
function g = check_class (g, label, f_nurbs, f_double, f_cagd)
  [a, ea] = attempt (f_nurbs);
  [r, er] = attempt (f_double);
  [b, eb] = attempt (f_cagd);
  g.pairs += 1;
  if ! isempty (ea) || ! isempty (er)
    if isempty (eb)
      error ("nurbs: %s: octave-nurbs fails (%s), the twin succeeds", label, [ea er]);
    end
    g.errors += 1;
    g.class_steps += isempty (ea);
    return;
  end
  if ! isempty (eb)
    error ("nurbs: %s: octave-nurbs succeeds, the twin fails (%s)", label, eb);
  end
  for k = 1:numel (a)
    ref = like (r{k}, a{k});
    [~, own] = differ (a{k}, ref, []);
    g.class_steps += ! isempty (own);
    [e, why] = differ (ref, b{k}, []);
    if ! isempty (why)
      error ("nurbs: %s, output %d: %s", label, k, why);
    end
    g.worst = max (g.worst, e);
  end
end

function [out, err] = attempt (f)
  out = {}; err = "";
  try
    out = f ();
  catch e
    err = e.message;
  end
end

% The relative difference of twin's b from octave-nurbs' a, or a reason they differ.
function [e, why] = differ (a, b, w)
  e = 0; why = "";
  if ! strcmp (class (a), class (b))
    why = sprintf ("class %s, octave-nurbs %s", class (b), class (a)); return;
  end
  if ! isequal (size (a), size (b))
    why = sprintf ("size %s, octave-nurbs %s", mat2str (size (b)), mat2str (size (a))); return;
  end
  if isstruct (a)
    if ! isequal (fieldnames (a), fieldnames (b))
      why = "different fields"; return;
    end
    for f = fieldnames (a)'
      [ef, why] = differ (a.(f{1}), b.(f{1}), []);
      if ! isempty (why), why = [f{1} ": " why]; return; end
      e = max (e, ef);
    end
    return;
  end
  if iscell (a)
    for k = 1:numel (a)
      [ek, why] = differ (a{k}, b{k}, []);
      if ! isempty (why), why = sprintf ("{%d}: %s", k, why); return; end
      e = max (e, ek);
    end
    return;
  end
  if ischar (a)
    if ! strcmp (a, b), why = "different text"; end
    return;
  end
  % Results in single are compared to single precision (a twin computes in double and
  % converts once; rounded to single, two results within 1e-12 may still be one unit of the
  % last place apart), integer results to one unit.
  tol = 1e-12;
  if isa (a, "single")
    tol = 8 * eps ("single");
  elseif isinteger (a)
    tol = 1 / max ([abs(double(a(:))); 1]);
  end
  a = double (a); b = double (b);
  if ! isequal (isnan (a), isnan (b))
    why = "NaN at other places"; return;
  end
  if ! isequal (a(isinf (a)), b(isinf (b))) || ! isequal (isinf (a), isinf (b))
    why = "Inf at other places"; return;
  end
  fin = isfinite (a);
  if ! isempty (w)
    w = abs (double (w));
    a = a .* reshape (repmat (w(:)', size (a, 1), 1), size (a));
    b = b .* reshape (repmat (w(:)', size (b, 1), 1), size (b));
    fin &= isfinite (a) & isfinite (b);
  end
  a = a(fin)(:); b = b(fin)(:);
  scale = max ([abs(a); realmin]);
  e = max ([abs(a - b); 0]) / scale;
  if e > tol
    why = sprintf ("values differ by %.3g relative", e);
  end
end

function s = ifelse_ (c, a, b)
  if c, s = a; else, s = b; end
end

% ---------------------------------------------------------------------------------------------
% Random inputs.

% Knots of degree p for n control points: "clamped", "open end" (the last knot fewer than
% p + 1 times), "open start", or "open" at both ends; interior knots repeated up to p times.
function U = knots (p, n, kind)
  interior = [];
  while numel (interior) < n - p - 1
    m = min (1 + floor (p * rand ()), n - p - 1 - numel (interior));
    x = 0.05 + 0.9 * rand ();
    if all (abs (x - interior) > 1e-3)
      interior = [interior, repmat(x, 1, m)];
    end
  end
  interior = sort (interior);
  lo = zeros (1, p + 1); hi = ones (1, p + 1);
  switch kind
    case "open end"
      hi = sort (1 + 0.2 * rand (1, p + 1)); hi(1) = 1;
    case "open start"
      lo = sort (-0.2 * rand (1, p + 1)); lo(end) = 0;
    case "open"
      lo = sort (-0.2 * rand (1, p + 1)); lo(end) = 0;
      hi = sort (1 + 0.2 * rand (1, p + 1)); hi(1) = 1;
  end
  U = [lo, interior, hi];
end

function kind = knot_kind ()
  kinds = {"clamped", "clamped", "clamped", "open end", "open start", "open"};
  kind = kinds{1 + floor (numel (kinds) * rand ())};
end

% Homogeneous coefficients 4 x sz: weights positive, of any sign, with zeros, or all 1.
function [C, sign] = coefs (sz)
  s = 10 ^ (3 * rand () - 1);
  r = rand ();
  if r < 0.4
    w = exp (log (0.3) + (log (3) - log (0.3)) * rand ([1, sz])); sign = "positive";
  elseif r < 0.6
    w = ones ([1, sz]); sign = "unit";
  elseif r < 0.85
    w = 2 * rand ([1, sz]) - 1; sign = "any sign";
  else
    w = 0.5 + rand ([1, sz]); w(1 + floor (numel (w) * rand ())) = 0; sign = "zero";
  end
  C = zeros ([4, sz]);
  C(4, :) = w(:)';
  C(1:3, :) = s * (2 * rand (3, prod (sz)) - 1);
end

% Parameters in [a, b] (sorted with the ends, or unsorted), sometimes with NaN, a value past
% the end of the knots (an error for both), or every value out of the domain but in the knots.
function t = params (a, b, n, lo, hi)
  if rand () < 0.5
    t = linspace (a, b, n);
  else
    t = a + (b - a) * rand (1, n);
  end
  r = rand ();
  if r < 0.08
    t(1 + floor (n * rand ())) = NaN;
  elseif r < 0.12
    t(end) = hi + 0.5;
  elseif r < 0.25 && hi > b
    t = b + (hi - b) * rand (1, n);     % past the domain, inside the knots
  end
end

% A random class conversion of parameters.
function t = as_class (t)
  r = rand ();
  if r < 0.07
    t = single (t);
  elseif r < 0.1
    t = int32 (round (t));
  elseif r < 0.12
    t = logical (t > 0.5);
  elseif r < 0.14 && isvector (t) && all (isfinite (t))
    t = sparse (t);
  end
end

function [g, crv] = curve_case (g, k)
  p = 1 + floor (5 * rand ()); n = p + 1 + floor (7 * rand ());
  kind = knot_kind ();
  U = knots (p, n, kind);
  [C, sign] = coefs (n);
  crv = nrbmak (C, U);
  if rand () < 0.1, crv.coefs = single (crv.coefs); end
  if rand () < 0.05, crv.knots = single (crv.knots); end
  if rand () < 0.5, m = 1 + floor (60 * rand ()); else, m = 256 + floor (600 * rand ()); end
  t = params (U(p+1), U(n+1), m, U(1), U(end));
  if ! any (strcmp (kind, {"open start", "open"}))
    % below U(p+1) octave-nurbs reads before its arrays: only above it there
  else
    t(t < U(p+1)) = U(p+1);
  end
  shape = rand ();
  if shape < 0.15, t = t'; elseif shape < 0.25 && mod (numel (t), 2) == 0, t = reshape (t, 2, []); elseif shape < 0.3, t = {t}; end
  if ! iscell (t), t = as_class (t); end
  label = sprintf ("nrbeval curve %d (degree %d, %s knots, %s weights)", k, p, kind, sign);
  [~, w] = safe_weights (crv, t);
  g = check (g, label, @() {nrbeval(crv, t)}, @() {cagd_nrbeval(crv, t)}, w);
  g = check (g, [label " [p, w]"], @() two (@nrbeval, crv, t), @() two (@cagd_nrbeval, crv, t));
  % bspeval at the same knots, any number of rows.
  c = crv.coefs(1:1 + floor (4 * rand ()), :);
  g = check (g, sprintf ("bspeval %d", k), @() {bspeval(p, c, U, t)}, @() {cagd_bspeval(p, c, U, t)});
end

function out = two (f, varargin)
  [a, b] = f (varargin{:});
  out = {a, b};
end

% The weights octave-nurbs evaluates (for the weighted comparison), [] when it fails.
function [p, w] = safe_weights (nrb, t)
  p = []; w = [];
  try
    [p, w] = nrbeval (nrb, t);
  end
end

function g = evaluators (g, count)
  for k = 1:count
    g = curve_case (g, k);
  end
  for k = 1:count
    p = 1 + floor (4 * rand (1, 2)); n = p + 1 + floor (5 * rand (1, 2));
    kinds = {knot_kind(), knot_kind()};
    U = {knots(p(1), n(1), kinds{1}), knots(p(2), n(2), kinds{2})};
    [C, sign] = coefs (n);
    srf = nrbmak (C, U);
    if rand () < 0.1, srf.coefs = single (srf.coefs); end
    t = cell (1, 2);
    for d = 1:2
      t{d} = params (U{d}(p(d)+1), U{d}(n(d)+1), 1 + floor (25 * rand ()), U{d}(1), U{d}(end));
      if any (strcmp (kinds{d}, {"open start", "open"})), t{d}(t{d} < U{d}(p(d)+1)) = U{d}(p(d)+1); end
    end
    r = rand ();
    if r < 0.5
      tt = {as_class(t{1}), t{2}};
    else
      m = min (numel (t{1}), numel (t{2}));
      tt = [t{1}(1:m); t{2}(1:m)];
      if r < 0.6, tt = tt'; elseif r < 0.7 && mod (m, 2) == 0, tt = reshape (tt, 2, 2, []); end
    end
    label = sprintf ("nrbeval surface %d (degrees %d, %d; %s, %s knots; %s weights)", k, p, kinds{:}, sign);
    [~, w] = safe_weights (srf, tt);
    g = check (g, label, @() {nrbeval(srf, tt)}, @() {cagd_nrbeval(srf, tt)}, w);
    g = check (g, [label " [p, w]"], @() two (@nrbeval, srf, tt), @() two (@cagd_nrbeval, srf, tt));
  end
  for k = 1:ceil (count / 3)
    p = 1 + floor (3 * rand (1, 3)); n = p + 1 + floor (3 * rand (1, 3));
    kinds = {knot_kind(), knot_kind(), knot_kind()};
    U = arrayfun (@(d) knots (p(d), n(d), kinds{d}), 1:3, "UniformOutput", false);
    [C, sign] = coefs (n);
    vol = nrbmak (C, U);
    t = cell (1, 3);
    for d = 1:3
      t{d} = params (U{d}(p(d)+1), U{d}(n(d)+1), 1 + floor (8 * rand ()), U{d}(1), U{d}(end));
      % below U(p+1) of a knot vector open at its start octave-nurbs reads before its arrays
      t{d}(t{d} < U{d}(p(d)+1)) = U{d}(p(d)+1);
    end
    if rand () < 0.5
      tt = t;
    else
      m = min (cellfun (@numel, t));
      tt = [t{1}(1:m); t{2}(1:m); t{3}(1:m)];
    end
    label = sprintf ("nrbeval volume %d (%s, %s, %s knots; %s weights)", k, kinds{:}, sign);
    [~, w] = safe_weights (vol, tt);
    g = check (g, label, @() {nrbeval(vol, tt)}, @() {cagd_nrbeval(vol, tt)}, w);
    g = check (g, [label " [p, w]"], @() two (@nrbeval, vol, tt), @() two (@cagd_nrbeval, vol, tt));
  end
  % Fixed forms: the issue's examples and classes octave-nurbs refuses.
  crv = nrbmak ([0 1 3 4 5; 0 2 2 0 1], [0 0 0 .4 .4 .4 1 1]);
  g = check (g, "unclamped end at 0.7", @() {nrbeval(crv, [0.2 0.4 0.7 1])}, @() {cagd_nrbeval(crv, [0.2 0.4 0.7 1])});
  dc = nrbderiv (nrbcirc (1));
  g = check (g, "[p, w] of nrbderiv (nrbcirc (1))", @() two (@nrbeval, dc, 0.5), @() two (@cagd_nrbeval, dc, 0.5));
  bad = crv; bad.coefs = int32 (bad.coefs);
  g = check (g, "int32 coefs", @() {nrbeval(bad, 0.5)}, @() {cagd_nrbeval(bad, 0.5)});
  g = check (g, "complex parameter", @() {nrbeval(crv, 0.5i)}, @() {cagd_nrbeval(crv, 0.5i)});
  g = check (g, "empty parameters", @() two (@nrbeval, crv, []), @() two (@cagd_nrbeval, crv, []));
  srf = nrbtestsrf ();
  g = check (g, "cell grid of 3 for a surface", @() {nrbeval(srf, {0.5, 0.5, 0.5})}, @() {cagd_nrbeval(srf, {0.5, 0.5, 0.5})});
  g = check (g, "matrix grid item", @() {nrbeval(srf, {[0 .5; .2 .7], 0.5})}, @() {cagd_nrbeval(srf, {[0 .5; .2 .7], 0.5})});
end

% ---------------------------------------------------------------------------------------------
% findspan, basisfun, basisfunder.

function g = spans_and_bases (g, count)
  for k = 1:count
    p = floor (5 * rand ()); n = p + 1 + floor (6 * rand ());
    U = knots (p, n, "clamped");
    u = rand (1, 1 + floor (30 * rand ()));
    u(u < 0.1) = 0; u(u > 0.9) = 1;
    nn = n - 1 + floor (3 * rand ()) - 1;          % n not always matching the knots
    if rand () < 0.1, u(1) = NaN; end
    if rand () < 0.05, u(end) = 1.5; end
    if rand () < 0.2, u = reshape (u, 1, 1, []); end
    uu = as_class (u);
    g = check (g, sprintf ("findspan %d", k), @() {findspan(nn, p, uu, U)}, @() {cagd_findspan(nn, p, uu, U)});
    s = findspan (n - 1, p, min (max (u(isfinite (u)), 0), 1), U);
    uf = min (max (u(isfinite (u)), 0), 1);
    if isempty (uf), continue; end
    if rand () < 0.3                                 % wrong spans whose knots exist
      s = min (max (s + round (2 * rand (size (s)) - 1), p), numel (U) - p - 2);
    end
    if rand () < 0.2, uf(1) = 1.3; end               % no range check in basisfun
    g = check (g, sprintf ("basisfun %d", k), @() {basisfun(s, uf, p, U)}, @() {cagd_basisfun(s, uf, p, U)});
    nd = floor (6 * rand ());
    g = check (g, sprintf ("basisfunder %d (nd = %d)", k, nd), @() {basisfunder(s, p, uf, U, nd)}, ...
               @() {cagd_basisfunder(s, p, uf, U, nd)});
  end
end

% ---------------------------------------------------------------------------------------------
% bspderiv, bspkntins, bspdegelev, nrbkntins, nrbdegelev.

function g = refinement (g, count)
  for k = 1:count
    p = 1 + floor (4 * rand ()); n = p + 1 + floor (6 * rand ());
    kind = knot_kind ();
    U = knots (p, n, kind);
    c = 2 * rand (1 + floor (4 * rand ()), n) - 1;
    g = check (g, sprintf ("bspderiv %d", k), @() two (@bspderiv, p, c, U), @() two (@cagd_bspderiv, p, c, U));
    u = U(1) + (U(end) - U(1)) * rand (1, 1 + floor (4 * rand ()));
    if rand () < 0.3, u = [u, U(p+2) * ones(1, 1 + floor (p * rand ()))]; end   % repeated knots
    if rand () < 0.1, u(end+1) = U(end); end                                     % the end of the range
    if rand () < 0.05, u(end+1) = U(end) + 1; end                                % outside: both fail
    % Any argument, at random, single, int32 or logical (octave-nurbs takes some, refuses others).
    [pa, ca, Ua, ua, classes] = some_class ({p, c, U, u});
    g = check_class (g, sprintf ("bspkntins %d (%s knots%s)", k, kind, classes), @() two (@bspkntins, pa, ca, Ua, ua), ...
                     @() two (@bspkntins, double (pa), double (ca), double (Ua), double (ua)), ...
                     @() two (@cagd_bspkntins, pa, ca, Ua, ua));
    t = floor (4 * rand ());
    [pa, ca, Ua, ta, classes] = some_class ({p, c, U, t});
    g = check_class (g, sprintf ("bspdegelev %d (%s knots, t = %d%s)", k, kind, t, classes), @() two (@bspdegelev, pa, ca, Ua, ta), ...
                     @() two (@bspdegelev, double (pa), double (ca), double (Ua), double (ta)), ...
                     @() two (@cagd_bspdegelev, pa, ca, Ua, ta));
  end
  for k = 1:count
    dims = 1 + floor (3 * rand ());
    p = 1 + floor (3 * rand (1, dims)); n = p + 1 + floor (3 * rand (1, dims));
    kinds = arrayfun (@(d) knot_kind (), 1:dims, "UniformOutput", false);
    U = arrayfun (@(d) knots (p(d), n(d), kinds{d}), 1:dims, "UniformOutput", false);
    if dims == 1, U = U{1}; end
    nrb = nrbmak (coefs (n), U);
    if dims == 1
      ins = rand (1, floor (4 * rand ()));
      elev = floor (3 * rand ());
    else
      ins = arrayfun (@(d) rand (1, floor (3 * rand ())), 1:dims, "UniformOutput", false);
      elev = floor (3 * rand (1, dims));
    end
    [insa, eleva, classes] = some_class ({ins, elev});
    label = sprintf ("%d (%d directions, %s knots%s)", k, dims, strjoin (kinds, "/"), classes);
    g = check_class (g, ["nrbkntins " label], @() {nrbkntins(nrb, insa)}, ...
                     @() {nrbkntins(nrb, to_double (insa))}, @() {cagd_nrbkntins(nrb, insa)});
    g = check_class (g, ["nrbdegelev " label], @() {nrbdegelev(nrb, eleva)}, ...
                     @() {nrbdegelev(nrb, to_double (eleva))}, @() {cagd_nrbdegelev(nrb, eleva)});
  end
end

% `x` in double (every array of a cell).
function x = to_double (x)
  if iscell (x)
    x = cellfun (@double, x, "UniformOutput", false);
  else
    x = double (x);
  end
end

% `ref` in the classes of `a` (structures and cells as they are, item by item).
function ref = like (ref, a)
  if iscell (a)
    ref = cellfun (@like, ref, a, "UniformOutput", false);
  elseif ! isstruct (a)
    ref = cast (ref, class (a));
  end
end

% The arguments `args` (a cell), one of them at random (with probability 0.3) converted to
% single, int32 or logical (numbers, or every array of a cell); `classes` says which.
function varargout = some_class (args)
  classes = "";
  if rand () < 0.3
    k = 1 + floor (numel (args) * rand ());
    cls = {"single", "int32", "logical"}{1 + floor (3 * rand ())};
    if iscell (args{k})
      args{k} = cellfun (@(x) feval (cls, x), args{k}, "UniformOutput", false);
    else
      args{k} = feval (cls, args{k});
    end
    classes = sprintf ("; argument %d %s", k, cls);
  end
  varargout = [args, {classes}];
end

% ---------------------------------------------------------------------------------------------
% nrbderiv and nrbdeval.

function g = derivatives (g, count)
  for k = 1:count
    dims = 1 + floor (3 * rand ());
    p = 1 + floor (3 * rand (1, dims)); n = p + 1 + floor (3 * rand (1, dims));
    kinds = arrayfun (@(d) knot_kind (), 1:dims, "UniformOutput", false);
    U = arrayfun (@(d) knots (p(d), n(d), kinds{d}), 1:dims, "UniformOutput", false);
    if dims == 1, U = U{1}; end
    % Weights of any sign and zero (nrbdeval then divides by zero or by a weight of either
    % sign, as octave-nurbs does), or positive.
    [C, sign] = coefs (n);
    if rand () < 0.4
      C(4, :) = 0.5 + rand (1, prod (n)); sign = "positive";
    end
    nrb = nrbmak (C, U);
    nout = 1 + floor ((4 - (dims == 3) * 2) * rand ());
    what = sprintf ("%d directions, %s knots, %s weights", dims, strjoin (kinds, "/"), sign);
    g = check (g, sprintf ("nrbderiv %d (%s, %d outputs)", k, what, nout), ...
               @() outs (@nrbderiv, nout, nrb), @() outs (@cagd_nrbderiv, nout, nrb));
    % octave-nurbs' nrbderiv fails for some knot vectors not clamped at their end (its
    % bspdegelev does): nothing to evaluate then (the twin failed as well, checked above).
    [D, failed] = attempt (@() outs (@nrbderiv, nout, nrb));
    if ! isempty (failed)
      continue;
    end
    if dims == 1
      tt = rand (1, 1 + floor (10 * rand ()));
      if rand () < 0.3, tt = {tt}; end
    elseif rand () < 0.5
      tt = arrayfun (@(d) rand (1, 1 + floor (5 * rand ())), 1:dims, "UniformOutput", false);
    else
      tt = rand (dims, 1 + floor (6 * rand ()));
    end
    m = 2 + floor (nout * rand ());
    if dims == 3, m = min (m, 3); end
    args = [{nrb}, D(1:min (nout, m - 1)), {tt}];
    g = check (g, sprintf ("nrbdeval %d (%s, %d derivative structures, %d outputs)", k, what, numel (args) - 2, m), ...
               @() outs (@nrbdeval, m, args{:}), @() outs (@cagd_nrbdeval, m, args{:}));
  end
end

function o = outs (f, n, varargin)
  o = cell (1, n);
  [o{:}] = f (varargin{:});
end

% ---------------------------------------------------------------------------------------------
% 3. nrbcoons.

function coons_cases (count)
  worst = 0;
  t = linspace (0, 1, 21);
  for k = 1:count
    % Four random NURBS boundaries through random corners (weights 1 at the corners, so that
    % the curves meet in homogeneous coordinates too).
    P = 10 * rand (3, 4);
    curves = cell (1, 4);
    ends = [1 2; 3 4; 1 3; 2 4];                     % u1: P1-P2, u2: P3-P4, v1: P1-P3, v2: P2-P4
    for c = 1:4
      p = 1 + floor (4 * rand ()); n = p + 1 + floor (5 * rand ());
      w = 0.3 + 2.7 * rand (1, n); w([1 end]) = 1;
      X = 10 * rand (3, n);
      X(:, 1) = P(:, ends(c, 1)); X(:, end) = P(:, ends(c, 2));
      curves{c} = nrbmak ([X .* w; w], knots (p, n, "clamped"));
    end
    a = nrbcoons (curves{:});
    b = cagd_nrbcoons (curves{:});
    if ! isequal (a.order, b.order) || ! isequal (a.number, b.number) || ! isequal (a.knots, b.knots)
      error ("nurbs: nrbcoons case %d: orders, numbers or knots differ", k);
    end
    pa = nrbeval (a, {t, t}); pb = cagd_nrbeval (b, {t, t});
    e = max (abs (pa(:) - pb(:))) / max (abs (pa(:)));
    ec = max (abs (a.coefs(:) - b.coefs(:))) / max (abs (a.coefs(:)));
    if e > 1e-12 || ec > 1e-12
      error ("nurbs: nrbcoons case %d: surfaces differ by %.3g (coefficients %.3g) relative", k, e, ec);
    end
    worst = max ([worst, e, ec]);
  end
  printf ("  nrbcoons: %d random NURBS boundaries, same knots and orders, surfaces on a 21 x 21 grid and coefficients within %.2g relative\n", count, worst);
end

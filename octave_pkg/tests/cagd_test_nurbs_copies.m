% cagd_test_nurbs_copies () -- octave-nurbs' own test blocks and demos on the cagd twins, in an
% Octave process where octave-nurbs is NOT loaded (octave_pkg/ci.sh runs it in a process of its
% own, after pkg load cagd only): every run is on a copy of the installed octave-nurbs whose
% calls of the twinned functions are renamed to cagd_<name> (cagd_nurbs_copy; the function
% definitions left as they are, the copy on the path only for the run), so that each renamed
% call reaches the cagd package and nothing else of octave-nurbs is on the path.
%
% Runs: the copy with no call renamed (octave-nurbs' own functions: the totals), the four
% evaluators' twins, each newer twin swapped in with them one at a time, and all 13 twins at
% once; with each = false (or CAGD_NURBS_EACH=0) only the first and the last (about a
% third of the time).  Each run must pass every test
% block and every demo, with the same totals as octave-nurbs' own functions.  For octave-nurbs
% 1.4.3 the totals are asserted as well: 127 test blocks, and 58 demos -- 57 in its .m files
% and one in tbasisfun.cc-tst, the test file its build extracts from the C++ source tbasisfun.cc
% (a count of the .m files alone, as `demo` over its functions gives, is 57).
% Prints the counts and "nurbs copies: OK".
function cagd_test_nurbs_copies (each)
  if nargin < 1
    each = ! strcmp (getenv ("CAGD_NURBS_EACH"), "0");
  end
  warning ("off", "Octave:gnuplot-graphics");
  if ! isempty (which ("nrbmak")) || ! isempty (which ("nrbeval"))
    error ("nurbs copies: octave-nurbs is loaded in this process (%s); run this in a process without pkg load nurbs", ...
           which ("nrbmak"));
  end
  [~, info] = pkg ("list", "nurbs");
  version = info{1}.version;
  [m_demos, tst_demos] = demo_counts (info{1});
  old = {"nrbeval", "bspeval", "basisfun", "findspan"};
  new = {"basisfunder", "bspderiv", "bspkntins", "bspdegelev", "nrbkntins", "nrbdegelev", ...
         "nrbderiv", "nrbdeval", "nrbcoons"};
  printf ("  octave-nurbs %s (not loaded): its own test blocks and demos, in a copy with calls renamed:\n", version);
  printf ("    demo blocks: %d in its .m files, %d in its C++ test files (*-tst)\n", m_demos, tst_demos);
  [t0, d0] = full_run ({}, "octave-nurbs' own functions", [], []);
  if strcmp (version, "1.4.3") && (! isequal (t0, [127 127]) || ! isequal (d0, [58 58]) ...
                                   || m_demos != 57 || tst_demos != 1)
    error ("nurbs copies: octave-nurbs 1.4.3 gives tests %d/%d, demos %d/%d (%d + %d), not 127/127, 58/58 (57 + 1)", ...
           t0, d0, m_demos, tst_demos);
  end
  if each
    % Each newer twin with the four: the files whose code reaches it run again; the others run
    % the same code as with the four alone (all passing there), so the totals are exact.
    [t4, d4] = full_run (old, "the 4 evaluators' twins", t0, d0);
    for k = 1:numel (new)
      [ta, da, s] = cagd_nurbs_copy ([old, new(k)], true, "both", new(k));
      [tb, db] = cagd_nurbs_copy (old, false, "both", new(k));
      t = t4 - tb + ta; d = d4 - db + da;
      printf ("    %-30s tests %3d/%3d, demos %2d/%2d (%d tests, %d demos reach it; %.0f s)\n", ...
              ["+ cagd_" new{k}], t, d, ta(2), da(2), s);
      if ta(1) != ta(2) || da(1) != da(2) || ! isequal (t, t0) || ! isequal (d, d0)
        error ("nurbs copies: octave-nurbs' tests or demos fail with cagd_%s", new{k});
      end
    end
  end
  full_run ([old, new], "every twin (13)", t0, d0);
  printf ("nurbs copies: OK\n");
end

% A run of the copy with `names` renamed: every block passes, and the totals are `t0`, `d0`
% (when given).
function [t, d] = full_run (names, label, t0, d0)
  [t, d, s] = cagd_nurbs_copy (names, true);
  printf ("    %-30s tests %3d/%3d, demos %2d/%2d (%.0f s)\n", label, t, d, s);
  if t(1) != t(2) || d(1) != d(2) || t(2) == 0 || d(2) == 0
    error ("nurbs copies: octave-nurbs' tests or demos fail with %s", label);
  end
  if ! isempty (t0) && (! isequal (t, t0) || ! isequal (d, d0))
    error ("nurbs copies: %s gives tests %d/%d, demos %d/%d; octave-nurbs' own functions %d/%d, %d/%d", ...
           label, t, d, t0, d0);
  end
end

% The %!demo blocks of the installed octave-nurbs: in its .m files, and in the test files its
% build extracted from its C++ sources (*-tst, beside the oct-files).
function [m, tst] = demo_counts (info)
  count = @(files) sum (cellfun (@(f) numel (regexp (fileread (f), '^%!demo', "lineanchors")), files));
  m = count (fullfile (info.dir, {dir(fullfile (info.dir, "*.m")).name}));
  adir = info.archprefix;
  sub = dir (fullfile (adir, "*-api-*"));
  if ! isempty (sub)
    adir = fullfile (adir, sub(1).name);
  end
  tst = count (fullfile (adir, {dir(fullfile (adir, "*-tst")).name}));
end

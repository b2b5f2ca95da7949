% [tests, demos, secs] = cagd_nurbs_copy (names, verbose, what) -- octave-nurbs' own test blocks and
% demos, run in a copy of the installed octave-nurbs in which every call of the functions
% `names` (a cell of octave-nurbs names, e.g. {"nrbeval", "findspan"}) is renamed to its twin
% cagd_<name>; the function definitions themselves are left as they are.
%
% The copy holds every .m file of octave-nurbs (and its private/ directory), its oct-files (run
% as they are: their C++ cannot be renamed) and the test files its build extracted from the C++
% sources (*-tst). octave-nurbs itself is not loaded: the copy is put on the path for the run
% and removed afterwards, so each call of a renamed function reaches the cagd package.
%
% tests = [passed, total] over every %!test/%!assert/%!error/... block (Octave's test ()),
% demos = [passed, total] over every %!demo block (each run in a function of its own, figures
% invisible; a demo passes when it runs without error).  With `verbose`, the output of failing
% tests and the errors of failing demos are printed.  `what` ("both", default, "tests" or
% "demos") runs only one kind ([0 0] for the other).
function [tests, demos, secs] = cagd_nurbs_copy (names, verbose, what)
  if nargin < 2, verbose = true; end
  if nargin < 3, what = "both"; end
  t0 = tic ();
  [mdir, adir] = nurbs_dirs ();
  copy = tempname ();
  mkdir (copy);
  mkdir (fullfile (copy, "private"));
  cleanup = onCleanup (@() remove_copy (copy));
  if isempty (names)
    pattern = "";
  else
    pattern = ['(?<![\w.])(' strjoin(names, '|') ')(?!\w)'];
  end
  files = {};
  for f = dir (fullfile (mdir, "*.m"))'
    write_renamed (fullfile (mdir, f.name), fullfile (copy, f.name), pattern);
    files{end+1} = fullfile (copy, f.name);
  end
  for f = dir (fullfile (mdir, "private", "*.m"))'
    write_renamed (fullfile (mdir, "private", f.name), fullfile (copy, "private", f.name), pattern);
  end
  for f = dir (fullfile (adir, "*.oct"))'
    copyfile (fullfile (adir, f.name), fullfile (copy, f.name));
  end
  for f = dir (fullfile (adir, "*-tst"))'
    write_renamed (fullfile (adir, f.name), fullfile (copy, f.name), pattern);
    files{end+1} = fullfile (copy, f.name);
  end
  addpath (copy);
  unwind_protect
    tests = demos = [0 0];
    if ! strcmp (what, "demos"), tests = run_tests (files, verbose); end
    if ! strcmp (what, "tests"), demos = run_demos (files, verbose); end
  unwind_protect_cleanup
    rmpath (copy);
  end_unwind_protect
  secs = toc (t0);
end

% The directories of the installed octave-nurbs: its .m files, and its oct-files and *-tst.
function [mdir, adir] = nurbs_dirs ()
  [~, info] = pkg ("list", "nurbs");
  if isempty (info)
    error ("cagd_nurbs_copy: octave-nurbs is not installed");
  end
  mdir = info{1}.dir;
  adir = info{1}.archprefix;
  sub = dir (fullfile (adir, "*-api-*"));
  if ! isempty (sub)
    adir = fullfile (adir, sub(1).name);
  end
end

% Copies `source` to `target` with every call matching `pattern` prefixed by cagd_; a line
% that defines a function is left as it is.
function write_renamed (source, target, pattern)
  text = fileread (source);
  if ! isempty (pattern)
    lines = strsplit (text, "\n");
    calls = cellfun (@isempty, regexp (lines, '^\s*function\b', "once"));
    lines(calls) = regexprep (lines(calls), pattern, 'cagd_$1');
    text = strjoin (lines, "\n");
  end
  fid = fopen (target, "w");
  fputs (fid, text);
  fclose (fid);
end

function counts = run_tests (files, verbose)
  counts = [0 0];
  for k = 1:numel (files)
    code = fileread (files{k});
    if isempty (regexp (code, '^%!(test|assert|error|fail|warning|xtest|shared)', "once", "lineanchors"))
      continue;
    end
    null = fopen ("/dev/null", "w");
    [ok, n] = test (files{k}, "quiet", null);
    fclose (null);
    counts += [ok, n];
    if ok != n && verbose
      [~, base, ext] = fileparts (files{k});
      printf ("    %s%s: %d of %d test blocks pass\n", base, ext, ok, n);
      test (files{k}, "verbose", stdout);
    end
  end
end

function counts = run_demos (files, verbose)
  counts = [0 0];
  old = get (0, "defaultfigurevisible");
  set (0, "defaultfigurevisible", "off");
  unwind_protect
    for k = 1:numel (files)
      [code, idx] = test (files{k}, "grabdemo");
      for j = 1:numel (idx) - 1
        block = code(idx(j):idx(j+1) - 1);
        counts(2) += 1;
        try
          run_block (block);
          counts(1) += 1;
        catch err
          if verbose
            [~, base, ext] = fileparts (files{k});
            printf ("    demo %d of %s%s FAILED: %s\n", j, base, ext, err.message);
          end
        end
        close all;
      end
    end
  unwind_protect_cleanup
    set (0, "defaultfigurevisible", old);
  end_unwind_protect
end

% One demo block in a function workspace of its own (as demo () runs it), output discarded.
function run_block (block)
  eval (sprintf ("function __cagd_demo_block__ ()\n%s\nendfunction", block));
  evalc ("__cagd_demo_block__ ();");
end

function remove_copy (copy)
  confirm_recursive_rmdir (false, "local");
  rmdir (copy, "s");
end

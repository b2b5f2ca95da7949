% [tests, demos, secs] = cagd_nurbs_copy (names, verbose, what, affected_by) -- octave-nurbs' own test blocks and
% demos, run in a copy of the installed octave-nurbs in which every call of the functions
% `names` (a cell of octave-nurbs names, e.g. {"nrbeval", "findspan"}) is renamed to its twin
% cagd_<name>; the function definitions themselves are left as they are.
%
% The copy holds every .m file of octave-nurbs (and its private/ directory), its oct-files (run
% as they are: their C++ cannot be renamed) and the test files its build extracted from the C++
% sources (*-tst). The caller's process must not have octave-nurbs loaded
% (cagd_test_nurbs_copies checks it): the copy is put on the path for the run and removed
% afterwards, so each call of a renamed function reaches the cagd package, every other call the
% copy.
%
% tests = [passed, total] over every %!test/%!assert/%!error/... block (Octave's test ()),
% demos = [passed, total] over every %!demo block (each run in a function of its own, figures
% invisible; a demo passes when it runs without error).  With `verbose`, the output of failing
% tests and the errors of failing demos are printed.  `what` ("both", default, "tests" or
% "demos") runs only one kind ([0 0] for the other).
%
% With `affected_by` (a cell of names), only the files whose code can reach one of those
% functions are run: the files that call one, or call a function of octave-nurbs whose file
% does, and so on (the call graph from the names each file mentions).  The others run exactly
% the same code whatever the renaming of those functions, so their results need no second
% run (octave-nurbs' compiled functions cannot be renamed and call the originals anyway).
function [tests, demos, secs] = cagd_nurbs_copy (names, verbose, what, affected_by)
  if nargin < 2, verbose = true; end
  if nargin < 3, what = "both"; end
  if nargin < 4, affected_by = {}; end
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
  sources = {};
  for f = dir (fullfile (mdir, "*.m"))'
    write_renamed (fullfile (mdir, f.name), fullfile (copy, f.name), pattern);
    files{end+1} = fullfile (copy, f.name);
    sources{end+1} = fullfile (mdir, f.name);
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
    sources{end+1} = fullfile (adir, f.name);
  end
  if ! isempty (affected_by)
    files = files(reaches (sources, mdir, affected_by));
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

% Which of the original `files` can reach a function of `targets`: the call graph of
% octave-nurbs' functions by the names each function's code mentions (comments left out),
% closed transitively; a file reaches what its code and its test and demo blocks call.
function hit = reaches (files, mdir, targets)
  defined = regexprep ({dir(fullfile (mdir, "*.m")).name}, '\.m$', '');
  pattern = ['(?<![\w.])(' strjoin(defined, '|') ')(?!\w)'];
  calls = containers.Map ();
  for k = 1:numel (defined)
    calls(defined{k}) = names_in (fullfile (mdir, [defined{k} ".m"]), pattern, false);
  end
  reach = containers.Map ();
  for k = 1:numel (defined)
    seen = {}; todo = calls(defined{k});
    while ! isempty (todo)
      f = todo{end}; todo(end) = [];
      if any (strcmp (seen, f)), continue; end
      seen{end+1} = f;
      todo = [todo, calls(f)];
    end
    reach(defined{k}) = seen;
  end
  hit = false (size (files));
  for k = 1:numel (files)
    mentioned = names_in (files{k}, pattern, true);
    closure = mentioned;
    for m = mentioned
      closure = [closure, reach(m{1})];
    end
    hit(k) = any (ismember (targets, closure));
  end
end

% The names matching `pattern` in the code of a file (comments dropped); with `blocks`, in
% its %! test and demo blocks too.
function names = names_in (file, pattern, blocks)
  lines = strsplit (fileread (file), "\n");
  keep = {};
  for k = 1:numel (lines)
    l = strtrim (lines{k});
    if strncmp (l, "%!", 2)
      if blocks, keep{end+1} = l(3:end); end
    elseif ! isempty (l) && ! any (l(1) == "%#")
      keep{end+1} = regexprep (l, '[%#].*$', '');
    end
  end
  names = unique (regexp (strjoin (keep, "\n"), pattern, "match"));
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
  ## One figure for every demo (a new figure starts a new gnuplot process).
  close all;
  figure (1);
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
        ## Back to one empty figure for the next demo.
        figs = get (0, "children");
        close (figs(figs != 1));
        figure (1);
        clf ("reset");
      end
    end
  unwind_protect_cleanup
    close all;
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

% cagd_test_package () -- the test blocks (%!test, %!assert, %!error) of every function of the
% installed package, run with Octave's test (); and every docstring: Texinfo that makeinfo
% formats without a complaint, with a usage line (@deftypefn) and an example.  Prints one line
% per function and "package tests: OK".
function cagd_test_package ()
  dir_ = fileparts (which ("cagd_bezier"));
  files = [dir(fullfile (dir_, "*.m")); dir(fullfile (dir_, "*.cc-tst"))];   % builtin twins: .cc-tst
  names = regexprep ({files.name}, '\.(m|cc-tst)$', '');
  names = names(! strncmp (names, "__", 2));
  warning ("off", "Octave:gnuplot-graphics");
  set (0, "defaultfigurevisible", "off");
  total = [0 0];
  bad = {};
  for k = 1:numel (names)
    [ok, n] = test (names{k}, "quiet", 0);
    [text, format] = get_help_text (names{k});
    [~, status] = __makeinfo__ (text, "plain text");
    docs = strcmp (format, "texinfo") && status == 0 && ! isempty (strfind (text, "@deftypefn")) ...
           && ! isempty (strfind (text, "@example"));
    printf ("  %-24s %2d of %2d test blocks; docstring %s\n", names{k}, ok, n, ifelse_ (docs, "ok", "BAD"));
    total += [ok n];
    if ok != n || n == 0 || ! docs
      bad{end+1} = names{k};
      test (names{k}, "verbose", stdout);
    end
  end
  printf ("  %d functions, %d of %d test blocks pass, every docstring formats\n", numel (names), total);
  if ! isempty (bad)
    error ("package tests: failures in %s", strjoin (bad, ", "));
  end
  printf ("package tests: OK\n");
end

function s = ifelse_ (c, a, b)
  if c, s = a; else, s = b; end
end

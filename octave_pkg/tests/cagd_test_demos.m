% cagd_test_demos () -- every %!demo block of every function of the installed package, run as
% demo () runs it (each block in a function of its own), headless: figures invisible, drawn by
% the graphics toolkit Octave has (gnuplot or fltk, off screen). A demo passes when it runs
% without an error and leaves no error behind; every function must have at least one.  Prints
% one line per function and "demos: OK".
function cagd_test_demos ()
  dir_ = fileparts (which ("cagd_bezier"));
  files = [dir(fullfile (dir_, "*.m")); dir(fullfile (dir_, "*.cc-tst"))];   % builtin twins: .cc-tst
  names = regexprep ({files.name}, '\.(m|cc-tst)$', '');
  names = names(! strncmp (names, "__", 2));
  warning ("off", "Octave:gnuplot-graphics");
  old = get (0, "defaultfigurevisible");
  set (0, "defaultfigurevisible", "off");
  close all;
  figure (1);
  total = [0 0];
  bad = {};
  unwind_protect
    for k = 1:numel (names)
      [code, idx] = test (names{k}, "grabdemo");
      n = numel (idx) - 1;
      ok = 0;
      for j = 1:n
        try
          run_block (code(idx(j):idx(j+1) - 1));
          ok += 1;
        catch err
          printf ("    demo %d of %s FAILED: %s\n", j, names{k}, err.message);
        end
        ## Back to one empty figure for the next demo.
        figs = get (0, "children");
        close (figs(figs != 1));
        figure (1);
        clf ("reset");
      end
      printf ("  %-24s %d of %d demos run\n", names{k}, ok, n);
      total += [ok n];
      if ok != n || n == 0
        bad{end+1} = names{k};
      end
    end
  unwind_protect_cleanup
    close all;
    set (0, "defaultfigurevisible", old);
  end_unwind_protect
  printf ("  %d functions, %d of %d demos run without an error (graphics toolkit %s)\n", ...
          numel (names), total, graphics_toolkit ());
  if ! isempty (bad)
    error ("demos: failures or no demo in %s", strjoin (bad, ", "));
  end
  printf ("demos: OK\n");
end

% One demo block in a function workspace of its own (as demo () runs it), output discarded.
function run_block (block)
  eval (sprintf ("function __cagd_demo_block__ ()\n%s\nendfunction", block));
  evalc ("__cagd_demo_block__ ();");
end

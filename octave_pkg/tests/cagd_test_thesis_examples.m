% cagd_test_thesis_examples (refdir) -- the thesis's worked examples and the appendix C and D
% data scripts through the package: runs the reference cases of octave_ref/cases that call the
% thesis functions, with the package loaded and octave_ref/fixed NOT on the path, and compares
% every number they save with what the fixed Octave code saved (octave_ref/expected): each
% element within 4 ULPs or 1e-14 relative to the array's scale.  Prints the worst errors and
% "thesis examples: OK" when all agree; errors otherwise.
%
% Cases: primer_2_4 (Primer 2.4), curves, patches, compat_snapshots (Primer 2.4, a patch,
% appendix C and D at N = 5), coons_thesis (Primer 4.3 and appendix C's data script at
% N = 2, 3, 10, 101), coons_random, gordon_thesis (appendix D's data script at N = 3, 10, 101),
% gordon_random, lagrange_basis.
%
% gordon_random has networks with clustered nodes, where both Octave's product form and the
% package's barycentric form are within kappa*eps*scale of the exact surface (kappa = Lu + Lv +
% Lu*Lv, L the Lebesgue constants of the nodes) but not necessarily within 1e-14 of each
% other (crates/cagd-octave/tests/it/octave_compat.rs checks both against exact arithmetic):
% for those grids (kappa >= 10) the bound is 2*kappa*eps of the scale, and the script says so.
function cagd_test_thesis_examples (refdir)
  cases = {"primer_2_4", "curves", "patches", "compat_snapshots", "coons_thesis", ...
           "coons_random", "gordon_thesis", "gordon_random", "lagrange_basis"};
  fixed = fullfile (refdir, "fixed");
  if any (strcmp (strsplit (path (), pathsep ()), fixed))
    error ("cagd_test_thesis_examples: octave_ref/fixed must not be on the path");
  end
  for f = {"deCasteljau", "ploskevB", "krpaCoons", "krpaGordon", "Lagrange"}
    if ! isempty (strfind (which (f{1}), refdir))
      error ("cagd_test_thesis_examples: %s is the fixed Octave code, not the package's (%s)", f{1}, which (f{1}));
    end
  end
  outdir = tempname ();
  mkdir (outdir);
  unwind_protect
    setenv ("CAGD_REF_OUT", outdir);
    total = struct ("n", 0, "identical", 0, "ulps", 0, "rel", 0);
    failed = {};
    for k = 1:numel (cases)
      name = cases{k};
      run_case (fullfile (refdir, "cases", [name ".m"]));
      expected = load (fullfile (refdir, "expected", [name ".txt"]));
      got = load (fullfile (outdir, [name ".txt"]));
      s = struct ("n", 0, "identical", 0, "ulps", 0, "rel", 0);
      vars = fieldnames (expected);
      for v = vars'
        if ! isfield (got, v{1})
          failed{end+1} = sprintf ("%s: %s missing", name, v{1});
          continue;
        end
        [ok, s] = cagd_close (got.(v{1}), expected.(v{1}), s);
        r = regexp (v{1}, '^(r\d+)_P$', 'tokens', 'once');
        if ! ok && strcmp (name, "gordon_random") && ! isempty (r)
          kappa = conditioning (expected.([r{1} "_xu"]), expected.([r{1} "_xv"]));
          a = got.(v{1}); b = expected.(v{1});
          rel = max (abs (a(:) - b(:))) / max (abs (b(:)));
          ok = kappa >= 10 && rel <= 2 * kappa * eps;
          printf ("  gordon_random %s: kappa = %.0f, difference %.2g of the scale (bound 2*kappa*eps = %.2g)\n", ...
                  r{1}, kappa, rel, 2 * kappa * eps);
        end
        if ! ok
          failed{end+1} = sprintf ("%s: %s differs", name, v{1});
        end
      end
      printf ("  %-18s %3d variables, %7d numbers, %7d bit for bit; worst %.1f ULPs, %.2g of the scale\n", ...
              name, numel (vars), s.n, s.identical, s.ulps, s.rel);
      total.n += s.n; total.identical += s.identical;
      total.ulps = max (total.ulps, s.ulps); total.rel = max (total.rel, s.rel);
    end
  unwind_protect_cleanup
    confirm_recursive_rmdir (false, "local");
    rmdir (outdir, "s");
  end_unwind_protect
  printf ("  all: %d numbers, %d bit for bit; worst %.1f ULPs, %.2g relative to the scale\n", ...
          total.n, total.identical, total.ulps, total.rel);
  if ! isempty (failed)
    error ("thesis examples: %d difference(s): %s", numel (failed), strjoin (failed, "; "));
  end
  printf ("thesis examples: OK\n");
end

% kappa = Lu + Lv + Lu*Lv: Lebesgue constants of the node vectors on [0, 1] (4001 samples).
function kappa = conditioning (xu, xv)
  t = linspace (0, 1, 4001);
  lebesgue = @(x) max (sum (abs (cell2mat (arrayfun (@(i) Lagrange (x, i, t), (1:numel (x))', ...
                                                       "UniformOutput", false))), 1));
  [lu, lv] = deal (lebesgue (xu), lebesgue (xv));
  kappa = lu + lv + lu * lv;
end

% The case script runs in this function's workspace (as octave_ref/run_cases.m runs it).
function run_case (file)
  source (file);
end

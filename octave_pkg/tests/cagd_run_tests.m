% cagd_run_tests (refdir) -- every test of the installed Octave package cagd, in this one
% Octave process (octave_pkg/ci.sh runs it after pkg install into a temporary prefix):
%   cagd_test_package          the test blocks of every function (docstring examples, errors)
%   cagd_test_thesis_examples  the thesis's examples and appendix C/D scripts vs octave_ref/expected
%   cagd_test_differential     >= 1000 random cases, package vs octave_ref/fixed
%   cagd_test_demos            every %!demo block of every function, headless
%   cagd_test_nurbs            the octave-nurbs twins: random calls of every argument form
%                              against octave-nurbs in this session, nrbcoons
%   cagd_test_bad_input        the bad-input table, then the process alive and correct
% (octave-nurbs' own tests and demos on the twins run in a process without octave-nurbs:
% cagd_test_nurbs_copies, from ci.sh.)
% The last line is "cagd package tests: OK" when all pass (the exit status of Octave 7 is not
% reliable at exit, see octave_ref/README.md).
function cagd_run_tests (refdir)
  pkg load cagd;
  printf ("cagd package from %s\n", fileparts (which ("__cagd__")));
  steps = {@() cagd_test_package (), @() cagd_test_demos (), ...
           @() cagd_test_thesis_examples (refdir), ...
           @() cagd_test_differential (refdir), @() cagd_test_nurbs (), ...
           @() cagd_test_bad_input ()};
  failed = 0;
  for k = 1:numel (steps)
    try
      steps{k} ();
    catch err
      failed += 1;
      printf ("FAILED: %s\n", err.message);
    end
  end
  if failed
    printf ("cagd package tests: %d of %d FAILED\n", failed, numel (steps));
  else
    printf ("cagd package tests: OK\n");
  end
end

% bug_setup.m -- the common start of every bug script (a script, run with `bug_setup;`).
%
% Puts the ORIGINAL thesis code (../original/, bugs included) and the plotting stand-ins
% (shim/: plot3 and surf record their arguments in the global CAGD_PLOTS instead of drawing,
% hold does nothing) on the path, silences the warning that the stand-ins shadow Octave's own
% functions, and empties CAGD_PLOTS.  The bug scripts are run by run_bugs.sh with
% octave_ref/bugs/ as the working directory.
addpath(fullfile(pwd, '..', 'original'));
warning('off', 'Octave:shadowed-function');
addpath(fullfile(pwd, 'shim'));
global CAGD_PLOTS;
CAGD_PLOTS = {};

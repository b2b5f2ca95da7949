% Bug: appendix C's data script for vrednostCoons writes u^2 and v^2, a matrix power; with the
% parameters as vectors (as everywhere else in the thesis, u = linspace(0,1,N)) it fails.
% (With scalar u and v it works; see vrednostcoons_no_output.)
bug_setup;
u = linspace(0, 1, 5);
v = u;
vrednostCoons_data;

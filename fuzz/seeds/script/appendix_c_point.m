% Data script of the thesis, appendix C, for algorithm 6 (vrednostCoons), as printed (one
% statement per line): the curves are expressions in the free parameters u and v.
c1 = [u;0;u-u^2];
c2 = [u;1;u];
d1 = [0;v^2;v-v^2];
d2 = [1;v;v];
P1 = [0;0;0];
P2 = [1;0;0];
P3 = [0;1;0];
P4 = [1;1;1];

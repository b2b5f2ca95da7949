% Bug: vrednostCoons declares no output ("function vrednostCoons(...)"): it only displays T
% (no semicolon on "T = rc+rd-rcd"), so no caller can use the value.  Thesis Primer 4.3:
% u = 0.2, v = 0.5 with appendix C's data for Algoritem 6.
bug_setup;
u = 0.2;
v = 0.5;
vrednostCoons_data;
vrednostCoons(u, v, c1, c2, d1, d2, P1, P2, P3, P4);
T = vrednostCoons(u, v, c1, c2, d1, d2, P1, P2, P3, P4);

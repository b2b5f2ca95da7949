% Bug: krpaCoons uses N (u = linspace(0,1,N), loops to N) but N is neither an argument nor
% set in its body; a function does not see the caller's N.  Data: appendix C's script, with
% N set in the calling workspace and the missing P4 = [1;1;1] supplied (see krpacoons_data_p4).
bug_setup;
N = 5;
krpaCoons_data;
P4 = [1;1;1];
krpaCoons(c1, c2, d1, d2, P1, P2, P3, P4);

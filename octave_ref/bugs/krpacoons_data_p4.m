% Bug: appendix C's data script assigns P3 twice ("P3 = [0;1;0]; P3 = [1;1;1];") and never
% P4, so P3 ends up as the corner x(1,1) and the call krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)
% cannot even be made.  (N is set here, as the script uses it without defining it.)
bug_setup;
N = 5;
krpaCoons_data;
printf('P3 = %s, exist(''P4'') = %d\n', mat2str(P3'), exist('P4'));
krpaCoons(c1, c2, d1, d2, P1, P2, P3, P4);

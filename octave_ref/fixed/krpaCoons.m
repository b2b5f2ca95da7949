% krpaCoons.m -- fixed version of ../original/krpaCoons.m (thesis appendix C, Algoritem 5).
%
% [R, P] = krpaCoons(c1, c2, d1, d2, P1, P2, P3, P4)
%   c1, c2   3 x N: the boundary curves x(u,0), x(u,1) sampled at u = linspace(0,1,N)
%   d1, d2   3 x N: the boundary curves x(0,v), x(1,v) sampled at v = linspace(0,1,N)
%   P1..P4   3 x 1: the corners x(0,0), x(1,0), x(0,1), x(1,1)  (eq. (4.3) written out)
%   R        N x 3N, packed: R(i, 3*j-2:3*j) = x(u(i), v(j))'
%   P        N x N x 3:      P(i, j, :) = x(u(i), v(j))   (what tenzor(R) gives)
%
% What was changed, and why:
%   1. N is defined as size(c1, 2): the original used N without defining it (neither as an
%      argument nor in the body), so it could not run.
%   2. The sizes of the inputs are checked (all four curves 3 x N, corners 3 x 1): the original
%      silently indexed whatever it was given.
%   3. R is preallocated as zeros(N, 3*N); the original's zeros(N,N) was too small and Octave
%      grew it column by column.
%   4. R and P are returned; the plotting (surf, plot3, hold) is removed.  P is built with the
%      copy loop of tenzor (appendix B, Algoritem 4) written inline, so that this file does not
%      depend on another fixed function.
%   5. The data script of appendix C assigns P3 twice ("P3 = [1;1;1]") and never P4; the callers
%      (octave_ref/cases/coons_thesis.m) pass P4 = [1;1;1].  Nothing to change here: the
%      function always took P4.
% The arithmetic -- rc, rd, rcd and rc+rd-rcd, with its term order -- is the original's.
function [R, P] = krpaCoons(c1,c2,d1,d2,P1,P2,P3,P4)
N = size(c1, 2);
for c = {c1, c2, d1, d2}
    if !isequal(size(c{1}), [3 N])
        error('krpaCoons: every boundary curve must be 3 x N (N = %d)', N);
    end;
end;
for p = {P1, P2, P3, P4}
    if !isequal(size(p{1}), [3 1])
        error('krpaCoons: every corner must be 3 x 1');
    end;
end;
u = linspace(0,1,N);
v = linspace(0,1,N);
R = zeros(N, 3*N);
for i = 1:N
    k = 1;
    for j = 1:N
        rc = (1-v(j))*c1(:,i)+v(j)*c2(:,i);
        rd = (1-u(i))*d1(:,j)+u(i)*d2(:,j);
        rcd = (1-u(i))*(1-v(j))*P1 + u(i)*(1-v(j))*P2 + (1-u(i))*v(j)*P3 + u(i)*v(j)*P4;
        R(i,k:(k+2)) = rc+rd-rcd;
        k = k+3;
    end;
end;
P = zeros(N, N, 3);
for k = 1:N
    for l = 1:N
        P(k,l,:) = R(k,3*l-2:3*l);
    end;
end;
end;

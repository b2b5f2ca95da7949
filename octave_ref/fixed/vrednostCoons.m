% vrednostCoons.m -- fixed version of ../original/vrednostCoons.m (thesis appendix C, Algoritem 6).
%
% [T, rc, rd, rcd] = vrednostCoons(u, v, c1, c2, d1, d2, P1, P2, P3, P4)
%   u, v     scalars: the parameters
%   c1, c2   3 x 1: the boundary curves at u, c1(u) = x(u,0), c2(u) = x(u,1)
%   d1, d2   3 x 1: the boundary curves at v, d1(v) = x(0,v), d2(v) = x(1,v)
%   P1..P4   3 x 1: the corners x(0,0), x(1,0), x(0,1), x(1,1)
%   T        3 x 1: the Coons patch point x(u,v) = rc + rd - rcd   (Izrek 4.2)
%   rc, rd, rcd   3 x 1: its three parts, eqs. (4.1), (4.2), (4.3)
%
% What was changed, and why:
%   1. The function returns T and its parts rc, rd, rcd: the original declared no output and
%      only displayed T (the missing semicolon on "T = rc+rd-rcd"), so no caller could use the
%      value.  The display is gone (semicolon added).
% The arithmetic, with its term order, is the original's.
function [T, rc, rd, rcd] = vrednostCoons(u,v,c1,c2,d1,d2,P1,P2,P3,P4)
rc = (1-v)*c1+v*c2;
rd = (1-u)*d1+u*d2;
rcd = (1-u)*(1-v)*P1+u*(1-v)*P2+(1-u)*v*P3+u*v*P4;
T = rc+rd-rcd;
end;

% Lagrange.m -- fixed version of ../original/Lagrange.m (thesis appendix D, Algoritem 8).
%
% v = Lagrange(x, m, u)
%   x   1 x (n): the interpolation nodes x(1), ..., x(n), distinct
%   m   the index (1-based) of the basis polynomial -- not its degree, as the thesis's
%       description says
%   u   any array of parameters
%   v   array of size(u): L_m(u) = prod_{j ~= m} (u - x(j)) / (x(m) - x(j))
%
% What was changed, and why:
%   1. The product starts at ones(size(u)): the original started it at zeros(size(u)), so every
%      factor multiplied zero and the function always returned 0 (Gordon surfaces built on it
%      were identically zero).
%   2. The function is closed with "end;" (the original relied on end-of-file).
% The loop and the order of the operations, ((u-x(j))./(x(m)-x(j))).*v, are the original's.
function v = Lagrange(x,m,u)
n = length(x);
v = ones(size(u));
for j = [1:m-1 m+1:n]
    v = (u-x(j))./(x(m)-x(j)).*v;
end;
end;

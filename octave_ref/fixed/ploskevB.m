% ploskevB.m -- minimally fixed version of ../original/ploskevB.m
% (thesis appendix B, Algoritem 2).
%
% P = ploskevB(kontrolneT, N)
%   kontrolneT  (m+1) x 3(n+1): the packed control net as tenzor reads it,
%               kontrolneT(i+1, 3*j+1:3*j+3) = b(i,j); m ~= n allowed.
%   N           number of samples per direction; u and v both run over linspace(0,1,N).
%   P           N x N x 3: P(i,j,:) is the point of the patch at (u, v) = (t(i), t(j)).
%
% What was changed, and why:
%   1. Returns P (new output "P = ...") and no longer plots (the surf line removed): plotting
%      belongs to the command line; the reference files need the numbers.
%   2. P is preallocated as zeros(N,N,3).
% The evaluation itself is unchanged; the m ~= n bug lived in bilinearna (see fixed/bilinearna.m).
% Coordinates stay 3: the packed layout cannot tell the dimension without a new argument.
function P = ploskevB(kontrolneT,N)
m = size(kontrolneT)(1)-1;
n = (size(kontrolneT)(2)/3)-1;
t = linspace(0,1,N);
P = zeros(N,N,3);
for i = 1:N
    for j = 1:N
        u = t(i);
        v = t(j);
        P(i,j,:) = bilinearna(kontrolneT,u,v,N);
    end;
end;
end;

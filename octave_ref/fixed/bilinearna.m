% bilinearna.m -- minimally fixed version of ../original/bilinearna.m
% (thesis appendix B, Algoritem 3).
%
% L = bilinearna(B, u, v, N)
%   B      (m+1) x 3(n+1): the packed control net (see tenzor.m); m ~= n allowed.
%   u, v   the parameters.
%   N      unused except for the (harmless) initial size of the work array, as in the original.
%   L      1 x 1 x 3: the point b(0,0)^(m,n)(u,v) of the tensor-product de Casteljau scheme.
%
% What was changed, and why:
%   1. m ~= n: the original ran k = 1:m bilinear steps over i = 1:(m-k+1), j = 1:(n-k+1).  For
%      m < n it stopped after m steps, i.e. returned a point of a degree (0, n-m) net, not of the
%      patch; for m > n the j loop became empty after n steps and the stale values were returned.
%      Now: min(m,n) bilinear steps (unchanged formula, unchanged term order), then |m-n| linear
%      steps in the direction whose degree remains,
%          in u:  B1(i,1,:) = (1-u)*B1(i,1,:) + u*B1(i+1,1,:)
%          in v:  B1(1,j,:) = (1-v)*B1(1,j,:) + v*B1(1,j+1,:)
%      This is the de Casteljau algorithm of thesis section 3.2 for a rectangular net.
%   2. The result is read from B1 (the last level), not from T, so that degree (0,n) and (m,0)
%      nets, which take no bilinear step, return their point instead of zeros.
function L = bilinearna(B,u,v,N)
T = zeros(N,N,3);
m = size(B)(1)-1;
n = (size(B)(2)/3)-1;
B1 = tenzor(B);
for k=1:min(m,n)
    for i = 1:(m-k+1)
        for j = 1:(n-k+1)
            T(i,j,:) = (1-u)*(1-v)*B1(i,j,:) + u*(1-v)*B1(i+1,j,:) + (1-u)*v*B1(i,j+1,:) + u*v*B1(i+1,j+1,:);
        end;
    end;
    B1=T;
end;
r = min(m,n);
for k=1:(m-r)
    for i = 1:(m-r-k+1)
        B1(i,1,:) = (1-u)*B1(i,1,:) + u*B1(i+1,1,:);
    end;
end;
for k=1:(n-r)
    for j = 1:(n-r-k+1)
        B1(1,j,:) = (1-v)*B1(1,j,:) + v*B1(1,j+1,:);
    end;
end;
L = B1(1,1,:);
end;
